//! Scripted callers hand stdout over as /dev/null opened read-write (Python's
//! `subprocess.DEVNULL`, cron, systemd units, daemons). That descriptor was refused as a
//! closed stdout ("standard output is closed", exit 2), so every such caller failed.

use std::fs::OpenOptions;
use std::process::{Command, Stdio};

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
