//! Files the tool reads that are not regular files: a FIFO `index.html` with a reader
//! deadlocked `render` (the page was read before it was written), a FIFO `SHA256SUMS` hung
//! `--check`, and a link to /dev/zero there was read until memory ran out. Each is now
//! refused, or for the page written through, within seconds.

use std::ffi::CString;
use std::io::Read;
use std::os::unix::ffi::OsStrExt;
use std::path::Path;
use std::time::Duration;

use super::cli_util::stderr;
use super::run_within;

fn mkfifo(path: &Path) {
    let c = CString::new(path.as_os_str().as_bytes()).unwrap();
    // SAFETY: a valid C string and a mode.
    assert_eq!(unsafe { libc::mkfifo(c.as_ptr(), 0o644) }, 0, "{path:?}");
}

/// `render fig6 --out out ARGS` in `dir`, within 60 s.
fn render(dir: &Path, args: &[&str]) -> std::process::Output {
    let mut all = vec!["render", "fig6", "--out", "out", "--format", "svg"];
    all.extend(args);
    run_within(dir, &all, &[], Duration::from_secs(60))
}

/// Asserts `o` is a refusal (exit 2, no panic) whose message contains `says`.
fn refused(o: &std::process::Output, says: &str) {
    let e = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(e.starts_with("jamchart: ") && e.contains(says), "{e}");
}

#[test]
fn a_fifo_gallery_page_with_a_reader_is_written_through() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let page = out.join("index.html");
    mkfifo(&page);
    let reader = std::thread::spawn(move || {
        let mut text = String::new();
        std::fs::File::open(&page)
            .unwrap()
            .read_to_string(&mut text)
            .unwrap();
        text
    });
    let o = render(dir.path(), &["-q"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = reader.join().unwrap();
    assert!(
        text.contains("<html") && text.contains("fig6"),
        "{text:.200}"
    );
}

#[test]
fn a_manifest_that_is_not_a_regular_file_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let o = render(dir.path(), &["--bless", "-q"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let manifest = dir.path().join("out/SHA256SUMS");
    let fresh = |m: &Path| {
        let _ = std::fs::remove_file(m);
        let _ = std::fs::remove_dir(m);
    };
    fresh(&manifest);
    mkfifo(&manifest);
    refused(
        &render(dir.path(), &["--check"]),
        "a FIFO, not a regular file",
    );
    fresh(&manifest);
    std::os::unix::fs::symlink("/dev/zero", &manifest).unwrap();
    refused(&render(dir.path(), &["--check"]), "a character device");
    fresh(&manifest);
    std::fs::create_dir(&manifest).unwrap();
    refused(&render(dir.path(), &["--check"]), "a directory");
    fresh(&manifest);
    // Sparse: 5 GB of zeros that take no room on the disk.
    let f = std::fs::File::create(&manifest).unwrap();
    f.set_len(5 << 30).unwrap();
    refused(&render(dir.path(), &["--check"]), "larger than 4 MiB");
}

#[test]
fn a_gallery_page_too_large_to_be_one_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let f = std::fs::File::create(out.join("index.html")).unwrap();
    f.set_len(1 << 30).unwrap();
    refused(&render(dir.path(), &["-q"]), "larger than 64 MiB");
    // The refusal leaves the folder as it was: no picture written beside the page.
    assert!(!out.join("fig6.svg").exists());
}

#[test]
fn settings_and_scene_files_that_are_not_regular_files_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    mkfifo(&d.join("fifo.toml"));
    std::os::unix::fs::symlink("/dev/zero", d.join("zero.toml")).unwrap();
    for args in [
        &["solve", "--config", "fifo.toml"][..],
        &["solve", "--config", "zero.toml"][..],
        &["render", "fifo.toml", "--out", "o"][..],
        &["render", "zero.toml", "--out", "o"][..],
        &["design", "--x-target", "40", "--config", "fifo.toml"][..],
    ] {
        let o = run_within(d, args, &[], Duration::from_secs(60));
        refused(&o, "not a regular file");
    }
}

/// A file given where a settings or scene file belongs that is not one (`--config .env`,
/// `/proc/self/environ` as `--config` or as a scene's `base`) had its refused line quoted in
/// the message: a database password, the whole environment. The message names the file, line
/// and column, never what the file holds.
#[test]
fn a_file_that_is_not_a_settings_file_is_never_quoted() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let secret = "s3cr3t-Pa55w0rd";
    std::fs::write(
        d.join(".env"),
        format!("DATABASE_URL=postgres://admin:{secret}@db:5432/app\nDEBUG=1\n"),
    )
    .unwrap();
    for base in ["/proc/self/environ", ".env"] {
        let name = base.rsplit('/').next().unwrap().trim_start_matches('.');
        std::fs::write(
            d.join(format!("{name}.toml")),
            format!(
                "title = \"t\"\nbase = \"{base}\"\n[chart]\nkind = \"sweep\"\n\
                 axis = {{ param = \"mu\", min = 0.1, max = 0.5, count = 5 }}\n\
                 panels = [\"x_jam_mm\"]\nlayers = [\"statics\"]\n"
            ),
        )
        .unwrap();
    }
    let env = [("JAMCHART_TEST_SECRET", Path::new(secret))];
    for (args, file) in [
        (&["solve", "--config", ".env"][..], ".env"),
        (
            &["solve", "--config", "/proc/self/environ"][..],
            "/proc/self/environ",
        ),
        (
            &["render", "environ.toml", "--out", "o"][..],
            "/proc/self/environ",
        ),
        (&["render", "env.toml", "--out", "o"][..], ".env"),
        (
            &["design", "--x-target", "40", "--config", ".env"][..],
            ".env",
        ),
    ] {
        let o = run_within(d, args, &env, Duration::from_secs(60));
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
        // Refused where the file is read, at its line and column.
        assert!(e.starts_with("jamchart: "), "{args:?}: {e}");
        assert!(e.contains(&format!("{file}:1:")), "{args:?}: {e}");
        for content in [secret, "admin", "JAMCHART_TEST_SECRET", "postgres"] {
            assert!(!e.contains(content), "{args:?} quotes {content}: {e}");
        }
    }
}
