//! The work-precision study: error of x_jam against run time for each integrator and tolerance.
//!
//! Each integrator runs at each tolerance (rtol = atol, without the verification run, so that
//! the raw method is measured) several times; the wall time is the median. The error is
//! |x_jam - x_ref| against a reference computed by the *other* integrator at a tight tolerance
//! (if that reference did not jam, by the same integrator, and the row says so). Runs that end
//! without a trusted jam are kept as rows with their status and reason.

use std::time::Instant;

use serde::Serialize;

use super::{DynamicsParams, DynamicsSolution, Method, run};
use crate::error::{Error, Result};
use crate::limits::{self, MAX_RUNS, MAX_TOLERANCES};
use crate::scene::{JamStatus, SceneParams};

/// What to measure.
#[derive(Debug, Clone, PartialEq)]
pub struct StudySettings {
    /// Relative tolerances to try (atol = rtol), each in (0, 1).
    pub tolerances: Vec<f64>,
    /// Timed runs per point, >= 1 (the median is reported).
    pub runs: usize,
    /// Tolerance of the references.
    pub reference_rtol: f64,
}

impl Default for StudySettings {
    fn default() -> Self {
        StudySettings {
            tolerances: vec![1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9],
            runs: 5,
            reference_rtol: 1e-11,
        }
    }
}

impl StudySettings {
    /// Checks the counts: at least 1 and at most the limits of tolerances and runs (the
    /// tolerances' values are checked point by point in [`run_study`]).
    pub fn validate(&self) -> Result<()> {
        limits::check_count(
            "tolerances",
            self.tolerances.len(),
            MAX_TOLERANCES,
            "the number of tolerances",
        )?;
        limits::check_count("runs", self.runs, MAX_RUNS, "the number of runs per point")
    }
}

/// A reference solution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reference {
    /// The integrator that made it.
    pub method: Method,
    /// Its relative tolerance (atol = rtol).
    pub rtol: f64,
    /// Its status.
    pub status: JamStatus,
    /// Its jam position in mm, where it jams.
    pub x_jam_mm: Option<f64>,
    /// Steps taken.
    pub steps: u64,
    /// Why it has no jam, if it has none.
    pub reason: Option<String>,
}

/// One point of the study.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StudyRow {
    /// The integrator.
    pub method: Method,
    /// The relative tolerance tried (atol = rtol).
    pub rtol: f64,
    /// The status it answered.
    pub status: JamStatus,
    /// Its jam position in mm, where it jams.
    pub x_jam_mm: Option<f64>,
    /// |x_jam - x_ref| in mm.
    pub error_mm: Option<f64>,
    /// |x_jam - x_ref| / x_ref.
    pub rel_error: Option<f64>,
    /// Method of the reference used for this row.
    pub reference: Option<Method>,
    /// Median wall time of the runs in s.
    pub median_time_s: f64,
    /// Timed runs.
    pub runs: usize,
    /// Steps taken (accepted).
    pub steps: u64,
    /// Steps rejected by the error control.
    pub rejected_steps: u64,
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
    /// Jacobian evaluations.
    pub jacobian_evals: u64,
    /// Why the row has no trusted jam (cross-check or failure), if it has none.
    pub reason: Option<String>,
}

/// The whole study.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Study {
    /// The references, one per integrator at the reference tolerance.
    pub references: Vec<Reference>,
    /// |x_ref(radau5) - x_ref(dopri5)| / x_ref(radau5), when both jam.
    pub references_rel_diff: Option<f64>,
    /// Each integrator at each tolerance.
    pub rows: Vec<StudyRow>,
}

const METHODS: [Method; 2] = [Method::Radau5, Method::Dopri5];

fn raw(params: &DynamicsParams, method: Method, rtol: f64) -> DynamicsParams {
    let mut raw = *params;
    raw.integrator.method = method;
    raw.integrator.rtol = rtol;
    raw.integrator.atol = Some(rtol);
    raw.verification.verify = false;
    raw
}

fn reason_of(s: &DynamicsSolution) -> Option<String> {
    s.cross_check
        .map(|c| c.to_string())
        .or_else(|| s.failure.map(|f| f.to_string()))
        .or_else(|| (s.status != JamStatus::Jams).then(|| format!("status {}", s.status)))
}

/// Runs the study; `progress(done, total)` is called once before the first point (done = 0) and
/// after each point.
pub fn run_study(
    scene: &SceneParams,
    params: &DynamicsParams,
    settings: &StudySettings,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Study> {
    scene.validate()?;
    params.validate()?;
    params.validate_scene(scene)?;
    settings.validate()?;
    // Each point's parameters must pass `validate`; its error (about rtol, the only key `raw`
    // changes that can fail) is named after the setting that gave the tolerance.
    let named = |key: &str, e: Error| match e {
        Error::InvalidValue { value, reason, .. } => Error::InvalidValue {
            key: key.to_string(),
            value,
            reason,
        },
        e => e,
    };
    let points = (settings.tolerances.iter().map(|&t| ("tolerances", t)))
        .chain([("reference_rtol", settings.reference_rtol)]);
    for (key, t) in points {
        for m in METHODS {
            raw(params, m, t).validate().map_err(|e| named(key, e))?;
        }
    }
    let total = METHODS.len() * (settings.tolerances.len() + 1);
    let mut done = 0;
    progress(done, total);
    let mut references = Vec::new();
    for m in METHODS {
        let s = run::run_once(scene, &raw(params, m, settings.reference_rtol), None);
        references.push(Reference {
            method: m,
            rtol: settings.reference_rtol,
            status: s.status,
            x_jam_mm: s.x_jam_mm.filter(|_| s.status == JamStatus::Jams),
            steps: s.steps,
            reason: reason_of(&s),
        });
        done += 1;
        progress(done, total);
    }
    let x_ref = |m: Method| {
        references
            .iter()
            .find(|r| r.method == m)
            .and_then(|r| r.x_jam_mm)
    };
    let references_rel_diff = match (x_ref(Method::Radau5), x_ref(Method::Dopri5)) {
        (Some(a), Some(b)) => Some((a - b).abs() / a),
        _ => None,
    };
    let mut rows = Vec::new();
    for m in METHODS {
        let other = if m == Method::Radau5 {
            Method::Dopri5
        } else {
            Method::Radau5
        };
        let reference = x_ref(other)
            .map(|x| (other, x))
            .or_else(|| x_ref(m).map(|x| (m, x)));
        for &rtol in &settings.tolerances {
            let p = raw(params, m, rtol);
            let mut times = Vec::with_capacity(settings.runs);
            let mut last = None;
            for _ in 0..settings.runs {
                let t0 = Instant::now();
                let s = run::run_once(scene, &p, None);
                times.push(t0.elapsed().as_secs_f64());
                let failed = s.status == JamStatus::IntegratorFailed;
                last = Some(s);
                // A failure is deterministic: timing it again teaches nothing.
                if failed {
                    break;
                }
            }
            let s = last.expect("runs >= 1");
            times.sort_by(f64::total_cmp);
            let jams = s.status == JamStatus::Jams;
            let err = match (jams, s.x_jam_mm, reference) {
                (true, Some(x), Some((_, xr))) => Some((x - xr).abs()),
                _ => None,
            };
            rows.push(StudyRow {
                method: m,
                rtol,
                status: s.status,
                x_jam_mm: s.x_jam_mm,
                error_mm: err,
                rel_error: err.zip(reference).map(|(e, (_, xr))| e / xr.abs()),
                reference: reference.map(|(rm, _)| rm),
                median_time_s: times[times.len() / 2],
                runs: times.len(),
                steps: s.steps,
                rejected_steps: s.rejected_steps,
                rhs_evals: s.rhs_evals,
                jacobian_evals: s.jacobian_evals,
                reason: reason_of(&s),
            });
            done += 1;
            progress(done, total);
        }
    }
    Ok(Study {
        references,
        references_rel_diff,
        rows,
    })
}
