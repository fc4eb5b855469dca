//! # jamchart
//!
//! Predicts where a circular workpiece jams while a rotating palm pushes it along a horizontal
//! surface, and draws the design charts an engineer reads theta_jam and x_jam off. It implements,
//! checks and extends H. Parvaz, "Theoretical and Numerical Analysis of Jamming Phenomenon in
//! Positioning of Circular Workpiece on Horizontal Surface", AUT J. Mech. Eng. 4(4) (2020) 553-564.
//!
//! ## The scene
//!
//! A palm hinged at the origin closes (its angle theta above +X decreases) and pushes a disc of
//! radius r and mass m along the ground y = 0. The disc touches the ground at A and the palm at B;
//! its centre is at (x, r) with
//!
//! ```text
//! x = r cot(theta / 2)                                     (Eq. 2, simplified)
//! ```
//!
//! which is also the distance from the hinge to A and to B (equal tangent lengths). As theta
//! decreases the disc moves out along +X. Friction mu_ground acts at A and mu_palm at B (the paper
//! has one mu for both). The disc jams when the ground friction can hold it: the palm then can no
//! longer move it, however it turns.
//!
//! ## Units
//!
//! Lengths in mm, forces in N, mass in kg, gravity in m/s^2, angles in degrees at every interface
//! (radians inside the formulas), time in s. Every name carries its unit where it is not obvious:
//! `radius_mm`, `force_n`, `theta_jam_deg`.
//!
//! ## The three models
//!
//! 1. [`statics`]: the closed form of the corrected Eq. 1. The sliding palm pushes along the edge
//!    of its friction cone; the ground reaction is R_t = F sin(theta - alpha_p),
//!    R_n = m g + F cos(theta - alpha_p), and the disc jams where R_t <= mu_g R_n:
//!
//!    ```text
//!    theta_jam = atan(mu_g) + atan(mu_p) + asin(m g sin(atan mu_g) / F),  x_jam = r cot(theta_jam/2)
//!    ```
//!
//!    With F -> infinity (a palm driven by prescribed motion) theta_jam -> 2 atan(mu) and
//!    x_jam -> r / mu for equal frictions: the self-locking wedge tan(theta/2) <= mu.
//! 2. [`minnorm`] (Section 3.2): the contact forces of least norm that satisfy equilibrium and the
//!    friction cones, solved as a convex program (clarabel); the disc is held exactly where they
//!    exist. The paper's formulation (a translational joint carries the moment; the closing palm
//!    blocks the way back) agrees with the closed form; a rolling disc jams later, at the
//!    self-locking wedge 2 atan(mu).
//! 3. [`dynamics`] (Section 4): a simulation of the paper's Adams model with an IMPACT contact and
//!    Adams' regularised friction, integrated by RADAU5 or DOPRI5 with the jam read off the
//!    disc's speed; a palm driven by motion jams near r/mu, a force-limited palm near the closed
//!    form at its force.
//!
//! The closed form is the oracle: the other two models are tested against it where physics says
//! they must agree.
//!
//! ## One port for every model
//!
//! [`models`] is the single place a model is chosen and run: a [`ModelSpec`] (the model and its
//! settings, chosen by data) goes into [`solve`] (or [`solve_column`] for a line of pushes), and
//! one [`Solution`] comes out (status, theta_jam, x_jam, wall time and the model's own
//! [`Detail`]: a [`statics::StaticsSolution`], [`minnorm::PalmSolution`] or
//! [`dynamics::DynamicsSolution`]). The command line, the Python package, the grids, sweeps,
//! charts and the reports all call it.
//! **To add a model**, write its module and register it in [`models`] (one variant in each of
//! `ModelKind`, `ModelSpec`, `Detail` and one arm of `solve`); **to add a chart kind**, write
//! what it computes in `figures/<kind>.rs` (its settings, and a `Serialize` data type whose
//! serde form is the data file, computed through the port alone) and how it looks in
//! `charts/<kind>.rs` (pure drawing of that data, the read-off derived from it), then name the
//! (settings, data, picture) triple in `charts/kinds.rs`, the kinds' one registration point;
//! its scene `charts/<name>.toml` is built in by `build.rs`.
//!
//! Outcomes are data ([`JamStatus`], with typed reasons in each model's solution); [`Error`]
//! is only for misuse. A push starting above 90 deg is outside every model
//! ([`OutsideModel::PalmLiftsDisc`]): the palm's push points upwards there and can lift
//! the disc, while every model keeps it on the ground.
//!
//! ## Corrections to the paper
//!
//! Each was verified by independent calculation and is pinned by a test.
//!
//! - **Eq. 2** simplifies: r (1 + cos t) / tan t + r sin t = r cot(t/2); x is also the distance
//!   from the hinge to both contact points.
//! - **Eq. 1, sign error**: the paper prints R_n = F_t sin(theta) - F_n cos(theta) + m g; the palm
//!   presses the disc down, and only R_t = F sin(theta - alpha), R_n = m g + F cos(theta - alpha)
//!   (alpha = atan mu) reproduces Table 1. The jam R_t < mu R_n then reduces to
//!   theta_jam = 2 alpha + asin(m g sin(alpha) / F): 44.646 deg and x_jam = 24.355 mm for the
//!   paper's m = 1 kg, g = 9.806 m/s^2, r = 10 mm, F = 200 N, mu = 0.4. F -> infinity gives
//!   the self-locking wedge tan(theta/2) = mu, x = r / mu (25.0 mm, the "threshold" of Fig. 7b).
//! - **Table 1**: the theta columns are the closed form truncated to 0.1 deg and the x columns
//!   r cot(theta/2) of that theta; the mu = 0.30 row's x = 35.50 mm does not match its own
//!   theta = 34.2 deg (r cot(17.1 deg) = 32.51 mm; the closed form gives 32.500 mm). The second
//!   model differs from the first by up to 0.6 % only through the paper's angle scan and solver
//!   tolerances: solved exactly, the minimum-norm model agrees with the closed form.
//! - **Eq. 7**: its moment rows are inconsistent with its force rows (476.7 looks like N cm
//!   against positions in mm; the lever arm 27.38 mm is 3 mm longer than x_jam). With one ground
//!   contact and a translating disc the force rows fix the reaction, so the minimum norm is
//!   trivial there; the moment is carried by the translational joint.
//! - **Section 4**: the printed IMPACT parameters are garbled (four parameters, three numbers); we
//!   use Adams' documented defaults (1e5 N/mm^e, exponent 2.2, 10 N s/mm, 0.01 mm). The palm is
//!   driven by motion, so the simulation's jam tends to r / mu, not the F = 200 N value; the
//!   paper's 25.58 mm at mu = 0.4 is 2.3 % above r / mu, which the 1 mm palm bar's offset
//!   explains. Adams' friction has no true stiction, so a jammed disc still creeps.
//!
//! ## Reports on the models
//!
//! `study` measures the models themselves, every answer through the port: error of x_jam and
//! theta_jam against the scene's physical reference beside wall time and integration error
//! (`jamchart accuracy`), the cost of a design map by each model, and a matrix of stiff and
//! extreme cases classed correct, flagged, failed or wrong (`jamchart stability`).
//!
//! ## Other questions of a scene
//!
//! [`uncertain`] answers a scene whose inputs are known only within a range (the interval of
//! theta_jam and x_jam over the box) or by a distribution (probabilities and quantiles of
//! x_jam); [`design`] turns the question round (the least push that carries the disc to a
//! target, the palm lengths that keep the jams on the palm); [`locator`] holds a disc in a
//! V-type locator (holds, slips or wedges, the capacity, the best and the most robust V).
//!
//! ## Charts
//!
//! [`charts`] turns scene files (`charts/<name>.toml`) into byte-identical SVG and PNG design
//! charts with the data behind them (`jamchart render`); their maps are evaluated in parallel,
//! bit-identical for any thread count.

#![warn(missing_docs)]
#![warn(unnameable_types)]

// The unit tests share fixtures with the integration tests, which name the crate `jamchart`.
#[cfg(test)]
extern crate self as jamchart;

/// Proptest's settings for a unit test of `cases` cases: saved failures live beside the test's
/// source file (`<file>.proptest-regressions`), not in a `proptest-regressions/` folder at the
/// top of the tree, and every run replays them.
#[cfg(test)]
fn proptest_config(cases: u32) -> proptest::test_runner::Config {
    proptest::test_runner::Config {
        cases,
        failure_persistence: Some(Box::new(
            proptest::test_runner::FileFailurePersistence::WithSource("proptest-regressions"),
        )),
        ..Default::default()
    }
}

// The house: settings and their files, the front ends (command line, Python package), the
// grid evaluator, the figures' computations, the reports and the paper's printed numbers.
#[macro_use]
mod settings;

mod atomic;
mod cli;
mod config;
mod csv_out;
mod error;
pub mod figures;
pub mod grid;
mod limits;
mod numbers;
mod paper;
// The Python package (`pip install .`); no Rust API of its own.
#[cfg(feature = "python")]
mod python;
mod scene;
pub mod study;

// The models, each with its settings and its own answer, and the port that runs them.
pub mod dynamics;
pub mod minnorm;
pub mod models;
pub mod statics;

// The other questions of a scene, and the charts.
pub mod ask;
pub mod charts;
pub mod design;
pub mod locator;
#[cfg(feature = "serve")]
pub mod serve;
pub mod uncertain;

#[doc = include_str!("guide.md")]
pub mod guide {}

// Where a library user or a binding starts: the scene, the port with its one solution type,
// the errors.
pub use config::Config;
pub use error::{Error, Fault, Refusal, Result};
pub use limits::Budget;
pub use models::{
    Detail, ModelKind, ModelSpec, Outcome, OutsideModel, Solution, solve, solve_column,
};
pub use scene::{JamStatus, Param, SceneParams};
pub use settings::{Numbers, SettingDoc, documented as settings_documented};

/// The `jamchart` command line (`src/main.rs` calls it): not a library entry.
#[doc(hidden)]
pub use cli::main as run_cli;

/// What the benchmarks (`benches/`) time or compare that no public entry reaches on its own:
/// one minimum-norm program, a range's two corners, and the reference solvers the fast paths
/// are checked against. Not a library entry: it changes with the code it times.
#[doc(hidden)]
pub mod bench_support {
    pub use crate::locator::reference::capacity_clarabel;
    pub use crate::locator::symmetric::applies as closed_form_applies;
    pub use crate::minnorm::contact::{Contact, ContactProblem, Joint, Space, Wrench};
    pub use crate::minnorm::palm::palm_problem;
    pub use crate::minnorm::qp::{solve as solve_program, solve_clarabel};

    /// The interval of theta_jam in deg over the box of `set` around `p` from its two extreme
    /// corners alone: the cheap part of [`crate::uncertain::range::closed_form`].
    pub fn range_corners(
        p: &crate::SceneParams,
        set: &crate::uncertain::UncertainSet,
    ) -> crate::Result<Option<[f64; 2]>> {
        Ok(crate::uncertain::range::ends(p, set)?
            .hull
            .map(|h| h.theta_jam_deg))
    }
}
