//! The words on a chart: each scene parameter's symbol, unit and axis label, and the subtitle
//! line naming a scene's parameters.

use crate::scene::Param;
use crate::scene::SceneParams;

/// The symbol of a scene parameter in labels, e.g. `F` for force_n (its declaration's).
pub fn param_symbol(p: Param) -> &'static str {
    p.decl().symbol
}

/// The unit of a scene parameter in labels; `-` for the friction coefficients.
pub fn param_unit(p: Param) -> &'static str {
    p.decl().unit
}

/// Axis label of a scene parameter: quantity, symbol and unit. An alias names what it sets
/// (`μ = μ_ground = μ_palm`).
pub fn axis_label(p: Param) -> String {
    let d = p.decl();
    let mut symbol = d.symbol.to_string();
    for k in d.sets {
        if let Some(set) = Param::named(k) {
            symbol = format!("{symbol} = {}", param_symbol(set));
        }
    }
    format!("{} {symbol} ({})", d.quantity, d.unit)
}

/// `symbol = value unit`, e.g. `F = 200 N`; a dimensionless one without unit (`μ = 0.27`).
pub fn param_value(p: Param, v: f64) -> String {
    match param_unit(p) {
        "-" => format!("{} = {v}", param_symbol(p)),
        unit => format!("{} = {v} {unit}", param_symbol(p)),
    }
}

/// One line naming the scene's parameters for under the title, without the `swept` ones (they
/// are on an axis).
pub fn scene_subtitle(p: &SceneParams, swept: &[Param]) -> String {
    scene_subtitle_with("closed-form statics (corrected Eq. 1)", p, swept)
}

/// [`scene_subtitle`] naming another source than the closed form, e.g. "simulation, ...".
pub fn scene_subtitle_with(source: &str, p: &SceneParams, swept: &[Param]) -> String {
    scene_subtitle_given(source, p, swept, &[])
}

/// [`scene_subtitle_with`] with the parameters of `given` named by their own text instead of
/// their value (e.g. `μ = 0.12 to 0.3 (curves at 0.21)` for a range drawn as a band).
pub fn scene_subtitle_given(
    source: &str,
    p: &SceneParams,
    swept: &[Param],
    given: &[(Param, String)],
) -> String {
    let own = |k: Param| given.iter().find(|(g, _)| *g == k).map(|(_, t)| t.clone());
    let split = own(Param::MuGround).is_some() || own(Param::MuPalm).is_some();
    let mu = match own(Param::Mu) {
        Some(t) => t,
        None if p.mu_ground == p.mu_palm && !split => format!("μ = {}", p.mu_ground),
        None => format!(
            "{}, {}",
            own(Param::MuGround).unwrap_or_else(|| format!("μ_ground = {}", p.mu_ground)),
            own(Param::MuPalm).unwrap_or_else(|| format!("μ_palm = {}", p.mu_palm))
        ),
    };
    let shown = [
        Param::MassKg,
        Param::RadiusMm,
        Param::ForceN,
        Param::GravityMS2,
    ];
    // The palm's offset only where it is not the paper's 0.
    let offset = (p.palm_offset_mm != 0.0).then_some(Param::PalmOffsetMm);
    let parts =
        std::iter::once((Param::Mu, mu)).chain(shown.into_iter().chain(offset).filter_map(|k| {
            k.get(p)
                .map(|v| (k, own(k).unwrap_or_else(|| param_value(k, v))))
        }));
    // The palm's length: where its reach ends curves and shades maps.
    let palm = (!swept.contains(&Param::PalmLengthMm))
        .then(|| format!("palm L = {} mm", p.palm_length_mm));
    let kept: Vec<String> = parts
        .filter(|(k, _)| !swept.contains(k))
        .map(|(_, s)| s)
        .chain(palm)
        .collect();
    format!("{source}: {}", kept.join(", "))
}
