//! Text runs as glyph outlines in an SVG: `<defs>` of the glyphs used, `<use>`s in place of
//! plotters' `<text>` placeholders (see the [parent module](super)).

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::rc::Rc;

use ab_glyph::{Font, GlyphId, OutlineCurve};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{BackendColor, FontTransform};

use super::{Run, degrees, font, px_per_unit};

/// A number for SVG: at most 4 decimals, no trailing zeros, never "-0".
///
/// A whole number (every glyph outline's point and most pens: font units are integers) is
/// written by `itoa`: std's exact formatting of `{v:.4}` went through its big-number fallback
/// for them, 10 M instructions of `render fig3`'s SVG. Same text: the decimals are all zeros
/// and trimmed, and -0 is 0.
fn num(v: f64) -> String {
    let mut s = String::new();
    push_num(&mut s, v);
    s
}

/// Appends [`num`]`(v)` to `out`.
fn push_num(out: &mut String, v: f64) {
    // Below 2^53 every whole f64 converts to i64 exactly.
    if v.fract() == 0.0 && v.abs() < 9_007_199_254_740_992.0 {
        out.push_str(itoa::Buffer::new().format(v as i64));
        return;
    }
    let s = format!("{v:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    out.push_str(if s == "-0" { "0" } else { s });
}

/// `text` escaped for an XML attribute.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

/// The SVG path data of glyph `id` in font units (y up), or None for a blank glyph.
fn glyph_path(id: GlyphId) -> Option<String> {
    let outline = font().outline(id)?;
    let mut d = String::new();
    let mut at: Option<ab_glyph::Point> = None;
    // A point, "x y", after `command` (a letter or a space).
    let p = |d: &mut String, command: char, q: ab_glyph::Point| {
        d.push(command);
        push_num(d, f64::from(q.x));
        d.push(' ');
        push_num(d, f64::from(q.y));
    };
    for c in &outline.curves {
        // The outliner closes each contour with a line back to its start, often of length 0.
        if let OutlineCurve::Line(a, b) = c
            && a == b
        {
            continue;
        }
        let start = match c {
            OutlineCurve::Line(a, _) | OutlineCurve::Quad(a, _, _) | OutlineCurve::Cubic(a, ..) => {
                *a
            }
        };
        if at != Some(start) {
            if at.is_some() {
                d.push('Z');
            }
            p(&mut d, 'M', start);
        }
        let end = match c {
            OutlineCurve::Line(_, b) => {
                p(&mut d, 'L', *b);
                *b
            }
            OutlineCurve::Quad(_, b, e) => {
                p(&mut d, 'Q', *b);
                p(&mut d, ' ', *e);
                *e
            }
            OutlineCurve::Cubic(_, b, c2, e) => {
                p(&mut d, 'C', *b);
                p(&mut d, ' ', *c2);
                p(&mut d, ' ', *e);
                *e
            }
        };
        at = Some(end);
    }
    if d.is_empty() {
        return None;
    }
    d.push('Z');
    Some(d)
}

/// The text runs of one SVG, collected while drawing and put in by [`SvgText::finish`].
#[derive(Debug, Default)]
pub struct SvgText {
    /// Glyph id -> path data, for `<defs>` (sorted: the bytes do not depend on drawing order).
    glyphs: BTreeMap<u16, Option<String>>,
    /// Per `draw_text`, in drawing order: its attributes (fill, label, transform) and its
    /// glyphs (`<use>`s, which depend on the text alone).
    runs: Vec<(String, String)>,
}

impl SvgText {
    /// A shared collector for [`super::Typeset::outlines`].
    pub fn shared() -> Rc<RefCell<SvgText>> {
        Rc::new(RefCell::new(SvgText::default()))
    }

    /// Records one run and returns its placeholder number.
    pub(super) fn push(
        &mut self,
        text: &str,
        size_px: f64,
        at: (f64, f64),
        pos: (HPos, VPos),
        t: FontTransform,
        color: BackendColor,
    ) -> usize {
        let run = Run::new(text);
        let (ax, bl) = run.anchor(pos.0, pos.1);
        let k = px_per_unit(size_px);
        let (r, g, b) = color.rgb;
        let mut s = format!(
            "fill=\"#{r:02X}{g:02X}{b:02X}\" aria-label=\"{}\"",
            escape(text)
        );
        if color.alpha < 1.0 {
            let _ = write!(s, " fill-opacity=\"{}\"", num(color.alpha));
        }
        let _ = write!(s, " transform=\"translate({} {})", num(at.0), num(at.1));
        if degrees(&t) != 0 {
            let _ = write!(s, " rotate({})", degrees(&t));
        }
        let _ = write!(
            s,
            " scale({k:.7} -{k:.7}) translate({} {})\"",
            num(-f64::from(ax)),
            num(-f64::from(bl))
        );
        let mut glyphs = String::new();
        for (id, pen) in run.glyphs {
            let path = self.glyphs.entry(id.0).or_insert_with(|| glyph_path(id));
            if path.is_some() {
                let _ = write!(
                    glyphs,
                    "<use xlink:href=\"#g{}\" x=\"{}\"/>",
                    id.0,
                    num(f64::from(pen))
                );
            }
        }
        self.runs.push((s, glyphs));
        self.runs.len() - 1
    }

    /// `svg` (as plotters wrote it) with the glyphs in `<defs>` and each placeholder `<text>`
    /// replaced by its run; an error names a placeholder that is missing or out of order.
    pub fn finish(&self, svg: &str) -> Result<String, String> {
        let open = svg.find("<svg").ok_or("no <svg> element")?;
        let open_end = open + svg[open..].find('>').ok_or("unterminated <svg> tag")?;
        let mut out = String::with_capacity(svg.len() + 64 * self.runs.len());
        out.push_str(&svg[..open_end]);
        out.push_str(" xmlns:xlink=\"http://www.w3.org/1999/xlink\">\n<defs>\n");
        for (id, d) in &self.glyphs {
            if let Some(d) = d {
                let _ = writeln!(out, "<path id=\"g{id}\" d=\"{d}\"/>");
            }
        }
        // A text drawn more than once (a table's repeated cells) is defined once and used.
        let mut seen: BTreeMap<&str, (usize, usize)> = BTreeMap::new();
        for (i, (_, glyphs)) in self.runs.iter().enumerate() {
            seen.entry(glyphs.as_str()).or_insert((i, 0)).1 += 1;
        }
        let mut shared: Vec<(usize, &str)> = seen
            .iter()
            .filter(|(_, (_, n))| *n > 1)
            .map(|(g, (first, _))| (*first, *g))
            .collect();
        shared.sort_unstable();
        let ids: BTreeMap<&str, usize> = shared.iter().map(|(i, g)| (*g, *i)).collect();
        for (i, glyphs) in &shared {
            let _ = writeln!(out, "<g id=\"t{i}\">{glyphs}</g>");
        }
        out.push_str("</defs>");
        let mut rest = &svg[open_end + 1..];
        for (i, (attrs, glyphs)) in self.runs.iter().enumerate() {
            let start = rest
                .find("<text")
                .ok_or_else(|| format!("text placeholder {i} missing"))?;
            let len = rest[start..]
                .find("</text>")
                .ok_or_else(|| format!("text placeholder {i} unterminated"))?;
            let element = &rest[start..start + len];
            let body = element[element.find('>').unwrap_or(0) + 1..].trim();
            if body != i.to_string() {
                return Err(format!("text placeholder {i} found as {body:?}"));
            }
            out.push_str(&rest[..start]);
            match ids.get(glyphs.as_str()) {
                Some(t) => {
                    let _ = write!(out, "<use xlink:href=\"#t{t}\" {attrs}/>");
                }
                None => {
                    let _ = write!(out, "<g {attrs}>{glyphs}</g>");
                }
            }
            rest = &rest[start + len + "</text>".len()..];
        }
        if rest.contains("<text") {
            return Err("a <text> element was not drawn through the typesetter".into());
        }
        out.push_str(rest);
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whole numbers take `itoa`'s way; the text is std's `{v:.4}` trimmed, as for the others.
    #[test]
    fn whole_numbers_are_written_as_std_writes_them() {
        let std = |v: f64| {
            let s = format!("{v:.4}");
            let s = s.trim_end_matches('0').trim_end_matches('.');
            if s == "-0" {
                "0".to_string()
            } else {
                s.to_string()
            }
        };
        for v in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            7.0,
            10.0,
            -100.0,
            1290.0,
            -2048.0,
            123456789.0,
            4503599627370495.0,
            -9007199254740991.0,
            0.5,
            -0.25,
            1e-5,
            -1e-5,
            12.34567,
            9007199254740992.0,
            1e300,
        ] {
            assert_eq!(num(v), std(v), "{v}");
        }
    }

    #[test]
    fn svg_placeholders_become_glyph_runs() {
        let runs = SvgText::shared();
        let i = runs.borrow_mut().push(
            "a<b",
            15.0,
            (10.0, 20.0),
            (HPos::Left, VPos::Top),
            FontTransform::None,
            BackendColor {
                alpha: 1.0,
                rgb: (0, 0, 0),
            },
        );
        let svg = format!(
            "<svg width=\"4\" xmlns=\"http://www.w3.org/2000/svg\">\n<text x=\"1\">\n{i}\n</text>\n</svg>\n"
        );
        let out = runs.borrow().finish(&svg).unwrap();
        assert!(out.contains("xmlns:xlink"), "{out}");
        assert!(out.contains("aria-label=\"a&lt;b\""), "{out}");
        assert_eq!(out.matches("<use ").count(), 3, "{out}");
        assert_eq!(out.matches("<path id=").count(), 3, "{out}");
        assert!(!out.contains("<text"), "{out}");
        // The same text twice is defined once.
        let twice = SvgText::shared();
        let black = BackendColor {
            alpha: 1.0,
            rgb: (0, 0, 0),
        };
        for at in [(0.0, 0.0), (0.0, 30.0)] {
            let pos = (HPos::Left, VPos::Top);
            twice
                .borrow_mut()
                .push("ab", 15.0, at, pos, FontTransform::None, black);
        }
        let svg = "<svg>\n<text>0</text>\n<text>1</text>\n</svg>";
        let out = twice.borrow().finish(svg).unwrap();
        assert_eq!(out.matches("<g id=\"t0\">").count(), 1, "{out}");
        assert_eq!(out.matches("<use xlink:href=\"#t0\"").count(), 2, "{out}");
        // A placeholder out of order is an error, not a silently wrong picture.
        assert!(runs.borrow().finish("<svg>\n<text>7</text>").is_err());
    }
}
