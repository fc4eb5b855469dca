//! The gallery page that `jamchart accuracy --out-dir` writes: its error-time chart read off
//! in headless Chromium and Firefox, checked against `accuracy.csv` cell for cell. Screenshots
//! are saved under `target/tmp/gallery_browser/` to look at. See `gallery_browser.rs` for the
//! browsers and what happens without them.

use crate::common::browser;
use crate::common::cli as cli_util;
use crate::common::gallery;

use std::collections::BTreeMap;

use browser::Kind;
use cli_util::jamchart;
use gallery::{assert_read_off_drawn, assert_row, csv_rows, pins};

/// A cell as a positive number (drawn on a log axis), or None.
fn positive(row: &BTreeMap<String, String>, key: &str) -> Option<f64> {
    row[key].parse::<f64>().ok().filter(|v| *v > 0.0)
}

/// The report's drawn points per panel as (row index, x, y) from its CSV: the error panel
/// (0) plots each non-statics row's relative error, the integration panel (1) each
/// integration error, against the median wall time; zero or missing values are not drawn.
fn drawn(rows: &[BTreeMap<String, String>]) -> [Vec<(usize, f64, f64)>; 2] {
    let on = |key: &str| -> Vec<(usize, f64, f64)> {
        (rows.iter().enumerate())
            .filter(|(_, r)| r["model"] != "statics")
            .filter_map(|(i, r)| Some((i, positive(r, "median_time_s")?, positive(r, key)?)))
            .collect()
    };
    [on("x_rel_error"), on("integration_error_mm")]
}

/// The point of `points` farthest from its nearest neighbour (log-log): a click on it cannot
/// land nearer another.
fn loneliest(points: &[(usize, f64, f64)]) -> (usize, f64, f64) {
    let d = |a: &(usize, f64, f64), b: &(usize, f64, f64)| {
        (a.1 / b.1).log10().powi(2) + (a.2 / b.2).log10().powi(2)
    };
    let gap = |a: &(usize, f64, f64)| {
        (points.iter().filter(|b| b.0 != a.0))
            .map(|b| d(a, b))
            .fold(f64::INFINITY, f64::min)
    };
    *points
        .iter()
        .max_by(|a, b| gap(a).total_cmp(&gap(b)))
        .unwrap()
}

in_chromium_and_firefox!(
    /// `jamchart accuracy --out-dir` wrote its error-time chart with no gallery page: finding
    /// the error and time of a point meant finding its row in accuracy.csv by hand. In
    /// Chromium and Firefox, its index.html reads every third drawn point of both panels (and
    /// a real click on one point of each) as that point's row of accuracy.csv, every cell to
    /// the file's digits; the screenshots with a read-off show its crosshair.
    the_accuracy_page_reads_its_points_off_as_csv_rows_in_chromium,
    the_accuracy_page_reads_its_points_off_as_csv_rows_in_firefox,
    reads_the_accuracy_chart_off
);

/// The checks of the test above in the browser of `kind`.
fn reads_the_accuracy_chart_off(kind: Kind) {
    let Some(browser) = browser::find(kind) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "accuracy",
        "--runs",
        "1",
        "--map-cells",
        "0",
        "--out-dir",
        "out",
    ];
    let r = jamchart(dir.path(), &args);
    assert_eq!(r.status.code(), Some(0), "{}", cli_util::stderr(&r));
    let out = dir.path().join("out");
    let rows = csv_rows(&out.join("accuracy.csv"));
    let page = out.join("index.html");
    let url = |hash: &str| format!("file://{}#{hash}", page.display());

    let panels = drawn(&rows);
    let mut hook = Vec::new();
    let mut wanted = Vec::new();
    for (p, points) in panels.iter().enumerate() {
        assert!(points.len() >= 3, "panel {p} draws {} points", points.len());
        for &(i, t, y) in points.iter().step_by(3) {
            hook.push(format!("accuracy@{p}:{}:{}", rows[i]["median_time_s"], y));
            wanted.push((p, i));
            assert_eq!(t.to_string().parse::<f64>().unwrap(), t);
        }
    }
    let clicks: Vec<(usize, usize)> = (panels.iter().enumerate())
        .map(|(p, points)| (p, loneliest(points).0))
        .collect();
    let click = (clicks.iter())
        .map(|&(p, i)| {
            let y = ["x_rel_error", "integration_error_mm"][p];
            format!("accuracy@{p}:{}:{}", rows[i]["median_time_s"], rows[i][y])
        })
        .collect::<Vec<_>>();
    let dom = browser.dom(
        &url(&format!(
            "readoff={}&click={}",
            hook.join(";"),
            click.join(";")
        )),
        None,
    );
    assert!(
        dom.contains("data-readoff=\"done\""),
        "the hook did not run"
    );
    let read = pins(&dom, "accuracy");
    assert_eq!(read.len(), wanted.len() + clicks.len(), "{read:?}");
    for (pin, (p, i)) in read.iter().zip(wanted.iter().chain(&clicks)) {
        assert_eq!(pin["panel"], *p, "{pin}");
        assert_eq!(pin["row"], *i, "{pin}");
        assert_row(pin, &rows[*i]);
    }
    eprintln!(
        "accuracy: {} points read and {} clicked, each as its row of accuracy.csv",
        wanted.len(),
        clicks.len()
    );

    // Screenshots to look at, with a point of the integration panel read, desktop and phone.
    let (_, t, y) = loneliest(&panels[1]);
    assert_read_off_drawn(
        &browser,
        &page,
        &format!("readoff=accuracy@1:{t}:{y}"),
        "accuracy",
    );
}
