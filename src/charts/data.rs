//! The data files written beside a chart: [`DataFile`], and a map's cells as long-format CSV.

use crate::csv_out::{Column, cells_summary, write_grid_cells};
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

/// A map's cells as they go into its long-format CSV: one row per cell (x fastest), the two
/// axis values then each column (see [`crate::csv_out::write_grid_cells`]). Borrowed from the
/// chart and written straight to the file: a map of 10^7 cells never holds its CSV in memory.
#[derive(Debug, Clone)]
pub struct CellsTable<'a> {
    header: Vec<&'a str>,
    xs: &'a [f64],
    ys: &'a [f64],
    columns: Vec<Column<'a>>,
}

impl CellsTable<'_> {
    /// Writes the CSV to `out` as it is made.
    pub fn write(&self, out: &mut dyn std::io::Write) -> std::io::Result<()> {
        write_grid_cells(out, &self.header, self.xs, self.ys, &self.columns)
    }

    /// The CSV in memory (tests, hashes).
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = Vec::new();
        self.write(&mut out).expect("memory takes every byte");
        out
    }
}

/// The cells of `grid` as a [`CellsTable`], each `(column, values)` named as in its JSON.
pub fn cells_csv<'a>(
    grid: &'a crate::grid::GridResult,
    x: GridParam,
    y: GridParam,
    columns: &[(&'a str, Column<'a>)],
) -> CellsTable<'a> {
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
pub fn axis_cells_csv<'a>(axes: CellAxes<'a>, columns: &[(&'a str, Column<'a>)]) -> CellsTable<'a> {
    let (header, columns) = cells_columns(axes, columns);
    CellsTable {
        header,
        xs: axes[0].1,
        ys: axes[1].1,
        columns,
    }
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
