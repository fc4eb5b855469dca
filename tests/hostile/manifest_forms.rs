//! The manifest as `sha256sum -c` reads it: a `sha256sum -b` manifest ("HASH *FILE") and
//! upper-case hex were read as changed pictures where `sha256sum -c` says OK. Each form is
//! checked by `render --check` and, where it is installed, by `sha256sum -c` itself: both
//! must agree.

use std::path::Path;
use std::process::Command;

use super::cli_util::{stderr, stdout};
use super::run;

/// Each rewriting of a manifest's `HASH  FILE` lines that `sha256sum -c` accepts.
fn forms(blessed: &str) -> Vec<(&'static str, String)> {
    let lines: Vec<(&str, &str)> = blessed
        .lines()
        .map(|l| l.split_once("  ").expect("HASH  FILE"))
        .collect();
    let each = |f: &dyn Fn(&str, &str) -> String| lines.iter().map(|(h, n)| f(h, n)).collect();
    vec![
        ("binary (-b)", each(&|h, n| format!("{h} *{n}\n"))),
        (
            "upper-case hex",
            each(&|h, n| format!("{}  {n}\n", h.to_uppercase())),
        ),
        (
            "tagged (--tag)",
            each(&|h, n| format!("SHA256 ({n}) = {h}\n")),
        ),
        ("CRLF line ends", each(&|h, n| format!("{h}  {n}\r\n"))),
        ("./ before the name", each(&|h, n| format!("{h}  ./{n}\n"))),
        ("BSD -r", each(&|h, n| format!("{h} {n}\n"))),
        ("escaped name", each(&|h, n| format!("\\{h}  {n}\n"))),
        ("comment and blanks", format!("# pictures\n\n{blessed}")),
    ]
}

/// `sha256sum -c SHA256SUMS` in `out`: Some(passed), None where sha256sum is not installed.
fn sha256sum_passes(out: &Path) -> Option<bool> {
    let o = Command::new("sha256sum")
        .args(["-c", "--quiet", "SHA256SUMS"])
        .current_dir(out)
        .output()
        .ok()?;
    Some(o.status.success())
}

#[test]
fn every_manifest_form_sha256sum_accepts_is_checked_as_it_does() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let check = ["render", "fig6", "--out", "out", "--check"];
    let o = run(d, &["render", "fig6", "--out", "out", "--bless", "-q"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let manifest = d.join("out/SHA256SUMS");
    let blessed = std::fs::read_to_string(&manifest).unwrap();
    for (form, text) in forms(&blessed) {
        std::fs::write(&manifest, &text).unwrap();
        let o = run(d, &check);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{form}: {}{}",
            stdout(&o),
            stderr(&o)
        );
        assert_ne!(sha256sum_passes(&d.join("out")), Some(false), "{form}");
    }
    // A changed hash fails both, in any of the forms.
    let other = if blessed.starts_with('0') { '1' } else { '0' };
    let wrong = format!("{other}{}", &blessed[1..]).replace("  ", " *");
    std::fs::write(&manifest, wrong).unwrap();
    let o = run(d, &check);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert_ne!(sha256sum_passes(&d.join("out")), Some(true));
}
