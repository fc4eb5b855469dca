//! A map's cells: written in full as long-format CSV beside its JSON, and summarised in it.

use serde::ser::{Serialize, SerializeMap, Serializer};

use crate::csv_out::{Column, Num, write_grid_cells};

/// A map's two axes for its cells: (name with unit, values), x then y.
pub type CellAxes<'a> = [(&'a str, &'a [f64]); 2];

/// A map's cells as they go into its long-format CSV: one row per cell (x fastest), the two
/// axis values then each column (as `csv_out::write_grid_cells` writes them). Borrowed from the
/// figure and written straight to the file: a map of 10^7 cells never holds its CSV in memory.
///
/// Its serde form is what a map's JSON says of its cells: the grid's size, the columns and,
/// per column, its least and greatest value and how many cells have one (a column of words:
/// how many cells say each word).
#[derive(Debug, Clone)]
pub struct CellsTable<'a> {
    header: Vec<&'a str>,
    xs: &'a [f64],
    ys: &'a [f64],
    columns: Vec<Column<'a>>,
}

impl<'a> CellsTable<'a> {
    /// The cells over `axes`, each `(name, column)` in index order `iy * nx + ix`.
    pub(crate) fn new(axes: CellAxes<'a>, columns: &[(&'a str, Column<'a>)]) -> Self {
        let mut header = vec![axes[0].0, axes[1].0];
        header.extend(columns.iter().map(|(name, _)| *name));
        CellsTable {
            header,
            xs: axes[0].1,
            ys: axes[1].1,
            columns: columns.iter().map(|(_, c)| *c).collect(),
        }
    }
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

impl Serialize for CellsTable<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(5))?;
        map.serialize_entry("nx", &self.xs.len())?;
        map.serialize_entry("ny", &self.ys.len())?;
        map.serialize_entry("order", "one row per cell, x fastest")?;
        map.serialize_entry("columns", &self.header)?;
        let summary: Vec<(&str, Summary)> = self.header[2..]
            .iter()
            .zip(&self.columns)
            .map(|(name, c)| (*name, Summary::of(c)))
            .collect();
        map.serialize_entry("summary", &Ordered(&summary))?;
        map.end()
    }
}

/// A column's summary in a map's JSON.
enum Summary<'a> {
    /// Least and greatest finite value, and how many cells have one.
    Numbers {
        min: Option<f64>,
        max: Option<f64>,
        cells_with_value: usize,
    },
    /// How many cells say each word, in the order the words first appear.
    Words(Vec<(&'a str, usize)>),
}

impl<'a> Summary<'a> {
    fn of(c: &Column<'a>) -> Self {
        let values: Vec<f64> = match c {
            Column::Dense(v) => v.iter().copied().filter(|x| x.is_finite()).collect(),
            Column::Sparse(v) => v
                .iter()
                .flatten()
                .copied()
                .filter(|x| x.is_finite())
                .collect(),
            Column::Words { words, of } => {
                // Each index counted, with its first cell, in one pass (a string compare per
                // cell was three quarters of `render fig3`'s data file); then the words in the
                // order of their first cell, an index whose word repeats another's merged.
                let (mut count, mut first) = ([0usize; 256], [0usize; 256]);
                for (cell, &w) in of.iter().enumerate() {
                    let w = usize::from(w);
                    if count[w] == 0 {
                        first[w] = cell;
                    }
                    count[w] += 1;
                }
                let mut seen: Vec<usize> = (0..256).filter(|&w| count[w] > 0).collect();
                seen.sort_by_key(|&w| first[w]);
                let mut counts: Vec<(&str, usize)> = Vec::new();
                for w in seen {
                    match counts.iter_mut().find(|(k, _)| *k == words[w]) {
                        Some((_, n)) => *n += count[w],
                        None => counts.push((words[w], count[w])),
                    }
                }
                return Summary::Words(counts);
            }
        };
        Summary::Numbers {
            min: values.iter().copied().reduce(f64::min),
            max: values.iter().copied().reduce(f64::max),
            cells_with_value: values.len(),
        }
    }
}

impl Serialize for Summary<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(None)?;
        match self {
            Summary::Numbers {
                min,
                max,
                cells_with_value,
            } => {
                map.serialize_entry("min", &min.map(Num))?;
                map.serialize_entry("max", &max.map(Num))?;
                map.serialize_entry("cells_with_value", cells_with_value)?;
            }
            Summary::Words(counts) => map.serialize_entry("cells", &Ordered(counts))?,
        }
        map.end()
    }
}

/// Pairs serialised as a map in their order.
struct Ordered<'a, V>(&'a [(&'a str, V)]);

impl<V: Serialize> Serialize for Ordered<'_, V> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_map(self.0.iter().map(|(k, v)| (k, v)))
    }
}

/// Serialises a map's optional cells as their summary (serde's `serialize_with`).
pub(crate) fn summary<C, S>(cells: &Option<C>, s: S) -> Result<S::Ok, S::Error>
where
    C: HasCells,
    S: Serializer,
{
    match cells {
        Some(c) => c.table().serialize(s),
        None => s.serialize_none(),
    }
}

/// Serialises a map's cells as their summary (serde's `serialize_with`).
pub(crate) fn summary_of<C, S>(cells: &C, s: S) -> Result<S::Ok, S::Error>
where
    C: HasCells,
    S: Serializer,
{
    cells.table().serialize(s)
}

/// A figure's grid of cells, written as a [`CellsTable`].
pub(crate) trait HasCells {
    /// The cells as they go into the CSV.
    fn table(&self) -> CellsTable<'_>;
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A column of words is counted per word, in first-seen order, and written word for word.
    #[test]
    fn a_text_column_is_counted_and_written_as_words() {
        let cols = [(
            "region",
            Column::Words {
                words: &["jam", "slide", "beyond_reach"],
                of: &[0, 1, 0, 2],
            },
        )];
        let xs = [0.0, 1.0];
        let t = CellsTable::new([("x", &xs), ("y", &xs)], &cols);
        let doc = serde_json::to_value(&t).unwrap();
        assert_eq!(
            doc["summary"]["region"]["cells"],
            serde_json::json!({"jam": 2, "slide": 1, "beyond_reach": 1})
        );
        assert_eq!(
            String::from_utf8(t.to_bytes()).unwrap(),
            "x,y,region\n0,0,jam\n1,0,slide\n0,1,jam\n1,1,beyond_reach\n"
        );
    }

    /// Words are summed over every index that spells them and listed in the order of their
    /// first cell, not of their index.
    #[test]
    fn words_are_counted_in_the_order_of_their_first_cell() {
        let cols = [(
            "region",
            Column::Words {
                words: &["slide", "jam", "slide", "beyond_reach"],
                of: &[1, 3, 2, 0, 1, 1],
            },
        )];
        let (xs, ys) = ([0.0, 1.0, 2.0], [0.0, 1.0]);
        let t = CellsTable::new([("x", &xs), ("y", &ys)], &cols);
        let doc = serde_json::to_string(&serde_json::to_value(&t).unwrap()["summary"]).unwrap();
        assert_eq!(
            doc,
            r#"{"region":{"cells":{"jam":3,"beyond_reach":1,"slide":2}}}"#
        );
    }
}
