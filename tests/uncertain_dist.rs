//! Distributed inputs through the binary: a normal input whose spread equals its mean.

use crate::common::cli as cli_util;
use jamchart::uncertain::Uncertain;

/// Regression: a normal input whose standard deviation equals its mean was refused ("the
/// highest value a sample can take is inf") while one a hair either side was taken: below +
/// p (1 - below), the truncated normal's share at p = 1 - 2^-53, rounded to 1 there. Every
/// quantile up to that p is now finite and continuous in the spread, and `solve --mu
/// normal(0.05,0.05)` answers.
#[test]
fn a_normal_input_with_its_spread_equal_to_its_mean_answers() {
    // The highest probability a sample reaches: 1 - 2^-53.
    let top = 1.0 - f64::EPSILON / 2.0;
    for mean in [0.05, 0.2, 1.0, 40.0] {
        let q = |sd: f64| Uncertain::Normal { mean, sd }.quantile(top);
        let (at, below, above) = (q(mean), q(mean * (1.0 - 1e-12)), q(mean * (1.0 + 1e-12)));
        assert!(at.is_finite(), "normal({mean},{mean}): {at}");
        assert!(below < at && at < above, "{below} {at} {above}");
        assert!((above - below) < 1e-9 * at, "{below} {at} {above}");
    }
    let dir = tempfile::tempdir().unwrap();
    let o = cli_util::jamchart(dir.path(), &["solve", "--mu", "normal(0.05,0.05)"]);
    assert_eq!(o.status.code(), Some(0), "{}", cli_util::stderr(&o));
}
