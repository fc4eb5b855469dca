//! The shaded band of a sweep with an uncertain input: where the jam can lie at each value of
//! the swept parameter.
//!
//! theta_jam is monotone in every uncertain input (the proof is in [`crate::statics`]), so at
//! each swept value the jams over the box run from the earliest-jam corner's to the
//! latest-jam corner's ([`crate::uncertain::range`]); the band's two edges are those corners'
//! curves. The shaded interval at a swept value is
//!
//! - from the earliest corner's jam (it `jams`, or is `jammed_at_start`);
//! - to the latest corner's jam where that one jams; where it lies past the palm's end
//!   (`beyond_reach`, or `never_jams`, which slides past every palm), to the palm's end: the
//!   contact at s_B = L, palm angle [`statics::reach_angle_rad`], disc position
//!   x = r cot(theta/2) + h / sin(theta) there. Between that corner and the palm's end every
//!   jam is on the palm (theta_jam is continuous along the box), so the shading is exact;
//! - nothing where the earliest corner itself does not jam on the palm (then no corner of the
//!   box does, or the earliest one cannot move the disc: `too_weak`).
//!
//! With a distribution, the corners are its 5 % and 95 % quantiles, so the shaded interval is the
//! exact 5-95 % quantile band of x_jam and theta_jam for one input (they are monotone in it).
//!
//! The CSV writes one row of layer `band` per swept value: each corner's status and jam, and the
//! shaded interval ([`BandRow`]).

use plotters::prelude::*;

use super::axes::{self, DrawResult, PlotAxis};
use super::legend::{LegendEntry, Swatch};
use super::style::BAND_FILL;
use super::sweep::{SeriesPoint, SweepPanel};

use crate::grid::GridParam;
use crate::scene::{JamStatus, SceneParams};
use crate::statics;

/// The band at one value of the swept parameter.
#[derive(Debug, Clone, PartialEq)]
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

/// The band's rows from its two edges (same swept values, in order), the latest corner's
/// parameters `latest_params` giving the palm's end at each value of `param`.
pub fn rows(
    param: GridParam,
    latest_params: &SceneParams,
    earliest: &[SeriesPoint],
    latest: &[SeriesPoint],
) -> Vec<BandRow> {
    earliest
        .iter()
        .zip(latest)
        .map(|(e, l)| {
            let p = param.apply(*latest_params, e.at);
            let reach = statics::reach_angle_rad(&p);
            let palm_end = (p.disc_position_mm(reach), reach.to_degrees());
            let jam = |s: &SeriesPoint| {
                matches!(s.status, Some(JamStatus::Jams | JamStatus::JammedAtStart))
                    .then_some((s.x_jam_mm?, s.theta_jam_deg?))
            };
            let past_palm = matches!(
                l.status,
                Some(JamStatus::BeyondReach | JamStatus::NeverJams)
            );
            let far = jam(l).or(past_palm.then_some(palm_end));
            let (x, theta) = match (jam(e), far) {
                (Some(a), Some(b)) => (
                    Some((a.0.min(b.0), a.0.max(b.0))),
                    Some((a.1.min(b.1), a.1.max(b.1))),
                ),
                _ => (None, None),
            };
            BandRow {
                at: e.at,
                earliest: e.clone(),
                latest: l.clone(),
                x_jam_mm: x,
                theta_jam_deg: theta,
            }
        })
        .collect()
}

/// Shades the band in `panel`: one polygon per run of swept values with an interval, so a
/// stretch where nothing can jam on the palm stays white.
pub fn draw<DB: DrawingBackend>(
    chart: &axes::Chart<DB>,
    rows: &[BandRow],
    panel: SweepPanel,
    (x, y): (&PlotAxis, &PlotAxis),
) -> DrawResult<DB> {
    for run in rows.split(|r| r.interval(panel).is_none()) {
        if run.len() < 2 {
            continue;
        }
        let lo = run
            .iter()
            .filter_map(|r| Some((r.at, r.interval(panel)?.0)));
        let hi = run
            .iter()
            .rev()
            .filter_map(|r| Some((r.at, r.interval(panel)?.1)));
        let ring: Vec<(f64, f64)> = lo
            .chain(hi)
            .map(|(a, v)| (x.to_plot(a), y.to_plot(v.clamp(y.min, y.max))))
            .collect();
        chart
            .plotting_area()
            .draw(&Polygon::new(ring, BAND_FILL.filled()))?;
    }
    Ok(())
}

/// The shade's legend entry: what it spans, and where the latest-jam edge lies past the palm
/// (then the shade runs to the palm's end and that edge is not drawn there).
pub fn legend_entry(rows: &[BandRow], label: &str) -> Option<LegendEntry> {
    if rows.iter().all(|r| r.x_jam_mm.is_none()) {
        return None;
    }
    let capped = rows
        .iter()
        .any(|r| r.x_jam_mm.is_some() && r.latest.x_jam_mm.is_none());
    let to = if capped { ", up to the palm's end" } else { "" };
    Some(LegendEntry::new(
        Swatch::Patch(BAND_FILL),
        format!("{label}: where it can jam{to}"),
    ))
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
        let r = &rows(GridParam::ForceN, &p, &e, &l)[0];
        let (lo, hi) = r.x_jam_mm.unwrap();
        assert!(
            (lo - 40.0).abs() < 1e-12 && (hi - 80.0).abs() < 1e-9,
            "{lo} {hi}"
        );
        let want = 2.0 * (p.radius_mm / 80.0).atan().to_degrees();
        let (tlo, thi) = r.theta_jam_deg.unwrap();
        assert!((tlo - want).abs() < 1e-9 && (thi - 35.0).abs() < 1e-12);
        let too_weak = [pt(40.0, JamStatus::TooWeak, None, None)];
        assert_eq!(rows(GridParam::ForceN, &p, &too_weak, &l)[0].x_jam_mm, None);
    }

    /// The legend never names a line that is not drawn: with mu 0.12 to 0.3 on the issue's
    /// shaft, the latest-jam corner (mu = 0.12) lies past the 80 mm palm at every push from
    /// 10 to 100 N, so its edge draws nothing; it kept a legend entry ("latest jam; no jam past
    /// the palm's end ...") beside no line. Now the shade's entry says it runs to the palm's end.
    #[test]
    fn the_latest_edge_past_the_palm_has_no_legend_entry() {
        use crate::charts::spec::load_scene;
        use crate::charts::sweep::Sweep;
        use crate::charts::{ChartSpec, Scene};
        use crate::figures::band::Band;
        use crate::figures::models::Live;
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("charts");
        let mut scene: Scene = load_scene(&dir, "fig7b").expect("fig7b loads");
        scene.params = crate::uncertain::shaft_25mm();
        let ChartSpec::Sweep(mut spec) = scene.chart.clone() else {
            panic!("fig7b is a sweep")
        };
        spec.axis.min = 10.0;
        spec.axis.max = 100.0;
        spec.axis.count = 11;
        spec.band = Some(Band {
            earliest: scene.params.with_mu(0.3),
            latest: scene.params.with_mu(0.12),
            label: "band over mu 0.12 to 0.3".into(),
        });
        let sweep = Sweep::compute(&scene, &spec, &Live).unwrap();
        let labels: Vec<String> = sweep.legend().into_iter().map(|e| e.label).collect();
        assert!(
            labels.iter().all(|l| !l.contains("latest jam")),
            "{labels:#?}"
        );
        assert!(
            labels
                .iter()
                .any(|l| l.contains("where it can jam, up to the palm's end")),
            "{labels:#?}"
        );
    }
}
