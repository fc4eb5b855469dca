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
    if !v.is_finite() {
        return String::new();
    }
    if v == 0.0 {
        return "0".into();
    }
    let magnitude = v.abs().log10().floor() as i32;
    let decimals = (SIGNIFICANT_DIGITS - 1 - magnitude).max(0) as usize;
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
}
