//! Text bound for a terminal. File names, paths, scene titles and values a user typed are
//! echoed in answers and messages; a control character among them (`ESC [ 2 J` in a scene
//! file's name clears the screen, `ESC ] 52` writes the clipboard) reached the terminal raw.
//! Every control character but newline and tab is written as an escape instead, and so are
//! the bidirectional controls that reorder what a line shows.

use std::borrow::Cow;
use std::io::Write;
use std::path::Path;

/// `text` with each control character but newline and tab, DEL and each bidirectional control
/// written as Rust writes it (`\u{1b}`), the rest as it is; borrowed when nothing needs it.
pub(crate) fn safe(text: &str) -> Cow<'_, str> {
    crate::error::escape_controls(text, true)
}

/// A path as an answer lists it, on one line: a newline or tab in it escaped as well (`--out
/// "$(printf 'a\nb')"` split `fig6: a` and `b/fig6.svg` over two lines of the answer).
pub(crate) fn path(p: &Path) -> String {
    crate::error::path_text(p)
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
