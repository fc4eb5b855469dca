//! Chart bytes: deterministic PNG encoding (the files are written by the crate's all-or-nothing writer, `atomic`).

/// Encodes an RGB8 buffer as PNG with only the IHDR, IDAT and IEND chunks: no time, no text, no
/// gamma, so the bytes depend on the pixels alone.
pub fn encode_png(rgb: &[u8], width: u32, height: u32) -> std::result::Result<Vec<u8>, String> {
    let mut out = Vec::with_capacity(rgb.len() / 8);
    {
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        // Fast keeps `render` quick; the chart images are flat greys that compress well anyway.
        enc.set_compression(png::Compression::Fast);
        let mut w = enc.write_header().map_err(|e| e.to_string())?;
        w.write_image_data(rgb).map_err(|e| e.to_string())?;
        w.finish().map_err(|e| e.to_string())?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

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
        assert_eq!(chunks, ["IHDR", "IDAT", "IEND"]);
    }
}
