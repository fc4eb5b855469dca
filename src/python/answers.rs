//! What `solve` returns: one push's [`Solution`], many pushes' [`Solutions`] (numpy arrays
//! shaped like the broadcast inputs), a range's or distribution's [`BoxAnswer`]; each a face
//! over the library's answer ([`crate::ask`]).

use std::sync::OnceLock;

use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::{PyImportError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use super::convert::{Lists, serde_to_python};
use crate::ask::{self, SolveAnswer, SolveQuestion, Words};
use crate::models::{ModelKind, Outcome};
use crate::scene::{JamStatus, SceneParams};

/// One push's answer: the status, theta_jam in deg and x_jam in mm (NaN where the model gives
/// none), and the model's whole record as `jamchart solve --format json` prints it.
// A free list: a loop of scalar calls makes and frees one a call, and reuses its memory.
#[pyclass(frozen, module = "jamchart", freelist = 16)]
pub(super) struct Solution {
    /// The library's whole answer, or its outcome and the scene it answers when first read.
    answer: Answer,
}

/// A [`Solution`]'s whole answer.
enum Answer {
    /// The library's answer, of one model, as the library boxed it (moved, not copied).
    Given(Box<ask::PushAnswer>),
    /// The question of a scene's numbers ([`SolveQuestion::of_scene`]), whose outcome the
    /// library gave alone ([`SolveQuestion::outcome`], the closed form in a loop of scalar
    /// calls: its record's extras and the clock are half the call), answered when its record,
    /// time, scene or text is first read. The scene alone is kept (72 bytes), not the
    /// question (488), which every call moved into the object.
    Later {
        outcome: Outcome,
        scene: SceneParams,
        answer: OnceLock<Box<ask::PushAnswer>>,
    },
}

impl Solution {
    /// The answer `answer` of one model.
    pub(super) fn given(answer: Box<ask::PushAnswer>) -> Self {
        Solution {
            answer: Answer::Given(answer),
        }
    }

    /// The answer of [`SolveQuestion::of_scene`]`(scene)`, whose outcome is `outcome`, asked
    /// when first read.
    pub(super) fn later(scene: SceneParams, outcome: Outcome) -> Self {
        Solution {
            answer: Answer::Later {
                outcome,
                scene,
                answer: OnceLock::new(),
            },
        }
    }

    /// The model, status, theta_jam and x_jam.
    fn outcome(&self) -> Outcome {
        match &self.answer {
            Answer::Given(a) => a.results[0].solution.outcome(),
            Answer::Later { outcome, .. } => *outcome,
        }
    }

    /// The library's whole answer.
    fn answer(&self) -> PyResult<&ask::PushAnswer> {
        let (scene, answer) = match &self.answer {
            Answer::Given(a) => return Ok(a),
            Answer::Later { scene, answer, .. } => (scene, answer),
        };
        if let Some(a) = answer.get() {
            return Ok(a);
        }
        let question = SolveQuestion::of_scene(*scene);
        let SolveAnswer::Push(a) = question.answer().map_err(super::keywords::error)? else {
            unreachable!("a question without ranges is one push")
        };
        Ok(answer.get_or_init(|| a))
    }
}

#[pymethods]
impl Solution {
    /// Does not pickle: see [`super::unpicklable`].
    fn __reduce__(&self) -> PyResult<()> {
        Err(super::unpicklable("Solution"))
    }

    /// The model that answered: `statics`, `min-norm` or `dynamics`.
    #[getter]
    fn model(&self) -> &'static str {
        self.outcome().model.as_str()
    }

    /// The outcome of the push: one of `jamchart.STATUSES` (`jams`, `beyond_reach`, ...).
    #[getter]
    fn status(&self) -> &'static str {
        self.outcome().status.as_str()
    }

    /// The palm angle at the jam in deg; NaN where the model gives none.
    #[getter]
    fn theta_jam_deg(&self) -> f64 {
        self.outcome().theta_jam_deg.unwrap_or(f64::NAN)
    }

    /// The disc position at the jam in mm (hinge to ground contact); NaN where the model gives
    /// none.
    #[getter]
    fn x_jam_mm(&self) -> f64 {
        self.outcome().x_jam_mm.unwrap_or(f64::NAN)
    }

    /// Wall time of the answer in s (of the closed form with its record, the first time the
    /// record, the time or the text is read).
    #[getter]
    fn elapsed_s(&self) -> PyResult<f64> {
        Ok(self.answer()?.results[0].solution.elapsed_s)
    }

    /// The scene answered, as a dict of its settings (TOML keys, their units).
    #[getter]
    fn inputs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, &self.answer()?.inputs, Lists::Plain)
    }

    /// The model's whole answer as a dict: the record of `jamchart solve --format json`
    /// (shared keys, then the model's own, `None` where JSON has null).
    #[getter]
    fn record<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, &self.answer()?.results[0], Lists::Plain)
    }

    /// The whole answer as `jamchart solve --format json` prints it: `inputs` and `results`.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, self.answer()?, Lists::Plain)
    }

    /// The command line's report, the settings named by their keywords.
    fn __str__(&self) -> PyResult<String> {
        Ok(self.answer()?.text(Words::Keys))
    }

    fn __repr__(&self) -> String {
        let s = self.outcome();
        match (s.theta_jam_deg, s.x_jam_mm) {
            (Some(t), Some(x)) => format!(
                "jamchart.Solution({}: {}, theta_jam_deg={t:.3}, x_jam_mm={x:.3})",
                s.model, s.status
            ),
            _ => format!("jamchart.Solution({}: {})", s.model, s.status),
        }
    }
}

/// Many pushes' answers, as numpy arrays shaped like the broadcast inputs.
#[pyclass(frozen, module = "jamchart")]
pub(super) struct Solutions {
    pub(super) model: ModelKind,
    /// The statuses as indices into `STATUSES` (uint8), filled in place.
    pub(super) status_code: Py<PyArrayDyn<u8>>,
    pub(super) theta_jam_deg: Py<PyArrayDyn<f64>>,
    pub(super) x_jam_mm: Py<PyArrayDyn<f64>>,
    /// x_jam on a long enough palm where the palm loses the part (`beyond_reach`), NaN
    /// elsewhere ([`crate::models::columns::Answers::past_palm_x_jam_mm`]).
    pub(super) past_palm_x_jam_mm: Py<PyArrayDyn<f64>>,
    /// The keywords that were arrays, each as float64 (not broadcast).
    pub(super) inputs: Vec<(&'static str, Py<PyArrayDyn<f64>>)>,
    /// The scene every push starts from (the single values given).
    pub(super) base: SceneParams,
    /// The scene's fields that differ from push to push (set by an array, or the push set by
    /// a push ratio): `base` holds no answer's value of them.
    pub(super) varying: Vec<&'static str>,
}

impl Solutions {
    /// The scene's settings every push shares, as {key: value}: `base` without the fields the
    /// arrays vary.
    fn shared<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = serde_to_python(py, &self.base, Lists::Plain)?.cast_into::<PyDict>()?;
        for key in &self.varying {
            if dict.contains(*key)? {
                dict.del_item(*key)?;
            }
        }
        Ok(dict)
    }
}

#[pymethods]
impl Solutions {
    /// The model that answered: `statics`, `min-norm` or `dynamics`.
    #[getter]
    fn model(&self) -> &'static str {
        self.model.as_str()
    }

    /// The statuses as a numpy array of str (`jams`, `beyond_reach`, ... as in
    /// `jamchart.STATUSES`), shaped like the inputs.
    #[getter]
    fn status<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let names = py
            .import("numpy")?
            .call_method1("array", (JamStatus::NAMES.to_vec(),))?;
        names.call_method1("take", (self.status_code.bind(py),))
    }

    /// The statuses as indices into `jamchart.STATUSES` (uint8): the array the answers were
    /// written into.
    #[getter]
    fn status_code<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<u8>> {
        self.status_code.bind(py).clone()
    }

    /// The palm angle at each jam in deg (float64, NaN where a push does not jam).
    #[getter]
    fn theta_jam_deg<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        self.theta_jam_deg.bind(py).clone()
    }

    /// The disc position at each jam in mm (float64, NaN where a push does not jam).
    #[getter]
    fn x_jam_mm<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        self.x_jam_mm.bind(py).clone()
    }

    /// Where each push the palm loses past its end (`beyond_reach`) would jam on a long enough
    /// palm, x in mm (float64, the closed form's; NaN for every other push and model).
    #[getter]
    fn past_palm_x_jam_mm<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        self.past_palm_x_jam_mm.bind(py).clone()
    }

    /// The shape of the answers: the inputs' broadcast shape.
    #[getter]
    fn shape<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        PyTuple::new(py, self.theta_jam_deg.bind(py).shape())
    }

    /// The scene's settings: the single values given (and the defaults) that every push
    /// shares, then each keyword given as an array, as float64 arrays.
    #[getter]
    fn inputs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = self.shared(py)?;
        for (key, a) in &self.inputs {
            dict.set_item(*key, a.bind(py))?;
        }
        Ok(dict)
    }

    /// Pickles as its arrays and the scene they start from (multiprocessing, joblib, Dask with
    /// processes).
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let make = py.import("jamchart._jamchart")?.getattr("_solutions")?;
        let inputs = PyDict::new(py);
        for (key, a) in &self.inputs {
            inputs.set_item(*key, a.bind(py))?;
        }
        let base = serde_json::to_string(&self.base).expect("a scene serialises");
        let state = (
            self.model.as_str(),
            self.status_code.bind(py),
            self.theta_jam_deg.bind(py),
            self.x_jam_mm.bind(py),
            self.past_palm_x_jam_mm.bind(py),
            inputs,
            base,
        );
        Ok((make, state).into_pyobject(py)?.into_any())
    }

    fn __len__(&self, py: Python<'_>) -> usize {
        self.theta_jam_deg
            .bind(py)
            .shape()
            .first()
            .copied()
            .unwrap_or(1)
    }

    /// A pandas DataFrame, one row per push: the array inputs (broadcast), the settings every
    /// push shares (`radius_mm`, `mass_kg`, ...), `status`, `theta_jam_deg`, `x_jam_mm` and
    /// `past_palm_x_jam_mm`. Needs pandas.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let pandas = py.import("pandas").map_err(|_| {
            PyImportError::new_err(
                "Solutions.to_pandas() needs pandas, which is not installed: pip install pandas",
            )
        })?;
        let numpy = py.import("numpy")?;
        let shape = self.shape(py)?;
        let columns = PyDict::new(py);
        for (key, a) in &self.inputs {
            let b = numpy.call_method1("broadcast_to", (a.bind(py), &shape))?;
            columns.set_item(*key, b.call_method0("ravel")?)?;
        }
        // The settings every push shares, one value down each column.
        let n: usize = self.theta_jam_deg.bind(py).len();
        for (key, value) in self.shared(py)?.iter() {
            if !columns.contains(&key)? {
                let full = numpy.call_method1("full", (n, value))?;
                columns.set_item(key, full)?;
            }
        }
        columns.set_item("status", self.status(py)?.call_method0("ravel")?)?;
        columns.set_item(
            "theta_jam_deg",
            self.theta_jam_deg.bind(py).call_method0("ravel")?,
        )?;
        columns.set_item("x_jam_mm", self.x_jam_mm.bind(py).call_method0("ravel")?)?;
        columns.set_item(
            "past_palm_x_jam_mm",
            self.past_palm_x_jam_mm.bind(py).call_method0("ravel")?,
        )?;
        pandas.call_method1("DataFrame", (columns,))
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let codes = self.status_code.bind(py).readonly();
        let mut counts = [0usize; JamStatus::NAMES.len()];
        for &c in codes.as_array().iter() {
            counts[usize::from(c)] += 1;
        }
        let seen: Vec<String> = counts
            .iter()
            .zip(JamStatus::NAMES)
            .filter(|(n, _)| **n > 0)
            .map(|(n, name)| format!("{name} {n}"))
            .collect();
        Ok(format!(
            "jamchart.Solutions({}, shape {}: {})",
            self.model,
            shape_text(self.theta_jam_deg.bind(py).shape()),
            seen.join(", ")
        ))
    }
}

/// The answer over a range or a distribution: theta_jam's and x_jam's intervals over the box,
/// where the jam comes earliest and latest, and with a distribution the probabilities and
/// quantiles; `record` is `jamchart solve --format json`'s record.
#[pyclass(frozen, module = "jamchart")]
pub(super) struct BoxAnswer {
    /// The library's answer, of one model.
    pub(super) answer: ask::BoxAnswer,
}

impl BoxAnswer {
    fn record(&self) -> &ask::BoxRecord {
        &self.answer.results[0]
    }
}

#[pymethods]
impl BoxAnswer {
    /// Does not pickle: see [`super::unpicklable`].
    fn __reduce__(&self) -> PyResult<()> {
        Err(super::unpicklable("BoxAnswer"))
    }

    /// The model that answered.
    #[getter]
    fn model(&self) -> &'static str {
        self.record().model
    }

    /// (min, max) of theta_jam in deg over the box; None where no point of it jams.
    #[getter]
    fn theta_jam_deg(&self) -> Option<(f64, f64)> {
        self.record().range.theta_jam_deg.map(|[a, b]| (a, b))
    }

    /// (min, max) of x_jam in mm over the box; None where no point of it jams.
    #[getter]
    fn x_jam_mm(&self) -> Option<(f64, f64)> {
        self.record().range.x_jam_mm.map(|[a, b]| (a, b))
    }

    /// Every status met in the box.
    #[getter]
    fn statuses(&self) -> Vec<&'static str> {
        self.record()
            .range
            .statuses
            .iter()
            .map(|s| s.as_str())
            .collect()
    }

    /// P(x_jam < x) for each x asked (`before_mm`), as [(x_mm, probability)]; empty without
    /// a distribution.
    #[getter]
    fn probability(&self) -> Vec<(f64, f64)> {
        self.record()
            .distribution
            .as_ref()
            .map_or_else(Vec::new, |d| {
                d.before
                    .iter()
                    .map(|b| (b.x_mm, b.probability.value))
                    .collect()
            })
    }

    /// The quantiles of x_jam in mm asked (`quantiles`), as [(q, x_jam_mm)]; empty without a
    /// distribution. A quantile whose jam lies beyond every position a double holds (a
    /// friction below about 5e-308) comes last, with x_jam_mm = inf.
    #[getter]
    fn quantiles(&self) -> Vec<(f64, f64)> {
        self.record()
            .distribution
            .as_ref()
            .map_or_else(Vec::new, |d| {
                let beyond = d.beyond_every_position.iter().map(|&q| (q, f64::INFINITY));
                d.quantiles
                    .iter()
                    .map(|q| (q.q, q.x_jam_mm.value))
                    .chain(beyond)
                    .collect()
            })
    }

    /// The whole answer as a dict: `jamchart solve --format json`'s record for this model.
    #[getter(record)]
    fn record_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, self.record(), Lists::Plain)
    }

    /// The whole answer as `jamchart solve --format json` prints it: `inputs`, `uncertain`
    /// and `results`.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, &self.answer, Lists::Plain)
    }

    /// The command line's report.
    fn __str__(&self) -> String {
        self.answer.text(Words::Keys)
    }

    /// The one-line verdict: the interval of each model, and the probabilities asked.
    fn __repr__(&self) -> String {
        format!("jamchart.BoxAnswer({})", self.answer.headline())
    }
}

/// A shape as Python prints it: `(3,)`, `(4, 3)`.
pub(super) fn shape_text(shape: &[usize]) -> String {
    match shape {
        [one] => format!("({one},)"),
        dims => {
            let all: Vec<String> = dims.iter().map(usize::to_string).collect();
            format!("({})", all.join(", "))
        }
    }
}

/// [`Solutions`] again from what its `__reduce__` gave: how a pickle is read.
#[pyfunction]
pub(super) fn _solutions(
    model: &str,
    status_code: Py<PyArrayDyn<u8>>,
    theta_jam_deg: Py<PyArrayDyn<f64>>,
    x_jam_mm: Py<PyArrayDyn<f64>>,
    past_palm_x_jam_mm: Py<PyArrayDyn<f64>>,
    inputs: &Bound<'_, PyDict>,
    base: &str,
) -> PyResult<Solutions> {
    let bad = |what: String| PyValueError::new_err(format!("not a pickled Solutions: {what}"));
    let model = serde_json::from_value(serde_json::Value::String(model.into()))
        .map_err(|e| bad(e.to_string()))?;
    let base = serde_json::from_str(base).map_err(|e| bad(e.to_string()))?;
    let mut arrays = Vec::new();
    for (k, a) in inputs.iter() {
        let key: String = k.extract()?;
        let param = super::keywords::scene_param(&key).ok_or_else(|| bad(key.clone()))?;
        arrays.push((param.as_str(), a.extract()?));
    }
    Ok(Solutions {
        model,
        status_code,
        theta_jam_deg,
        x_jam_mm,
        past_palm_x_jam_mm,
        varying: super::solve::varying(arrays.iter().map(|(k, _)| *k), false),
        inputs: arrays,
        base,
    })
}

/// Several models' answers to one push (`solve(model="all")`): each model's [`Solution`], which
/// to design to and why, and the answers side by side as a table.
#[pyclass(frozen, module = "jamchart")]
pub(super) struct Comparison {
    /// The library's answer, of every model asked.
    pub(super) answer: ask::PushAnswer,
}

impl Comparison {
    /// Model `k`'s answer alone, as `solve(model=...)` gives it.
    fn one(&self, k: usize) -> Solution {
        let mut answer = self.answer.clone();
        answer.results = vec![self.answer.results[k].clone()];
        Solution::given(Box::new(answer))
    }
}

#[pymethods]
impl Comparison {
    /// Does not pickle: see [`super::unpicklable`].
    fn __reduce__(&self) -> PyResult<()> {
        Err(super::unpicklable("Comparison"))
    }

    /// The models that answered, in order: `statics`, `min-norm`, `dynamics`.
    #[getter]
    fn models(&self) -> Vec<&'static str> {
        let results = &self.answer.results;
        results.iter().map(|r| r.solution.model.as_str()).collect()
    }

    /// Each model's answer by its name, as `solve(model=NAME)` gives it.
    #[getter]
    fn solutions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (k, r) in self.answer.results.iter().enumerate() {
            dict.set_item(r.solution.model.as_str(), Bound::new(py, self.one(k))?)?;
        }
        Ok(dict)
    }

    /// Which answer to design to and why (a slow push, a driven palm, a fast push), and where
    /// the models disagree: the paragraph that ends the report.
    #[getter]
    fn guidance(&self) -> String {
        self.answer.guidance().unwrap_or_default()
    }

    /// The scene answered, as a dict of its settings (TOML keys, their units).
    #[getter]
    fn inputs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, &self.answer.inputs, Lists::Plain)
    }

    /// The whole answer as `jamchart solve --model all --format json` prints it.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, &self.answer, Lists::Plain)
    }

    /// A pandas DataFrame, one row per model: `model`, `status`, `theta_jam_deg`, `x_jam_mm`
    /// (NaN where a model gives none) and `elapsed_s`. Needs pandas.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let pandas = py.import("pandas").map_err(|_| {
            PyImportError::new_err(
                "Comparison.to_pandas() needs pandas, which is not installed: pip install pandas",
            )
        })?;
        let solutions = self.answer.results.iter().map(|r| &r.solution);
        let columns = PyDict::new(py);
        columns.set_item("model", self.models())?;
        let status: Vec<&str> = solutions.clone().map(|s| s.status.as_str()).collect();
        columns.set_item("status", status)?;
        let nan = |v: Option<f64>| v.unwrap_or(f64::NAN);
        let theta: Vec<f64> = solutions.clone().map(|s| nan(s.theta_jam_deg)).collect();
        columns.set_item("theta_jam_deg", theta)?;
        let x: Vec<f64> = solutions.clone().map(|s| nan(s.x_jam_mm)).collect();
        columns.set_item("x_jam_mm", x)?;
        let elapsed: Vec<f64> = solutions.map(|s| s.elapsed_s).collect();
        columns.set_item("elapsed_s", elapsed)?;
        pandas.call_method1("DataFrame", (columns,))
    }

    /// The command line's report, the settings named by their keywords, ending with which
    /// answer to design to.
    fn __str__(&self) -> String {
        self.answer.text(Words::Keys)
    }

    fn __repr__(&self) -> String {
        format!("jamchart.Comparison({})", self.answer.headline())
    }

    /// IPython shows the report, not the one-line repr.
    fn _repr_pretty_(&self, p: &Bound<'_, PyAny>, _cycle: bool) -> PyResult<()> {
        p.call_method1("text", (self.answer.text(Words::Keys),))?;
        Ok(())
    }
}
