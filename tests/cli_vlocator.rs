//! `jamchart vlocator` run as a user would: text, JSON keys, and bad input.

use crate::common::cli as cli_util;
use cli_util::{jamchart, json, stderr, stdout};

#[test]
fn json_has_the_documented_keys_and_per_flank_forces() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(&jamchart(
        dir.path(),
        &[
            "vlocator",
            "--included-angle",
            "90",
            "--mu",
            "0.3",
            "--load",
            "5",
            "--format",
            "json",
        ],
    ));
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(
        keys,
        [
            "verdict",
            "self_locking",
            "locking_needed",
            "friction_held",
            "forces",
            "capacity",
            "optimum",
            "inputs"
        ]
    );
    assert_eq!(v["verdict"], "held");
    let forces = v["forces"].as_array().unwrap();
    assert_eq!(forces[0]["flank"], "left");
    assert_eq!(forces[1]["flank"], "right");
    for f in forces {
        for k in ["normal_n", "tangential_up_n", "fx_n", "fy_n", "utilisation"] {
            assert!(f[k].is_f64(), "{k}");
        }
    }
    // Equilibrium: the flank forces carry W = 9.806 N up and the 5 N push sideways.
    let sum = |k: &str| forces.iter().map(|f| f[k].as_f64().unwrap()).sum::<f64>();
    assert!((sum("fx_n") + 5.0).abs() < 1e-9 && (sum("fy_n") - 9.806).abs() < 1e-9);
    let c = &v["capacity"];
    // A free 90 deg V holds a sideways centre load up to W (friction adds nothing).
    assert!((c["p_max_over_w"].as_f64().unwrap() - 1.0).abs() < 1e-12);
    assert_eq!(c["unbounded"], false);
    assert_eq!(c["failure_mode"], "rolls_over_right");
    let o = &v["optimum"];
    assert_eq!(o["criterion"], "balanced");
    // gamma* = 2 atan sqrt(mu W / P).
    let want = 2.0 * (0.3_f64 * 9.806 / 5.0).sqrt().atan().to_degrees();
    assert!((o["included_angle_deg"].as_f64().unwrap() - want).abs() < 1e-6);
    assert_eq!(o["at_bound"], false);
    assert_eq!(v["inputs"]["rotation"], "free");
    assert!(v["inputs"]["load_at_rim_deg"].is_null());
}

#[test]
fn text_gives_the_verdict_with_units() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &["vlocator", "--included-angle", "90", "--load", "20"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let t = stdout(&o);
    assert!(t.contains("verdict: slips"), "{t}");
    assert!(t.contains("rolls out over the right flank"), "{t}");
    assert!(t.contains("P_max = 9.806 N = 1.000 W"), "{t}");
    assert!(t.contains("deg") && t.contains("rho*"), "{t}");
    let o = jamchart(
        dir.path(),
        &["vlocator", "--included-angle", "20", "--load", "100"],
    );
    let t = stdout(&o);
    assert!(
        t.contains("verdict: wedged") && t.contains("lower bound"),
        "{t}"
    );
}

/// Bad input exits 2 with one line naming the flag and the value.
#[test]
fn bad_input_exits_2_naming_the_flag_and_value() {
    let dir = tempfile::tempdir().unwrap();
    let cases: &[(&[&str], &[&str])] = &[
        (&["--flank-angles", "100,90"], &["--flank-angles", "190"]),
        (&["--flank-angles", "-5,40"], &["--flank-angles", "-5"]),
        (&["--flank-angles", "10"], &["--flank-angles", "10"]),
        (&["--included-angle", "180"], &["--included-angle", "180"]),
        (&["--mu", "-0.2"], &["--mu", "-0.2"]),
        (&["--mu-right", "-1"], &["--mu-right", "-1"]),
        (&["--load", "inf"], &["--load", "inf"]),
        (&["--load", "-3"], &["--load", "-3"]),
        (&["--load-angle", "nan"], &["--load-angle", "NaN"]),
        (&["--mass", "0"], &["--mass", "0"]),
        (
            &["--included-angle", "60", "--flank-angles", "30,30"],
            &["--included-angle", "--flank-angles"],
        ),
        (&["--rotation", "spin"], &["spin", "free, blocked"]),
    ];
    for (args, needles) in cases {
        let mut all = vec!["vlocator"];
        all.extend_from_slice(args);
        let o = jamchart(dir.path(), &all);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(stdout(&o).is_empty(), "{args:?}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("jamchart: "), "{err}");
        for n in *needles {
            assert!(err.contains(n), "{args:?}: {err} lacks {n}");
        }
    }
}

#[test]
fn help_names_units_and_defaults() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(dir.path(), &["vlocator", "--help"]);
    assert_eq!(o.status.code(), Some(0));
    let t = stdout(&o);
    for s in [
        "--flank-angles <A1,A2>",
        "[default: 90 deg]",
        "m/s²",
        "--load-at-rim",
        "blocked",
    ] {
        assert!(t.contains(s), "{s}: {t}");
    }
}

/// The shaft's V-block in one command: a 30 N sideways load over mu 0.12 to 0.3 on the
/// 0.4 kg shaft. It took about 8 runs of trial and error and the tool never said that no single
/// V works; now it says so, names the load the narrowest unlocked V drops and what would open a
/// window (mu_hi <= W / P = 0.1307, or P <= W / mu_hi = 13.07 N).
#[test]
fn robust_v_block_says_no_single_v_works_and_what_opens_it() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "vlocator", "--mu", "0.12:0.3", "--load", "30", "--mass", "0.4",
    ];
    let out = stdout(&jamchart(dir.path(), &args));
    assert!(out.contains("no single V works over this range"), "{out}");
    assert!(out.contains("up to 0.1307"), "{out}");
    assert!(out.contains("loads up to 13.075 N"), "{out}");
    let mut json_args = args.to_vec();
    json_args.extend(["--format", "json"]);
    let v = json(&jamchart(dir.path(), &json_args));
    assert_eq!(v["design"]["windows"].as_array().unwrap().len(), 0);
    let w = 0.4 * 9.806;
    let mu_max = v["design"]["opening"]["mu_hi_max"].as_f64().unwrap();
    assert!((mu_max - w / 30.0).abs() < 1e-9, "{mu_max}");
    for s in v["standard_v_blocks"].as_array().unwrap() {
        assert_eq!(s["verdict"]["status"], "drops");
    }
}

/// A window over a range: its ends are the closed form's, 2 atan mu_hi and 2 atan(W / P) for a
/// sideways load, and the robust angle 2 atan sqrt(mu_hi W / P).
#[test]
fn robust_v_block_window_is_the_closed_forms() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(&jamchart(
        dir.path(),
        &[
            "vlocator", "--mu", "0.12:0.3", "--load", "5", "--format", "json",
        ],
    ));
    let win = &v["design"]["windows"][0];
    let deg = |x: f64| 2.0 * x.atan().to_degrees();
    assert!((win[0].as_f64().unwrap() - deg(0.3)).abs() < 1e-7, "{win}");
    assert!(
        (win[1].as_f64().unwrap() - deg(9.806 / 5.0)).abs() < 1e-7,
        "{win}"
    );
    let r = v["design"]["robust"]["included_angle_deg"]
        .as_f64()
        .unwrap();
    assert!(
        (r - deg((0.3 * 9.806 / 5.0_f64).sqrt())).abs() < 1e-7,
        "{r}"
    );
}

/// Bad ranges exit 2 naming the flag: reversed, a distribution (the robust V-block holds a
/// range, it does not weigh one), a mass range reaching 0, a direction range over 360 deg.
#[test]
fn robust_v_block_refuses_bad_ranges_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    for (args, want) in [
        (vec!["--mu", "0.3:0.12", "--load", "30"], "--mu"),
        (vec!["--mu", "normal(0.2,0.03)", "--load", "30"], "--mu"),
        (vec!["--mu", "0.1:0.2", "--mass", "0:1"], "--mass"),
        (vec!["--mass", "normal(1,0.1)", "--load", "3"], "--mass"),
        (
            vec!["--mu", "0.1:0.2", "--load-angle", "-200:200"],
            "--load-angle",
        ),
    ] {
        let mut all = vec!["vlocator"];
        all.extend(args);
        let out = jamchart(dir.path(), &all);
        assert_eq!(out.status.code(), Some(2), "{all:?}");
        let err = stderr(&out);
        assert!(
            err.starts_with("jamchart: ") && err.contains(want),
            "{all:?}: {err}"
        );
    }
}

/// The help promises ranges on `--mu-left`, `--mu-right` and `--mass`, and each was refused
/// (`--mu 0.2:0.4 --mu-left 0.3` named the flank flag that "broke one friction range"). Each
/// combination is now a box of its own: a flank given as a number keeps it, a flank's range is
/// its own, and the mass ranges too; the JSON box says which.
#[test]
fn robust_v_block_takes_flank_and_mass_ranges() {
    let dir = tempfile::tempdir().unwrap();
    // The arguments, then the box's ends: mu_left, mu_right, mass_kg.
    let cases: [(&[&str], [f64; 6]); 5] = [
        (
            &["--mu", "0.2:0.4", "--mu-left", "0.3"],
            [0.3, 0.3, 0.2, 0.4, 1.0, 1.0],
        ),
        (
            &["--mu", "0.2:0.4", "--mu-right", "0.25"],
            [0.2, 0.4, 0.25, 0.25, 1.0, 1.0],
        ),
        (&["--mu-left", "0.2:0.4"], [0.2, 0.4, 0.3, 0.3, 1.0, 1.0]),
        (
            &["--mu-left", "0.1:0.2", "--mu-right", "0.3:0.5"],
            [0.1, 0.2, 0.3, 0.5, 1.0, 1.0],
        ),
        (
            &["--load", "6:9", "--mass", "0.5:2"],
            [0.3, 0.3, 0.3, 0.3, 0.5, 2.0],
        ),
    ];
    for (args, [l0, l1, r0, r1, m0, m1]) in cases {
        let (left, right, mass) = ((l0, l1), (r0, r1), (m0, m1));
        let mut all = vec!["vlocator", "--format", "json"];
        all.extend(args);
        let v = json(&jamchart(dir.path(), &all));
        let ends = |k: &str| {
            let e = &v["box"][k];
            (e[0].as_f64().unwrap(), e[1].as_f64().unwrap())
        };
        assert_eq!(ends("mu_left"), left, "{args:?}");
        assert_eq!(ends("mu_right"), right, "{args:?}");
        assert_eq!(ends("mass_kg"), mass, "{args:?}");
        // Locking is decided by the smaller of the highs (free rotation): 2 atan min.
        let lock = v["design"]["lock_bound_deg"].as_f64().unwrap();
        let want = 2.0 * left.1.min(right.1).atan().to_degrees();
        assert!((lock - want).abs() < 1e-12, "{args:?}: {lock}");
    }
}

/// The engineer's V-block, charted from a scene file in an empty folder: flank friction 0.1 to
/// 0.25 written as a range (`mu = "0.1:0.25"`; the chart wanted a centre and a width), the
/// 25 mm shaft (0.4 kg) under 20 N sideways. It renders, its data has the range's row with
/// no window (as `vlocator --mu 0.1:0.25 --load 20 --mass 0.4` answers), and the gallery's
/// table lists the range and the load the chart is drawn for.
#[test]
fn a_robust_chart_takes_the_friction_range_as_written() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("vblock.toml"),
        "title = \"My V-block\"\n[chart]\nkind = \"vlocator_robust\"\n\
         locator = { mass_kg = 0.4 }\nmu = \"0.1:0.25\"\nload_n = 20\n",
    )
    .unwrap();
    let r = jamchart(dir.path(), &["render", "vblock.toml", "--out", "out"]);
    assert_eq!(r.status.code(), Some(0), "{}", stderr(&r));
    let out = dir.path().join("out");
    assert!(out.join("vblock.png").is_file());
    let csv = std::fs::read_to_string(out.join("vblock.csv")).unwrap();
    let row = csv
        .lines()
        .find(|l| l.starts_with("0.15,0.1,0.25,"))
        .unwrap_or_else(|| panic!("no row for the range:\n{csv}"));
    let answer = json(&jamchart(
        dir.path(),
        &[
            "vlocator", "--mu", "0.1:0.25", "--load", "20", "--mass", "0.4", "--format", "json",
        ],
    ));
    let design = &answer["design"];
    assert!(design["windows"].as_array().unwrap().is_empty(), "{design}");
    let cells: Vec<&str> = row.split(',').collect();
    let lock: f64 = cells[3].parse().unwrap();
    assert!(
        (lock - design["lock_bound_deg"].as_f64().unwrap()).abs() < 1e-4,
        "{row}"
    );
    assert_eq!(cells[4..], ["", "", "", ""], "no window: {row}");
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(
        html.contains("<code>mu</code></td><td>0.1:0.25</td>"),
        "{html}"
    );
    assert!(
        html.contains("<code>load_n</code></td><td>20</td>"),
        "{html}"
    );
}

/// `vlocator --radius 12.5` (the palm commands' flag) got a bare "unexpected argument": it is
/// refused with the reason, that a V-block's verdict does not depend on the radius.
#[test]
fn a_radius_is_refused_because_the_verdict_does_not_depend_on_it() {
    let dir = tempfile::tempdir().unwrap();
    for flag in ["--radius", "--radius-mm"] {
        let o = jamchart(dir.path(), &["vlocator", flag, "12.5", "--load", "20"]);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        let err = stderr(&o);
        assert!(
            err.contains("a V-block's verdict does not depend on the part's radius"),
            "{err}"
        );
        assert!(stdout(&o).is_empty());
    }
}
