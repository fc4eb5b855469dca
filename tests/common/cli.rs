//! Running the real binary from the tests.

use std::path::Path;
use std::process::{Command, Output};

use serde_json::Value;

/// Runs `jamchart ARGS` in `dir`, without a backtrace or thread-count setting inherited from
/// the caller.
pub fn jamchart(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .current_dir(dir)
        .env_remove("RUST_BACKTRACE")
        .env_remove("RAYON_NUM_THREADS")
        .output()
        .expect("the binary runs")
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Sends `SIG<signal>` (e.g. "TERM") to the running `child`, waits for it and asserts the
/// signal ended it (a non-zero status).
pub fn kill_and_wait(child: &mut std::process::Child, signal: &str) {
    let sent = Command::new("kill")
        .args([format!("-{signal}"), child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let status = child.wait().unwrap();
    assert!(!status.success(), "SIG{signal}: {status:?}");
}

/// The repository root (scene files, config/paper.toml).
pub fn repo() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Stdout parsed as JSON, after checking the run succeeded.
pub fn json(o: &Output) -> Value {
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(o));
    serde_json::from_slice(&o.stdout).expect("stdout is JSON")
}

/// The example shaft as flags: a 25 mm steel shaft (r 12.5 mm), 0.4 kg, a 40 N push and an
/// 80 mm palm; the friction is the test's.
pub const SHAFT: [&str; 8] = [
    "--radius",
    "12.5",
    "--mass",
    "0.4",
    "--force",
    "40",
    "--palm-length",
    "80",
];

/// The longest run of digits in `s`: a number printed in full (1e300 as 301 digits, 1e-300
/// with 300 zeros) shows as a long run.
pub fn longest_digit_run(s: &str) -> usize {
    s.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

/// Runs `jamchart ARGS` in `dir` under a 4 GiB address-space cap (`ulimit -v`).
pub fn jamchart_capped(dir: &Path, args: &[&str]) -> Output {
    jamchart_under(dir, 4 << 20, args)
}

/// Runs `jamchart ARGS` in `dir` under an address-space cap of `kib` KiB (`ulimit -v`).
pub fn jamchart_under(dir: &Path, kib: u64, args: &[&str]) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {kib} && exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .current_dir(dir)
        .env_remove("RAYON_NUM_THREADS")
        .output()
        .unwrap()
}

/// A scene file `dir/scenes/NAME.toml` on the paper's parameters.
pub fn scene(dir: &Path, name: &str, body: &str) {
    let sc = dir.join("scenes");
    std::fs::create_dir_all(&sc).unwrap();
    let base = repo().join("config/paper.toml");
    let text = format!("title = \"t\"\nbase = \"{}\"\n{body}", base.display());
    std::fs::write(sc.join(format!("{name}.toml")), text).unwrap();
}

/// The `[chart]` of a jam map of `n` x `n` cells (regions and boundary).
pub fn jam_map(n: usize) -> String {
    format!(
        "[chart]\nkind = \"jam_map\"\nx_axis = {{ param = \"mu\", min = 0.1, max = 0.5, \
         count = {n} }}\ny_axis = {{ param = \"theta_deg\", min = 10.0, max = 70.0, \
         count = {n} }}\nlayers = [\"regions\", \"boundary\"]\n"
    )
}

/// `render NAME` of `dir/scenes/NAME.toml` into `dir/o`, under the 4 GiB cap.
pub fn render(dir: &Path, name: &str) -> Output {
    jamchart_capped(
        dir,
        &["render", name, "--scenes-dir", "scenes", "--out", "o"],
    )
}

/// `doc` without its wall times (`elapsed_s`), which differ from run to run.
pub fn timeless(mut doc: Value) -> Value {
    fn strip(v: &mut Value) {
        match v {
            Value::Object(map) => {
                map.remove("elapsed_s");
                map.values_mut().for_each(strip);
            }
            Value::Array(items) => items.iter_mut().for_each(strip),
            _ => {}
        }
    }
    strip(&mut doc);
    doc
}

/// The command line's JSON for `args` (with `--format json`), without wall times.
pub fn json_of(args: &[&str]) -> Value {
    let dir = tempfile::tempdir().unwrap();
    let mut all = args.to_vec();
    all.extend(["--format", "json"]);
    timeless(json(&jamchart(dir.path(), &all)))
}
