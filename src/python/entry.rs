//! The keyword functions (`solve`, `render`, `design`, `vlocator`) as the module's own C
//! functions, each with its signature in its docstring (`solve($module, /, *, mu=0.4, ...)`),
//! which `inspect.signature` and `help` read. The keywords are the settings' declarations,
//! known at import, so the function is made then; pyo3's `#[pyfunction]` fixes a signature
//! when the crate compiles.
//!
//! A Python wrapper carrying the signature cost a scalar `solve` a tenth of its time (a frame
//! and a dict of the keywords). A function made with `PyCFunction::new_closure` pickles badly
//! (its `__self__` is a capsule, and Dask ships functions by pickling); these have the module
//! as `__self__` and pickle by name.

use std::any::Any;
use std::ffi::CString;
use std::panic::{self, AssertUnwindSafe};

use pyo3::exceptions::PyTypeError;
use pyo3::ffi;
use pyo3::panic::PanicException;
use pyo3::prelude::*;
use pyo3::types::{PyCFunction, PyDict, PyTuple};

/// What a keyword function does with its positional arguments (in its declared order) and its
/// keywords (those positionals given by keyword taken out).
pub(super) type Body = for<'py> fn(
    Python<'py>,
    Vec<Bound<'py, PyAny>>,
    Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>>;

/// The C function of keyword function `name`: `body` behind [`call`].
macro_rules! keyword_native {
    ($name:literal, $body:expr) => {{
        unsafe extern "C" fn entry(
            _module: *mut pyo3::ffi::PyObject,
            args: *mut pyo3::ffi::PyObject,
            kwargs: *mut pyo3::ffi::PyObject,
        ) -> *mut pyo3::ffi::PyObject {
            // SAFETY: CPython calls a METH_VARARGS | METH_KEYWORDS function with its
            // arguments' tuple and their dict or NULL, borrowed, the thread attached.
            unsafe { super::entry::call($name, $body, args, kwargs) }
        }
        |m: &Bound<'_, PyModule>| super::entry::add(m, $name, entry)
    }};
}
pub(super) use keyword_native;

/// Adds keyword function `name` to module `m` as C function `entry`, its docstring opening
/// with its signature.
pub(super) fn add(
    m: &Bound<'_, PyModule>,
    name: &'static str,
    entry: ffi::PyCFunctionWithKeywords,
) -> PyResult<()> {
    let declared = super::docs::keyword_function(name).expect("a keyword function of FUNCTIONS");
    let mut params = vec!["$module".to_string(), "/".to_string()];
    params.extend(declared.positional.iter().map(|p| p.to_string()));
    params.push("*".into());
    params.extend(declared.keywords.iter().map(|(k, default)| match default {
        Some(d) => format!("{k}={d}"),
        None => k.to_string(),
    }));
    let doc = format!("{name}({})\n--\n\n{}", params.join(", "), declared.doc);
    // The method's definition lives as long as the module's function: for the process.
    let leak = |text: String| -> &'static std::ffi::CStr {
        Box::leak(
            CString::new(text)
                .expect("no NUL in a name or a doc")
                .into_boxed_c_str(),
        )
    };
    let f = PyCFunction::new_with_keywords(m.py(), entry, leak(name.into()), leak(doc), Some(m))?;
    m.add(name, f)
}

/// Keyword function `name` called with `args` and `kwargs` as CPython passes them: its
/// positional arguments (given by position or by keyword, none more) and required keywords
/// checked as Python checks a `def`'s, then `body`; its error raised, and a panic raised as
/// pyo3's `PanicException`, never unwound into the interpreter.
///
/// # Safety
/// `args` is a tuple and `kwargs` a dict or NULL, both borrowed for the call, and the calling
/// thread is attached to the interpreter.
pub(super) unsafe fn call(
    name: &'static str,
    body: Body,
    args: *mut ffi::PyObject,
    kwargs: *mut ffi::PyObject,
) -> *mut ffi::PyObject {
    Python::attach(|py| {
        let run = || -> PyResult<Bound<'_, PyAny>> {
            // SAFETY: the caller's promise.
            let args = unsafe { Bound::from_borrowed_ptr(py, args) }.cast_into::<PyTuple>()?;
            let kwargs = unsafe { Bound::from_borrowed_ptr_or_opt(py, kwargs) }
                .map(|k| k.cast_into::<PyDict>())
                .transpose()?;
            let (given, kwargs) = arguments(name, args, kwargs)?;
            body(py, given, kwargs.as_ref())
        };
        match panic::catch_unwind(AssertUnwindSafe(run)) {
            Ok(Ok(answer)) => answer.into_ptr(),
            Ok(Err(e)) => {
                e.restore(py);
                std::ptr::null_mut()
            }
            Err(payload) => {
                PanicException::new_err(panic_text(payload.as_ref())).restore(py);
                std::ptr::null_mut()
            }
        }
    })
}

/// A call's positional arguments and its keywords, as a [`Body`] takes them.
type Arguments<'py> = (Vec<Bound<'py, PyAny>>, Option<Bound<'py, PyDict>>);

/// The positional arguments of a call of `name`, those given by keyword taken out of its
/// keywords (a copy: the caller's dict is not the function's to change); its mistakes refused
/// with Python's words.
fn arguments<'py>(
    name: &str,
    args: Bound<'py, PyTuple>,
    kwargs: Option<Bound<'py, PyDict>>,
) -> PyResult<Arguments<'py>> {
    let declared = super::docs::keyword_function(name).expect("a keyword function of FUNCTIONS");
    if declared.bare && args.is_empty() {
        // Keywords alone, to a function without positional or required ones (solve in a
        // loop): nothing to move or check.
        return Ok((Vec::new(), kwargs));
    }
    let (positional, keywords) = (&declared.positional, &declared.keywords);
    let mut given: Vec<Bound<'py, PyAny>> = args.iter().collect();
    let mut kwargs = kwargs;
    if given.len() < positional.len()
        && let Some(kw) = &kwargs
    {
        let kw = kw.copy()?;
        for p in &positional[given.len()..] {
            if let Some(v) = kw.get_item(p)? {
                kw.del_item(p)?;
                given.push(v);
            }
        }
        kwargs = Some(kw);
    }
    if given.len() != positional.len() {
        let takes = match positional.len() {
            0 => "no positional arguments (give each value by its keyword)".to_string(),
            1 => format!("1 positional argument ({})", positional[0]),
            n => format!("{n} positional arguments ({})", positional.join(", ")),
        };
        let were = match given.len() {
            1 => "1 was".to_string(),
            n => format!("{n} were"),
        };
        return Err(PyTypeError::new_err(format!(
            "{name}() takes {takes} but {were} given"
        )));
    }
    for (k, _) in keywords.iter().filter(|(_, d)| d.is_none()) {
        if !kwargs
            .as_ref()
            .is_some_and(|kw| kw.contains(k).unwrap_or(false))
        {
            return Err(PyTypeError::new_err(format!(
                "{name}() missing required keyword argument: '{k}'"
            )));
        }
    }
    Ok((given, kwargs))
}

/// A panic's message, as pyo3 words it.
fn panic_text(payload: &(dyn Any + Send)) -> String {
    match (
        payload.downcast_ref::<String>(),
        payload.downcast_ref::<&str>(),
    ) {
        (Some(s), _) => s.clone(),
        (None, Some(s)) => s.to_string(),
        (None, None) => "panic from Rust code".into(),
    }
}
