//! CSV files a spreadsheet reads: the csv crate writes serde rows (quoting is its business), and
//! every number is a plain decimal with sensible digits ([`Dec`]): no `2.47e1`, no `-0.00000`.
//!
//! Column names are the quantity's one name with its unit, as in JSON and TOML: `x_jam_mm`,
//! `theta_jam_deg`, `force_n`.

use serde::{Serialize, Serializer};

/// Significant digits of a CSV number: 7 resolve 10 nm on a 25 mm jam position and 1e-5 deg on
/// a 45 deg angle, below anything the models claim.
pub const SIGNIFICANT_DIGITS: i32 = 7;

/// A number in a data file, written as a plain decimal of 7 significant digits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dec(pub f64);

impl Serialize for Dec {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&plain(self.0))
    }
}

/// `v` as a plain decimal: [`SIGNIFICANT_DIGITS`] significant digits, no exponent, trailing
/// zeros dropped, never `-0`; empty for NaN and infinities. Below 1.8e19 (what a u64 holds)
/// every whole digit is kept; beyond, the whole digits past the seventh are 0
/// ([`plain_wide`]).
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
/// N <= 22) and round to an integer ([`Rounded`]), whose eight digits are placed around the
/// point by word operations; when the scaled value lies within 1e-6 of a rounding tie (the
/// scaling's error is below 2e-8) or out of that range, fall back to std. A property test
/// checks the two agree byte for byte.
pub fn push_plain(out: &mut Vec<u8>, v: f64) {
    if !v.is_finite() {
        return;
    }
    if v == 0.0 {
        out.push(b'0');
        return;
    }
    match Rounded::of(v) {
        Some(r) => r.push(out),
        None if !(WIDE_BELOW..WIDE_FROM).contains(&v.abs()) => plain_wide(out, v),
        None => out.extend_from_slice(plain_std(v).as_bytes()),
    }
}

/// Below this magnitude [`plain`] writes a number from its seven digits in exponent form
/// ([`plain_wide`]): the same text as std's fixed formatting, which works out hundreds of
/// exact digits first (1e-300 has 306 decimals).
const WIDE_BELOW: f64 = 1e-22;

/// From this magnitude (what a u64 holds) [`plain`] keeps seven significant digits and writes
/// the other whole digits as 0 ([`plain_wide`]).
const WIDE_FROM: f64 = 1.8e19;

/// [`plain`] of a number of more than 22 decimal places or beyond [`WIDE_FROM`], from the
/// seven digits of `format!("{v:.6e}")`.
///
/// std's fixed formatting works out every exact digit of such a number, 300 for 1e300 (whose
/// whole digits past the seventeenth are the binary expansion's, not the model's), tens of
/// microseconds each: `render fig3 --set mass_kg=1:1e300` spent 93 % of half a minute on them,
/// writing a margin of 1e300 N in each of its 160,801 cells. Below 1e-22 the text is std's
/// (the seventh digit's place is the same in both forms, and both round exactly there); from
/// [`WIDE_FROM`] on, the whole digits past the seventh are 0, as the seven significant digits
/// promise.
fn plain_wide(out: &mut Vec<u8>, v: f64) {
    let e = format!("{v:.6e}");
    let (mantissa, exponent) = e.split_once('e').expect("the e form has an exponent");
    let exponent: i64 = exponent.parse().expect("the exponent is an integer");
    let digits: Vec<u8> = mantissa.bytes().filter(u8::is_ascii_digit).collect();
    let end = digits.iter().rposition(|&d| d != b'0').map_or(1, |i| i + 1);
    let digits = &digits[..end];
    if v < 0.0 {
        out.push(b'-');
    }
    match usize::try_from(exponent) {
        // A whole part of exponent + 1 digits, the fraction after it.
        Ok(e) => {
            let whole = e + 1;
            out.extend_from_slice(&digits[..digits.len().min(whole)]);
            out.extend(std::iter::repeat_n(
                b'0',
                whole.saturating_sub(digits.len()),
            ));
            if digits.len() > whole {
                out.push(b'.');
                out.extend_from_slice(&digits[whole..]);
            }
        }
        // 0.(-exponent - 1 zeros)(the digits).
        Err(_) => {
            out.extend_from_slice(b"0.");
            out.extend(std::iter::repeat_n(b'0', (-exponent - 1) as usize));
            out.extend_from_slice(digits);
        }
    }
}

/// Exact powers of ten as f64 (10^22 is the largest).
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// Powers of ten as f64 from 10^-22 to 10^22: `TENS[22 + k]` is 10^k, exact for k >= 0 and
/// the nearest f64 below.
const TENS: [f64; 45] = [
    1e-22, 1e-21, 1e-20, 1e-19, 1e-18, 1e-17, 1e-16, 1e-15, 1e-14, 1e-13, 1e-12, 1e-11, 1e-10,
    1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7,
    1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// [`decimals`] by comparing with a power of ten instead of `log10` (a sixth of a map's CSV
/// cost, callgrind of `render fig3`); None outside 1e-22..1e22.
///
/// The decimal exponent k of `a` (`TENS`'s last entry <= a) is m or m + 1, where m =
/// floor(e log10 2) for `a`'s binary exponent e (a is in [2^e, 2^(e+1)), whose decimal
/// logarithms lie within log10 2 < 1 of each other): one compare with 10^(m+1) tells which.
/// (`1233 / 4096` is log10 2 to 5e-6, exact in the floor for |e| < 681, far beyond the
/// table.) The two can differ from `log10` only for `a` within an ulp or so of a power of ten,
/// where `log10` rounds onto the integer; such an `a` rounds to that power at 7 significant
/// digits and at 8, so the digits written are the same (`fast_digits_are_std_digits` checks
/// values next to every power of ten against std with `log10`).
fn decimals_by_table(a: f64) -> Option<usize> {
    let exponent = ((a.to_bits() >> 52) & 0x7ff) as i64 - 1023;
    let m = (exponent * 1233) >> 12;
    // 10^(m+1) is TENS[m + 23]; outside -23..=21 a lies outside the table's range.
    let next = TENS.get(usize::try_from(m + 23).ok()?)?;
    let k = m + i64::from(a >= *next);
    (-22..22)
        .contains(&k)
        .then(|| (SIGNIFICANT_DIGITS as i64 - 1 - k).max(0) as usize)
}

/// Room a short number takes in a row ([`Rounded::write_short`] writes at most 25 bytes).
const SHORT_NUMBER: usize = 32;

/// `|v|` rounded to `decimals` decimals as std rounds it: `q / 10^decimals`, `q` >= 1.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Rounded {
    /// The digits as an integer.
    q: u64,
    /// Where the decimal point goes: 0 to 22.
    decimals: usize,
    /// The sign of v.
    negative: bool,
}

impl Rounded {
    /// `v` (finite, not 0) by scaled integer rounding; None where it could differ from std's
    /// exact rounding.
    ///
    /// Below 2^53 the scaled value's floor is its conversion to an integer and its fraction the
    /// exact difference, so no libm `floor` or `round`.
    #[inline(always)]
    fn of(v: f64) -> Option<Rounded> {
        let a = v.abs();
        Self::with_decimals(v, decimals_by_table(a).unwrap_or_else(|| decimals(a)))
    }

    /// [`Rounded::of`] for any `v`, None also for 0, NaN and the infinities: their exponent
    /// lies outside [`decimals_by_table`]'s table, which covers every number [`Rounded::of`]
    /// rounds (decimals above 22 do not scale exactly). So a map's numbers need no test of
    /// their own before it (its bit tests were 14 of the 268 instructions a row of
    /// `render fig3`'s cells took).
    #[inline(always)]
    fn of_any(v: f64) -> Option<Rounded> {
        Self::with_decimals(v, decimals_by_table(v.abs())?)
    }

    /// [`Rounded::of`] with `decimals` worked out.
    #[inline(always)]
    fn with_decimals(v: f64, decimals: usize) -> Option<Rounded> {
        let a = v.abs();
        let scale = *POW10.get(decimals)?;
        let scaled = a * scale;
        let negative = v < 0.0;
        // 2^53: above it an f64 has no fraction, and u64 holds the integer.
        if scaled >= 9_007_199_254_740_992.0 {
            return (decimals == 0 && a < 1.8e19).then_some(Rounded {
                q: a as u64,
                decimals,
                negative,
            });
        }
        // Through i64, one instruction each way where u64 takes a dozen: scaled < 2^53.
        let floor = scaled as i64;
        let fraction = scaled - floor as f64;
        if (fraction - 0.5).abs() < 1e-6 {
            return None;
        }
        // Round half away from zero, as f64::round; no tie gets here.
        let q = floor as u64 + u64::from(fraction > 0.5);
        (q > 0).then_some(Rounded {
            q,
            decimals,
            negative,
        })
    }

    /// The value the digits spell: q and 10^decimals are exact f64, so their quotient is the
    /// decimal correctly rounded, as parsing the text would give it.
    fn value(self) -> f64 {
        let v = self.q as f64 / POW10[self.decimals];
        if self.negative { -v } else { v }
    }

    /// Appends the digits, the point placed and the fraction's trailing zeros dropped.
    #[inline]
    fn push(self, out: &mut Vec<u8>) {
        let mut text = [0u8; SHORT_NUMBER];
        match self.write_short(&mut text) {
            Some(len) => out.extend_from_slice(&text[..len]),
            None => self.push_long(out),
        }
    }

    /// [`Rounded::push`] into the front of `to` for q < 10^8 (every number of at most
    /// [`SIGNIFICANT_DIGITS`] digits but the whole ones above 10^8), its length; None, nothing
    /// written, for a larger q.
    ///
    /// The eight digits of q ([`eight_digits`]) are placed by word-sized copies and shifts,
    /// their zeros counted by `leading_zeros` and `trailing_zeros` of the word: no loop and no
    /// call. At most 25 bytes are written: a sign, `0.`, 14 zeros and 8 digits.
    #[inline(always)]
    fn write_short(self, to: &mut [u8; SHORT_NUMBER]) -> Option<usize> {
        const ZEROS: u64 = u64::from_le_bytes([b'0'; 8]);
        let q = u32::try_from(self.q).ok().filter(|&q| q < 100_000_000)?;
        let digits = eight_digits(q);
        let text = digits + ZEROS;
        // Zero digits at the end and at the front of the eight (q >= 1, so not all of them).
        let trailing = (digits.leading_zeros() / 8) as usize;
        let leading = (digits.trailing_zeros() / 8) as usize;
        to[0] = b'-';
        let mut at = usize::from(self.negative);
        let d = self.decimals;
        if d >= 8 {
            // 0.(d - 8 zeros)(the eight digits): at most 14 zeros, as d <= 22.
            to[at..at + 2].copy_from_slice(b"0.");
            to[at + 2..at + 18].copy_from_slice(&[b'0'; 16]);
            at += 2 + (d - 8);
            to[at..at + 8].copy_from_slice(&text.to_le_bytes());
            at += 8 - trailing;
        } else {
            let int_len = 8 - d;
            // The integer part without its leading zeros, but one.
            let skip = leading.min(int_len - 1);
            to[at..at + 8].copy_from_slice(&(text >> (8 * skip)).to_le_bytes());
            at += int_len - skip;
            let fraction = d.saturating_sub(trailing);
            if fraction > 0 {
                to[at] = b'.';
                to[at + 1..at + 9].copy_from_slice(&(text >> (8 * int_len)).to_le_bytes());
                at += 1 + fraction;
            }
        }
        Some(at)
    }

    /// [`Rounded::push`] for any q, by `itoa`.
    fn push_long(self, out: &mut Vec<u8>) {
        let (mut q, mut decimals) = (self.q, self.decimals);
        while decimals > 0 && q % 10 == 0 {
            q /= 10;
            decimals -= 1;
        }
        if self.negative {
            out.push(b'-');
        }
        let mut digits = itoa::Buffer::new();
        let d = digits.format(q).as_bytes();
        // Integer part, then the fraction padded with leading zeros.
        match d.len().checked_sub(decimals) {
            Some(0) | None => out.push(b'0'),
            Some(int_len) => out.extend_from_slice(&d[..int_len]),
        }
        if decimals > 0 {
            out.push(b'.');
            out.extend(std::iter::repeat_n(b'0', decimals.saturating_sub(d.len())));
            out.extend_from_slice(&d[d.len().saturating_sub(decimals)..]);
        }
    }
}

/// The eight decimal digits of `q` (< 10^8, zero-padded) as the bytes of a u64, the first digit
/// in the lowest byte (so `to_le_bytes` reads them in order), each 0 to 9: two halves of four
/// digits, then pairs, then digits, each split done in all lanes at once by a multiply and a
/// shift (x / 100 = x * 10486 >> 20 for x < 10^4, x / 10 = x * 103 >> 10 for x < 100).
#[inline]
fn eight_digits(q: u32) -> u64 {
    let halves = u64::from(q / 10_000) | u64::from(q % 10_000) << 32;
    let hundreds = ((halves * 10_486) >> 20) & 0x0000_007f_0000_007f;
    let pairs = hundreds | (halves - 100 * hundreds) << 16;
    let tens = ((pairs * 103) >> 10) & 0x000f_000f_000f_000f;
    tens | (pairs - 10 * tens) << 8
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

/// A [`Column`] as its rows write it: a word column's words quoted once, not once a cell.
///
/// A tag byte of its own (`repr(u8)`): the kind found in the spare values of the words' `Vec`
/// took a dozen instructions per field of every row to decode (with `Rounded::of_any`, a row
/// of `render fig3`'s cells: 268 -> 246 instructions, callgrind).
#[repr(u8)]
enum Prepared<'a> {
    /// A value in every cell.
    Dense(&'a [f64]),
    /// An empty field where a cell has no value.
    Sparse(&'a [Option<f64>]),
    /// Each cell's word as its index into the words, quoted as the csv crate quotes them.
    Words { quoted: Vec<Field>, of: &'a [u8] },
}

impl Prepared<'_> {
    fn of<'a>(column: &Column<'a>) -> Prepared<'a> {
        match *column {
            Column::Dense(v) => Prepared::Dense(v),
            Column::Sparse(v) => Prepared::Sparse(v),
            Column::Words { words, of } => Prepared::Words {
                quoted: words
                    .iter()
                    .map(|w| {
                        let mut b = Vec::new();
                        push_text(&mut b, w);
                        Field::new(b)
                    })
                    .collect(),
                of,
            },
        }
    }

    /// Cell `i`'s field.
    #[inline(always)]
    fn write(&self, rows: &mut Rows, i: usize) {
        match self {
            Prepared::Dense(v) => rows.number(v[i]),
            Prepared::Sparse(v) => v[i].into_iter().for_each(|x| rows.number(x)),
            Prepared::Words { quoted, of } => rows.field(&quoted[usize::from(of[i])]),
        }
    }

    /// The most bytes a field of this column takes.
    fn longest(&self) -> usize {
        match self {
            Prepared::Dense(_) | Prepared::Sparse(_) => PLAIN_MAX_BYTES,
            Prepared::Words { quoted, .. } => quoted.iter().map(Field::len).max().unwrap_or(0),
        }
    }
}

/// Bytes written once per map and copied into many rows (an axis value, a word).
///
/// Copied by a fixed [`Field::SHORT`]-byte copy of its head, which the compiler inlines, then
/// cut back to its length: a call to memcpy per field of a few bytes was a tenth of a map's
/// CSV.
struct Field {
    /// The first SHORT bytes, padded with zeros.
    head: [u8; Field::SHORT],
    /// All the bytes: copied after the head where there are more than SHORT.
    bytes: Vec<u8>,
}

impl Field {
    /// Fields up to this long take the fixed copy alone.
    const SHORT: usize = 32;

    fn new(bytes: Vec<u8>) -> Self {
        let mut head = [0; Self::SHORT];
        let n = bytes.len().min(Self::SHORT);
        head[..n].copy_from_slice(&bytes[..n]);
        Field { head, bytes }
    }

    fn len(&self) -> usize {
        self.bytes.len()
    }
}

/// The longest [`plain`] text: `-0.` and 330 decimals, of -5e-324 (a number's decimals are
/// 6 less its decimal exponent, which is -324 at least; the largest f64 has 309 digits).
const PLAIN_MAX_BYTES: usize = 333;

/// Rows as they are made, in a buffer of fixed length that goes to the writer whenever
/// [`ROWS_BUFFER_BYTES`] are in it: past that it has room for the longest row and then for a
/// fixed-length copy ([`Field::SHORT`], [`SHORT_NUMBER`]) at its end, so a field is written
/// by a copy of fixed length and one bounds check, with no capacity check and no call.
struct Rows {
    bytes: Vec<u8>,
    /// How many of them are rows.
    at: usize,
}

impl Rows {
    fn new(longest_row: usize) -> Self {
        let room = ROWS_BUFFER_BYTES + longest_row + Field::SHORT.max(SHORT_NUMBER);
        Rows {
            bytes: vec![0; room],
            at: 0,
        }
    }

    #[inline(always)]
    fn byte(&mut self, b: u8) {
        self.bytes[self.at] = b;
        self.at += 1;
    }

    #[inline(always)]
    fn field(&mut self, f: &Field) {
        let to =
            (self.bytes[self.at..].first_chunk_mut::<{ Field::SHORT }>()).expect("room for a row");
        *to = f.head;
        if f.len() > Field::SHORT {
            self.bytes[self.at..self.at + f.len()].copy_from_slice(&f.bytes);
        }
        self.at += f.len();
    }

    /// [`push_plain`]`(v)`.
    #[inline(always)]
    fn number(&mut self, v: f64) {
        if let Some(r) = Rounded::of_any(v) {
            let to =
                (self.bytes[self.at..].first_chunk_mut::<SHORT_NUMBER>()).expect("room for a row");
            if let Some(len) = r.write_short(to) {
                self.at += len;
                return;
            }
        }
        let mut text = Vec::new();
        push_plain(&mut text, v);
        self.bytes[self.at..self.at + text.len()].copy_from_slice(&text);
        self.at += text.len();
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

/// Writes a map's cells as long-format CSV (one row per cell, x fastest) to `out` as it is made, [`ROWS_BUFFER_BYTES`] at a time.
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
    // "x," and "y": each axis value formatted once.
    let field = |v: &f64, tail: Option<u8>| {
        let mut b = Vec::with_capacity(Field::SHORT);
        push_plain(&mut b, *v);
        b.extend(tail);
        Field::new(b)
    };
    let xs: Vec<Field> = xs.iter().map(|x| field(x, Some(b','))).collect();
    let ys: Vec<Field> = ys.iter().map(|y| field(y, None)).collect();
    let columns: Vec<Prepared> = columns.iter().map(Prepared::of).collect();
    let mut head = csv::WriterBuilder::new()
        .has_headers(false)
        .from_writer(Vec::new());
    head.write_record(header)?;
    out.write_all(&head.into_inner().map_err(|e| e.into_error())?)?;
    let longest = |fields: &[Field]| fields.iter().map(Field::len).max().unwrap_or(0);
    let longest_row =
        longest(&xs) + longest(&ys) + columns.iter().map(|c| 1 + c.longest()).sum::<usize>() + 1;
    let mut rows = Rows::new(longest_row);
    for (iy, y) in ys.iter().enumerate() {
        for (ix, x) in xs.iter().enumerate() {
            let i = iy * xs.len() + ix;
            rows.field(x);
            rows.field(y);
            for c in &columns {
                rows.byte(b',');
                c.write(&mut rows, i);
            }
            rows.byte(b'\n');
            if rows.at >= ROWS_BUFFER_BYTES {
                out.write_all(&rows.bytes[..rows.at])?;
                rows.at = 0;
            }
        }
    }
    out.write_all(&rows.bytes[..rows.at])?;
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
/// infinities, `0` for `-0`. The value is the text's without writing it: q / 10^N of the
/// rounded digits q, both exact f64, is the decimal correctly rounded, as parsing gives it
/// (`json_numbers_are_the_plain_text_parsed` checks).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Num(pub f64);

impl Serialize for Num {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let v = self.0;
        if !v.is_finite() {
            return s.serialize_none();
        }
        // The f64 the plain decimal parses to, whose shortest form it is: the rounded digits'
        // own value, or where std rounds, the text parsed.
        let rounded = match v == 0.0 {
            true => 0.0,
            false => Rounded::of(v).map_or_else(|| plain(v).parse().unwrap_or(v), Rounded::value),
        };
        s.serialize_f64(rounded + 0.0)
    }
}

/// `v` rounded to [`SIGNIFICANT_DIGITS`] significant digits whatever its size, as parsing
/// `format!("{v:.6e}")` gives it (`plain` keeps every whole digit above 10^7, this does not).
/// Below 10^7 the digits are [`plain`]'s, so their value comes from [`Rounded`] without any
/// text (an exact formatting and a parse per number of the gallery's read-offs was 3 % of
/// `render fig7c`'s instructions); above, and where [`Rounded`] declines, the text is made and
/// parsed. Not finite or 0: `v` itself.
pub fn significant(v: f64) -> f64 {
    if !v.is_finite() || v == 0.0 {
        return v;
    }
    let fast = (v.abs() < 1e7).then(|| Rounded::of(v)).flatten();
    fast.map_or_else(|| format!("{v:.6e}").parse().unwrap_or(v), Rounded::value)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cells' rounding, with no test for 0 and non-finite numbers before it, declines
    /// them (their text is the slow path's) and rounds every other number as `Rounded::of`.
    #[test]
    fn rounding_of_any_number_declines_zero_and_non_finite_ones() {
        for v in [0.0, -0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert_eq!(Rounded::of_any(v), None, "{v}");
        }
        for v in [
            5e-324, 2.2e-308, 1e-300, 1e-22, 1.5e-17, 1e-16, 0.1, 24.35, 1e7, 9.9e15, 1e21, 1e22,
            1.7e308, -3.3, -1e-5,
        ] {
            assert_eq!(Rounded::of_any(v), Rounded::of(v), "{v}");
        }
    }

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

    /// 20,000 cases from a fixed seed: the same values on every run.
    fn runner() -> proptest::test_runner::TestRunner {
        proptest::test_runner::TestRunner::new_with_rng(
            proptest::test_runner::Config {
                cases: 20_000,
                ..Default::default()
            },
            proptest::test_runner::TestRng::deterministic_rng(Default::default()),
        )
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
            let want = if v.is_finite() && v != 0.0 && v.abs() < WIDE_FROM {
                plain_std(v)
            } else {
                plain(v)
            };
            assert_eq!(fast, want, "{v:e}");
        };
        let mut runner = runner();
        let slow = std::cell::Cell::new(0);
        let values = (1.0f64..10.0, -20i32..20, any::<bool>());
        runner
            .run(&values, |(m, e, neg)| {
                let v = m * 10f64.powi(e) * if neg { -1.0 } else { 1.0 };
                check(v);
                if (-15..=15).contains(&e) {
                    slow.set(slow.get() + usize::from(Rounded::of(v).is_none()));
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

    /// [`Num`]'s value is the plain text parsed, bit for bit: over 40 decades, on and next to
    /// rounding ties and powers of ten, and any f64.
    #[test]
    fn json_numbers_are_the_plain_text_parsed() {
        use proptest::prelude::*;
        let check = |v: f64| {
            let want = match plain(v).parse::<f64>() {
                Ok(p) => serde_json::to_string(&(p + 0.0)).unwrap(),
                Err(_) => "null".to_string(),
            };
            assert_eq!(serde_json::to_string(&Num(v)).unwrap(), want, "{v:e}");
        };
        let mut runner = runner();
        let values = (1.0f64..10.0, -25i32..25, any::<bool>(), any::<f64>());
        runner
            .run(&values, |(m, e, neg, any)| {
                let v = m * 10f64.powi(e) * if neg { -1.0 } else { 1.0 };
                for v in [v, v.round(), f64::from_bits(v.to_bits() + 1), any] {
                    check(v);
                }
                Ok(())
            })
            .unwrap();
        for k in -25..=25 {
            let p = 10f64.powi(k);
            for v in [p, f64::from_bits(p.to_bits() - 1), 0.5 * p, 2.5e-7 * p] {
                check(v);
                check(-v);
            }
        }
    }

    /// [`significant`] is the exact formatting at 7 significant digits, parsed, bit for bit:
    /// random values over 50 decades, their neighbours, values next to every power of ten and
    /// on ties of the seventh digit.
    #[test]
    fn significant_is_the_formatted_digits_parsed() {
        use proptest::prelude::*;
        let check = |v: f64| {
            let want: f64 = format!("{v:.6e}").parse().unwrap();
            assert_eq!(significant(v).to_bits(), want.to_bits(), "{v:e}");
        };
        let mut runner = runner();
        let values = (1.0f64..10.0, -25i32..25, any::<bool>(), any::<f64>());
        runner
            .run(&values, |(m, e, neg, any)| {
                let v = m * 10f64.powi(e) * if neg { -1.0 } else { 1.0 };
                let tie = (v * 1e6).round() / 1e6 + 5e-7;
                for v in [v, v.round(), f64::from_bits(v.to_bits() + 1), tie] {
                    check(v);
                }
                if any.is_finite() {
                    check(any);
                }
                Ok(())
            })
            .unwrap();
        for k in -25..=25 {
            let p = 10f64.powi(k);
            for v in [
                p,
                f64::from_bits(p.to_bits() - 1),
                0.5 * p,
                2.5e-7 * p,
                9.9999995 * p,
            ] {
                check(v);
                check(-v);
            }
        }
        assert_eq!(significant(0.0), 0.0);
        assert!(significant(f64::NAN).is_nan());
    }

    /// Beyond what a u64 holds a number keeps its seven significant digits and the other
    /// whole digits are 0: std's exact expansion of 1e300 wrote the binary expansion's 300
    /// digits, tens of microseconds each (`render fig3 --set mass_kg=1:1e300` took half a
    /// minute, 93 % of it here). Below 1e-22 the text is std's exact one, only sooner.
    #[test]
    fn numbers_beyond_the_fast_path_keep_seven_digits() {
        use proptest::prelude::*;
        assert_eq!(plain(4.9030000000000001e302).len(), 303);
        assert!(plain(4.903e302).starts_with("4903000000000000000000"));
        assert_eq!(plain(-1e300), format!("-1{}", "0".repeat(300)));
        assert_eq!(plain(1.8e19), "18000000000000000000");
        assert_eq!(plain(123_456_789e20), format!("1234568{}", "0".repeat(22)));
        assert_eq!(plain(1.5e-300), format!("0.{}15", "0".repeat(299)));
        let mut runner = runner();
        let values = (1.0f64..10.0, 19i32..309, -324i32..-22, any::<bool>());
        runner
            .run(&values, |(m, big, small, neg)| {
                let sign = if neg { -1.0 } else { 1.0 };
                // Large: seven digits as the e form rounds them, the rest zeros.
                let v = sign * m * 10f64.powi(big);
                if v.is_finite() && v.abs() >= WIDE_FROM {
                    let text = plain(v);
                    let e = format!("{:.6e}", v.abs());
                    let (mantissa, exponent) = e.split_once('e').unwrap();
                    let digits: String = mantissa.replace('.', "");
                    let whole: usize = exponent.parse::<usize>().unwrap() + 1;
                    let unsigned = text.trim_start_matches('-');
                    prop_assert_eq!(unsigned.len(), whole, "{:e}", v);
                    prop_assert!(
                        unsigned.starts_with(digits.trim_end_matches('0')),
                        "{:e}",
                        v
                    );
                    prop_assert_eq!(text.starts_with('-'), neg);
                    prop_assert_eq!(significant(v), text.parse::<f64>().unwrap(), "{:e}", v);
                }
                // Small: std's exact text.
                let v = sign * m * 10f64.powi(small);
                if v != 0.0 && v.abs() < WIDE_BELOW {
                    prop_assert_eq!(plain(v), plain_std(v), "{:e}", v);
                }
                Ok(())
            })
            .unwrap();
    }

    /// A row's room for a number holds the longest plain text there is.
    #[test]
    fn no_plain_number_is_longer_than_its_room() {
        use proptest::prelude::*;
        assert_eq!(plain(-5e-324).len(), PLAIN_MAX_BYTES);
        for v in [f64::MIN, f64::MIN_POSITIVE, -1.2345678e-310, -9.999999e307] {
            assert!(plain(v).len() <= PLAIN_MAX_BYTES, "{v:e}");
        }
        let mut runner = proptest::test_runner::TestRunner::new_with_rng(
            proptest::test_runner::Config {
                cases: 5_000,
                ..Default::default()
            },
            proptest::test_runner::TestRng::deterministic_rng(Default::default()),
        );
        runner
            .run(&any::<f64>(), |v| {
                prop_assert!(plain(v).len() <= PLAIN_MAX_BYTES, "{v:e}");
                Ok(())
            })
            .unwrap();
    }

    /// The eight digits of every q below 10^5 and of q spread up to 10^8 are std's.
    #[test]
    fn eight_digits_are_the_zero_padded_decimal() {
        let check = |q: u32| {
            let text = (eight_digits(q) + u64::from_le_bytes([b'0'; 8])).to_le_bytes();
            assert_eq!(text, *format!("{q:08}").as_bytes(), "{q}");
        };
        (0..100_000).for_each(check);
        (0..100_000_000).step_by(997).for_each(check);
        [99_999_999, 10_000_000, 9_999_999, 10_000_001]
            .into_iter()
            .for_each(check);
    }
}
