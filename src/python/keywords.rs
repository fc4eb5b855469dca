//! A call's keywords as the library's [`Keywords`]: numbers, names, switches and lists as
//! TOML values, a `Range` or a distribution as the command line's text, and the
//! scene's parameters given as numpy arrays set apart for the array entry.

use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyString, PyTuple};
use smallvec::SmallVec;

use crate::ask::Keywords;
use crate::error::Error;
use crate::scene::Param;
use crate::settings::{self, Decl};
use crate::uncertain::Uncertain;

/// The library's error as the exception a Python user expects: `ValueError` for bad input
/// (the message names the key, the value and the valid values), `TypeError` for a keyword
/// the function does not take, `OSError` for a file.
pub(super) fn error(e: Error) -> PyErr {
    match e {
        Error::Io { .. } | Error::UnsafeOutput { .. } => {
            pyo3::exceptions::PyOSError::new_err(e.to_string())
        }
        Error::UnknownKey { .. } => PyTypeError::new_err(e.to_string()),
        e => PyValueError::new_err(e.to_string()),
    }
}

/// [`error`] of a call of `function`: an unknown key as Python words it.
pub(super) fn refused(function: &str, e: Error) -> PyErr {
    match e {
        Error::UnknownKey { key, nearest } => unknown(function, &key, nearest.as_deref()),
        e => error(e),
    }
}

/// The `TypeError` of an unknown keyword, with the nearest known one.
fn unknown(function: &str, key: &str, nearest: Option<&str>) -> PyErr {
    let hint = nearest.map_or(String::new(), |k| format!("; did you mean {k}?"));
    PyTypeError::new_err(format!(
        "{function}() got an unexpected keyword argument '{key}'{hint} (jamchart.keywords() \
         lists them with units)"
    ))
}

/// A distribution of one input, e.g. `jamchart.normal(0.2, 0.03)`: what `solve` answers with
/// an interval, probabilities and quantiles.
#[pyclass(frozen, module = "jamchart", name = "Distribution")]
pub(super) struct Distribution(pub(super) Uncertain);

#[pymethods]
impl Distribution {
    fn __repr__(&self) -> String {
        made(&self.0)
    }

    /// The value a point answer keeps: a uniform's midpoint, a normal's mean, a lognormal's
    /// median.
    #[getter]
    fn nominal(&self) -> f64 {
        self.0.nominal()
    }

    /// The value below which a fraction `p` in [0, 1] of the input lies (the inverse CDF).
    fn quantile(&self, p: f64) -> PyResult<f64> {
        if !(0.0..=1.0).contains(&p) {
            return Err(PyValueError::new_err(format!(
                "quantile: p = {} is not a probability; give a number in [0, 1]",
                settings::number_text(p)
            )));
        }
        Ok(self.0.quantile(p))
    }

    /// The fraction of the input at or below `x` (the CDF).
    fn cdf(&self, x: f64) -> PyResult<f64> {
        if x.is_nan() {
            return Err(PyValueError::new_err("cdf: x is NaN; give a number"));
        }
        Ok(self.0.cdf(x))
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (name, a, b) = match self.0 {
            Uncertain::Uniform { lo, hi } => ("uniform", lo, hi),
            Uncertain::Normal { mean, sd } => ("normal", mean, sd),
            Uncertain::LogNormal { median, sigma } => ("lognormal", median, sigma),
            u => unreachable!("a Distribution holds a distribution, not {u}"),
        };
        let make = py.import("jamchart._jamchart")?.getattr(name)?;
        Ok((make, (a, b)).into_pyobject(py)?.into_any())
    }
}

/// How a face's call that makes `u` is written: `jamchart.normal(0.2, 0.03)`,
/// `jamchart.Range(0.12, 0.3)`.
fn made(u: &Uncertain) -> String {
    let t = settings::number_text;
    let (name, a, b) = match *u {
        Uncertain::Point { value } => return format!("jamchart.Distribution({})", t(value)),
        Uncertain::Range { lo, hi } => ("Range", lo, hi),
        Uncertain::Uniform { lo, hi } => ("uniform", lo, hi),
        Uncertain::Normal { mean, sd } => ("normal", mean, sd),
        Uncertain::LogNormal { median, sigma } => ("lognormal", median, sigma),
    };
    format!("jamchart.{name}({}, {})", t(a), t(b))
}

/// `u`, refused (`ValueError` naming the call that made it, e.g. `jamchart.normal(0.2, -1)`)
/// where its numbers cannot describe any input.
fn checked(u: Uncertain) -> PyResult<Uncertain> {
    match u.shape_error() {
        None => Ok(u),
        Some(why) => Err(PyValueError::new_err(format!("{}: {why}", made(&u)))),
    }
}

/// Normal with mean `mean` and standard deviation `sd`, truncated at 0 (a friction, a push or
/// a mass is never negative): `solve(mu=normal(0.2, 0.03))`, the CLI's `--mu normal(0.2,0.03)`.
#[pyfunction]
pub(super) fn normal(mean: f64, sd: f64) -> PyResult<Distribution> {
    Ok(Distribution(checked(Uncertain::Normal { mean, sd })?))
}

/// Uniform on [`low`, `high`]: `solve(mu=uniform(0.12, 0.3))`, the CLI's
/// `--mu uniform(0.12,0.3)`. For the worst case over the values, without probabilities, give
/// a `Range`.
#[pyfunction]
pub(super) fn uniform(low: f64, high: f64) -> PyResult<Distribution> {
    Ok(Distribution(checked(Uncertain::Uniform {
        lo: low,
        hi: high,
    })?))
}

/// Lognormal: ln X is normal with mean ln(`median`) and standard deviation `sigma`:
/// `solve(force_n=lognormal(40, 0.1))`, the CLI's `--force lognormal(40,0.1)`.
#[pyfunction]
pub(super) fn lognormal(median: f64, sigma: f64) -> PyResult<Distribution> {
    Ok(Distribution(checked(Uncertain::LogNormal {
        median,
        sigma,
    })?))
}

/// Every value from `low` to `high`, none more likely: `solve(mu=Range(0.12, 0.3))` answers the
/// worst case over them (an interval, no probabilities), as the CLI's `--mu 0.12:0.3` (the text
/// `"0.12:0.3"` is the same range).
#[pyclass(frozen, module = "jamchart", name = "Range")]
pub(super) struct Range(pub(super) Uncertain);

#[pymethods]
impl Range {
    #[new]
    fn new(low: f64, high: f64) -> PyResult<Self> {
        Ok(Range(checked(Uncertain::Range { lo: low, hi: high })?))
    }

    /// The low end.
    #[getter]
    fn low(&self) -> f64 {
        self.0.ends().0
    }

    /// The high end.
    #[getter]
    fn high(&self) -> f64 {
        self.0.ends().1
    }

    /// The value a point answer keeps: the midpoint.
    #[getter]
    fn nominal(&self) -> f64 {
        self.0.nominal()
    }

    fn __repr__(&self) -> String {
        made(&self.0)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<Range>().is_ok_and(|o| o.get().0 == self.0)
    }

    fn __hash__(&self) -> u64 {
        let (lo, hi) = self.0.ends();
        lo.to_bits().rotate_left(17) ^ hi.to_bits()
    }

    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let make = py.get_type::<Range>();
        Ok((make, self.0.ends()).into_pyobject(py)?.into_any())
    }
}

/// What the keywords of one call give: the library's keywords, and the scene's parameters
/// given as arrays (of at least one dimension), in the order given.
pub(super) struct Given<'py> {
    /// Every keyword but the arrays, as the library reads them.
    pub keywords: Keywords,
    /// The scene's parameters given as arrays, as float64.
    pub arrays: Vec<(Param, Bound<'py, PyArrayDyn<f64>>)>,
}

/// The scene parameters a keyword names: every parameter a grid axis can vary but the palm
/// angle (the state of a push, not a parameter of its scene).
pub(super) fn scene_param(key: &str) -> Option<Param> {
    Param::all().find(|p| p.as_str() == key && *p != Param::ThetaDeg)
}

/// A call's numbers by keyword, as the library's
/// [`crate::ask::SolveQuestion::from_numbers`] takes them: a dozen at most, held without an
/// allocation.
pub(super) type Numbers = SmallVec<[(&'static str, f64); 12]>;

/// The keywords of a call where each is a scene parameter given one number (a float or an int,
/// a numpy float64 too: what [`given`] reads as one number), as the library's
/// [`crate::ask::SolveQuestion::from_numbers`] takes them; None where any is anything else (a
/// None, a bool, a name, a range, an array...), which [`given`] reads.
pub(super) fn scene_numbers(
    kwargs: &[(Bound<'_, PyString>, Bound<'_, PyAny>)],
) -> PyResult<Option<Numbers>> {
    let mut out = SmallVec::new();
    for (k, v) in kwargs {
        let number = v.is_instance_of::<PyFloat>()
            || (v.is_instance_of::<PyInt>() && !v.is_instance_of::<PyBool>());
        let interned = scene_keys(k.py())
            .iter()
            .find(|(s, _)| s.as_ptr() == k.as_ptr());
        let param = match interned {
            Some(&(_, p)) => Some(p),
            None => scene_param(&k.to_cow()?),
        };
        let (true, Some(param)) = (number, param) else {
            return Ok(None);
        };
        // An int beyond a double's range: `given` raises its own error.
        let Ok(x) = v.extract::<f64>() else {
            return Ok(None);
        };
        out.push((param.as_str(), x));
    }
    Ok(Some(out))
}

/// The scene parameters' keywords as interned Python strings: the keys of a call are these
/// very objects (Python interns the names a call spells), found by identity without reading
/// their text, which under the stable ABI makes a bytes object per key.
fn scene_keys(py: Python<'_>) -> &[(Py<PyString>, Param)] {
    static KEYS: PyOnceLock<Vec<(Py<PyString>, Param)>> = PyOnceLock::new();
    KEYS.get_or_init(py, || {
        let params = Param::all().filter(|p| scene_param(p.as_str()).is_some());
        params
            .map(|p| (PyString::intern(py, p.as_str()).unbind(), p))
            .collect()
    })
}

/// Reads `kwargs` of `function`: a keyword left at None is left out (it is the signature's
/// default; one the function does not list is refused); a scene parameter given an array is
/// set apart when `arrays` (the array entry takes it), and each of `lists` takes a list of
/// numbers.
pub(super) fn given<'py>(
    py: Python<'py>,
    function: &str,
    kwargs: Option<&Bound<'py, PyDict>>,
    arrays: bool,
    lists: &[&str],
) -> PyResult<Given<'py>> {
    let mut out = Given {
        keywords: Keywords::default(),
        arrays: Vec::new(),
    };
    for (k, v) in kwargs.into_iter().flat_map(|d| d.iter()) {
        let key: String = k.extract()?;
        if v.is_none() {
            // Only a None needs the declared names (the rest are checked as the question is
            // built).
            let listed = super::docs::keyword_names(function);
            if !listed.contains(&key.as_str()) {
                let known = listed.iter().copied();
                return Err(unknown(function, &key, crate::ask::nearest(&key, known)));
            }
            continue;
        }
        let param = scene_param(&key).filter(|_| arrays);
        let value = match lists.contains(&key.as_str()) {
            true => list(&key, &v)?,
            false => match value(py, &key, param.is_some(), &v)? {
                Value::One(x) => x,
                Value::Array(a) => {
                    let param = param.expect("only a scene parameter takes an array");
                    // Before its elements are read: a broadcast view of 2^40 pushes is one
                    // number in memory, and reading it took hours.
                    crate::limits::check_items(&key, a.len() as f64, crate::limits::PUSH)
                        .map_err(error)?;
                    check_array(param.decl(), &a)?;
                    out.arrays.push((param, a));
                    continue;
                }
            },
        };
        out.keywords.0.insert(key, value);
    }
    Ok(out)
}

/// A keyword's value: one value, or an array for the array entry.
enum Value<'py> {
    One(toml::Value),
    Array(Bound<'py, PyArrayDyn<f64>>),
}

/// The value of keyword `key`: a number (a numpy scalar too), a name, True or False, a range
/// `Range(low, high)`, a distribution, the CLI's text (`"0.12:0.3"`, `"normal(0.2,0.03)"`), or
/// where `array` (a scene parameter of the array entry) a numpy array of real numbers.
fn value<'py>(
    py: Python<'py>,
    key: &str,
    array: bool,
    v: &Bound<'py, PyAny>,
) -> PyResult<Value<'py>> {
    let one = |x: toml::Value| Ok(Value::One(x));
    if let Ok(b) = v.cast::<PyBool>() {
        return match scene_param(key) {
            Some(_) => Err(PyTypeError::new_err(format!(
                "{key} takes a number or an array of numbers, not a bool"
            ))),
            None => one(toml::Value::Boolean(b.is_true())),
        };
    }
    if v.is_instance_of::<PyInt>()
        && scene_param(key).is_none()
        && let Ok(i) = v.extract::<i64>()
    {
        return one(toml::Value::Integer(i));
    }
    if v.is_instance_of::<PyFloat>() || v.is_instance_of::<PyInt>() {
        return one(toml::Value::Float(v.extract()?));
    }
    if let Ok(d) = v.cast::<Distribution>() {
        return one(toml::Value::String(d.get().0.to_string()));
    }
    if let Ok(r) = v.cast::<Range>() {
        return one(toml::Value::String(r.get().0.to_string()));
    }
    if v.is_instance_of::<PyTuple>() {
        return Err(tuple_refused(key));
    }
    if let Ok(s) = v.cast::<PyString>() {
        return one(toml::Value::String(s.to_cow()?.into_owned()));
    }
    let a = real_array(py, key, v)?;
    if a.ndim() == 0 {
        return one(toml::Value::Float(
            a.get_owned([0; 0].as_slice()).unwrap_or(f64::NAN),
        ));
    }
    match array {
        true => Ok(Value::Array(a)),
        false => Err(PyValueError::new_err(format!(
            "{key} takes a single value, not an array"
        ))),
    }
}

/// The `ValueError` of a tuple given for `key`: numpy reads `(0.12, 0.3)` as two values, a
/// range needs saying so.
pub(super) fn tuple_refused(key: &str) -> PyErr {
    PyValueError::new_err(format!(
        "{key}: a tuple could mean two values or a range; give jamchart.Range(LOW, HIGH) (or the \
         text \"LOW:HIGH\") for every value between, a list or numpy array for those values \
         alone"
    ))
}

/// Most dimensions of an input array: what the numpy crate reads.
const MAX_NDIM: usize = 32;

/// `v` as a float64 numpy array, aligned; refused unless its elements are real numbers (a bool,
/// complex or date array is not a list of numbers, whatever numpy makes of it).
fn real_array<'py>(
    py: Python<'py>,
    key: &str,
    v: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let numpy = py.import("numpy")?;
    let raw = numpy.call_method1("asarray", (v,)).map_err(|e| {
        PyValueError::new_err(format!(
            "{key} takes a number or an array of numbers: {}",
            e.value(py)
        ))
    })?;
    let kind: String = raw.getattr("dtype")?.getattr("kind")?.extract()?;
    if !matches!(kind.as_str(), "f" | "i" | "u") {
        let dtype = raw.getattr("dtype")?.str()?.to_string();
        return Err(PyValueError::new_err(format!(
            "{key} takes a number or an array of numbers, not an array of {dtype}"
        )));
    }
    // rust-numpy reads at most 32 dimensions (numpy 2 makes up to 64) and panics beyond.
    let ndim: usize = raw.getattr("ndim")?.extract()?;
    if ndim > MAX_NDIM {
        return Err(PyValueError::new_err(format!(
            "{key}: an array of {ndim} dimensions; give at most {MAX_NDIM}"
        )));
    }
    let a = numpy.call_method1("asarray", (raw, numpy.getattr("float64")?))?;
    // Aligned (a copy where not): an array read from bytes at an odd offset, as dask's workers
    // receive theirs, is valid numpy but cannot be read as Rust numbers in place.
    let a = numpy.call_method1("require", (a, py.None(), "A"))?;
    Ok(a.cast_into::<PyArrayDyn<f64>>()?)
}

/// A keyword that takes a list of numbers (or one).
fn list(key: &str, v: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    let refuse = || PyValueError::new_err(format!("{key} takes a number or a list of numbers"));
    if v.is_instance_of::<PyBool>() || v.is_instance_of::<PyString>() {
        return Err(refuse());
    }
    let numbers: Vec<f64> = match v.extract::<f64>() {
        Ok(x) => vec![x],
        Err(_) => v.extract().map_err(|_| refuse())?,
    };
    Ok(toml::Value::Array(
        numbers.into_iter().map(toml::Value::Float).collect(),
    ))
}

/// Row-major position `pos` of an array of `shape` as its index along each axis.
pub(super) fn multi_index(pos: usize, shape: &[usize]) -> Vec<usize> {
    let mut rest = pos;
    let mut index: Vec<usize> = shape
        .iter()
        .rev()
        .map(|&d| {
            let i = rest % d.max(1);
            rest /= d.max(1);
            i
        })
        .collect();
    index.reverse();
    index
}

/// Checks every element of `a` against `decl`; the error names the first bad element by its
/// index: `invalid mu[3] = -0.2: friction coefficient must be a finite number >= 0`.
fn check_array(decl: &Decl, a: &Bound<'_, PyArrayDyn<f64>>) -> PyResult<()> {
    let ro = a.readonly();
    let view = ro.as_array();
    // Row-major position, then its index: an indexed walk cost more than the check.
    let first = match view.as_slice() {
        Some(values) => decl.check.first_refused(values),
        None => view.iter().position(|v| !decl.check.accepts(*v)),
    };
    let bad = first.map(|pos| {
        let index = multi_index(pos, view.shape());
        (index, view.iter().nth(pos).copied().unwrap_or(f64::NAN))
    });
    match bad {
        None => Ok(()),
        Some((index, v)) => {
            let at: Vec<String> = index.iter().map(usize::to_string).collect();
            let key = format!("{}[{}]", decl.key, at.join(", "));
            let Err(e) = decl.check_real(v) else {
                unreachable!("the check refused the value")
            };
            let Error::InvalidValue { reason, value, .. } = e else {
                return Err(error(e));
            };
            Err(error(Error::InvalidValue { key, value, reason }))
        }
    }
}
