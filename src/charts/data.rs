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

/// The cells of `grid` as long-format CSV: one row per cell (x fastest), the two axis values then
/// each `(column, values)` (see [`crate::csv_out::grid_cells`]).
pub fn cells_csv(
    grid: &crate::grid::GridResult,
    x: GridParam,
    y: GridParam,
    columns: &[(&str, Column)],
) -> DataFile {
    let (header, values) = cells_columns(x, y, columns);
    DataFile::csv(grid_cells(&header, &grid.x_values, &grid.y_values, &values))
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
    let (header, values) = cells_columns(x, y, columns);
    let file = format!("{scene}.csv");
    cells_summary(&file, &header, (grid.nx(), grid.ny()), &values)
}

fn cells_columns<'a, 'b>(
    x: GridParam,
    y: GridParam,
    columns: &[(&'a str, Column<'b>)],
) -> (Vec<&'a str>, Vec<Column<'b>>) {
    let mut header = vec![x.as_str(), y.as_str()];
    header.extend(columns.iter().map(|(name, _)| *name));
    (header, columns.iter().map(|(_, c)| *c).collect())
}
