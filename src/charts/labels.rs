//! The words on a chart: each scene parameter's symbol, unit and axis label, and the subtitle
//! line naming a scene's parameters.

use crate::grid::GridParam;
use crate::model::SceneParams;

/// The symbol of a scene parameter in labels, e.g. `F` for force_n.
pub fn param_symbol(p: GridParam) -> &'static str {
    match p {
        GridParam::Mu => "μ",
        GridParam::MuGround => "μ_ground",
        GridParam::MuPalm => "μ_palm",
        GridParam::RadiusMm => "r",
        GridParam::MassKg => "m",
        GridParam::ForceN => "F",
        GridParam::GravityMS2 => "g",
        GridParam::StartAngleDeg => "θ_start",
        GridParam::PalmLengthMm => "L_palm",
        GridParam::ThetaDeg => "θ",
    }
}

/// The unit of a scene parameter in labels; `-` for the friction coefficients.
pub fn param_unit(p: GridParam) -> &'static str {
    match p {
        GridParam::Mu | GridParam::MuGround | GridParam::MuPalm => "-",
        GridParam::RadiusMm | GridParam::PalmLengthMm => "mm",
        GridParam::MassKg => "kg",
        GridParam::ForceN => "N",
        GridParam::GravityMS2 => "m/s²",
        GridParam::StartAngleDeg | GridParam::ThetaDeg => "deg",
    }
}

/// Axis label of a scene parameter: quantity, symbol and unit.
pub fn axis_label(p: GridParam) -> String {
    let quantity = match p {
        GridParam::Mu => "friction coefficient",
        GridParam::MuGround => "ground friction coefficient",
        GridParam::MuPalm => "palm friction coefficient",
        GridParam::RadiusMm => "disc radius",
        GridParam::MassKg => "disc mass",
        GridParam::ForceN => "palm push",
        GridParam::GravityMS2 => "gravity",
        GridParam::StartAngleDeg => "start angle of the palm",
        GridParam::PalmLengthMm => "palm length",
        GridParam::ThetaDeg => "palm angle",
    };
    // One mu stands for both contacts; the label says so.
    let symbol = match p {
        GridParam::Mu => "μ = μ_ground = μ_palm",
        _ => param_symbol(p),
    };
    format!("{quantity} {symbol} ({})", param_unit(p))
}

/// `symbol = value unit`, e.g. `F = 200 N`.
fn param_value(p: GridParam, v: f64) -> String {
    format!("{} = {v} {}", param_symbol(p), param_unit(p))
}

/// One line naming the scene's parameters for under the title, without the `swept` ones (they
/// are on an axis).
pub fn scene_subtitle(p: &SceneParams, swept: &[GridParam]) -> String {
    scene_subtitle_with("closed-form statics (corrected Eq. 1)", p, swept)
}

/// [`scene_subtitle`] naming another source than the closed form, e.g. "simulation, ...".
pub fn scene_subtitle_with(source: &str, p: &SceneParams, swept: &[GridParam]) -> String {
    let mu = if p.mu_ground == p.mu_palm {
        format!("μ = {}", p.mu_ground)
    } else {
        format!("μ_ground = {}, μ_palm = {}", p.mu_ground, p.mu_palm)
    };
    let shown = [
        GridParam::MassKg,
        GridParam::RadiusMm,
        GridParam::ForceN,
        GridParam::GravityMS2,
    ];
    let parts = std::iter::once((GridParam::Mu, mu)).chain(
        shown
            .into_iter()
            .filter_map(|k| k.get(p).map(|v| (k, param_value(k, v)))),
    );
    let kept: Vec<String> = parts
        .filter(|(k, _)| !swept.contains(k))
        .map(|(_, s)| s)
        .collect();
    format!("{source}: {}", kept.join(", "))
}
