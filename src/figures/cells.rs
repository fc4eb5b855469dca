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
        match c {
            Column::Dense(v) => Self::extremes(Self::reduce_dense(v)),
            Column::Sparse(v) => Self::extremes(Self::reduce(v.iter().flatten().copied())),
            Column::Words { words, of } => {
                // Each index counted in one pass (a string compare per cell was three quarters
                // of `render fig3`'s data file); then the words in the order of their first
                // cell, an index whose word repeats another's merged.
                let mut count = [0usize; 256];
                for &w in of.iter() {
                    count[usize::from(w)] += 1;
                }
                let mut seen: Vec<usize> = (0..256).filter(|&w| count[w] > 0).collect();
                let first = |w: usize| of.iter().position(|&x| usize::from(x) == w);
                seen.sort_by_cached_key(|&w| first(w));
                let mut counts: Vec<(&str, usize)> = Vec::new();
                for w in seen {
                    match counts.iter_mut().find(|(k, _)| *k == words[w]) {
                        Some((_, n)) => *n += count[w],
                        None => counts.push((words[w], count[w])),
                    }
                }
                Summary::Words(counts)
            }
        }
    }

    /// The least and greatest finite value of `values` (+inf and -inf without one) and how
    /// many are finite, in one pass with nothing collected (a copy of every finite value, read
    /// three times, and a branch per value were two thirds of `render fig3`'s data file).
    ///
    /// Compares and selects, without a branch. Where -0 and 0 tie for an extreme either may be
    /// kept: the JSON writes both as 0 ([`Num`]).
    fn reduce(values: impl Iterator<Item = f64>) -> (f64, f64, usize) {
        let (mut min, mut max, mut cells_with_value) = (f64::INFINITY, f64::NEG_INFINITY, 0);
        for x in values {
            let finite = x.is_finite();
            min = if finite && x < min { x } else { min };
            max = if finite && x > max { x } else { max };
            cells_with_value += usize::from(finite);
        }
        (min, max, cells_with_value)
    }

    /// [`Summary::reduce`] of a column with a value in every cell, in four lanes that the
    /// compiler keeps in vector registers.
    fn reduce_dense(values: &[f64]) -> (f64, f64, usize) {
        const LANES: usize = 4;
        let (mut min, mut max) = ([f64::INFINITY; LANES], [f64::NEG_INFINITY; LANES]);
        let mut count = [0usize; LANES];
        let mut quads = values.chunks_exact(LANES);
        for quad in &mut quads {
            for k in 0..LANES {
                let (x, finite) = (quad[k], quad[k].is_finite());
                min[k] = if finite && x < min[k] { x } else { min[k] };
                max[k] = if finite && x > max[k] { x } else { max[k] };
                count[k] += usize::from(finite);
            }
        }
        let (rest_min, rest_max, rest) = Self::reduce(quads.remainder().iter().copied());
        let lower = |a: f64, b: f64| if b < a { b } else { a };
        let upper = |a: f64, b: f64| if b > a { b } else { a };
        (
            min.into_iter().fold(rest_min, lower),
            max.into_iter().fold(rest_max, upper),
            rest + count.iter().sum::<usize>(),
        )
    }

    /// The summary of `cells_with_value` finite values from `min` to `max`.
    fn extremes((min, max, cells_with_value): (f64, f64, usize)) -> Self {
        let some = |v: f64| (cells_with_value > 0).then_some(v);
        Summary::Numbers {
            min: some(min),
            max: some(max),
            cells_with_value,
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

    proptest::proptest! {
        /// A column's least and greatest value and count, in lanes, are those of the plain
        /// fold over the finite values, whatever the length and wherever NaN and infinities lie.
        #[test]
        fn dense_extremes_are_the_plain_folds(
            values in proptest::collection::vec(proptest::num::f64::ANY, 0..40),
        ) {
            let finite: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
            let plain = (
                finite.iter().copied().reduce(f64::min),
                finite.iter().copied().reduce(f64::max),
                finite.len(),
            );
            let Summary::Numbers { min, max, cells_with_value } = Summary::of(&Column::Dense(&values))
            else {
                panic!("a column of numbers");
            };
            // A tie of -0 and 0 may keep either; the JSON writes both as 0.
            let zero = |v: Option<f64>| v.map(|x| x + 0.0);
            proptest::prop_assert_eq!((zero(min), zero(max), cells_with_value), (zero(plain.0), zero(plain.1), plain.2));
        }
    }
}
