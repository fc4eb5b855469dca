//! Series told apart: every curve and point set of a chart differs from every other
//! by what it looks like, in colour and in the print style's greys alike.
//!
//! A chart's legend shows each drawn series' sample (the legend names no line that is not
//! drawn, and a series is drawn as its sample shows it), so the samples [`legend`] draws,
//! recorded while a scene renders, are the series' looks.

use super::legend::{self, Swatch};
use super::print::{Ink, stroke_grey};
use super::style::Marker;
use super::*;

/// An RGB triple.
type Rgb = (u8, u8, u8);

/// A line's look: its colour, dashes (dash, gap in px; None for solid) and width in px.
type LineLook = (Rgb, Option<(u32, u32)>, u32);

/// A series' look as printed: its line (colour, dashes, width) and its marker (shape, colour).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Look {
    line: Option<LineLook>,
    marker: Option<(Marker, Rgb)>,
}

/// Two greys closer than this read as the same ink on paper (a fifth of the range).
const PRINT_GREY_STEP: i32 = 48;

/// The look of a legend sample in `ink`, or None for what is not a series (region patches,
/// step numbers).
fn look(sw: Swatch, ink: Ink) -> Option<Look> {
    // Lines and markers are strokes or small fills: both print as a stroke's grey would.
    let tone = |c: plotters::style::RGBColor| -> Rgb {
        let c = (c.0, c.1, c.2);
        match ink {
            Ink::Colour => c,
            Ink::Print => stroke_grey(c),
        }
    };
    let line = |k: style::LineKind, c| Some((tone(c), k.dashes(), k.width()));
    let marker = |m: Marker| Some((m, tone(m.color())));
    Some(match sw {
        Swatch::Line(k) => Look {
            line: line(k, k.color()),
            marker: None,
        },
        Swatch::Stroke(k, c, px) => Look {
            line: Some((tone(c), k.dashes(), px)),
            marker: None,
        },
        Swatch::Marker(m) => Look {
            line: None,
            marker: marker(m),
        },
        Swatch::LineMarker(k, m) => Look {
            line: line(k, style::marked_line_color(m)),
            marker: marker(m),
        },
        Swatch::Patch(_) | Swatch::Step(_) => return None,
    })
}

/// Whether two lines read apart: by dashes or width, else by colour (by a clear step of grey
/// in print, where hues are gone).
fn lines_differ(a: LineLook, b: LineLook) -> bool {
    if a.1 != b.1 || a.2 != b.2 {
        return true;
    }
    let grey = a.0.0 == a.0.1 && a.0.1 == a.0.2 && b.0.0 == b.0.1 && b.0.1 == b.0.2;
    if grey {
        (i32::from(a.0.0) - i32::from(b.0.0)).abs() >= PRINT_GREY_STEP
    } else {
        a.0 != b.0
    }
}

/// Why two looks cannot be told apart, or None.
fn clash(a: Look, b: Look) -> Option<&'static str> {
    if a == b {
        return Some("the same colour, line and marker");
    }
    // A marker every few points does not tell two lines apart between them.
    match (a.line, b.line) {
        (Some(p), Some(q)) if !lines_differ(p, q) => Some("lines that differ only by marker"),
        _ => None,
    }
}

/// Regression: integration-error drew radau5's curves in one black solid line told
/// apart by their markers only, fig6 and vlocator-optimum series differed only by marker, and
/// fig5 had two legend entries in the same thin blue dash. For every built-in scene in both
/// inks, no two series share their look, and no two lines differ only by their markers.
#[test]
fn every_series_is_told_apart_in_colour_and_in_print() {
    style::init_fonts();
    let mut faults = Vec::new();
    for name in builtin::scene_names() {
        for ink in [Ink::Colour, Ink::Print] {
            let ink_key = match ink {
                Ink::Colour => "style=\"colour\"",
                Ink::Print => "style=\"print\"",
            };
            let settings = [ink_key.parse().unwrap()];
            let scene = SceneSource::BuiltIn(name.clone())
                .load(&settings)
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            let chart = Chart::of_scene(&scene).expect("the scene computes");
            let s = &scene.size;
            let (drawn, swatches) = legend::record_swatches(|| {
                output::svg(s.width_px, s.height_px, s.scale, scene.style, |root| {
                    chart.draw(root).map_err(|e| e.to_string())
                })
            });
            drawn.expect("the scene draws");
            let looks: Vec<(Swatch, Look)> = swatches
                .into_iter()
                .filter_map(|sw| look(sw, ink).map(|l| (sw, l)))
                .collect();
            for (i, (sa, a)) in looks.iter().enumerate() {
                for (sb, b) in &looks[i + 1..] {
                    if let Some(why) = clash(*a, *b) {
                        faults.push(format!("{name} ({ink:?}): {sa:?} and {sb:?}: {why}"));
                    }
                }
            }
        }
    }
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}

#[test]
fn the_clash_rule_catches_what_it_should() {
    use super::style::LineKind;
    let solid = |m| look(Swatch::LineMarker(LineKind::Solid, m), Ink::Print).unwrap();
    // Blue and vermillion lines print as greys 51 and 59: one ink on paper.
    assert!(clash(solid(Marker::Circle), solid(Marker::Triangle)).is_some());
    let a = look(Swatch::Line(LineKind::Solid), Ink::Colour).unwrap();
    let b = look(Swatch::Line(LineKind::Dashed), Ink::Colour).unwrap();
    assert_eq!(clash(a, b), None);
    assert!(clash(a, a).is_some());
    let dot = look(Swatch::Marker(Marker::Dot), Ink::Colour).unwrap();
    let square = look(Swatch::Marker(Marker::Square), Ink::Colour).unwrap();
    assert_eq!(clash(dot, square), None);
}
