//! The data files written beside a chart: [`DataFile`], and a map's cells as long-format CSV.

use crate::figures::{DataFormat, FigureData};

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

    /// The data file of a figure of scene `scene` titled `title`: a JSON figure's serde form
    /// under the scene's name and title (and a map's `cells_file`, its cells' CSV), every number rounded to
    /// [`SIGNIFICANT_DIGITS`](crate::csv_out::SIGNIFICANT_DIGITS) (null where not finite); a CSV
    /// figure's rows.
    pub(crate) fn of<D: FigureData>(data: &D, scene: &str, title: &str) -> Self {
        match D::FORMAT {
            DataFormat::Json => {
                #[derive(serde::Serialize)]
                struct Doc<'a, D> {
                    scene: &'a str,
                    title: &'a str,
                    #[serde(skip_serializing_if = "Option::is_none")]
                    cells_file: Option<String>,
                    #[serde(flatten)]
                    data: &'a D,
                }
                let cells_file = data.cells().map(|_| format!("{scene}.csv"));
                let mut doc = serde_json::to_value(Doc {
                    scene,
                    title,
                    cells_file,
                    data,
                })
                .expect("figure data serialises to JSON");
                round_numbers(&mut doc);
                Self::json(&doc)
            }
            DataFormat::Csv => Self::csv(data.csv()),
        }
    }

    /// CSV bytes, numbers in plain decimals.
    pub fn csv(bytes: Vec<u8>) -> Self {
        DataFile {
            extension: "csv",
            bytes,
        }
    }
}

/// Every number of `doc` that is not an integer rounded as [`crate::csv_out::Num`] rounds it,
/// in place (the document rebuilt, each object's keys inserted again, cost as much as the
/// rounding).
fn round_numbers(doc: &mut serde_json::Value) {
    use serde_json::Value;
    match doc {
        Value::Number(n) => {
            if let Some(v) = n.as_f64().filter(|_| n.is_f64()) {
                *doc = serde_json::to_value(crate::csv_out::Num(v)).expect("a number serialises");
            }
        }
        Value::Array(a) => a.iter_mut().for_each(round_numbers),
        Value::Object(o) => o.values_mut().for_each(round_numbers),
        _ => {}
    }
}
