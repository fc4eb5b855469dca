//! The band of an uncertain input on a sweep or a jam map: the scenes at the box's
//! earliest-jam and latest-jam corners ([`crate::uncertain::range`]).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::grid::GridParam;
use crate::scene::SceneParams;
use crate::uncertain::{Uncertain, UncertainSet};

/// The two edges of a band: the scene at the corner where the jam comes earliest and at the
/// one where it comes latest ([`crate::uncertain::range`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Band {
    /// The scene at the earliest-jam corner.
    pub earliest: crate::scene::SceneParams,
    /// The scene at the latest-jam corner.
    pub latest: crate::scene::SceneParams,
    /// What the band spans, for the legend, e.g. `μ 0.12 to 0.3`.
    pub label: String,
}

/// The band of the uncertain inputs along a sweep of `param`: the closed form at the box's two
/// extreme corners (ranges at their ends; a distribution at its 5 % and 95 % quantiles, which
/// is the exact quantile band for one input, as x_jam is monotone in it).
pub fn from_uncertain(
    p: &SceneParams,
    uncertain: &UncertainSet,
    param: GridParam,
) -> Result<Option<Band>> {
    if uncertain.is_empty() {
        return Ok(None);
    }
    let swept = param.decl();
    let mut edges = uncertain.clone();
    let mut label = Vec::new();
    for i in &mut edges.inputs {
        let clash = i.keys.contains(&swept.key) || i.name == swept.key;
        if clash || swept.sets.iter().any(|k| i.keys.contains(k)) {
            return Err(Error::invalid(
                i.name,
                i.value,
                format!(
                    "it is the swept parameter {}; give it a single value",
                    swept.key
                ),
            ));
        }
        if i.value.is_distribution() {
            let (lo, hi) = (
                i.value.quantile(BAND_QUANTILE),
                i.value.quantile(1.0 - BAND_QUANTILE),
            );
            let pct = 100.0 * BAND_QUANTILE;
            label.push(format!(
                "{} {} ({pct}–{} % quantiles)",
                i.name,
                i.value,
                100.0 - pct
            ));
            i.value = Uncertain::Range { lo, hi };
        } else {
            // A range's ends as the user wrote them (shortest form: 0.12, not 0.1200).
            let (lo, hi) = i.value.ends();
            label.push(format!("{} {lo} to {hi}", i.name));
        }
    }
    let box_answer = crate::uncertain::range::ends(p, &edges)?;
    Ok(Some(Band {
        earliest: edges.apply(p, &box_answer.earliest.values),
        latest: edges.apply(p, &box_answer.latest.values),
        label: format!("band over {}", label.join(", ")),
    }))
}

/// The quantile of a distributed input at the band's lower edge (5 %; 95 % at the upper).
const BAND_QUANTILE: f64 = 0.05;
