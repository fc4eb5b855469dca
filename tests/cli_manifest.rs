//! `render --bless` and `render --check` on a user's own scene folder, as a user locks their
//! charts in CI: bless, check passes, one key changed, check fails naming the chart.

use crate::common::cli as cli_util;
use std::path::Path;

use sha2::Digest;

use cli_util::{jamchart, repo, stderr, stdout};

/// A user's repository: `scenes/` with two scene files of their own (copies of built-in ones).
fn user_repo() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("scenes")).unwrap();
    for (theirs, ours) in [("shaft", "fig7b"), ("pin", "fig7a")] {
        std::fs::copy(
            repo().join(format!("charts/{ours}.toml")),
            dir.path().join(format!("scenes/{theirs}.toml")),
        )
        .unwrap();
    }
    dir
}

fn render(dir: &Path, flag: &str) -> std::process::Output {
    jamchart(dir, &["render", "scenes", "--out", "charts", flag])
}

#[test]
fn bless_then_check_passes_and_a_changed_key_fails_naming_the_chart() {
    let dir = user_repo();
    let blessed = render(dir.path(), "--bless");
    assert_eq!(blessed.status.code(), Some(0), "{}", stderr(&blessed));
    let manifest = std::fs::read_to_string(dir.path().join("charts/SHA256SUMS")).unwrap();
    let files: Vec<&str> = manifest
        .lines()
        .map(|l| l.split_once("  ").expect("HASH  FILE").1)
        .collect();
    assert_eq!(files, ["pin.png", "pin.svg", "shaft.png", "shaft.svg"]);
    // The manifest holds the hashes of the files written beside it (sha256sum -c would pass).
    for line in manifest.lines() {
        let (hash, file) = line.split_once("  ").unwrap();
        let bytes = std::fs::read(dir.path().join("charts").join(file)).unwrap();
        let digest: String = sha2::Sha256::digest(&bytes)
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect();
        assert_eq!(hash, digest, "{file}");
    }

    let ok = render(dir.path(), "--check");
    assert_eq!(ok.status.code(), Some(0), "{}", stderr(&ok));
    assert!(stdout(&ok).contains("4 pictures match"), "{}", stdout(&ok));
    assert!(stderr(&ok).is_empty(), "{}", stderr(&ok));

    // One key of one scene changed: only that scene's pictures are named.
    let shaft = dir.path().join("scenes/shaft.toml");
    let text = std::fs::read_to_string(&shaft).unwrap();
    std::fs::write(&shaft, format!("{text}\n[scene]\nmu = 0.3\n")).unwrap();
    let before = std::fs::read(dir.path().join("charts/shaft.png")).unwrap();
    let broken = render(dir.path(), "--check");
    assert_eq!(broken.status.code(), Some(1), "{}", stderr(&broken));
    let err = stderr(&broken);
    assert!(
        err.starts_with("jamchart: 2 pictures differ from charts/SHA256SUMS: shaft.png, shaft.svg"),
        "{err}"
    );
    let out = stdout(&broken);
    assert!(out.contains("shaft.png: changed"), "{out}");
    assert!(!out.contains("pin."), "{out}");
    // --check writes nothing into the checked folder.
    assert_eq!(
        std::fs::read(dir.path().join("charts/shaft.png")).unwrap(),
        before
    );
}

#[test]
fn check_names_a_removed_scene_missing_and_a_new_one_not_blessed() {
    let dir = user_repo();
    assert_eq!(render(dir.path(), "--bless").status.code(), Some(0));
    std::fs::rename(
        dir.path().join("scenes/pin.toml"),
        dir.path().join("scenes/bolt.toml"),
    )
    .unwrap();
    let out = render(dir.path(), "--check");
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let text = stdout(&out);
    assert!(text.contains("pin.png: missing"), "{text}");
    assert!(text.contains("bolt.svg: not in the manifest"), "{text}");
}

#[test]
fn check_without_a_manifest_is_bad_input_exit_2() {
    let dir = user_repo();
    let out = render(dir.path(), "--check");
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.starts_with("jamchart: no manifest charts/SHA256SUMS to check against")
            && err.contains("--bless"),
        "{err}"
    );
    assert!(!dir.path().join("charts").exists());
}

#[test]
fn bless_and_check_together_are_refused() {
    let dir = user_repo();
    let out = jamchart(
        dir.path(),
        &["render", "scenes", "--out", "charts", "--bless", "--check"],
    );
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("--check"), "{}", stderr(&out));
}
