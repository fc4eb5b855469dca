//! The simulated disc (Fig. 5): speed x_dot and position x against time, beside a rigid disc
//! touching the turning palm, and the jam P_jam.
//!
//! One simulation with the scene's `[dynamics]` settings records the series every
//! `series_dt_s`; set `after_jam_s` in the scene's `[dynamics.series]` so the collapse after the
//! jam is visible. Beside the motion: the speed a rigid disc touching the turning palm would
//! have, r omega / (2 sin^2(theta/2)) (the jam is read where x_dot falls below
//! `jam_speed_ratio` of it), and that disc's position r cot(theta/2)
//! ([`Models::touching_disc`]).

use serde::{Deserialize, Serialize};

use super::models::{Live, Models};
use super::{DataFormat, Figure, FigureData, Input};
use crate::csv_out::{Dec, to_csv};
use crate::dynamics::DynamicsParams;
use crate::dynamics::jam::SeriesRow;
use crate::error::{Error, Result};
use crate::models::{Detail, ModelSpec};
use crate::scene::{JamStatus, SceneParams};
use crate::statics;

/// `[chart]` keys of `kind = "time_series"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TimeSeriesSettings {
    /// Sampling interval of the drawn series in s, in [1e-5, 0.1] (default: 0.001; the collapse
    /// at the jam takes a few ms, a pixel of the time axis about 2 ms).
    pub series_dt_s: f64,
}

impl Default for TimeSeriesSettings {
    fn default() -> Self {
        TimeSeriesSettings { series_dt_s: 0.001 }
    }
}

impl Figure for TimeSeriesSettings {
    type Data = TimeSeriesData;

    /// Checks the sampling interval.
    fn validate(&self, _input: &Input) -> Result<()> {
        let dt = self.series_dt_s;
        // Below 1e-5 s a default run records over 150 000 rows for nothing a picture shows.
        if !(dt.is_finite() && (1e-5..=0.1).contains(&dt)) {
            return Err(Error::invalid(
                "chart.series_dt_s",
                dt,
                "the sampling interval lies in [1e-5, 0.1] s",
            ));
        }
        Ok(())
    }

    fn check_size(&self, input: &Input) -> Result<()> {
        let rows = crate::limits::series_rows(
            input.params.start_angle_deg,
            input.dynamics.drive.omega_deg_s,
            self.series_dt_s,
        );
        crate::limits::check_items(
            "chart.series_dt_s and dynamics.drive.omega_deg_s",
            rows,
            crate::limits::SERIES_ROW,
        )
    }

    /// Runs the simulation; a run that failed or recorded fewer than two samples is an error
    /// (it would be drawn as empty panels).
    fn compute(&self, input: &Input, models: &dyn Models) -> Result<TimeSeriesData> {
        let (p, d) = (&input.params, &input.dynamics);
        let spec = ModelSpec::Dynamics {
            params: *d,
            series_dt_s: Some(self.series_dt_s),
        };
        let sol = models.solve(&spec, p)?;
        let failed = |reason: String| Error::ModelFailed {
            scene: String::new(),
            model: "simulation",
            reason,
        };
        let Detail::Dynamics(sol) = sol.detail else {
            return Err(failed(format!("it cannot run this scene ({})", sol.status)));
        };
        if let Some(f) = &sol.failure {
            return Err(failed(format!("the integrator gave up: {f}")));
        }
        if sol.series.len() < 2 {
            return Err(failed(format!(
                "it recorded {} samples (status {})",
                sol.series.len(),
                sol.status
            )));
        }
        Ok(TimeSeriesData {
            params: *p,
            dynamics: *d,
            samples: samples(models, p, d, &sol.series),
            status: sol.status,
            theta_jam_deg: sol.theta_jam_deg,
            jam: sol.t_jam_s.zip(sol.x_jam_mm),
            x_rigid_mm: statics::solve(p).x_rigid_mm.filter(|x| x.is_finite()),
        })
    }
}

/// One sample of the simulated series and the rigid disc at its palm angle: a row of the data
/// file (the same columns for `render` (Fig. 5) and `solve --series`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    /// Time from the start of the push in s.
    pub t_s: Dec,
    /// Palm angle in deg.
    pub theta_deg: Dec,
    /// Disc position (hinge to ground contact) in mm.
    pub x_mm: Dec,
    /// Disc speed in mm/s.
    pub x_dot_mm_s: Dec,
    /// The speed of a rigid disc touching the turning palm, in mm/s.
    pub geometric_speed_mm_s: Dec,
    /// The position of that disc in mm.
    pub touching_x_mm: Dec,
    /// Penetration of the palm into the disc in mm (0 for a rigid contact).
    pub penetration_mm: Dec,
    /// Palm's normal force on the disc in N.
    pub normal_n: Dec,
    /// Palm's friction force on the disc in N.
    pub palm_friction_n: Dec,
    /// Ground's normal force in N.
    pub ground_normal_n: Dec,
    /// Ground's friction force in N.
    pub ground_friction_n: Dec,
}

/// The samples of `rows`, simulated for scene `p` with `d`, beside the rigid disc touching
/// the palm.
pub fn samples(
    models: &dyn Models,
    p: &SceneParams,
    d: &DynamicsParams,
    rows: &[SeriesRow],
) -> Vec<Sample> {
    let theta: Vec<f64> = rows.iter().map(|r| r.theta_deg).collect();
    let rigid = models.touching_disc(p, d, &theta);
    rows.iter()
        .zip(rigid)
        .map(|(r, disc)| Sample {
            t_s: Dec(r.t_s),
            theta_deg: Dec(r.theta_deg),
            x_mm: Dec(r.x_mm),
            x_dot_mm_s: Dec(r.x_dot_mm_s),
            geometric_speed_mm_s: Dec(disc.speed_mm_s),
            touching_x_mm: Dec(disc.x_mm),
            penetration_mm: Dec(r.penetration_mm),
            normal_n: Dec(r.normal_n),
            palm_friction_n: Dec(r.palm_friction_n),
            ground_normal_n: Dec(r.ground_normal_n),
            ground_friction_n: Dec(r.ground_friction_n),
        })
        .collect()
}

/// The time series `rows` of scene `p` as CSV, one row per [`Sample`], units in the header.
pub fn series_csv(p: &SceneParams, d: &DynamicsParams, rows: &[SeriesRow]) -> Vec<u8> {
    to_csv(samples(&Live, p, d, rows))
}

/// The computed time series: its samples are the data file.
#[derive(Debug, Clone, Serialize)]
pub struct TimeSeriesData {
    /// The scene's parameters.
    pub params: SceneParams,
    /// The simulation's settings.
    pub dynamics: DynamicsParams,
    /// The samples, in time order (at least two).
    pub samples: Vec<Sample>,
    /// The simulation's status.
    pub status: JamStatus,
    /// Its theta_jam in deg.
    pub theta_jam_deg: Option<f64>,
    /// Its jam (t_jam in s, x_jam in mm), if it jams.
    pub jam: Option<(f64, f64)>,
    /// The closed form's F -> infinity limit r/mu in mm, where finite.
    pub x_rigid_mm: Option<f64>,
}

impl FigureData for TimeSeriesData {
    const FORMAT: DataFormat = DataFormat::Csv;

    fn csv(&self) -> Vec<u8> {
        to_csv(&self.samples)
    }
}
