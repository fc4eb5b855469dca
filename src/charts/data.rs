//! The data files written beside a chart: [`DataFile`], and a map's cells as long-format CSV.

use crate::csv_out::{Dec, dec, to_csv_with_header};
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
/// each `(column, values)` (an empty cell where a value is None).
pub fn cells_csv(
    grid: &crate::grid::GridResult,
    x: GridParam,
    y: GridParam,
    columns: &[(&str, Vec<Option<f64>>)],
) -> DataFile {
    let mut header = vec![x.as_str(), y.as_str()];
    header.extend(columns.iter().map(|(name, _)| *name));
    let rows = grid.y_values.iter().enumerate().flat_map(|(iy, yv)| {
        grid.x_values.iter().enumerate().map(move |(ix, xv)| {
            let i = grid.index(ix, iy);
            let mut row = vec![Some(Dec(*xv)), Some(Dec(*yv))];
            row.extend(columns.iter().map(|(_, v)| dec(v[i])));
            row
        })
    });
    DataFile::csv(to_csv_with_header(&header, rows))
}
