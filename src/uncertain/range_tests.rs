//! The closed form over a box of inputs: the interval from the corners against
//! point solves at the range's ends and against a brute-force grid over the box, and the
//! status breakpoints against the closed form.

use jamchart::statics;
use jamchart::uncertain::range::{self, End, Reached};
use jamchart::uncertain::{Uncertain, UncertainInput, UncertainSet};
use jamchart::{JamStatus, SceneParams};

/// The 25 mm shaft: r 12.5 mm, 0.4 kg, 40 N, an 80 mm palm; mu nominal 0.21.
use super::shaft as shaft_25mm;
use shaft_25mm::shaft_25mm as shaft;

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

/// The ends of `solve --mu 0.12:0.3` for the shaft: the point solve at mu = 0.3 (it jams),
/// and the palm's end at mu = 0.12, whose jam lies past it (the points between jam up to the
/// palm's end, x = L = 80 mm, and no further); the status changes where the jam leaves the
/// palm: s_B(theta_jam(mu)) = 80 mm.
#[test]
fn the_shafts_ends_are_the_point_solve_and_the_palms_end() {
    let p = shaft();
    let set = UncertainSet {
        inputs: vec![input("mu", &["mu_ground", "mu_palm"], 0.12, 0.3)],
    };
    let a = range::closed_form(&p, &set).unwrap();
    let (t_hi, x_lo) = raw(&p.with_mu(0.3));
    let reach = p.reach_angle();
    let (t_lo, x_hi) = (reach.to_degrees(), 80.0);
    let [a0, a1] = a.theta_jam_deg.unwrap();
    let [b0, b1] = a.x_jam_mm.unwrap();
    for (got, want) in [(a0, t_lo), (a1, t_hi), (b0, x_lo), (b1, x_hi)] {
        assert!((got - want).abs() < 1e-12 * want, "{got} vs {want}");
    }
    assert_eq!(a.reached, Some([Reached::PalmEnd, Reached::Corner]));
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
/// extremes of the point answers (through the port; a palm long enough for every jam): no
/// grid point lies outside it, and the grid's own extremes (it holds the corners) equal it.
#[test]
fn the_corners_interval_is_a_brute_force_grids() {
    let p = SceneParams {
        palm_offset_mm: 0.5,
        palm_length_mm: 1000.0,
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
    let a = range::closed_form(&p, &set).unwrap();
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
        let s = jamchart::solve(&jamchart::ModelSpec::Statics, &set.apply(&p, &v)).unwrap();
        assert_eq!(s.status, JamStatus::Jams, "{v:?}");
        let (t, x) = (s.theta_jam_deg.unwrap(), s.x_jam_mm.unwrap());
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
    let exact = range::closed_form(&p, &set).unwrap();
    let s = range::sampled(&jamchart::ModelSpec::Statics, &p, &set).unwrap();
    assert_eq!(
        s.method,
        // Nine points of one input, as the output says.
        range::RangeMethod::Sampled { samples: 9 }
    );
    let (e, g) = (exact.x_jam_mm.unwrap(), s.x_jam_mm.unwrap());
    assert!(
        (e[0] - g[0]).abs() < 1e-9 && (e[1] - g[1]).abs() < 1e-9,
        "{e:?} vs {g:?}"
    );
}

/// Regression (the range answer's speed): the breakpoints were found by a scan of
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
    let a = range::closed_form(&p, &set).unwrap();
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
    let reach_deg = p.reach_angle().to_degrees();
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
        let a = range::closed_form(&p, &set).unwrap();
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

/// The paper's scene (r 10 mm, 1 kg, mu 0.4) with `start_angle_deg` and one input's range.
fn paper_box(
    start_angle_deg: f64,
    name: &'static str,
    lo: f64,
    hi: f64,
) -> (SceneParams, UncertainSet) {
    let p = SceneParams {
        start_angle_deg,
        ..SceneParams::default()
    };
    let keys: &[&'static str] = match name {
        "mu" => &["mu_ground", "mu_palm"],
        "force_n" => &["force_n"],
        other => panic!("{other}"),
    };
    let set = UncertainSet {
        inputs: vec![input(name, keys, lo, hi)],
    };
    let mid = set.apply(&p, &[0.5 * (lo + hi)]);
    (mid, set)
}

/// Asserts `got` is [lo, hi] to `tol`.
fn assert_interval(got: Option<[f64; 2]>, want: [f64; 2], tol: f64) {
    let [a, b] = got.expect("an interval");
    assert!(
        (a - want[0]).abs() < tol && (b - want[1]).abs() < tol,
        "{got:?} vs {want:?}"
    );
}

/// Regression: a too weak earliest corner lost the jams beside it. `solve --force 2:10 --mu 0.4
/// --start-angle 80` printed theta_jam from 64.960 to 64.960 deg, while the push of 8 N alone
/// jams at 70.683 deg (14.102 mm), and pushes from 3.64 to 6.14 N are held at the start (80
/// deg, 11.918 mm): the push that just moves the disc leaves it held at the start.
#[test]
fn a_too_weak_corner_keeps_the_jams_and_the_holds_beside_it() {
    let (p, set) = paper_box(80.0, "force_n", 2.0, 10.0);
    let a = range::closed_form(&p, &set).unwrap();
    assert_eq!(a.earliest.status, JamStatus::TooWeak);
    assert_interval(a.theta_jam_deg, [64.960, 80.0], 5e-4);
    assert_interval(a.x_jam_mm, [11.918, 15.709], 5e-4);
    assert_eq!(a.reached, Some([Reached::Corner, Reached::HeldAtStart]));
    let at_8 = statics::solve(&set.apply(&p, &[8.0]));
    let [t0, t1] = a.theta_jam_deg.unwrap();
    assert!((t0..=t1).contains(&at_8.theta_jam_deg.unwrap()), "{at_8:?}");
    // Two inputs: the earliest corner (mu_ground 0.5046, 3.39 kg) is too weak, while mu_ground
    // 0.3 with 2 kg jams at 75.842 deg; it was printed as 40.745 to 40.745 deg.
    let p = SceneParams {
        radius_mm: 4.895,
        palm_offset_mm: 4.169,
        mu_palm: 0.69,
        force_n: 13.57,
        ..SceneParams::default()
    };
    let set = UncertainSet {
        inputs: vec![
            input("mu_ground", &["mu_ground"], 0.0839, 0.5046),
            input("mass_kg", &["mass_kg"], 0.388, 3.39),
        ],
    };
    let a = range::closed_form(&set.apply(&p, &[0.3, 2.0]), &set).unwrap();
    assert_interval(a.theta_jam_deg, [40.745, 90.0], 5e-4);
    let inside = statics::solve(&set.apply(&p, &[0.3, 2.0]));
    assert!((inside.theta_jam_deg.unwrap() - 75.842).abs() < 5e-4);
}

/// Regression: a corner held at the start was printed at its unclamped closed form. `solve --mu
/// 0.4 --start-angle 60 --force 5:20` printed theta_jam up to 90.353 deg and x_jam down to
/// 9.939 mm; at 5 N the disc is held at the start, 60 deg, 17.321 mm, and the palm never turns
/// past it.
#[test]
fn a_corner_held_at_the_start_answers_the_start_angle() {
    let (p, set) = paper_box(60.0, "force_n", 5.0, 20.0);
    let a = range::closed_form(&p, &set).unwrap();
    assert_eq!(a.earliest.status, JamStatus::JammedAtStart);
    assert_interval(a.theta_jam_deg, [54.095, 60.0], 5e-4);
    assert_interval(a.x_jam_mm, [17.321, 19.586], 5e-4);
}

/// Regression: a range whose lower friction is 0 lost its interval. `solve --mu 0:0.3` printed
/// "no point of the box jams" above "jams from 0.06507 to 0.3" (the JSON interval null): the
/// corner mu = 0 never jams, and between it and mu = 0.065 the jam lies past the palm, so the
/// latest jam is at the palm's end (x = L = 150 mm).
#[test]
fn a_friction_range_from_zero_keeps_its_interval() {
    let (p, set) = paper_box(90.0, "mu", 0.0, 0.3);
    let a = range::closed_form(&p, &set).unwrap();
    assert_eq!(a.latest.status, JamStatus::NeverJams);
    let reach = p.reach_angle().to_degrees();
    let top = statics::solve(&p.with_mu(0.3));
    assert_interval(a.theta_jam_deg, [reach, top.theta_jam_deg.unwrap()], 1e-9);
    assert_interval(a.x_jam_mm, [top.x_jam_mm.unwrap(), 150.0], 1e-9);
    assert_eq!(a.reached, Some([Reached::PalmEnd, Reached::Corner]));
}

/// `solve --mu 0:0.3` said `never_jams for mu < 2.794e-10`: the bisection of the status put
/// the end of never_jams at its bracket's last float, 2^-30 of the range, while only mu = 0
/// never jams (`--mu 1e-10` is beyond_reach). never_jams is the low end alone, a stretch
/// that ends where it begins, and the next status starts there; also along the box's
/// diagonal, with the other friction a range from 0 as well.
#[test]
fn only_a_friction_of_zero_never_jams() {
    let (p, set) = paper_box(90.0, "mu", 0.0, 0.3);
    let a = range::closed_form(&p, &set).unwrap();
    let segments = &a.inputs[0].segments;
    assert_eq!(segments[0].status, JamStatus::NeverJams);
    assert_eq!(
        (segments[0].from, segments[0].to),
        (0.0, 0.0),
        "{segments:?}"
    );
    assert_eq!(segments[1].status, JamStatus::BeyondReach, "{segments:?}");
    assert_eq!(segments[1].from, 0.0, "{segments:?}");
    assert_eq!(statics::status(&p.with_mu(1e-10)), JamStatus::BeyondReach);
    // Over a subnormal range the step above 0 is a float, not 1e-9 of the width (which
    // rounds to 0): never_jams once, then the next status, not never_jams eight times over.
    let (p0, set0) = paper_box(90.0, "mu", 0.0, 1e-322);
    let a = range::closed_form(&p0, &set0).unwrap();
    let statuses: Vec<JamStatus> = a.inputs[0].segments.iter().map(|s| s.status).collect();
    assert_eq!(
        statuses,
        [JamStatus::NeverJams, JamStatus::BeyondReach],
        "{:?}",
        a.inputs[0].segments
    );
    // Two frictions from 0: the statuses of the box, found along its diagonal.
    let set = UncertainSet {
        inputs: vec![
            input("mu_ground", &["mu_ground"], 0.0, 0.3),
            input("mu_palm", &["mu_palm"], 0.0, 0.3),
        ],
    };
    let a = range::closed_form(&p, &set).unwrap();
    for i in &a.inputs {
        let first = &i.segments[0];
        assert_ne!(
            first.status,
            JamStatus::NeverJams,
            "{}: {:?}",
            i.name,
            i.segments
        );
    }
    assert_eq!(
        a.statuses,
        [
            JamStatus::NeverJams,
            JamStatus::BeyondReach,
            JamStatus::Jams
        ],
        "{:?}",
        a.statuses
    );
}

/// Regression: the statics' interval counted the jams past the palm's end (the closed form on
/// a long enough palm) while the sampled models left those points out. Now both are over the
/// points that jam on the palm or are held at the start: for the shaft with mu 0.12 to 0.3
/// (beyond the 80 mm palm below mu = 0.149) every sample of the port lies inside the exact
/// interval, no sample that answers lies past the palm, and the exact interval's lower end is
/// the palm's end, not the 14.355 deg at mu = 0.12 that no point answers.
#[test]
fn every_model_leaves_the_jams_past_the_palm_out_of_its_interval() {
    let p = shaft();
    let set = UncertainSet {
        inputs: vec![input("mu", &["mu_ground", "mu_palm"], 0.12, 0.3)],
    };
    let exact = range::closed_form(&p, &set).unwrap();
    let [t0, t1] = exact.theta_jam_deg.unwrap();
    let reach = p.reach_angle().to_degrees();
    assert!((t0 - reach).abs() < 1e-9, "{t0} vs the palm's end {reach}");
    for spec in [
        jamchart::ModelSpec::Statics,
        jamchart::ModelKind::MinNorm.with(&Default::default(), &Default::default()),
    ] {
        let s = range::sampled(&spec, &p, &set).unwrap();
        assert!(s.statuses.contains(&JamStatus::BeyondReach), "{spec:?}");
        let [s0, s1] = s.theta_jam_deg.unwrap();
        assert!(
            s0 >= reach && s1 <= t1 + 1e-6,
            "{spec:?}: {s0} .. {s1} vs {t0} .. {t1}"
        );
    }
}
