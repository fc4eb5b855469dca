//! What a chart kind draws: [`Picture`], its figure's data prepared for drawing.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::DataFile;
use super::axes::{DrawResult, PlotFrame};
use super::readoff::ReadOffData;
use crate::figures::Figure;

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

    /// What the gallery's read-off needs ([`ReadOffData`]), given the plotting areas the
    /// drawing built; None where the frames do not match the drawing.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData>;

    /// The data file of scene `scene` titled `title`: the data's serde form (JSON) or rows
    /// (CSV).
    fn data_file(&self, scene: &str, title: &str) -> DataFile {
        DataFile::of(self.data(), scene, title)
    }
}
