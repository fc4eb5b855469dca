//! `jamchart render` run as a process in a temporary directory.

use crate::common::cli as cli_util;
use cli_util::{jamchart, repo, stderr, stdout};

fn scenes_dir() -> String {
    repo().join("charts").display().to_string()
}

#[test]
fn render_one_scene_writes_picture_and_data_and_nothing_else() {
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(
        dir.path(),
        &[
            "render",
            "fig7b",
            "--out",
            "o",
            "--scenes-dir",
            &scenes_dir(),
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut files: Vec<String> = std::fs::read_dir(dir.path().join("o"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .collect();
    files.sort();
    // No temporary file is left behind, and no other scene is rendered.
    assert_eq!(files, ["fig7b.csv", "fig7b.png", "fig7b.svg", "index.html"]);
    let csv = std::fs::read_to_string(dir.path().join("o/fig7b.csv")).unwrap();
    assert!(
        csv.starts_with("layer,force_n,status,x_jam_mm,theta_jam_deg,past_palm_x_jam_mm\n"),
        "{csv:.80}"
    );
    let png = std::fs::read(dir.path().join("o/fig7b.png")).unwrap();
    assert_eq!(&png[1..4], b"PNG");
    // Not a terminal: no progress bar on stderr.
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn svg_format_writes_no_png() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "render",
        "fig3",
        "--format",
        "svg",
        "--out",
        "o",
        "--scenes-dir",
        &scenes_dir(),
    ];
    let out = jamchart(dir.path(), &args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(dir.path().join("o/fig3.svg").exists() && dir.path().join("o/fig3.json").exists());
    assert!(!dir.path().join("o/fig3.png").exists());
}

#[test]
fn unknown_scene_exits_2_and_lists_the_known_ones() {
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(
        dir.path(),
        &[
            "render",
            "fig9",
            "--out",
            "o",
            "--scenes-dir",
            &scenes_dir(),
        ],
    );
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.starts_with("jamchart: ") && err.contains("fig9"),
        "{err}"
    );
    assert!(
        err.contains(
            "fig3, fig4, fig5, fig6, fig7a, fig7b, fig7c, integration-error, jam-probability, \
             stability-matrix"
        ),
        "{err}"
    );
    assert!(
        !dir.path().join("o").exists(),
        "nothing is written for a bad request"
    );
}

#[test]
fn bad_scene_file_names_file_line_and_key() {
    let dir = tempfile::tempdir().unwrap();
    let charts = dir.path().join("charts");
    std::fs::create_dir(&charts).unwrap();
    std::fs::write(
        charts.join("bad.toml"),
        "title = \"t\"\nbase = \"none.toml\"\n[chart]\nkind = \"sweep\"\nx_axis = { param = \"mu\", min = 0.1, max = 0.5, count = 5 }\n",
    )
    .unwrap();
    let out = jamchart(dir.path(), &["render", "--scenes-dir", "charts"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("none.toml"), "{err}");
    std::fs::write(
        charts.join("bad.toml"),
        "title = \"t\"\nbase = \"none.toml\"\n[chart]\nkind = \"sweep\"\nx_axs = 1\n",
    )
    .unwrap();
    let out = jamchart(dir.path(), &["render", "--scenes-dir", "charts"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    // The chart's own mistake comes before the missing base, named with its line and path.
    assert!(
        err.contains("bad.toml:5:9: chart.x_axs = 1: unknown key; did you mean x_axis?"),
        "{err}"
    );
}

/// Regression: `render fig7a fig7a` drew the scene twice at once, both writes went through the
/// same temporary file, and the run failed with "cannot write o/fig7a.csv" (or left torn files).
#[test]
fn a_scene_named_twice_is_rendered_once() {
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(
        dir.path(),
        &[
            "render",
            "fig7a",
            "fig7a",
            "fig7a",
            "fig7a",
            "--out",
            "o",
            "--scenes-dir",
            &scenes_dir(),
        ],
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let mut files: Vec<String> = std::fs::read_dir(dir.path().join("o"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .collect();
    files.sort();
    assert_eq!(files, ["fig7a.csv", "fig7a.png", "fig7a.svg", "index.html"]);
}

/// Scenes used to be read from ./charts, so `render` failed outside the repository and after
/// `cargo install`: the built-in scenes and paper set make an empty folder enough.
#[test]
fn render_in_an_empty_folder_draws_every_built_in_scene() {
    let dir = tempfile::tempdir().unwrap();
    let list = jamchart(dir.path(), &["scenes"]);
    assert!(list.status.success(), "{}", stderr(&list));
    let names: Vec<String> = String::from_utf8_lossy(&list.stdout)
        .lines()
        .map(|l| l.split_whitespace().next().unwrap().to_string())
        .collect();
    assert!(
        names.len() >= 8 && names.contains(&"fig3".to_string()),
        "{names:?}"
    );
    let out = jamchart(dir.path(), &["render"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let index = std::fs::read_to_string(dir.path().join("out/index.html")).unwrap();
    for n in &names {
        for ext in ["svg", "png"] {
            let f = dir.path().join(format!("out/{n}.{ext}"));
            assert!(f.exists(), "{} missing", f.display());
            assert!(
                index.contains(&format!("href=\"{n}.{ext}\"")),
                "index.html lacks {n}.{ext}"
            );
        }
    }
}

/// A user's scene in another folder: no `base` means the built-in paper set, and `--set`
/// changes its parameters without editing the file.
#[test]
fn own_scene_file_renders_from_its_path_and_set_overrides_it() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("mine")).unwrap();
    let text = "title = \"shaft\"\n[scene]\nradius_mm = 25.0\n[chart]\nkind = \"sweep\"\n\
                x_axis = { param = \"mu\", min = 0.1, max = 0.5, count = 5 }\n\
                panels = [\"x_jam_mm\"]\nlayers = [\"statics\"]\n";
    std::fs::write(dir.path().join("mine/shaft.toml"), text).unwrap();
    let plain = jamchart(dir.path(), &["render", "mine/shaft.toml", "--out", "a"]);
    assert!(plain.status.success(), "{}", stderr(&plain));
    let set = ["render", "mine", "--out", "b", "--set", "force_n=80"];
    let pushed = jamchart(dir.path(), &set);
    assert!(pushed.status.success(), "{}", stderr(&pushed));
    let a = std::fs::read_to_string(dir.path().join("a/shaft.csv")).unwrap();
    let b = std::fs::read_to_string(dir.path().join("b/shaft.csv")).unwrap();
    assert_eq!(a.lines().count(), b.lines().count());
    assert_ne!(a, b, "--set force_n=80 changed nothing");
    // fig3's axis mu sets both frictions: a fixed palm friction needs a mu_ground axis.
    let palm = ["render", "fig3", "--set", "mu_palm=0.6", "--out", "c"];
    let refused = jamchart(dir.path(), &palm);
    assert_eq!(refused.status.code(), Some(2));
    assert!(
        stderr(&refused).contains("chart.x_axis.param=mu_ground"),
        "{}",
        stderr(&refused)
    );
    let fixed = [
        &palm[..],
        &["--set", "chart.x_axis.param=mu_ground", "--format", "svg"],
    ]
    .concat();
    let out = jamchart(dir.path(), &fixed);
    assert!(out.status.success(), "{}", stderr(&out));
    let bad = jamchart(dir.path(), &["render", "fig3", "--set", "radious=3"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(stderr(&bad).contains("radius_mm"), "{}", stderr(&bad));
}

/// Data files held `2.4746092876045168e1`, `4.08e-1` and `-0.00000`; a spreadsheet wants plain
/// decimals. Every numeric cell of these CSVs is one, and no cell is a negative zero.
#[test]
fn csv_cells_are_plain_decimals() {
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(
        dir.path(),
        &["render", "fig4", "fig5", "fig7b", "--format", "svg"],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    for name in ["fig4.csv", "fig5.csv", "fig7b.csv"] {
        let text = std::fs::read_to_string(dir.path().join("out").join(name)).unwrap();
        for cell in text.lines().skip(1).flat_map(|l| l.split(',')) {
            if let Ok(v) = cell.parse::<f64>() {
                let zero_ok = v != 0.0 || cell == "0";
                assert!(
                    !cell.contains(['e', 'E']) && zero_ok,
                    "{name}: cell {cell:?}"
                );
            }
        }
    }
}

/// A second `render` of one scene into the same folder replaced index.html with that scene
/// alone: the gallery lists every chart in the folder, however many renders wrote it.
#[test]
fn second_render_into_the_folder_keeps_the_other_charts_in_the_gallery() {
    let dir = tempfile::tempdir().unwrap();
    for scene in ["fig7a", "fig7b"] {
        let out = jamchart(
            dir.path(),
            &["render", scene, "--out", "o", "--scenes-dir", &scenes_dir()],
        );
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    }
    let index = std::fs::read_to_string(dir.path().join("o/index.html")).unwrap();
    for scene in ["fig7a", "fig7b"] {
        assert!(
            index.contains(&format!("<section id=\"{scene}\">")),
            "{scene} missing from index.html"
        );
        assert!(
            index.contains(&format!("<img src=\"{scene}.png\"")),
            "{scene}"
        );
    }
}

/// Regression: writers into one folder at once lost gallery entries. Six sweeps and a render
/// each built index.html from the folder as they found it, and the last page written listed
/// 1 to 6 of the 8 charts. Each now builds and writes the page under the folder's lock; the
/// test widens the window between building and writing (the staging pause) so that every
/// writer would build its page before any wrote one.
#[test]
fn writers_into_one_folder_at_once_all_join_its_gallery() {
    let dir = tempfile::tempdir().unwrap();
    let sweeps: Vec<String> = (0..6).map(|i| format!("s{i}")).collect();
    let run = |args: Vec<String>| {
        std::process::Command::new(env!("CARGO_BIN_EXE_jamchart"))
            .args(args)
            .current_dir(dir.path())
            .env("JAMCHART_TEST_PAUSE_AFTER_STAGING_MS", "300")
            .env("RAYON_NUM_THREADS", "1")
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap()
    };
    let mut children: Vec<std::process::Child> = sweeps
        .iter()
        .map(|name| {
            let args = ["sweep", "mu=0.2:0.6:5", "--name", name, "--out", "o"];
            run(args.iter().map(|s| s.to_string()).collect())
        })
        .collect();
    let render = ["render", "fig7a", "fig7b", "--out", "o", "--scenes-dir"];
    let mut args: Vec<String> = render.iter().map(|s| s.to_string()).collect();
    args.push(scenes_dir());
    children.push(run(args));
    for c in children {
        let out = c.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    }
    let index = std::fs::read_to_string(dir.path().join("o/index.html")).unwrap();
    let names = sweeps.iter().map(String::as_str).chain(["fig7a", "fig7b"]);
    let missing: Vec<&str> = names
        .filter(|n| !index.contains(&format!("<section id=\"{n}\">")))
        .collect();
    assert!(missing.is_empty(), "missing from index.html: {missing:?}");
}

/// Regression: a wrong or invalid `[scene]` key in a scene file named no file or
/// line (the `--config` path did), and with one bad file in a folder the error did not say
/// which file.
#[test]
fn a_bad_scene_key_names_its_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let scenes = dir.path().join("scenes");
    std::fs::create_dir(&scenes).unwrap();
    let sweep = "[chart]\nkind = \"sweep\"\nx_axis = { param = \"force_n\", min = 50.0, max = 1000.0, count = 5 }\n";
    std::fs::write(
        scenes.join("good.toml"),
        format!("title = \"good\"\n[scene]\nmu = 0.2\n{sweep}"),
    )
    .unwrap();
    std::fs::write(
        scenes.join("typo.toml"),
        format!("title = \"typo\"\n[scene]\nradus_mm = 3\n{sweep}"),
    )
    .unwrap();
    let o = jamchart(dir.path(), &["render", "scenes"]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(err.contains("typo.toml:3:"), "{err}");
    assert!(err.contains("radus_mm"), "{err}");
    std::fs::write(
        scenes.join("typo.toml"),
        format!("title = \"typo\"\n[scene]\nradius_mm = -3\n{sweep}"),
    )
    .unwrap();
    let err = stderr(&jamchart(dir.path(), &["render", "scenes"]));
    assert!(
        err.contains("typo.toml:3:") && err.contains("radius_mm = -3"),
        "{err}"
    );
    // `[scene] mu` works as `--set mu` does.
    std::fs::remove_file(scenes.join("typo.toml")).unwrap();
    assert_eq!(
        jamchart(dir.path(), &["render", "scenes"]).status.code(),
        Some(0)
    );
}

/// Regression: the key reference lived in charts/README.md, which an installed binary does not
/// have; `jamchart scenes --keys` prints it.
#[test]
fn scenes_keys_prints_the_key_reference() {
    let o = jamchart(repo(), &["scenes", "--keys"]);
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    let readme = std::fs::read_to_string(repo().join("charts/README.md")).unwrap();
    assert_eq!(out, readme);
    assert!(out.contains("#### `kind = \"universal\"`"));
}

/// `render --set KEY=VALUE` applies to every scene it can; a scene that cannot show
/// the key says so on stderr (a V-block chart has its own parameters; an axis that varies the
/// key hides it), while a chart that marks the value (read-off lines) stays quiet.
#[test]
fn a_scene_that_cannot_show_a_set_key_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &[
            "render",
            "fig7a",
            "vlocator-optimum",
            "universal",
            "--set",
            "radius_mm=12",
            "--set",
            "mu=0.27",
            "--format",
            "svg",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("scene fig7a varies radius_mm along chart.x_axis, so --set radius_mm=12"),
        "{err}"
    );
    assert!(
        err.contains("scene vlocator-optimum does not take --set mu=0.27"),
        "{err}"
    );
    assert!(!err.contains("scene universal"), "{err}");
    assert!(!err.contains("fig7a varies mu"), "{err}");
}

/// The capacity chart's legend listed the hatched self-locking band where the axis starts past
/// it and nothing is hatched: the entry is there only when the band is drawn.
#[test]
fn the_capacity_legend_lists_the_wedged_band_only_where_it_is_drawn() {
    let dir = tempfile::tempdir().unwrap();
    let svg = |extra: &[&str], out: &str| {
        let mut args = vec![
            "render",
            "vlocator-capacity",
            "--format",
            "svg",
            "--out",
            out,
        ];
        args.extend_from_slice(extra);
        let o = jamchart(dir.path(), &args);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        std::fs::read_to_string(dir.path().join(out).join("vlocator-capacity.svg")).unwrap()
    };
    let entry = "hatched: the V self-locks";
    assert!(svg(&[], "a").contains(entry));
    assert!(!svg(&["--set", "chart.x_axis.min=40"], "b").contains(entry));
}
