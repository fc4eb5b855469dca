//! Numbers shown to a user, in one place.
//!
//! Echoed inputs and answers (`solve`, `design`, `vlocator`, warnings and error messages) go
//! through [`Num`] / [`fixed`]: at most 12 significant digits, so a midpoint's rounding
//! (`(0.16 + 0.3) / 2 = 0.22999999999999998`) reads `0.23`, and exponent form outside
//! 1e-4..1e15, where Rust's `{}` writes 1e-300 with 300 zeros and `{:.3}` writes 1e300 with
//! 301 digits.
//!
//! Numbers in the report tables (`accuracy`, `stability`): an engineer reads `0.254 mm`,
//! `17.4 nm` or `0`, not `2.54e-1`, `1.74e-5` or `0.00e0`.
//!
//! Three significant digits; a length picks the unit that keeps its digits before the point
//! (mm from 0.1 mm, else um, nm, pm from 1 of each); an angle below a thousandth of a degree and a ratio below 1e-3 keep an
//! exponent, which is the honest form there. Zero is `0` with its unit; a missing value is `-`.
//!
//! And one number beside another: [`floats_away`], the float a few steps from it.

use std::fmt;

/// Significant digits an echoed number keeps: enough for any value a person types (and
/// for f64's own noise, about 1e-16 relative, to vanish).
const SHOWN_DIGITS: usize = 12;

/// Below this magnitude (and above [`PLAIN_MAX`]) a number reads in exponent form.
const PLAIN_MIN: f64 = 1e-4;

/// See [`PLAIN_MIN`].
const PLAIN_MAX: f64 = 1e15;

/// An f64 shown to a user: `0.23`, `150`, `1e-300`, `1e300`, `NaN`; see the module docs.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Num(pub f64);

impl fmt::Display for Num {
    /// With a precision (`{:.3}`), [`fixed`] to that many decimals (`24.355`, and `1e-300`
    /// where `{:.3}` alone would print `0.000`); without one, 12 significant digits as the
    /// module docs say. Width and alignment are not applied.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        if let Some(decimals) = f.precision() {
            return f.write_str(&fixed(v, decimals));
        }
        if !v.is_finite() || v == 0.0 {
            return write!(f, "{v}");
        }
        // Round to SHOWN_DIGITS significant digits through the exponent form, which is exact
        // to print and parse; the shortest form of the rounded value then has no noise.
        let r: f64 = format!("{v:.prec$e}", prec = SHOWN_DIGITS - 1)
            .parse()
            .unwrap_or(v);
        if (PLAIN_MIN..PLAIN_MAX).contains(&r.abs()) {
            write!(f, "{r}")
        } else {
            write!(f, "{r:e}")
        }
    }
}

/// [`fixed`], or `more than 1.8e308` for a magnitude past the largest double (a disc that
/// starts at a palm angle that rounds to 0 rad lies at no finite distance): `inf` is no answer,
/// and `f64::MAX` in full has 17 digits.
pub(crate) fn fixed_or_past(v: f64, decimals: usize) -> String {
    match v.is_finite() {
        true => fixed(v, decimals),
        false => "more than 1.8e308".into(),
    }
}

/// `v` with `decimals` decimals (`24.355`), or with as many in exponent form where that would run past 15 digits
/// before the point or show a nonzero value as zero (`1e300`, `1e-300`).
pub(crate) fn fixed(v: f64, decimals: usize) -> String {
    let a = v.abs();
    let shows_zero = a > 0.0 && a < 0.5 * 10f64.powi(-(decimals as i32));
    if !v.is_finite() {
        format!("{v}")
    } else if a >= PLAIN_MAX || shows_zero {
        // As many significant digits as the fixed form shows of an ordinary value.
        let e = format!("{v:.decimals$e}");
        let (mantissa, exponent) = e.split_once('e').unwrap_or((&e, "0"));
        format!("{}e{exponent}", trim_zeros(mantissa))
    } else {
        format!("{v:.decimals$}")
    }
}

/// `v` with `digits` significant digits, trailing zeros dropped (`0.1484`, `14.84`, `1484`,
/// and `12346` for 12345.6: the integer part is kept whole), in exponent form outside
/// 1e-4..1e15 (`1e308`, `2.5e-300`), where the fixed form ran to 309 digits.
pub(crate) fn sig(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return v.to_string();
    }
    let digits = digits.max(1);
    let a = v.abs();
    if !(PLAIN_MIN..PLAIN_MAX).contains(&a) {
        let e = format!("{v:.prec$e}", prec = digits - 1);
        let (mantissa, exponent) = e.split_once('e').unwrap_or((&e, "0"));
        return format!("{}e{exponent}", trim_zeros(mantissa));
    }
    let magnitude = a.log10().floor() as i32;
    let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
    trim_zeros(&format!("{v:.decimals$}")).to_string()
}

/// `1.2500` as `1.25`, `2.000` as `2`; a number without a point as it is.
fn trim_zeros(t: &str) -> &str {
    if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.')
    } else {
        t
    }
}

/// `v` with three significant digits (`0.0102`, `24.7`, `254`, `1.00e300`): the fixed form
/// up to 1e15, an exponent beyond (1e300 printed 301 digits).
fn sig3(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if !v.is_finite() || v.abs() >= PLAIN_MAX {
        return sci3(v);
    }
    let magnitude = v.abs().log10().floor() as i32;
    let decimals = (2 - magnitude).max(0) as usize;
    format!("{v:.decimals$}")
}

/// `v` with three significant digits and an exponent (`1.54e-8`).
fn sci3(v: f64) -> String {
    format!("{v:.2e}")
}

/// A length in mm, in the unit that shows it best: `0.254 mm`, `17.4 um`, `9.29 nm`, `0 mm`.
pub(crate) fn length_mm(v: Option<f64>) -> String {
    let Some(v) = v else {
        return "-".into();
    };
    let a = v.abs();
    match a {
        _ if a == 0.0 || a >= 0.1 => format!("{} mm", sig3(v)),
        _ if a >= 1e-3 => format!("{} um", sig3(v * 1e3)),
        _ if a >= 1e-6 => format!("{} nm", sig3(v * 1e6)),
        _ if a >= 1e-9 => format!("{} pm", sig3(v * 1e9)),
        _ => format!("{} mm", sci3(v)),
    }
}

/// An angle in deg: `0.0518 deg`, `1.54e-8 deg`, `0 deg`.
pub(crate) fn angle_deg(v: Option<f64>) -> String {
    v.map_or("-".into(), |v| format!("{} deg", plain_or_sci(v)))
}

/// A ratio without unit (a relative error): `0.0102`, `3.81e-10`, `0`.
pub(crate) fn ratio(v: Option<f64>) -> String {
    v.map_or("-".into(), plain_or_sci)
}

fn plain_or_sci(v: f64) -> String {
    if v == 0.0 || v.abs() >= 1e-3 {
        sig3(v)
    } else {
        sci3(v)
    }
}

/// Bytes in a human unit: `1.26 GiB`, `640 MiB`, `12 kiB`.
pub fn human_bytes(b: u64) -> String {
    let units = ["B", "kiB", "MiB", "GiB", "TiB", "PiB", "EiB"];
    let mut v = b as f64;
    let mut i = 0;
    while v >= 1024.0 && i + 1 < units.len() {
        v /= 1024.0;
        i += 1;
    }
    match i {
        0 => format!("{b} B"),
        _ if v.fract() == 0.0 => format!("{v:.0} {}", units[i]),
        _ => format!("{v:.1} {}", units[i]),
    }
}

/// A duration in a human unit: `0.25 ms`, `12 s`, `10 min`, `2.8 h`.
pub fn human_seconds(s: f64) -> String {
    let shown = |v: f64, unit: &str| format!("{} {unit}", sig(v, 2));
    match s {
        _ if s < 1e-3 => shown(s * 1e6, "us"),
        _ if s < 1.0 => shown(s * 1e3, "ms"),
        _ if s < 120.0 => shown(s, "s"),
        _ if s < 7200.0 => shown(s / 60.0, "min"),
        _ if s < 172_800.0 => shown(s / 3600.0, "h"),
        _ => shown(s / 86_400.0, "days"),
    }
}

/// The float `n` floats above `x` (below for n < 0), for x and the result of one sign
/// (n steps at once, where f64::next_up takes one); zero steps to the smallest
/// subnormal of the sign of n, an infinity one step inward to the largest finite float.
pub(crate) fn floats_away(x: f64, n: i64) -> f64 {
    if x == 0.0 {
        return f64::from_bits(1).copysign(n as f64);
    }
    // Up is one more in the bits of a positive x, one less in those of a negative one.
    let n = if x > 0.0 { n } else { -n };
    f64::from_bits(x.to_bits().wrapping_add_signed(n))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn human_seconds_reads_well() {
        assert_eq!(human_seconds(2.2e-4), "220 us");
        assert_eq!(human_seconds(0.0092), "9.2 ms");
        assert_eq!(human_seconds(600.0), "10 min");
        assert_eq!(human_seconds(2200.0), "37 min");
        assert_eq!(human_seconds(1e4), "2.8 h");
    }

    #[test]
    fn human_bytes_reads_well() {
        assert_eq!(human_bytes(512), "512 B");
        assert_eq!(human_bytes(1 << 30), "1 GiB");
        assert_eq!(human_bytes(3 * (1 << 29)), "1.5 GiB");
    }

    /// Regression: `solve --mu 1e-300` echoed mu with 300 zeros, its
    /// `x_rigid` line 1e300 with 301 digits, and `solve --mu 0.16:0.3` the nominal mu as
    /// 0.22999999999999998; echoed numbers now keep 12 digits and an exponent at the extremes.
    #[test]
    fn echoed_numbers_read_short() {
        assert_eq!(Num((0.16 + 0.3) / 2.0).to_string(), "0.23");
        assert_eq!(Num((0.2 + 0.4) / 2.0).to_string(), "0.3");
        assert_eq!(Num(1e-300).to_string(), "1e-300");
        assert_eq!(Num(-1e300).to_string(), "-1e300");
        assert_eq!(Num(150.0).to_string(), "150");
        assert_eq!(Num(9.806).to_string(), "9.806");
        assert_eq!(Num(0.0).to_string(), "0");
        assert_eq!(Num(1.0 / 3.0).to_string(), "0.333333333333");
        assert_eq!(Num(f64::NAN).to_string(), "NaN");
        assert_eq!(fixed(24.3554, 3), "24.355");
        assert_eq!(fixed(0.0, 3), "0.000");
        assert_eq!(fixed(1e300, 3), "1e300");
        assert_eq!(fixed(1e-300, 3), "1e-300");
        assert_eq!(fixed(0.0004, 3), "4e-4");
        assert_eq!(fixed(0.0006, 3), "0.001");
        assert_eq!(fixed(1.1459155902e-298, 3), "1.146e-298");
    }

    /// The CLI's answers printed `{:.3}` of raw f64s: `x = 0.000 mm` for a
    /// disc at 1e-7 mm, 301 digits for 1e300. `Num` with a precision is [`fixed`]: the same
    /// text as `{:.3}` for every ordinary value, an exponent at the extremes.
    #[test]
    fn num_with_a_precision_is_fixed() {
        for (v, d) in [
            (24.354551, 3),
            (-3.26912, 3),
            (1.542264957, 4),
            (0.0, 3),
            (9.806, 0),
        ] {
            assert_eq!(format!("{:.d$}", Num(v)), format!("{v:.d$}"), "{v} to {d}");
        }
        assert_eq!(format!("{:.3} mm", Num(1.2e-7)), "1.2e-7 mm");
        assert_eq!(format!("{:.3}", Num(1e300)), "1e300");
        assert_eq!(format!("{}", Num(0.1 + 0.2)), "0.3");
    }

    /// Numbers of four significant digits (a range's breakpoints) printed 1e308 with 309
    /// digits and 1e-300 with 300 zeros; the fixed form of ordinary values is kept as it was.
    #[test]
    fn significant_digits_read_short_at_every_magnitude() {
        assert_eq!(sig(0.148437, 4), "0.1484");
        assert_eq!(sig(14.84, 4), "14.84");
        assert_eq!(sig(12345.6, 4), "12346");
        assert_eq!(sig(0.3, 4), "0.3");
        assert_eq!(sig(1e308, 4), "1e308");
        assert_eq!(sig(-2.345678e-300, 4), "-2.346e-300");
        assert_eq!(sig(5e-324, 4), "4.941e-324");
        assert_eq!(sig(0.0, 4), "0");
        assert_eq!(length_mm(Some(1e300)), "1.00e300 mm");
        assert_eq!(angle_deg(Some(-1e20)), "-1.00e20 deg");
        for v in [1e308, f64::MAX, 1e-308, 5e-324, 123456789.123, -1e15] {
            for text in [sig(v, 4), Num(v).to_string(), fixed(v, 3), ratio(Some(v))] {
                assert!(text.len() <= 20, "{v}: {text}");
            }
        }
    }

    #[test]
    fn zero_and_small_numbers_read_with_their_unit() {
        assert_eq!(length_mm(Some(0.0)), "0 mm");
        assert_eq!(length_mm(Some(0.2540)), "0.254 mm");
        assert_eq!(length_mm(Some(24.746)), "24.7 mm");
        assert_eq!(length_mm(Some(1.74053e-5)), "17.4 nm");
        assert_eq!(length_mm(Some(7.372e-4)), "737 nm");
        assert_eq!(length_mm(Some(0.05)), "50.0 um");
        assert_eq!(length_mm(Some(9.285e-9)), "9.29 pm");
        assert_eq!(length_mm(Some(-3.2e-3)), "-3.20 um");
        assert_eq!(length_mm(Some(3e-13)), "3.00e-13 mm");
        assert_eq!(length_mm(None), "-");
        assert_eq!(angle_deg(Some(0.0)), "0 deg");
        assert_eq!(angle_deg(Some(0.0518)), "0.0518 deg");
        assert_eq!(angle_deg(Some(1.5351e-8)), "1.54e-8 deg");
        assert_eq!(ratio(Some(0.0)), "0");
        assert_eq!(ratio(Some(1.02e-2)), "0.0102");
        assert_eq!(ratio(Some(3.8125e-10)), "3.81e-10");
    }

    /// The float beside a number: both ways from either zero to the smallest subnormal,
    /// across the ones and the largest finite float, and from an infinity inward.
    #[test]
    fn the_float_beside_a_number() {
        let up = [
            (0.0, 5e-324),
            (-0.0, 5e-324),
            (-5e-324, -0.0),
            (1.0, 1.0 + f64::EPSILON),
            (-f64::MAX, -1.797_693_134_862_315_5e308),
            (f64::MAX, f64::INFINITY),
            (f64::NEG_INFINITY, -f64::MAX),
        ];
        for (v, want) in up {
            assert_eq!(floats_away(v, 1), want, "{v:e}");
        }
        assert_eq!(floats_away(f64::INFINITY, -1), f64::MAX);
        assert_eq!(floats_away(0.0, -1), -5e-324);
        assert_eq!(floats_away(1.0, -2), 1.0 - 2.0 * f64::EPSILON / 2.0);
    }
}
