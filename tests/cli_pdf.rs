//! `--format pdf`, for print, from the same drawing and as deterministic as the SVG: the PDF is the
//! SVG's drawing through svg2pdf, its bytes the same on every run and thread count, its text
//! outlines (no font in the file).

use crate::common::cli as cli_util;

use std::path::Path;
use std::process::Command;

/// `jamchart render SCENES --format pdf` into DIR/`out` on `threads` threads: each PDF's bytes.
fn pdfs(dir: &Path, out: &str, threads: &str, scenes: &[&str]) -> Vec<(String, Vec<u8>)> {
    let r = Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .arg("render")
        .args(scenes)
        .args(["--out", out, "--format", "pdf", "--quiet"])
        .current_dir(dir)
        .env("RAYON_NUM_THREADS", threads)
        .output()
        .unwrap();
    assert_eq!(r.status.code(), Some(0), "{}", cli_util::stderr(&r));
    scenes
        .iter()
        .map(|s| {
            let path = dir.join(out).join(format!("{s}.pdf"));
            let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            (s.to_string(), bytes)
        })
        .collect()
}

/// A PDF for print: one page, the same bytes on a second run and on 1 and 2 threads, no font
/// (text is outlines, as in the SVG), no picture but the PDF (and the data) written.
#[test]
fn render_format_pdf_is_deterministic_across_runs_and_threads_with_text_as_outlines() {
    let dir = tempfile::tempdir().unwrap();
    let scenes = ["fig3", "vlocator-optimum"];
    let one = pdfs(dir.path(), "one", "1", &scenes);
    let two = pdfs(dir.path(), "two", "2", &scenes);
    let again = pdfs(dir.path(), "again", "2", &scenes);
    for ((a, b), c) in one.iter().zip(&two).zip(&again) {
        assert!(
            a.1 == b.1,
            "{}: the PDF differs between 1 and 2 threads",
            a.0
        );
        assert!(b.1 == c.1, "{}: the PDF differs between two runs", a.0);
        let text = String::from_utf8_lossy(&a.1);
        assert!(text.starts_with("%PDF-"), "{}: not a PDF", a.0);
        assert_eq!(
            text.matches("/Type /Page\n").count(),
            1,
            "{}: one page",
            a.0
        );
        assert!(!text.contains("/Font"), "{}: a font in the PDF", a.0);
        assert!(
            !text.contains("/CreationDate"),
            "{}: a date in the PDF",
            a.0
        );
        eprintln!(
            "{}.pdf: {} bytes, identical on 1 and 2 threads and two runs",
            a.0,
            a.1.len()
        );
    }
    let mut written: Vec<String> = std::fs::read_dir(dir.path().join("one"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    written.sort();
    assert!(
        !written
            .iter()
            .any(|f| f.ends_with(".svg") || f.ends_with(".png")),
        "{written:?}"
    );
}
