//! The min-norm solver's tolerance against its error in theta_jam (part of the accuracy report).
//!
//! clarabel decides "held" to its tolerances, so the boundary the bisection finds moves with
//! them. For each tolerance tol the palm scene is solved by clarabel alone (no exact path) with
//! `tol_feas = tol_gap = tol_infeas = tol`, in the paper's translational formulation, and
//! theta_jam is compared with the closed form (corrected Eq. 1), which that formulation equals
//! exactly (module docs of [`crate::minnorm`]). The bisection's own width (`bisection_tol_rad`,
//! 1e-9 rad = 5.7e-8 deg by default) is the floor of the error.

use serde::Serialize;

use super::palm::{self, Formulation, MinNormSettings};
use super::qp::QpSettings;
use crate::error::{Error, Result};
use crate::scene::{JamStatus, SceneParams};
use crate::statics;

/// One tolerance of the study.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ToleranceRow {
    /// clarabel's tol_feas = tol_gap = tol_infeas.
    pub tol: f64,
    /// The min-norm outcome at this tolerance.
    pub status: JamStatus,
    /// theta_jam in deg (None without a jam).
    pub theta_jam_deg: Option<f64>,
    /// |theta_jam - theta_jam(closed form)| in deg (None unless both jam).
    pub error_deg: Option<f64>,
    /// Programs solved by the bisection.
    pub solves: u32,
    /// clarabel iterations over all of them (a deterministic cost).
    pub iterations: u32,
    /// Programs clarabel left undetermined.
    pub undetermined_solves: u32,
}

/// Solves the palm scene `p` with clarabel at each tolerance in `tolerances` (each in (0, 1)),
/// with the other settings of `s` and the translational formulation.
pub fn tolerance_study(
    p: &SceneParams,
    s: &MinNormSettings,
    tolerances: &[f64],
) -> Result<Vec<ToleranceRow>> {
    p.validate()?;
    s.validate()?;
    let oracle = statics::solve(p);
    let oracle_theta = (oracle.status == JamStatus::Jams)
        .then_some(oracle.theta_jam_deg)
        .flatten();
    tolerances
        .iter()
        .map(|&tol| {
            if !(tol.is_finite() && tol > 0.0 && tol < 1.0) {
                return Err(Error::invalid(
                    "min_norm tolerances",
                    tol,
                    "must lie strictly between 0 and 1",
                ));
            }
            let settings = MinNormSettings {
                formulation: Formulation::Translational,
                qp: QpSettings {
                    fast_path: false,
                    tol_feas: tol,
                    tol_gap: tol,
                    tol_infeas: tol,
                    ..s.qp
                },
                ..*s
            };
            let sol = palm::solve(p, &settings)?;
            let theta = (sol.status == JamStatus::Jams)
                .then_some(sol.theta_jam_deg)
                .flatten();
            Ok(ToleranceRow {
                tol,
                status: sol.status,
                theta_jam_deg: sol.theta_jam_deg,
                error_deg: theta.zip(oracle_theta).map(|(a, b)| (a - b).abs()),
                solves: sol.solves,
                iterations: sol.iterations,
                undetermined_solves: sol.undetermined_solves,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At clarabel's default 1e-8 the boundary is the closed form's to 1e-5 deg (the agreement
    /// asked of the min-norm model); a looser tolerance is never more accurate than a tighter one
    /// by more than the floor.
    #[test]
    fn default_tolerance_meets_the_oracle() {
        let rows = tolerance_study(
            &SceneParams::default(),
            &MinNormSettings::default(),
            &[1e-3, 1e-8],
        )
        .unwrap();
        let e = rows[1].error_deg.expect("jams at 1e-8");
        assert!(e < 1e-5, "error {e:e} deg at tol 1e-8");
        assert!(rows.iter().all(|r| r.iterations > 0 && r.solves > 0));
    }

    #[test]
    fn tolerance_outside_the_unit_interval_is_refused() {
        let err = tolerance_study(&SceneParams::default(), &MinNormSettings::default(), &[1.5])
            .unwrap_err()
            .to_string();
        assert!(err.contains("1.5"), "{err}");
    }
}
