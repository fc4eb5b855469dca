//! The image-hash regression: every scene's SVG and PNG must have the SHA-256 recorded in
//! `charts/SHA256SUMS` (sha256sum format, so `cd out && sha256sum -c ../charts/SHA256SUMS`
//! checks a render by hand), and the same bytes whatever the rayon thread count. Each PNG's
//! decoded pixels must also have the SHA-256 recorded in `charts/PIXELS`, so that a change of
//! how the pixels are encoded (a deflate level or library) shows apart from a change of the
//! picture: the first changes SHA256SUMS only, the second both.
//!
//! When a chart changes on purpose, look at the new PNGs, then re-bless the manifest:
//!
//! ```text
//! JAMCHART_BLESS=1 cargo test --release --test integration chart_hashes
//! ```
//!
//! and set `jamchart::charts::CHART_FORMAT` (src/charts/mod.rs) to the new manifest's hash prefix,
//! as `chart_format_is_the_manifest_hash_prefix` says.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use jamchart::charts::{self, Formats, Rendered};
use sha2::{Digest, Sha256};

fn charts_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("charts")
}

fn render_all(threads: usize) -> Vec<Rendered> {
    let dir = charts_dir();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool");
    pool.install(|| {
        charts::scene_names(&dir)
            .expect("charts/ lists")
            .iter()
            .map(|n| {
                let scene = charts::load_scene(&dir, n).expect("scene loads");
                let r = charts::render(&scene, Formats::Both).expect("scene renders");
                // `render` checks the paths it plans before computing: they are the ones written.
                let mut written = vec![r.data.extension];
                written.extend(r.cells.as_ref().map(|_| charts::CellsCsv::EXTENSION));
                assert_eq!(written, scene.chart.data_extensions(), "{n}");
                r
            })
            .collect()
    })
}

fn hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// file name -> hash of every rendered picture.
fn hashes(rendered: &[Rendered]) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    for r in rendered {
        let svg = r.svg.as_deref().expect("svg requested");
        let png = r.png.as_deref().expect("png requested");
        out.insert(format!("{}.svg", r.name), hex(svg));
        out.insert(format!("{}.png", r.name), hex(png));
    }
    out
}

/// The SHA-256 of a PNG's pixels, decoded to 8-bit RGB (a palette expanded), with its size.
fn pixel_hash(png_bytes: &[u8]) -> String {
    let mut decoder = png::Decoder::new(png_bytes);
    decoder.set_transformations(png::Transformations::EXPAND);
    let mut reader = decoder.read_info().expect("the PNG's header decodes");
    let mut pixels = vec![0; reader.output_buffer_size()];
    let frame = reader
        .next_frame(&mut pixels)
        .expect("the PNG's pixels decode");
    assert_eq!(
        (frame.color_type, frame.bit_depth),
        (png::ColorType::Rgb, png::BitDepth::Eight),
        "charts are 8-bit RGB or indexed"
    );
    let mut hashed = format!("{}x{} rgb8\n", frame.width, frame.height).into_bytes();
    hashed.extend_from_slice(&pixels[..frame.buffer_size()]);
    hex(&hashed)
}

/// file name -> hash of every rendered PNG's pixels.
fn pixel_hashes(rendered: &[Rendered]) -> BTreeMap<String, String> {
    rendered
        .iter()
        .map(|r| {
            let png = r.png.as_deref().expect("png requested");
            (format!("{}.png", r.name), pixel_hash(png))
        })
        .collect()
}

fn write_manifest(path: &Path, hashes: &BTreeMap<String, String>) {
    let text: String = hashes.iter().map(|(f, h)| format!("{h}  {f}\n")).collect();
    std::fs::write(path, text).expect("manifest writes");
}

/// What differs between the manifest at `path` and `now`, a line per file.
fn differences(path: &Path, now: &BTreeMap<String, String>) -> Vec<String> {
    let recorded = read_manifest(path);
    let mut problems = Vec::new();
    for (file, h) in now {
        match recorded.get(file) {
            Some(r) if r == h => {}
            Some(r) => problems.push(format!("{file}: manifest {r}, now {h}")),
            None => problems.push(format!("{file}: not in the manifest, now {h}")),
        }
    }
    for file in recorded.keys().filter(|f| !now.contains_key(*f)) {
        problems.push(format!("{file}: in the manifest but no scene renders it"));
    }
    problems
}

fn read_manifest(path: &Path) -> BTreeMap<String, String> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    text.lines()
        .filter_map(|l| l.split_once("  "))
        .map(|(h, f)| (f.trim().to_string(), h.trim().to_string()))
        .collect()
}

#[test]
fn chart_bytes_match_the_manifest_for_any_thread_count() {
    let one = render_all(1);
    let two = render_all(2);
    for (a, b) in one.iter().zip(&two) {
        assert!(
            a == b,
            "scene {}: bytes differ between 1 and 2 rayon threads",
            a.name
        );
    }
    let now = hashes(&one);
    let pixels = pixel_hashes(&one);
    let (manifest, pixel_manifest) = (charts_dir().join("SHA256SUMS"), charts_dir().join("PIXELS"));
    if std::env::var_os("JAMCHART_BLESS").is_some() {
        write_manifest(&manifest, &now);
        write_manifest(&pixel_manifest, &pixels);
        return;
    }
    let pixel_problems = differences(&pixel_manifest, &pixels);
    assert!(
        pixel_problems.is_empty(),
        "chart pixels changed:\n  {}\nlook at the PNGs (jamchart render), then re-bless with \
         JAMCHART_BLESS=1 cargo test --release --test integration chart_hashes and set CHART_FORMAT in \
         src/charts/mod.rs to the new manifest's hash prefix",
        pixel_problems.join("\n  ")
    );
    let problems = differences(&manifest, &now);
    assert!(
        problems.is_empty(),
        "chart bytes changed (the PNGs' pixels did not: charts/PIXELS holds):\n  {}\nlook at \
         the PNGs (jamchart render), then re-bless with JAMCHART_BLESS=1 cargo test --release \
         --test integration chart_hashes and set CHART_FORMAT in src/charts/mod.rs to the new \
         manifest's hash prefix",
        problems.join("\n  ")
    );
}

/// `--version`'s chart format must change whenever a built-in chart's bytes do: it is the hash
/// prefix of the manifest, so a re-bless that leaves it alone fails here.
#[test]
fn chart_format_is_the_manifest_hash_prefix() {
    let manifest = std::fs::read(charts_dir().join("SHA256SUMS")).expect("manifest reads");
    let prefix = &hex(&manifest)[..12];
    assert_eq!(
        charts::CHART_FORMAT,
        prefix,
        "charts/SHA256SUMS changed: set CHART_FORMAT in src/charts/mod.rs to \"{prefix}\" \
         (sha256sum charts/SHA256SUMS | cut -c1-12)"
    );
}
