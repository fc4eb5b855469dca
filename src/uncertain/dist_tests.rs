//! Probabilities and quantiles of x_jam under distributed inputs: the exact
//! monotone map against a brute-force quadrature of the input and the closed form at its
//! quantiles, Monte Carlo against the exact answer, and Monte Carlo bit-identical for any
//! thread count.

use super::shaft;

use jamchart::SceneParams;
use jamchart::statics;
use jamchart::uncertain::dist::{self, DistMethod, DistQuestion};
use jamchart::uncertain::{Uncertain, UncertainInput, UncertainSet};

/// The 25 mm shaft with mu normal(0.2, 0.03) for both contacts.
fn shaft() -> (SceneParams, UncertainSet) {
    let p = shaft::shaft_25mm().with_mu(0.2);
    let set = UncertainSet {
        inputs: vec![UncertainInput {
            name: "mu",
            keys: vec!["mu_ground", "mu_palm"],
            value: Uncertain::Normal {
                mean: 0.2,
                sd: 0.03,
            },
        }],
    };
    (p, set)
}

fn ask(samples: u64) -> DistQuestion {
    DistQuestion {
        before_mm: vec![50.0, 60.0, 70.0],
        quantiles: vec![0.05, 0.5, 0.95],
        samples,
        seed: 7,
    }
}

/// x_jam of the closed form at friction `mu`.
fn x_at(p: &SceneParams, mu: f64) -> f64 {
    let q = p.with_mu(mu);
    q.disc_position_mm(statics::theta_jam_rad(&q))
}

/// The exact quantiles are the closed form at the input's quantiles, mirrored (x_jam falls as
/// mu grows), and P(x_jam < x) matches a midpoint quadrature of the input over 2e5 cells.
#[test]
fn exact_answers_match_the_closed_form_and_a_quadrature() {
    let (p, set) = shaft();
    let u = set.inputs[0].value;
    let d = dist::exact(&p, &set, &ask(1)).expect("one distributed input");
    assert_eq!(d.method, DistMethod::Exact);
    for q in &d.quantiles {
        let want = x_at(&p, u.quantile(1.0 - q.q));
        assert!(
            (q.x_jam_mm.value - want).abs() < 1e-9 * want,
            "{q:?} vs {want}"
        );
    }
    let n = 200_000;
    for b in &d.before {
        let hits = (0..n)
            .filter(|i| x_at(&p, u.quantile((*i as f64 + 0.5) / n as f64)) < b.x_mm)
            .count();
        let quad = hits as f64 / n as f64;
        assert!(
            (b.probability.value - quad).abs() < 2e-5,
            "P(before {}) = {} vs quadrature {quad}",
            b.x_mm,
            b.probability.value
        );
    }
}

/// Monte Carlo of the same question lands within its 95 % intervals of the exact answer (the
/// seed is fixed, so this is deterministic), and the intervals are as narrow as 1e5 samples
/// make them.
#[test]
fn monte_carlo_brackets_the_exact_answer() {
    let (p, set) = shaft();
    let exact = dist::exact(&p, &set, &ask(1)).unwrap();
    let mc = dist::monte_carlo(&jamchart::ModelSpec::Statics, &p, &set, &ask(100_000)).unwrap();
    for (e, m) in exact.before.iter().zip(&mc.before) {
        let (v, lo, hi) = (e.probability.value, m.probability.lo, m.probability.hi);
        assert!(
            lo <= v && v <= hi,
            "P(before {}) = {v} outside [{lo}, {hi}]",
            e.x_mm
        );
        assert!(hi - lo < 0.0065, "width {}", hi - lo);
    }
    for (e, m) in exact.quantiles.iter().zip(&mc.quantiles) {
        let (v, lo, hi) = (e.x_jam_mm.value, m.x_jam_mm.lo, m.x_jam_mm.hi);
        assert!(lo <= v && v <= hi, "q {}: {v} outside [{lo}, {hi}]", e.q);
    }
}

/// The samples depend on the seed and their index only: one thread and two give the same
/// answer, bit for bit, for a sample count that is not a whole number of chunks.
#[test]
fn monte_carlo_is_bit_identical_for_any_thread_count() {
    let (p, mut set) = shaft();
    set.inputs.push(UncertainInput {
        name: "force_n",
        keys: vec!["force_n"],
        value: Uncertain::Uniform { lo: 30.0, hi: 50.0 },
    });
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                dist::monte_carlo(&jamchart::ModelSpec::Statics, &p, &set, &ask(5_000)).unwrap()
            })
    };
    let (one, two) = (run(1), run(2));
    assert_eq!(format!("{one:?}"), format!("{two:?}"));
    let other_seed = DistQuestion {
        seed: 8,
        ..ask(5_000)
    };
    let three = dist::monte_carlo(&jamchart::ModelSpec::Statics, &p, &set, &other_seed).unwrap();
    assert_ne!(format!("{one:?}"), format!("{three:?}"));
}
