//! `jamchart.design` and `jamchart.vlocator`: keywords -> the library's question -> its answer,
//! as a [`DesignAnswer`] or [`VlocatorAnswer`] object whose attributes are the answer's fields
//! (`jamchart design --format json`'s keys, their units in their names).

use pyo3::exceptions::PyAttributeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::convert::{Lists, to_python};
use super::keywords::{self, refused};
use crate::ask::{self, DesignQuestion, VlocatorQuestion, Words};

/// A Python class over a library answer: each top-level field of its serde form an attribute
/// (nested values as dicts and lists), `to_dict()` the whole document, `repr` the one-line
/// verdict, `str` the command line's report in keyword words.
macro_rules! answer_class {
    ($(#[$doc:meta])* $name:ident($answer:ty)) => {
        $(#[$doc])*
        #[pyclass(frozen, module = "jamchart")]
        pub(super) struct $name {
            answer: $answer,
            /// The answer's serde form, made once.
            document: serde_json::Map<String, serde_json::Value>,
        }

        impl $name {
            fn new(answer: $answer) -> Self {
                let document = match serde_json::to_value(&answer).expect("answers serialise") {
                    serde_json::Value::Object(map) => map,
                    _ => unreachable!("an answer serialises as an object"),
                };
                $name { answer, document }
            }
        }

        #[pymethods]
        impl $name {
            /// Does not pickle: see [`super::unpicklable`].
            fn __reduce__(&self) -> PyResult<()> {
                Err(super::unpicklable(stringify!($name)))
            }

            fn __getattr__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
                match self.document.get(name) {
                    Some(v) => to_python(py, v, Lists::Plain),
                    None => Err(PyAttributeError::new_err(format!(
                        "{} has no attribute '{name}'; it has {}",
                        stringify!($name),
                        self.document.keys().cloned().collect::<Vec<_>>().join(", ")
                    ))),
                }
            }

            fn __dir__(&self) -> Vec<String> {
                let methods = ["to_dict", "headline", "report"].map(String::from);
                self.document.keys().cloned().chain(methods).collect()
            }

            /// The whole answer as dicts and lists: the JSON document of the command line's
            /// `--format json`.
            fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
                to_python(py, &serde_json::Value::Object(self.document.clone()), Lists::Plain)
            }

            /// The verdict in one line.
            #[getter]
            fn headline(&self) -> String {
                self.answer.headline()
            }

            /// The command line's report, the settings named by their keywords.
            #[getter]
            fn report(&self) -> String {
                self.answer.text(Words::Keys)
            }

            fn __str__(&self) -> String {
                self.answer.text(Words::Keys)
            }

            fn __repr__(&self) -> String {
                format!("jamchart.{}({})", stringify!($name), self.answer.headline())
            }

            /// IPython shows the report, not the one-line repr.
            fn _repr_pretty_(&self, p: &Bound<'_, PyAny>, _cycle: bool) -> PyResult<()> {
                p.call_method1("text", (self.answer.text(Words::Keys),))?;
                Ok(())
            }
        }
    };
}

answer_class! {
    /// `jamchart.design`'s answer: the least push, the largest friction and the palm lengths
    /// over the box, each checked by the nonsmooth simulation.
    DesignAnswer(ask::DesignAnswer)
}

answer_class! {
    /// `jamchart.vlocator`'s answer: one V's verdict, forces, capacity and optimum angle, or
    /// over a box the window of included angles that works and the most robust V.
    VlocatorAnswer(ask::VlocatorAnswer)
}

/// `jamchart.design(x_target_mm, **scene)`: see the package's docs.
pub(super) fn design(
    py: Python<'_>,
    keywords: Option<&Bound<'_, PyDict>>,
) -> PyResult<DesignAnswer> {
    let given = keywords::given(py, "design", keywords, false, &[])?;
    let question =
        DesignQuestion::from_keywords(given.keywords).map_err(|e| refused("design", e))?;
    super::solve::warn(py, question.warnings())?;
    // Other threads run meanwhile; Ctrl-C is raised once the answer (seconds) is in.
    let answer = super::solve::watched(py, |_| question.answer())?;
    Ok(DesignAnswer::new(answer))
}

/// `jamchart.vlocator(**locator)`: see the package's docs.
pub(super) fn vlocator(
    py: Python<'_>,
    keywords: Option<&Bound<'_, PyDict>>,
) -> PyResult<VlocatorAnswer> {
    let given = keywords::given(py, "vlocator", keywords, false, &["flank_angles"])?;
    let question =
        VlocatorQuestion::from_keywords(given.keywords).map_err(|e| refused("vlocator", e))?;
    super::solve::warn(py, question.warnings())?;
    // Other threads run meanwhile; Ctrl-C is raised once the answer (seconds) is in.
    let answer = super::solve::watched(py, |_| question.answer())?;
    Ok(VlocatorAnswer::new(answer))
}
