//! Serde forms as Python objects: a record (`solve --format json`'s) as dicts, lists and
//! numbers; a figure's data with its lists of numbers as numpy arrays.

use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;

/// How lists of numbers come out.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Lists {
    /// As Python lists (a record: small, read as it prints).
    Plain,
    /// As float64 numpy arrays, null as NaN (a figure's data: columns to compute with).
    Arrays,
}

/// `value` (serde's form of any `Serialize` value) as a Python object.
pub(super) fn to_python<'py>(
    py: Python<'py>,
    value: &Value,
    lists: Lists,
) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => pyo3::types::PyBool::new(py, *b).to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_f64()) {
            (Some(i), _) if !n.is_f64() => i.into_pyobject(py)?.into_any(),
            (_, Some(f)) => f.into_pyobject(py)?.into_any(),
            _ => n.as_u64().unwrap_or(u64::MAX).into_pyobject(py)?.into_any(),
        },
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(items) if lists == Lists::Arrays && is_numeric(items) => {
            let values: Vec<f64> = items
                .iter()
                .map(|v| v.as_f64().unwrap_or(f64::NAN))
                .collect();
            PyArray1::from_vec(py, values).into_any()
        }
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(to_python(py, item, lists)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (k, v) in map {
                dict.set_item(k, to_python(py, v, lists)?)?;
            }
            dict.into_any()
        }
    })
}

/// A list of numbers (nulls, where a number is not finite, among them), not empty.
fn is_numeric(items: &[Value]) -> bool {
    items.iter().any(Value::is_number) && items.iter().all(|v| v.is_number() || v.is_null())
}

/// Any `Serialize` value as Python objects, through its serde form.
pub(super) fn serde_to_python<'py, T: serde::Serialize>(
    py: Python<'py>,
    value: &T,
    lists: Lists,
) -> PyResult<Bound<'py, PyAny>> {
    let v = serde_json::to_value(value).expect("answers serialise");
    to_python(py, &v, lists)
}
