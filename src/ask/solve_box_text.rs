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
                        // The far end reached at the palm's end by a corner pushed past it is
                        // not that corner's jam ("latest jam: x_jam = 80.000 mm" for a part the
                        // palm loses): said as what it is, with the jam a long palm would give.
                        if let (Reached::PalmEnd, false) = (how, c.status == JamStatus::Jams) {
                            let _ = writeln!(s, "  {}", pushed_past_text(c, &at(c), point, t, x));
                            continue;
                        }
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
                    let instead: Vec<String> = a
                        .statuses
                        .iter()
                        .map(|&st| format!("{st} ({})", without_jam(st)))
                        .collect();
                    let _ = writeln!(
                        s,
                        "  no point of the box jams on the palm or is held at the start: {}",
                        instead.join("; ")
                    );
                    let _ = writeln!(
                        s,
                        "  its two extreme {point}s: {}, {}; {}, {}",
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
    // Which end brings the jam nearest the hinge is said only where the range has a jam: over
    // a range that is too weak throughout, "the jam comes earliest at the high end" told of a
    // jam that does not exist.
    let jams =
        (i.segments.iter()).any(|g| matches!(g.status, JamStatus::Jams | JamStatus::JammedAtStart));
    let then = match (jams, &i.segments[..]) {
        (true, _) => format!("the jam comes earliest at the {end} end"),
        (false, [one]) => format!("{}: no jam on this range", without_jam(one.status)),
        (false, _) => "no jam on this range".to_string(),
    };
    format!(
        "{n} in [{}, {}]: {}; {then}",
        round(i.lo),
        round(i.hi),
        parts.join(", ")
    )
}

/// The interval's far end where it is the palm's end, reached because corner `c` pushes the
/// part past it: `furthest out: pushed past the palm's end (x = 80.000 mm, theta = 17.761
/// deg) at the corner mu = 0.12, beyond_reach; on a long enough palm it would jam at theta_jam
/// = 14.355 deg, x_jam = 99.261 mm`.
fn pushed_past_text(c: &Corner, at: &str, point: &str, theta_deg: f64, x_mm: f64) -> String {
    let head = format!(
        "furthest out: pushed past the palm's end (x = {:.3} mm, theta = {:.3} deg) at the \
         {point} {at}, {}",
        Num(x_mm),
        Num(theta_deg),
        c.status
    );
    match &c.past_palm {
        Some(past) => format!(
            "{head}; on a long enough palm it would jam at theta_jam = {:.3} deg, x_jam = {:.3} \
             mm (a palm of at least {:.3} mm)",
            Num(past.theta_jam_deg),
            Num(past.x_jam_mm),
            Num(past.palm_length_needed_mm)
        ),
        None => format!("{head} ({})", without_jam(c.status)),
    }
}

/// What happens at a point of `status`, which has no jam on the palm.
fn without_jam(status: JamStatus) -> &'static str {
    match status {
        JamStatus::TooWeak => "the push cannot move the part",
        JamStatus::NeverJams => "no friction: the part slides on without jamming",
        JamStatus::BeyondReach => "the part is pushed past the palm's end",
        JamStatus::OutsideModel => "outside what the model represents",
        JamStatus::Inaccurate | JamStatus::IntegratorFailed => "no answer to trust",
        JamStatus::Jams | JamStatus::JammedAtStart => "a jam",
    }
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

#[cfg(test)]
mod tests {
    use crate::ask::{SolveQuestion, Words};

    /// The report of `solve` for a JSON body of keywords.
    fn report(body: &str) -> String {
        let question: SolveQuestion = serde_json::from_str(body).unwrap();
        question.answer().unwrap().text(Words::Flags)
    }

    /// A box where nothing jams (every corner too weak) said "the jam comes earliest at the
    /// high end" and named "the corners where it would jam": words of a jam that does not
    /// exist. It says what happens instead.
    #[test]
    fn a_box_without_a_jam_speaks_of_no_jam() {
        let text = report(r#"{"mu": "0.2:0.4", "force_n": "1e-3:1e-2"}"#);
        assert!(!text.contains("jam comes"), "{text}");
        assert!(!text.contains("would jam"), "{text}");
        assert!(
            text.contains(
                "no point of the box jams on the palm or is held at the start: too_weak (the \
                 push cannot move the part)"
            ),
            "{text}"
        );
        assert!(
            text.contains(
                "mu in [0.2, 0.4]: too_weak over the whole range; the push cannot move the \
                 part: no jam on this range"
            ),
            "{text}"
        );
        // A range with a jam still says which end brings it nearest the hinge.
        let text = report(
            r#"{"mu": "0.12:0.3", "radius_mm": 12.5, "mass_kg": 0.4, "force_n": 40, "palm_length_mm": 80}"#,
        );
        assert!(
            text.contains("the jam comes earliest at the high end"),
            "{text}"
        );
    }

    /// `solve --mu 0.12:0.3` for the 25 mm shaft said "latest jam (furthest out): x_jam =
    /// 80.000 mm, at the palm's end" for a corner whose part the palm pushes past its end, and
    /// the range record gave no jam for it. It is named for what it is, with the jam a long
    /// palm would give (99.261 mm, as `solve --mu 0.12` says), in the text and the record.
    #[test]
    fn a_corner_pushed_past_the_palm_is_not_called_a_jam() {
        let shaft = r#""radius_mm": 12.5, "mass_kg": 0.4, "force_n": 40, "palm_length_mm": 80"#;
        let question: SolveQuestion =
            serde_json::from_str(&format!(r#"{{"mu": "0.12:0.3", {shaft}}}"#)).unwrap();
        let answer = question.answer().unwrap();
        let text = answer.text(Words::Flags);
        assert!(!text.contains("latest jam"), "{text}");
        assert!(
            text.contains(
                "furthest out: pushed past the palm's end (x = 80.000 mm, theta = 17.761 deg) at \
                 the corner mu = 0.12, beyond_reach; on a long enough palm it would jam at \
                 theta_jam = 14.355 deg, x_jam = 99.261 mm (a palm of at least 99.261 mm)"
            ),
            "{text}"
        );
        let record = serde_json::to_value(&answer).unwrap();
        let latest = &record["results"][0]["latest"];
        assert_eq!(latest["status"], "beyond_reach", "{latest}");
        assert!(latest["x_jam_mm"].is_null(), "{latest}");
        let would = latest["past_palm"]["x_jam_mm"].as_f64().unwrap();
        assert!((would - 99.2613605241956).abs() < 1e-9, "{latest}");
        // A corner that jams on the palm has none.
        assert!(
            record["results"][0]["earliest"]["past_palm"].is_null(),
            "{record}"
        );
    }
}
