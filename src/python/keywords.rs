//! A call's keywords read against the settings' one declaration ([`crate::settings`]): the
//! scene's parameters (numbers, numpy arrays, ranges, distributions), the models' settings
//! (single values, at their sections) and the model.

use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyString, PyTuple};

use crate::config::Config;
use crate::error::Error;
use crate::grid::GridParam;
use crate::models::ModelKind;
use crate::settings::{self, Decl};
use crate::uncertain::{Uncertain, UncertainSet};

/// The library's error as the exception a Python user expects: `ValueError` for bad input
/// (the message names the key, the value and the valid values), `OSError` for a file.
pub(super) fn error(e: Error) -> PyErr {
    match e {
        Error::Io { .. } | Error::UnsafeOutput { .. } => {
            pyo3::exceptions::PyOSError::new_err(e.to_string())
        }
        e => PyValueError::new_err(e.to_string()),
    }
}

/// A range or a distribution of one input, e.g. `jamchart.normal(0.2, 0.03)`: what `solve`
/// answers with an interval, probabilities and quantiles.
#[pyclass(frozen, module = "jamchart", name = "Distribution")]
pub(super) struct Distribution(pub(super) Uncertain);

#[pymethods]
impl Distribution {
    fn __repr__(&self) -> String {
        let t = settings::number_text;
        match self.0 {
            Uncertain::Uniform { lo, hi } => format!("jamchart.uniform({}, {})", t(lo), t(hi)),
            Uncertain::Normal { mean, sd } => format!("jamchart.normal({}, {})", t(mean), t(sd)),
            Uncertain::LogNormal { median, sigma } => {
                format!("jamchart.lognormal({}, {})", t(median), t(sigma))
            }
            u => format!("jamchart.Distribution({u})"),
        }
    }

    /// The value a point answer keeps: a uniform's midpoint, a normal's mean, a lognormal's
    /// median.
    #[getter]
    fn nominal(&self) -> f64 {
        self.0.nominal()
    }

    /// The value below which a fraction `p` in [0, 1] of the input lies (the inverse CDF).
    fn quantile(&self, p: f64) -> f64 {
        self.0.quantile(p)
    }

    /// The fraction of the input at or below `x` (the CDF).
    fn cdf(&self, x: f64) -> f64 {
        self.0.cdf(x)
    }
}

/// Normal with mean `mean` and standard deviation `sd`, truncated at 0 (a friction, a push or
/// a mass is never negative): `solve(mu=normal(0.2, 0.03))`, the CLI's `--mu normal(0.2,0.03)`.
#[pyfunction]
pub(super) fn normal(mean: f64, sd: f64) -> Distribution {
    Distribution(Uncertain::Normal { mean, sd })
}

/// Uniform on [`low`, `high`]: `solve(mu=uniform(0.12, 0.3))`, the CLI's
/// `--mu uniform(0.12,0.3)`. A tuple `(low, high)` is a range: its worst case, no
/// probabilities.
#[pyfunction]
pub(super) fn uniform(low: f64, high: f64) -> Distribution {
    Distribution(Uncertain::Uniform { lo: low, hi: high })
}

/// Lognormal: ln X is normal with mean ln(`median`) and standard deviation `sigma`:
/// `solve(force_n=lognormal(40, 0.1))`, the CLI's `--force lognormal(40,0.1)`.
#[pyfunction]
pub(super) fn lognormal(median: f64, sigma: f64) -> Distribution {
    Distribution(Uncertain::LogNormal { median, sigma })
}

/// A scene parameter's value as given.
enum Given<'py> {
    Number(f64),
    Array(Bound<'py, PyArrayDyn<f64>>),
    Uncertain(Uncertain),
}

/// What the keywords of one call say.
pub(super) struct Read<'py> {
    /// The scene (every number given, ranges at their nominal values) and the models'
    /// settings, validated.
    pub config: Config,
    /// The scene parameters given as arrays (of at least one dimension), in the order their
    /// values apply (an alias before the keys it sets, `push_ratio` last), each with the
    /// keyword it was given as.
    pub arrays: Vec<(GridParam, Bound<'py, PyArrayDyn<f64>>)>,
    /// Numbers that apply after an array (a key an array's alias sets as well): per push.
    pub late: Vec<(GridParam, f64)>,
    /// The ranges and distributions.
    pub uncertain: UncertainSet,
    /// The model (default: the closed-form statics).
    pub model: ModelKind,
    /// The keywords the caller takes itself, in the order given.
    pub extras: Vec<(&'static str, Bound<'py, PyAny>)>,
}

/// The scene parameters a keyword names: every parameter a grid axis can vary but the palm
/// angle (the state of a push, not a parameter of its scene).
pub(super) fn scene_param(key: &str) -> Option<GridParam> {
    GridParam::named(key).filter(|p| *p != GridParam::ThetaDeg)
}

/// Reads `kwargs` of function `function`: scene parameters, models' settings, `model`, and
/// the caller's own `extras`.
pub(super) fn read<'py>(
    py: Python<'py>,
    function: &str,
    kwargs: Option<&Bound<'py, PyDict>>,
    extras: &[&'static str],
) -> PyResult<Read<'py>> {
    let mut scene: Vec<(GridParam, Given<'py>)> = Vec::new();
    let mut others = toml::Table::new();
    let mut model = ModelKind::Statics;
    let mut own = Vec::new();
    for (k, v) in kwargs.into_iter().flat_map(|d| d.iter()) {
        let key: String = k.extract()?;
        let key = key.as_str();
        if v.is_none() && key != "model" && !extras.contains(&key) {
            // None is the keyword's default, as the signature shows it.
            if scene_param(key).is_none() && settings::find(key).is_none() {
                return Err(unknown(function, key, extras));
            }
            continue;
        }
        if key == "model" {
            model = model_named(&v)?;
        } else if let Some(x) = extras.iter().find(|x| **x == key) {
            own.push((*x, v));
        } else if let Some(param) = scene_param(key) {
            scene.push((param, given(py, param, &v)?));
        } else if let Some(decl) = settings::find(key).filter(|d| d.section != "scene") {
            insert_at(&mut others, decl, toml_value(decl, &v)?);
        } else {
            return Err(unknown(function, key, extras));
        }
    }
    // The order values apply in: an alias before the keys it sets, push_ratio (which reads
    // the mass and gravity) last.
    let order = |p: &GridParam| GridParam::all().position(|q| q == *p);
    scene.sort_by_key(|(p, _)| order(p));
    let mut config = match others.is_empty() {
        true => Config::default(),
        false => Config::default().overlay(&others).map_err(error)?,
    };
    let (numbers, uncertain) = split_uncertain(&scene)?;
    let mut arrays = Vec::new();
    let mut late = Vec::new();
    for (param, g) in scene {
        if let Given::Array(a) = g {
            arrays.push((param, a));
        }
    }
    for (param, v) in numbers {
        match arrays.iter().any(|(a, _)| order(a) < order(&param)) {
            true => late.push((param, v)),
            false => config.scene = param.apply(config.scene, v),
        }
    }
    // Every path to an answer checks the scene and the model it runs; the models' settings given
    // (a dynamics tolerance asked of the statics too) and the box of a range are checked here.
    if !others.is_empty() || !uncertain.is_empty() {
        config.validate().map_err(error)?;
    }
    Ok(Read {
        config,
        arrays,
        late,
        uncertain,
        model,
        extras: own,
    })
}

/// The numbers of `scene` and its uncertain inputs: each range or distribution checked against
/// its setting as the CLI's `--mu 0.12:0.3` is ([`crate::uncertain::take`]), its nominal value
/// among the numbers.
fn split_uncertain(
    scene: &[(GridParam, Given)],
) -> PyResult<(Vec<(GridParam, f64)>, UncertainSet)> {
    let numbers = || {
        scene.iter().filter_map(|(p, g)| match g {
            Given::Number(v) => Some((*p, *v)),
            _ => None,
        })
    };
    if !scene.iter().any(|(_, g)| matches!(g, Given::Uncertain(_))) {
        return Ok((numbers().collect(), UncertainSet::default()));
    }
    let mut table = toml::Table::new();
    for (p, g) in scene {
        let value = match g {
            Given::Number(v) => toml::Value::Float(*v),
            Given::Uncertain(u) => toml::Value::String(u.to_string()),
            Given::Array(_) => {
                return Err(PyValueError::new_err(format!(
                    "{} is an array, and a range or a distribution is answered for one scene: \
                     give single values with it, or call solve once per value",
                    p.as_str()
                )));
            }
        };
        table.insert(p.as_str().to_string(), value);
    }
    let set = crate::uncertain::take(&mut table, crate::config::scene_decls()).map_err(error)?;
    let order = |p: &GridParam| GridParam::all().position(|q| q == *p);
    let mut numbers: Vec<(GridParam, f64)> = table
        .iter()
        .filter_map(|(k, v)| Some((scene_param(k)?, v.as_float()?)))
        .collect();
    numbers.sort_by_key(|(p, _)| order(p));
    Ok((numbers, set))
}

/// A scene parameter's value: a number, a numpy array (anything `numpy.asarray` reads as
/// float64), a range `(low, high)`, a distribution, or the CLI's text (`"0.12:0.3"`,
/// `"normal(0.2,0.03)"`). Each number is checked against the parameter's declaration.
fn given<'py>(py: Python<'py>, param: GridParam, v: &Bound<'py, PyAny>) -> PyResult<Given<'py>> {
    let decl = param.decl();
    let number = |x: f64| -> PyResult<Given<'py>> {
        decl.check_real(x).map_err(error)?;
        Ok(Given::Number(x))
    };
    let uncertain = |u: Uncertain| -> PyResult<Given<'py>> {
        match u {
            Uncertain::Point { value } => number(value),
            u if decl.uncertain => Ok(Given::Uncertain(u)),
            u => Err(PyValueError::new_err(
                Error::invalid(
                    decl.key,
                    u,
                    format!(
                        "{} takes a single number or an array; a range or a distribution is \
                         taken by {}",
                        decl.key,
                        takers()
                    ),
                )
                .to_string(),
            )),
        }
    };
    if v.is_exact_instance_of::<PyFloat>() {
        return number(v.extract()?);
    }
    if v.is_instance_of::<PyInt>() && !v.is_instance_of::<PyBool>() {
        return number(v.extract::<f64>()?);
    }
    if let Ok(d) = v.cast::<Distribution>() {
        return uncertain(d.get().0);
    }
    if let Ok(t) = v.cast::<PyTuple>() {
        let pair: Option<(f64, f64)> = t.extract().ok();
        let Some((lo, hi)) = pair else {
            return Err(PyValueError::new_err(format!(
                "{}: a tuple is a range (low, high) of two numbers; give an array (a list or \
                 numpy array) for many values",
                decl.key
            )));
        };
        return uncertain(Uncertain::Range { lo, hi });
    }
    if let Ok(s) = v.cast::<PyString>() {
        let text = s.to_cow()?;
        let text = text.as_ref();
        let u = Uncertain::parse(text).map_err(|why| {
            PyValueError::new_err(format!("invalid {} = {text}: {why}", decl.key))
        })?;
        return uncertain(u);
    }
    if v.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{} takes a number or an array of numbers, not a bool",
            decl.key
        )));
    }
    let numpy = py.import("numpy")?;
    let a = numpy
        .call_method1("asarray", (v, numpy.getattr("float64")?))
        .map_err(|e| {
            PyValueError::new_err(format!(
                "{} takes a number or an array of numbers: {}",
                decl.key,
                e.value(py)
            ))
        })?;
    // Aligned (a copy where not): an array read from bytes at an odd offset, as dask's workers
    // receive theirs, is valid numpy but cannot be read as Rust numbers in place.
    let a = numpy.call_method1("require", (a, py.None(), "A"))?;
    let a = a.cast_into::<PyArrayDyn<f64>>()?;
    if a.ndim() == 0 {
        return number(a.get_owned([0; 0].as_slice()).unwrap_or(f64::NAN));
    }
    check_array(decl, &a)?;
    Ok(Given::Array(a))
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
        let mut rest = pos;
        let mut index: Vec<usize> = view
            .shape()
            .iter()
            .rev()
            .map(|&d| {
                let i = rest % d.max(1);
                rest /= d.max(1);
                i
            })
            .collect();
        index.reverse();
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

/// `mu, mu_ground, mu_palm, mass_kg and force_n`: the scene's settings that take a range or a
/// distribution.
pub(super) fn takers() -> String {
    let names: Vec<&str> = crate::config::scene_decls()
        .filter(|d| d.uncertain)
        .map(|d| d.key)
        .collect();
    match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => names.join(""),
    }
}

/// The model named `v`: `statics`, `min-norm` (or `min_norm`), `dynamics`.
fn model_named(v: &Bound<'_, PyAny>) -> PyResult<ModelKind> {
    let names: Vec<&str> = ModelKind::ALL.iter().map(|k| k.as_str()).collect();
    let text: String = v.extract().map_err(|_| {
        PyTypeError::new_err(format!("model is a name: one of {}", names.join(", ")))
    })?;
    ModelKind::ALL
        .into_iter()
        .find(|k| k.as_str() == text || k.as_str().replace('-', "_") == text)
        .ok_or_else(|| {
            error(Error::invalid(
                "model",
                &text,
                format!("the models are {}", names.join(", ")),
            ))
        })
}

/// `v` as the TOML value of setting `decl` (a switch, a whole number, a number or a name).
fn toml_value(decl: &Decl, v: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    use crate::settings::Kind;
    let refuse = |what: &str| {
        PyValueError::new_err(format!(
            "invalid {} = {}: {} takes {what}; arrays are taken by the scene's parameters ({})",
            decl.path(),
            v.repr().map_or_else(|_| "?".into(), |r| r.to_string()),
            decl.key,
            GridParam::all()
                .filter(|p| *p != GridParam::ThetaDeg)
                .map(GridParam::as_str)
                .collect::<Vec<_>>()
                .join(", ")
        ))
    };
    Ok(match decl.kind {
        Kind::Switch => toml::Value::Boolean(
            v.cast::<PyBool>()
                .map_err(|_| refuse("True or False"))?
                .is_true(),
        ),
        Kind::Choice(names) => toml::Value::String(
            v.extract()
                .map_err(|_| refuse(&format!("one of {}", names.join(", "))))?,
        ),
        Kind::Count => {
            if v.is_instance_of::<PyBool>() {
                return Err(refuse("a whole number"));
            }
            toml::Value::Integer(v.extract().map_err(|_| refuse("a whole number"))?)
        }
        _ => {
            if v.is_instance_of::<PyBool>() || v.is_instance_of::<PyString>() {
                return Err(refuse("a number"));
            }
            toml::Value::Float(v.extract().map_err(|_| refuse("a number"))?)
        }
    })
}

/// Puts `value` at `decl`'s section and key in `table` (`dynamics.integrator.method`).
fn insert_at(table: &mut toml::Table, decl: &Decl, value: toml::Value) {
    decl.section_in(table).insert(decl.key.to_string(), value);
}

/// Every keyword `function` takes: `model`, the scene's parameters, the models' settings and
/// `extras`.
pub(super) fn all_keywords(extras: &[&'static str]) -> Vec<&'static str> {
    let scene = GridParam::all()
        .filter(|p| *p != GridParam::ThetaDeg)
        .map(GridParam::as_str);
    let models = settings::palm_family()
        .filter(|d| d.section != "scene")
        .map(|d| d.key);
    std::iter::once("model")
        .chain(scene)
        .chain(models)
        .chain(extras.iter().copied())
        .collect()
}

/// The `TypeError` of an unknown keyword, with the nearest known ones.
fn unknown(function: &str, key: &str, extras: &[&'static str]) -> PyErr {
    let all = all_keywords(extras);
    let mut near: Vec<(usize, &str)> = all
        .iter()
        .map(|k| (edit_distance(key, k), *k))
        .filter(|(d, k)| *d <= 2.max(key.len() / 4) || k.starts_with(key))
        .collect();
    near.sort();
    let hint = match near.first() {
        Some((_, k)) => format!("; did you mean {k}?"),
        None => String::new(),
    };
    PyTypeError::new_err(format!(
        "{function}() got an unexpected keyword argument '{key}'{hint} (jamchart.keywords() \
         lists them with units)"
    ))
}

/// Levenshtein distance between two keys (short ASCII words).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}
