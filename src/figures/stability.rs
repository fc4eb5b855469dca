//! The stability matrix as a figure (scene `stability-matrix`): one row per case and one
//! column per model and method, each answer classed against the case's physical reference
//! ([`crate::study::stability::Class`]).
//!
//! The classes, statuses and x_jam do not depend on timing, so the figure is the same on
//! every machine; wall times are in `jamchart stability`'s table, not here.

use serde::{Deserialize, Serialize};

use super::{DataFormat, Figure, FigureData, Input, Models};
use crate::config::Config;
use crate::error::{Error, Result};
use crate::models::{ModelKind, ModelSpec};
use crate::scene::{JamStatus, SceneParams};
use crate::study::Reference;
use crate::study::stability::{self, Class};

/// `[chart]` keys of `kind = "stability"`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct StabilitySettings {
    /// Case names to draw, in the matrix's order (default: every case). An empty list is
    /// refused: it once drew every case, the opposite of what it says.
    pub cases: Option<Vec<String>>,
}

impl Figure for StabilitySettings {
    type Data = StabilityData;

    /// Checks that the list names at least one case and that every named case exists.
    fn validate(&self, _input: &Input) -> Result<()> {
        let Some(cases) = &self.cases else {
            return Ok(());
        };
        if cases.is_empty() {
            return Err(Error::invalid(
                "chart.cases",
                "[]",
                "name at least one case, or leave chart.cases out to draw every case",
            ));
        }
        let all = stability::cases(&Config::default());
        for name in cases {
            if !all.iter().any(|c| &c.name == name) {
                let known: Vec<&str> = all.iter().map(|c| c.name.as_str()).collect();
                return Err(Error::invalid(
                    "chart.cases",
                    name,
                    format!(
                        "not a case of the matrix; the cases are {}",
                        known.join(", ")
                    ),
                ));
            }
        }
        Ok(())
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        // Its cases are names from the fixed matrix (checked by validate): at most its 26 rows.
        Ok(())
    }

    /// Runs the matrix of the input's parameters through `models`.
    fn compute(&self, input: &Input, models: &dyn Models) -> Result<StabilityData> {
        let base = Config {
            scene: input.params,
            min_norm: input.min_norm,
            dynamics: input.dynamics,
        };
        self.validate(input)?;
        let all = stability::cases(&base);
        let cases: Vec<_> = match &self.cases {
            None => all,
            Some(named) => all
                .into_iter()
                .filter(|c| named.contains(&c.name))
                .collect(),
        };
        let solve = |s: &ModelSpec, p: &SceneParams| models.solve(s, p);
        let report = stability::run_with(&solve, &base, &cases, &stability::methods(&base))?;
        Ok(StabilityData {
            methods: report.methods,
            cases: (report.cases.into_iter())
                .map(|c| CaseName {
                    name: c.name,
                    what: c.what,
                })
                .collect(),
            rows: (report.rows.into_iter())
                .map(|r| Answer {
                    case: r.case,
                    model: r.model,
                    method: r.method,
                    status: r.status,
                    x_jam_mm: r.x_jam_mm,
                    reference: r.reference,
                    x_error_mm: r.x_error_mm,
                    allowance_mm: r.allowance_mm,
                    class: r.class,
                    reason: r.reason.as_ref().map(|w| w.tag()),
                })
                .collect(),
        })
    }
}

/// A case of the matrix: a row.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CaseName {
    /// Its name, e.g. `contact_1um`.
    pub name: String,
    /// What is extreme about it.
    pub what: String,
}

/// One answer of the matrix: a cell.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Answer {
    /// The case's name.
    pub case: String,
    /// The model.
    pub model: ModelKind,
    /// How it answered: closed_form, exact, clarabel, radau5, dopri5, nonsmooth.
    pub method: &'static str,
    /// Its status.
    pub status: JamStatus,
    /// x_jam in mm.
    pub x_jam_mm: Option<f64>,
    /// The case's physical reference.
    pub reference: Reference,
    /// |x_jam - x_ref| in mm (both jam).
    pub x_error_mm: Option<f64>,
    /// The allowance of `correct` in mm.
    pub allowance_mm: Option<f64>,
    /// The class.
    pub class: Class,
    /// Why there is no trusted answer, if there is none (the reason's tag).
    pub reason: Option<&'static str>,
}

/// The computed matrix: its serde form is its data file (no wall times: they differ between
/// runs).
#[derive(Debug, Clone, Serialize)]
pub struct StabilityData {
    /// The method labels, in column order.
    pub methods: Vec<String>,
    /// The cases, in row order.
    pub cases: Vec<CaseName>,
    /// One answer per case and method, case-major.
    pub rows: Vec<Answer>,
}

impl StabilityData {
    /// The answers of one class.
    pub fn of_class(&self, class: Class) -> impl Iterator<Item = &Answer> {
        self.rows.iter().filter(move |r| r.class == class)
    }
}

impl FigureData for StabilityData {
    const FORMAT: DataFormat = DataFormat::Json;
}
