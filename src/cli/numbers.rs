//! Numbers in the report tables (`accuracy`, `stability`): an engineer reads `0.254 mm`,
//! `17.4 nm` or `0`, not `2.54e-1`, `1.74e-5` or `0.00e0`.
//!
//! Three significant digits; a length picks the unit that keeps its digits before the point
//! (mm from 0.1 mm, else um, nm, pm from 1 of each); an angle below a thousandth of a degree and a ratio below 1e-3 keep an
//! exponent, which is the honest form there. Zero is `0` with its unit; a missing value is `-`.

/// `v` with three significant digits, no exponent (`0.0102`, `24.7`, `254`).
fn sig3(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
