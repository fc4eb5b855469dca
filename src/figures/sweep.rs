//! The sweep (Figs. 6, 7a, 7b): x_jam and theta_jam against one scene parameter.
//!
//! Each layer contributes [`Series`] (a curve or a point set, named by its [`Curve`]); each
//! panel of the chart plots one quantity of every series. The layers live in
//! [`super::sweep_layers`]: a new model's points are one more [`SweepLayer`] variant and one
//! function there. An uncertain input adds its band ([`super::band`]).

use serde::{Deserialize, Serialize};

use super::band::{self, BandRow};
use super::models::Models;
use super::sweep_layers::{self, Curve, Series, SeriesPoint, SweepLayer, SweepPanel};
use super::{DataFormat, Figure, FigureData, Input};
use crate::csv_out::{Dec, dec, to_csv_with_header};
use crate::error::{Error, Result};
use crate::grid::GridAxis;
use crate::scene::Param;
use crate::scene::{JamStatus, SceneParams};

/// `[chart]` keys of `kind = "sweep"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepSettings {
    /// The swept parameter, its range, sample count (curves) and scale: the x axis, under the
    /// key every chart kind names its x axis with (`axis`, the key's old spelling, is read as
    /// it).
    pub x_axis: GridAxis,
    /// The panels, top to bottom (default: x_jam_mm then theta_jam_deg).
    #[serde(default = "both_panels")]
    pub panels: Vec<SweepPanel>,
    /// The layers to draw (default: statics).
    #[serde(default = "statics_only")]
    pub layers: Vec<SweepLayer>,
    /// Draw the read-off at the scene's own value of the swept parameter: the closed form's
    /// x_jam and theta_jam there, with lines to the axes and the values printed (default:
    /// false; `--set chart.read_off=true --set mu=0.27`).
    #[serde(default)]
    pub read_off: bool,
    /// The band of an uncertain input (`sweep ... --mu 0.12:0.3`, or a range in a sweep
    /// scene's `[scene]` or `--set`): the closed form at the box's two extreme corners, drawn
    /// as two edges with the band shaded between them and written as one CSV row of layer
    /// `band` per swept value ([`super::band`]) (default: none; the built-in scenes have
    /// none).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub band: Option<band::Band>,
}

fn both_panels() -> Vec<SweepPanel> {
    vec![SweepPanel::XJamMm, SweepPanel::ThetaJamDeg]
}

fn statics_only() -> Vec<SweepLayer> {
    vec![SweepLayer::Statics]
}

impl Figure for SweepSettings {
    type Data = SweepData;

    fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
        vec![("x_axis", self.x_axis)]
    }

    /// With the read-off, the chart marks the scene's value of the swept parameter.
    fn marks_scene_value(&self) -> bool {
        self.read_off
    }

    fn enable_read_off(&mut self) -> bool {
        self.read_off = true;
        true
    }

    /// Checks the axis, panels and layers against the scene.
    fn validate(&self, input: &Input) -> Result<()> {
        self.x_axis.validate("chart.x_axis")?;
        if self.x_axis.param == Param::ThetaDeg {
            return Err(Error::invalid(
                "chart.x_axis.param",
                "theta_deg",
                "a sweep varies a scene parameter",
            ));
        }
        for v in [self.x_axis.min, self.x_axis.max] {
            self.x_axis.param.apply(input.params, v).validate()?;
        }
        if self.panels.is_empty() || self.panels.len() > 3 {
            return Err(Error::invalid(
                "chart.panels",
                self.panels.len(),
                "a sweep has 1 to 3 panels",
            ));
        }
        for l in &self.layers {
            sweep_layers::validate(*l, &self.x_axis)?;
        }
        Ok(())
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        crate::limits::check_items(
            "chart.x_axis.count",
            self.x_axis.count as f64,
            crate::limits::SWEEP_POINT,
        )
    }

    /// Computes the series of every layer, the band and the read-off.
    fn compute(&self, input: &Input, models: &dyn Models) -> Result<SweepData> {
        let mut series = Vec::new();
        for l in &self.layers {
            series.extend(sweep_layers::series(*l, &self.x_axis, input, models)?);
        }
        let mut rows = Vec::new();
        if let Some(band) = &self.band {
            let [earliest, latest] = band::edges(&self.x_axis, input, band)?;
            rows = band::rows(
                self.x_axis.param,
                &band.latest,
                &earliest.points,
                &latest.points,
            );
            series.extend([earliest, latest]);
        }
        let at = self
            .x_axis
            .param
            .get(&input.params)
            .filter(|_| self.read_off);
        // With a band the read-off is its two ends there (the scene's own value of an
        // uncertain input is only the range's midpoint).
        let read_off_band = match (at, &self.band) {
            (Some(v), Some(b)) => Some(band::at(self.x_axis.param, v, b)?),
            _ => None,
        };
        let read_off = match (self.read_off && self.band.is_none(), at) {
            (true, Some(v)) => {
                let s = crate::models::solve(&crate::models::ModelSpec::Statics, &input.params)?;
                let jams = s.status == JamStatus::Jams;
                Some(SeriesPoint {
                    at: v,
                    x_jam_mm: s.x_jam_mm.filter(|_| jams),
                    theta_jam_deg: s.theta_jam_deg.filter(|_| jams),
                    status: Some(s.status),
                    past_palm_x_jam_mm: s.past_palm().map(|p| p.x_jam_mm),
                })
            }
            _ => None,
        };
        Ok(SweepData {
            params: input.params,
            settings: self.clone(),
            series,
            read_off,
            read_off_band,
            band: rows,
        })
    }
}

/// The computed sweep; its rows are its CSV data file (one row per swept value).
#[derive(Debug, Clone, Serialize)]
pub struct SweepData {
    /// The scene's parameters.
    pub params: SceneParams,
    /// The settings it was computed with.
    #[serde(flatten)]
    pub settings: SweepSettings,
    /// Every layer's series (with a band, its two edges last).
    pub series: Vec<Series>,
    /// The closed form at the scene's own value of the swept parameter, when read off
    /// without a band.
    pub read_off: Option<SeriesPoint>,
    /// With a band, the read-off: the band's two ends at the scene's own value of the swept
    /// parameter.
    pub read_off_band: Option<BandRow>,
    /// The shaded band of an uncertain input, one row per swept value (empty without one).
    pub band: Vec<BandRow>,
}

/// The ten columns a band adds to a sweep's CSV.
const BAND_COLUMNS: [&str; 10] = [
    "earliest_status",
    "earliest_x_jam_mm",
    "earliest_theta_jam_deg",
    "latest_status",
    "latest_x_jam_mm",
    "latest_theta_jam_deg",
    "band_x_jam_lo_mm",
    "band_x_jam_hi_mm",
    "band_theta_jam_lo_deg",
    "band_theta_jam_hi_deg",
];

impl FigureData for SweepData {
    const FORMAT: DataFormat = DataFormat::Csv;

    /// One CSV row per point of every series, the read-off as a row of layer `read_off`; with
    /// a band, its edges as one row of layer `band` per swept value instead.
    fn csv(&self) -> Vec<u8> {
        if !self.band.is_empty() {
            return self.band_csv();
        }
        let rows = self.layer_rows().map(|(layer, p)| {
            let status = p.status.map_or("", JamStatus::as_str);
            (
                layer,
                Dec(p.at),
                status,
                dec(p.x_jam_mm),
                dec(p.theta_jam_deg),
                dec(p.past_palm_x_jam_mm),
            )
        });
        to_csv_with_header(&self.header(), rows)
    }
}

impl SweepData {
    /// The columns of every sweep's CSV: `x_jam_mm` is empty where there is no jam on the
    /// palm; `past_palm_x_jam_mm` gives, on a `beyond_reach` row, where the jam would be on a
    /// long enough palm.
    fn header(&self) -> [&'static str; 6] {
        [
            "layer",
            self.settings.x_axis.param.as_str(),
            "status",
            "x_jam_mm",
            "theta_jam_deg",
            "past_palm_x_jam_mm",
        ]
    }

    /// Every point of the layers but a band's edges (written in the band's own rows), then
    /// the read-off, each with its layer's name.
    fn layer_rows(&self) -> impl Iterator<Item = (&'static str, &SeriesPoint)> {
        self.series
            .iter()
            .filter(|s| !matches!(s.curve, Curve::BandEarliest | Curve::BandLatest))
            .flat_map(|ser| ser.points.iter().map(|p| (ser.curve.name(), p)))
            .chain(self.read_off.iter().map(|p| ("read_off", p)))
    }

    /// The CSV of a sweep with a band: the other layers' rows as without one, then one row of
    /// layer `band` per swept value with each corner's status, x_jam and theta_jam and the
    /// shaded interval (empty where nothing is shaded), in ten more columns. The columns the
    /// band rows leave empty are the other layers' (and the other way round).
    fn band_csv(&self) -> Vec<u8> {
        let mut header = self.header().to_vec();
        header.extend(BAND_COLUMNS);
        let status = |p: &SeriesPoint| p.status.map_or("", JamStatus::as_str);
        let ends = |i: Option<(f64, f64)>| (dec(i.map(|i| i.0)), dec(i.map(|i| i.1)));
        let layers = self.layer_rows().map(|(layer, p)| {
            let (x, t) = (dec(p.x_jam_mm), dec(p.theta_jam_deg));
            let n = None;
            (
                layer,
                Dec(p.at),
                status(p),
                x,
                t,
                dec(p.past_palm_x_jam_mm),
                "",
                n,
                n,
                "",
                n,
                n,
                n,
                n,
                n,
                n,
            )
        });
        // The read-off with a band is its row at the read-off's value, of layer `read_off`.
        let read_off = self.read_off_band.iter().map(|r| ("read_off", r));
        let band = (self.band.iter().map(|r| ("band", r)))
            .chain(read_off)
            .map(|(layer, r)| {
                let (e, l) = (&r.earliest, &r.latest);
                let ((x0, x1), (t0, t1)) = (ends(r.x_jam_mm), ends(r.theta_jam_deg));
                let (ex, et) = (dec(e.x_jam_mm), dec(e.theta_jam_deg));
                let (lx, lt) = (dec(l.x_jam_mm), dec(l.theta_jam_deg));
                let n = None;
                let (es, ls) = (status(e), status(l));
                (
                    layer,
                    Dec(r.at),
                    "",
                    n,
                    n,
                    n,
                    es,
                    ex,
                    et,
                    ls,
                    lx,
                    lt,
                    x0,
                    x1,
                    t0,
                    t1,
                )
            });
        to_csv_with_header(&header, layers.chain(band))
    }
}
