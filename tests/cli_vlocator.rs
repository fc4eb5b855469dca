//! `jamchart vlocator` run as a user would: text, JSON keys, and bad input.

#[path = "common/cli.rs"]
mod cli_util;
use cli_util::{jamchart, json, stderr, stdout};

#[test]
fn json_has_the_issue_keys_and_per_flank_forces() {
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
