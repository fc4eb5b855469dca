//! The V-block at the edges of the float range: a tolerance summed over forces of 9e307 N
//! overflowed to inf, so `vlocator --load 9e307` printed "held on both flanks" beside "no
//! equilibrium", and `--load 10:1e308` called the 60 deg V-block "works". And a load that
//! cancels the weight was `held`, though nothing presses the disc into the V.

use serde_json::Value;

use super::cli_util::json;
use super::run;

fn vlocator(args: &[&str]) -> Value {
    let dir = tempfile::tempdir().unwrap();
    let mut all = vec!["vlocator", "--format", "json"];
    all.extend(args);
    json(&run(dir.path(), &all))
}

#[test]
fn a_sideways_load_at_the_top_of_the_float_range_slips() {
    for load in ["9e307", "1.7e308", "1e300"] {
        let v = vlocator(&["--load", load]);
        assert_eq!(v["verdict"], "slips", "{load}: {v}");
        assert!(v["forces"].is_null(), "{load}");
    }
    // Pressed into the V it is held, and its forces scale with it: the same ratio to the load
    // as at 10 N, to 1e-9.
    let ratio = |load: &str| {
        let v = vlocator(&["--load", load, "--load-angle", "-80", "--mass", "1e-300"]);
        assert_eq!(v["verdict"], "held", "{load}: {v}");
        v["forces"][0]["normal_n"].as_f64().unwrap() / load.parse::<f64>().unwrap()
    };
    let at_10 = ratio("10");
    for load in ["9e307", "1e-200"] {
        let r = ratio(load);
        assert!(
            (r / at_10 - 1.0).abs() < 1e-9,
            "{load}: {r} against {at_10}"
        );
    }
}

#[test]
fn a_load_range_to_the_top_of_the_float_range_drops_from_every_standard_v() {
    let v = vlocator(&["--load", "10:1e308"]);
    for s in v["standard_v_blocks"].as_array().unwrap() {
        assert_eq!(s["verdict"]["status"], "drops", "{s}");
    }
    assert_eq!(v["design"]["windows"].as_array().unwrap().len(), 0);
    // What opens it is the point capacity of the narrowest V that does not lock: W / 0.3.
    let l = v["design"]["opening"]["load_hi_max_n"].as_f64().unwrap();
    assert!((l - 9.806 / 0.3).abs() < 1e-9 * l, "{l}");
}

#[test]
fn a_load_that_cancels_the_weight_is_unloaded_not_held() {
    let v = vlocator(&["--load", "9.806", "--load-angle", "90"]);
    assert_eq!(v["verdict"], "unloaded", "{v}");
    for f in v["forces"].as_array().unwrap() {
        assert_eq!(f["normal_n"].as_f64(), Some(0.0), "{f}");
    }
}
