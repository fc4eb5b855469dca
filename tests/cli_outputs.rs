//! Output files of every command (`solve --series`, `render`, `accuracy --out-dir`): never a
//! special file or a link replaced, all or nothing, no temporary file left behind.

use std::os::unix::fs::FileTypeExt;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::common::cli as cli_util;
use cli_util::{jamchart, kill_and_wait, repo, stderr};

fn scenes_dir() -> String {
    repo().join("charts").display().to_string()
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn mkfifo(p: &Path) {
    assert!(Command::new("mkfifo").arg(p).status().unwrap().success());
}

/// `accuracy` at its smallest: one tolerance of one integrator, one run, no map.
const SMALL_ACCURACY: &[&str] = &[
    "accuracy",
    "--tolerances",
    "1e-3",
    "--runs",
    "1",
    "--min-norm-tolerances",
    "none",
    "--map-cells",
    "0",
    "--penetrations",
    "none",
    "--methods",
    "radau5",
    "--nonsmooth-steps",
    "none",
];

/// One command per output kind, writing `target` (a path under `dir`) as one of its outputs.
fn commands(target: &str) -> Vec<Vec<String>> {
    let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<String>>();
    let (dir, file) = target.split_once('/').unwrap();
    vec![
        s(&[
            "solve",
            "--model",
            "dynamics",
            "--no-verify",
            "--series",
            target,
        ]),
        s(&[
            "render",
            file.split('.').next().unwrap(),
            "--out",
            dir,
            "--scenes-dir",
            &scenes_dir(),
        ]),
        s(&[SMALL_ACCURACY, &["--out-dir", dir]].concat()),
    ]
}

/// Regression ("--series replaces a special file"): `mknod X/full c 1 7` then
/// `solve --series X/full` left a 663 kB regular file in its place; a symlink and a directory
/// fared no better. Every output path of every command must refuse them and leave them be.
#[test]
fn output_files_never_replace_a_special_file_or_a_symlink() {
    for (cmd_index, target) in ["x/full.csv", "x/fig7b.svg", "x/accuracy.json"]
        .into_iter()
        .enumerate()
    {
        let cmd = &commands(target)[cmd_index];
        for kind in ["char-device", "symlink", "dangling-symlink", "directory"] {
            let dir = tempfile::tempdir().unwrap();
            std::fs::create_dir(dir.path().join("x")).unwrap();
            let p = dir.path().join(target);
            let kept = dir.path().join("kept.csv");
            std::fs::write(&kept, "keep me").unwrap();
            match kind {
                // /dev/full (1:7): neither a terminal nor /dev/null. Needs root, as the tests run.
                "char-device" => assert!(
                    Command::new("mknod")
                        .args([p.to_str().unwrap(), "c", "1", "7"])
                        .status()
                        .unwrap()
                        .success()
                ),
                "symlink" => std::os::unix::fs::symlink(&kept, &p).unwrap(),
                "dangling-symlink" => std::os::unix::fs::symlink("nowhere", &p).unwrap(),
                _ => std::fs::create_dir(&p).unwrap(),
            }
            let args: Vec<&str> = cmd.iter().map(String::as_str).collect();
            let out = jamchart(dir.path(), &args);
            let err = stderr(&out);
            assert_eq!(out.status.code(), Some(2), "{kind} {args:?}: {err}");
            assert!(err.contains("refusing to write"), "{kind} {args:?}: {err}");
            let m = std::fs::symlink_metadata(&p).unwrap();
            let same = match kind {
                "char-device" => m.file_type().is_char_device(),
                "directory" => m.is_dir(),
                _ => m.file_type().is_symlink(),
            };
            assert!(same, "{kind} {args:?}: the node was replaced");
            assert_eq!(std::fs::read_to_string(&kept).unwrap(), "keep me");
            assert_eq!(
                names(&dir.path().join("x")),
                [target.split_once('/').unwrap().1]
            );
        }
    }
}

/// FIFOs and /dev/null are streams: written through, left in place.
#[test]
fn output_streams_are_written_through() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("series.csv");
    mkfifo(&fifo);
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    let args = [
        "solve",
        "--model",
        "dynamics",
        "--no-verify",
        "--series",
        "series.csv",
    ];
    let out = jamchart(dir.path(), &args);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    // Checked before the join: a binary that replaced the FIFO would leave the reader blocked.
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
    let csv = reader.join().unwrap();
    assert!(csv.starts_with("t_s,theta_deg,x_mm"), "{csv:.80}");
    assert!(csv.lines().count() > 100);
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
    let out = jamchart(
        dir.path(),
        &["solve", "--model", "dynamics", "--series", "/dev/null"],
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(
        std::fs::metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device()
    );
}

/// Regression ("a failed command leaves a partial set"): render onto a full disk
/// failed on accuracy.svg but left complete .csv files of other scenes; accuracy --out-dir left
/// .md and .csv when .json failed. Here a directory squats one name of the set: the command
/// fails and the folder is as it was.
#[test]
fn a_failed_command_leaves_the_output_folder_as_it_found_it() {
    let accuracy = [SMALL_ACCURACY, &["--out-dir", "o"]].concat();
    let cases: [(&[&str], &str); 2] = [
        (&["render", "fig7a", "fig7b", "--out", "o"], "o/fig7b.png"),
        (&accuracy, "o/accuracy.json"),
    ];
    for (args, squat) in cases {
        let dir = tempfile::tempdir().unwrap();
        let o = dir.path().join("o");
        std::fs::create_dir(&o).unwrap();
        std::fs::write(o.join("fig7a.csv"), "old").unwrap();
        std::fs::write(o.join("accuracy.md"), "old").unwrap();
        std::fs::create_dir(dir.path().join(squat)).unwrap();
        let mut args = args.to_vec();
        let sd = scenes_dir();
        if args[0] == "render" {
            args.extend(["--scenes-dir", &sd]);
        }
        let before = names(&o);
        let out = jamchart(dir.path(), &args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert_eq!(names(&o), before, "{args:?}: {}", stderr(&out));
        assert_eq!(std::fs::read_to_string(o.join("fig7a.csv")).unwrap(), "old");
        assert_eq!(
            std::fs::read_to_string(o.join("accuracy.md")).unwrap(),
            "old"
        );
    }
}

/// A render writes each picture as soon as it is drawn: one that goes to a FIFO is written
/// through once, the same bytes as into a file, and not again with the rest of the set (a
/// second write would wait for a reader forever).
#[test]
fn a_picture_into_a_fifo_is_written_once() {
    let dir = tempfile::tempdir().unwrap();
    let (o, plain) = (dir.path().join("o"), dir.path().join("plain"));
    std::fs::create_dir(&o).unwrap();
    let fifo = o.join("fig3.svg");
    mkfifo(&fifo);
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    let render = |out: &str| {
        Command::new(env!("CARGO_BIN_EXE_jamchart"))
            .args([
                "render",
                "fig3",
                "--out",
                out,
                "--scenes-dir",
                &scenes_dir(),
            ])
            .current_dir(dir.path())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap()
    };
    let mut child = render("o");
    let t0 = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if t0.elapsed() > Duration::from_secs(60) {
            kill_and_wait(&mut child, "KILL");
            panic!("the render did not finish: a second write into the FIFO?");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    assert!(status.success());
    let through = reader.join().unwrap();
    assert!(render("plain").wait().unwrap().success());
    assert_eq!(through, std::fs::read(plain.join("fig3.svg")).unwrap());
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
    assert!(o.join("fig3.png").is_file() && o.join("fig3.csv").is_file());
}

/// The temporary files of a render that is still writing, in `o`.
fn temporaries(o: &Path) -> Vec<String> {
    names(o)
        .into_iter()
        .filter(|n| n.starts_with('.') && n.ends_with(".tmp"))
        .collect()
}

/// Regression ("temporary files pile up"): a render killed by SIGTERM left
/// `.fig3.json.5971.12.tmp` behind. A FIFO nobody reads as one output holds the render with
/// its other files in temporaries; SIGTERM, SIGINT or SIGHUP must remove
/// them.
#[test]
fn a_killed_render_leaves_no_temporary_file() {
    for signal in ["TERM", "INT", "HUP"] {
        let dir = tempfile::tempdir().unwrap();
        let o = dir.path().join("o");
        std::fs::create_dir(&o).unwrap();
        mkfifo(&o.join("fig7b.svg"));
        let mut child = Command::new(env!("CARGO_BIN_EXE_jamchart"))
            .args([
                "render",
                "fig7b",
                "--out",
                "o",
                "--scenes-dir",
                &scenes_dir(),
            ])
            .current_dir(dir.path())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let t0 = Instant::now();
        while temporaries(&o).len() < 2 {
            assert!(
                t0.elapsed() < Duration::from_secs(60),
                "no temporaries appeared"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
        kill_and_wait(&mut child, signal);
        assert_eq!(names(&o), ["fig7b.svg"], "SIG{signal}");
    }
}

/// Temporaries of our naming whose process is gone (killed by SIGKILL) are swept by the next
/// write into the folder; a live process's are left alone.
#[test]
fn stale_temporaries_of_ours_are_swept() {
    let dir = tempfile::tempdir().unwrap();
    let o = dir.path().join("o");
    std::fs::create_dir(&o).unwrap();
    let mut child = Command::new("true").spawn().unwrap();
    let dead = child.id();
    child.wait().unwrap();
    let stale: PathBuf = o.join(format!(".fig3.json.{dead}.12.tmp"));
    let live = o.join(format!(".fig3.json.{}.0.tmp", std::process::id()));
    std::fs::write(&stale, "x").unwrap();
    std::fs::write(&live, "x").unwrap();
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
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(!stale.exists() && live.exists());
}

/// `JAMCHART_SYNC` chooses what a set syncs against a power loss: `none` writes the same files
/// as the default `data`, and any other value is refused, naming the variable, its value and
/// what to give, before any file or folder is made.
#[test]
fn the_sync_policy_is_data_or_none_and_anything_else_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let render = |out: &str, sync: Option<&str>| {
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_jamchart"));
        cmd.args(["render", "fig7b", "--quiet", "--out", out])
            .args(["--scenes-dir", &scenes_dir()])
            .current_dir(dir.path())
            .env_remove("JAMCHART_SYNC");
        if let Some(v) = sync {
            cmd.env("JAMCHART_SYNC", v);
        }
        cmd.output().unwrap()
    };
    for (out, sync) in [
        ("default", None),
        ("data", Some("data")),
        ("none", Some("none")),
    ] {
        let o = render(out, sync);
        assert_eq!(o.status.code(), Some(0), "{sync:?}: {}", stderr(&o));
    }
    for out in ["data", "none"] {
        assert_eq!(
            names(&dir.path().join(out)),
            names(&dir.path().join("default"))
        );
        // The gallery page names its folder in the command it shows: the charts and data only.
        for name in names(&dir.path().join("default")) {
            if name == "index.html" {
                continue;
            }
            let read = |d: &str| std::fs::read(dir.path().join(d).join(&name)).unwrap();
            assert!(read(out) == read("default"), "{out}/{name} differs");
        }
    }
    let o = render("refused", Some("sometimes"));
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.contains("JAMCHART_SYNC") && err.contains("sometimes") && err.contains("none"),
        "{err}"
    );
    assert!(!dir.path().join("refused").exists(), "{err}");
}
