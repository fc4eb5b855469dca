//! Random boxes of uncertain inputs over random palm scenes, and the point answers inside a
//! box: what the range, sweep band and jam map band tests check their intervals against.

use jamchart::uncertain::{Uncertain, UncertainInput, UncertainSet};
use jamchart::{JamStatus, ModelSpec, SceneParams};
use rand_chacha::ChaCha8Rng;
use rand_core::{Rng, SeedableRng};

/// A seeded source of uniform numbers.
pub struct Draw(ChaCha8Rng);

impl Draw {
    pub fn new(seed: u64) -> Self {
        Draw(ChaCha8Rng::seed_from_u64(seed))
    }

    /// Uniform on [lo, hi).
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let u = (self.0.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * u
    }

    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.uniform(0.0, 1.0) < p
    }

    /// One of `items`.
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[(self.uniform(0.0, items.len() as f64) as usize).min(items.len() - 1)]
    }
}

/// The inputs that take a range: (name as written, the fields it sets, its flag).
pub const INPUTS: [(&str, &[&str], &str); 5] = [
    ("mu", &["mu_ground", "mu_palm"], "--mu"),
    ("mu_ground", &["mu_ground"], "--mu-ground"),
    ("mu_palm", &["mu_palm"], "--mu-palm"),
    ("mass_kg", &["mass_kg"], "--mass"),
    ("force_n", &["force_n"], "--force"),
];

/// A random palm scene: every parameter the range answer depends on varied, the start angle
/// often at 90 deg (the most a model represents) and the palm offset often 0.
pub fn scene(d: &mut Draw) -> SceneParams {
    SceneParams {
        mu_ground: d.uniform(0.0, 0.8),
        mu_palm: d.uniform(0.0, 0.8),
        radius_mm: d.uniform(2.0, 20.0),
        mass_kg: d.uniform(0.1, 5.0),
        force_n: d.uniform(1.0, 300.0),
        start_angle_deg: if d.chance(0.3) {
            90.0
        } else {
            d.uniform(30.0, 90.0)
        },
        palm_length_mm: d.uniform(15.0, 200.0),
        palm_offset_mm: if d.chance(0.5) {
            0.0
        } else {
            d.uniform(0.0, 5.0)
        },
        ..SceneParams::default()
    }
}

/// A random range of input `name`: frictions and masses from 0 at times, pushes low enough to
/// be too weak at times.
pub fn range(d: &mut Draw, name: &str) -> (f64, f64) {
    let (lo, width) = match name {
        "mass_kg" => (
            if d.chance(0.15) {
                0.0
            } else {
                d.uniform(0.05, 3.0)
            },
            d.uniform(0.1, 3.0),
        ),
        "force_n" => (d.uniform(0.5, 80.0), d.uniform(1.0, 200.0)),
        _ => (
            if d.chance(0.2) {
                0.0
            } else {
                d.uniform(0.0, 0.6)
            },
            d.uniform(0.01, 0.6),
        ),
    };
    (lo, lo + width)
}

/// `n` distinct inputs (never `mu` with a friction of its own).
pub fn inputs(d: &mut Draw, n: usize) -> Vec<usize> {
    loop {
        let picked: Vec<usize> = (0..n).map(|_| d.pick(&[0, 1, 2, 3, 4])).collect();
        let distinct = (0..n).all(|i| (0..i).all(|j| picked[j] != picked[i]));
        let mu_twice = picked.contains(&0) && (picked.contains(&1) || picked.contains(&2));
        if distinct && !mu_twice {
            return picked;
        }
    }
}

/// A random box of one or two inputs around a random scene; the scene holds the inputs'
/// midpoints.
pub fn random_box(d: &mut Draw) -> (SceneParams, UncertainSet) {
    let mut p = scene(d);
    let n = if d.chance(0.5) { 1 } else { 2 };
    let set = UncertainSet {
        inputs: inputs(d, n)
            .into_iter()
            .map(|i| {
                let (name, keys, _) = INPUTS[i];
                let (lo, hi) = range(d, name);
                UncertainInput {
                    name,
                    keys: keys.to_vec(),
                    value: Uncertain::Range { lo, hi },
                }
            })
            .collect(),
    };
    let mid: Vec<f64> = set.inputs.iter().map(|i| i.value.nominal()).collect();
    p = set.apply(&p, &mid);
    (p, set)
}

/// The closed form's point answer through the model port: its status and, where it answers
/// one, (theta_jam in deg, x_jam in mm).
pub fn point(p: &SceneParams) -> (JamStatus, Option<(f64, f64)>) {
    let s = jamchart::solve(&ModelSpec::Statics, p).expect("a valid scene");
    let jam = match (s.theta_jam_deg, s.x_jam_mm) {
        (Some(t), Some(x)) => Some((t, x)),
        _ => None,
    };
    (s.status, jam)
}

/// Every answer (theta_jam, x_jam) met along `at(t)`, t in [0, 1]: `n` evenly spaced points,
/// and, between neighbours whose statuses differ, the two ends of a bisection of the status
/// to 2^-60 of the step, so that a stretch narrower than the step (a disc held at the start
/// just above the push that moves it) is met too.
pub fn along(n: usize, at: impl Fn(f64) -> SceneParams, out: &mut Vec<(f64, f64)>) {
    let ts: Vec<f64> = (0..n).map(|j| j as f64 / (n - 1) as f64).collect();
    let answers: Vec<(JamStatus, Option<(f64, f64)>)> = ts.iter().map(|&t| point(&at(t))).collect();
    out.extend(answers.iter().filter_map(|a| a.1));
    for j in 1..n {
        if answers[j - 1].0 == answers[j].0 {
            continue;
        }
        let (mut a, mut b) = (ts[j - 1], ts[j]);
        let first = answers[j - 1].0;
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            if point(&at(m)).0 == first {
                a = m;
            } else {
                b = m;
            }
        }
        out.extend([point(&at(a)).1, point(&at(b)).1].into_iter().flatten());
    }
}

/// The answers over the box `set` around `p`: along every line of an `n`-point grid per input
/// (each line refined at its status changes, [`along`]).
pub fn answers_in_box(p: &SceneParams, set: &UncertainSet, n: usize) -> Vec<(f64, f64)> {
    let ends: Vec<(f64, f64)> = set.inputs.iter().map(|i| i.value.ends()).collect();
    let value = |i: usize, t: f64| ends[i].0 + (ends[i].1 - ends[i].0) * t;
    let mut out = Vec::new();
    match ends.len() {
        1 => along(n, |t| set.apply(p, &[value(0, t)]), &mut out),
        2 => {
            for j in 0..n {
                let s = j as f64 / (n - 1) as f64;
                along(n, |t| set.apply(p, &[value(0, t), value(1, s)]), &mut out);
                along(n, |t| set.apply(p, &[value(0, s), value(1, t)]), &mut out);
            }
        }
        k => panic!("boxes of one or two inputs, not {k}"),
    }
    out
}

/// How an interval breaks its promise against the answers met in its box.
#[derive(Debug, Clone, PartialEq)]
pub enum Broken {
    /// A point answers outside it (by `by`, deg or mm).
    Misses {
        quantity: &'static str,
        value: f64,
        by: f64,
    },
    /// An end lies `by` from the nearest answer's extreme: it claims a value no point reaches.
    Claims {
        quantity: &'static str,
        end: f64,
        by: f64,
    },
    /// Points answer, and the interval says none does.
    Empty { answers: usize },
}

/// Checks `interval` ([lo, hi] or None) of `quantity` against `values`: every value inside it
/// (to `inside` relative), each end within `claim` (relative) of the values' extreme.
pub fn check(
    quantity: &'static str,
    interval: Option<[f64; 2]>,
    values: &[f64],
    inside: f64,
    claim: f64,
) -> Vec<Broken> {
    let Some([lo, hi]) = interval else {
        return match values.len() {
            0 => Vec::new(),
            answers => vec![Broken::Empty { answers }],
        };
    };
    let scale = |v: f64| v.abs().max(1.0);
    let mut out = Vec::new();
    for &v in values {
        let by = (lo - v).max(v - hi);
        if by > inside * scale(v) {
            out.push(Broken::Misses {
                quantity,
                value: v,
                by,
            });
            break;
        }
    }
    let min = values.iter().copied().fold(f64::INFINITY, f64::min);
    let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    for (end, reached) in [(lo, min), (hi, max)] {
        let by = (end - reached).abs();
        if by.is_nan() || by > claim * scale(end) {
            out.push(Broken::Claims { quantity, end, by });
        }
    }
    out
}
