//! The band of an uncertain input on a sweep or a jam map: the scenes at the box's
//! earliest-jam and latest-jam corners ([`crate::uncertain::range`]), and on a sweep the
//! interval it shades at each swept value.
//!
//! theta_jam is monotone in every uncertain input (the proof is in [`crate::statics`]), so at
//! each swept value the box's answers run between its earliest-jam corner's and its
//! latest-jam corner's; the band's two edges are those corners' curves. The shaded interval at
//! a swept value is the hull of the two corners' answers (as a range's interval is): a corner
//! that jams or is held at the start gives its own end, a too weak earliest corner the start
//! angle (the points where the push just moves the disc are held there), a latest corner whose
//! jam lies past the palm's end (or that never jams) the palm's end; nothing where no point of
//! the box jams on the palm or is held.
//!
//! With a distribution, the corners are its 5 % and 95 % quantiles, so the shaded interval is the
//! exact 5-95 % quantile band of x_jam and theta_jam for one input (they are monotone in it).
//!
//! A sweep's CSV writes one row of layer `band` per swept value: each corner's status and jam,
//! and the shaded interval ([`BandRow`]).

use serde::{Deserialize, Serialize};

use super::Input;
use super::sweep_layers::{Curve, Series, SeriesPoint, SweepPanel, closed_form, closed_form_point};
use crate::error::{Error, Result};
use crate::grid::GridAxis;
use crate::numbers::Num;
use crate::scene::Param;
use crate::scene::{JamStatus, SceneParams};
use crate::uncertain::{Uncertain, UncertainSet, range};

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
    /// The uncertain inputs and where each corner takes them, for the subtitle and the
    /// read-off (default: none).
    #[serde(default)]
    pub inputs: Vec<BandInput>,
}

/// One uncertain input of a band: what it spans and its value at each corner.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BandInput {
    /// The setting as written (`mu`, `force_n`).
    pub name: String,
    /// What it spans, e.g. `0.12 to 0.3`, or for a distribution `normal(0.2,0.03), 5–95 %
    /// quantiles 0.1507 to 0.2493`.
    pub span: String,
    /// Its value at the earliest-jam corner.
    pub earliest: f64,
    /// Its value at the latest-jam corner.
    pub latest: f64,
}

/// The band of the uncertain inputs along a sweep of `param`: the closed form at the box's two
/// extreme corners (ranges at their ends; a distribution at its 5 % and 95 % quantiles, which
/// is the exact quantile band for one input, as x_jam is monotone in it).
pub fn from_uncertain(
    p: &SceneParams,
    uncertain: &UncertainSet,
    param: Param,
) -> Result<Option<Band>> {
    if uncertain.is_empty() {
        return Ok(None);
    }
    let swept = param.decl();
    let mut edges = uncertain.clone();
    let (mut label, mut spans) = (Vec::new(), Vec::new());
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
            spans.push(format!(
                "{}, {pct}–{} % quantiles {} to {}",
                i.value,
                100.0 - pct,
                Num(lo),
                Num(hi)
            ));
            i.value = Uncertain::Range { lo, hi };
        } else {
            // A range's ends as the user wrote them (shortest form: 0.12, not 0.1200).
            let (lo, hi) = i.value.ends();
            label.push(format!("{} {lo} to {hi}", i.name));
            spans.push(format!("{lo} to {hi}"));
        }
    }
    let box_answer = range::ends(p, &edges)?;
    let inputs = (edges.inputs.iter().enumerate())
        .zip(spans)
        .map(|((k, i), span)| BandInput {
            name: i.name.to_string(),
            span,
            earliest: box_answer.earliest.values[k],
            latest: box_answer.latest.values[k],
        })
        .collect();
    Ok(Some(Band {
        earliest: edges.apply(p, &box_answer.earliest.values),
        latest: edges.apply(p, &box_answer.latest.values),
        label: format!("band over {}", label.join(", ")),
        inputs,
    }))
}

/// The band's two edges: the closed form at the earliest-jam corner and at the latest.
pub(super) fn edges(axis: &GridAxis, scene: &Input, band: &Band) -> Result<[Series; 2]> {
    let edge = |params, curve, which: &str| -> Result<Series> {
        let at = Input {
            params,
            ..scene.clone()
        };
        Ok(Series {
            curve,
            // The band's own label is the shade's legend entry; an edge says which it is.
            label: format!("band edge: {which}"),
            points: closed_form(axis, &at, |v, s| closed_form_point(v, &s))?,
            flat_names: None,
            callout: None,
        })
    };
    Ok([
        edge(band.earliest, Curve::BandEarliest, "earliest jam")?,
        edge(band.latest, Curve::BandLatest, "latest jam")?,
    ])
}

/// The quantile of a distributed input at the band's lower edge (5 %; 95 % at the upper).
const BAND_QUANTILE: f64 = 0.05;

/// The band at one value of the swept parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BandRow {
    /// The swept parameter's value.
    pub at: f64,
    /// The closed form at the earliest-jam corner.
    pub earliest: SeriesPoint,
    /// The closed form at the latest-jam corner.
    pub latest: SeriesPoint,
    /// The shaded x_jam interval in mm, (low, high); None where nothing is shaded.
    pub x_jam_mm: Option<(f64, f64)>,
    /// The shaded theta_jam interval in deg, (low, high); None where nothing is shaded.
    pub theta_jam_deg: Option<(f64, f64)>,
}

impl BandRow {
    /// The shaded interval in `panel`.
    pub fn interval(&self, panel: SweepPanel) -> Option<(f64, f64)> {
        match panel {
            SweepPanel::XJamMm => self.x_jam_mm,
            SweepPanel::ThetaJamDeg => self.theta_jam_deg,
        }
    }
}

/// The band at the value `v` of the swept parameter `param`: the closed form at both
/// corners there and the interval between them (a sweep's read-off with a band).
pub fn at(param: Param, v: f64, band: &Band) -> Result<BandRow> {
    let corner = |p: &SceneParams| -> Result<SeriesPoint> {
        let s = crate::models::solve(&crate::models::ModelSpec::Statics, &param.apply(*p, v))?;
        Ok(closed_form_point(v, &s))
    };
    let (e, l) = (corner(&band.earliest)?, corner(&band.latest)?);
    Ok(rows(param, &band.latest, &[e], &[l]).remove(0))
}

/// The band's rows from its two edges (same swept values, in order), the latest corner's
/// parameters `latest_params` giving the palm's end at each value of `param`.
pub fn rows(
    param: Param,
    latest_params: &SceneParams,
    earliest: &[SeriesPoint],
    latest: &[SeriesPoint],
) -> Vec<BandRow> {
    earliest
        .iter()
        .zip(latest)
        .map(|(e, l)| {
            let p = param.apply(*latest_params, e.at);
            let answer = |s: &SeriesPoint| {
                let status = s.status.unwrap_or(JamStatus::OutsideModel);
                (status, s.theta_jam_deg.zip(s.x_jam_mm))
            };
            let hull = range::hull(&p, answer(e), answer(l));
            BandRow {
                at: e.at,
                earliest: e.clone(),
                latest: l.clone(),
                x_jam_mm: hull.map(|h| (h.x_jam_mm[0], h.x_jam_mm[1])),
                theta_jam_deg: hull.map(|h| (h.theta_jam_deg[0], h.theta_jam_deg[1])),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pt(at: f64, status: JamStatus, x: Option<f64>, t: Option<f64>) -> SeriesPoint {
        SeriesPoint {
            at,
            x_jam_mm: x,
            theta_jam_deg: t,
            status: Some(status),
            past_palm_x_jam_mm: None,
        }
    }

    /// The shade runs from the earliest jam to the palm's end when the latest corner's jam
    /// lies past the palm: x = r cot(theta_L/2) with tan(theta_L/2) = r/L (h = 0), i.e. x = L.
    #[test]
    fn a_latest_jam_past_the_palm_is_shaded_to_the_palms_end() {
        let p = SceneParams {
            palm_length_mm: 80.0,
            palm_offset_mm: 0.0,
            ..Default::default()
        };
        let e = [pt(40.0, JamStatus::Jams, Some(40.0), Some(35.0))];
        let l = [pt(40.0, JamStatus::BeyondReach, None, None)];
        let r = &rows(Param::ForceN, &p, &e, &l)[0];
        let (lo, hi) = r.x_jam_mm.unwrap();
        assert!(
            (lo - 40.0).abs() < 1e-12 && (hi - 80.0).abs() < 1e-9,
            "{lo} {hi}"
        );
        let want = 2.0 * (p.radius_mm / 80.0).atan().to_degrees();
        let (tlo, thi) = r.theta_jam_deg.unwrap();
        assert!((tlo - want).abs() < 1e-9 && (thi - 35.0).abs() < 1e-12);
        // A too weak earliest corner: the pushes that just move the disc hold it at the start
        // (90 deg, x = r = 10 mm), so the shade runs from there to the palm's end.
        let too_weak = [pt(40.0, JamStatus::TooWeak, None, None)];
        let (lo, hi) = rows(Param::ForceN, &p, &too_weak, &l)[0].x_jam_mm.unwrap();
        assert!(
            (lo - 10.0).abs() < 1e-9 && (hi - 80.0).abs() < 1e-9,
            "{lo} {hi}"
        );
    }
}
