//! The two reports, `accuracy` and `stability`, run as the real binary in a temp dir.

use serde_json::Value;

use crate::common::cli as cli_util;
use cli_util::{jamchart, stderr, stdout};

/// Regression: the built-in scenes of the integrators' work-precision chart and of
/// the stability matrix were named `accuracy` and `stability`, so `render` wrote an
/// accuracy.csv and a stability.json of other schemas than the reports' files of those names.
fn no_scene_writes_a_file_of(dir: &std::path::Path, report_dir: &str) {
    let scenes = stdout(&jamchart(dir, &["scenes"]));
    for entry in std::fs::read_dir(dir.join(report_dir)).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        let stem = name.split('.').next().unwrap();
        assert!(
            !scenes
                .lines()
                .any(|l| l.split_whitespace().next() == Some(stem)),
            "a scene writes {stem}.* too:\n{scenes}"
        );
    }
}

/// A small accuracy run writes its table, CSV, JSON, map CSV and wall-time chart; the CSV has
/// one header and one row per source, every row through the port against its reference.
#[test]
fn accuracy_writes_every_output_with_one_schema() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &[
            "accuracy",
            "--drive",
            "force",
            "--methods",
            "radau5",
            "--tolerances",
            "1e-3,1e-5",
            "--penetrations",
            "none",
            "--nonsmooth-steps",
            "0.1",
            "--runs",
            "1",
            "--converged-rtol",
            "1e-9",
            "--min-norm-tolerances",
            "1e-3,1e-8",
            "--map-cells",
            "6",
            "--format",
            "csv",
            "--out-dir",
            "acc",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = stdout(&o);
    let header = csv.lines().next().unwrap();
    assert!(
        header.starts_with(
            "model,method,tolerance,penetration_um,step_deg,status,theta_jam_deg,x_jam_mm,"
        ),
        "{header}"
    );
    // statics, exact, 2 clarabel, 2 radau5, 1 nonsmooth.
    assert_eq!(csv.lines().count(), 1 + 7, "{csv}");
    for name in [
        "accuracy.md",
        "accuracy.csv",
        "accuracy.json",
        "accuracy_map.csv",
        "accuracy.svg",
        "accuracy.png",
    ] {
        assert!(dir.path().join("acc").join(name).is_file(), "{name}");
    }
    no_scene_writes_a_file_of(dir.path(), "acc");
    let json: Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("acc/accuracy.json")).unwrap(),
    )
    .unwrap();
    let rows = json["accuracy"]["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 7);
    for r in rows {
        assert!(r["median_time_s"].as_f64().unwrap() > 0.0, "{r}");
        // A force drive's simulations are judged by the converged rigid dynamics (the
        // closed form lacks the disc's coast), the quasi-static models by the closed form at F.
        let want = if r["model"] == "dynamics" {
            "rigid_dynamics"
        } else {
            "closed_form"
        };
        assert_eq!(r["reference"], want, "{r}");
    }
    // clarabel at 1e-8 meets the closed form to 1e-6 relative.
    let clarabel = &rows[3];
    assert_eq!(clarabel["method"], "clarabel");
    assert!(
        clarabel["x_rel_error"].as_f64().unwrap() < 1e-6,
        "{clarabel}"
    );
    // The force-driven simulation: within 1 % of the rigid dynamics (the contact's give), its
    // integration error far smaller.
    let sim = &rows[5];
    assert!(sim["x_rel_error"].as_f64().unwrap() < 1e-2, "{sim}");
    assert!(
        sim["integration_error_mm"].as_f64().unwrap() < 1e-3,
        "{sim}"
    );
    let map = json["map_cost"]["rows"].as_array().unwrap();
    assert_eq!(map.len(), 5);
    let md = std::fs::read_to_string(dir.path().join("acc/accuracy.md")).unwrap();
    assert!(md.contains("## Floors of the simulation"), "{md}");
    assert!(md.contains("A 6 x 6 map"), "{md}");
}

/// The accuracy report opened with its tables and references, leaving the reader to work out
/// what to design to. Its first paragraph now says it in one line, from the numbers computed:
/// the closed form's x_jam and theta_jam (as its reference line gives them) and the rigid limit
/// of the motion-driven palm, for two frictions.
#[test]
fn accuracy_opens_with_what_to_design_to() {
    let dir = tempfile::tempdir().unwrap();
    for mu in ["0.4", "0.3"] {
        let o = jamchart(
            dir.path(),
            &[
                "accuracy",
                "--mu",
                mu,
                "--methods",
                "radau5",
                "--tolerances",
                "1e-3",
                "--penetrations",
                "none",
                "--nonsmooth-steps",
                "none",
                "--min-norm-tolerances",
                "none",
                "--runs",
                "1",
                "--map-cells",
                "0",
                "--quiet",
            ],
        );
        assert!(o.status.success(), "{}", stderr(&o));
        let md = stdout(&o);
        let mut paragraphs = md.split("\n\n");
        assert!(paragraphs.next().unwrap().starts_with("# "), "{md}");
        let summary = paragraphs.next().unwrap();
        assert!(!summary.contains('\n'), "one line: {summary}");
        // The references as the report lists them, rounded as the summary gives them.
        let reference = |kind: &str, key: &str| -> f64 {
            let line = md
                .lines()
                .find(|l| l.starts_with(&format!("- reference {kind}:")))
                .unwrap();
            let at = line.find(key).unwrap() + key.len();
            line[at..]
                .split_whitespace()
                .next()
                .unwrap()
                .parse()
                .unwrap()
        };
        let x = reference("closed_form", "x_jam = ");
        let theta = reference("closed_form", "theta_jam = ");
        let rigid = reference("rigid", "x_jam = ");
        for said in [
            format!("Design to x_jam = {x:.3} mm (theta_jam = {theta:.3} deg)"),
            format!("or to {rigid:.3} mm, the rigid limit"),
        ] {
            assert!(summary.contains(&said), "{said}: {summary}");
        }
        assert!(summary.contains("the simulation comes within"), "{summary}");
        assert!(md.find(summary).unwrap() < md.find("| model |").unwrap());
    }
}

#[test]
fn accuracy_refuses_bad_flags_before_computing() {
    let dir = tempfile::tempdir().unwrap();
    for (args, named) in [
        (
            vec!["--tolerances", "1e-3,2"],
            "tolerances = 2 (flag --tolerances)",
        ),
        (
            vec!["--converged-rtol", "0"],
            "converged_rtol = 0 (flag --converged-rtol)",
        ),
        (vec!["--runs", "1001"], "runs = 1001 (flag --runs)"),
        (
            vec!["--min-norm-tolerances", "1e-3,abc"],
            "min_norm_tolerances = abc (flag --min-norm-tolerances)",
        ),
        (
            vec!["--penetrations", "0"],
            "penetrations_um = 0 (flag --penetrations)",
        ),
        (
            vec!["--map-cells", "3000"],
            "cells_per_axis = 3000 (flag --map-cells)",
        ),
    ] {
        let mut all = vec!["accuracy", "--out-dir", "never"];
        all.extend(args.iter().copied());
        let o = jamchart(dir.path(), &all);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(named), "{args:?}: {}", stderr(&o));
        // Refused before anything ran or was written.
        assert!(!dir.path().join("never").exists(), "{args:?}");
    }
}

/// A few cases of the stability matrix through every method: the table's classes, the CSV's
/// schema, the time it took, and an unknown case named with the list of cases.
#[test]
fn stability_runs_the_named_cases_and_refuses_an_unknown_one() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &[
            "stability",
            "--cases",
            "paper,contact_0.01um,frictionless",
            "--format",
            "json",
            "--out-dir",
            "st",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("stability matrix of 3 cases x 6 methods took"));
    let doc: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let rows = doc["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 18);
    assert!(
        rows.iter().all(|r| r["class"] != "wrong_unflagged"),
        "{doc}"
    );
    let dopri = rows
        .iter()
        .find(|r| r["case"] == "contact_0.01um" && r["method"] == "dopri5")
        .unwrap();
    assert_eq!(dopri["class"], "failed_named");
    assert_eq!(dopri["reason"]["reason"], "integrator_gave_up");
    let csv = std::fs::read_to_string(dir.path().join("st/stability.csv")).unwrap();
    assert!(
        csv.starts_with("case,model,method,finished,status,x_jam_mm,"),
        "{csv}"
    );
    assert!(dir.path().join("st/stability.md").is_file());
    no_scene_writes_a_file_of(dir.path(), "st");

    let o = jamchart(dir.path(), &["stability", "--cases", "paper,stiff"]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.contains("cases = stiff (flag --cases)") && err.contains("contact_1um"),
        "{err}"
    );
}

/// The section of chart `name` in a gallery page, markers included.
fn section_of<'a>(page: &'a str, name: &str) -> &'a str {
    let open = format!("<!-- chart {name} -->");
    let start = page
        .find(&open)
        .unwrap_or_else(|| panic!("no section {name}:\n{page}"));
    let end = start + page[start..].find("<!-- /chart -->").unwrap();
    &page[start..end]
}

/// `accuracy --out-dir` wrote its error-time chart without a gallery page: it writes
/// index.html with the chart's section (its read-off, the command, links to its files; no
/// link to the map's CSV it did not write), keeps the section of a chart `render` drew into
/// the folder before, and a later `render` keeps the accuracy section as written (before, a
/// picture no render recorded got a bare section without read-off).
#[test]
fn accuracy_writes_a_gallery_section_that_render_keeps() {
    let dir = tempfile::tempdir().unwrap();
    let render = |scene: &str| {
        let r = jamchart(
            dir.path(),
            &["render", scene, "--out", "o", "--format", "svg"],
        );
        assert_eq!(r.status.code(), Some(0), "{}", stderr(&r));
        std::fs::read_to_string(dir.path().join("o/index.html")).unwrap()
    };
    let first = render("fig3");
    let accuracy = [
        "accuracy",
        "--methods",
        "radau5",
        "--tolerances",
        "1e-3",
        "--penetrations",
        "none",
        "--runs",
        "1",
        "--map-cells",
        "0",
        "--out-dir",
        "o",
    ];
    let r = jamchart(dir.path(), &accuracy);
    assert_eq!(r.status.code(), Some(0), "{}", stderr(&r));
    let page = std::fs::read_to_string(dir.path().join("o/index.html")).unwrap();
    let section = section_of(&page, "accuracy");
    assert!(
        section.contains("<figure class=\"readoff\" data-chart=\"accuracy\">"),
        "{section}"
    );
    assert!(section.contains("\"kind\":\"points\""), "{section}");
    for f in ["md", "csv", "json", "svg", "png"] {
        let link = format!("<a href=\"accuracy.{f}\">accuracy.{f}</a>");
        assert!(section.contains(&link), "{link} missing:\n{section}");
    }
    assert!(!section.contains("accuracy_map.csv"), "{section}");
    assert!(
        section.contains(&format!(
            "Reproduce: <code>jamchart {}</code>",
            accuracy.join(" ")
        )),
        "{section}"
    );
    assert_eq!(section_of(&page, "fig3"), section_of(&first, "fig3"));
    let again = render("fig7b");
    assert_eq!(section_of(&again, "accuracy"), section);
    assert!(again.contains("<section id=\"fig3\">"), "{again}");
}
