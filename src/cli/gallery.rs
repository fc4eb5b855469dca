//! The gallery page (`index.html`) of an output folder, written by `render`, `sweep` and
//! `accuracy --out-dir`: the sections of the charts drawn now, and those of the page already in
//! the folder for charts drawn before ([`charts::gallery::index_html`]).
//!
//! Several commands may write into one folder at once. Each builds the page from what is in
//! the folder and writes it with its charts while it holds the folder's lock ([`lock_folder`]),
//! so the next one to take the lock finds the charts of the one before on disk: six sweeps and
//! a render at once each built the page from the folder as it found it, and the last page
//! written listed 1 to 6 of the 8 charts.

use std::os::fd::AsRawFd;
use std::path::Path;

use crate::charts::{self, gallery::Entry};
use crate::config;
use crate::error::{Error, Result};

/// The page of folder `out` with the sections of `entries` (drawn now, their files about to
/// be written): the previous page's sections of charts not drawn now, and a bare section for
/// any other picture in the folder.
pub(crate) fn page(out: &Path, entries: &[Entry]) -> Result<String> {
    let index = out.join("index.html");
    // A FIFO or /dev/null there is written through: it holds no page to extend.
    let previous = match config::regular_or_missing(&index)? {
        Some(true) => Some(config::read_regular(
            &index,
            config::MAX_PAGE_BYTES,
            "remove it, or write into another folder",
        )?),
        Some(false) | None => None,
    };
    let mut files: Vec<String> = std::fs::read_dir(out)
        .map(|dir| {
            dir.filter_map(|e| Some(e.ok()?.file_name().to_str()?.to_string()))
                .filter(|n| !n.starts_with('.'))
                .collect()
        })
        .unwrap_or_default();
    files.extend(entries.iter().flat_map(|e| e.files.iter().cloned()));
    files.sort();
    files.dedup();
    Ok(charts::gallery::index_html(
        entries,
        previous.as_deref(),
        &files,
    ))
}

/// An exclusive lock on an output folder for building its gallery page and writing it with the
/// files it lists ([`lock_folder`]); released when dropped (its descriptor closes).
pub(crate) struct FolderLock {
    _folder: Option<std::fs::File>,
}

/// Waits for the exclusive lock on folder `dir` (which exists) and takes it: `flock` on the
/// folder itself, so no lock file is left in it and a killed writer's lock goes with its
/// process. A folder whose file system keeps no locks is written unlocked, as before.
pub(crate) fn lock_folder(dir: &Path) -> Result<FolderLock> {
    let shown = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    let folder = std::fs::File::open(shown).map_err(|e| Error::io("open", shown, e))?;
    loop {
        // SAFETY: flock on a descriptor owned here, open for the call's duration.
        if unsafe { libc::flock(folder.as_raw_fd(), libc::LOCK_EX) } == 0 {
            return Ok(FolderLock {
                _folder: Some(folder),
            });
        }
        match std::io::Error::last_os_error() {
            e if e.kind() == std::io::ErrorKind::Interrupted => continue,
            // ENOLCK, EOPNOTSUPP, ...: no lock to be had there.
            _ => return Ok(FolderLock { _folder: None }),
        }
    }
}

/// The command line this process was started with, as a user would type it (`jamchart`
/// and each argument quoted for a POSIX shell where it needs it).
pub(crate) fn typed_command() -> String {
    let words = std::env::args().skip(1).map(|w| shell_word(&w));
    std::iter::once("jamchart".to_string())
        .chain(words)
        .collect::<Vec<_>>()
        .join(" ")
}

/// `w` quoted for a POSIX shell when it holds anything but plain characters.
pub(crate) fn shell_word(w: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "-_./=:,+@%".contains(c);
    if !w.is_empty() && w.chars().all(plain) {
        w.to_string()
    } else {
        format!("'{}'", w.replace('\'', "'\\''"))
    }
}
