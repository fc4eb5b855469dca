//! Temporary files that never outlive the process: registered while they exist, removed on
//! SIGINT, SIGTERM and SIGHUP, and swept when a dead process left some behind. The folders a
//! write creates for its outputs are registered too, until the write is done: a signal
//! removes them when they are still empty (a SIGHUP once left an empty output folder).
//!
//! Names are `.<final name>.<pid>.<n>.tmp` in the directory of the final file (the rename must
//! not cross file systems); the pid says whose they are, so a sweep removes only those whose
//! process is gone.

use std::collections::HashSet;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, MutexGuard, Once};

/// Every temporary file of this process that exists now.
static LIVE: Mutex<Option<HashSet<PathBuf>>> = Mutex::new(None);

/// The registry, locked; a panic elsewhere never makes it unusable.
pub(super) fn lock() -> MutexGuard<'static, Option<HashSet<PathBuf>>> {
    LIVE.lock().unwrap_or_else(|e| e.into_inner())
}

/// The folders this process created for outputs it has not finished writing, outermost first.
static CREATED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The created folders, locked; a panic elsewhere never makes them unusable.
fn created() -> MutexGuard<'static, Vec<PathBuf>> {
    CREATED.lock().unwrap_or_else(|e| e.into_inner())
}

/// Creates folder `dir` and registers it, under the lock, so that a signal sees every folder
/// that exists.
pub(super) fn create_dir(dir: &Path) -> std::io::Result<()> {
    let mut created = created();
    std::fs::create_dir(dir)?;
    created.push(dir.to_path_buf());
    Ok(())
}

/// Unregisters `dirs` (their write is over: they hold its files, or were removed).
pub(super) fn forget_dirs(dirs: &[PathBuf]) {
    created().retain(|d| !dirs.contains(d));
}

/// What a signal leaves undone: removes every registered temporary file, then every
/// registered folder that is empty, deepest first (only those under `within` when given: a
/// test's own). Holds the registry (a commit in progress finishes first, and no temporary is
/// created after it) and returns it held.
fn remove_leftovers(within: Option<&Path>) -> MutexGuard<'static, Option<HashSet<PathBuf>>> {
    let mine = |p: &Path| within.is_none_or(|w| p.starts_with(w));
    let live = lock();
    for p in live.iter().flatten().filter(|p| mine(p)) {
        let _ = std::fs::remove_file(p);
    }
    let mut dirs = created();
    let (gone, kept): (Vec<PathBuf>, Vec<PathBuf>) = dirs.drain(..).partition(|d| mine(d));
    *dirs = kept;
    // remove_dir removes only an empty folder: one that a finished write filled stays.
    for d in gone.iter().rev() {
        let _ = std::fs::remove_dir(d);
    }
    live
}

/// Installs the signal handler once: on SIGINT, SIGTERM or SIGHUP it removes the temporary
/// files and then lets the signal take its default effect (the exit status says the signal).
///
/// The handler holds the registry while it removes and exits, so no temporary file is created
/// after it started, and a commit in progress (which holds the registry too) finishes first.
pub fn install_signal_cleanup() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // A file-size limit (`ulimit -f`) sends SIGXFSZ, whose default kills the process and
        // left `.tmp` files behind (`render fig3`); ignored, the write fails with EFBIG, an I/O
        // error like a full disk, and the temporary is removed as for any failed write.
        // SAFETY: SIG_IGN installs no handler code; nothing else in the process sets SIGXFSZ.
        unsafe {
            libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
        }
        use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
        let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
            return; // no handler: temporaries are still swept by the next run
        };
        // Without a thread to spare (`ulimit -u`) the run goes on without the cleanup handler,
        // as when the handler cannot be registered: the next run sweeps the temporaries.
        let _ = std::thread::Builder::new().spawn(move || {
            if let Some(sig) = signals.forever().next() {
                let _live = remove_leftovers(None);
                let _ = signal_hook::low_level::emulate_default_handler(sig);
                // Not reached for these three signals; exit as a shell would report them.
                std::process::exit(128 + sig);
            }
        });
    });
}

/// A fresh name `.<name>.<pid>.<n>.tmp` beside `dest`.
pub(super) fn temp_name(dest: &Path) -> PathBuf {
    let dir = dest
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = dest
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    // Unique per call, not only per process: two threads may write into one directory.
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    dir.join(format!(".{name}.{}.{n}.tmp", std::process::id()))
}

/// A registered temporary file, removed when dropped unless [`Temp::keep`] said it was renamed.
pub(super) struct Temp {
    pub(super) path: PathBuf,
    renamed: bool,
}

impl Temp {
    /// Creates `.<name>.<pid>.<n>.tmp` beside `dest` (never following a file already there).
    pub(super) fn create(dest: &Path) -> std::io::Result<(Temp, File)> {
        let path = temp_name(dest);
        // Created under the registry's lock, so the signal handler sees every file that exists.
        let mut live = lock();
        let file = File::options().write(true).create_new(true).open(&path)?;
        live.get_or_insert_with(HashSet::new).insert(path.clone());
        Ok((
            Temp {
                path,
                renamed: false,
            },
            file,
        ))
    }

    /// Marks the file as renamed away (the registry entry goes, the file is not removed).
    pub(super) fn keep(mut self) {
        self.renamed = true;
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        let mut live = lock();
        if !self.renamed {
            let _ = std::fs::remove_file(&self.path);
        }
        if let Some(set) = live.as_mut() {
            set.remove(&self.path);
        }
    }
}

/// The pid in a temporary file name of ours, `.<name>.<pid>.<n>.tmp`.
fn temp_owner(file_name: &str) -> Option<u32> {
    let rest = file_name.strip_prefix('.')?.strip_suffix(".tmp")?;
    let mut parts = rest.rsplitn(3, '.');
    let n = parts.next()?;
    let pid = parts.next()?;
    let name = parts.next()?;
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    (digits(n) && !name.is_empty()).then_some(())?;
    pid.parse().ok().filter(|_| digits(pid))
}

/// Whether process `pid` is gone; None where /proc cannot say (then nothing is swept).
fn is_dead(pid: u32) -> Option<bool> {
    Path::new("/proc/self")
        .exists()
        .then(|| !Path::new("/proc").join(pid.to_string()).exists())
}

/// Removes temporary files of our naming in `dir` whose process is gone (a run killed by
/// SIGKILL, or one from before signals were handled); returns how many.
pub fn sweep_stale(dir: &Path) -> usize {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let me = std::process::id();
    let mut removed = 0;
    for e in entries.flatten() {
        let Some(pid) = e.file_name().to_str().and_then(temp_owner) else {
            continue;
        };
        let regular = e.file_type().is_ok_and(|t| t.is_file());
        if regular
            && pid != me
            && is_dead(pid) == Some(true)
            && std::fs::remove_file(e.path()).is_ok()
        {
            removed += 1;
        }
    }
    removed
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression: a SIGHUP while a render wrote into a folder it had
    /// created removed the temporaries but left the empty folder. What the handler does,
    /// short of exiting, removes both; a folder that holds another file stays.
    #[test]
    fn a_signal_removes_the_empty_folders_a_write_created() {
        let dir = tempfile::tempdir().unwrap();
        let (outer, inner) = (dir.path().join("a"), dir.path().join("a/b"));
        create_dir(&outer).unwrap();
        create_dir(&inner).unwrap();
        let (temp, _file) = Temp::create(&inner.join("fig3.png")).unwrap();
        assert!(temp.path.exists());
        let kept = dir.path().join("kept");
        create_dir(&kept).unwrap();
        std::fs::write(kept.join("other.txt"), "x").unwrap();
        drop(remove_leftovers(Some(dir.path())));
        assert!(
            !temp.path.exists() && !outer.exists(),
            "a/b or a left behind"
        );
        assert!(kept.join("other.txt").exists());
        // Nothing registered is left for a later signal.
        assert!(!created().iter().any(|d| d.starts_with(dir.path())));
        temp.keep();
    }

    #[test]
    fn temp_names_are_recognised_with_their_owner() {
        assert_eq!(temp_owner(".fig3.json.5971.12.tmp"), Some(5971));
        assert_eq!(temp_owner(".a.1.0.tmp"), Some(1));
        for not_ours in [
            "fig3.json.5971.12.tmp",
            ".fig3.json.tmp",
            "..1.2.tmp",
            ".x.ab.2.tmp",
            ".x.1.2.tmpx",
            ".x.1..tmp",
        ] {
            assert_eq!(temp_owner(not_ours), None, "{not_ours}");
        }
    }

    #[test]
    fn sweep_removes_only_dead_processes_temporaries() {
        let dir = tempfile::tempdir().unwrap();
        let mut child = std::process::Command::new("true").spawn().unwrap();
        let dead = child.id();
        child.wait().unwrap();
        let stale = dir.path().join(format!(".fig3.json.{dead}.12.tmp"));
        let mine = dir
            .path()
            .join(format!(".fig3.svg.{}.0.tmp", std::process::id()));
        let other = dir.path().join("fig3.json");
        for p in [&stale, &mine, &other] {
            std::fs::write(p, "x").unwrap();
        }
        assert_eq!(sweep_stale(dir.path()), 1);
        assert!(!stale.exists() && mine.exists() && other.exists());
    }

    #[test]
    fn a_dropped_temp_is_removed_and_unregistered() {
        let dir = tempfile::tempdir().unwrap();
        let (t, _f) = Temp::create(&dir.path().join("a.csv")).unwrap();
        let p = t.path.clone();
        assert!(p.exists() && lock().as_ref().unwrap().contains(&p));
        drop(t);
        assert!(!p.exists() && !lock().as_ref().unwrap().contains(&p));
    }
}
