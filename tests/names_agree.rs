//! One name per quantity across text, JSON and CSV: the F -> infinity limit was "unlimited
//! push" in text, `x_rigid_mm` in the statics' JSON, `x_wedge_mm` in the dynamics', a
//! `rigid_limit` layer in CSV and reference in the accuracy table, and `x_rigid_mm` also named
//! the rigid contact's jam in a cross-check; the table's CSV and JSON were written by separate
//! code. These tests read what the binary writes.

use crate::common::cli as cli_util;
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
    // The jam past the palm's end is the range record's `past_palm.x_jam_mm`.
    assert!(
        sweep.ends_with(&[
            "x_jam_mm".into(),
            "theta_jam_deg".into(),
            "past_palm_x_jam_mm".into()
        ]),
        "{sweep:?}"
    );
    let map = header("fig7c.csv");
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("out/fig7c.json")).unwrap())
            .unwrap();
    let axes = [&doc["x_axis"]["param"], &doc["y_axis"]["param"]];
    assert_eq!(map[..2], axes.map(|a| a.as_str().unwrap().to_string()));
    let cells = &doc["cells"];
    assert_eq!(doc["cells_file"], "fig7c.csv");
    let listed = listed_columns(cells);
    assert_eq!(
        listed, map,
        "fig7c.json lists other columns than fig7c.csv has"
    );
    // The status says why a cell has no x_jam (the blank's legend): a word per cell, with
    // no iso-lines; its name is the sweep's and the solve record's.
    assert_eq!(map[2], "status", "{map:?}");
    assert!(sweep.contains(&"status".to_string()), "{sweep:?}");
    for column in &map[2..] {
        assert!(
            cells["summary"].get(column).is_some(),
            "{column} is not summarised in fig7c.json"
        );
        if column == "status" {
            continue;
        }
        assert!(
            doc["iso_lines"].get(column).is_some(),
            "fig7c.json has no iso-lines named {column}"
        );
        assert!(
            !column.is_empty()
                && QUANTITIES
                    .iter()
                    .chain(&["gap_to_x_rigid_pct"])
                    .any(|q| q == column),
            "{column}"
        );
    }
}

/// Every JSON key anywhere in `v`.
fn keys(v: &serde_json::Value, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Object(m) => m.iter().for_each(|(k, v)| {
            out.push(k.clone());
            keys(v, out)
        }),
        serde_json::Value::Array(a) => a.iter().for_each(|v| keys(v, out)),
        _ => {}
    }
}

/// The words of `text` (runs of ASCII letters, digits and `_`) that contain `part`.
fn words_with<'a>(text: &'a str, part: &str) -> Vec<&'a str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| w.contains(part))
        .collect()
}

/// Regression ("one quantity has four names"): the rigid limit
/// x_rigid = r cot((alpha_g + alpha_p) / 2), the jam as F -> infinity, is `x_rigid_mm` / `theta_rigid_deg` in every JSON
/// (statics and dynamics records), `x_rigid` in text, `rigid` as a sweep layer and as the
/// accuracy table's reference, and `gap_to_x_rigid_pct` on a map; the rigid contact's jam is
/// `x_jam_rigid_mm` everywhere. Any other name with "rigid" or "wedge" in data fails here.
#[test]
fn the_rigid_limit_has_one_name_everywhere() {
    const NAMES: [&str; 7] = [
        "x_rigid_mm",
        "theta_rigid_deg",
        "x_rigid",
        "theta_rigid",
        "rigid",
        "x_jam_rigid_mm",
        "gap_to_x_rigid_pct",
    ];
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let all = json(&jamchart(
        d,
        &["solve", "--model", "all", "--format", "json"],
    ));
    let text = stdout(&jamchart(d, &["solve", "--model", "all"]));
    let out = jamchart(d, &["render", "fig7b", "fig7c", "--format", "svg"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let read = |name: &str| std::fs::read_to_string(d.join("out").join(name)).unwrap();
    let accuracy = jamchart(
        d,
        &[
            "accuracy",
            "--runs",
            "1",
            "--map-cells",
            "0",
            "--tolerances",
            "1e-4",
            "--min-norm-tolerances",
            "1e-8",
            "--format",
            "csv",
        ],
    );
    assert!(accuracy.status.success(), "{}", stderr(&accuracy));

    // Names in data: JSON keys, CSV headers, the sweep's layers and the references.
    let mut names = Vec::new();
    keys(&all, &mut names);
    let fig7c: serde_json::Value = serde_json::from_str(&read("fig7c.json")).unwrap();
    keys(&fig7c, &mut names);
    for csv in [read("fig7b.csv"), read("fig7c.csv"), stdout(&accuracy)] {
        names.extend(csv.lines().next().unwrap().split(',').map(String::from));
        // First and ninth columns: the sweep's layer, the accuracy table's reference.
        for line in csv.lines().skip(1) {
            let fields: Vec<&str> = line.split(',').collect();
            names.extend([fields[0], fields.get(8).copied().unwrap_or("")].map(String::from));
        }
    }
    for n in &names {
        for w in words_with(n, "rigid")
            .into_iter()
            .chain(words_with(n, "wedge"))
        {
            assert!(
                NAMES.contains(&w),
                "{w:?} names the rigid limit or contact anew"
            );
        }
    }
    assert!(
        names.iter().any(|n| n == "rigid"),
        "no layer or reference named rigid"
    );

    // Text: the same name, no other.
    for bad in ["unlimited push", "x_wedge", "rigid_limit"] {
        assert!(!text.contains(bad), "text says {bad:?}: {text}");
    }
    assert!(text.contains("x_rigid "), "{text}");

    // The statics and dynamics records give the same x_rigid_mm.
    let results = all["results"].as_array().unwrap();
    let x_rigid: Vec<f64> = results
        .iter()
        .filter_map(|r| r["x_rigid_mm"].as_f64())
        .collect();
    assert!(
        x_rigid.len() >= 2,
        "statics and dynamics both carry x_rigid_mm: {all}"
    );
    assert!(
        x_rigid
            .iter()
            .all(|x| (x - x_rigid[0]).abs() <= 1e-9 * x_rigid[0]),
        "{x_rigid:?}"
    );
}

/// The columns a map's JSON says its cells CSV has.
fn listed_columns(cells: &serde_json::Value) -> Vec<&str> {
    let columns = cells["columns"].as_array().unwrap();
    columns.iter().map(|c| c.as_str().unwrap()).collect()
}

/// The longest array anywhere in `v`.
fn longest_array(v: &serde_json::Value) -> usize {
    match v {
        serde_json::Value::Array(a) => a.iter().map(longest_array).max().unwrap_or(0).max(a.len()),
        serde_json::Value::Object(o) => o.values().map(longest_array).max().unwrap_or(0),
        _ => 0,
    }
}

/// Every map writes its cells once, as long CSV (one row per cell, the columns its JSON lists),
/// and its JSON does not repeat the grid. Regression: vlocator-capacity.json held a
/// flat `iy * nx + ix` grid of 115,239 numbers and had no CSV.
#[test]
fn every_map_writes_its_cells_as_long_csv_listed_in_its_json() {
    let dir = tempfile::tempdir().unwrap();
    let maps = ["fig3", "fig7c", "vlocator-capacity"];
    let mut args = vec!["render", "--format", "svg"];
    args.extend(maps);
    let out = jamchart(dir.path(), &args);
    assert!(out.status.success(), "{}", stderr(&out));
    for name in maps {
        let read = |ext: &str| {
            std::fs::read_to_string(dir.path().join("out").join(format!("{name}.{ext}"))).unwrap()
        };
        let doc: serde_json::Value = serde_json::from_str(&read("json")).unwrap();
        let csv = read("csv");
        let cells = &doc["cells"];
        assert_eq!(doc["cells_file"], format!("{name}.csv"));
        let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
        assert_eq!(listed_columns(cells), header, "{name}");
        let (nx, ny) = (cells["nx"].as_u64().unwrap(), cells["ny"].as_u64().unwrap());
        assert_eq!(csv.lines().count() as u64, 1 + nx * ny, "{name}");
        let longest = longest_array(&doc);
        assert!(
            longest < (nx * ny / 4) as usize,
            "{name}.json has an array of {longest}"
        );
    }
}
