//! `render --check` wrote its new renders into `$TMPDIR/jamchart-check-<pid>`: a predictable
//! name, reused as found (a folder made there beforehand, or a link planted there, which
//! redirected the writes outside it). It now makes a fresh private folder.

use std::os::unix::fs::PermissionsExt;
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

#[test]
fn the_new_renders_go_to_a_fresh_private_folder() {
    let dir = tempfile::tempdir().unwrap();
    let tmp = tempfile::tempdir().unwrap();
    let o = render(dir.path(), tmp.path(), &["--bless", "-q"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // A check that passes writes nothing anywhere.
    let o = render(dir.path(), tmp.path(), &["--check"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(std::fs::read_dir(tmp.path()).unwrap().count(), 0);
    // A check that fails names its folder: new, under TMPDIR, mode 0700, holding the renders.
    let o = render(
        dir.path(),
        tmp.path(),
        &["--check", "--set", "title=changed"],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let out = stdout(&o);
    let named = out
        .lines()
        .find_map(|l| l.strip_prefix("the new renders are in "))
        .unwrap_or_else(|| panic!("no folder named: {out}"));
    let folder = Path::new(named);
    assert_eq!(folder.parent(), Some(tmp.path()), "{named}");
    let name = folder.file_name().unwrap().to_string_lossy();
    assert!(name.starts_with("jamchart-check-"), "{name}");
    let meta = std::fs::symlink_metadata(folder).unwrap();
    assert!(meta.is_dir(), "{named} is not a plain folder");
    assert_eq!(meta.permissions().mode() & 0o777, 0o700, "{named}");
    assert!(folder.join("fig6.png").is_file());
    // A second failing check makes another folder: nothing is reused.
    let o = render(
        dir.path(),
        tmp.path(),
        &["--check", "--set", "title=changed"],
    );
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert_eq!(std::fs::read_dir(tmp.path()).unwrap().count(), 2);
    assert!(!stdout(&o).contains(named));
}
