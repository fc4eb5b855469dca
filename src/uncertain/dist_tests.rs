//! Probabilities and quantiles of x_jam under distributed inputs: the exact
//! monotone map against a brute-force quadrature of the input and the closed form at its
//! quantiles, Monte Carlo against the exact answer, and Monte Carlo bit-identical for any
//! thread count.

use super::shaft;

use jamchart::SceneParams;
use jamchart::statics;
use jamchart::uncertain::dist::{self, DistAnswer, DistMethod, DistQuestion};
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

/// The exact P(x_jam < x) of a wide distribution was coarse and contradicted its own quantile:
/// `solve --mu "lognormal(0.01,3)" --before 1e5,1e6,1e7 --quantiles 0.99` gave 0.9377 / 0.9926
/// / 0.9926 beside q99 = 1.048e6 mm, its root found by 40 halvings of the friction over the
/// whole support (every friction below 1.4e-5 one bracket). Bisected in probability, P at
/// each quantile is that quantile's probability, and the three values are the ones an exact
/// 40-digit transform gives (0.93860, 0.98957, 0.99896).
#[test]
fn a_wide_distribution_gives_each_quantile_its_own_probability() {
    let p = SceneParams::default();
    let wide = |value: Uncertain| UncertainSet {
        inputs: vec![UncertainInput {
            name: "mu",
            keys: vec!["mu_ground", "mu_palm"],
            value,
        }],
    };
    let qs = [0.001, 0.01, 0.05, 0.5, 0.9, 0.99, 0.999];
    for value in [
        Uncertain::LogNormal {
            median: 0.01,
            sigma: 3.0,
        },
        Uncertain::LogNormal {
            median: 0.2,
            sigma: 0.25,
        },
        Uncertain::Uniform { lo: 1e-9, hi: 0.8 },
        Uncertain::Normal {
            mean: 0.05,
            sd: 0.05,
        },
    ] {
        let set = wide(value);
        let at_quantiles = dist::exact(
            &p,
            &set,
            &DistQuestion {
                before_mm: Vec::new(),
                quantiles: qs.to_vec(),
                samples: 1,
                seed: 1,
            },
        )
        .expect("one distributed input");
        let x_q: Vec<f64> = at_quantiles
            .quantiles
            .iter()
            .map(|q| q.x_jam_mm.value)
            .collect();
        // P(x_jam < x) a hair below and above each quantile brackets its probability (both
        // equal it where x_jam has no atom; a disc held at the start is one).
        let p_before = |scale: f64| {
            let ask = DistQuestion {
                before_mm: x_q.iter().map(|x| x * scale).collect(),
                quantiles: Vec::new(),
                samples: 1,
                seed: 1,
            };
            let d = dist::exact(&p, &set, &ask).unwrap();
            d.before
                .iter()
                .map(|b| b.probability.value)
                .collect::<Vec<_>>()
        };
        let (below, above) = (p_before(1.0 - 1e-12), p_before(1.0 + 1e-12));
        for ((q, lo), hi) in qs.iter().zip(below).zip(above) {
            assert!(
                lo <= q + 1e-9 && q - 1e-9 <= hi,
                "{value}: P(x_jam < q{q}) from {lo} to {hi}"
            );
        }
    }
    let ask = DistQuestion {
        before_mm: vec![1e5, 1e6, 1e7],
        quantiles: Vec::new(),
        samples: 1,
        seed: 1,
    };
    let set = wide(Uncertain::LogNormal {
        median: 0.01,
        sigma: 3.0,
    });
    let d = dist::exact(&p, &set, &ask).unwrap();
    for (b, want) in d.before.iter().zip([0.93860, 0.98957, 0.99896]) {
        let got = b.probability.value;
        assert!(
            (got - want).abs() < 1e-5,
            "P(x_jam < {}) = {got}, not {want}",
            b.x_mm
        );
    }
}

/// `solve --mu 'lognormal(5e-324,1)'` printed `quantile of x_jam = inf mm [inf, inf] (width
/// NaN)` with exit 0: a jam position beyond what a double holds. Such a quantile is answered
/// as beyond every position (an outcome: the box is still answered), and no answer carries a
/// number that is not finite.
#[test]
fn a_quantile_beyond_every_position_is_said_so_not_infinite() {
    let p = SceneParams::default();
    let set = UncertainSet {
        inputs: vec![UncertainInput {
            name: "mu",
            keys: vec!["mu_ground", "mu_palm"],
            value: Uncertain::LogNormal {
                median: 5e-324,
                sigma: 1.0,
            },
        }],
    };
    let ask = DistQuestion {
        before_mm: vec![50.0],
        quantiles: vec![0.05, 0.5, 0.95],
        samples: 10_000,
        seed: 1,
    };
    let mc = dist::monte_carlo(&jamchart::ModelSpec::Statics, &p, &set, &ask).unwrap();
    let answers: Vec<DistAnswer> = dist::exact(&p, &set, &ask)
        .into_iter()
        .chain([mc])
        .collect();
    for d in &answers {
        assert!(d.quantiles.is_empty(), "{d:?}");
        assert_eq!(d.beyond_every_position, ask.quantiles, "{d:?}");
        assert!(
            (d.before.iter()).all(|b| b.probability.value == 0.0 && b.probability.hi == 0.0),
            "{d:?}"
        );
    }
    // Where the jam lies within reach the same question answers, every number finite.
    let set = UncertainSet {
        inputs: vec![UncertainInput {
            value: Uncertain::LogNormal {
                median: 1e-300,
                sigma: 1.0,
            },
            ..set.inputs[0].clone()
        }],
    };
    let d = dist::monte_carlo(&jamchart::ModelSpec::Statics, &p, &set, &ask).unwrap();
    let numbers = d
        .quantiles
        .iter()
        .flat_map(|q| [q.x_jam_mm.value, q.x_jam_mm.lo, q.x_jam_mm.hi]);
    let probabilities = d
        .before
        .iter()
        .flat_map(|b| [b.probability.value, b.probability.lo]);
    assert!(numbers.chain(probabilities).all(f64::is_finite), "{d:?}");
}

/// An observer that answers Break stops the draws: no answer, the error says it was asked,
/// and the chunks after the stop are not drawn.
#[test]
fn monte_carlo_stops_when_its_observer_says_so() {
    use std::sync::atomic::{AtomicU64, Ordering};
    let (p, set) = shaft();
    let drawn = AtomicU64::new(0);
    let stop_after = 4 * 1024;
    let got = dist::monte_carlo_observed(
        &jamchart::models::ModelSpec::Statics,
        &p,
        &set,
        &ask(1_000_000),
        &|progress| {
            if let dist::Progress::Drawn(k) = progress {
                drawn.fetch_add(k, Ordering::Relaxed);
            }
            match drawn.load(Ordering::Relaxed) >= stop_after {
                true => jamchart::uncertain::Flow::Break(()),
                false => jamchart::uncertain::Flow::Continue(()),
            }
        },
    );
    assert!(matches!(got, Err(jamchart::Error::Stopped)), "{got:?}");
    // Each thread finishes the chunk it had begun.
    let threads = rayon::current_num_threads() as u64;
    assert!(drawn.load(Ordering::Relaxed) <= stop_after + 2 * threads * 1024);
}
