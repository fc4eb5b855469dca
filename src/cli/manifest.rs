//! `render --bless` and `render --check`: a manifest of the pictures' SHA-256 beside them, in
//! `sha256sum`'s format (the one of `charts/SHA256SUMS`), so a user locks the charts of their own
//! scenes in their CI the way this repository locks its own.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use sha2::{Digest, Sha256};

use crate::charts::Rendered;

/// The manifest's file name in the output folder.
pub const MANIFEST: &str = "SHA256SUMS";

/// Picture file name -> lowercase hex SHA-256, sorted by name.
pub type Hashes = BTreeMap<String, String>;

/// The SHA-256 of `bytes` as lowercase hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .fold(String::new(), |mut s, b| {
            let _ = write!(s, "{b:02x}");
            s
        })
}

/// The hash of every picture rendered (SVG, PNG and PDF, as requested), by file name.
pub fn hashes(rendered: &[Rendered]) -> Hashes {
    let mut out = Hashes::new();
    for r in rendered {
        for (ext, bytes) in [("svg", &r.svg), ("png", &r.png), ("pdf", &r.pdf)] {
            if let Some(b) = bytes {
                out.insert(format!("{}.{ext}", r.name), sha256_hex(b));
            }
        }
    }
    out
}

/// The manifest text: `HASH  FILE` lines sorted by file, as `sha256sum` writes them (so `cd OUT
/// && sha256sum -c SHA256SUMS` checks it too).
pub fn text(hashes: &Hashes) -> String {
    hashes.iter().map(|(f, h)| format!("{h}  {f}\n")).collect()
}

/// Reads a manifest's text back; lines that are not `HASH  FILE` (blank, comments) are skipped.
pub fn parse(text: &str) -> Hashes {
    text.lines()
        .filter_map(|l| l.split_once("  "))
        .map(|(h, f)| (f.trim().to_string(), h.trim().to_string()))
        .collect()
}

/// How one picture differs from the manifest.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Difference {
    /// Rendered with other bytes than blessed.
    Changed {
        /// The picture's file name.
        file: String,
        /// The hash in the manifest.
        blessed: String,
        /// The hash rendered now.
        now: String,
    },
    /// In the manifest, but no scene rendered it now (a scene removed or renamed, or a format
    /// left out).
    Missing {
        /// The picture's file name.
        file: String,
    },
    /// Rendered now, but not in the manifest (a scene added since the bless).
    NotBlessed {
        /// The picture's file name.
        file: String,
    },
}

impl Difference {
    /// The picture's file name.
    pub fn file(&self) -> &str {
        match self {
            Difference::Changed { file, .. }
            | Difference::Missing { file }
            | Difference::NotBlessed { file } => file,
        }
    }
}

/// Every difference between the manifest and the pictures rendered now, by file name.
pub fn compare(blessed: &Hashes, now: &Hashes) -> Vec<Difference> {
    let mut out = Vec::new();
    for (file, h) in now {
        match blessed.get(file) {
            Some(b) if b == h => {}
            Some(b) => out.push(Difference::Changed {
                file: file.clone(),
                blessed: b.clone(),
                now: h.clone(),
            }),
            None => out.push(Difference::NotBlessed { file: file.clone() }),
        }
    }
    for file in blessed.keys().filter(|f| !now.contains_key(*f)) {
        out.push(Difference::Missing { file: file.clone() });
    }
    out.sort_by(|a, b| a.file().cmp(b.file()));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sha256_of_abc_is_the_fips_vector() {
        // FIPS 180-2, appendix B.1.
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }

    #[test]
    fn manifest_text_parses_back_and_compare_names_each_kind_of_difference() {
        let blessed: Hashes = [("a.png", "11"), ("b.png", "22"), ("c.png", "33")]
            .map(|(f, h)| (f.to_string(), h.to_string()))
            .into();
        assert_eq!(parse(&text(&blessed)), blessed);
        assert!(compare(&blessed, &blessed).is_empty());
        let now: Hashes = [("a.png", "11"), ("b.png", "99"), ("d.png", "44")]
            .map(|(f, h)| (f.to_string(), h.to_string()))
            .into();
        assert_eq!(
            compare(&blessed, &now),
            [
                Difference::Changed {
                    file: "b.png".into(),
                    blessed: "22".into(),
                    now: "99".into()
                },
                Difference::Missing {
                    file: "c.png".into()
                },
                Difference::NotBlessed {
                    file: "d.png".into()
                },
            ]
        );
    }
}
