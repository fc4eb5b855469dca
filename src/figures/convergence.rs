//! The min-norm program's convergence (Fig. 4): clarabel's interior-point iterations at the
//! jam, objective phi^2 (N^2) and the relative primal and dual residuals.
//!
//! The jam angle comes from the scene's min-norm settings (the exact path answers it without
//! iterations); the trace is clarabel's at that angle ([`Models::min_norm_trace`]).

use serde::{Deserialize, Serialize};

use super::{DataFormat, Figure, FigureData, Input, Models};
use crate::csv_out::{Dec, to_csv};
use crate::error::{Error, Result};
use crate::minnorm::{HoldStatus, MinNormSettings};
use crate::models::ModelSpec;
use crate::scene::{JamStatus, SceneParams};

/// `[chart]` keys of `kind = "convergence"`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ConvergenceSettings {
    /// Palm angle of the trace in deg, in (0, 180) (default: the min-norm theta_jam, or the
    /// start angle when the disc does not jam).
    pub theta_deg: Option<f64>,
}

impl Figure for ConvergenceSettings {
    type Data = ConvergenceData;

    /// Checks the angle.
    fn validate(&self, _input: &Input) -> Result<()> {
        if let Some(t) = self.theta_deg
            && !(t.is_finite() && t > 0.0 && t < 180.0)
        {
            return Err(Error::invalid(
                "chart.theta_deg",
                t,
                "the palm angle lies in (0, 180) deg",
            ));
        }
        Ok(())
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        Ok(())
    }

    /// Finds theta_jam by the min-norm model (unless the settings give the angle), then
    /// traces clarabel there.
    fn compute(&self, input: &Input, models: &dyn Models) -> Result<ConvergenceData> {
        let (p, s) = (&input.params, &input.min_norm);
        let (theta_deg, at) = match self.theta_deg {
            Some(t) => (t, TraceAt::Given),
            None => {
                let sol = models.solve(&ModelSpec::MinNorm(*s), p)?;
                match sol.theta_jam_deg {
                    Some(t) => (t, TraceAt::ThetaJam),
                    None => (p.start_angle_deg, TraceAt::Start(sol.status)),
                }
            }
        };
        let t = models.min_norm_trace(p, theta_deg, s)?;
        // No iteration to draw: the figure fails instead of drawing empty panels.
        if t.trace.is_empty() {
            return Err(Error::ModelFailed {
                scene: String::new(),
                model: "min-norm program",
                reason: format!(
                    "clarabel recorded no iteration at {theta_deg} deg ({})",
                    held_words(t.status)
                ),
            });
        }
        let rows = t
            .trace
            .iter()
            .map(|p| TraceRow {
                theta_deg: Dec(theta_deg),
                iteration: p.iteration as usize,
                objective_n2: Dec(p.objective_n2),
                res_primal: Dec(p.res_primal),
                res_dual: Dec(p.res_dual),
            })
            .collect();
        Ok(ConvergenceData {
            params: *p,
            min_norm: *s,
            theta_deg,
            at,
            status: t.status,
            rows,
        })
    }
}

/// Where the trace was taken.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TraceAt {
    /// At the angle the settings give.
    Given,
    /// At the min-norm model's theta_jam.
    ThetaJam,
    /// At the start angle: the model found no jam (its status).
    Start(JamStatus),
}

/// One interior-point iteration: a row of the data file.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TraceRow {
    /// The palm angle of the trace in deg.
    pub theta_deg: Dec,
    /// The iteration, from 0.
    pub iteration: usize,
    /// The objective phi^2 = sum |f|^2 in N^2 (Eq. 4).
    pub objective_n2: Dec,
    /// The relative primal residual (equilibrium, cones).
    pub res_primal: Dec,
    /// The relative dual residual.
    pub res_dual: Dec,
}

/// The computed trace: its rows are the data file.
#[derive(Debug, Clone, Serialize)]
pub struct ConvergenceData {
    /// The scene's parameters.
    pub params: SceneParams,
    /// The min-norm settings of the trace (formulation, clarabel's tolerances).
    pub min_norm: MinNormSettings,
    /// The palm angle of the trace in deg.
    pub theta_deg: f64,
    /// Where it was taken.
    pub at: TraceAt,
    /// clarabel's verdict there.
    pub status: HoldStatus,
    /// One row per iteration (never empty).
    pub rows: Vec<TraceRow>,
}

impl FigureData for ConvergenceData {
    const FORMAT: DataFormat = DataFormat::Csv;

    /// The rows: palm angle (deg), iteration, objective (N^2), residuals.
    fn csv(&self) -> Vec<u8> {
        to_csv(&self.rows)
    }
}

/// A hold status in words: "held", "not held", "undetermined".
pub fn held_words(s: HoldStatus) -> &'static str {
    match s {
        HoldStatus::Held => "held",
        HoldStatus::NotHeld => "not held",
        HoldStatus::Undetermined => "undetermined",
    }
}
