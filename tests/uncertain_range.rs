//! The closed form over a box of inputs (issue 19): the interval from the corners against
//! point solves at the range's ends and against a brute-force grid over the box, and the
//! status breakpoints against the closed form.

use jamchart::statics;
use jamchart::uncertain::range::{self, End};
use jamchart::uncertain::{Uncertain, UncertainInput, UncertainSet};
use jamchart::{JamStatus, SceneParams};

/// The shaft: r 12.5 mm, 0.4 kg, 40 N, an 80 mm palm; mu nominal 0.21.
use jamchart::uncertain::shaft_25mm as shaft;

fn input(name: &'static str, keys: &[&'static str], lo: f64, hi: f64) -> UncertainInput {
    UncertainInput {
        name,
        keys: keys.to_vec(),
        value: Uncertain::Range { lo, hi },
    }
}

/// theta_jam (deg) and x_jam (mm) of the closed form where it jams on a long enough palm.
fn raw(p: &SceneParams) -> (f64, f64) {
    let t = statics::theta_jam_rad(p);
    (t.to_degrees(), p.disc_position_mm(t))
}

/// The ends of `solve --mu 0.12:0.3` for the shaft are the point solves at mu = 0.12 and 0.3,
/// and the status changes where the jam leaves the palm: s_B(theta_jam(mu)) = 80 mm.
#[test]
fn the_shafts_ends_are_the_point_solves_and_the_breakpoint_is_the_palms_end() {
    let p = shaft();
    let set = UncertainSet {
        inputs: vec![input("mu", &["mu_ground", "mu_palm"], 0.12, 0.3)],
    };
    let a = range::closed_form(&p, &set);
    let (t_hi, x_lo) = raw(&p.with_mu(0.3));
    let (t_lo, x_hi) = raw(&p.with_mu(0.12));
    let [a0, a1] = a.theta_jam_deg.unwrap();
    let [b0, b1] = a.x_jam_mm.unwrap();
    for (got, want) in [(a0, t_lo), (a1, t_hi), (b0, x_lo), (b1, x_hi)] {
        assert!((got - want).abs() < 1e-12 * want, "{got} vs {want}");
    }
    assert_eq!(a.earliest.status, statics::solve(&p.with_mu(0.3)).status);
    assert_eq!(a.latest.status, JamStatus::BeyondReach);
    assert_eq!(a.inputs[0].earliest_at, End::High);
    let segs = &a.inputs[0].segments;
    assert_eq!(segs.len(), 2, "{segs:?}");
    assert_eq!(
        (segs[0].status, segs[1].status),
        (JamStatus::BeyondReach, JamStatus::Jams)
    );
    let mu_star = segs[0].to;
    let q = p.with_mu(mu_star);
    let s_b = q.contact_distance_mm(statics::theta_jam_rad(&q));
    assert!((s_b - 80.0).abs() < 1e-5, "s_B at mu = {mu_star}: {s_b}");
    assert!((mu_star - 0.1489).abs() < 5e-5, "{mu_star}");
    assert_eq!(a.statuses, [JamStatus::BeyondReach, JamStatus::Jams]);
}

/// Over a box of four independent inputs the corners' interval is the brute-force grid's
/// extremes: no grid point lies outside it, and the grid's own extremes (it holds the
/// corners) equal it.
#[test]
fn the_corners_interval_is_a_brute_force_grids() {
    let p = SceneParams {
        palm_offset_mm: 0.5,
        ..shaft()
    };
    let set = UncertainSet {
        inputs: vec![
            input("mu_ground", &["mu_ground"], 0.12, 0.3),
            input("mu_palm", &["mu_palm"], 0.1, 0.5),
            input("force_n", &["force_n"], 30.0, 50.0),
            input("mass_kg", &["mass_kg"], 0.2, 0.6),
        ],
    };
    let a = range::closed_form(&p, &set);
    let [t0, t1] = a.theta_jam_deg.unwrap();
    let [x0, x1] = a.x_jam_mm.unwrap();
    let n = 9;
    let (mut gt, mut gx) = (
        [f64::INFINITY, f64::NEG_INFINITY],
        [f64::INFINITY, f64::NEG_INFINITY],
    );
    let mut worst_outside: f64 = 0.0;
    for flat in 0..n * n * n * n {
        let mut rest = flat;
        let v: Vec<f64> = set
            .inputs
            .iter()
            .map(|i| {
                let (lo, hi) = i.value.ends();
                let j = rest % n;
                rest /= n;
                lo + (hi - lo) * j as f64 / (n - 1) as f64
            })
            .collect();
        let (t, x) = raw(&set.apply(&p, &v));
        gt = [gt[0].min(t), gt[1].max(t)];
        gx = [gx[0].min(x), gx[1].max(x)];
        worst_outside = worst_outside
            .max(t0 - t)
            .max(t - t1)
            .max(x0 - x)
            .max(x - x1);
    }
    assert!(
        worst_outside <= 1e-9,
        "a grid point lies {worst_outside} outside"
    );
    for (got, want) in [(t0, gt[0]), (t1, gt[1]), (x0, gx[0]), (x1, gx[1])] {
        assert!(
            (got - want).abs() < 1e-9 * want.abs(),
            "{got} vs grid {want}"
        );
    }
    let ends: Vec<End> = a.inputs.iter().map(|i| i.earliest_at).collect();
    assert_eq!(ends, [End::High, End::High, End::Low, End::High]);
}

/// A model that samples the box (here the statics through the port, so the oracle is exact)
/// reports the samples' range: with every sample on the palm it spans the corners' interval,
/// and it says how many samples it took.
#[test]
fn a_sampled_box_spans_the_corners_interval() {
    let p = shaft();
    let set = UncertainSet {
        inputs: vec![input("mu", &["mu_ground", "mu_palm"], 0.15, 0.3)],
    };
    let exact = range::closed_form(&p, &set);
    let s = range::sampled(&jamchart::ModelSpec::Statics, &p, &set).unwrap();
    assert_eq!(
        s.method,
        range::Method::Sampled {
            samples: range::SAMPLES_PER_INPUT
        }
    );
    let (e, g) = (exact.x_jam_mm.unwrap(), s.x_jam_mm.unwrap());
    assert!(
        (e[0] - g[0]).abs() < 1e-9 && (e[1] - g[1]).abs() < 1e-9,
        "{e:?} vs {g:?}"
    );
}

/// Regression (issue 19, the range answer's speed): the breakpoints were found by a scan of
/// 64 evenly spaced `statics::solve`s along each input (each one beyond the palm ran the
/// past-palm bisection, 160.8 us against a 110 ns point answer), and a status holding on a
/// stretch narrower than 1/63 of the range fell between two scan points and was never
/// reported. Now the walk goes from the low end's status to the high end's, each change found
/// where theta_jam crosses its angle: here the shaft with the palm starting at 18.5 deg jams
/// only for mu within about 0.003 of 0.157 (theta_jam between the reach angle, 17.76 deg, and
/// the start), 1/1000 of the range 0.01:3.
#[test]
fn a_status_on_a_stretch_narrower_than_the_old_scan_step_is_reported() {
    let p = SceneParams {
        start_angle_deg: 18.5,
        ..shaft()
    };
    let set = UncertainSet {
        inputs: vec![input("mu", &["mu_ground", "mu_palm"], 0.01, 3.0)],
    };
    let a = range::closed_form(&p, &set);
    let segs = &a.inputs[0].segments;
    let statuses: Vec<JamStatus> = segs.iter().map(|s| s.status).collect();
    assert_eq!(
        statuses,
        [
            JamStatus::BeyondReach,
            JamStatus::Jams,
            JamStatus::JammedAtStart
        ],
        "{segs:?}"
    );
    assert!(segs[1].to - segs[1].from < (3.0 - 0.01) / 63.0, "{segs:?}");
    // The jams stretch runs from the reach angle to the start angle.
    let theta_deg = |mu: f64| statics::theta_jam_rad(&p.with_mu(mu)).to_degrees();
    let reach_deg = statics::reach_angle_rad(&p).to_degrees();
    assert!(
        (theta_deg(segs[1].from) - reach_deg).abs() < 1e-6,
        "{segs:?}"
    );
    assert!((theta_deg(segs[1].to) - 18.5).abs() < 1e-6, "{segs:?}");
    // Either side of each change the closed form's own status agrees.
    for w in segs.windows(2) {
        let at = |mu: f64| statics::solve(&p.with_mu(mu)).status;
        assert_eq!(at(w[0].to - 1e-6), w[0].status);
        assert_eq!(at(w[0].to + 1e-6), w[1].status);
    }
    // The box's statuses (in the order of JamStatus::ALL) are the three.
    assert_eq!(a.statuses.len(), 3);
    assert!(statuses.iter().all(|s| a.statuses.contains(s)));
}

/// Every single input's status change where the jam leaves the palm is solved for (closed form
/// for the push, the mass and the palm's friction; Newton's method for the ground's friction
/// and for both): the change lies where the contact reaches the palm's end, s_B = 80 mm, to
/// 1e-9 of the range, and the closed form's own status agrees either side of it.
#[test]
fn each_inputs_change_at_the_palms_end_is_where_s_b_is_the_palm_length() {
    let cases: [(&'static str, &[&'static str], f64, f64, f64); 5] = [
        ("mu", &["mu_ground", "mu_palm"], 0.21, 0.05, 0.5),
        ("mu_ground", &["mu_ground"], 0.21, 0.02, 0.6),
        ("mu_palm", &["mu_palm"], 0.21, 0.0, 0.6),
        ("force_n", &["force_n"], 0.15, 10.0, 400.0),
        ("mass_kg", &["mass_kg"], 0.15, 0.05, 3.0),
    ];
    for (name, keys, mu, lo, hi) in cases {
        let p = shaft().with_mu(mu);
        let set = UncertainSet {
            inputs: vec![input(name, keys, lo, hi)],
        };
        let a = range::closed_form(&p, &set);
        let segs = &a.inputs[0].segments;
        assert_eq!(segs.len(), 2, "{name}: {segs:?}");
        let at = |x: f64| set.apply(&p, &[x]);
        let change = segs[0].to;
        let q = at(change);
        let s_b = q.contact_distance_mm(statics::theta_jam_rad(&q));
        assert!(
            (s_b - 80.0).abs() < 1e-6,
            "{name}: s_B at {change} is {s_b}"
        );
        let step = 1e-9 * (hi - lo);
        assert_eq!(statics::solve(&at(change)).status, segs[1].status, "{name}");
        assert_eq!(
            statics::solve(&at(change - step)).status,
            segs[0].status,
            "{name}"
        );
        let statuses = [segs[0].status, segs[1].status];
        assert!(
            statuses.contains(&JamStatus::BeyondReach) && statuses.contains(&JamStatus::Jams),
            "{name}: {segs:?}"
        );
    }
}
