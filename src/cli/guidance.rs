//! Which model answers which design question, printed after `solve --model all`.

use std::fmt::Write;

use crate::config::Config;
use crate::dynamics::Drive;
use crate::models::{Detail, ModelKind, Solution};
use crate::numbers::Num;
use crate::scene::JamStatus;

/// Models whose x_jam differ by more than this are flagged: 2 % of x_jam is about the spread of
/// the paper's own two models and Adams run (0.6 % and 2.3 %).
pub const DISAGREEMENT_PCT: f64 = 2.0;

/// The paragraph after several models' answers: which to design to, and where they disagree.
pub fn guidance<'a>(
    config: &Config,
    results: impl Iterator<Item = &'a Solution> + Clone,
) -> String {
    let x_of = |kind: ModelKind| {
        results
            .clone()
            .find(|r| r.model == kind)
            .and_then(|r| r.x_jam_mm)
    };
    let mut s = String::from("\nwhich to design to:\n");
    if let Some(x) = x_of(ModelKind::Statics) {
        let _ = writeln!(
            s,
            "  a slow push limited to F = {} N: statics, x_jam = {x:.3} mm",
            config.scene.force_n,
            x = Num(x)
        );
    }
    let rigid = results.clone().find_map(|r| match &r.detail {
        Detail::Statics(d) => d.x_rigid_mm,
        _ => None,
    });
    if let Some(x) = rigid {
        let offset = if config.scene.palm_offset_mm > 0.0 {
            " + h / sin(alpha_g + alpha_p)"
        } else {
            ""
        };
        let _ = writeln!(
            s,
            "  a palm driven by motion (it pushes as hard as needed): the limit x_rigid = \
             r cot((alpha_g + alpha_p)/2){offset} = {x:.3} mm",
            x = Num(x)
        );
    }
    let drive = match config.dynamics.drive.mode {
        Drive::Motion => "motion drive: it tends to the driven-palm limit",
        Drive::Force => "force drive: it tends to the statics at F",
    };
    let dynamics = results.clone().find(|r| r.model == ModelKind::Dynamics);
    if let Some((x, status)) = dynamics.and_then(|r| r.x_jam_mm.map(|x| (x, r.status))) {
        // An answer its model does not stand behind is not a figure to design to.
        let trust = match status {
            JamStatus::Jams | JamStatus::JammedAtStart => String::new(),
            other => format!(", untrusted ({other}: see its reason above)"),
        };
        let _ = writeln!(
            s,
            "  a fast push where inertia and contact stiffness matter: dynamics ({drive}), \
             x_jam = {x:.3} mm{trust}",
            x = Num(x)
        );
    }
    let answered: Vec<(ModelKind, f64)> = results
        .clone()
        .filter_map(|r| r.x_jam_mm.map(|x| (r.model, x)))
        .collect();
    if results.clone().all(|r| r.status == JamStatus::OutsideModel) {
        s.push_str("  none: the scene lies outside every model (each one's reason is above)\n");
    }
    // Against the first answer (the closed form, the oracle, in `--model all`).
    if let Some(((a, xa), rest)) = answered.split_first() {
        for (b, xb) in rest {
            let pct = 100.0 * (xb - xa) / xa;
            if pct.abs() > DISAGREEMENT_PCT {
                let _ = writeln!(
                    s,
                    "  note: {b} differs from {a} by {pct:+.1} % in x_jam (more than \
                     {DISAGREEMENT_PCT} %): they answer different questions, see above"
                );
            }
        }
    }
    s
}
