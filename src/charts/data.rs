//! The data files written beside a chart: [`DataFile`], and a map's cells as long-format CSV.

use crate::csv_out::{Column, cells_summary, grid_cells};
use crate::grid::GridParam;

/// The data behind a chart: file extension and bytes.
#[derive(Debug, Clone, PartialEq)]
pub struct DataFile {
    /// `csv` or `json`.
    pub extension: &'static str,
    /// The file content.
    pub bytes: Vec<u8>,
}

impl DataFile {
    /// Compact JSON of `doc` with a trailing newline.
    pub fn json(doc: &serde_json::Value) -> Self {
        let mut bytes = serde_json::to_vec(doc).expect("JSON values serialise");
        bytes.push(b'\n');
        DataFile {
            extension: "json",
            bytes,
        }
    }

    /// CSV bytes (see [`crate::csv_out`]).
    pub fn csv(bytes: Vec<u8>) -> Self {
        DataFile {
            extension: "csv",
            bytes,
        }
    }
}

/// A map's two axes for its cells: (name with unit, values), x then y.
pub type CellAxes<'a> = [(&'a str, &'a [f64]); 2];

/// The cells of `grid` as long-format CSV: one row per cell (x fastest), the two axis values then
/// each `(column, values)` (see [`crate::csv_out::grid_cells`]).
pub fn cells_csv(
    grid: &crate::grid::GridResult,
    x: GridParam,
    y: GridParam,
    columns: &[(&str, Column)],
) -> DataFile {
    axis_cells_csv(grid_axes(grid, x, y), columns)
}

/// What a map's JSON says about the cells [`cells_csv`] writes to `<scene>.csv` (see
/// [`crate::csv_out::cells_summary`]): the same column names.
pub fn cells_json(
    scene: &str,
    grid: &crate::grid::GridResult,
    x: GridParam,
    y: GridParam,
    columns: &[(&str, Column)],
) -> serde_json::Value {
    axis_cells_json(scene, grid_axes(grid, x, y), columns)
}

fn grid_axes(grid: &crate::grid::GridResult, x: GridParam, y: GridParam) -> CellAxes<'_> {
    [
        (x.as_str(), &grid.x_values[..]),
        (y.as_str(), &grid.y_values[..]),
    ]
}

/// [`cells_csv`] over any two named axes (a V-locator's parameters, say).
pub fn axis_cells_csv(axes: CellAxes, columns: &[(&str, Column)]) -> DataFile {
    let (header, values) = cells_columns(axes, columns);
    DataFile::csv(grid_cells(&header, axes[0].1, axes[1].1, &values))
}

/// [`cells_json`] over any two named axes.
pub fn axis_cells_json(
    scene: &str,
    axes: CellAxes,
    columns: &[(&str, Column)],
) -> serde_json::Value {
    let (header, values) = cells_columns(axes, columns);
    let file = format!("{scene}.csv");
    cells_summary(&file, &header, (axes[0].1.len(), axes[1].1.len()), &values)
}

fn cells_columns<'a, 'b>(
    axes: CellAxes<'a>,
    columns: &[(&'a str, Column<'b>)],
) -> (Vec<&'a str>, Vec<Column<'b>>) {
    let mut header = vec![axes[0].0, axes[1].0];
    header.extend(columns.iter().map(|(name, _)| *name));
    (header, columns.iter().map(|(_, c)| *c).collect())
}
