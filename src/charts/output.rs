//! Chart bytes: a drawing made into SVG and into deterministic PNG, through [`Typeset`] (the
//! files are written by the crate's all-or-nothing writer, `atomic`).

use plotters::coord::Shift;
use plotters::prelude::*;

use super::print::{Grey, Ink};
use super::typeset::{Quantise, SvgText, Typeset};

/// The SVG backend as charts see it: text as outlines, everything `scale` times larger, in the
/// scene's ink.
pub type SvgArea<'a> = DrawingArea<Typeset<Grey<SVGBackend<'a>>>, Shift>;
/// The PNG backend as charts see it: text rasterised, anti-aliasing quantised, scaled, in the
/// scene's ink.
pub type PngArea<'a> = DrawingArea<Typeset<Grey<Quantise<BitMapBackend<'a>>>>, Shift>;

/// An SVG `width` x `height` px drawn by `draw` on a drawing `scale` times smaller.
pub fn svg<F>(width: u32, height: u32, scale: f64, ink: Ink, draw: F) -> Result<Vec<u8>, String>
where
    F: for<'a> FnOnce(&SvgArea<'a>) -> Result<(), String>,
{
    let runs = SvgText::shared();
    let mut s = String::new();
    {
        let backend = SVGBackend::with_string(&mut s, (width, height));
        let root = Typeset::outlines(Grey(backend, ink), scale, runs.clone()).into_drawing_area();
        draw(&root)?;
        root.present().map_err(|e| e.to_string())?;
    }
    let svg = runs.borrow().finish(&s)?;
    Ok(svg.into_bytes())
}

/// A PDF of one page from the SVG `svg` ([`svg`]'s bytes: the same drawing, its text already
/// outlines, so the PDF embeds no font), through `svg2pdf`; 1 px is 1 pt (72 dpi), so a
/// 1000 x 800 px chart prints 35.3 x 28.2 cm and scales without loss.
///
/// The bytes depend only on the SVG's: `svg2pdf` writes no date, producer id or random
/// document id (`tests/cli_pdf.rs` renders twice and on 1 and 2 threads and compares).
pub fn pdf(svg: &[u8]) -> Result<Vec<u8>, String> {
    let tree = svg2pdf::usvg::Tree::from_data(svg, &svg2pdf::usvg::Options::default())
        .map_err(|e| format!("the SVG does not parse for the PDF: {e}"))?;
    svg2pdf::to_pdf(
        &tree,
        svg2pdf::ConversionOptions::default(),
        svg2pdf::PageOptions::default(),
    )
    .map_err(|e| format!("PDF conversion: {e}"))
}

/// A PNG `width` x `height` px drawn by `draw` on a drawing `scale` times smaller.
pub fn png<F>(width: u32, height: u32, scale: f64, ink: Ink, draw: F) -> Result<Vec<u8>, String>
where
    F: for<'a> FnOnce(&PngArea<'a>) -> Result<(), String>,
{
    let mut rgb = vec![0u8; width as usize * height as usize * 3];
    {
        let backend = Quantise(BitMapBackend::with_buffer(&mut rgb, (width, height)));
        let root = Typeset::raster(Grey(backend, ink), scale).into_drawing_area();
        draw(&root)?;
        root.present().map_err(|e| e.to_string())?;
    }
    encode_png(&rgb, width, height)
}

/// Encodes an RGB8 buffer as PNG with only the IHDR, (PLTE,) IDAT and IEND chunks: no time, no
/// text, no gamma, so the bytes depend on the pixels alone.
///
/// Line art has few colours: with at most 256 the image is stored indexed (one byte a pixel,
/// palette in order of first appearance, so still deterministic), which is smaller; otherwise
/// as RGB.
pub fn encode_png(rgb: &[u8], width: u32, height: u32) -> std::result::Result<Vec<u8>, String> {
    let mut out = Vec::with_capacity(rgb.len() / 16);
    {
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_depth(png::BitDepth::Eight);
        // Per-row adaptive filters and zlib's default level: about half the bytes of Fast with
        // no filter on anti-aliased line art, for a few ms per chart.
        enc.set_compression(png::Compression::Default);
        enc.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
        let indexed = palette(rgb);
        let data = match &indexed {
            Some((palette, indices)) => {
                enc.set_color(png::ColorType::Indexed);
                enc.set_palette(palette.clone());
                indices.as_slice()
            }
            None => {
                enc.set_color(png::ColorType::Rgb);
                rgb
            }
        };
        let mut w = enc.write_header().map_err(|e| e.to_string())?;
        w.write_image_data(data).map_err(|e| e.to_string())?;
        w.finish().map_err(|e| e.to_string())?;
    }
    Ok(out)
}

/// The palette (RGB triples, in order of first appearance) and one index per pixel, or None when
/// the image has more than 256 colours.
///
/// Line art repeats the previous pixel's colour almost everywhere, so that is tried first; the
/// rest go through a small open-addressed table (at most 256 keys in 1024 slots) instead of a
/// `HashMap`, whose SipHash per pixel was a quarter of `render fig3`. Same palette order, same
/// bytes; `palette_matches_the_hash_map_oracle` checks it against the plain `HashMap`.
fn palette(rgb: &[u8]) -> Option<(Vec<u8>, Vec<u8>)> {
    /// Slots of the table: a power of two, four times the 256 keys so probes stay short.
    const SLOTS: usize = 1024;
    /// Marks an empty slot: no RGB triple packs to it (the top byte of a packed key is 0).
    const EMPTY: u32 = u32::MAX;
    let mut keys = [EMPTY; SLOTS];
    let mut values = [0u8; SLOTS];
    let mut palette = Vec::new();
    let mut indices = Vec::with_capacity(rgb.len() / 3);
    let mut last: Option<(u32, u8)> = None;
    for px in rgb.chunks_exact(3) {
        let key = u32::from(px[0]) << 16 | u32::from(px[1]) << 8 | u32::from(px[2]);
        if let Some((k, i)) = last {
            if k == key {
                indices.push(i);
                continue;
            }
        }
        // Fibonacci hashing: the top bits of key * 2^32 / phi.
        let mut slot = (key.wrapping_mul(0x9E37_79B9) >> 22) as usize;
        let i = loop {
            if keys[slot] == key {
                break values[slot];
            }
            if keys[slot] == EMPTY {
                let i = u8::try_from(palette.len() / 3).ok()?;
                keys[slot] = key;
                values[slot] = i;
                palette.extend_from_slice(&[px[0], px[1], px[2]]);
                break i;
            }
            slot = (slot + 1) & (SLOTS - 1);
        };
        last = Some((key, i));
        indices.push(i);
    }
    Some((palette, indices))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plain palette the fast one replaced: a `HashMap`, colours in order of first appearance.
    fn palette_oracle(rgb: &[u8]) -> Option<(Vec<u8>, Vec<u8>)> {
        let mut index: std::collections::HashMap<[u8; 3], u8> = std::collections::HashMap::new();
        let mut palette = Vec::new();
        let mut indices = Vec::with_capacity(rgb.len() / 3);
        for px in rgb.chunks_exact(3) {
            let key = [px[0], px[1], px[2]];
            let i = match index.get(&key) {
                Some(i) => *i,
                None => {
                    let i = u8::try_from(index.len()).ok()?;
                    index.insert(key, i);
                    palette.extend_from_slice(&key);
                    i
                }
            };
            indices.push(i);
        }
        Some((palette, indices))
    }

    proptest::proptest! {
        #[test]
        fn palette_matches_the_hash_map_oracle(
            colours in proptest::collection::vec(proptest::array::uniform3(0u8..=255), 1..300),
            picks in proptest::collection::vec(0usize..1000, 0..2000),
        ) {
            // Runs of repeated pixels, drawn from up to 299 colours: both sides of the 256 limit.
            let rgb: Vec<u8> = picks
                .iter()
                .flat_map(|&p| colours[p % colours.len()])
                .collect();
            proptest::prop_assert_eq!(palette(&rgb), palette_oracle(&rgb));
        }
    }

    #[test]
    fn png_has_no_metadata_chunks() {
        let png = encode_png(&[255u8; 4 * 3 * 3], 4, 3).unwrap();
        let mut chunks = Vec::new();
        let mut i = 8;
        while i + 8 <= png.len() {
            let len = u32::from_be_bytes(png[i..i + 4].try_into().unwrap()) as usize;
            chunks.push(String::from_utf8_lossy(&png[i + 4..i + 8]).to_string());
            i += 12 + len;
        }
        assert_eq!(chunks, ["IHDR", "PLTE", "IDAT", "IEND"]);
    }

    #[test]
    fn few_colours_are_indexed_and_decode_to_the_same_pixels() {
        let rgb: Vec<u8> = (0..40u8).flat_map(|i| [i, 255 - i, 7]).collect();
        let png = encode_png(&rgb, 8, 5).unwrap();
        let mut reader = png::Decoder::new(std::io::Cursor::new(&png))
            .read_info()
            .unwrap();
        assert_eq!(reader.info().color_type, png::ColorType::Indexed);
        let palette = reader.info().palette.clone().unwrap().into_owned();
        let mut buf = vec![0; reader.output_buffer_size()];
        let frame = reader.next_frame(&mut buf).unwrap();
        let back: Vec<u8> = buf[..frame.buffer_size()]
            .iter()
            .flat_map(|&i| palette[3 * i as usize..3 * i as usize + 3].to_vec())
            .collect();
        assert_eq!(back, rgb);
        // 300 colours do not fit a palette: RGB.
        let many: Vec<u8> = (0..300u32)
            .flat_map(|i| [(i % 256) as u8, (i / 256) as u8, 0])
            .collect();
        let png = encode_png(&many, 300, 1).unwrap();
        let reader = png::Decoder::new(std::io::Cursor::new(&png))
            .read_info()
            .unwrap();
        assert_eq!(reader.info().color_type, png::ColorType::Rgb);
    }
}
