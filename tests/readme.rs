//! The README's commands print what it shows. Each `$ jamchart ...` line of a `console` block
//! runs in an empty folder and its stdout is compared with the lines below it: `[..]` in a
//! line stands for any text, a line `...` for any lines. A changed output fails here until
//! the README shows it.
//!
//! Hand-written rather than trycmd: trycmd runs a Markdown file's commands in the file's
//! folder (the checkout, where `render` would write into the user's `out/`), and what is
//! needed here is the split, the run and the two wildcards.

use crate::common::cli::{jamchart, repo, stderr, stdout};

/// A command of the README and the output it shows.
struct Shown {
    args: Vec<String>,
    expected: Vec<String>,
}

/// The `$ jamchart` commands of the `console` blocks of `text`.
fn commands(text: &str) -> Vec<Shown> {
    let mut out: Vec<Shown> = Vec::new();
    let mut in_console = false;
    for line in text.lines() {
        match (in_console, line.trim_end()) {
            (false, "```console") => in_console = true,
            (true, "```") => in_console = false,
            (true, l) if l.starts_with("$ ") => {
                let words = split(&l[2..]);
                assert_eq!(words[0], "jamchart", "the README runs jamchart only: {l}");
                out.push(Shown {
                    args: words[1..].to_vec(),
                    expected: Vec::new(),
                });
            }
            (true, l) => out
                .last_mut()
                .expect("a console block starts with a command")
                .expected
                .push(l.to_string()),
            _ => {}
        }
    }
    out
}

/// Words of a command line as a POSIX shell splits them (single and double quotes).
fn split(line: &str) -> Vec<String> {
    let (mut words, mut word, mut quote, mut started) = (Vec::new(), String::new(), None, false);
    for c in line.chars() {
        match (quote, c) {
            (None, '\'' | '"') => (quote, started) = (Some(c), true),
            (Some(q), c) if c == q => quote = None,
            (None, ' ') => {
                if started {
                    words.push(std::mem::take(&mut word));
                }
                started = false;
            }
            (_, c) => (word, started) = (word + &c.to_string(), true),
        }
    }
    assert!(quote.is_none(), "an unclosed quote: {line}");
    if started {
        words.push(word);
    }
    words
}

/// Whether `got` is `want` with `[..]` standing for any text.
fn line_matches(want: &str, got: &str) -> bool {
    let mut parts = want.split("[..]");
    let first = parts.next().unwrap_or("");
    let Some(mut rest) = got.strip_prefix(first) else {
        return false;
    };
    let parts: Vec<&str> = parts.collect();
    for (i, part) in parts.iter().enumerate() {
        if i + 1 == parts.len() {
            return rest.ends_with(part);
        }
        match rest.find(part) {
            Some(k) => rest = &rest[k + part.len()..],
            None => return false,
        }
    }
    rest.is_empty()
}

/// Whether the lines `got` are `want`, a `...` line standing for any lines.
fn lines_match(want: &[String], got: &[&str]) -> bool {
    match want.split_first() {
        None => got.is_empty(),
        Some((w, rest)) if w == "..." => (0..=got.len()).any(|k| lines_match(rest, &got[k..])),
        Some((w, rest)) => {
            !got.is_empty() && line_matches(w, got[0]) && lines_match(rest, &got[1..])
        }
    }
}

#[test]
fn the_readme_commands_print_what_it_shows() {
    let text = std::fs::read_to_string(repo().join("README.md")).expect("README.md reads");
    let shown = commands(&text);
    assert!(shown.len() >= 3, "the README shows its three jobs");
    for s in shown {
        let dir = tempfile::tempdir().expect("a temporary folder");
        let args: Vec<&str> = s.args.iter().map(String::as_str).collect();
        let o = jamchart(dir.path(), &args);
        assert!(o.status.success(), "jamchart {args:?}: {}", stderr(&o));
        let out = stdout(&o);
        let got: Vec<&str> = out.lines().collect();
        assert!(
            lines_match(&s.expected, &got),
            "`jamchart {}` printed\n{out}\nwhere the README shows\n{}",
            args.join(" "),
            s.expected.join("\n")
        );
    }
}

#[test]
fn the_wildcards_match_what_they_say() {
    assert!(line_matches("took [..]", "took 51.7 us"));
    assert!(line_matches("a [..] c [..]", "a b c d"));
    assert!(!line_matches("took [..] s", "took 3 us"));
    assert!(!line_matches("exact", "exactly"));
    let want = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    assert!(lines_match(
        &want(&["a", "...", "d"]),
        &["a", "b", "c", "d"]
    ));
    assert!(lines_match(&want(&["..."]), &[]));
    assert!(!lines_match(&want(&["a", "d"]), &["a", "b", "d"]));
    assert_eq!(
        split("jamchart solve --mu 'normal(0.2, 0.03)' \"x y\""),
        ["jamchart", "solve", "--mu", "normal(0.2, 0.03)", "x y"]
    );
}
