use super::*;

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn atomic_write_replaces_and_leaves_no_temp() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("a.svg");
    write_atomic(&p, b"one").unwrap();
    write_atomic(&p, b"two").unwrap();
    assert_eq!(std::fs::read(&p).unwrap(), b"two");
    assert_eq!(names(dir.path()), ["a.svg"]);
}

#[test]
fn missing_directories_are_created_and_removed_again_on_failure() {
    let dir = tempfile::tempdir().unwrap();
    let ok = dir.path().join("new/deeper/a.csv");
    write_atomic(&ok, b"x").unwrap();
    assert_eq!(std::fs::read(&ok).unwrap(), b"x");
    // The second output cannot be written (its name is a directory): the set's new
    // directories go again.
    let squat = dir.path().join("squat");
    std::fs::create_dir(&squat).unwrap();
    let a = dir.path().join("fresh/a.csv");
    let err = write_all(&[Output::bytes(&a, b"a"), Output::bytes(&squat, b"b")]).unwrap_err();
    assert!(err.to_string().contains("it is a directory"), "{err}");
    assert_eq!(names(dir.path()), ["new", "squat"]);
}

/// Regression ("a failed command leaves a partial set"): the second of three files
/// fails at its rename; the first, already renamed, must get its old version back and the
/// third must not appear.
#[test]
fn a_failed_command_leaves_the_output_folder_as_it_found_it() {
    let dir = tempfile::tempdir().unwrap();
    let [a, b, c] = ["a.csv", "b.svg", "c.png"].map(|n| dir.path().join(n));
    std::fs::write(&a, "old a").unwrap();
    let outputs = [(&a, b"new a"), (&b, b"new b"), (&c, b"new c")]
        .map(|(path, bytes)| Output::bytes(path, bytes.as_slice()));
    let staged = Set::begin(outputs.iter().map(|o| o.path)).unwrap();
    staged.stage_all(&outputs).unwrap();
    // A directory squats b's name after the checks (as a disk filling up would fail there).
    std::fs::create_dir(&b).unwrap();
    std::fs::write(b.join("inside"), "x").unwrap();
    let err = staged.commit().unwrap_err();
    assert!(err.to_string().contains("b.svg"), "{err}");
    assert_eq!(std::fs::read_to_string(&a).unwrap(), "old a");
    assert!(!c.exists());
    assert_eq!(
        names(dir.path()),
        ["a.csv", "b.svg"],
        "no temporary file left"
    );
}

/// A FIFO named `p` in `dir`.
fn mkfifo(dir: &Path) -> PathBuf {
    let fifo = dir.join("p");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(made.unwrap().success());
    fifo
}

#[test]
fn a_fifo_is_written_through_and_stays_a_fifo() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let fifo = mkfifo(dir.path());
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).unwrap())
    };
    let file = dir.path().join("f.csv");
    write_all(&[
        Output::bytes(&file, b"file"),
        Output::bytes(&fifo, b"through the pipe"),
    ])
    .unwrap();
    // Checked before the join: had the FIFO been replaced, the reader would stay blocked.
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
    assert_eq!(reader.join().unwrap(), b"through the pipe");
    assert_eq!(std::fs::read(&file).unwrap(), b"file");
    assert_eq!(names(dir.path()), ["f.csv", "p"]);
}

/// A FIFO that no process reads: the open waited for a reader without end (`solve --series
/// fifo` with nobody reading hung). It now fails after `FIFO_READER_WAIT`, naming the FIFO
/// and saying to start its reader, and leaves the FIFO in place.
#[test]
fn a_fifo_without_a_reader_is_an_error_not_a_wait_without_end() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let fifo = mkfifo(dir.path());
    let e = write_all(&[Output::bytes(&fifo, b"nobody reads")])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("start its reader first") && e.contains('p'),
        "{e}"
    );
    assert!(
        std::fs::symlink_metadata(&fifo)
            .unwrap()
            .file_type()
            .is_fifo()
    );
}

#[test]
fn a_symlink_is_refused_and_neither_it_nor_its_target_changes() {
    let dir = tempfile::tempdir().unwrap();
    let target = dir.path().join("target.csv");
    std::fs::write(&target, "keep").unwrap();
    let link = dir.path().join("link.csv");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let msg = write_atomic(&link, b"x").unwrap_err().to_string();
    assert!(msg.contains("symbolic link"), "{msg}");
    assert!(std::fs::symlink_metadata(&link).unwrap().is_symlink());
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep");
}

#[test]
fn a_failed_write_names_the_file_and_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("plain");
    std::fs::write(&file, "x").unwrap();
    let p = file.join("a.csv");
    let msg = write_atomic(&p, b"x").unwrap_err().to_string();
    assert!(
        msg.contains("plain") && msg.contains("not a directory"),
        "{msg}"
    );
    assert_eq!(names(dir.path()), ["plain"]);
}

/// A set staged a file at a time (`render` stages a map's cells CSV while it draws): when the
/// command fails before the commit (a later scene's error), dropping the set removes the staged
/// temporary and the folders the set created, and nothing reaches the final names.
#[test]
fn a_set_dropped_before_its_commit_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let [a, b] = ["new/sub/a.csv", "new/sub/b.svg"].map(|n| dir.path().join(n));
    let set = Set::begin([a.as_path(), b.as_path()]).unwrap();
    set.stage(Output::bytes(&a, b"cells")).unwrap();
    assert_eq!(names(&dir.path().join("new/sub")).len(), 1, "a's temporary");
    drop(set);
    assert_eq!(names(dir.path()), Vec::<String>::new());
}

/// Files staged out of order (as threads finish them) are renamed in the declared order: with
/// two names taken, the error is the first declared one's, and every rename is undone.
#[test]
fn a_set_commits_in_the_declared_order() {
    let dir = tempfile::tempdir().unwrap();
    let [a, b, c] = ["a.csv", "b.svg", "c.png"].map(|n| dir.path().join(n));
    std::fs::write(&a, "old a").unwrap();
    let set = Set::begin([a.as_path(), b.as_path(), c.as_path()]).unwrap();
    for (p, bytes) in [(&c, "new c"), (&a, "new a"), (&b, "new b")] {
        set.stage(Output::bytes(p, bytes.as_bytes())).unwrap();
    }
    // Directories take b's and c's names after the checks.
    for squat in [&b, &c] {
        std::fs::create_dir(squat).unwrap();
        std::fs::write(squat.join("inside"), "x").unwrap();
    }
    let err = set.commit().unwrap_err();
    assert!(err.to_string().contains("b.svg"), "{err}");
    assert_eq!(std::fs::read_to_string(&a).unwrap(), "old a");
    assert_eq!(names(dir.path()), ["a.csv", "b.svg", "c.png"]);
}
