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

/// The page size of `pdf`, from its MediaBox, in pt.
fn media_box(pdf: &[u8]) -> (f64, f64) {
    let text = String::from_utf8_lossy(pdf);
    let start = text.find("/MediaBox [").expect("a MediaBox") + "/MediaBox [".len();
    let numbers: Vec<f64> = text[start..]
        .split(']')
        .next()
        .unwrap()
        .split_whitespace()
        .map(|n| n.parse().unwrap())
        .collect();
    (numbers[2] - numbers[0], numbers[3] - numbers[1])
}

/// PDF pages were the chart's size (1 px = 1 pt, 1000 x 950 pt for Fig. 3) with no way to print
/// on paper: `--paper a4` and `--paper letter` fit the chart onto the sheet (595 x 842 pt,
/// 612 x 792 pt), the default stays the chart's size, and a paper without `--format pdf` is
/// refused. The gallery of PDFs links them (no picture to show) and its command to reproduce
/// a chart names the format and the paper (it said `jamchart render fig3 --out DIR`, which
/// writes SVG and PNG).
#[test]
fn paper_fits_the_pdf_onto_a4_or_letter() {
    let dir = tempfile::tempdir().unwrap();
    for (paper, size) in [
        (None, (1000.0, 950.0)),
        (Some("a4"), (595.0, 842.0)),
        (Some("letter"), (612.0, 792.0)),
    ] {
        let out = paper.unwrap_or("chart");
        let mut args = vec!["render", "fig3", "--format", "pdf", "--out", out, "--quiet"];
        args.extend(paper.iter().flat_map(|p| ["--paper", p]));
        let o = cli_util::jamchart(dir.path(), &args);
        assert_eq!(o.status.code(), Some(0), "{}", cli_util::stderr(&o));
        let pdf = std::fs::read(dir.path().join(out).join("fig3.pdf")).unwrap();
        let (w, h) = media_box(&pdf);
        assert!(
            (w.round(), h.round()) == size,
            "{paper:?}: {w} x {h} pt, not {size:?}"
        );
        let page = std::fs::read_to_string(dir.path().join(out).join("index.html")).unwrap();
        assert!(page.contains("<a href=\"fig3.pdf\">"), "{page}");
        assert!(!page.contains("<img"), "{page}");
        let reproduce = match paper {
            Some(p) => format!("jamchart render fig3 --format pdf --paper {p} --out {out}"),
            None => format!("jamchart render fig3 --format pdf --out {out}"),
        };
        assert!(page.contains(&reproduce), "{reproduce}: {page}");
    }
    let o = cli_util::jamchart(
        dir.path(),
        &["render", "fig3", "--paper", "a4", "--out", "no"],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(
        cli_util::stderr(&o).contains("add --format pdf"),
        "{}",
        cli_util::stderr(&o)
    );
    assert!(!dir.path().join("no").exists());
}
