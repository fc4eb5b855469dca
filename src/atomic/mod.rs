//! Output files: written whole or not at all, as one set, never onto a special file or a link.
//!
//! Every command writes its files through [`write_all`], or a [`Set`] (the same steps, with
//! files staged one at a time as they are made):
//! 1. each path is checked ([`destination::check`]): a new name or a regular file is replaced,
//!    a FIFO, terminal or /dev/null is written through, anything else is refused;
//! 2. every regular file is written to a temporary file beside it, and its write-back to the
//!    disk started (the set's [`SyncPolicy`]; step 4 waits for it);
//! 3. the streams are written (by a [`Set`], each as it is staged);
//! 4. the temporary files' data is synced to the disk, one file after another (the write-back
//!    started in step 2 has done most of it; the first sync commits the file system's journal
//!    for all), then the temporary files are renamed over their final names, each old file kept
//!    aside (a hard link) until all renames succeeded, and put back if one fails.
//!
//! So a command that fails leaves the regular files as it found them (a stream may have been
//! written: it cannot be taken back), and a directory this set created is removed again.
//! Temporary files are registered while they exist and removed on SIGINT, SIGTERM and SIGHUP
//! ([`install_signal_cleanup`]); ones left by a killed process are swept by the next write
//! into the same directory ([`cleanup::sweep_stale`]).
//!
//! Hand-written rather than `tempfile::NamedTempFile::persist`: tempfile creates its files with
//! mode 0600, and charts and data are ordinary files other users should read.

pub mod cleanup;
pub mod destination;

use std::collections::HashSet;
use std::io::Write;
use std::ops::DerefMut;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

pub use cleanup::install_signal_cleanup;
pub use destination::{Destination, check_all};

use crate::error::{Error, Result};
use cleanup::Temp;

/// One output: where and what.
#[derive(Clone, Copy)]
pub struct Output<'a> {
    /// The final path.
    pub path: &'a Path,
    /// The content.
    pub content: Content<'a>,
}

impl<'a> Output<'a> {
    /// `bytes` to `path`.
    pub fn bytes(path: &'a Path, bytes: &'a [u8]) -> Self {
        Output {
            path,
            content: Content::Bytes(bytes),
        }
    }
}

/// What an output holds: its bytes, or a writer that makes them as it writes (a map's cells
/// CSV, hundreds of MB at 10^7 cells, never held whole in memory; its temporary file is
/// renamed into place with the rest of the set, as any other).
#[derive(Clone, Copy)]
pub enum Content<'a> {
    /// The whole content.
    Bytes(&'a [u8]),
    /// Writes the content into the writer it is given (buffered here).
    Writer(&'a dyn Writes),
}

/// Content made as it is written (see [`Content::Writer`]).
pub trait Writes: Sync {
    /// Writes the whole content to `out`.
    fn write_into(&self, out: &mut dyn Write) -> std::io::Result<()>;
}

impl Content<'_> {
    /// Writes the content to `out` and flushes it.
    fn write_to(&self, out: &mut dyn Write) -> std::io::Result<()> {
        match self {
            Content::Bytes(b) => out.write_all(b)?,
            Content::Writer(w) => {
                // 64 kiB: a few hundred rows of a CSV per write call.
                let mut buffered = std::io::BufWriter::with_capacity(1 << 16, &mut *out);
                w.write_into(&mut buffered)?;
                buffered.flush()?;
            }
        }
        out.flush()
    }
}

/// Writes one file atomically (see the module doc): a set of one.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    write_all(&[Output::bytes(path, bytes)])
}

/// Writes every output, or none of the regular files (see the module doc).
pub fn write_all(outputs: &[Output]) -> Result<()> {
    let set = Set::begin(outputs.iter().map(|o| o.path))?;
    set.stage_all(outputs)?;
    set.commit()
}

/// The environment variable of a test hook: milliseconds to wait between staging a set (its
/// folders created, its temporaries written) and committing it, at most `MAX_PAUSE_MS`.
/// A test of the binary sends a signal in that window, which a render otherwise passes
/// through in about a millisecond. Unset, empty or not a number: no pause.
pub const PAUSE_VAR: &str = "JAMCHART_TEST_PAUSE_AFTER_STAGING_MS";

/// 60 s: longer than any test waits for a signal to land, short enough that a stray setting
/// cannot hold a write for long.
const MAX_PAUSE_MS: u64 = 60_000;

fn pause_for_tests() {
    let ms = std::env::var(PAUSE_VAR)
        .ok()
        .and_then(|v| v.trim().parse::<u64>().ok())
        .map_or(0, |ms| ms.min(MAX_PAUSE_MS));
    if ms > 0 {
        std::thread::sleep(std::time::Duration::from_millis(ms));
    }
}

/// Creates the missing parent directories of `paths`; returns those it created, outermost
/// first.
fn create_parents(paths: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let mut created: Vec<PathBuf> = Vec::new();
    for path in paths {
        let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) else {
            continue;
        };
        let missing: Vec<&Path> = parent.ancestors().take_while(|a| !a.exists()).collect();
        for d in missing.into_iter().rev() {
            if d.as_os_str().is_empty() {
                continue;
            }
            match cleanup::create_dir(d) {
                Ok(()) => created.push(d.to_path_buf()),
                // `a/b/..` reads as missing until `a/b` exists: nothing new to remove later.
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && d.is_dir() => {}
                Err(e) => {
                    remove_dirs(&created);
                    return Err(Error::io("create the directory", d, e));
                }
            }
        }
    }
    Ok(created)
}

/// Removes the folders a set created, deepest first (one that is not empty, because someone
/// else wrote there, stays), and unregisters them.
fn remove_dirs(created: &[PathBuf]) {
    for d in created.iter().rev() {
        let _ = std::fs::remove_dir(d);
    }
    cleanup::forget_dirs(created);
}

/// A set of outputs written as one ([`write_all`] in steps): declared first, staged from any
/// thread as each is made, committed together. `render` stages a map's cells CSV while the
/// map's pictures are still being drawn, so the longest file is written beside the drawing
/// rather than after it.
///
/// Dropped without a commit, it removes its temporary files and the folders it created.
pub struct Set {
    /// The declared paths, in the order their files are renamed into place.
    order: Vec<PathBuf>,
    /// The folders [`Set::begin`] created, outermost first.
    created: Vec<PathBuf>,
    /// The folders whose stale temporaries were swept.
    swept: Mutex<HashSet<PathBuf>>,
    /// Staged regular files: their place in `order`, temporary file and final path.
    staged: Mutex<Vec<(usize, Temp, PathBuf)>>,
    /// What the commit syncs before the renames.
    sync: SyncPolicy,
    /// The paths of every output staged so far, streams too.
    given: Mutex<HashSet<PathBuf>>,
}

/// The environment variable that chooses the [`SyncPolicy`]: `data` (the default) or `none`.
pub const SYNC_VAR: &str = "JAMCHART_SYNC";

/// What a set makes sure of against a power loss, beyond the renames that make it whole under a
/// kill: from [`SYNC_VAR`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SyncPolicy {
    /// Each temporary file's data is on the disk before any file of the set is renamed into
    /// place: after a power loss every file is its old or its new version, whole (the default).
    /// A staged file's write-back starts at once, without waiting; the commit then syncs the
    /// files one after another, which costs the wait for the last bytes and one journal commit.
    Data,
    /// No sync: the renames still make the set whole under a kill, but a power loss soon after
    /// can leave a file just written empty or short, as most tools that draw charts leave it.
    /// For scratch output that is rendered again anyway (benchmarks, a CI check).
    None,
}

impl SyncPolicy {
    /// The policy [`SYNC_VAR`] names; unset or empty is [`SyncPolicy::Data`].
    pub fn from_env() -> Result<Self> {
        match std::env::var(SYNC_VAR) {
            Err(std::env::VarError::NotPresent) => Ok(SyncPolicy::Data),
            Ok(v) if v.is_empty() || v == "data" => Ok(SyncPolicy::Data),
            Ok(v) if v == "none" => Ok(SyncPolicy::None),
            Ok(v) => Err(Error::invalid(
                SYNC_VAR,
                v,
                "give data (sync each file before the renames, the default) or none (renames only)",
            )),
            Err(std::env::VarError::NotUnicode(v)) => Err(Error::invalid(
                SYNC_VAR,
                v.to_string_lossy(),
                "give data or none",
            )),
        }
    }
}

/// Starts the write-back of `file`'s dirty pages to the disk and returns at once (Linux's
/// `sync_file_range` with `SYNC_FILE_RANGE_WRITE`; elsewhere nothing): the sync at the commit
/// then finds most of the data written. A failure here is not reported: the sync reports it.
fn start_write_back(file: &std::fs::File) {
    #[cfg(target_os = "linux")]
    {
        use std::os::fd::AsRawFd;
        // SAFETY: a plain system call on an open descriptor; no memory is passed.
        unsafe {
            libc::sync_file_range(file.as_raw_fd(), 0, 0, libc::SYNC_FILE_RANGE_WRITE);
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = file;
}

impl Set {
    /// Step 1 of the module doc for every path the set will write, and their missing folders
    /// created.
    pub fn begin<'p>(paths: impl IntoIterator<Item = &'p Path>) -> Result<Set> {
        let order: Vec<PathBuf> = paths.into_iter().map(Path::to_path_buf).collect();
        let sync = SyncPolicy::from_env()?;
        check_all(order.iter().map(PathBuf::as_path))?;
        let created = create_parents(&order)?;
        Ok(Set {
            order,
            created,
            sync,
            swept: Mutex::new(HashSet::new()),
            staged: Mutex::new(Vec::new()),
            given: Mutex::new(HashSet::new()),
        })
    }

    /// Steps 2 and 3 for one output: a regular file is written to its temporary file and its
    /// write-back started, a stream is written now.
    pub fn stage(&self, output: Output) -> Result<()> {
        lock_ignoring_poison(&self.given).insert(output.path.to_path_buf());
        match destination::check(output.path)? {
            Destination::Stream => write_stream(output.path, output.content),
            Destination::New | Destination::Regular => self.stage_file(output),
        }
    }

    /// Whether an output to `path` was staged already ([`Set::stage`]; a stream is written
    /// then).
    pub fn has(&self, path: &Path) -> bool {
        lock_ignoring_poison(&self.given).contains(path)
    }

    /// Steps 2 and 3 for `outputs`: the regular files written in parallel, each write-back
    /// started as its file is written, then the streams. The first
    /// failure in output order is reported, so the message does not depend on the thread
    /// count.
    pub fn stage_all(&self, outputs: &[Output]) -> Result<()> {
        use rayon::prelude::*;
        let mut regular = Vec::new();
        let mut streams = Vec::new();
        for o in outputs {
            lock_ignoring_poison(&self.given).insert(o.path.to_path_buf());
            match destination::check(o.path)? {
                Destination::Stream => streams.push(o),
                Destination::New | Destination::Regular => regular.push(o),
            }
        }
        let written: Vec<Result<()>> = regular.par_iter().map(|o| self.stage_file(**o)).collect();
        written.into_iter().collect::<Result<()>>()?;
        for o in streams {
            write_stream(o.path, o.content)?;
        }
        Ok(())
    }

    /// Writes a regular file's temporary and starts its write-back ([`Set::commit`] syncs it).
    fn stage_file(&self, o: Output) -> Result<()> {
        let dir = o.path.parent().filter(|d| !d.as_os_str().is_empty());
        let dir = dir.unwrap_or(Path::new("."));
        if lock_ignoring_poison(&self.swept).insert(dir.to_path_buf()) {
            cleanup::sweep_stale(dir);
        }
        let (temp, mut f) = Temp::create(o.path).map_err(|e| Error::io("write", o.path, e))?;
        o.content
            .write_to(&mut f)
            .map_err(|e| Error::io("write", o.path, e))?;
        if self.sync == SyncPolicy::Data {
            start_write_back(&f);
        }
        let place = self.order.iter().position(|p| p == o.path);
        lock_ignoring_poison(&self.staged).push((
            place.unwrap_or(usize::MAX),
            temp,
            o.path.to_path_buf(),
        ));
        Ok(())
    }

    /// Step 4 of the module doc, under the registry's lock so that a signal waits for it: the
    /// staged files renamed into place in the declared order.
    pub fn commit(mut self) -> Result<()> {
        pause_for_tests();
        let mut files = std::mem::take(lock_ignoring_poison(&self.staged).deref_mut());
        files.sort_by(|a, b| (a.0, &a.2).cmp(&(b.0, &b.2)));
        if self.sync == SyncPolicy::Data {
            // Every file is synced before the first rename, in the declared order, and the
            // first failure is reported (the temporaries go with the set). One after another:
            // the write-back is under way since each file was staged, and the first sync's
            // journal commit holds the other files' metadata too. Each temporary is opened
            // again for it, so a set of many files holds no descriptors open until its commit.
            for (_, temp, dest) in &files {
                let synced = std::fs::File::open(&temp.path).and_then(|f| f.sync_data());
                synced.map_err(|e| Error::io("write", dest.as_path(), e))?;
            }
        }
        let live = cleanup::lock();
        // Per renamed file: its final path and where its old version is kept (None: it was new).
        let mut done: Vec<(&Path, Option<PathBuf>)> = Vec::new();
        let mut failure = None;
        for (_, temp, dest) in &files {
            let kept = match keep_old(dest) {
                Ok(k) => k,
                Err(e) => {
                    failure = Some(e);
                    break;
                }
            };
            if let Err(e) = std::fs::rename(&temp.path, dest) {
                if let Some(k) = kept {
                    let _ = std::fs::remove_file(k);
                }
                failure = Some(Error::io("write", dest.as_path(), e));
                break;
            }
            done.push((dest, kept));
        }
        for (dest, kept) in done {
            match (&failure, kept) {
                // Undo: the old version comes back (an atomic replace), a new file goes.
                (Some(_), Some(k)) => drop(std::fs::rename(k, dest)),
                (Some(_), None) => drop(std::fs::remove_file(dest)),
                (None, Some(k)) => drop(std::fs::remove_file(k)),
                (None, None) => {}
            }
        }
        drop(live);
        if let Some(e) = failure {
            // The temporaries go, then the folders this set created (`Drop`).
            drop(files);
            return Err(e);
        }
        for (_, temp, _) in files {
            temp.keep();
        }
        // The folders hold the set's files now: they stay.
        cleanup::forget_dirs(&std::mem::take(&mut self.created));
        Ok(())
    }
}

impl Drop for Set {
    fn drop(&mut self) {
        // Temporaries first, so that the folders they were in are empty.
        lock_ignoring_poison(&self.staged).clear();
        remove_dirs(&self.created);
    }
}

/// `m` locked; a panic on another thread never makes it unusable.
fn lock_ignoring_poison<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// How long a FIFO's reader has to open it: a reader started beside jamchart (`--series
/// >(gzip > s.gz)`, a script's `cat fifo &`) opens it within milliseconds.
pub const FIFO_READER_WAIT: std::time::Duration = std::time::Duration::from_secs(5);

/// Writes through a FIFO, terminal or /dev/null (never creating or truncating anything).
///
/// Opened without blocking: a FIFO that no process reads held the open, and the run, until a
/// reader came, which may be never. The open is retried for [`FIFO_READER_WAIT`]; then the
/// error says to start the reader first. Once open, the writes block as usual.
fn write_stream(path: &Path, content: Content) -> Result<()> {
    use std::os::unix::fs::OpenOptionsExt;
    let open = || {
        std::fs::File::options()
            .write(true)
            // Never become the controlling terminal of this process.
            .custom_flags(libc::O_NOCTTY | libc::O_NONBLOCK)
            .open(path)
    };
    let t0 = std::time::Instant::now();
    let mut file = loop {
        match open() {
            Err(e) if e.raw_os_error() == Some(libc::ENXIO) => {
                if t0.elapsed() >= FIFO_READER_WAIT {
                    let why = format!(
                        "no process opened this FIFO to read it within {} s; start its reader \
                         first, or give a file",
                        FIFO_READER_WAIT.as_secs()
                    );
                    return Err(Error::io("write", path, std::io::Error::other(why)));
                }
                std::thread::sleep(std::time::Duration::from_millis(10));
            }
            r => break r.map_err(|e| Error::io("write", path, e))?,
        }
    };
    rustix::fs::fcntl_setfl(&file, rustix::fs::OFlags::empty())
        .map_err(|e| Error::io("write", path, e.into()))?;
    content
        .write_to(&mut file)
        .map_err(|e| Error::io("write", path, e))
}

/// Keeps the old version of `dest` under a temporary name (a hard link, or a copy where the
/// file system has none) until the whole set is in place; None when there is no old version.
fn keep_old(dest: &Path) -> Result<Option<PathBuf>> {
    if !dest.is_file() {
        return Ok(None);
    }
    let keep = cleanup::temp_name(dest);
    std::fs::hard_link(dest, &keep)
        .or_else(|_| std::fs::copy(dest, &keep).map(drop))
        .map_err(|e| Error::io("keep the old version of", dest, e))?;
    Ok(Some(keep))
}

#[cfg(test)]
mod tests;
