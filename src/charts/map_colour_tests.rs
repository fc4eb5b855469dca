//! A filled map's colours: every cell shows the colour of its own band, and a cell without a
//! value none.

use super::*;

/// The README's shaft (r = 12.5 mm, 0.4 kg, an 80 mm palm) over the push and the friction:
/// below mu = 0.15 it is pushed past the palm's end (blank), above it jams at up to 80 mm.
fn shaft_map() -> Scene {
    let set: Vec<_> = [
        "radius_mm=12.5",
        "mass_kg=0.4",
        "palm_length_mm=80",
        "chart.x_axis={param=\"force_n\", min=10.0, max=1000.0, count=61, scale=\"log\"}",
        "chart.y_axis={param=\"mu\", min=0.12, max=0.3, count=61}",
        "chart.theta_jam_levels_deg=[]",
    ]
    .iter()
    .map(|s| s.parse().unwrap())
    .collect();
    SceneSource::BuiltIn("fig7c".into()).load(&set).unwrap()
}

/// Regression: the mu x F map drew a yellow "< 30 mm" band along the whole edge of its blank,
/// where x_jam is about 80 mm: the blank's cells carried a stand-in below every level, and
/// the shading interpolated across from it to 80 mm through every band. Around each blank
/// cell's sample (a fifth of the spacing to the next: the blank's edge lies half-way) no
/// pixel has a band's colour, and at each other cell's sample a band's colour is its own
/// band's. The blank's legend says why it is blank: past the palm's end.
#[test]
fn no_cell_of_a_contour_map_shows_a_colour_its_value_does_not_have() {
    style::init_fonts();
    let scene = shaft_map();
    let chart = Chart::of_scene(&scene).unwrap();
    let (w, h) = (scene.size.width_px, scene.size.height_px);
    let (png, frames) = axes::record_frames(|| {
        output::png(w, h, scene.size.scale, scene.style, |root| {
            chart.draw(root).map_err(|e| e.to_string())
        })
    });
    let rgb = super::tests::rgb_pixels(&png.unwrap());
    let pixel = |x: i32, y: i32| {
        let i = 3 * (y as usize * w as usize + x as usize);
        RGBColor(rgb[i], rgb[i + 1], rgb[i + 2])
    };
    let doc: serde_json::Value =
        serde_json::from_slice(&chart.data_file(&scene.name, &scene.title).bytes).unwrap();
    let levels: Vec<f64> = (doc["x_jam_levels_mm"].as_array().unwrap().iter())
        .map(|v| v.as_f64().unwrap())
        .collect();
    let colors = style::band_colors(levels.len() + 1);
    // status and x_jam_mm per cell, x fastest.
    let csv = String::from_utf8(chart.cells().unwrap().to_bytes()).unwrap();
    let cells: Vec<(String, Option<f64>)> = (csv.lines().skip(1))
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[2].to_string(), f[3].parse().ok())
        })
        .collect();
    let (nx, ny) = (61, 61);
    assert_eq!(cells.len(), nx * ny);
    let f = frames[0];
    let at = |ix: usize, iy: usize| {
        let (u, v) = (ix as f64 / (nx - 1) as f64, iy as f64 / (ny - 1) as f64);
        let x = (f.left + u * (f.right - f.left)) * f64::from(w);
        let y = (f.bottom + v * (f.top - f.bottom)) * f64::from(h);
        (x, y)
    };
    let reach = (at(1, 1).0 - at(0, 0).0).min(at(0, 0).1 - at(1, 1).1) / 5.0;
    let (mut blank, mut wrong) = (0, Vec::new());
    for iy in 0..ny {
        for ix in 0..nx {
            let (status, x_jam) = &cells[iy * nx + ix];
            let (x, y) = at(ix, iy);
            let (x, y) = (x.round() as i32, y.round() as i32);
            match x_jam {
                None => {
                    assert_eq!(status, "beyond_reach");
                    blank += 1;
                    let r = reach.floor() as i32;
                    for (dx, dy) in (-r..=r).flat_map(|dx| (-r..=r).map(move |dy| (dx, dy))) {
                        let (px, py) = (x + dx, y + dy);
                        let inside = (0..w as i32).contains(&px) && (0..h as i32).contains(&py);
                        if inside && colors.contains(&pixel(px, py)) {
                            wrong.push(format!("blank cell ({ix}, {iy}) at ({px}, {py})"));
                        }
                    }
                }
                Some(v) => {
                    let band = levels.iter().filter(|l| v >= *l).count();
                    let c = pixel(x, y);
                    if colors.contains(&c) && c != colors[band] {
                        wrong.push(format!("cell ({ix}, {iy}), x_jam {v} mm, at ({x}, {y})"));
                    }
                }
            }
        }
    }
    assert!(blank > 100, "{blank} blank cells");
    assert!(
        wrong.is_empty(),
        "{} pixels:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
    let svg = String::from_utf8(render(&scene, Formats::Svg).unwrap().svg.unwrap()).unwrap();
    assert!(
        svg.contains(
            "blank, no jam on the palm: the disc is pushed past the palm's end (L = 80.0 mm)"
        ),
        "the legend says why the blank is blank"
    );
}
