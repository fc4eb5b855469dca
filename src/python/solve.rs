//! `jamchart.solve`: one push, numpy arrays of pushes (broadcast, answered in place on the
//! rayon pool with the GIL released, Ctrl-C checked between chunks), or a range or
//! distribution of inputs.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use numpy::{
    PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyReadwriteArrayDyn, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyUserWarning, PyValueError};
use pyo3::prelude::*;

use super::answers::{BoxAnswer, Comparison, Solution, Solutions, shape_text};
use super::entry::Kwargs;
use super::keywords::{self, error, refused};
use crate::ask::{Flow, SolveAnswer, SolveQuestion, Words};
use crate::models::columns::{self, Answers, Finished, Pushes};
use crate::models::{ModelKind, ModelSpec};
use crate::scene::Param;

/// How often a long map looks for Ctrl-C: an interrupt is seen within this and one chunk of
/// work per thread.
const POLL: Duration = Duration::from_millis(50);

/// Closed-form maps smaller than this are answered without a watching thread: a million
/// answers take milliseconds, less than a user can interrupt.
const WATCHED_STATICS: usize = 1 << 22;

/// `jamchart.solve(**keywords)`: see the package's docs (`help(jamchart.solve)`).
pub(super) fn solve<'py>(py: Python<'py>, kwargs: &Kwargs<'py>) -> PyResult<Bound<'py, PyAny>> {
    // Numbers of the scene alone (the common call, often in a loop): the library reads them
    // without a keyword map.
    if let Some(numbers) = keywords::scene_numbers(kwargs.pairs())? {
        let question = SolveQuestion::from_numbers(&numbers).map_err(|e| refused("solve", e))?;
        warn(py, question.warnings(Words::Keys))?;
        if let Some(outcome) = question.outcome().map_err(error)? {
            // `from_numbers` asks `of_scene` of its scene: the scene asks it again.
            let scene = question.config.scene;
            return Ok(Bound::new(py, Solution::later(scene, outcome))?.into_any());
        }
        return one_push(py, &question, ModelKind::Statics);
    }
    let keywords = kwargs.dict(py)?;
    let keywords = keywords.as_ref();
    let given = keywords::given(py, "solve", keywords, true, &["before_mm", "quantiles"])?;
    let scalars: Vec<(Param, f64)> = given
        .keywords
        .0
        .iter()
        .filter_map(|(k, v)| Some((keywords::scene_param(k)?, v.as_float()?)))
        .collect();
    let mut keys: Vec<&str> = given.keywords.0.keys().map(String::as_str).collect();
    keys.extend(given.arrays.iter().map(|(p, _)| p.as_str()));
    SolveQuestion::refuse_two_pushes(&keys).map_err(error)?;
    let question = SolveQuestion::from_keywords(given.keywords).map_err(|e| refused("solve", e))?;
    let [model] = question.models[..] else {
        // Every model: one scene's answers side by side, and which to design to.
        if !question.uncertain.is_empty() || !given.arrays.is_empty() {
            return Err(PyValueError::new_err(
                "model=\"all\" compares the models on one scene: give single values, or call \
                 solve once per model (\"statics\", \"min-norm\", \"dynamics\") for arrays, \
                 ranges and distributions",
            ));
        }
        warn(py, question.warnings(Words::Keys))?;
        let SolveAnswer::Push(answer) = watched(py, |_| question.answer())? else {
            unreachable!("a question without ranges is one push")
        };
        return Ok(Bound::new(py, Comparison { answer: *answer })?.into_any());
    };
    // An array call's scene warnings are its pushes' (`solve_arrays`): the scene the arrays
    // start from holds defaults where they give values.
    match given.arrays.is_empty() {
        true => warn(py, question.warnings(Words::Keys))?,
        false => warn(
            py,
            question.unused_warning(Words::Keys).into_iter().collect(),
        )?,
    }
    if !question.uncertain.is_empty() {
        if let Some((p, _)) = given.arrays.first() {
            return Err(PyValueError::new_err(format!(
                "{} is an array, and a range or a distribution is answered for one scene: give \
                 single values with it, or call solve once per value",
                p.as_str()
            )));
        }
        // Sampled answers take a while: other threads run meanwhile, Ctrl-C stops them.
        let SolveAnswer::Box(answer) = answer_box(py, &question)? else {
            unreachable!("a question with ranges is answered over its box")
        };
        return Ok(Bound::new(py, BoxAnswer { answer })?.into_any());
    }
    if given.arrays.is_empty() {
        return one_push(py, &question, model);
    }
    let spec = model.with(&question.config.min_norm, &question.config.dynamics);
    // A number whose parameter applies after an array's (a key an array's alias sets as well,
    // push_ratio after the mass) is applied per push, after the array.
    let order = |p: &Param| Param::all().position(|q| q == *p);
    let late: Vec<(Param, f64)> = scalars
        .into_iter()
        .filter(|(p, _)| given.arrays.iter().any(|(a, _)| order(a) < order(p)))
        .collect();
    let solutions = solve_arrays(py, &question, &given.arrays, &late, &spec)?;
    Ok(Bound::new(py, solutions)?.into_any())
}

/// The answer of `question`, one push of `model`.
fn one_push<'py>(
    py: Python<'py>,
    question: &SolveQuestion,
    model: ModelKind,
) -> PyResult<Bound<'py, PyAny>> {
    let answer = match model {
        ModelKind::Statics => question.answer(),
        // A simulation or a min-norm search takes a while: other threads run meanwhile.
        _ => py.detach(|| question.answer()),
    }
    .map_err(error)?;
    let SolveAnswer::Push(answer) = answer else {
        unreachable!("a question without ranges is one push")
    };
    Ok(Bound::new(py, Solution::given(answer))?.into_any())
}

/// Answers the pushes of `arrays`, broadcast together over `question`'s scene (with `late`
/// applied to each push after them), into new numpy arrays.
fn solve_arrays<'py>(
    py: Python<'py>,
    question: &SolveQuestion,
    arrays: &[(Param, Bound<'py, PyArrayDyn<f64>>)],
    late: &[(Param, f64)],
    spec: &ModelSpec,
) -> PyResult<Solutions> {
    let shape = broadcast_shape(arrays)?;
    // Before anything is copied or allocated: the answers (a status byte and two float64)
    // and a broadcast copy of each array, per push.
    let count: f64 = shape.iter().map(|&d| d as f64).product();
    let names: Vec<&str> = arrays.iter().map(|(p, _)| p.as_str()).collect();
    let per_push = 17 + 8 * arrays.len() as u64;
    crate::limits::check_pushes(&names.join(", "), count, per_push, spec).map_err(error)?;
    let numpy = py.import("numpy")?;
    // Each array as it is where it has the answers' shape (no copy), broadcast where not.
    let mut held: Vec<(Param, PyReadonlyArrayDyn<'py, f64>)> = Vec::new();
    for (param, a) in arrays {
        let column = match a.len() == 1 || (a.shape() == shape.as_slice() && a.is_c_contiguous()) {
            true => numpy.call_method1("ascontiguousarray", (a,))?,
            false => numpy.call_method1(
                "ascontiguousarray",
                (numpy.call_method1("broadcast_to", (a, shape.clone()))?,),
            )?,
        };
        held.push((*param, column.cast_into::<PyArrayDyn<f64>>()?.readonly()));
    }
    let late: Vec<(Param, [f64; 1])> = late.iter().map(|(p, v)| (*p, [*v])).collect();
    let mut columns: Vec<(Param, &[f64])> = Vec::new();
    for (param, a) in &held {
        let values = a
            .as_slice()
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        columns.push((*param, values));
    }
    columns.extend(late.iter().map(|(p, v)| (*p, &v[..])));
    let pushes = Pushes {
        base: question.config.scene,
        columns,
    };
    let warnings = pushes
        .unit_warnings()
        .into_iter()
        .map(|(i, w)| format!("{w} (the first such push: index {})", index_text(i, &shape)));
    warn(py, warnings.collect())?;
    // SAFETY: the arrays are left unset (calloc's pass to zero them cost as much as a tenth of
    // a closed-form map): `answer_watched` writes every element, and on any error or
    // interrupt the `?` below drops them before Python sees them.
    let (status, theta, x, past) = unsafe {
        (
            PyArrayDyn::<u8>::new(py, shape.clone(), false),
            PyArrayDyn::<f64>::new(py, shape.clone(), false),
            PyArrayDyn::<f64>::new(py, shape.clone(), false),
            PyArrayDyn::<f64>::new(py, shape.clone(), false),
        )
    };
    // An empty array asks nothing: its answers are empty too.
    if shape.iter().product::<usize>() > 0 {
        let (mut s, mut t, mut xw, mut pw): (
            PyReadwriteArrayDyn<u8>,
            PyReadwriteArrayDyn<f64>,
            PyReadwriteArrayDyn<f64>,
            PyReadwriteArrayDyn<f64>,
        ) = (
            status.readwrite(),
            theta.readwrite(),
            x.readwrite(),
            past.readwrite(),
        );
        let out = Answers {
            status: s.as_slice_mut().expect("a new array is contiguous"),
            theta_jam_deg: t.as_slice_mut().expect("a new array is contiguous"),
            x_jam_mm: xw.as_slice_mut().expect("a new array is contiguous"),
            past_palm_x_jam_mm: Some(pw.as_slice_mut().expect("a new array is contiguous")),
        };
        answer_watched(py, spec, &pushes, out)?;
    }
    Ok(Solutions {
        model: spec.kind(),
        status_code: status.unbind(),
        theta_jam_deg: theta.unbind(),
        x_jam_mm: x.unbind(),
        past_palm_x_jam_mm: past.unbind(),
        inputs: arrays
            .iter()
            .map(|(p, a)| (p.as_str(), a.clone().unbind()))
            .collect(),
        varying: varying(
            arrays.iter().map(|(p, _)| p.as_str()),
            late.iter().any(|(p, _)| *p == Param::PushRatio),
        ),
        base: question.config.scene,
    })
}

/// Answers `pushes` into `out` with the GIL released; a long map runs on a thread of its own
/// while this one looks for Ctrl-C every [`POLL`] and stops the map at its next chunk.
fn answer_watched(py: Python<'_>, spec: &ModelSpec, pushes: &Pushes, out: Answers) -> PyResult<()> {
    if matches!(spec, ModelSpec::Statics) && pushes.len() < WATCHED_STATICS {
        return py
            .detach(|| columns::solve_into(spec, pushes, out))
            .map_err(error);
    }
    match watched(py, |stop| {
        columns::solve_into_until(spec, pushes, out, stop)
    })? {
        Finished::All => Ok(()),
        Finished::Stopped { answered } => Err(PyValueError::new_err(format!(
            "the map stopped after {answered} of {} pushes",
            pushes.len()
        ))),
    }
}

/// Runs `work` with the GIL released on a thread of its own while this one looks for Ctrl-C
/// every [`POLL`]: on Ctrl-C, `stop` is set (work that looks at it ends within a chunk) and the
/// `KeyboardInterrupt` is raised once the work has returned. Other Python threads run meanwhile.
pub(super) fn watched<T: Send>(
    py: Python<'_>,
    work: impl FnOnce(&AtomicBool) -> crate::Result<T> + Send,
) -> PyResult<T> {
    let stop = AtomicBool::new(false);
    let (done, interrupt) = py.detach(|| {
        std::thread::scope(|s| {
            let (tx, rx) = mpsc::channel();
            let stop = &stop;
            s.spawn(move || {
                let _ = tx.send(work(stop));
            });
            let mut interrupt: Option<PyErr> = None;
            loop {
                match rx.recv_timeout(POLL) {
                    Ok(done) => return (done, interrupt),
                    Err(mpsc::RecvTimeoutError::Timeout) if interrupt.is_none() => {
                        if let Err(e) = Python::attach(|py| py.check_signals()) {
                            stop.store(true, Ordering::Relaxed);
                            interrupt = Some(e);
                        }
                    }
                    Err(mpsc::RecvTimeoutError::Timeout) => {}
                    Err(mpsc::RecvTimeoutError::Disconnected) => {
                        return (
                            Err(crate::error::Error::Defect(
                                "the work's thread ended without an answer".into(),
                            )),
                            interrupt,
                        );
                    }
                }
            }
        })
    });
    if let Some(e) = interrupt {
        return Err(e);
    }
    done.map_err(error)
}

/// `question`'s answer over its box, watched for Ctrl-C ([`watched`]): a Monte Carlo stops
/// within a chunk of samples per thread.
fn answer_box(py: Python<'_>, question: &SolveQuestion) -> PyResult<SolveAnswer> {
    watched(py, |stop| {
        question.answer_observed(&|_| match stop.load(Ordering::Relaxed) {
            true => Flow::Break(()),
            false => Flow::Continue(()),
        })
    })
}

/// The scene's fields that the arrays `keys` vary from push to push: the fields each sets,
/// and the push where a push ratio sets it (an array of them, or one applied after a mass
/// array: `late`).
pub(super) fn varying<'a>(keys: impl Iterator<Item = &'a str>, late: bool) -> Vec<&'static str> {
    let mut out: Vec<&'static str> = Vec::new();
    for param in keys.filter_map(keywords::scene_param) {
        match param {
            Param::PushRatio => out.push("force_n"),
            p => out.extend(p.fields().0),
        }
    }
    if late {
        out.push("force_n");
    }
    out
}

/// Flat index `i` of an array of `shape` as numpy writes its multi-index: `(0, 3)`, `3`.
fn index_text(i: usize, shape: &[usize]) -> String {
    let mut index: Vec<String> = keywords::multi_index(i, shape)
        .iter()
        .map(usize::to_string)
        .collect();
    match index.len() {
        1 => index.remove(0),
        _ => format!("({})", index.join(", ")),
    }
}

/// The shape the arrays broadcast to, by numpy's rules; the error names two that do not.
fn broadcast_shape(arrays: &[(Param, Bound<'_, PyArrayDyn<f64>>)]) -> PyResult<Vec<usize>> {
    let ndim = arrays.iter().map(|(_, a)| a.ndim()).max().unwrap_or(0);
    let mut shape = vec![1usize; ndim];
    let mut from: Vec<Option<usize>> = vec![None; ndim];
    for (k, (param, a)) in arrays.iter().enumerate() {
        let offset = ndim - a.ndim();
        for (i, &d) in a.shape().iter().enumerate() {
            let at = offset + i;
            if d == shape[at] || d == 1 {
                continue;
            }
            if shape[at] == 1 {
                shape[at] = d;
                from[at] = Some(k);
                continue;
            }
            let other = &arrays[from[at].unwrap_or(0)];
            return Err(PyValueError::new_err(format!(
                "{} has shape {} and {} has shape {}: they do not broadcast together (numpy's \
                 rules: equal lengths or 1 along each axis, counted from the last)",
                other.0.as_str(),
                shape_text(other.1.shape()),
                param.as_str(),
                shape_text(a.shape())
            )));
        }
    }
    Ok(shape)
}

/// Each line as a Python `UserWarning` at the caller's line (the CLI's warnings on stderr),
/// without the flags the CLI names: a keyword is its TOML key.
pub(super) fn warn(py: Python<'_>, lines: Vec<String>) -> PyResult<()> {
    for line in lines {
        let text = without_flags(&line).replace('\0', " ");
        let text = std::ffi::CString::new(text).expect("no NUL");
        // 1: the frame that called the package's function, the user's line.
        PyErr::warn(py, &py.get_type::<PyUserWarning>(), &text, 1)?;
    }
    Ok(())
}

/// `line` without its ` (--flag ...)` asides.
fn without_flags(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut rest = line;
    while let Some(at) = rest.find(" (--") {
        out.push_str(&rest[..at]);
        rest = rest[at..].find(')').map_or("", |end| &rest[at + end + 1..]);
    }
    out.push_str(rest);
    out
}
