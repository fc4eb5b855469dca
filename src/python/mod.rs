//! The Python package `jamchart`: the same crate, built with its `python` feature by maturin
//! (`pip install .` in a checkout; `pyproject.toml`), as the extension module
//! `jamchart._jamchart` beside the pure-Python layer in `src/python/jamchart/` (keyword
//! signatures and docs, type stubs). This module has no public Rust API.
//!
//! Every keyword of `jamchart.solve` and `jamchart.render` is a declared setting
//! ([`crate::settings`], under its TOML key); every answer comes from the model port
//! ([`crate::models`]): arrays through [`crate::models::columns`], filled in place in numpy's
//! buffers with the GIL released, one push through [`crate::models::solve`] and its record.
//! Bad input raises `ValueError` with the library's message (the key, the value, the valid
//! values); an unknown keyword raises `TypeError`.

mod answers;
mod charts;
mod convert;
mod docs;
mod keywords;
mod reports;
mod solve;

use pyo3::prelude::*;

use crate::scene::JamStatus;

/// The extension module; `jamchart/__init__.py` re-exports it with signatures and docs.
#[pymodule]
#[pyo3(name = "_jamchart")]
fn jamchart_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("STATUSES", JamStatus::NAMES.to_vec())?;
    m.add("CHART_FORMAT", crate::charts::CHART_FORMAT)?;
    m.add_class::<answers::Solution>()?;
    m.add_class::<answers::Solutions>()?;
    m.add_class::<answers::BoxAnswer>()?;
    m.add_class::<keywords::Distribution>()?;
    m.add_class::<charts::Chart>()?;
    m.add_class::<reports::DesignAnswer>()?;
    m.add_class::<reports::VlocatorAnswer>()?;
    m.add_function(wrap_pyfunction!(solve::solve, m)?)?;
    m.add_function(wrap_pyfunction!(keywords::normal, m)?)?;
    m.add_function(wrap_pyfunction!(keywords::uniform, m)?)?;
    m.add_function(wrap_pyfunction!(keywords::lognormal, m)?)?;
    m.add_function(wrap_pyfunction!(charts::render, m)?)?;
    m.add_function(wrap_pyfunction!(charts::scenes, m)?)?;
    m.add_function(wrap_pyfunction!(reports::design, m)?)?;
    m.add_function(wrap_pyfunction!(reports::vlocator, m)?)?;
    m.add_function(wrap_pyfunction!(docs::keywords, m)?)?;
    m.add_function(wrap_pyfunction!(docs::doc, m)?)?;
    Ok(())
}
