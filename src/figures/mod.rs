//! Figures as data: what each chart kind computes, as typed values, before anything is drawn.
//!
//! A figure's settings (the kind's `[chart]` keys) and an [`Input`] (the scene's parameters and
//! the models' settings) go into `compute`, which calls only the model port ([`Models`]), the
//! grid and the studies, and returns the kind's data: a `Serialize` struct whose serde form is
//! the chart's data file (JSON), or whose rows are (CSV). [`crate::charts`] draws that data;
//! any other front end can take it as it is, without a picture.
//!
//! Kinds, one module each: [`jam_map`] (Fig. 3), [`convergence`] (Fig. 4), [`time_series`]
//! (Fig. 5), [`sweep`] (Figs. 6, 7a, 7b, with [`sweep_layers`] and [`band`]), [`contour_map`] (Fig. 7c), [`jam_probability`] (P(jam before x) under a distributed input), [`universal`] (one chart for any part),
//! [`work_precision`] (the accuracy study), [`stability`] (the stability matrix);
//! [`vlocator_capacity`], [`vlocator_optimum`] and [`vlocator_robust`] (V-type locators,
//! [`crate::locator`]); [`error_time`] is `jamchart accuracy`'s measured study, not a scene.

pub mod band;
pub(crate) mod cells;
pub mod contour_map;
pub mod contours;
pub mod convergence;
pub mod error_time;
mod iso_rings;
pub mod jam_map;
pub mod jam_probability;
pub(crate) mod models;
pub mod stability;
pub mod sweep;
pub mod sweep_layers;
pub mod time_series;
pub mod universal;
pub mod vlocator_capacity;
pub mod vlocator_optimum;
pub mod vlocator_robust;
pub mod work_precision;

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::dynamics::DynamicsParams;
use crate::error::Result;
use crate::grid::{GridAxis, JamPoint};
use crate::minnorm::MinNormSettings;
use crate::scene::Param;
use crate::scene::SceneParams;

pub use crate::csv_out::Dec;
pub use cells::CellsTable;
pub use models::{Models, TouchingDisc};

/// What a figure is computed from besides its own settings: the scene's parameters and the
/// settings of the models it may run.
#[derive(Debug, Clone, PartialEq)]
pub struct Input {
    /// The palm scene (a V-locator figure has its own parameters in its settings).
    pub params: SceneParams,
    /// The minimum-norm model's settings (used only by figures that solve programs).
    pub min_norm: MinNormSettings,
    /// The simulation's settings (used only by figures that simulate).
    pub dynamics: DynamicsParams,
}

/// A chart kind's `[chart]` settings: how they are checked, and how they compute the figure's
/// data through the model port.
pub(crate) trait Figure: Sized + DeserializeOwned + Serialize {
    /// The computed figure.
    type Data: FigureData;

    /// The axes over scene parameters, as (key under `[chart]`, axis): the scene checks that a
    /// `mu` axis does not hide two different frictions, `--read-off` that its value is on the
    /// axis. None by default.
    fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
        Vec::new()
    }

    /// Whether the figure reads the palm scene's parameters (a V-locator's figure has its own,
    /// under `[chart.locator]`). True by default.
    fn takes_scene(&self) -> bool {
        true
    }

    /// The parameters the chart is drawn with, for the gallery's table: its heading ("scene",
    /// "V-block") and the values by their TOML keys. The palm scene's by default.
    fn parameters(&self, input: &Input) -> (&'static str, toml::Table) {
        (
            "scene",
            toml::Table::try_from(input.params).unwrap_or_default(),
        )
    }

    /// Whether the figure marks the scene's own value of its x axis' parameter (a read-off),
    /// so that setting it shows although the axis varies it. False by default.
    fn marks_scene_value(&self) -> bool {
        false
    }

    /// Turns on the read-off at the scene's own values (`render --read-off`); false for a kind
    /// that has none (the settings stay as they were).
    fn enable_read_off(&mut self) -> bool {
        false
    }

    /// Checks the settings against the input, before anything is computed.
    fn validate(&self, input: &Input) -> Result<()>;

    /// Checks the figure's size against [`crate::limits`] (memory and output it would need).
    fn check_size(&self, input: &Input) -> Result<()>;

    /// Computes the figure; min-norm programs and simulations go through `models`.
    fn compute(&self, input: &Input, models: &dyn Models) -> Result<Self::Data>;
}

/// A model's jam at a point of a figure's parameters; its serde form names them,
/// `{"mu": 0.4, "status": "jams", "theta_jam_deg": 44.64619, "x_jam_mm": 24.35455}`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct At<const N: usize> {
    /// The parameters.
    pub params: [Param; N],
    /// Their values, in their units.
    pub at: [f64; N],
    /// The model's answer there.
    pub point: JamPoint,
}

impl<const N: usize> Serialize for At<N> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = s.serialize_map(Some(N + 3))?;
        for (param, v) in self.params.iter().zip(&self.at) {
            map.serialize_entry(param.as_str(), v)?;
        }
        map.serialize_entry("status", &self.point.status)?;
        map.serialize_entry("theta_jam_deg", &self.point.theta_jam_deg)?;
        map.serialize_entry("x_jam_mm", &self.point.x_jam_mm)?;
        map.end()
    }
}

/// How a figure's data file is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DataFormat {
    /// The data's serde form as JSON, every number to
    /// seven significant digits; a map's cells go beside it
    /// as long-format CSV.
    Json,
    /// The data's rows as CSV (a table: a sweep, a trace, a study).
    Csv,
}

impl DataFormat {
    /// The data file's extension.
    pub fn extension(self) -> &'static str {
        match self {
            DataFormat::Json => "json",
            DataFormat::Csv => "csv",
        }
    }
}

/// A computed figure: typed data whose serde form is its data file.
pub(crate) trait FigureData: Serialize {
    /// How the data file is written.
    const FORMAT: DataFormat;

    /// Whether the figure may have cells written beside its JSON (a map).
    const CELLS: bool = false;

    /// The CSV of a [`DataFormat::Csv`] figure: its rows.
    fn csv(&self) -> Vec<u8> {
        Vec::new()
    }

    /// A map's cells as long-format CSV, beside its JSON (None by default, and for a map
    /// whose cells were not computed).
    fn cells(&self) -> Option<CellsTable<'_>> {
        None
    }
}
