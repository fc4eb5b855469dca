//! The shaded band of a sweep with an uncertain input: where the jam can lie at each value of
//! the swept parameter.
//!
//! theta_jam is monotone in every uncertain input (the proof is in [`crate::statics`]), so at
//! each swept value the box's answers run between its earliest-jam corner's and its
//! latest-jam corner's; the band's two edges are those corners' curves. The shaded interval at
//! a swept value is [`crate::uncertain::range::hull`] of the two corners' answers: a corner
//! that jams or is held at the start gives its own end, a too weak earliest corner the start
//! angle (the points where the push just moves the disc are held there), a latest corner whose
//! jam lies past the palm's end (or that never jams) the palm's end; nothing where no point of
//! the box jams on the palm or is held.
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
use crate::uncertain::range;

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
        // A too weak earliest corner: the pushes that just move the disc hold it at the start
        // (90 deg, x = r = 10 mm), so the shade runs from there to the palm's end.
        let too_weak = [pt(40.0, JamStatus::TooWeak, None, None)];
        let (lo, hi) = rows(GridParam::ForceN, &p, &too_weak, &l)[0]
            .x_jam_mm
            .unwrap();
        assert!(
            (lo - 10.0).abs() < 1e-9 && (hi - 80.0).abs() < 1e-9,
            "{lo} {hi}"
        );
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
