//! The Python package `jamchart`: the same crate, built with its `python` feature by maturin
//! (`pip install .` in a checkout; `pyproject.toml`), as the extension module
//! `jamchart._jamchart` beside the pure-Python layer in `src/python/jamchart/` (which re-exports
//! it and holds the type stubs). This module has no public Rust API.
//!
//! A face over the library's questions and answers ([`crate::ask`]): each function reads its
//! keywords as the library's [`crate::ask::Keywords`] (arrays aside, which go to the model
//! port's array entry, [`crate::models::columns`], filled in place in numpy's buffers with
//! the GIL released), asks the question and returns its answer as a Python object. Bad input
//! raises `ValueError` with the library's message (the key, the value and the valid values);
//! an unknown keyword raises `TypeError`. Every function is registered from one list,
//! [`docs::FUNCTIONS`].

mod answers;
mod charts;
mod convert;
mod docs;
mod entry;
mod keywords;
mod reports;
mod solve;

use pyo3::prelude::*;

use crate::scene::JamStatus;

/// The extension module; `jamchart/__init__.py` re-exports it.
#[pymodule]
#[pyo3(name = "_jamchart")]
fn jamchart_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("STATUSES", JamStatus::NAMES.to_vec())?;
    m.add("CHART_FORMAT", crate::charts::CHART_FORMAT)?;
    let classes = [
        class::<answers::BoxAnswer>(m)?,
        class::<answers::Comparison>(m)?,
        class::<charts::Chart>(m)?,
        class::<reports::DesignAnswer>(m)?,
        class::<keywords::Distribution>(m)?,
        class::<keywords::Range>(m)?,
        class::<answers::Solution>(m)?,
        class::<answers::Solutions>(m)?,
        class::<reports::VlocatorAnswer>(m)?,
    ];
    docs::add_all(m)?;
    m.add_function(wrap_pyfunction!(docs::_functions, m)?)?;
    m.add_function(wrap_pyfunction!(docs::_doc, m)?)?;
    m.add_function(wrap_pyfunction!(docs::_stub, m)?)?;
    m.add_function(wrap_pyfunction!(answers::_solutions, m)?)?;
    m.add_function(wrap_pyfunction!(docs::_session, m)?)?;
    m.add("__all__", docs::all(&classes))?;
    Ok(())
}

/// The `TypeError` of pickling answer class `name`: it holds the library's whole answer
/// (models' details, a chart's computed figure), which has no form to be read back from; what
/// crosses between processes is its dict, its numbers, or an array answer (`Solutions`,
/// `Distribution` and `Range` pickle).
fn unpicklable(name: &str) -> PyErr {
    let instead = match name {
        "Chart" => "its .svg or .png bytes or its .data",
        _ => "its .to_dict() (dicts, lists and numbers, the command line's JSON)",
    };
    pyo3::exceptions::PyTypeError::new_err(format!(
        "a jamchart.{name} does not pickle: return {instead} or the numbers you need from a \
         worker process; array answers (jamchart.Solutions) pickle"
    ))
}

/// Adds class `T` to the module; its Python name.
fn class<T: pyo3::PyClass>(m: &Bound<'_, PyModule>) -> PyResult<String> {
    m.add_class::<T>()?;
    Ok(m.py().get_type::<T>().name()?.to_string())
}

/// The stub's opening: the module's constants and classes (the functions follow, from
/// [`docs::FUNCTIONS`]).
const CLASSES_STUB: &str = r#""""Types of the package jamchart: every keyword is a declared setting (its unit in its name).

The keyword lists below are the settings' declaration's (a test compares them); the docs of
each are in help(jamchart.solve).
"""

import os
from typing import Any, Dict, List, Literal, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
STATUSES: List[str]
CHART_FORMAT: str

class Range:
    """Every value from low to high, none more likely: the worst case over them."""
    def __init__(self, low: float, high: float) -> None: ...
    @property
    def low(self) -> float: ...
    @property
    def high(self) -> float: ...
    @property
    def nominal(self) -> float: ...

class Distribution:
    """A distribution of one input: normal, uniform or lognormal."""
    @property
    def nominal(self) -> float: ...
    def quantile(self, p: float) -> float: ...
    def cdf(self, x: float) -> float: ...

_Array = Union[npt.NDArray[Any], List[float], List[List[float]]]
_Values = Union[float, _Array]
_Uncertain = Union[float, Range, Distribution, str]
_UncertainValues = Union[float, _Array, Range, Distribution, str]

class Solution:
    """One push's answer."""
    @property
    def model(self) -> str: ...
    @property
    def status(self) -> str: ...
    @property
    def theta_jam_deg(self) -> float: ...
    @property
    def x_jam_mm(self) -> float: ...
    @property
    def elapsed_s(self) -> float: ...
    @property
    def inputs(self) -> Dict[str, Any]: ...
    @property
    def record(self) -> Dict[str, Any]: ...
    def to_dict(self) -> Dict[str, Any]: ...

class Solutions:
    """Many pushes' answers, shaped like the broadcast inputs."""
    @property
    def model(self) -> str: ...
    @property
    def status(self) -> npt.NDArray[np.str_]: ...
    @property
    def status_code(self) -> npt.NDArray[np.uint8]: ...
    @property
    def theta_jam_deg(self) -> npt.NDArray[np.float64]: ...
    @property
    def x_jam_mm(self) -> npt.NDArray[np.float64]: ...
    @property
    def past_palm_x_jam_mm(self) -> npt.NDArray[np.float64]: ...
    @property
    def shape(self) -> Tuple[int, ...]: ...
    @property
    def inputs(self) -> Dict[str, Any]: ...
    def __len__(self) -> int: ...
    def to_pandas(self) -> Any: ...

class BoxAnswer:
    """The answer over a range or distribution of inputs."""
    @property
    def model(self) -> str: ...
    @property
    def theta_jam_deg(self) -> Optional[Tuple[float, float]]: ...
    @property
    def x_jam_mm(self) -> Optional[Tuple[float, float]]: ...
    @property
    def statuses(self) -> List[str]: ...
    @property
    def probability(self) -> List[Tuple[float, float]]: ...
    @property
    def quantiles(self) -> List[Tuple[float, float]]: ...
    @property
    def record(self) -> Dict[str, Any]: ...
    def to_dict(self) -> Dict[str, Any]: ...

class Comparison:
    """Every model's answer to one push (solve(model="all")), and which to design to."""
    @property
    def models(self) -> List[str]: ...
    @property
    def solutions(self) -> Dict[str, Solution]: ...
    @property
    def guidance(self) -> str: ...
    @property
    def inputs(self) -> Dict[str, Any]: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_pandas(self) -> Any: ...

class _Report:
    """An answer whose JSON document's keys are its attributes."""
    @property
    def headline(self) -> str: ...
    @property
    def report(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def __getattr__(self, name: str) -> Any: ...

class DesignAnswer(_Report):
    """jamchart.design's answer; each key of `jamchart design --format json` is an attribute."""

class VlocatorAnswer(_Report):
    """jamchart.vlocator's answer; each key of `jamchart vlocator --format json` is an attribute."""

class Chart:
    """A drawn design chart."""
    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def svg(self) -> bytes: ...
    @property
    def png(self) -> bytes: ...
    @property
    def data(self) -> Any: ...
    @property
    def data_format(self) -> str: ...
    def save(
        self, path: Union[str, "os.PathLike[str]"], *, paper: Optional[Literal["a4", "letter"]] = None
    ) -> None: ...
"#;
