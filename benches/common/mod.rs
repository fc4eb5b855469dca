//! What every benchmark shares: the median of noisy timings.

use std::time::Instant;

/// The median of `v` (the upper middle for an even count).
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The median wall time of `runs` calls of `f`, in s.
#[allow(dead_code)] // not every benchmark times a closure
pub fn median_s(runs: usize, mut f: impl FnMut()) -> f64 {
    median(
        (0..runs)
            .map(|_| {
                let t0 = Instant::now();
                f();
                t0.elapsed().as_secs_f64()
            })
            .collect(),
    )
}
