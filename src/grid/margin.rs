//! The statics jam margin over a (parameter, theta) grid, with the trigonometry hoisted.
//!
//! Expanding the corrected Eq. 1 margin mu_g R_n - R_t with cos(theta - alpha_p) and
//! sin(theta - alpha_p):
//!
//! ```text
//! margin(theta) = mu_g m g + A cos(theta) + B sin(theta)
//! A = F (mu_g cos alpha_p + sin alpha_p),   B = F (mu_g sin alpha_p - cos alpha_p)
//! ```
//!
//! so a cell costs two multiplications and two additions once the per-parameter coefficients
//! (c0, A, B) and the per-angle (cos theta, sin theta) are tabulated. The tables are computed
//! once, before the parallel loop, so every cell uses the same bits whatever thread runs it.

use rayon::prelude::*;

use super::GridRequest;
use crate::scene::Param;
use crate::scene::SceneParams;

/// The margin of one scene as a function of theta: `c0_n + a_n cos(theta) + b_n sin(theta)`.
///
/// Derived from the corrected Eq. 1 (the statics' ground reaction): margin = mu_g R_n - R_t
/// with R_n = m g + F cos(theta - alpha_p) and R_t = F sin(theta - alpha_p); expanding the
/// difference angles and collecting cos(theta) and sin(theta) gives the three coefficients.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarginCoeffs {
    /// mu_g m g in N.
    pub c0_n: f64,
    /// F (mu_g cos alpha_p + sin alpha_p) in N.
    pub a_n: f64,
    /// F (mu_g sin alpha_p - cos alpha_p) in N.
    pub b_n: f64,
}

impl MarginCoeffs {
    /// The coefficients of scene `p`.
    pub fn new(p: &SceneParams) -> Self {
        let (sa, ca) = p.alpha_palm().sin_cos();
        MarginCoeffs {
            c0_n: p.mu_ground * p.weight_n(),
            a_n: p.force_n * (p.mu_ground * ca + sa),
            b_n: p.force_n * (p.mu_ground * sa - ca),
        }
    }

    /// The margin in N at the angle whose cosine and sine are `(cos_t, sin_t)`.
    #[inline]
    pub fn at(&self, cos_t: f64, sin_t: f64) -> f64 {
        self.c0_n + self.a_n * cos_t + self.b_n * sin_t
    }
}

/// The margin over the grid of `req` (one axis is `theta_deg`), in index order.
pub(super) fn margin_grid(req: &GridRequest, xs: &[f64], ys: &[f64]) -> Vec<f64> {
    let theta_on_x = req.x.param == Param::ThetaDeg;
    let (thetas, other, other_param) = if theta_on_x {
        (xs, ys, req.y.param)
    } else {
        (ys, xs, req.x.param)
    };
    let trig: Vec<(f64, f64)> = thetas
        .iter()
        .map(|t| {
            let (s, c) = t.to_radians().sin_cos();
            (c, s)
        })
        .collect();
    let coeffs: Vec<MarginCoeffs> = other
        .iter()
        .map(|&v| MarginCoeffs::new(&other_param.apply(req.base, v)))
        .collect();

    let nx = xs.len();
    let mut out = vec![0.0; nx * ys.len()];
    out.par_chunks_mut(nx).enumerate().for_each(|(iy, row)| {
        if theta_on_x {
            let k = coeffs[iy];
            for (cell, &(c, s)) in row.iter_mut().zip(&trig) {
                *cell = k.at(c, s);
            }
        } else {
            let (c, s) = trig[iy];
            for (cell, k) in row.iter_mut().zip(&coeffs) {
                *cell = k.at(c, s);
            }
        }
    });
    out
}
