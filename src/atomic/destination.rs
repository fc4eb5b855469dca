//! What an output path is, and whether jamchart may write there.
//!
//! A new name or a regular file is replaced atomically (temporary file, then rename). A FIFO, a
//! terminal and /dev/null are streams: they are written through, since they cannot be replaced
//! and a rename onto them would swap a system node for a regular file. Everything else is
//! refused and left untouched: a symbolic link (unless it leads to a stream, as /dev/stdout
//! does), a directory, a block device, a socket and any other character device (/dev/full,
//! /dev/mem, a disk).

use std::fs::{FileType, Metadata};
use std::os::unix::fs::{FileTypeExt, MetadataExt};
use std::path::Path;

use crate::error::{Error, Result};

/// How an output path is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Destination {
    /// Nothing there yet: created atomically.
    New,
    /// A regular file: replaced atomically.
    Regular,
    /// A FIFO, terminal or /dev/null (possibly behind a symbolic link): written through.
    Stream,
}

/// Linux character-device majors of terminals: 4 (tty0-63, ttyS*), 5 (/dev/tty, console,
/// ptmx) and 136-143 (Unix98 pseudo-terminals /dev/pts/*).
fn is_terminal_device(major: u32) -> bool {
    matches!(major, 4 | 5 | 136..=143)
}

/// /dev/null is character device 1:3 on Linux.
fn is_dev_null(major: u32, minor: u32) -> bool {
    (major, minor) == (1, 3)
}

/// A stream jamchart writes through: a FIFO, a terminal or /dev/null.
fn is_stream(m: &Metadata) -> bool {
    let t = m.file_type();
    if t.is_fifo() {
        return true;
    }
    if !t.is_char_device() {
        return false;
    }
    let (major, minor) = (libc::major(m.rdev()), libc::minor(m.rdev()));
    is_terminal_device(major) || is_dev_null(major, minor)
}

/// What a non-regular file is, in words, for the refusal.
fn describe(t: FileType, m: &Metadata) -> String {
    if t.is_dir() {
        "a directory".into()
    } else if t.is_block_device() {
        "a block device".into()
    } else if t.is_socket() {
        "a socket".into()
    } else if t.is_char_device() {
        format!(
            "a character device ({}:{}) that is neither a terminal nor /dev/null",
            libc::major(m.rdev()),
            libc::minor(m.rdev())
        )
    } else {
        "not a regular file".into()
    }
}

/// Classifies `path`, or refuses it with what it is and what to do.
pub fn check(path: &Path) -> Result<Destination> {
    let refuse = |what: String| Error::UnsafeOutput {
        path: path.to_path_buf(),
        what,
    };
    let m = match std::fs::symlink_metadata(path) {
        Ok(m) => m,
        // NotADirectory: a file stands where a parent directory should; check_parent says so.
        Err(e) if is_missing(&e) => {
            return match path.parent().filter(|p| !p.as_os_str().is_empty()) {
                Some(parent) => check_parent(parent).map(|()| Destination::New),
                None => Ok(Destination::New),
            };
        }
        Err(e) => return Err(Error::io("inspect", path, e)),
    };
    let t = m.file_type();
    if t.is_file() {
        return Ok(Destination::Regular);
    }
    if t.is_symlink() {
        // Followed only to a stream (/dev/stdout -> /proc/self/fd/1 -> a pipe or terminal):
        // writing through a link to a regular file would let a planted link aim the output
        // anywhere, and replacing the link would break it.
        return match std::fs::metadata(path) {
            Ok(target) if is_stream(&target) => Ok(Destination::Stream),
            Ok(target) if target.is_file() => Err(refuse(
                "a symbolic link to a regular file (give the target's own path)".into(),
            )),
            Ok(target) => Err(refuse(format!(
                "a symbolic link to {}",
                describe(target.file_type(), &target)
            ))),
            Err(_) => Err(refuse("a dangling symbolic link".into())),
        };
    }
    if is_stream(&m) {
        return Ok(Destination::Stream);
    }
    Err(refuse(describe(t, &m)))
}

/// The parent of a new output exists as a directory, or is missing (it will be created); any
/// other thing under that name is refused before anything is computed.
///
/// The directory that will hold the new entry must be writable, and a dangling symbolic link
/// is not a missing folder: `stability --out-dir` on either once failed only after computing.
fn check_parent(parent: &Path) -> Result<()> {
    let refuse = |what: &str| Error::UnsafeOutput {
        path: parent.to_path_buf(),
        what: what.into(),
    };
    match std::fs::metadata(parent) {
        Ok(m) if m.is_dir() => {
            let c = std::ffi::CString::new(parent.as_os_str().as_encoded_bytes())
                .map_err(|_| refuse("a path with a NUL byte"))?;
            // SAFETY: access reads the NUL-terminated path and nothing else.
            if unsafe { libc::access(c.as_ptr(), libc::W_OK | libc::X_OK) } != 0 {
                return Err(refuse(
                    "a folder this user cannot write into, and an output is to go inside it",
                ));
            }
            Ok(())
        }
        Ok(_) => Err(refuse("not a directory, and an output is to go inside it")),
        Err(e) if is_missing(&e) && std::fs::symlink_metadata(parent).is_ok() => Err(refuse(
            "a dangling symbolic link, where a folder for the output would be created",
        )),
        Err(e) if is_missing(&e) => match parent.parent() {
            Some(up) if !up.as_os_str().is_empty() => check_parent(up),
            _ => Ok(()),
        },
        Err(e) => Err(Error::io("inspect", parent, e)),
    }
}

fn is_missing(e: &std::io::Error) -> bool {
    use std::io::ErrorKind::{NotADirectory, NotFound};
    matches!(e.kind(), NotFound | NotADirectory)
}

/// Checks every path of an output set before anything is computed; a path named twice is
/// refused (the second file would silently replace the first).
pub fn check_all<'a>(paths: impl IntoIterator<Item = &'a Path>) -> Result<()> {
    let mut seen = std::collections::HashSet::new();
    for p in paths {
        if !seen.insert(p) {
            return Err(Error::OutputTwice { path: p.into() });
        }
        check(p)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::fs::symlink;

    #[test]
    fn regular_files_and_new_names_are_replaced_atomically() {
        let dir = tempfile::tempdir().unwrap();
        let f = dir.path().join("a.csv");
        assert_eq!(check(&f).unwrap(), Destination::New);
        std::fs::write(&f, "x").unwrap();
        assert_eq!(check(&f).unwrap(), Destination::Regular);
        assert_eq!(
            check(&dir.path().join("new/deeper/b.csv")).unwrap(),
            Destination::New
        );
    }

    #[test]
    fn dev_null_and_fifos_are_streams_other_devices_are_refused() {
        assert_eq!(check(Path::new("/dev/null")).unwrap(), Destination::Stream);
        let msg = check(Path::new("/dev/full")).unwrap_err().to_string();
        assert!(msg.contains("character device (1:7)"), "{msg}");
        let dir = tempfile::tempdir().unwrap();
        let fifo = dir.path().join("p");
        let ok = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(ok.success());
        assert_eq!(check(&fifo).unwrap(), Destination::Stream);
    }

    #[test]
    fn links_to_files_directories_and_nowhere_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("t.csv");
        std::fs::write(&target, "keep").unwrap();
        let cases = [
            ("to_file", target.clone(), "symbolic link to a regular file"),
            (
                "to_dir",
                dir.path().to_path_buf(),
                "symbolic link to a directory",
            ),
            (
                "dangling",
                dir.path().join("nowhere"),
                "dangling symbolic link",
            ),
            ("to_null", "/dev/null".into(), ""),
        ];
        for (name, to, says) in cases {
            let link = dir.path().join(name);
            symlink(&to, &link).unwrap();
            match check(&link) {
                Ok(d) => assert!(says.is_empty() && d == Destination::Stream, "{name}"),
                Err(e) => assert!(e.to_string().contains(says), "{name}: {e}"),
            }
        }
        std::fs::create_dir(dir.path().join("d")).unwrap();
        let msg = check(&dir.path().join("d")).unwrap_err().to_string();
        assert!(msg.contains("it is a directory"), "{msg}");
        let msg = check(&target.join("x.csv")).unwrap_err().to_string();
        assert!(msg.contains("not a directory"), "{msg}");
    }

    #[test]
    fn a_path_named_twice_is_refused() {
        let p = Path::new("out/a.csv");
        let msg = check_all([p, p]).unwrap_err().to_string();
        assert!(msg.contains("named twice"), "{msg}");
    }
}
