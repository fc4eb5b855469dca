//! The one registration point of chart kinds: `chart_kinds!` lists them, and generates from
//! that list the scene's `[chart]` settings ([`ChartSpec`]), the drawn chart ([`Chart`]) and
//! every dispatch between them.
//!
//! A kind is a triple: its settings (the `[chart]` keys, which compute the figure's data:
//! [`crate::figures::Figure`]), its data ([`crate::figures::FigureData`], the data file), and
//! its picture (a module of `charts` implementing [`Picture`], which draws the data). Adding a
//! kind is its figure module under `src/figures/`, its picture module here, one line in the list
//! below and a scene `charts/<name>.toml` (compiled in by `build.rs`), with its keys in
//! charts/README.md (`tests/scene_docs.rs` fails until they are there).

use plotters::coord::Shift;
use plotters::prelude::*;
use serde::Serialize;

use super::DataFile;
use super::axes::{DrawResult, PlotFrame};
use super::picture::Picture;
use super::readoff::ReadOffData;
use super::{
    contour_map, convergence, jam_map, jam_probability, stability, sweep, time_series, universal,
    vlocator_capacity, vlocator_optimum, vlocator_robust, work_precision,
};
use crate::config::read_section;
use crate::error::Result;
use crate::figures::models::Models;
use crate::figures::{self as fig, CellsTable, Figure, FigureData, Input};
use crate::grid::GridAxis;

/// Generates [`ChartSpec`], [`Chart`] and their dispatch from the list of kinds.
macro_rules! chart_kinds {
    ($($(#[$doc:meta])* $variant:ident($name:literal, $spec:ty => $chart:ty),)+) => {
        /// The chart kind and its settings (`[chart]`, chosen by its `kind` key).
        #[derive(Debug, Clone, PartialEq)]
        pub enum ChartSpec {
            $($(#[$doc])* $variant($spec),)+
        }

        /// A computed chart of any kind, ready to draw.
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
                let (format, cells) = match self {
                    $(ChartSpec::$variant(_) => (
                        <<$spec as Figure>::Data as FigureData>::FORMAT,
                        <<$spec as Figure>::Data as FigureData>::CELLS,
                    ),)+
                };
                let mut exts = vec![format.extension()];
                exts.extend(cells.then_some("csv"));
                exts
            }

            pub(crate) fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
                match self {
                    $(ChartSpec::$variant(s) => s.param_axes(),)+
                }
            }

            pub(crate) fn takes_scene(&self) -> bool {
                match self {
                    $(ChartSpec::$variant(s) => s.takes_scene(),)+
                }
            }

            /// The parameters the chart is drawn with, for the gallery's table: its heading
            /// and the values by their TOML keys ([`Figure::parameters`]).
            pub(crate) fn parameters(&self, input: &Input) -> (&'static str, toml::Table) {
                match self {
                    $(ChartSpec::$variant(s) => s.parameters(input),)+
                }
            }

            pub(crate) fn marks_scene_value(&self) -> bool {
                match self {
                    $(ChartSpec::$variant(s) => s.marks_scene_value(),)+
                }
            }

            pub(crate) fn enable_read_off(&mut self) -> bool {
                match self {
                    $(ChartSpec::$variant(s) => s.enable_read_off(),)+
                }
            }

            pub(crate) fn validate(&self, input: &Input) -> Result<()> {
                match self {
                    $(ChartSpec::$variant(s) => s.validate(input),)+
                }
            }

            pub(crate) fn check_size(&self, input: &Input) -> Result<()> {
                match self {
                    $(ChartSpec::$variant(s) => s.check_size(input),)+
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
            /// Computes the figure of `spec` from `input` (min-norm programs and simulations
            /// through `models`) and prepares it for drawing under `title`.
            pub(crate) fn compute(
                spec: &ChartSpec,
                input: &Input,
                title: &str,
                models: &dyn Models,
            ) -> Result<Chart> {
                Ok(match spec {
                    $(ChartSpec::$variant(s) => {
                        Chart::$variant(<$chart as Picture>::new(s.compute(input, models)?, title))
                    })+
                })
            }

            /// Draws on a white root, any backend.
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
            pub fn cells(&self) -> Option<CellsTable<'_>> {
                match self {
                    $(Chart::$variant(c) => c.data().cells(),)+
                }
            }

            /// The gallery's read-off data, given the plotting areas
            /// the drawing built ([`super::axes::record_frames`]); every kind has one (None only
            /// where the frames do not match the drawing).
            pub fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
                match self {
                    $(Chart::$variant(c) => c.read_off(frames),)+
                }
            }

            /// The data file of scene `scene` titled `title`.
            pub fn data_file(&self, scene: &str, title: &str) -> DataFile {
                match self {
                    $(Chart::$variant(c) => c.data_file(scene, title),)+
                }
            }

            /// The figure's typed data as its serde form, every number as computed (the data
            /// file rounds them to 7 significant digits).
            pub fn data_value(&self) -> serde_json::Value {
                match self {
                    $(Chart::$variant(c) => {
                        serde_json::to_value(c.data()).expect("figure data serialises")
                    })+
                }
            }
        }
    };
}

chart_kinds! {
    /// A jam/slide map over a parameter and the palm angle (Fig. 3).
    JamMap("jam_map", fig::jam_map::JamMapSettings => jam_map::JamMap),
    /// theta_jam and x_jam against one parameter (Figs. 6, 7a, 7b).
    Sweep("sweep", fig::sweep::SweepSettings => sweep::Sweep),
    /// theta_jam and x_jam / r over a friction and F / (m g): one chart for any part.
    Universal("universal", fig::universal::UniversalSettings => universal::Universal),
    /// P(jam before x) against x for a distributed input, exact or Monte Carlo with its band.
    JamProbability("jam_probability", fig::jam_probability::JamProbabilitySettings => jam_probability::JamProbability),
    /// Iso-lines of x_jam and theta_jam over two parameters (Fig. 7c).
    ContourMap("contour_map", fig::contour_map::ContourMapSettings => contour_map::ContourMap),
    /// The min-norm program's convergence trace at theta_jam (Fig. 4).
    Convergence("convergence", fig::convergence::ConvergenceSettings => convergence::Convergence),
    /// The simulated disc speed and position against time (Fig. 5).
    TimeSeries("time_series", fig::time_series::TimeSeriesSettings => time_series::TimeSeries),
    /// Error of x_jam against cost per integrator, and the min-norm tolerance against its
    /// error (the accuracy study).
    WorkPrecision("work_precision", fig::work_precision::WorkPrecisionSettings => work_precision::WorkPrecision),
    /// Holding capacity of a V-locator over included angle and load direction.
    VlocatorCapacity("vlocator_capacity", fig::vlocator_capacity::VlocatorCapacitySettings => vlocator_capacity::VlocatorCapacity),
    /// Optimum included angle of a V-locator against load direction and load.
    VlocatorOptimum("vlocator_optimum", fig::vlocator_optimum::VlocatorOptimumSettings => vlocator_optimum::VlocatorOptimum),
    /// The included-angle window of a V-block over friction and load ranges.
    VlocatorRobust("vlocator_robust", fig::vlocator_robust::VlocatorRobustSettings => vlocator_robust::VlocatorRobust),
    /// The stability matrix: case by method, coloured by class.
    Stability("stability", fig::stability::StabilitySettings => stability::Stability),
}
