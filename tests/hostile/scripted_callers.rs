//! Scripted callers hand stdout over as /dev/null opened read-write (Python's
//! `subprocess.DEVNULL`, cron, systemd units, daemons). That descriptor was refused as a
//! closed stdout ("standard output is closed", exit 2), so every such caller failed.

use std::fs::OpenOptions;
use std::process::{Command, Stdio};

use super::cli_util::stderr;

/// `jamchart ARGS` with stdout on /dev/null opened read-write, as those callers open it.
fn to_dev_null_read_write(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    let null = OpenOptions::new()
        .read(true)
        .write(true)
        .open("/dev/null")
        .unwrap();
    Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::from(null))
        .stderr(Stdio::piped())
        .output()
        .unwrap()
}

#[test]
fn stdout_on_dev_null_opened_read_write_is_answered() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["solve", "--mu", "0.3"][..],
        &["render", "fig6", "--out", "out", "-q"][..],
        &["vlocator", "--load", "5"][..],
    ] {
        let o = to_dev_null_read_write(dir.path(), args);
        let e = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {e}");
        assert_eq!(e, "", "{args:?}");
    }
    assert!(dir.path().join("out/fig6.png").is_file());
}

/// The same from Python, the caller the report names: `subprocess.run(..., stdout=DEVNULL)`.
/// Skipped, saying so, where no python3 is installed.
#[test]
fn python_subprocess_devnull_runs_jamchart() {
    let dir = tempfile::tempdir().unwrap();
    let script = format!(
        "import subprocess, sys\n\
         for args in (['solve', '--mu', '0.3'], ['render', 'fig6', '--out', 'out', '-q']):\n\
         \x20   r = subprocess.run([{bin:?}] + args, stdout=subprocess.DEVNULL, \
         stderr=subprocess.PIPE)\n\
         \x20   print(r.returncode, r.stderr.decode().strip())\n",
        bin = env!("CARGO_BIN_EXE_jamchart")
    );
    let Ok(o) = Command::new("python3")
        .arg("-c")
        .arg(&script)
        .current_dir(dir.path())
        .output()
    else {
        eprintln!("python3 is not installed: the read-write /dev/null test above stands in");
        return;
    };
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        text,
        "0 \n0 \n",
        "{text} {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// `jamchart ARGS` in `dir` with stderr on `/dev/full`, where every write fails.
fn stderr_full(dir: &std::path::Path, args: &[&str]) -> std::process::Output {
    let full = OpenOptions::new().write(true).open("/dev/full").unwrap();
    Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::from(full))
        .output()
        .unwrap()
}

/// A diagnostic written to an unwritable stderr panicked (`eprintln!`): `solve --mass 60
/// 2>/dev/full` exited 101 with nothing on stdout, and so did every command that warns or
/// fails. The answer still goes to stdout with the exit code it has when stderr is
/// writable; the lost diagnostic is dropped.
#[test]
fn an_unwritable_stderr_loses_only_the_diagnostic() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("SHA256SUMS"),
        "0".repeat(64) + "  fig6.svg\n",
    )
    .unwrap();
    for (args, code) in [
        // A warning beside an answer.
        (&["solve", "--mass", "60"][..], 0),
        (&["vlocator", "--mu", "30"][..], 0),
        (
            &[
                "sweep",
                "mu=0.1:0.5:5",
                "--radius",
                "0.1",
                "--format",
                "svg",
            ][..],
            0,
        ),
        (
            &[
                "render", "fig6", "--out", "o", "--format", "svg", "--set", "mu=0.3",
            ][..],
            0,
        ),
        // An error.
        (&["solve", "--config", "missing.toml"][..], 2),
        // A usage error, and the help printed for a missing subcommand.
        (&["solve", "--no-such-flag"][..], 2),
        (&[][..], 2),
        // A failed check: its report on stdout, its summary on stderr.
        (
            &["render", "fig6", "--out", ".", "--format", "svg", "--check"][..],
            1,
        ),
    ] {
        let o = stderr_full(dir.path(), args);
        let heard = super::run(dir.path(), args);
        assert_eq!(
            heard.status.code(),
            Some(code),
            "{args:?}: {}",
            stderr(&heard)
        );
        assert!(!heard.stderr.is_empty(), "{args:?} writes a diagnostic");
        assert_eq!(o.status.code(), Some(code), "{args:?}");
        // The answer but its timing ("took 21.3 us").
        let answer = |o: &std::process::Output| -> String {
            let text = String::from_utf8_lossy(&o.stdout).into_owned();
            let lines = text
                .lines()
                .filter(|l| !l.trim_start().starts_with("took "));
            lines.collect::<Vec<_>>().join("\n")
        };
        assert_eq!(answer(&o), answer(&heard), "{args:?}");
    }
}
