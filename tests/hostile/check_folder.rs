//! `render --check` wrote its new renders into a folder under `$TMPDIR` and left it there on
//! every failed check. A check now writes nothing anywhere: the report says how to look at the
//! new pictures (render into another folder) and how to accept them (`--bless`).

use std::path::Path;
use std::time::Duration;

use super::cli_util::{stderr, stdout};
use super::run_within;

/// `render fig6 --out out ARGS` in `dir` with TMPDIR set to `tmp`.
fn render(dir: &Path, tmp: &Path, args: &[&str]) -> std::process::Output {
    let mut all = vec!["render", "fig6", "--out", "out", "--format", "png"];
    all.extend(args);
    run_within(dir, &all, &[("TMPDIR", tmp)], Duration::from_secs(60))
}

/// Every file under `dir`, as paths relative to it, sorted.
fn files(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            match e.path().is_dir() {
                true => stack.push(e.path()),
                false => out.push(e.path().strip_prefix(dir).unwrap().display().to_string()),
            }
        }
    }
    out.sort();
    out
}

#[test]
fn a_check_leaves_no_folder_behind_and_says_how_to_accept() {
    let dir = tempfile::tempdir().unwrap();
    let tmp = tempfile::tempdir().unwrap();
    let o = render(dir.path(), tmp.path(), &["--bless", "-q"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let blessed = files(dir.path());
    let o = render(dir.path(), tmp.path(), &["--check"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = render(
        dir.path(),
        tmp.path(),
        &["--check", "--set", "title=changed"],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("fig6.png: changed (blessed "), "{out}");
    assert!(
        out.contains("render them into another folder: the same command with another --out"),
        "{out}"
    );
    assert!(
        out.contains("accept it: the same command with --bless instead of --check"),
        "{out}"
    );
    // Neither the temporary directory nor the checked folder gained a file.
    assert_eq!(files(tmp.path()), Vec::<String>::new());
    assert_eq!(files(dir.path()), blessed);
}
