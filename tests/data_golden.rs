//! The data file beside each chart against its golden copy, field by field: every key and
//! string the same, every array as long, every number within a relative 1e-6 (the files round
//! to 7 significant digits, so a last digit that libm rounds the other way on another machine
//! still passes). A map's JSON is compared here (its pictures' bytes are `chart_hashes`'
//! concern); a changed data file fails with the path of each field that moved.
//!
//! When a data file changes on purpose, re-bless the golden copies under `tests/golden/data/`:
//!
//! ```text
//! JAMCHART_BLESS=1 cargo test --release --test integration data_golden
//! ```

use std::path::Path;

use jamchart::charts::{self, Formats};
use serde_json::Value;

/// Relative tolerance of a number.
const REL: f64 = 1e-6;

/// The paths of the fields of `got` that differ from `want`, under `at`.
fn differences(at: &str, want: &Value, got: &Value, out: &mut Vec<String>) {
    match (want, got) {
        (Value::Object(w), Value::Object(g)) => {
            for (k, wv) in w {
                match g.get(k) {
                    Some(gv) => differences(&format!("{at}/{k}"), wv, gv, out),
                    None => out.push(format!("{at}/{k}: missing")),
                }
            }
            for k in g.keys().filter(|k| !w.contains_key(*k)) {
                out.push(format!("{at}/{k}: new"));
            }
        }
        (Value::Array(w), Value::Array(g)) if w.len() == g.len() => {
            for (i, (wv, gv)) in w.iter().zip(g).enumerate() {
                differences(&format!("{at}[{i}]"), wv, gv, out);
            }
        }
        (Value::Array(w), Value::Array(g)) => {
            out.push(format!("{at}: {} items, was {}", g.len(), w.len()))
        }
        (Value::Number(w), Value::Number(g)) => {
            let (w, g) = (w.as_f64().unwrap(), g.as_f64().unwrap());
            if (w - g).abs() > REL * w.abs().max(g.abs()) {
                out.push(format!("{at}: {g}, was {w}"));
            }
        }
        _ if want == got => {}
        _ => out.push(format!("{at}: {got}, was {want}")),
    }
}

#[test]
fn every_json_data_file_matches_its_golden_copy_field_by_field() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = root.join("charts");
    let golden = root.join("tests/golden/data");
    let bless = std::env::var_os("JAMCHART_BLESS").is_some();
    let mut problems = Vec::new();
    let mut compared = 0;
    for name in charts::scene_names(&dir).expect("charts/ lists") {
        let scene = charts::load_scene(&dir, &name).expect("scene loads");
        let r = charts::render(&scene, Formats::Svg).expect("scene renders");
        if r.data.extension != "json" {
            continue;
        }
        let path = golden.join(format!("{name}.json"));
        if bless {
            std::fs::create_dir_all(&golden).expect("the golden folder");
            std::fs::write(&path, &r.data.bytes).expect("the golden copy writes");
            continue;
        }
        let got: Value = serde_json::from_slice(&r.data.bytes).expect("the data file is JSON");
        let want: Value = match std::fs::read(&path) {
            Ok(bytes) => serde_json::from_slice(&bytes).expect("the golden copy is JSON"),
            Err(e) => {
                problems.push(format!("{}: {e}", path.display()));
                continue;
            }
        };
        let mut diff = Vec::new();
        differences(&name, &want, &got, &mut diff);
        problems.extend(diff.into_iter().take(20));
        compared += 1;
    }
    assert!(
        problems.is_empty(),
        "data files changed:\n  {}\nif on purpose, re-bless with JAMCHART_BLESS=1 cargo test \
         --release --test integration data_golden",
        problems.join("\n  ")
    );
    assert!(
        bless || compared >= 6,
        "only {compared} JSON data files compared"
    );
}

#[test]
fn the_comparison_sees_what_it_must() {
    let v = |s: &str| -> Value { serde_json::from_str(s).unwrap() };
    let diff = |a: &str, b: &str| {
        let mut out = Vec::new();
        differences("d", &v(a), &v(b), &mut out);
        out
    };
    assert!(diff(r#"{"x": 1.0, "s": "a"}"#, r#"{"x": 1.0000001, "s": "a"}"#).is_empty());
    assert_eq!(
        diff(r#"{"x": 1.0}"#, r#"{"x": 1.001}"#),
        ["d/x: 1.001, was 1"]
    );
    assert_eq!(
        diff(r#"{"s": "a"}"#, r#"{"s": "b"}"#),
        [r#"d/s: "b", was "a""#]
    );
    assert_eq!(diff(r#"[1, 2]"#, r#"[1]"#), ["d: 1 items, was 2"]);
    assert_eq!(
        diff(r#"{"a": 1}"#, r#"{"b": 1}"#),
        ["d/a: missing", "d/b: new"]
    );
    assert_eq!(
        diff(r#"{"a": null}"#, r#"{"a": 0.0}"#),
        ["d/a: 0.0, was null"]
    );
}
