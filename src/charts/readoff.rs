//! What the gallery's read-off needs of a chart, embedded in `index.html` as JSON: where each
//! plotting area lies in the picture, its axes (range and scale) and the chart's own data.
//!
//! A page opened from disk cannot fetch its CSV, so the page carries this instead; it stays
//! small: a jam map gives its boundary per column and the rule that turns it into a status
//! (not its 160k cells), a sweep its curves. The frames come from the drawing itself
//! ([`super::axes::record_frames`]), so pointer and picture cannot disagree.
//!
//! The schema is [`ReadOffData`], one variant per `kind`: its serde form, written by
//! [`ReadOffData::to_json`] (every number that is not an integer at 7 significant digits), is
//! what `gallery.js` reads, and `readoff_tests` checks every key the script reads against the
//! script and against the form of every built-in scene.

use serde::ser::SerializeStruct;
use serde::{Serialize, Serializer};

use super::axes::PlotFrame;
use super::ticks::PlotAxis;
use crate::JamStatus;
use crate::figures::convergence::TraceRow;
use crate::figures::error_time::ErrorTimeRow;
use crate::figures::stability::Answer;
use crate::figures::work_precision::PrecisionRow;
use crate::grid::AxisScale;

/// The gallery's read-off of one chart: `kind` (the variant's name in snake case) says how the
/// page reads it.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ReadOffData {
    /// A jam/slide map: the boundary per column and the rule that turns it into a status.
    ///
    /// The status at (v, theta): `beyond_reach` when theta < reach_deg(v) (the contact lies
    /// past the palm's end), else `jam` when theta <= theta_jam_deg(v) (margin >= 0), else
    /// `slide`; between columns the page interpolates straight in plot space.
    JamMap {
        /// The model of the boundary, as `solve` names it.
        model: &'static str,
        /// The map's parameter.
        x: Axis,
        /// The one plotting area; its y axis is the palm angle.
        panels: Vec<Panel>,
        /// The boundary, one entry per column.
        columns: JamMapColumns,
        /// The disc, which turns a palm angle into the disc's position.
        disc: Disc,
    },
    /// Curves against one parameter, one panel per quantity (theta_jam, x_jam): the page reads
    /// the panel's quantity of every series at the pointer's x.
    Sweep {
        /// The swept parameter, shared by the panels.
        x: Axis,
        /// One plotting area per quantity.
        panels: Vec<QuantityPanel>,
        /// The curves and markers.
        series: Vec<SweepSeries>,
    },
    /// A map's cells (the universal chart, contour maps, the V-locator's capacity): the page
    /// interpolates numbers bilinearly in plot space and gives a text (a status) or a flag of
    /// the nearest cell.
    Grid {
        /// The model of the cells, as `solve` names it (`vlocator`: the locator's exact path).
        model: &'static str,
        /// The map's x parameter.
        x: Axis,
        /// The one plotting area.
        panels: Vec<Panel>,
        /// The cells.
        grid: Grid,
    },
    /// Stacked panels whose x axes may differ (the V-locator's optimum and robust charts, the
    /// time series, P(jam)): each panel has its own x axis and reads the sweep `sweep` names;
    /// the page reads the panel under the pointer, every quantity of every series at the
    /// pointer's x (straight between samples, as the curves are drawn), and lists the sweep's
    /// fixed inputs beside them.
    Panels {
        /// What answered: `statics`, `simulation` or `vlocator`.
        model: &'static str,
        /// The plotting areas, top to bottom.
        panels: Vec<SweepPanel>,
        /// The sweeps the panels read.
        sweeps: Vec<Sweep>,
    },
    /// Discrete points whose data is a table (the convergence trace, the work-precision and
    /// accuracy charts, the stability matrix): the page reads the point of the panel nearest
    /// the pointer (distance in fractions of the plotting area) and shows its whole row, the
    /// row of the chart's data file (CSV cells as their text, so the page and the file agree
    /// to the digit).
    Points {
        /// Whether the page draws lines from the point to the axes (false where they mean
        /// nothing: the matrix's cells).
        crosshair: bool,
        /// The size of a cell around each point in axis units, outlined when read (the
        /// matrix); left out for plain points.
        #[serde(skip_serializing_if = "Option::is_none")]
        cell: Option<[f64; 2]>,
        /// The plotting areas, top to bottom.
        panels: Vec<PointsPanel>,
        /// The rows the points name.
        rows: Rows,
    },
}

impl ReadOffData {
    /// The read-off as the page embeds it: compact JSON, every number that is not an integer
    /// at 7 significant digits, finer than any chart's resolution (a pixel is 1e-3 of an
    /// axis), so that `0.10200000000000001` becomes `0.102` and the page stays small.
    pub fn to_json(&self) -> String {
        page_json(self)
    }
}

/// `doc` as compact JSON with every `f64` rounded by [`crate::csv_out::significant`] (null
/// where not finite, as serde_json writes it).
fn page_json(doc: &impl Serialize) -> String {
    /// serde_json's compact form with rounded numbers.
    struct SevenDigits;
    impl serde_json::ser::Formatter for SevenDigits {
        fn write_f64<W: ?Sized + std::io::Write>(
            &mut self,
            w: &mut W,
            v: f64,
        ) -> std::io::Result<()> {
            let v = crate::csv_out::significant(v);
            serde_json::ser::CompactFormatter.write_f64(w, v)
        }
    }
    let mut out = Vec::new();
    doc.serialize(&mut serde_json::Serializer::with_formatter(
        &mut out,
        SevenDigits,
    ))
    .expect("read-off data has string keys and serialises");
    String::from_utf8(out).expect("serde_json writes UTF-8")
}

/// An axis as the read-off sees it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Axis {
    /// The parameter's key, which names it in the read-off's text and values; empty for an
    /// axis without a quantity (the matrix's), which the page does not print.
    pub param: &'static str,
    /// Quantity and unit, as drawn.
    pub label: String,
    /// The value at the axis' start.
    pub min: f64,
    /// The value at its end.
    pub max: f64,
    /// Whether the scale is logarithmic (the page maps it through ln, as drawn).
    pub log: bool,
}

impl Axis {
    /// The axis `a` as drawn, its quantity `param`.
    pub fn of(param: &'static str, a: &PlotAxis) -> Self {
        Axis {
            param,
            label: a.label.clone(),
            min: a.min,
            max: a.max,
            log: a.scale == AxisScale::Log,
        }
    }
}

/// A plotting area of a map: where it lies in the picture and its y axis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Panel {
    /// Where it lies, as fractions of the picture.
    pub frame: PlotFrame,
    /// Its y axis.
    pub y: Axis,
}

/// A plotting area of a sweep: [`Panel`] and the quantity it shows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QuantityPanel {
    /// Where it lies, as fractions of the picture.
    pub frame: PlotFrame,
    /// Its y axis.
    pub y: Axis,
    /// The key of the series' column it shows ([`SweepSeries`]).
    pub quantity: &'static str,
}

/// A plotting area of a `panels` read-off: its own x axis and the sweep it reads.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepPanel {
    /// Where it lies, as fractions of the picture.
    pub frame: PlotFrame,
    /// Its y axis.
    pub y: Axis,
    /// The key of the series' column the pointer's y is read against.
    pub quantity: &'static str,
    /// Its x axis.
    pub x: Axis,
    /// The index of the sweep it reads in `sweeps`.
    pub sweep: usize,
}

/// A plotting area of a `points` read-off: its axes and the points drawn in it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PointsPanel {
    /// Where it lies, as fractions of the picture.
    pub frame: PlotFrame,
    /// Its y axis.
    pub y: Axis,
    /// Its x axis.
    pub x: Axis,
    /// Each point as (x, y, index of its row in `rows`), finite.
    pub points: Vec<(f64, f64, usize)>,
}

impl PointsPanel {
    /// A panel of `points` (x, y, row), those not finite left out (not drawn either).
    pub fn new(frame: PlotFrame, x: Axis, y: Axis, points: &[(f64, f64, usize)]) -> Self {
        let points = (points.iter().copied())
            .filter(|(x, y, _)| x.is_finite() && y.is_finite())
            .collect();
        PointsPanel {
            frame,
            y,
            x,
            points,
        }
    }
}

/// Values under names the chart chooses, in order: a JSON object whose keys are data (a
/// map's quantities, a sweep's fixed inputs, a series' columns).
#[derive(Debug, Clone, PartialEq)]
pub struct Named<T>(pub Vec<(&'static str, T)>);

impl<T: Serialize> Serialize for Named<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_map(self.0.iter().map(|(k, v)| (k, v)))
    }
}

/// A jam map's boundary per column (each list one entry per column).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JamMapColumns {
    /// The column's value of the map's parameter, under its key (`x.param`).
    #[serde(flatten)]
    pub at: Named<Vec<f64>>,
    /// theta_jam in deg (null where the model gives none).
    pub theta_jam_deg: Vec<Option<f64>>,
    /// x_jam in mm (null where the model gives none).
    pub x_jam_mm: Vec<Option<f64>>,
    /// The boundary's status.
    pub status: Vec<JamStatus>,
    /// The palm angle in deg below which the contact lies past the palm's end.
    pub reach_deg: Vec<f64>,
}

/// The disc of a jam map, which places it at a palm angle theta:
/// x = r / tan(theta / 2) + palm offset / sin(theta).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Disc {
    /// Disc radius r in mm.
    pub radius_mm: f64,
    /// Palm offset in mm.
    pub palm_offset_mm: f64,
    /// Palm length in mm.
    pub palm_length_mm: f64,
}

/// A curve or markers of a sweep, one entry per point in each list.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SweepSeries {
    /// As in the legend.
    pub label: String,
    /// Its layer's name.
    pub layer: &'static str,
    /// Whether it is drawn as a line (read straight between points) or as markers (read
    /// within 2 % of the axis of the pointer).
    pub line: bool,
    /// The parameter's value of each point.
    pub at: Vec<f64>,
    /// x_jam in mm (null where the model gives none).
    pub x_jam_mm: Vec<Option<f64>>,
    /// theta_jam in deg (null where the model gives none).
    pub theta_jam_deg: Vec<Option<f64>>,
}

/// Most samples per axis of a grid read-off: 101 x 101 cells of three quantities at 7 digits
/// are about 300 kB of page, and the iso-lines they are read between are smooth (the browser
/// test measures the error against `solve`).
pub const GRID_SAMPLES: usize = 101;

/// A map's cells as the read-off carries them: every k-th row and column so that at most
/// [`GRID_SAMPLES`] per axis (and the last), row by row (x fastest).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Grid {
    /// The kept columns' x.
    pub x: Vec<f64>,
    /// The kept rows' y.
    pub y: Vec<f64>,
    /// Each quantity's value per kept cell, under its key.
    pub cells: Named<Cells>,
    /// The kept cells' flat indices in the map.
    #[serde(skip)]
    kept: Vec<usize>,
}

impl Grid {
    /// The kept cells of a map over `xs` by `ys` (cell (ix, iy) at flat index
    /// `iy * xs.len() + ix`), without quantities yet.
    pub fn over(xs: &[f64], ys: &[f64]) -> Self {
        let picks = |n: usize| {
            let mut v: Vec<usize> = (0..n).step_by(n.div_ceil(GRID_SAMPLES).max(1)).collect();
            if v.last() != Some(&(n - 1)) {
                v.push(n - 1);
            }
            v
        };
        let (ixs, iys) = (picks(xs.len()), picks(ys.len()));
        Grid {
            x: ixs.iter().map(|i| xs[*i]).collect(),
            y: iys.iter().map(|i| ys[*i]).collect(),
            cells: Named(Vec::new()),
            kept: (iys.iter())
                .flat_map(|iy| ixs.iter().map(move |ix| iy * xs.len() + ix))
                .collect(),
        }
    }

    /// With quantity `key`, a number per cell given its flat index.
    pub fn numbers(self, key: &'static str, at: impl Fn(usize) -> Option<f64>) -> Self {
        let cells = Cells::Numbers(self.kept.iter().map(|i| at(*i)).collect());
        self.with(key, cells)
    }

    /// With quantity `key`, a status per cell given its flat index.
    pub fn statuses(self, key: &'static str, at: impl Fn(usize) -> &'static str) -> Self {
        let cells = Cells::Statuses(self.kept.iter().map(|i| at(*i)).collect());
        self.with(key, cells)
    }

    /// With quantity `key`, a flag per cell given its flat index.
    pub fn flags(self, key: &'static str, at: impl Fn(usize) -> bool) -> Self {
        let cells = Cells::Flags(self.kept.iter().map(|i| at(*i)).collect());
        self.with(key, cells)
    }

    fn with(mut self, key: &'static str, cells: Cells) -> Self {
        self.cells.0.push((key, cells));
        self
    }
}

/// One quantity of a map's cells: numbers (null where there is none), statuses or flags.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Cells {
    /// A number per cell, interpolated by the page.
    Numbers(Vec<Option<f64>>),
    /// A status per cell, the nearest one's read.
    Statuses(Vec<&'static str>),
    /// A flag per cell, the nearest one's read.
    Flags(Vec<bool>),
}

/// A sweep of a `panels` read-off: the parameter's samples, the inputs held fixed and the
/// series read at them.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// The swept parameter's key.
    pub param: &'static str,
    /// Its samples.
    pub at: Vec<f64>,
    /// The inputs held fixed, under their keys, listed beside the read values.
    pub fixed: Named<Fixed>,
    /// The series, each quantity one entry per sample.
    pub series: Vec<PanelSeries>,
    /// Where `param` stands among the keys (see [`ParamKey`]).
    pub param_key: ParamKey,
}

/// Where a [`Sweep`]'s `param` is written: first (`param`, `at`, `fixed`, `series`) or last
/// (`at`, `series`, `fixed`, `param`, the V-locator optimum's page). The page reads both the
/// same; the order only keeps each page's bytes as they were.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamKey {
    /// `param`, `at`, `fixed`, `series`.
    First,
    /// `at`, `series`, `fixed`, `param`.
    Last,
}

impl Serialize for Sweep {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_struct("Sweep", 4)?;
        match self.param_key {
            ParamKey::First => {
                m.serialize_field("param", self.param)?;
                m.serialize_field("at", &self.at)?;
                m.serialize_field("fixed", &self.fixed)?;
                m.serialize_field("series", &self.series)?;
            }
            ParamKey::Last => {
                m.serialize_field("at", &self.at)?;
                m.serialize_field("series", &self.series)?;
                m.serialize_field("fixed", &self.fixed)?;
                m.serialize_field("param", self.param)?;
            }
        }
        m.end()
    }
}

/// An input a sweep holds fixed.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Fixed {
    /// A number (null where there is none: a time series' t_jam without a jam).
    Number(Option<f64>),
    /// A range, lo to hi.
    Range([f64; 2]),
    /// A status.
    Status(JamStatus),
    /// A text (a distribution).
    Text(String),
}

/// A series of a sweep: its label, scalars and quantities, each quantity one entry per
/// sample of the sweep (null where there is none, a gap in the curve).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PanelSeries {
    /// As in the legend.
    pub label: String,
    /// The friction coefficient of the series, where it has one (the V-locator's optimum).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mu: Option<f64>,
    /// The quantities, under their keys (a panel's `quantity` names one).
    #[serde(flatten)]
    pub columns: Named<Vec<Option<f64>>>,
}

/// The rows a `points` read-off's points name: the chart's data file, row by row.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum Rows {
    /// The min-norm program's convergence trace.
    Trace(Vec<TraceRow>),
    /// The work-precision study.
    Precision(Vec<PrecisionRow>),
    /// The accuracy study's wall-time chart.
    Accuracy(Vec<ErrorTimeRow>),
    /// The stability matrix, case by method.
    Stability(Vec<Answer>),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_keeps_seven_significant_digits() {
        #[derive(Serialize)]
        struct Doc {
            a: (f64, f64, Option<f64>, f64, u32, f64),
            b: &'static str,
        }
        let doc = Doc {
            a: (
                0.10200000000000001,
                30.951435839204933,
                None,
                f64::NAN,
                3,
                -0.0,
            ),
            b: "x",
        };
        assert_eq!(
            page_json(&doc),
            r#"{"a":[0.102,30.95144,null,null,3,-0.0],"b":"x"}"#
        );
    }
}
