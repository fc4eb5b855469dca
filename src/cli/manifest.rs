//! `render --bless` and `render --check`: a manifest of the pictures' SHA-256 beside them, in
//! `sha256sum`'s format (the one of `charts/SHA256SUMS`), so a user locks the charts of their own
//! scenes in their CI the way this repository locks its own.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use sha2::{Digest, Sha256};

use crate::charts::Rendered;
use crate::error::{Error, Result};

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

/// Reads a manifest back as `sha256sum -c` reads it: `HASH  FILE` (text mode), `HASH *FILE`
/// (`sha256sum -b`), `SHA256 (FILE) = HASH` (`--tag`) and `HASH FILE` (BSD `-r`), hex in either
/// case, leading blanks, a CR before the newline, a backslash that escapes the name (`\\`,
/// `\n`, `\r`) and a `./` before it. A line of none of these forms (blank, a comment) is
/// skipped, as `sha256sum -c` skips it with a warning; a file listed twice with two hashes is
/// an error naming the line. `path` names the manifest in that error.
pub fn parse(text: &str, path: &Path) -> Result<Hashes> {
    let mut out = Hashes::new();
    // sha256sum takes the first checksum line's form, GNU or BSD `-r`, for every later line.
    let mut reversed = None;
    for (i, line) in text.split('\n').enumerate() {
        let line = line.strip_suffix('\r').unwrap_or(line);
        let Some((file, hash)) = checksum_line(line, &mut reversed) else {
            continue;
        };
        let file = file.trim_start_matches("./").to_string();
        match out.get(&file) {
            Some(h) if *h != hash => {
                return Err(Error::Config {
                    path: path.to_path_buf(),
                    line: i + 1,
                    column: 1,
                    message: format!(
                        "{} is listed twice with different hashes; keep one line per \
                         picture (render --bless writes the manifest afresh)",
                        crate::error::cut(&file)
                    ),
                });
            }
            _ => {
                out.insert(file, hash);
            }
        }
    }
    Ok(out)
}

/// Hex digits of a SHA-256.
const HEX_LEN: usize = 64;

/// One line's (file, lowercase hash), as coreutils' `split_3` reads it; None when the line is
/// not a checksum line. `reversed` is the form of the first checksum line (see [`parse`]).
fn checksum_line(line: &str, reversed: &mut Option<bool>) -> Option<(String, String)> {
    let line = line.trim_start_matches(|c: char| c.is_ascii_whitespace());
    let (escaped, line) = match line.strip_prefix('\\') {
        Some(rest) => (true, rest),
        None => (false, line),
    };
    let name = |raw: &str| {
        if escaped {
            unescape(raw)
        } else {
            Some(raw.to_string())
        }
    };
    if let Some(rest) = line.strip_prefix("SHA256") {
        // BSD tagged: the name runs to the last ')', whatever it holds.
        let rest = rest.strip_prefix(' ').unwrap_or(rest).strip_prefix('(')?;
        let (file, after) = rest.rsplit_once(')')?;
        let hash = after.trim_start_matches([' ', '\t']).strip_prefix('=')?;
        let hash = hash.trim_start_matches([' ', '\t']);
        return Some((name(file)?, hex(hash)?));
    }
    let hash = hex(line.get(..HEX_LEN)?)?;
    let rest = line[HEX_LEN..].strip_prefix([' ', '\t'])?;
    // `HASH  FILE` or `HASH *FILE`; anything else after one blank is BSD `-r`'s `HASH FILE`.
    let gnu = rest.len() > 1 && (rest.starts_with(' ') || rest.starts_with('*'));
    let file = match (gnu, *reversed.get_or_insert(!gnu)) {
        (true, false) => &rest[1..],
        (false, true) => rest,
        _ => return None,
    };
    Some((name(file)?, hash))
}

/// `h` as lowercase hex when it is 64 hex digits and nothing else.
fn hex(h: &str) -> Option<String> {
    (h.len() == HEX_LEN && h.bytes().all(|b| b.is_ascii_hexdigit())).then(|| h.to_ascii_lowercase())
}

/// A name escaped by sha256sum (`\\` a backslash, `\n` a newline, `\r` a CR); None for any
/// other escape.
fn unescape(raw: &str) -> Option<String> {
    let mut out = String::with_capacity(raw.len());
    let mut chars = raw.chars();
    while let Some(c) = chars.next() {
        out.push(match c {
            '\\' => match chars.next()? {
                '\\' => '\\',
                'n' => '\n',
                'r' => '\r',
                _ => return None,
            },
            c => c,
        });
    }
    Some(out)
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
        let hashed: Hashes = blessed
            .iter()
            .map(|(f, h)| (f.clone(), sha256_hex(h.as_bytes())))
            .collect();
        assert_eq!(parse(&text(&hashed), Path::new("S")).unwrap(), hashed);
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

    /// Every form `sha256sum -c` accepts reads as the same hash: a `sha256sum -b` manifest
    /// (`HASH *FILE`) and upper-case hex were read as changed pictures where `sha256sum -c`
    /// says OK. `tests/hostile` checks the same forms against `sha256sum -c` itself.
    #[test]
    fn every_form_sha256sum_reads_gives_the_same_hash() {
        let h = sha256_hex(b"abc");
        let up = h.to_ascii_uppercase();
        let read = |text: &str| parse(text, Path::new("S")).unwrap();
        for text in [
            format!("{h}  a.png\n"),
            format!("{h} *a.png\n"),
            format!("{up}  a.png\n"),
            format!("{h}  a.png\r\n"),
            format!("  {h}  ./a.png"),
            format!("{h} a.png\n"),
            format!("{h}\ta.png\n"),
            format!("SHA256 (a.png) = {up}\n"),
            format!("\\{h}  a.png\n"),
            format!("# pictures\n\n{h}  a.png\n"),
        ] {
            let hashes = read(&text);
            assert_eq!(hashes.len(), 1, "{text:?}: {hashes:?}");
            assert_eq!(hashes.get("a.png"), Some(&h), "{text:?}");
        }
        // Names as sha256sum escapes them, and lines it does not read.
        assert!(read(&format!("\\{h}  a\\\\b\\nc.png\n")).contains_key("a\\b\nc.png"));
        for text in [
            format!("{h}0  a.png\n"),
            format!("{}  a.png\n", &h[1..]),
            format!("\\{h}  a\\x.png\n"),
            // The first line is GNU's form; BSD -r's after it is not read (nor the reverse).
            format!("{h}  b.png\n{h} a.png\n"),
        ] {
            assert!(!read(&text).contains_key("a.png"), "{text:?}");
        }
        let twice = parse(
            &format!("{h}  a.png\n{}  a.png\n", sha256_hex(b"x")),
            Path::new("S"),
        );
        let msg = twice.unwrap_err().to_string();
        assert!(
            msg.contains("S:2:") && msg.contains("a.png is listed twice"),
            "{msg}"
        );
    }
}
