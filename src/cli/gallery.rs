//! The gallery page (`index.html`) of an output folder, written by `render` and by `accuracy
//! --out-dir`: the sections of the charts drawn now, and those of the page already in the
//! folder for charts drawn before ([`charts::gallery::index_html`]).

use std::path::Path;

use crate::charts::{self, gallery::Entry};
use crate::config;
use crate::error::Result;

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
