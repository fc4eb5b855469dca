//! The gallery's read-off of the charts that had none: the time series (fig5), the
//! min-norm program's trace (fig4), the integrators' work-precision chart (integration-error)
//! and the stability matrix, in headless Chromium and Firefox, checked against each chart's
//! own data file and against `jamchart solve` for the same inputs. Screenshots are saved under
//! `target/tmp/gallery_browser/` to look at. See `gallery_browser.rs` for the browsers and
//! what happens without them.

use crate::common::browser;
use crate::common::cli as cli_util;
use crate::common::gallery;

use std::collections::BTreeMap;

use browser::Kind;
use cli_util::{jamchart, json};
use gallery::{assert_read_off_drawn, assert_row, csv_rows, gallery_of, num, pins};
use serde_json::Value;

/// A CSV cell as a number.
fn cell(row: &BTreeMap<String, String>, key: &str) -> f64 {
    row[key]
        .parse()
        .unwrap_or_else(|e| panic!("{key} = {:?}: {e}", row[key]))
}

/// Relative difference of `got` from `want`.
fn rel(got: f64, want: f64) -> f64 {
    ((got - want) / want).abs()
}

in_chromium_and_firefox!(
    /// Regression: fig5 (disc speed and position against time, the jam marked), fig4 (the
    /// min-norm program's iterations), the work-precision chart and the stability matrix were
    /// plain pictures in the gallery. In Chromium and Firefox: fig5 read at a sample gives its
    /// CSV row (speed, position, palm angle, the rigid disc's) to the embedded 7 digits and
    /// between samples the straight line between them, with the jam as `jamchart solve --model
    /// dynamics` gives it; fig4 and the work-precision chart read at each drawn point give that
    /// point's CSV row, cell for cell; the matrix read at a cell, and clicked inside one, gives
    /// that cell's row of its JSON (case, method, status, x_jam, class).
    the_gallery_reads_the_time_series_and_study_charts_off_in_chromium,
    the_gallery_reads_the_time_series_and_study_charts_off_in_firefox,
    reads_the_time_series_and_study_charts_off
);

/// The checks of the test above in the browser of `kind`.
fn reads_the_time_series_and_study_charts_off(kind: Kind) {
    let scenes = ["fig4", "fig5", "integration-error", "stability-matrix"];
    let Some((browser, dir, out)) = gallery_of(kind, &scenes) else {
        return;
    };
    let page = out.join("index.html");
    let url = |hash: &str| format!("file://{}#{hash}", page.display());

    // fig5: at t = 1 s (a sample), between two samples, and on the position panel.
    let series = csv_rows(&out.join("fig5.csv"));
    let (t_on, t_between) = (1.0, 1.2345);
    let k = series
        .iter()
        .position(|r| cell(r, "t_s") >= t_between)
        .unwrap();
    let (a, b) = (&series[k - 1], &series[k]);
    let w = (t_between - cell(a, "t_s")) / (cell(b, "t_s") - cell(a, "t_s"));
    let straight = |key: &str| cell(a, key) + w * (cell(b, key) - cell(a, key));
    let at_one = series.iter().find(|r| cell(r, "t_s") == t_on).unwrap();
    let hook = format!(
        "readoff=fig5@0:{t_on};fig5@1:{t_between};fig4@0:2:40000;fig4@1:3:1e-6&\
         click=stability-matrix:4.3:-3.4"
    );
    let dom = browser.dom(&url(&hook), None);
    assert!(
        dom.contains("data-readoff=\"done\""),
        "the hook did not run"
    );
    let fig5 = pins(&dom, "fig5");
    assert_eq!(fig5.len(), 2, "{fig5:?}");
    let mut worst: f64 = 0.0;
    let on_sample = |key: &str| cell(at_one, key);
    let wants: [&dyn Fn(&str) -> f64; 2] = [&on_sample, &straight];
    for (pin, want) in fig5.iter().zip(wants) {
        let curves = pin["curves"].as_array().unwrap();
        for (curve, keys) in curves.iter().zip([
            &["x_dot_mm_s", "x_mm", "theta_deg"][..],
            &["geometric_speed_mm_s", "touching_x_mm"][..],
        ]) {
            for key in keys {
                let err = rel(num(curve, key), want(key));
                worst = worst.max(err);
                assert!(err < 2e-6, "{key} at t {}: {curve}", num(pin, "t_s"));
            }
        }
    }
    eprintln!("fig5 against its CSV: worst relative error {worst:.1e}");
    let solve = json(&jamchart(
        dir.path(),
        &["solve", "--model", "dynamics", "--format", "json"],
    ));
    let r = &solve["results"][0];
    for key in ["t_jam_s", "x_jam_mm", "theta_jam_deg"] {
        let (got, want) = (num(&fig5[0], key), num(r, key));
        eprintln!("fig5 {key}: {got} (solve {want})");
        assert!(rel(got, want) < 1e-6, "{key}: {}", fig5[0]);
    }
    assert_eq!(fig5[0]["status"], r["status"]);

    // fig4: the point nearest the pointer, iteration 2's objective and iteration 3's primal
    // or dual residual (both 1e-6 there), with its whole row.
    let trace = csv_rows(&out.join("fig4.csv"));
    let fig4 = pins(&dom, "fig4");
    assert_eq!(fig4.len(), 2, "{fig4:?}");
    assert_row(&fig4[0], &trace[2]);
    assert_row(&fig4[1], &trace[3]);

    // The matrix: a real click inside the cell of method 4 (dopri5), case 3 (contact_1um).
    let matrix: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("stability-matrix.json")).unwrap())
            .unwrap();
    let methods = matrix["methods"].as_array().unwrap().len();
    let clicked = pins(&dom, "stability-matrix");
    assert_eq!(clicked.len(), 1, "the click pinned nothing");
    assert_eq!(num(&clicked[0], "row") as usize, 3 * methods + 4);

    // The work-precision chart at every drawn point, and the matrix at every cell.
    let study = csv_rows(&out.join("integration-error.csv"));
    let mut hook = Vec::new();
    let mut wanted = Vec::new();
    for r in &study {
        let (x, y, p) = match r["study"].as_str() {
            "integrator" if !r["rel_error"].is_empty() => ("rhs_evals", "rel_error", 0),
            "min_norm" if !r["error_deg"].is_empty() => ("tol", "error_deg", 1),
            _ => continue,
        };
        hook.push(format!("integration-error@{p}:{}:{}", r[x], r[y]));
        wanted.push(r);
    }
    let cases = matrix["cases"].as_array().unwrap().len();
    for i in 0..cases {
        for j in 0..methods {
            hook.push(format!("stability-matrix:{j}:-{i}"));
        }
    }
    let dom = browser.dom(&url(&format!("readoff={}", hook.join(";"))), None);
    let read = pins(&dom, "integration-error");
    assert_eq!(read.len(), wanted.len(), "{read:?}");
    for (pin, row) in read.iter().zip(&wanted) {
        assert_row(pin, row);
    }
    eprintln!(
        "integration-error: {} points read as their CSV rows",
        read.len()
    );
    let cells = pins(&dom, "stability-matrix");
    let rows = matrix["rows"].as_array().unwrap();
    assert_eq!(cells.len(), rows.len(), "one read per cell");
    for (k, (pin, row)) in cells.iter().zip(rows).enumerate() {
        assert_eq!(num(pin, "row") as usize, k, "{pin}");
        for key in ["case", "model", "method", "status", "class", "reason"] {
            assert_eq!(pin[key], row[key], "{key} of cell {k}: {pin}");
        }
        for key in ["x_jam_mm", "reference.x_jam_mm"] {
            let want = key.split('.').fold(row, |v, part| &v[part]);
            match (pin[key].as_f64(), want.as_f64()) {
                (Some(got), Some(want)) => assert!(rel(got, want) < 1e-6 || got == want, "{pin}"),
                (got, want) => assert_eq!(got, want, "{key} of cell {k}: {pin}"),
            }
        }
    }
    eprintln!(
        "stability-matrix: {} cells read as their JSON rows",
        cells.len()
    );

    // Screenshots to look at, with the read-off drawn: fig5 (crosshair at the point read)
    // and the matrix (a ring on the cell read), desktop and phone. Each chart alone in its
    // gallery, at the top of the page: headless Chromium's screenshot of a page scrolled by
    // script is blank.
    for (scene, hook) in [
        ("fig5", "readoff=fig5@1:1.2"),
        ("stability-matrix", "readoff=stability-matrix:4:-3"),
    ] {
        let (browser, _dir, out) = gallery_of(kind, &[scene]).unwrap();
        assert_read_off_drawn(&browser, &out.join("index.html"), hook, scene);
    }
}
