//! Files the tool reads as input (settings and scene files, a render's manifest, the gallery
//! page it extends): regular files of a bounded size, never a stream.
//!
//! A FIFO without a writer blocked the read forever, one with a writer deadlocked `render`
//! (its page is read before it is written), and a link to /dev/zero was read until memory ran
//! out. So a file is opened without blocking, refused unless it is a regular file, and read
//! no further than its cap.

use std::fs::FileType;
use std::io::Read;
use std::os::unix::fs::{FileTypeExt, OpenOptionsExt};
use std::path::Path;

use crate::error::{Error, Result};

/// Largest settings, scene or manifest file read, in bytes (4 MiB): the committed settings
/// and scenes are under 2 kB, and a manifest line is about 80 bytes (50,000 pictures).
pub const MAX_INPUT_BYTES: u64 = 4 << 20;

/// Largest gallery page (`index.html`) read to be extended, in bytes (64 MiB): every built-in
/// scene's page, read-offs included, is 0.74 MB (`render --out DIR`).
pub const MAX_PAGE_BYTES: u64 = 64 << 20;

/// What a file that is not regular is, in words.
fn kind(t: FileType) -> &'static str {
    if t.is_fifo() {
        "a FIFO"
    } else if t.is_dir() {
        "a directory"
    } else if t.is_char_device() {
        "a character device"
    } else if t.is_block_device() {
        "a block device"
    } else if t.is_socket() {
        "a socket"
    } else {
        "not a regular file"
    }
}

/// Reads `path`, a regular file of at most `max_bytes`, as UTF-8 text (see the module doc);
/// `advice` says what to do instead ("give a TOML file").
pub fn read_regular(path: &Path, max_bytes: u64, advice: &str) -> Result<String> {
    let refuse = |why: String| Error::io("read", path, std::io::Error::other(why));
    let file = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK | libc::O_NOCTTY)
        .open(path)
        .map_err(|e| Error::io("read", path, e))?;
    let meta = file.metadata().map_err(|e| Error::io("read", path, e))?;
    if !meta.is_file() {
        return Err(refuse(format!(
            "{}, not a regular file; {advice}",
            kind(meta.file_type())
        )));
    }
    let mut text = String::new();
    file.take(max_bytes + 1)
        .read_to_string(&mut text)
        .map_err(|e| Error::io("read", path, e))?;
    if text.len() as u64 > max_bytes {
        return Err(refuse(format!(
            "larger than {}; {advice}",
            crate::numbers::human_bytes(max_bytes)
        )));
    }
    Ok(text)
}

/// Whether `path` (links followed) is a regular file: Some(true), Some(false) for anything
/// else (a FIFO, a device, a directory), None when nothing is there.
pub fn regular_or_missing(path: &Path) -> Result<Option<bool>> {
    match std::fs::metadata(path) {
        Ok(m) => Ok(Some(m.is_file())),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(Error::io("read", path, e)),
    }
}
