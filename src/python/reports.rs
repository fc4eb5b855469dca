//! `jamchart.design` and `jamchart.vlocator`: the CLI's inverse and V-block answers, their
//! keywords read as the commands' flags (each a declared setting), their JSON as dicts.

use clap::Parser;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString, PyTuple};

use super::convert::{Lists, to_python};
use super::keywords::{Distribution, error};
use crate::cli::design::DesignArgs;
use crate::cli::vlocator::VlocatorArgs;
use crate::settings::{self, Decl};

/// `design`'s flags, parsed as the command parses them.
#[derive(Parser)]
#[command(name = "design")]
struct Design {
    #[command(flatten)]
    args: DesignArgs,
}

/// `vlocator`'s flags, parsed as the command parses them.
#[derive(Parser)]
#[command(name = "vlocator")]
struct Vlocator {
    #[command(flatten)]
    args: VlocatorArgs,
}

/// `jamchart.design(x_target_mm, **scene)`: see the package's docs.
#[pyfunction]
#[pyo3(signature = (keywords=None))]
pub(super) fn design<'py>(
    py: Python<'py>,
    keywords: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let scene = || settings::palm_family().filter(|d| d.section == "scene");
    let mut words = vec!["design".to_string(), "--format".into(), "json".into()];
    for (k, v) in keywords.into_iter().flat_map(|d| d.iter()) {
        let key: String = k.extract()?;
        let key = key.as_str();
        match key {
            "x_target_mm" => words.extend(["--x-target".to_string(), number_text(&v)?]),
            _ => words.extend(flag_words("design", key, &v, scene)?),
        }
    }
    let parsed = Design::try_parse_from(&words).map_err(clap_error)?;
    let json = py
        .detach(|| crate::cli::design::run(&parsed.args))
        .map_err(error)?;
    json_to_python(py, &json)
}

/// `jamchart.vlocator(**locator)`: see the package's docs.
#[pyfunction]
#[pyo3(signature = (keywords=None))]
pub(super) fn vlocator<'py>(
    py: Python<'py>,
    keywords: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let locator = || settings::locator_family().filter(|d| d.flag.is_some());
    let mut words = vec!["vlocator".to_string(), "--format".into(), "json".into()];
    for (k, v) in keywords.into_iter().flat_map(|d| d.iter()) {
        let key: String = k.extract()?;
        let key = key.as_str();
        match key {
            _ if v.is_none() => {}
            "included_angle_deg" => {
                words.extend(["--included-angle".to_string(), number_text(&v)?])
            }
            "flank_angles" => {
                let (a1, a2): (f64, f64) = v.extract().map_err(|_| {
                    PyValueError::new_err("flank_angles is a pair of angles in deg (left, right)")
                })?;
                words.push(format!("--flank-angles={a1},{a2}"));
            }
            _ => words.extend(flag_words("vlocator", key, &v, locator)?),
        }
    }
    let parsed = Vlocator::try_parse_from(&words).map_err(clap_error)?;
    let json = py
        .detach(|| crate::cli::vlocator::run(&parsed.args))
        .map_err(error)?;
    json_to_python(py, &json)
}

/// The flag and value of keyword `key` among the declarations `decls` (each with a flag): a
/// number, a range `(low, high)`, a distribution, or the CLI's text.
fn flag_words<I: Iterator<Item = &'static Decl>>(
    function: &str,
    key: &str,
    v: &Bound<'_, PyAny>,
    decls: impl Fn() -> I,
) -> PyResult<Vec<String>> {
    let Some(flag) = decls().find(|d| d.key == key).and_then(|d| d.flag) else {
        let known: Vec<&str> = decls().map(|d| d.key).collect();
        return Err(PyTypeError::new_err(format!(
            "{function}() got an unexpected keyword argument '{key}'; it takes {}",
            known.join(", ")
        )));
    };
    let value = if let Ok(d) = v.cast::<Distribution>() {
        d.get().0.to_string()
    } else if let Ok(t) = v.cast::<PyTuple>() {
        let (lo, hi): (f64, f64) = t.extract().map_err(|_| {
            PyValueError::new_err(format!(
                "{key}: a tuple is a range (low, high) of two numbers"
            ))
        })?;
        format!(
            "{}:{}",
            settings::number_text(lo),
            settings::number_text(hi)
        )
    } else if let Ok(s) = v.cast::<PyString>() {
        s.to_cow()?.into_owned()
    } else {
        number_text(v)?
    };
    Ok(vec![format!("--{flag}={value}")])
}

/// A number as the CLI reads it back exactly.
fn number_text(v: &Bound<'_, PyAny>) -> PyResult<String> {
    let x: f64 = v.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "expected a number, not {}",
            v.get_type()
                .name()
                .map_or_else(|_| "?".into(), |n| n.to_string())
        ))
    })?;
    Ok(settings::number_text(x))
}

/// clap's refusal as a `ValueError`: its message without the usage lines.
fn clap_error(e: clap::Error) -> PyErr {
    let text = e.to_string();
    let first = text
        .lines()
        .find(|l| !l.trim().is_empty())
        .unwrap_or_default()
        .trim_start_matches("error: ");
    PyValueError::new_err(first.to_string())
}

/// The command's JSON as dicts and lists.
fn json_to_python<'py>(py: Python<'py>, json: &str) -> PyResult<Bound<'py, PyAny>> {
    let doc: serde_json::Value =
        serde_json::from_str(json).map_err(|e| PyValueError::new_err(e.to_string()))?;
    to_python(py, &doc, Lists::Plain)
}
