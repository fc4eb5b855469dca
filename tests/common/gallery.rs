//! The gallery's browser tests' shared parts (`#[macro_use] #[path = "common/gallery.rs"]
//! mod gallery;`, after `browser` and `cli_util`): a check run in both browsers, a gallery
//! rendered into a temporary folder, the pinned read-offs of a dumped page.

use std::path::{Path, PathBuf};

use serde_json::Value;

use super::browser::{self, Browser, Kind};
use super::cli::{self as cli_util, jamchart};

/// A check as two tests: `$chromium` runs it in Chromium, `$firefox` in Firefox (the gallery
/// must work in current Chromium and Firefox). Doc comments before the invocation document both.
macro_rules! in_chromium_and_firefox {
    ($(#[$doc:meta])* $chromium:ident, $firefox:ident, $check:ident) => {
        $(#[$doc])*
        #[test]
        fn $chromium() {
            $check(Kind::Chromium);
        }

        $(#[$doc])*
        #[test]
        fn $firefox() {
            $check(Kind::Firefox);
        }
    };
}

/// The browser of `kind`, and `scenes` rendered as PNG with their gallery into DIR/out:
/// (browser, DIR, DIR/out); None where [`browser::find`] says the test may skip.
pub fn gallery_of(kind: Kind, scenes: &[&str]) -> Option<(Browser, tempfile::TempDir, PathBuf)> {
    let browser = browser::find(kind)?;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let mut args = vec!["render"];
    args.extend(scenes);
    args.extend(["--out", "out", "--format", "png"]);
    let r = jamchart(dir.path(), &args);
    assert_eq!(r.status.code(), Some(0), "{}", cli_util::stderr(&r));
    Some((browser, dir, out))
}

/// The pinned read-offs of chart `name` in a dumped DOM: each pin's `data-values`, in order.
pub fn pins(dom: &str, name: &str) -> Vec<Value> {
    let start = dom
        .find(&format!("<figure class=\"readoff\" data-chart=\"{name}\">"))
        .unwrap_or_else(|| panic!("no read-off figure for {name}"));
    let figure = &dom[start..start + dom[start..].find("</figure>").unwrap()];
    figure
        .split("data-values=\"")
        .skip(1)
        .map(|s| {
            let raw = &s[..s.find('"').unwrap()];
            let text = raw
                .replace("&quot;", "\"")
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&amp;", "&");
            serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"))
        })
        .collect()
}

pub fn num(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

/// Reddish pixels in a PNG screenshot (the crosshair is #e00; the chart's orange read-off
/// lines count too, so compare two screenshots).
pub fn red_pixels(png_path: &Path) -> usize {
    let file = std::fs::File::open(png_path).unwrap();
    let mut r = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .unwrap();
    let mut buf = vec![0; r.output_buffer_size()];
    let info = r.next_frame(&mut buf).unwrap();
    let step = info.color_type.samples();
    buf[..info.buffer_size()]
        .chunks_exact(step)
        .filter(|p| p[0] > 150 && p[0] > p[1].saturating_add(100) && p[1].abs_diff(p[2]) < 30)
        .count()
}

/// A pinned read-off of a `points` chart agrees with its data file's row cell for cell: the
/// same text in every column (a number pinned as a number, e.g. the iteration, by value; an
/// empty cell as none), so the page shows the file's digits.
pub fn assert_row(pin: &Value, row: &std::collections::BTreeMap<String, String>) {
    for (k, want) in row {
        let got = match &pin[k] {
            Value::String(s) => s.clone(),
            Value::Null => String::new(),
            other => other.to_string(),
        };
        assert_eq!(&got, want, "{k} in {pin}");
    }
}

/// A CSV file as rows of (column, cell text), through the csv crate (a cell may hold a quoted
/// comma: a failure's reason in accuracy.csv).
pub fn csv_rows(path: &Path) -> Vec<std::collections::BTreeMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records()
        .map(|rec| {
            header
                .iter()
                .cloned()
                .zip(rec.unwrap().iter().map(String::from))
                .collect()
        })
        .collect()
}

/// Screenshots of the gallery page `page` at desktop and phone size, with the read-off hook
/// `hook` and without, saved to look at as `gallery-STEM-SIZE-BROWSER.png` and `plain-...`
/// under target/tmp/gallery_browser: the read-off must draw its red crosshair or ring (more than
/// 20 red pixels over the plain page's). A chart alone in its gallery, at the top of the page:
/// headless Chromium's screenshot of a page scrolled by script is blank.
pub fn assert_read_off_drawn(browser: &Browser, page: &Path, hook: &str, stem: &str) {
    let shots = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("gallery_browser");
    std::fs::create_dir_all(&shots).unwrap();
    let tag = format!("{:?}", browser.kind).to_lowercase();
    let url = |hash: &str| format!("file://{}#{hash}", page.display());
    for (name, size) in [("desktop", (1000, 1300)), ("phone", (390, 844))] {
        let path = shots.join(format!("gallery-{stem}-{name}-{tag}.png"));
        browser.screenshot(&url(hook), size, &path);
        let plain = shots.join(format!("plain-{stem}-{name}-{tag}.png"));
        browser.screenshot(&url(""), size, &plain);
        let (red, none) = (red_pixels(&path), red_pixels(&plain));
        eprintln!(
            "screenshot {}: {red} red pixels, {none} without",
            path.display()
        );
        assert!(red > none + 20, "no read-off drawn in {}", path.display());
    }
}
