//! What `solve` returns: one push's [`Solution`], many pushes' [`Solutions`] (numpy arrays
//! shaped like the broadcast inputs), a range's or distribution's [`BoxAnswer`]; each a face
//! over the library's answer ([`crate::ask`]).

use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyImportError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use super::convert::{Lists, serde_to_python};
use crate::ask::{self, Words};
use crate::models::{self, ModelKind};
use crate::scene::{JamStatus, SceneParams};

/// One push's answer: the status, theta_jam in deg and x_jam in mm (NaN where the model gives
/// none), and the model's whole record as `jamchart solve --format json` prints it.
#[pyclass(frozen, module = "jamchart")]
pub(super) struct Solution {
    /// The library's answer, of one model.
    pub(super) answer: ask::PushAnswer,
}

impl Solution {
    fn solution(&self) -> &models::Solution {
        &self.answer.results[0].solution
    }
}

#[pymethods]
impl Solution {
    /// The model that answered: `statics`, `min-norm` or `dynamics`.
    #[getter]
    fn model(&self) -> &'static str {
        self.solution().model.as_str()
    }

    /// The outcome of the push: one of `jamchart.STATUSES` (`jams`, `beyond_reach`, ...).
    #[getter]
    fn status(&self) -> &'static str {
        self.solution().status.as_str()
    }

    /// The palm angle at the jam in deg; NaN where the model gives none.
    #[getter]
    fn theta_jam_deg(&self) -> f64 {
        self.solution().theta_jam_deg.unwrap_or(f64::NAN)
    }

    /// The disc position at the jam in mm (hinge to ground contact); NaN where the model gives
    /// none.
    #[getter]
    fn x_jam_mm(&self) -> f64 {
        self.solution().x_jam_mm.unwrap_or(f64::NAN)
    }

    /// Wall time of the answer in s.
    #[getter]
    fn elapsed_s(&self) -> f64 {
        self.solution().elapsed_s
    }

    /// The scene answered, as a dict of its settings (TOML keys, their units).
    #[getter]
    fn inputs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, &self.answer.inputs, Lists::Plain)
    }

    /// The model's whole answer as a dict: the record of `jamchart solve --format json`
    /// (shared keys, then the model's own, `None` where JSON has null).
    #[getter]
    fn record<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, &self.answer.results[0], Lists::Plain)
    }

    /// The whole answer as `jamchart solve --format json` prints it: `inputs` and `results`.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        serde_to_python(py, &self.answer, Lists::Plain)
    }

    /// The command line's report, the settings named by their keywords.
    fn __str__(&self) -> String {
        self.answer.text(Words::Keys)
    }

    fn __repr__(&self) -> String {
        let s = self.solution();
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
    /// elsewhere ([`crate::models::columns::past_palm_into`]).
    pub(super) past_palm_x_jam_mm: Py<PyArrayDyn<f64>>,
    /// The keywords that were arrays, each as float64 (not broadcast).
    pub(super) inputs: Vec<(&'static str, Py<PyArrayDyn<f64>>)>,
    /// The scene every push starts from (the single values given).
    pub(super) base: SceneParams,
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

    /// The scene's settings: the single values given (and the defaults), then each keyword
    /// given as an array, as float64 arrays.
    #[getter]
    fn inputs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = serde_to_python(py, &self.base, Lists::Plain)?.cast_into::<PyDict>()?;
        for (key, a) in &self.inputs {
            dict.set_item(*key, a.bind(py))?;
        }
        Ok(dict)
    }

    fn __len__(&self, py: Python<'_>) -> usize {
        self.theta_jam_deg
            .bind(py)
            .shape()
            .first()
            .copied()
            .unwrap_or(1)
    }

    /// A pandas DataFrame, one row per push: the array inputs (broadcast), `status`,
    /// `theta_jam_deg`, `x_jam_mm` and `past_palm_x_jam_mm`. Needs pandas.
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
