//! The shaded band of a sweep with an uncertain input, drawn from the band's rows
//! ([`crate::figures::band::BandRow`]: where the jam can lie at each value of the swept
//! parameter).

use plotters::prelude::*;

use super::axes::{self, DrawResult, PlotAxis};
use super::legend::{LegendEntry, Swatch};
use super::style::BAND_FILL;
use crate::figures::band::BandRow;
use crate::figures::sweep_layers::SweepPanel;

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
    /// The legend never names a line that is not drawn: with mu 0.12 to 0.3 on the 25 mm
    /// shaft, the latest-jam corner (mu = 0.12) lies past the 80 mm palm at every push from
    /// 10 to 100 N, so its edge draws nothing; it kept a legend entry ("latest jam; no jam past
    /// the palm's end ...") beside no line. Now the shade's entry says it runs to the palm's end.
    #[test]
    fn the_latest_edge_past_the_palm_has_no_legend_entry() {
        use crate::charts::picture::Picture;
        use crate::charts::spec::load_scene;
        use crate::charts::sweep::Sweep;
        use crate::charts::{ChartSpec, Scene};
        use crate::figures::band::Band;
        use crate::figures::models::Live;
        use crate::figures::{Figure, Input};
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("charts");
        let mut scene: Scene = load_scene(&dir, "fig7b").expect("fig7b loads");
        scene.params = crate::uncertain::shaft::shaft_25mm();
        let ChartSpec::Sweep(mut spec) = scene.chart.clone() else {
            panic!("fig7b is a sweep")
        };
        spec.x_axis.min = 10.0;
        spec.x_axis.max = 100.0;
        spec.x_axis.count = 11;
        spec.band = Some(Band {
            earliest: scene.params.with_mu(0.3),
            latest: scene.params.with_mu(0.12),
            label: "band over mu 0.12 to 0.3".into(),
            inputs: Vec::new(),
        });
        let input = Input {
            params: scene.params,
            min_norm: scene.min_norm,
            dynamics: scene.dynamics,
        };
        let sweep = Sweep::new(spec.compute(&input, &Live).unwrap(), &scene.title);
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
