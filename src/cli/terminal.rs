//! Text bound for a terminal. File names, paths, scene titles and values a user typed are
//! echoed in answers and messages; a control character among them (`ESC [ 2 J` in a scene
//! file's name clears the screen, `ESC ] 52` writes the clipboard) reached the terminal raw.
//! Every control character but newline and tab is written as an escape instead, and so are
//! the bidirectional controls that reorder what a line shows.

use std::borrow::Cow;
use std::io::Write;

/// Whether `c` is written as an escape: C0 and C1 controls (but newline and tab), DEL, and the
/// bidirectional embeddings, overrides and isolates (U+202A-U+202E, U+2066-U+2069).
fn escaped(c: char) -> bool {
    (c.is_control() && c != '\n' && c != '\t')
        || ('\u{202a}'..='\u{202e}').contains(&c)
        || ('\u{2066}'..='\u{2069}').contains(&c)
}

/// `text` with each character [`escaped`] written as Rust writes it (`\u{1b}`), the rest as
/// it is; borrowed when nothing needs it.
pub(crate) fn safe(text: &str) -> Cow<'_, str> {
    if !text.chars().any(escaped) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 16);
    for c in text.chars() {
        if escaped(c) {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// Writes `text` and a newline to stderr, control characters escaped ([`safe`]): every
/// diagnostic (a warning, an error, a note) goes through here.
///
/// A failed write is dropped: `eprintln!` panicked on an unwritable stderr (`2>/dev/full`), so a
/// warning cost the answer on stdout and turned exit 0 into 101. A diagnostic nobody can read
/// changes neither the answer nor the exit code.
pub(crate) fn diagnostic(text: &str) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(err, "{}", safe(text)).and_then(|()| err.flush());
}

#[cfg(test)]
mod tests {
    use super::safe;

    #[test]
    fn control_characters_are_escaped_and_plain_text_is_kept() {
        assert_eq!(safe("fig3: out/fig3.png\n\tok"), "fig3: out/fig3.png\n\tok");
        assert_eq!(safe("out/\u{1b}[2J.png"), "out/\\u{1b}[2J.png");
        assert_eq!(safe("a\rb\u{7f}c\u{9b}d"), "a\\u{d}b\\u{7f}c\\u{9b}d");
        assert_eq!(safe("x\u{202e}gnp.exe"), "x\\u{202e}gnp.exe");
        assert_eq!(safe("mu = 0.3, μ, ²"), "mu = 0.3, μ, ²");
    }
}
