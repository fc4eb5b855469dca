//! Each model's own answer through the port ([`jamchart::solve`]), as the tests read it.

use jamchart::dynamics::{DynamicsParams, DynamicsSolution};
use jamchart::minnorm::{MinNormSettings, PalmSolution};
use jamchart::statics::StaticsSolution;
use jamchart::{Detail, ModelSpec, SceneParams};

/// The port's answer for `p` by `spec`, the model's own part.
fn detail(spec: &ModelSpec, p: &SceneParams) -> jamchart::Result<Detail> {
    Ok(jamchart::solve(spec, p)?.detail)
}

/// The closed form's answer for `p`. Panics on an invalid scene and where the port answers
/// `outside_model` instead (a push starting above 90 deg).
pub fn statics(p: &SceneParams) -> StaticsSolution {
    match detail(&ModelSpec::Statics, p).expect("a valid scene") {
        Detail::Statics(s) => s,
        other => panic!("the closed form did not answer {p:?}: {other:?}"),
    }
}

/// The min-norm model's answer for `p` with `settings`. Panics where the port answers
/// `outside_model` instead.
pub fn min_norm(p: &SceneParams, settings: &MinNormSettings) -> jamchart::Result<PalmSolution> {
    match detail(&ModelSpec::MinNorm(*settings), p)? {
        Detail::MinNorm(s) => Ok(s),
        other => panic!("the min-norm model did not answer {p:?}: {other:?}"),
    }
}

/// One simulation of `scene` with `params`, the time series every `series_dt_s` s when given.
/// Panics where the port answers `outside_model` instead of simulating (no mass, a push
/// starting above 90 deg).
pub fn simulate(
    scene: &SceneParams,
    params: &DynamicsParams,
    series_dt_s: Option<f64>,
) -> jamchart::Result<DynamicsSolution> {
    let spec = ModelSpec::Dynamics {
        params: *params,
        series_dt_s,
    };
    match detail(&spec, scene)? {
        Detail::Dynamics(s) => Ok(*s),
        other => panic!("the simulation did not run for {scene:?}: {other:?}"),
    }
}
