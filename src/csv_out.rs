//! CSV files a spreadsheet reads: the csv crate writes serde rows (quoting is its business), and
//! every number is a plain decimal with sensible digits ([`Dec`]): no `2.47e1`, no `-0.00000`.
//!
//! Column names are the quantity's one name with its unit, as in JSON and TOML: `x_jam_mm`,
//! `theta_jam_deg`, `force_n`.

use serde::{Serialize, Serializer};

/// Significant digits of a CSV number: 7 resolve 10 nm on a 25 mm jam position and 1e-5 deg on
/// a 45 deg angle, below anything the models claim.
pub const SIGNIFICANT_DIGITS: i32 = 7;

/// A number written as a plain decimal with [`SIGNIFICANT_DIGITS`] (see [`plain`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dec(pub f64);

impl Serialize for Dec {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&plain(self.0))
    }
}

/// `v` as a plain decimal: [`SIGNIFICANT_DIGITS`] significant digits, no exponent, trailing
/// zeros dropped, never `-0`; empty for NaN and infinities.
pub fn plain(v: f64) -> String {
    let mut out = Vec::with_capacity(24);
    push_plain(&mut out, v);
    String::from_utf8(out).expect("digits, sign and point are ASCII")
}

/// Appends [`plain`]`(v)` to `out` without allocating.
///
/// The digits are those of std's exact `format!("{v:.N}")` (N decimals for
/// [`SIGNIFICANT_DIGITS`]), which costs an allocation and a big-number fallback per call: a map's
/// long CSV has 10^5 to 10^6 numbers. No crate does fixed significant digits without an
/// exponent: `ryu` and `dtoa` write the shortest round-trip digits only, and `lexical`'s
/// digit limit rounds those shortest digits a second time. So: scale by 10^N (exact for
/// N <= 22), round to an integer and write it with `itoa`; when the scaled value lies within
/// 1e-6 of a rounding tie (the scaling's error is below 2e-8) or out of that range, fall back
/// to std. A property test checks the two agree byte for byte.
pub fn push_plain(out: &mut Vec<u8>, v: f64) {
    if !v.is_finite() {
        return;
    }
    if v == 0.0 {
        out.push(b'0');
        return;
    }
    if !push_fast(out, v) {
        out.extend_from_slice(plain_std(v).as_bytes());
    }
}

/// Exact powers of ten as f64 (10^22 is the largest).
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// Exact negative powers of ten as f64, nearest: 10^-1 to 10^-22.
const POW10_NEG: [f64; 22] = [
    1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15,
    1e-16, 1e-17, 1e-18, 1e-19, 1e-20, 1e-21, 1e-22,
];

/// [`decimals`] by comparing with the powers of ten instead of `log10` (a sixth of a map's
/// CSV cost, callgrind of `render fig3`); None outside 1e-22..1e22.
///
/// The two can differ only for `a` within an ulp or so of a power of ten, where `log10`
/// rounds onto the integer; such an `a` rounds to that power at 7 significant digits and
/// at 8, so the digits written are the same (`fast_digits_are_std_digits` checks values
/// next to every power of ten against std with `log10`).
fn decimals_by_table(a: f64) -> Option<usize> {
    let below_one = POW10_NEG.iter().take_while(|&&p| a < p).count();
    if a >= 1.0 {
        let above = POW10.iter().take_while(|&&p| p <= a).count();
        (above < POW10.len()).then(|| (SIGNIFICANT_DIGITS as usize).saturating_sub(above))
    } else {
        (below_one < POW10_NEG.len()).then_some(SIGNIFICANT_DIGITS as usize + below_one)
    }
}

/// [`push_plain`] by scaled integer rounding; false (nothing written) where it could differ
/// from std's exact rounding.
fn push_fast(out: &mut Vec<u8>, v: f64) -> bool {
    let a = v.abs();
    let decimals = decimals_by_table(a).unwrap_or_else(|| decimals(a));
    let Some(&scale) = POW10.get(decimals) else {
        return false;
    };
    let scaled = a * scale;
    // 2^53: above it an f64 has no fraction, and u64 holds the integer.
    if scaled >= 9_007_199_254_740_992.0 {
        if decimals > 0 || a >= 1.8e19 {
            return false;
        }
        if v < 0.0 {
            out.push(b'-');
        }
        out.extend_from_slice(itoa::Buffer::new().format(a as u64).as_bytes());
        return true;
    }
    let floor = scaled.floor();
    if ((scaled - floor) - 0.5).abs() < 1e-6 {
        return false;
    }
    let q = scaled.round() as u64;
    if q == 0 {
        out.push(b'0');
        return true;
    }
    if v < 0.0 {
        out.push(b'-');
    }
    let mut digits = itoa::Buffer::new();
    let d = digits.format(q).as_bytes();
    if decimals == 0 {
        out.extend_from_slice(d);
        return true;
    }
    // Integer part, then the fraction padded with leading zeros, trailing zeros dropped.
    let int_len = d.len().saturating_sub(decimals);
    match int_len {
        0 => out.push(b'0'),
        n => out.extend_from_slice(&d[..n]),
    }
    let frac_digits = &d[int_len..];
    let Some(last) = frac_digits.iter().rposition(|c| *c != b'0') else {
        return true;
    };
    out.push(b'.');
    out.extend(std::iter::repeat_n(b'0', decimals - frac_digits.len()));
    out.extend_from_slice(&frac_digits[..=last]);
    true
}

/// Decimals that leave [`SIGNIFICANT_DIGITS`] significant digits of `a` (> 0).
fn decimals(a: f64) -> usize {
    let magnitude = a.log10().floor() as i32;
    (SIGNIFICANT_DIGITS - 1 - magnitude).max(0) as usize
}

/// [`plain`] through std's exact decimal formatting: the slow path, and the oracle of the tests.
fn plain_std(v: f64) -> String {
    let decimals = decimals(v.abs());
    let mut s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.truncate(s.trim_end_matches('0').trim_end_matches('.').len());
    }
    if s == "-0" { "0".into() } else { s }
}

/// Optional numbers as [`Dec`] (None is an empty cell).
pub fn dec(v: Option<f64>) -> Option<Dec> {
    v.map(Dec)
}

/// CSV of `rows`, the header from the row type's field names.
pub fn to_csv<R: Serialize>(rows: impl IntoIterator<Item = R>) -> Vec<u8> {
    write(csv::Writer::from_writer(Vec::new()), None, rows)
}

/// CSV of `rows` under `header` (for columns named at run time, e.g. the swept parameter).
pub fn to_csv_with_header<R: Serialize>(
    header: &[&str],
    rows: impl IntoIterator<Item = R>,
) -> Vec<u8> {
    let w = csv::WriterBuilder::new()
        .has_headers(false)
        .from_writer(Vec::new());
    write(w, Some(header), rows)
}

fn write<R: Serialize>(
    mut w: csv::Writer<Vec<u8>>,
    header: Option<&[&str]>,
    rows: impl IntoIterator<Item = R>,
) -> Vec<u8> {
    // Writing to memory fails only on a row that is not a flat record: a bug, not input.
    if let Some(h) = header {
        w.write_record(h).expect("a header writes");
    }
    for r in rows {
        w.serialize(r).expect("rows are flat records");
    }
    w.into_inner().expect("memory takes every byte")
}

/// A column of a map's cells, in index order `iy * nx + ix` (x fastest).
#[derive(Debug, Clone, Copy)]
pub enum Column<'a> {
    /// A value in every cell.
    Dense(&'a [f64]),
    /// An empty field where a cell has no value.
    Sparse(&'a [Option<f64>]),
    /// A word per cell, e.g. the status: `words[of[i]]` in cell i (a byte a cell, where a
    /// reference to the word was sixteen: 2.4 MB of fig3's 160,801 cells).
    Words {
        /// The words a cell may hold.
        words: &'a [&'a str],
        /// Each cell's word, as its index in `words`.
        of: &'a [u8],
    },
}

impl Column<'_> {
    fn push(&self, out: &mut Vec<u8>, i: usize) {
        match self {
            Column::Dense(v) => push_plain(out, v[i]),
            Column::Sparse(v) => v[i].into_iter().for_each(|x| push_plain(out, x)),
            Column::Words { words, of } => push_text(out, words[usize::from(of[i])]),
        }
    }
}

/// Long-format CSV of a map's cells: one row per cell (x fastest), the x value, the y value,
/// then each column; `header` names all of them. In memory: [`write_grid_cells`] streams it.
#[cfg(test)]
pub fn grid_cells(header: &[&str], xs: &[f64], ys: &[f64], columns: &[Column]) -> Vec<u8> {
    let mut out = Vec::new();
    write_grid_cells(&mut out, header, xs, ys, columns).expect("memory takes every byte");
    out
}

/// Rows buffered before they go to the writer: large enough that a file write is cheap, small
/// enough that a map of 10^7 cells never holds its CSV (hundreds of MB) in memory.
const ROWS_BUFFER_BYTES: usize = 1 << 16;

/// Writes [`grid_cells`] to `out` as it is made, [`ROWS_BUFFER_BYTES`] at a time.
///
/// The header goes through the csv crate; the rows are written here byte by byte: a number
/// ([`push_plain`]) is digits, a sign and a point, which never need quoting, and a word is
/// quoted as the csv crate quotes it ([`push_text`]). The csv crate's field writer, with its
/// quoting scan per field, was half the cost of a map's CSV (`render fig3`, callgrind);
/// `streamed_cells_are_the_csv_crates` checks the bytes against it.
pub fn write_grid_cells<W: std::io::Write>(
    mut out: W,
    header: &[&str],
    xs: &[f64],
    ys: &[f64],
    columns: &[Column],
) -> std::io::Result<()> {
    let fmt = |v: &f64| {
        let mut b = Vec::with_capacity(16);
        push_plain(&mut b, *v);
        b
    };
    let (xs, ys): (Vec<Vec<u8>>, Vec<Vec<u8>>) =
        (xs.iter().map(fmt).collect(), ys.iter().map(fmt).collect());
    let mut head = csv::WriterBuilder::new()
        .has_headers(false)
        .from_writer(Vec::new());
    head.write_record(header)?;
    let mut buf = head.into_inner().map_err(|e| e.into_error())?;
    buf.reserve(ROWS_BUFFER_BYTES + 256);
    for (iy, y) in ys.iter().enumerate() {
        for (ix, x) in xs.iter().enumerate() {
            let i = iy * xs.len() + ix;
            buf.extend_from_slice(x);
            buf.push(b',');
            buf.extend_from_slice(y);
            for c in columns {
                buf.push(b',');
                c.push(&mut buf, i);
            }
            buf.push(b'\n');
            if buf.len() >= ROWS_BUFFER_BYTES {
                out.write_all(&buf)?;
                buf.clear();
            }
        }
    }
    out.write_all(&buf)?;
    out.flush()
}

/// Appends `word` as the csv crate writes a field (its default, quote only where needed):
/// in double quotes, each quote doubled, when it holds a comma, a quote or a line break.
fn push_text(out: &mut Vec<u8>, word: &str) {
    if !word
        .bytes()
        .any(|b| matches!(b, b',' | b'"' | b'\n' | b'\r'))
    {
        out.extend_from_slice(word.as_bytes());
        return;
    }
    out.push(b'"');
    for b in word.bytes() {
        if b == b'"' {
            out.push(b'"');
        }
        out.push(b);
    }
    out.push(b'"');
}

/// A number for JSON with the digits of [`plain`]: rounded to [`SIGNIFICANT_DIGITS`], so that
/// serde_json's shortest form prints `24.35455`, not `24.354551362801473`; null for NaN and
/// infinities, `0` for `-0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl Serialize for Num {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match plain(self.0).parse::<f64>() {
            // A plain decimal of 7 digits parses to the f64 whose shortest form it is.
            Ok(v) if self.0.is_finite() => s.serialize_f64(v + 0.0),
            _ => s.serialize_none(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_plain_decimals_without_noise() {
        assert_eq!(plain(24.746092876045168), "24.74609");
        assert_eq!(plain(0.10200000000000001), "0.102");
        assert_eq!(plain(-0.000000001), "-0.000000001");
        assert_eq!(plain(-1e-12 * 1e-3), "-0.000000000000001");
        assert_eq!(plain(-0.0), "0");
        assert_eq!(plain(1e-2), "0.01");
        assert_eq!(plain(40816.79195004728), "40816.79");
        assert_eq!(plain(12_000_000.4), "12000000");
        assert_eq!(plain(f64::NAN), "");
    }

    #[test]
    fn rows_get_their_header_and_quoting() {
        #[derive(Serialize)]
        struct Row {
            layer: &'static str,
            x_jam_mm: Option<Dec>,
            reason: &'static str,
        }
        let rows = [
            Row {
                layer: "statics",
                x_jam_mm: Some(Dec(24.3546)),
                reason: "",
            },
            Row {
                layer: "min_norm",
                x_jam_mm: None,
                reason: "step size too small, at t = 0.4 s",
            },
        ];
        let text = String::from_utf8(to_csv(rows)).unwrap();
        assert_eq!(
            text,
            "layer,x_jam_mm,reason\nstatics,24.3546,\nmin_norm,,\"step size too small, at t = 0.4 s\"\n"
        );
        let text = String::from_utf8(to_csv_with_header(&["mu", "x"], [[Dec(0.1), Dec(-0.0)]]));
        assert_eq!(text.unwrap(), "mu,x\n0.1,0\n");
    }

    /// The fast path writes exactly std's digits: random values over 40 decades, values on
    /// and next to rounding ties, whole numbers and the limits of each branch.
    #[test]
    fn fast_digits_are_std_digits() {
        use proptest::prelude::*;
        let check = |v: f64| {
            let mut fast = Vec::new();
            push_plain(&mut fast, v);
            let fast = String::from_utf8(fast).unwrap();
            let want = if v.is_finite() && v != 0.0 {
                plain_std(v)
            } else {
                plain(v)
            };
            assert_eq!(fast, want, "{v:e}");
        };
        let config = proptest::test_runner::Config {
            cases: 20_000,
            ..Default::default()
        };
        let mut runner = proptest::test_runner::TestRunner::new_with_rng(
            config,
            proptest::test_runner::TestRng::deterministic_rng(Default::default()),
        );
        let slow = std::cell::Cell::new(0);
        let values = (1.0f64..10.0, -20i32..20, any::<bool>());
        runner
            .run(&values, |(m, e, neg)| {
                let v = m * 10f64.powi(e) * if neg { -1.0 } else { 1.0 };
                check(v);
                if (-15..=15).contains(&e) {
                    slow.set(slow.get() + usize::from(!push_fast(&mut Vec::new(), v)));
                }
                check(v.round());
                check(f64::from_bits(v.to_bits() + 1));
                Ok(())
            })
            .unwrap();
        // Between 1e-15 and 1e16 the fast path is the common one: std's path takes the exact
        // ties, rare but for values above about 1e13, whose ulp of 1/512 or more lands on x.5.
        assert!(slow.get() <= 200, "{} of 20000 took std's path", slow.get());
        for k in -22..=22 {
            let p = 10f64.powi(k);
            for v in [
                p,
                f64::from_bits(p.to_bits() - 1),
                f64::from_bits(p.to_bits() + 1),
            ] {
                check(v);
                check(-v);
            }
        }
        for v in [
            0.12345675,
            1.2345675,
            2.5,
            0.5,
            1234567.5,
            9999999.5,
            0.99999995,
            999999.95,
            1e-20,
            1e-22,
            1e-23,
            1e-300,
            5e-324,
            9.007199254740992e15,
            1.8e19,
            3e19,
            1e300,
            f64::MAX,
            f64::MIN_POSITIVE,
            -0.0,
            0.0,
            f64::NAN,
            f64::INFINITY,
            100.0,
            0.001,
        ] {
            check(v);
            check(-v);
        }
    }

    #[test]
    fn grid_cells_write_one_row_per_cell_x_fastest() {
        let text = grid_cells(
            &["mu", "theta_deg", "margin_n", "x_jam_mm"],
            &[0.1, 0.2],
            &[10.0],
            &[
                Column::Dense(&[-0.0, 1.0 / 3.0]),
                Column::Sparse(&[None, Some(24.354551362801473)]),
            ],
        );
        assert_eq!(
            String::from_utf8(text).unwrap(),
            "mu,theta_deg,margin_n,x_jam_mm\n0.1,10,0,\n0.2,10,0.3333333,24.35455\n"
        );
    }

    /// The rows as the csv crate wrote them before they were streamed: the oracle.
    fn grid_cells_by_the_csv_crate(
        header: &[&str],
        xs: &[f64],
        ys: &[f64],
        columns: &[Column],
    ) -> Vec<u8> {
        let mut w = csv::WriterBuilder::new()
            .has_headers(false)
            .from_writer(Vec::new());
        w.write_record(header).unwrap();
        let mut buf = Vec::new();
        for iy in 0..ys.len() {
            for ix in 0..xs.len() {
                for v in [xs[ix], ys[iy]] {
                    buf.clear();
                    push_plain(&mut buf, v);
                    w.write_field(&buf).unwrap();
                }
                for c in columns {
                    buf.clear();
                    match c {
                        Column::Dense(v) => push_plain(&mut buf, v[iy * xs.len() + ix]),
                        Column::Sparse(v) => v[iy * xs.len() + ix]
                            .into_iter()
                            .for_each(|x| push_plain(&mut buf, x)),
                        Column::Words { words, of } => buf.extend_from_slice(
                            words[usize::from(of[iy * xs.len() + ix])].as_bytes(),
                        ),
                    }
                    w.write_field(&buf).unwrap();
                }
                w.write_record(None::<&[u8]>).unwrap();
            }
        }
        w.into_inner().unwrap()
    }

    proptest::proptest! {
        /// Streamed rows are the csv crate's, byte for byte: numbers of every size and sign,
        /// empty cells, words that need quoting, and maps past the row buffer's size.
        #[test]
        fn streamed_cells_are_the_csv_crates(
            nx in 1usize..40,
            ny in 1usize..40,
            values in proptest::collection::vec(proptest::num::f64::ANY, 1..64),
            words in proptest::collection::vec("[a-z_,\"\n\r ]{0,6}", 1..6),
        ) {
            let n = nx * ny;
            let dense: Vec<f64> = (0..n).map(|i| values[i % values.len()]).collect();
            let sparse: Vec<Option<f64>> =
                (0..n).map(|i| (i % 3 != 0).then(|| values[(i * 7) % values.len()])).collect();
            let words: Vec<&str> = words.iter().map(String::as_str).collect();
            let of: Vec<u8> = (0..n).map(|i| (i % words.len()) as u8).collect();
            let xs: Vec<f64> = (0..nx).map(|i| values[(i * 3) % values.len()]).collect();
            let ys: Vec<f64> = (0..ny).map(|i| i as f64 * 0.1 - 1.0).collect();
            let header = ["x, mm", "y", "a", "b", "c"];
            let columns = [Column::Dense(&dense), Column::Sparse(&sparse), Column::Words { words: &words, of: &of }];
            proptest::prop_assert_eq!(
                grid_cells(&header, &xs, &ys, &columns),
                grid_cells_by_the_csv_crate(&header, &xs, &ys, &columns)
            );
        }
    }

    /// A map larger than the row buffer streams in pieces, with the bytes of the whole.
    #[test]
    fn a_large_map_streams_in_pieces_with_the_same_bytes() {
        struct Counting(Vec<u8>, usize);
        impl std::io::Write for Counting {
            fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
                self.1 += 1;
                self.0.extend_from_slice(b);
                Ok(b.len())
            }
            fn flush(&mut self) -> std::io::Result<()> {
                Ok(())
            }
        }
        let xs: Vec<f64> = (0..300).map(|i| f64::from(i) / 7.0).collect();
        let margin: Vec<f64> = (0..300 * 300).map(|i| f64::from(i).sin() * 40.0).collect();
        let header = ["mu", "theta_deg", "margin_n"];
        let columns = [Column::Dense(&margin)];
        let mut w = Counting(Vec::new(), 0);
        write_grid_cells(&mut w, &header, &xs, &xs, &columns).unwrap();
        assert!(w.0.len() > 20 * ROWS_BUFFER_BYTES, "{} bytes", w.0.len());
        assert!(w.1 > 20, "{} writes", w.1);
        assert_eq!(
            w.0,
            grid_cells_by_the_csv_crate(&header, &xs, &xs, &columns)
        );
    }

    #[test]
    fn json_numbers_have_the_csv_digits() {
        let nums: Vec<Num> = [24.354551362801473, -0.0, 1e-9, f64::NAN, 40.0]
            .map(Num)
            .into();
        let doc = serde_json::to_string(&nums);
        assert_eq!(doc.unwrap(), "[24.35455,0.0,1e-9,null,40.0]");
    }
}
