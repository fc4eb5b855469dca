//! Chart bytes: a drawing made into SVG and into deterministic PNG, through [`Typeset`] (the
//! files are written by the crate's all-or-nothing writer, `atomic`).

use plotters::coord::Shift;
use plotters::prelude::*;

use super::print::{Grey, Ink};
use super::typeset::{Canvas, Quantise, SvgText, Typeset};

/// The SVG backend as charts see it: text as outlines, everything `scale` times larger, in the
/// scene's ink.
pub type SvgArea<'a> = DrawingArea<Typeset<Grey<SVGBackend<'a>>>, Shift>;
/// The PNG backend as charts see it: text rasterised, anti-aliasing quantised, scaled, in the
/// scene's ink.
pub type PngArea<'a> = DrawingArea<Typeset<Grey<Quantise<Canvas<'a>>>>, Shift>;

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

choice! {
    /// A sheet of paper a PDF is printed on, portrait: the chart is fitted onto it within
    /// a margin of `PAPER_MARGIN_PT` (36 pt, half an inch), centred across and at the top.
    pub enum Paper {
        /// ISO A4, 210 x 297 mm (595 x 842 pt).
        A4 = "a4",
        /// US Letter, 8.5 x 11 in (612 x 792 pt).
        Letter = "letter",
    }
}

/// The margin around a chart on paper, in pt: half an inch (12.7 mm), wider than the edge an
/// office printer cannot print on (about 5 mm).
pub const PAPER_MARGIN_PT: f64 = 36.0;

impl Paper {
    /// Width and height in pt (1/72 in), portrait.
    pub fn size_pt(self) -> (f64, f64) {
        const PT_PER_MM: f64 = 72.0 / 25.4;
        match self {
            Paper::A4 => (210.0 * PT_PER_MM, 297.0 * PT_PER_MM),
            Paper::Letter => (8.5 * 72.0, 11.0 * 72.0),
        }
    }

    /// The SVG `svg` of `size_px` (width, height) on this paper: an SVG of the page's size in
    /// pt holding the chart, scaled to fit within the margins, centred across, at the top.
    fn page(self, svg: &[u8], (width_px, height_px): (u32, u32)) -> Result<Vec<u8>, String> {
        let chart = std::str::from_utf8(svg).map_err(|e| format!("the SVG is not UTF-8: {e}"))?;
        let (w, h) = (f64::from(width_px), f64::from(height_px));
        let (page_w, page_h) = self.size_pt();
        let m = PAPER_MARGIN_PT;
        let scale = ((page_w - 2.0 * m) / w).min((page_h - 2.0 * m) / h);
        let left = (page_w - scale * w) / 2.0;
        Ok(format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{page_w}\" height=\"{page_h}\" \
             viewBox=\"0 0 {page_w} {page_h}\"><g transform=\"translate({left} {m}) \
             scale({scale})\">{chart}</g></svg>"
        )
        .into_bytes())
    }
}

/// A PDF of one page from the SVG `svg` of `size_px` ([`svg`]'s bytes: the same drawing, its
/// text already outlines, so the PDF embeds no font), through `svg2pdf`. Without `paper` the
/// page is the chart's size, 1 px to 1 pt (72 dpi), so a 1000 x 800 px chart prints 35.3 x
/// 28.2 cm and scales without loss; on `paper` the chart is fitted onto the sheet.
///
/// The bytes depend only on the SVG's: `svg2pdf` writes no date, producer id or random
/// document id (`tests/cli_pdf.rs` renders twice and on 1 and 2 threads and compares).
pub fn pdf(svg: &[u8], size_px: (u32, u32), paper: Option<Paper>) -> Result<Vec<u8>, String> {
    let page = paper.map(|p| p.page(svg, size_px)).transpose()?;
    let svg = page.as_deref().unwrap_or(svg);
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
    populate(&mut rgb);
    {
        let backend = Quantise(Canvas::new(&mut rgb, (width, height)));
        let root = Typeset::raster(Grey(backend, ink), scale).into_drawing_area();
        draw(&root)?;
        root.present().map_err(|e| e.to_string())?;
    }
    encode_png(rgb, width, height)
}

/// Maps `buf`'s pages now, in one call (Linux's `MADV_POPULATE_WRITE`), rather than in one
/// fault each as they are first written: a fault costs about a microsecond on a virtual
/// machine, and a chart's canvas is hundreds of pages (2.85 MB, fig3's size, took 0.9 ms
/// of faults against 0.4 ms mapped at once, written by C on this project's machine). Advice
/// only: where the kernel has no such call (before 5.14) or
/// the buffer spans no whole page, the pages fault as before.
fn populate(buf: &mut [u8]) {
    #[cfg(target_os = "linux")]
    {
        // SAFETY: sysconf reads a constant of the system.
        let page = usize::try_from(unsafe { libc::sysconf(libc::_SC_PAGESIZE) }).unwrap_or(0);
        if page == 0 {
            return;
        }
        let start = buf.as_mut_ptr() as usize;
        let (first, end) = (
            start.next_multiple_of(page),
            (start + buf.len()) / page * page,
        );
        if end > first {
            // SAFETY: [first, end) lies within `buf`, which this function borrows mutably, and
            // populating pages for writing changes no byte of them.
            unsafe {
                libc::madvise(
                    first as *mut libc::c_void,
                    end - first,
                    libc::MADV_POPULATE_WRITE,
                );
            }
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = buf;
}

/// Encodes an RGB8 buffer as PNG with only the IHDR, (PLTE,) IDAT and IEND chunks: no time, no
/// text, no gamma, so the bytes depend on the pixels alone.
///
/// Line art has few colours: with at most 256 the image is stored indexed (one byte a pixel,
/// palette in order of first appearance, so still deterministic), which is smaller; otherwise
/// as RGB. Rows are filtered per row adaptively and deflated at zlib's default level (6) by
/// zlib-rs, flate2's backend here (Cargo.toml says why): about half the bytes of Fast with no
/// filter on anti-aliased line art, for a few ms per chart.
///
/// The IDAT's filtered rows are the png crate's own (`write_image_data` with
/// `Compression::Default` and `AdaptiveFilterType::Adaptive`), made here by [`filter_rows`]
/// and deflated in one write into flate2's encoder: the crate writes each row into flate2
/// twice, and flate2 zeroes its 32 kiB output buffer on every write, which was 14 % of
/// `render fig3`'s instructions. zlib-rs's stream depends on how its input arrives, so the
/// compressed bytes differ from the crate's; what it inflates to does not
/// (`idat_is_the_png_crates_own` checks it; charts/SHA256SUMS and charts/PIXELS check the
/// charts' bytes and pixels).
pub fn encode_png(rgb: Vec<u8>, width: u32, height: u32) -> std::result::Result<Vec<u8>, String> {
    let indexed = palette(&rgb);
    let filtered = match &indexed {
        // The picture's buffer, no longer read, holds the filtered rows: its pages are
        // mapped already, where a new buffer's would fault.
        Some((_, indices)) => filter_rows(indices, width as usize, 1, rgb),
        None => filter_rows(&rgb, width as usize * 3, 3, Vec::new()),
    };
    let mut zlib = flate2::write::ZlibEncoder::new(
        Vec::with_capacity(filtered.len() / 16),
        flate2::Compression::default(),
    );
    std::io::Write::write_all(&mut zlib, &filtered).map_err(|e| e.to_string())?;
    let idat = zlib.finish().map_err(|e| e.to_string())?;
    let mut out = Vec::with_capacity(idat.len() + 1024);
    {
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_depth(png::BitDepth::Eight);
        match indexed {
            Some((palette, _)) => {
                enc.set_color(png::ColorType::Indexed);
                enc.set_palette(palette);
            }
            None => enc.set_color(png::ColorType::Rgb),
        }
        let mut w = enc.write_header().map_err(|e| e.to_string())?;
        w.write_chunk(png::chunk::IDAT, &idat)
            .map_err(|e| e.to_string())?;
        w.finish().map_err(|e| e.to_string())?;
    }
    Ok(out)
}

/// The rows of `data` (`row_len` bytes each, `bpp` bytes a pixel) as PNG filters them, each
/// behind its filter-type byte: the png crate's adaptive choice, the least sum of the filtered
/// bytes read as signed, over Sub, Up, Average and Paeth (later ones win ties; None is not
/// tried), with a row of zeros above the first.
///
/// The four sums come from one pass over the row that filters each byte four ways and keeps
/// only the sums ([`filter_sums`]); the chosen filter then writes the row once. (Four passes
/// that each wrote a filtered row and summed it with u64 adds were a quarter of the PNG.) A
/// row that repeats the one above is all zeros under Up and Paeth, and Paeth wins that tie:
/// it is not summed. Where the processor has AVX2 the same code is compiled for it, 32 bytes
/// a lane instead of 16 (same integers, same bytes: `idat_of_line_art_is_the_png_crates_own`).
/// The rows are written into `room`, whatever it held, grown where it is too small.
fn filter_rows(data: &[u8], row_len: usize, bpp: usize, room: Vec<u8>) -> Vec<u8> {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2, checked just above.
        return unsafe { filter_rows_avx2(data, row_len, bpp, room) };
    }
    filter_rows_in::<16>(data, row_len, bpp, room)
}

/// [`filter_rows`] compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn filter_rows_avx2(data: &[u8], row_len: usize, bpp: usize, room: Vec<u8>) -> Vec<u8> {
    filter_rows_in::<32>(data, row_len, bpp, room)
}

/// [`filter_rows`], the sums taken `PIECE` bytes at a time.
#[inline(always)]
fn filter_rows_in<const PIECE: usize>(
    data: &[u8],
    row_len: usize,
    bpp: usize,
    room: Vec<u8>,
) -> Vec<u8> {
    let zeros = vec![0u8; row_len];
    let mut out = room;
    out.clear();
    out.reserve(data.len() + data.len() / row_len.max(1));
    let mut prev: &[u8] = &zeros;
    for cur in data.chunks_exact(row_len) {
        if cur == prev {
            out.push(PAETH);
            out.resize(out.len() + row_len, 0);
            continue;
        }
        let sums = filter_sums::<PIECE>(bpp, prev, cur);
        // PNG filter types 1 Sub, 2 Up, 3 Average, 4 Paeth: the least sum, the later on a tie.
        let mut best = 0;
        for k in 1..4 {
            if sums[k] <= sums[best] {
                best = k;
            }
        }
        let filter = best as u8 + 1;
        out.push(filter);
        let start = out.len();
        out.resize(start + row_len, 0);
        filter_row(filter, bpp, prev, cur, &mut out[start..]);
        prev = cur;
    }
    out
}

/// The PNG filter type of Paeth.
const PAETH: u8 = 4;

/// The sums of |filtered byte| (read as signed) of row `cur` under Sub, Up, Average and
/// Paeth, `prev` the row above, in one pass of `PIECE` bytes at a time into u16 lanes (at most
/// 128 a byte, so 256 pieces fit before the lanes are added up), which the compiler
/// vectorises.
///
/// Line art repeats: where a piece, the byte left of it and the two above are all one value,
/// every filter gives 0 and the piece is skipped; where only the row above repeats the piece
/// and its left byte, Up and Paeth give 0 (Paeth predicts b, or a = b = c) and Sub and Average
/// alone are summed: on a chart with a grid, most pieces take one of the two.
#[inline(always)]
fn filter_sums<const PIECE: usize>(bpp: usize, prev: &[u8], cur: &[u8]) -> [u64; 4] {
    let n = cur.len();
    let prev = &prev[..n];
    let head = bpp.min(n);
    let abs = |v: u8| u16::from((v as i8).unsigned_abs());
    let avg = |a: u8, b: u8| ((u16::from(a) + u16::from(b)) / 2) as u8;
    let mut sums = [0u64; 4];
    // The first pixel: a = c = 0, so Sub keeps the byte and Paeth predicts b.
    for i in 0..head {
        let (x, b) = (cur[i], prev[i]);
        let filtered = [
            x,
            x.wrapping_sub(b),
            x.wrapping_sub(b / 2),
            x.wrapping_sub(b),
        ];
        for (s, f) in sums.iter_mut().zip(filtered) {
            *s += u64::from(abs(f));
        }
    }
    let (a, c) = (&cur[..n - head], &prev[..n - head]);
    let (x, b) = (&cur[head..], &prev[head..]);
    let mut lanes = [[0u16; PIECE]; 4];
    let mut pieces_in_lanes = 0;
    let add_up = |lanes: &mut [[u16; PIECE]; 4], sums: &mut [u64; 4]| {
        for (s, l) in sums.iter_mut().zip(lanes.iter_mut()) {
            *s += l.iter().map(|&v| u64::from(v)).sum::<u64>();
            *l = [0; PIECE];
        }
    };
    let (mut xs, mut as_) = (x.chunks_exact(PIECE), a.chunks_exact(PIECE));
    let (mut bs, mut cs) = (b.chunks_exact(PIECE), c.chunks_exact(PIECE));
    for (((x, a), b), c) in (&mut xs).zip(&mut as_).zip(&mut bs).zip(&mut cs) {
        let piece = |s: &[u8]| -> [u8; PIECE] { s.try_into().expect("a piece") };
        let (x, a, b, c) = (piece(x), piece(a), piece(b), piece(c));
        if x == b && a == c {
            if x == a {
                continue;
            }
            for j in 0..PIECE {
                lanes[0][j] += abs(x[j].wrapping_sub(a[j]));
                lanes[2][j] += abs(x[j].wrapping_sub(avg(a[j], x[j])));
            }
        } else {
            for j in 0..PIECE {
                lanes[0][j] += abs(x[j].wrapping_sub(a[j]));
                lanes[1][j] += abs(x[j].wrapping_sub(b[j]));
                lanes[2][j] += abs(x[j].wrapping_sub(avg(a[j], b[j])));
                lanes[3][j] += abs(x[j].wrapping_sub(paeth(a[j], b[j], c[j])));
            }
        }
        pieces_in_lanes += 1;
        if pieces_in_lanes == 256 {
            add_up(&mut lanes, &mut sums);
            pieces_in_lanes = 0;
        }
    }
    add_up(&mut lanes, &mut sums);
    let rest =
        (xs.remainder().iter().zip(as_.remainder())).zip(bs.remainder().iter().zip(cs.remainder()));
    for ((&x, &a), (&b, &c)) in rest {
        let filtered = [
            x.wrapping_sub(a),
            x.wrapping_sub(b),
            x.wrapping_sub(avg(a, b)),
            x.wrapping_sub(paeth(a, b, c)),
        ];
        for (s, f) in sums.iter_mut().zip(filtered) {
            *s += u64::from(abs(f));
        }
    }
    sums
}

/// Row `cur` under PNG filter type `filter` (1 Sub, 2 Up, 3 Average, 4 Paeth) into `out`,
/// `prev` the row above: each byte less its prediction from left `a`, above `b` and
/// upper-left `c` (0 left of the first pixel).
#[inline(always)]
fn filter_row(filter: u8, bpp: usize, prev: &[u8], cur: &[u8], out: &mut [u8]) {
    let n = cur.len();
    let (prev, out) = (&prev[..n], &mut out[..n]);
    let head = bpp.min(n);
    // The first pixel: a = c = 0, so Paeth predicts b.
    for i in 0..head {
        out[i] = cur[i].wrapping_sub(match filter {
            1 => 0,
            3 => prev[i] / 2,
            _ => prev[i],
        });
    }
    let (a, c) = (&cur[..n - head], &prev[..n - head]);
    let (x, b, o) = (&cur[head..], &prev[head..], &mut out[head..]);
    match filter {
        1 => o
            .iter_mut()
            .zip(x.iter().zip(a))
            .for_each(|(o, (x, a))| *o = x.wrapping_sub(*a)),
        2 => o
            .iter_mut()
            .zip(x.iter().zip(b))
            .for_each(|(o, (x, b))| *o = x.wrapping_sub(*b)),
        3 => o
            .iter_mut()
            .zip(x.iter().zip(a.iter().zip(b)))
            .for_each(|(o, (x, (a, b)))| {
                *o = x.wrapping_sub(((u16::from(*a) + u16::from(*b)) / 2) as u8)
            }),
        _ => o
            .iter_mut()
            .zip(x.iter().zip(a.iter().zip(b.iter().zip(c))))
            .for_each(|(o, (x, (a, (b, c))))| *o = x.wrapping_sub(paeth(*a, *b, *c))),
    }
}

/// The PNG specification's Paeth predictor: of left `a`, above `b` and upper-left `c`, the one
/// nearest `a + b - c`, ties in that order; in unsigned bytes (FPNGE's form, as the png crate
/// has it), which vectorises: |p - a| = |b - c|, |p - b| = |a - c|, and |p - c| matters only
/// when c lies between a and b, where it is ||b - c| - |a - c||.
fn paeth(a: u8, b: u8, c: u8) -> u8 {
    let pa = b.max(c) - b.min(c);
    let pb = a.max(c) - a.min(c);
    let pc = if (a < c) == (c < b) {
        pa.max(pb) - pa.min(pb)
    } else {
        255
    };
    if pa <= pb && pa <= pc {
        a
    } else if pb <= pc {
        b
    } else {
        c
    }
}

/// The palette (RGB triples, in order of first appearance) and one index per pixel, or None when
/// the image has more than 256 colours.
///
/// Line art repeats the previous pixel's colour almost everywhere, so the image is read in
/// runs: a pixel's colour is looked up once, and the pixels after it that repeat it are found
/// by comparing the bytes with those three before them, 16 at a time ([`repeats`]), and take
/// its index by fixed 16-byte fills. The lookup is a small open-addressed table (at most 256
/// keys in 1024 slots) instead of a `HashMap`, whose SipHash per pixel was a quarter of
/// `render fig3`. Same palette order, same bytes; `palette_matches_the_hash_map_oracle` checks
/// it against the plain `HashMap`.
fn palette(rgb: &[u8]) -> Option<(Vec<u8>, Vec<u8>)> {
    /// Slots of the table: a power of two, four times the 256 keys so probes stay short.
    const SLOTS: usize = 1024;
    /// Marks an empty slot: no RGB triple packs to it (the top byte of a packed key is 0).
    const EMPTY: u32 = u32::MAX;
    /// Indices written at once; the buffer has that many bytes past its end until the last.
    const FILL: usize = 16;
    let mut keys = [EMPTY; SLOTS];
    let mut values = [0u8; SLOTS];
    let mut palette = Vec::new();
    let pixels = rgb.len() / 3;
    let rgb = &rgb[..3 * pixels];
    let mut indices = vec![0u8; pixels + FILL];
    populate(&mut indices);
    let mut done = 0;
    while done < pixels {
        let at = 3 * done;
        let px = &rgb[at..at + 3];
        let key = u32::from(px[0]) << 16 | u32::from(px[1]) << 8 | u32::from(px[2]);
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
                palette.extend_from_slice(px);
                break i;
            }
            slot = (slot + 1) & (SLOTS - 1);
        };
        // This pixel and the whole pixels after it whose bytes repeat those 3 before them.
        let end = done + 1 + repeats(rgb, at + 3) / 3;
        while done < end {
            indices[done..done + FILL].copy_from_slice(&[i; FILL]);
            done += FILL;
        }
        done = end;
    }
    indices.truncate(pixels);
    Some((palette, indices))
}

/// How many bytes of `bytes` from `start` (>= 3) equal the byte three before them, in a row:
/// 16 at a time as a u128 each, the first that differs found from the trailing zeros of
/// their xor, then one at a time.
fn repeats(bytes: &[u8], start: usize) -> usize {
    const BLOCK: usize = 16;
    let word = |k: usize| -> u128 {
        u128::from_le_bytes(
            bytes[k..k + BLOCK]
                .try_into()
                .expect("a slice of BLOCK bytes"),
        )
    };
    let mut j = start;
    while j + BLOCK <= bytes.len() {
        let differ = word(j) ^ word(j - 3);
        if differ != 0 {
            return j - start + (differ.trailing_zeros() / 8) as usize;
        }
        j += BLOCK;
    }
    while j < bytes.len() && bytes[j] == bytes[j - 3] {
        j += 1;
    }
    j - start
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
            picks in proptest::collection::vec((0usize..1000, 1usize..40), 0..300),
            tail in 0usize..3,
        ) {
            // Runs of 1 to 39 repeated pixels (shorter and longer than a 16-byte compare),
            // drawn from up to 299 colours: both sides of the 256 limit; and a buffer whose
            // last pixel is cut short.
            let mut rgb: Vec<u8> = picks
                .iter()
                .flat_map(|&(p, run)| std::iter::repeat_n(colours[p % colours.len()], run))
                .flatten()
                .collect();
            rgb.extend(std::iter::repeat_n(7, tail));
            proptest::prop_assert_eq!(palette(&rgb), palette_oracle(&rgb));
        }
    }

    /// The encoder as it was, through the png crate's `write_image_data`: the oracle of the
    /// filtered rows made by [`filter_rows`] (compare through [`inflated`]).
    fn encode_png_oracle(rgb: &[u8], width: u32, height: u32) -> Vec<u8> {
        let mut out = Vec::new();
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_depth(png::BitDepth::Eight);
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
        let mut w = enc.write_header().unwrap();
        w.write_image_data(data).unwrap();
        w.finish().unwrap();
        out
    }

    /// The PNG `png` with its IDAT chunks' zlib stream inflated: its signature, its chunks'
    /// types and contents in order, the IDAT's filter bytes and filtered rows (no CRC, no
    /// compressed bytes), so that two encodings of the same rows compare equal whatever
    /// deflate made of them.
    fn inflated(png: &[u8]) -> Vec<u8> {
        use std::io::Read;
        let mut out = png[..8].to_vec();
        let (mut pos, mut idat) = (8, Vec::new());
        while pos + 8 <= png.len() {
            let len = u32::from_be_bytes(png[pos..pos + 4].try_into().unwrap()) as usize;
            let (kind, data) = (&png[pos + 4..pos + 8], &png[pos + 8..pos + 8 + len]);
            if kind == b"IDAT" {
                idat.extend_from_slice(data);
            } else {
                if !idat.is_empty() {
                    out.extend_from_slice(b"IDAT");
                    flate2::read::ZlibDecoder::new(&idat[..])
                        .read_to_end(&mut out)
                        .unwrap();
                    idat.clear();
                }
                out.extend_from_slice(kind);
                out.extend_from_slice(data);
            }
            pos += 12 + len;
        }
        out
    }

    /// A xorshift generator of pseudo-random u64 from `seed`.
    fn xorshift(seed: u64) -> impl FnMut() -> u64 {
        let mut state = seed | 1;
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        }
    }

    /// Rows of noise longer than 256 pieces of either width (a filter sum's u16 lanes are
    /// added up every 256 pieces): the png crate's rows, from both widths.
    #[test]
    fn rows_past_the_lanes_capacity_filter_as_the_png_crates() {
        let mut next = xorshift(7);
        let (width, height) = (3000u32, 4u32);
        let rgb: Vec<u8> = (0..3 * width * height).map(|_| next() as u8).collect();
        assert_eq!(
            inflated(&encode_png(rgb.clone(), width, height).unwrap()),
            inflated(&encode_png_oracle(&rgb, width, height))
        );
        let row_len = 3 * width as usize;
        assert_eq!(
            filter_rows_in::<16>(&rgb, row_len, 3, Vec::new()),
            // A buffer that held something else: the rows replace it.
            filter_rows_in::<32>(&rgb, row_len, 3, vec![7; 3 * row_len])
        );
    }

    proptest::proptest! {
        /// Indexed and RGB images of runs, gradients and noise: every filter wins somewhere;
        /// rows up to 600 bytes, many pieces of a filter sum.
        #[test]
        fn idat_is_the_png_crates_own(
            width in 1u32..200,
            height in 1u32..40,
            colours in 1usize..400,
            seed in proptest::prelude::any::<u64>(),
        ) {
            let mut next = xorshift(seed);
            let n = (width * height) as usize;
            let rgb: Vec<u8> = (0..n)
                .flat_map(|i| {
                    let k = match next() % 3 {
                        0 => i % colours,
                        1 => (i / 7) % colours,
                        _ => next() as usize % colours,
                    } as u32;
                    [(k * 37) as u8, (k * 11 + i as u32 / 5) as u8, (k >> 3) as u8]
                })
                .collect();
            let png = encode_png(rgb.clone(), width, height).unwrap();
            proptest::prop_assert_eq!(
                inflated(&png),
                inflated(&encode_png_oracle(&rgb, width, height))
            );
        }
    }

    proptest::proptest! {
        /// Line art as charts have it: a background, vertical lines that run down many rows,
        /// horizontal lines, rows that repeat the one above and rows that repeat it but for a
        /// few pixels, so that pieces are skipped, summed short and summed whole; indexed and
        /// RGB. Both piece widths give the png crate's rows.
        #[test]
        fn idat_of_line_art_is_the_png_crates_own(
            width in 1u32..150,
            height in 1u32..30,
            colours in 2u32..300,
            seed in proptest::prelude::any::<u64>(),
        ) {
            let mut next = xorshift(seed);
            let colour = |k: u64| {
                let k = (k % u64::from(colours)) as u32;
                [(k * 37) as u8, (k * 11) as u8, (k >> 3) as u8]
            };
            let (w, h) = (width as usize, height as usize);
            let verticals: Vec<usize> = (0..1 + next() % 8).map(|_| next() as usize % w).collect();
            let mut rows: Vec<Vec<[u8; 3]>> = Vec::new();
            for _ in 0..h {
                let row = match (rows.last(), next() % 4) {
                    (Some(above), 0) => above.clone(),
                    (Some(above), 1) => {
                        let mut row = above.clone();
                        for _ in 0..1 + next() % 3 {
                            row[next() as usize % w] = colour(next());
                        }
                        row
                    }
                    (_, 2) => vec![colour(next()); w],
                    _ => {
                        let mut row = vec![colour(0); w];
                        for &v in &verticals {
                            row[v] = colour(1 + v as u64);
                        }
                        row
                    }
                };
                rows.push(row);
            }
            let rgb: Vec<u8> = rows.concat().concat();
            proptest::prop_assert_eq!(
                inflated(&encode_png(rgb.clone(), width, height).unwrap()),
                inflated(&encode_png_oracle(&rgb, width, height))
            );
            let mut inputs = vec![(rgb.clone(), 3 * w, 3)];
            inputs.extend(palette(&rgb).map(|(_, indices)| (indices, w, 1)));
            for (data, row_len, bpp) in inputs {
                proptest::prop_assert_eq!(
                    filter_rows_in::<16>(&data, row_len, bpp, Vec::new()),
                    filter_rows_in::<32>(&data, row_len, bpp, Vec::new())
                );
            }
        }
    }

    /// The unsigned-byte Paeth is the specification's, over every (a, b, c).
    #[test]
    fn paeth_is_the_specifications_over_every_byte_triple() {
        let spec = |a: u8, b: u8, c: u8| {
            let p = i16::from(a) + i16::from(b) - i16::from(c);
            let (pa, pb, pc) = (
                (p - i16::from(a)).abs(),
                (p - i16::from(b)).abs(),
                (p - i16::from(c)).abs(),
            );
            if pa <= pb && pa <= pc {
                a
            } else if pb <= pc {
                b
            } else {
                c
            }
        };
        for a in 0..=255u8 {
            for b in 0..=255u8 {
                for c in 0..=255u8 {
                    assert_eq!(paeth(a, b, c), spec(a, b, c), "a {a} b {b} c {c}");
                }
            }
        }
    }

    #[test]
    fn png_has_no_metadata_chunks() {
        let png = encode_png(vec![255u8; 4 * 3 * 3], 4, 3).unwrap();
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
        let png = encode_png(rgb.clone(), 8, 5).unwrap();
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
        let png = encode_png(many.clone(), 300, 1).unwrap();
        let reader = png::Decoder::new(std::io::Cursor::new(&png))
            .read_info()
            .unwrap();
        assert_eq!(reader.info().color_type, png::ColorType::Rgb);
    }
}
