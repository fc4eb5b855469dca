//! The text of the answer over a box: the interval of each model with its corners and the
//! statuses along each input, then the distribution's probabilities and quantiles.

use std::fmt::Write;

use super::Words;
use super::solve::BoxAnswer;
use crate::models::{self, ModelKind};
use crate::numbers::Num;
use crate::scene::JamStatus;
use crate::uncertain::dist::{DistAnswer, DistMethod, Estimate};
use crate::uncertain::range::{Corner, End, InputEnds, RangeMethod, Reached};

impl BoxAnswer {
    /// The command line's report: the scene and its uncertain inputs, then each model's
    /// interval, corners and statuses, and the distribution's answer. It names no setting, so
    /// it reads the same in every face's words.
    pub fn text(&self, _words: Words) -> String {
        let (p, uncertain, results) = (&self.inputs, &self.uncertain, &self.results);
        let mut s = String::new();
        let _ = writeln!(
            s,
            "scene: r = {} mm, g = {} m/s^2, start at {} deg, palm {} mm; nominal mu_ground = {}, \
             mu_palm = {}, m = {} kg, F = {} N",
            Num(p.radius_mm),
            Num(p.gravity_m_s2),
            Num(p.start_angle_deg),
            Num(p.palm_length_mm),
            Num(p.mu_ground),
            Num(p.mu_palm),
            Num(p.mass_kg),
            Num(p.force_n)
        );
        let _ = writeln!(s, "uncertain: {}", uncertain.describe());
        for note in uncertain.box_notes() {
            let _ = writeln!(s, "  {note}");
        }
        for r in results {
            let a = &r.range;
            let how = match a.method {
                RangeMethod::Corners => {
                    "exact: theta_jam is monotone in every input, so the box is \
                                    answered from its corners"
                        .to_string()
                }
                RangeMethod::Sampled { samples } => format!(
                    "sampled at {samples} points of a grid over the box: the range of the samples, \
                     not a bound"
                ),
            };
            let _ = writeln!(s, "\n{} over the box ({how}):", r.model);
            let names: Vec<&str> = a.inputs.iter().map(|i| i.name).collect();
            let at = |c: &Corner| {
                let v: Vec<String> = names
                    .iter()
                    .zip(&c.values)
                    .map(|(n, v)| format!("{n} = {}", round(*v)))
                    .collect();
                v.join(", ")
            };
            let point = match a.method {
                RangeMethod::Corners => "corner",
                RangeMethod::Sampled { .. } => "sample",
            };
            match (a.theta_jam_deg, a.x_jam_mm, a.reached) {
                (Some([t0, t1]), Some([x0, x1]), Some([low, high])) => {
                    let _ = writeln!(
                        s,
                        "  theta_jam from {t0:.3} to {t1:.3} deg, x_jam from {x0:.3} to {x1:.3} mm, \
                         over the points that jam on the palm or are held at the start",
                        t0 = Num(t0),
                        t1 = Num(t1),
                        x0 = Num(x0),
                        x1 = Num(x1)
                    );
                    for (what, c, how, t, x) in [
                        (
                            "earliest jam (nearest the hinge)",
                            &a.earliest,
                            high,
                            t1,
                            x0,
                        ),
                        ("latest jam (furthest out)", &a.latest, low, t0, x1),
                    ] {
                        let reached = match how {
                            Reached::Corner => format!("at the {point} {}, {}", at(c), c.status),
                            Reached::HeldAtStart => format!(
                                "held at the start where the push just moves the disc; the corner \
                                 {} is {}",
                                at(c),
                                c.status
                            ),
                            Reached::PalmEnd => {
                                format!("at the palm's end; the corner {} is {}", at(c), c.status)
                            }
                        };
                        let _ = writeln!(
                            s,
                            "  {what}: theta_jam = {t:.3} deg, x_jam = {x:.3} mm, {reached}",
                            t = Num(t),
                            x = Num(x)
                        );
                    }
                }
                _ if a.statuses == [JamStatus::OutsideModel] => {
                    if let Some(why) = models::outside(ModelKind::Statics, p) {
                        let _ = writeln!(s, "  not run: {why}");
                    }
                }
                _ => {
                    let _ = writeln!(
                        s,
                        "  no point of the box jams on the palm or is held at the start"
                    );
                    let _ = writeln!(
                        s,
                        "  the {point}s where it would jam earliest and latest: {}, {}; {}, {}",
                        at(&a.earliest),
                        a.earliest.status,
                        at(&a.latest),
                        a.latest.status
                    );
                }
            }
            let others = if a.inputs.len() > 1 {
                " (the other inputs at their nominal values)"
            } else {
                ""
            };
            for i in &a.inputs {
                let _ = writeln!(s, "  {}{others}", segments_text(i));
            }
            let seen: Vec<&str> = a.statuses.iter().map(|s| s.as_str()).collect();
            let _ = writeln!(s, "  statuses in the box: {}", seen.join(", "));
            if let Some(d) = &r.distribution {
                distribution_text(&mut s, d);
            }
        }
        s
    }
}

/// The probabilities and quantiles, with the sample count and interval widths of a Monte Carlo.
fn distribution_text(s: &mut String, d: &DistAnswer) {
    let how = match d.method {
        DistMethod::Exact => "exact, by the monotone map of the input's distribution".to_string(),
        DistMethod::MonteCarlo {
            samples,
            seed,
            without_jam,
        } => format!(
            "Monte Carlo, {samples} samples (seed {seed}{}; ranges drawn as uniform), 95 % \
             intervals",
            match without_jam {
                0 => String::new(),
                k => format!(", {k} without a jam position"),
            }
        ),
    };
    let _ = writeln!(s, "  distribution of x_jam on a long enough palm ({how}):");
    let interval = |e: &Estimate, digits: usize| match d.method {
        DistMethod::Exact => String::new(),
        DistMethod::MonteCarlo { .. } => format!(
            " [{:.digits$}, {:.digits$}] (width {:.digits$})",
            Num(e.lo),
            Num(e.hi),
            Num(e.hi - e.lo)
        ),
    };
    for b in &d.before {
        let _ = writeln!(
            s,
            "    P(jams before x = {} mm) = {:.4}{}",
            Num(b.x_mm),
            Num(b.probability.value),
            interval(&b.probability, 4)
        );
    }
    for q in &d.quantiles {
        let _ = writeln!(
            s,
            "    {:>4} % quantile of x_jam = {:.3} mm{}",
            round(100.0 * q.q),
            Num(q.x_jam_mm.value),
            interval(&q.x_jam_mm, 3)
        );
    }
    for q in &d.beyond_every_position {
        let _ = writeln!(
            s,
            "    {:>4} % quantile of x_jam: beyond {:.1e} mm, past every position a double \
             holds (frictions too small for a jam within any reach)",
            round(100.0 * q),
            f64::MAX
        );
    }
}

/// `mu: beyond_reach for mu < 0.148, jams from 0.148 to 0.3; the jam comes earliest at the
/// high end`.
fn segments_text(i: &InputEnds) -> String {
    let n = i.name;
    let parts: Vec<String> = match &i.segments[..] {
        [one] => vec![format!("{} over the whole range", one.status)],
        segs => segs
            .iter()
            .enumerate()
            .map(|(j, g)| match j {
                _ if g.from == g.to => format!("{} at {n} = {}", g.status, round(g.from)),
                0 => format!("{} for {n} < {}", g.status, round(g.to)),
                _ => format!("{} from {} to {}", g.status, round(g.from), round(g.to)),
            })
            .collect(),
    };
    let end = match i.earliest_at {
        End::Low => "low",
        End::High => "high",
    };
    format!(
        "{n} in [{}, {}]: {}; the jam comes earliest at the {end} end",
        round(i.lo),
        round(i.hi),
        parts.join(", ")
    )
}

/// Four significant digits: a breakpoint found to 1e-9 of the range reads as 0.1484.
fn round(v: f64) -> String {
    crate::numbers::sig(v, 4)
}

impl BoxAnswer {
    /// The verdict in one line: each model's interval over the box, and the probabilities
    /// asked of a distribution.
    pub fn headline(&self) -> String {
        let each: Vec<String> = self
            .results
            .iter()
            .map(|r| {
                let a = &r.range;
                let span = match (a.theta_jam_deg, a.x_jam_mm) {
                    (Some([t0, t1]), Some([x0, x1])) => format!(
                        "theta_jam {:.3} to {:.3} deg, x_jam {:.3} to {:.3} mm",
                        Num(t0),
                        Num(t1),
                        Num(x0),
                        Num(x1)
                    ),
                    _ => {
                        let seen: Vec<&str> = a.statuses.iter().map(|s| s.as_str()).collect();
                        format!("no jam on the palm ({})", seen.join(", "))
                    }
                };
                let probabilities: Vec<String> = r
                    .distribution
                    .iter()
                    .flat_map(|d| &d.before)
                    .map(|b| {
                        format!(
                            ", P(jams before {} mm) = {:.4}",
                            Num(b.x_mm),
                            Num(b.probability.value)
                        )
                    })
                    .collect();
                format!("{}: {span}{}", r.model, probabilities.concat())
            })
            .collect();
        format!("over {}: {}", self.uncertain.describe(), each.join("; "))
    }
}
