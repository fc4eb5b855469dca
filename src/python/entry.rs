//! The keyword functions (`solve`, `render`, `design`, `vlocator`) as the module's own C
//! functions, each with its signature in its docstring (`solve($module, /, *, mu=0.4, ...)`),
//! which `inspect.signature` and `help` read. The keywords are the settings' declarations,
//! known at import, so the function is made then; pyo3's `#[pyfunction]` fixes a signature
//! when the crate compiles.
//!
//! Each takes the vectorcall convention (`METH_FASTCALL | METH_KEYWORDS`, in the stable ABI
//! from CPython 3.10): the call's values arrive as an array beside a tuple of their names, and
//! no dict is made for a scalar `solve` (the dict, made by the interpreter for the older
//! convention, was a fifth of the call). pyo3's trampoline, the one its `#[pyfunction]`s go
//! through, counts the thread as attached and raises a panic as `PanicException`.
//!
//! A Python wrapper carrying the signature cost a scalar `solve` a tenth of its time (a frame
//! and a dict of the keywords). A function made with `PyCFunction::new_closure` pickles badly
//! (its `__self__` is a capsule, and Dask ships functions by pickling); these have the module
//! as `__self__` and pickle by name.

use std::ffi::CString;

use pyo3::exceptions::PyTypeError;
use pyo3::ffi;
use pyo3::prelude::*;
use pyo3::types::{PyCFunction, PyDict, PyString, PyTuple};
use smallvec::SmallVec;

/// What a keyword function does with its positional arguments (in its declared order) and its
/// keywords (those positionals given by keyword taken out).
pub(super) type Body =
    for<'py> fn(Python<'py>, Vec<Bound<'py, PyAny>>, &Kwargs<'py>) -> PyResult<Bound<'py, PyAny>>;

/// A call's keywords, in the order given: each name (a `str`) and its value.
pub(super) struct Kwargs<'py>(SmallVec<[(Bound<'py, PyString>, Bound<'py, PyAny>); 8]>);

impl<'py> Kwargs<'py> {
    /// The names and values, in the order given.
    pub(super) fn pairs(&self) -> &[(Bound<'py, PyString>, Bound<'py, PyAny>)] {
        &self.0
    }

    /// The keywords as a new dict, None when there are none: what a `def`'s `**kwargs` holds.
    pub(super) fn dict(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        if self.0.is_empty() {
            return Ok(None);
        }
        let dict = PyDict::new(py);
        for (k, v) in &self.0 {
            dict.set_item(k, v)?;
        }
        Ok(Some(dict))
    }

    /// Whether keyword `name` was given.
    fn has(&self, name: &str) -> bool {
        self.0.iter().any(|(k, _)| k == name)
    }
}

/// The C function of keyword function `name`: `body` behind [`call`], through pyo3's
/// trampoline.
macro_rules! keyword_native {
    ($name:literal, $body:expr) => {{
        /// # Safety
        /// CPython calls a `METH_FASTCALL | METH_KEYWORDS` function with its values' array
        /// (`nargs` positional, then one per name of `kwnames`, a tuple or NULL), borrowed,
        /// the thread attached.
        unsafe fn run(
            py: pyo3::Python<'_>,
            _module: *mut pyo3::ffi::PyObject,
            args: *const *mut pyo3::ffi::PyObject,
            nargs: pyo3::ffi::Py_ssize_t,
            kwnames: *mut pyo3::ffi::PyObject,
        ) -> pyo3::PyResult<*mut pyo3::ffi::PyObject> {
            // SAFETY: the caller's promise, which `call` asks.
            unsafe { super::entry::call(py, $name, $body, args, nargs, kwnames) }
        }
        |m: &Bound<'_, PyModule>| {
            let entry = pyo3::impl_::trampoline::get_trampoline_function!(
                fastcall_cfunction_with_keywords,
                run
            );
            super::entry::add(m, $name, entry)
        }
    }};
}
pub(super) use keyword_native;

/// Adds keyword function `name` to module `m` as C function `entry`, its docstring opening
/// with its signature.
pub(super) fn add(
    m: &Bound<'_, PyModule>,
    name: &'static str,
    entry: ffi::PyCFunctionFastWithKeywords,
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
    let leak = |text: String| -> *const std::ffi::c_char {
        Box::leak(
            CString::new(text)
                .expect("no NUL in a name or a doc")
                .into_boxed_c_str(),
        )
        .as_ptr()
    };
    let def = Box::leak(Box::new(ffi::PyMethodDef {
        ml_name: leak(name.into()),
        ml_meth: ffi::PyMethodDefPointer {
            PyCFunctionFastWithKeywords: entry,
        },
        ml_flags: ffi::METH_FASTCALL | ffi::METH_KEYWORDS,
        ml_doc: leak(doc),
    }));
    let module_name = m.name()?;
    // SAFETY: `def` lives for the process; the module and its name are live objects.
    let f = unsafe {
        Bound::from_owned_ptr_or_err(
            m.py(),
            ffi::PyCFunction_NewEx(def, m.as_ptr(), module_name.as_ptr()),
        )?
    }
    .cast_into::<PyCFunction>()?;
    m.add(name, f)
}

/// Keyword function `name` called as CPython passes a vectorcall: its positional arguments
/// (given by position or by keyword, none more) and required keywords checked as Python
/// checks a `def`'s, then `body`.
///
/// # Safety
/// `args` holds `nargs` positional values and then one value per name of `kwnames` (a tuple
/// of `str`, or NULL for none), all borrowed for the call, and the calling thread is attached
/// to the interpreter.
pub(super) unsafe fn call(
    py: Python<'_>,
    name: &'static str,
    body: Body,
    args: *const *mut ffi::PyObject,
    nargs: ffi::Py_ssize_t,
    kwnames: *mut ffi::PyObject,
) -> PyResult<*mut ffi::PyObject> {
    // SAFETY: the caller's promise.
    let names = unsafe { Bound::from_borrowed_ptr_or_opt(py, kwnames) }
        .map(|k| k.cast_into::<PyTuple>())
        .transpose()?;
    let nargs = usize::try_from(nargs).unwrap_or(0);
    let count = nargs + names.as_ref().map_or(0, |n| n.len());
    let values: &[*mut ffi::PyObject] = match count {
        0 => &[],
        // SAFETY: the caller's promise: `count` values from `args`.
        _ => unsafe { std::slice::from_raw_parts(args, count) },
    };
    // SAFETY: each value is a live object borrowed for the call.
    let value = |p: *mut ffi::PyObject| unsafe { Bound::from_borrowed_ptr(py, p) };
    let mut kwargs = Kwargs(SmallVec::new());
    if let Some(names) = &names {
        for (k, v) in names.iter().zip(&values[nargs..]) {
            kwargs.0.push((k.cast_into::<PyString>()?, value(*v)));
        }
    }
    let positional: Vec<Bound<'_, PyAny>> = values[..nargs].iter().map(|p| value(*p)).collect();
    let (given, kwargs) = arguments(name, positional, kwargs)?;
    Ok(body(py, given, &kwargs)?.into_ptr())
}

/// The positional arguments of a call of `name`, those given by keyword taken out of its
/// keywords; its mistakes refused with Python's words.
fn arguments<'py>(
    name: &str,
    mut given: Vec<Bound<'py, PyAny>>,
    mut kwargs: Kwargs<'py>,
) -> PyResult<(Vec<Bound<'py, PyAny>>, Kwargs<'py>)> {
    let declared = super::docs::keyword_function(name).expect("a keyword function of FUNCTIONS");
    if declared.bare && given.is_empty() {
        // Keywords alone, to a function without positional or required ones (solve in a
        // loop): nothing to move or check.
        return Ok((given, kwargs));
    }
    let (positional, keywords) = (&declared.positional, &declared.keywords);
    for p in positional.iter().skip(given.len()) {
        if let Some(i) = kwargs.0.iter().position(|(k, _)| k == p) {
            given.push(kwargs.0.remove(i).1);
        }
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
        if !kwargs.has(k) {
            return Err(PyTypeError::new_err(format!(
                "{name}() missing required keyword argument: '{k}'"
            )));
        }
    }
    Ok((given, kwargs))
}
