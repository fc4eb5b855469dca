//! One name per quantity across text, JSON and CSV: the F -> infinity limit was "unlimited
//! push" in text, `x_rigid_mm` in JSON and a `rigid_limit` layer in CSV; the table's CSV and
//! JSON were written by separate code. These tests read what the binary writes.

#[path = "common/cli.rs"]
mod cli_util;
use cli_util::{jamchart, json, stderr, stdout};

/// The quantities of a jam, with their unit suffix as in JSON keys and CSV headers.
const QUANTITIES: [&str; 4] = ["theta_jam_deg", "x_jam_mm", "theta_rigid_deg", "x_rigid_mm"];

/// `x_jam_mm` -> `x_jam`: the name the text prints before " = value unit".
fn stem(key: &str) -> &str {
    key.rsplit_once('_').map_or(key, |(s, _)| s)
}

#[test]
fn solve_text_prints_each_json_quantity_under_its_name() {
    let dir = tempfile::tempdir().unwrap();
    let doc = json(&jamchart(dir.path(), &["solve", "--format", "json"]));
    let statics = &doc["results"][0];
    let text = stdout(&jamchart(dir.path(), &["solve"]));
    for key in QUANTITIES {
        let v = statics[key]
            .as_f64()
            .unwrap_or_else(|| panic!("JSON lacks {key}: {statics}"));
        let printed = format!("{} ", stem(key));
        assert!(text.contains(&printed), "text lacks {printed:?}: {text}");
        assert!(
            text.contains(&format!("{v:.3}")),
            "text lacks {key} = {v:.3}: {text}"
        );
    }
}

#[test]
fn table_csv_header_is_the_json_keys() {
    let dir = tempfile::tempdir().unwrap();
    let csv = stdout(&jamchart(dir.path(), &["table", "--format", "csv"]));
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let rows = json(&jamchart(dir.path(), &["table", "--format", "json"]));
    let keys: Vec<&str> = rows[0]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    assert_eq!(header, keys);
}

/// The chart data names its columns as JSON does: a sweep's CSV and a map's long CSV use the
/// quantities' JSON keys; a map's JSON lists the CSV's columns and summarises each quantity
/// under its column name, and names its iso-lines the same way.
#[test]
fn chart_csv_columns_are_json_names() {
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(dir.path(), &["render", "fig7b", "fig7c", "--format", "svg"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let header = |name: &str| -> Vec<String> {
        let text = std::fs::read_to_string(dir.path().join("out").join(name)).unwrap();
        text.lines()
            .next()
            .unwrap()
            .split(',')
            .map(String::from)
            .collect()
    };
    let sweep = header("fig7b.csv");
    assert!(
        sweep.ends_with(&["x_jam_mm".into(), "theta_jam_deg".into()]),
        "{sweep:?}"
    );
    let map = header("fig7c.csv");
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("out/fig7c.json")).unwrap())
            .unwrap();
    let axes = [&doc["x_axis"]["param"], &doc["y_axis"]["param"]];
    assert_eq!(map[..2], axes.map(|a| a.as_str().unwrap().to_string()));
    let cells = &doc["cells"];
    assert_eq!(cells["file"], "fig7c.csv");
    let listed: Vec<&str> = cells["columns"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    assert_eq!(
        listed, map,
        "fig7c.json lists other columns than fig7c.csv has"
    );
    for column in &map[2..] {
        assert!(
            cells["summary"].get(column).is_some(),
            "{column} is not summarised in fig7c.json"
        );
        assert!(
            doc["iso_lines"].get(column).is_some(),
            "fig7c.json has no iso-lines named {column}"
        );
        assert!(
            !column.is_empty()
                && QUANTITIES
                    .iter()
                    .chain(&["x_gap_to_rigid_limit_pct"])
                    .any(|q| q == column),
            "{column}"
        );
    }
}
