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
//! Outcomes are data ([`model::JamStatus`]); [`error::Error`] is only for misuse.
//!
//! ## Grids and charts
//!
//! [`grid`] evaluates a model over any two scene parameters in parallel, bit-identical for any
//! thread count; [`charts`] turns scene files (`charts/<name>.toml`) into byte-identical SVG and
//! PNG design charts with the data behind them (`jamchart render`).

pub mod atomic;
pub mod charts;
pub mod cli;
pub mod config;
pub mod dynamics;
pub mod error;
pub mod grid;
pub mod minnorm;
pub mod model;
pub mod models;
pub mod paper;
pub mod statics;
pub mod study;

pub use error::{Error, Result};
pub use model::{JamStatus, SceneParams};
