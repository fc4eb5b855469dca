//! The one registration point of chart kinds: `chart_kinds!` lists them, and generates from
//! that list the scene's `[chart]` settings ([`ChartSpec`]), the computed chart ([`Chart`]) and
//! every dispatch between them.
//!
//! A kind is a module with two types: its `[chart]` settings, which implement [`Kind`] (checks,
//! compute), and the computed chart, which draws itself on any backend and gives its data.
//! Adding a kind is that module, one line in the list below (its variant, `kind` key, data
//! format `json` for maps or `csv`, settings and chart types) and a
//! scene `charts/<name>.toml` (compiled in by `build.rs`), with its keys in charts/README.md
//! (`tests/scene_docs.rs` fails until they are there).

use plotters::coord::Shift;
use plotters::prelude::*;
use serde::Serialize;
use serde::de::DeserializeOwned;

use super::axes::{DrawResult, PlotFrame};
use super::spec::Scene;
use super::{
    DataFile, contour_map, convergence, jam_map, stability, sweep, time_series, universal,
    vlocator_capacity, vlocator_optimum, vlocator_robust, work_precision,
};
use crate::config::read_section;
use crate::error::Result;
use crate::figures::models::Models;
use crate::figures::{CellsTable, Figure, FigureData};
use crate::grid::GridAxis;

/// A chart kind's `[chart]` settings: how they are checked and how they compute their chart.
///
/// The computed chart draws itself and gives its data: it has the methods
/// `draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB>` (on a
/// white root, any backend) and `data(&self, scene: &Scene) -> DataFile`, which the list's
/// dispatch calls.
pub(crate) trait Kind: Sized + DeserializeOwned + Serialize {
    /// The computed chart.
    type Chart;

    /// The axes over scene parameters, as (key under `[chart]`, axis): the scene checks that a
    /// `mu` axis does not hide two different frictions, `--read-off` that its value is on the
    /// axis. None by default.
    fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
        Vec::new()
    }

    /// Whether the chart reads the palm scene's `[scene]` parameters (a V-locator's chart has
    /// its own, under `[chart.locator]`). True by default.
    fn takes_scene(&self) -> bool {
        true
    }

    /// Whether the chart marks the scene's own value of its x axis' parameter (read-off lines),
    /// so that setting it shows although the axis varies it. False by default.
    fn marks_scene_value(&self) -> bool {
        false
    }

    /// Turns on the read-off at the scene's own values (`render --read-off`); false for a kind
    /// that has none (the settings stay as they were).
    fn enable_read_off(&mut self) -> bool {
        false
    }

    /// Checks the settings against the scene, before anything is computed.
    fn validate(&self, scene: &Scene) -> Result<()>;

    /// Checks the chart's size against [`crate::limits`] (memory and output it would need).
    fn check_size(&self, scene: &Scene) -> Result<()>;

    /// Computes what the chart draws; min-norm programs and simulations go through `models`.
    fn compute(&self, scene: &Scene, models: &dyn Models) -> Result<Self::Chart>;

    /// Whether the chart may write its cells as long-format CSV beside its JSON (a map).
    const CELLS: bool = false;

    /// A map's cells as long-format CSV, beside its JSON (None by default).
    fn cells(_chart: &Self::Chart) -> Option<super::data::CellsTable<'_>> {
        None
    }
}

/// A chart kind's picture: its figure's data ([`crate::figures`]) ready to draw, on any
/// backend, with the gallery's read-off derived from the same data.
pub(crate) trait Picture: Sized {
    /// The kind's `[chart]` settings, which compute the data.
    type Settings: Figure;

    /// `data` prepared for drawing (geometry traced once for both formats) under `title`.
    fn new(data: <Self::Settings as Figure>::Data, title: &str) -> Self;

    /// The data drawn.
    fn data(&self) -> &<Self::Settings as Figure>::Data;

    /// Draws on a white root.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB>;

    /// What the gallery's read-off needs (see [`super::readoff`]), given the plotting areas the
    /// drawing built; None where the frames do not match the drawing.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<serde_json::Value>;

    /// The data file of `scene`: the data's serde form (JSON) or rows (CSV).
    fn data_file(&self, scene: &Scene) -> DataFile {
        DataFile::of(self.data(), &scene.name, &scene.title)
    }
}

/// The [`Kind`] of a kind split into a figure and a picture: computes the figure from the
/// scene's input and prepares it for drawing. (A kind not yet split implements [`Kind`]
/// itself.)
macro_rules! split_kind {
    (legacy $spec:ty => $chart:ty) => {};
    (figure $spec:ty => $chart:ty) => {
        impl Kind for $spec {
            const CELLS: bool = <<$spec as Figure>::Data as FigureData>::CELLS;
            type Chart = $chart;

            fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
                Figure::param_axes(self)
            }

            fn takes_scene(&self) -> bool {
                Figure::takes_scene(self)
            }

            fn marks_scene_value(&self) -> bool {
                Figure::marks_scene_value(self)
            }

            fn enable_read_off(&mut self) -> bool {
                Figure::enable_read_off(self)
            }

            fn validate(&self, scene: &Scene) -> Result<()> {
                Figure::validate(self, &scene.input())
            }

            fn check_size(&self, scene: &Scene) -> Result<()> {
                Figure::check_size(self, &scene.input())
            }

            fn compute(&self, scene: &Scene, models: &dyn Models) -> Result<$chart> {
                let data = Figure::compute(self, &scene.input(), models)
                    .map_err(|e| e.in_scene(&scene.name))?;
                Ok(<$chart as Picture>::new(data, &scene.title))
            }

            fn cells(chart: &$chart) -> Option<CellsTable<'_>> {
                chart.data().cells()
            }
        }
    };
}

/// Generates [`ChartSpec`], [`Chart`] and their dispatch from the list of kinds.
macro_rules! chart_kinds {
    ($($(#[$doc:meta])* $variant:ident($name:literal, $data:literal, $mode:ident $spec:ty => $chart:ty),)+) => {
        $(split_kind!($mode $spec => $chart);)+

        /// The chart kind and its settings (`[chart]`, chosen by its `kind` key).
        #[derive(Debug, Clone, PartialEq)]
        pub enum ChartSpec {
            $($(#[$doc])* $variant($spec),)+
        }

        /// A computed chart of any kind.
        #[allow(missing_docs)] // one variant per kind, documented on ChartSpec
        pub enum Chart {
            $($variant($chart),)+
        }

        impl ChartSpec {
            /// Every kind's `kind` key, in the order of the list.
            pub const KINDS: &[&str] = &[$($name,)+];

            /// The `kind` key.
            pub fn kind(&self) -> &'static str {
                match self {
                    $(ChartSpec::$variant(_) => $name,)+
                }
            }

            /// The extensions of the data files the chart may write: its data (`json` for
            /// maps and tables, `csv` else), then a map's cells (`csv` beside `json`).
            pub fn data_extensions(&self) -> Vec<&'static str> {
                let (data, cells) = match self {
                    $(ChartSpec::$variant(_) => ($data, <$spec as Kind>::CELLS),)+
                };
                let mut exts = vec![data];
                exts.extend(cells.then_some("csv"));
                exts
            }

            pub(crate) fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
                match self {
                    $(ChartSpec::$variant(s) => Kind::param_axes(s),)+
                }
            }

            pub(crate) fn takes_scene(&self) -> bool {
                match self {
                    $(ChartSpec::$variant(s) => Kind::takes_scene(s),)+
                }
            }

            pub(crate) fn marks_scene_value(&self) -> bool {
                match self {
                    $(ChartSpec::$variant(s) => Kind::marks_scene_value(s),)+
                }
            }

            pub(crate) fn enable_read_off(&mut self) -> bool {
                match self {
                    $(ChartSpec::$variant(s) => Kind::enable_read_off(s),)+
                }
            }

            pub(crate) fn validate(&self, scene: &Scene) -> Result<()> {
                match self {
                    $(ChartSpec::$variant(s) => Kind::validate(s, scene),)+
                }
            }

            pub(crate) fn check_size(&self, scene: &Scene) -> Result<()> {
                match self {
                    $(ChartSpec::$variant(s) => Kind::check_size(s, scene),)+
                }
            }

            /// The settings of kind `kind` from the rest of `[chart]`; None for an unknown
            /// kind.
            pub(crate) fn read(
                kind: &str,
                table: &toml::Table,
            ) -> Option<std::result::Result<ChartSpec, crate::config::Refusal>> {
                $(if kind == $name {
                    return Some(read_section(table, table, "chart").map(ChartSpec::$variant));
                })+
                None
            }
        }

        /// As written in a scene: the kind's keys and `kind`.
        impl Serialize for ChartSpec {
            fn serialize<S: serde::Serializer>(
                &self,
                serializer: S,
            ) -> std::result::Result<S::Ok, S::Error> {
                use serde::ser::Error as _;
                let mut table = match self {
                    $(ChartSpec::$variant(s) => toml::Table::try_from(s),)+
                }
                .map_err(S::Error::custom)?;
                table.insert("kind".into(), self.kind().into());
                table.serialize(serializer)
            }
        }

        impl Chart {
            /// Computes what `scene`'s chart draws; min-norm programs and simulations go
            /// through `models`.
            pub(crate) fn compute_with(
                scene: &Scene,
                models: &dyn Models,
            ) -> Result<Chart> {
                Ok(match &scene.chart {
                    $(ChartSpec::$variant(s) => Chart::$variant(Kind::compute(s, scene, models)?),)+
                })
            }

            pub(crate) fn draw_kind<DB: DrawingBackend>(
                &self,
                root: &DrawingArea<DB, Shift>,
            ) -> DrawResult<DB> {
                match self {
                    $(Chart::$variant(c) => c.draw(root),)+
                }
            }

            /// A map's cells as long-format CSV: the two parameters and each quantity per
            /// cell, units in the header; None for charts whose data is CSV already.
            pub fn cells(&self) -> Option<super::data::CellsTable<'_>> {
                match self {
                    $(Chart::$variant(c) => <$spec as Kind>::cells(c),)+
                }
            }

            /// The gallery's read-off data (see [`super::readoff`]), given the plotting areas
            /// the drawing built ([`super::axes::record_frames`]); every kind has one (None only
            /// where the frames do not match the drawing).
            pub fn read_off(&self, frames: &[PlotFrame]) -> Option<serde_json::Value> {
                match self {
                    $(Chart::$variant(c) => c.read_off(frames),)+
                }
            }

            /// The data behind the chart.
            pub fn data_file(&self, scene: &Scene) -> DataFile {
                match self {
                    $(Chart::$variant(c) => c.data_file(scene),)+
                }
            }
        }
    };
}

chart_kinds! {
    /// A jam/slide map over a parameter and the palm angle (Fig. 3).
    JamMap("jam_map", "json", figure crate::figures::jam_map::JamMapSettings => jam_map::JamMap),
    /// theta_jam and x_jam against one parameter (Figs. 6, 7a, 7b).
    Sweep("sweep", "csv", legacy sweep::SweepSpec => sweep::Sweep),
    /// theta_jam and x_jam / r over a friction and F / (m g): one chart for any part.
    Universal("universal", "json", figure crate::figures::universal::UniversalSettings => universal::Universal),
    /// Iso-lines of x_jam and theta_jam over two parameters (Fig. 7c).
    ContourMap("contour_map", "json", figure crate::figures::contour_map::ContourMapSettings => contour_map::ContourMap),
    /// The min-norm program's convergence trace at theta_jam (Fig. 4).
    Convergence("convergence", "csv", legacy convergence::ConvergenceSpec => convergence::Convergence),
    /// The simulated disc speed and position against time (Fig. 5).
    TimeSeries("time_series", "csv", legacy time_series::TimeSeriesSpec => time_series::TimeSeries),
    /// Error of x_jam against cost per integrator, and the min-norm tolerance against its
    /// error (the accuracy study).
    WorkPrecision("work_precision", "csv", legacy work_precision::WorkPrecisionSpec => work_precision::WorkPrecision),
    /// Holding capacity of a V-locator over included angle and load direction.
    VlocatorCapacity("vlocator_capacity", "json", legacy vlocator_capacity::VlocatorCapacitySpec => vlocator_capacity::VlocatorCapacity),
    /// Optimum included angle of a V-locator against load direction and load.
    VlocatorOptimum("vlocator_optimum", "json", legacy vlocator_optimum::VlocatorOptimumSpec => vlocator_optimum::VlocatorOptimum),
    /// The included-angle window of a V-block over friction and load ranges.
    VlocatorRobust("vlocator_robust", "csv", legacy vlocator_robust::VlocatorRobustSpec => vlocator_robust::VlocatorRobust),
    /// The stability matrix: case by method, coloured by class.
    Stability("stability", "json", legacy stability::StabilitySpec => stability::Stability),
}

impl ChartSpec {
    /// The V-block a V-locator chart is drawn for (its `locator` table); None for the charts of
    /// the palm scene, whose parameters are the scene's.
    pub fn locator(&self) -> Option<&crate::locator::LocatorParams> {
        match self {
            ChartSpec::VlocatorCapacity(s) => Some(&s.locator),
            ChartSpec::VlocatorOptimum(s) => Some(&s.locator),
            ChartSpec::VlocatorRobust(s) => Some(&s.locator),
            _ => None,
        }
    }
}
