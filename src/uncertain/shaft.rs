//! The worked example of the range, distribution and `design` tests and of the uncertainty
//! benchmark: a 25 mm shaft (r = 12.5 mm) of 0.4 kg pushed with 40 N by an 80 mm palm, mu 0.21
//! at both contacts (the middle of a 0.12 to 0.3 friction range); every other setting is the
//! paper's default.

use jamchart::SceneParams;

/// The 25 mm shaft.
pub fn shaft_25mm() -> SceneParams {
    SceneParams {
        radius_mm: 12.5,
        mass_kg: 0.4,
        force_n: 40.0,
        palm_length_mm: 80.0,
        ..Default::default()
    }
    .with_mu(0.21)
}
