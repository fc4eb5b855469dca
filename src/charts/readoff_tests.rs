//! The gallery's read-off as the page reads it: frames that put a value where the chart drew
//! it, a read-off for every built-in scene, and every key `gallery.js` reads written by the
//! types of [`super::readoff`] (and read by the script).

use std::collections::BTreeSet;

use serde_json::Value;

use super::{Formats, SceneSource, render};

/// Every built-in scene's name and read-off as the page embeds it.
fn built_in_read_offs() -> Vec<(String, Value)> {
    (super::builtin::scene_names().into_iter())
        .map(|name| {
            let scene = SceneSource::BuiltIn(name.clone()).load(&[]).unwrap();
            let r = render(&scene, Formats::Svg).unwrap();
            let json = (r.read_off.as_deref()).unwrap_or_else(|| panic!("{name} has no read-off"));
            (name, serde_json::from_str(json).unwrap())
        })
        .collect()
}

/// The pixel of (x, y) in a `w` x `h` picture, through the read-off's first panel as the
/// page maps it (frames are at pixel centres).
fn pixel_of(doc: &Value, x: f64, y: f64, (w, h): (u32, u32)) -> (usize, usize) {
    let f = &doc["panels"][0]["frame"];
    let frac = |a: &Value, v: f64| {
        let (lo, hi) = (a["min"].as_f64().unwrap(), a["max"].as_f64().unwrap());
        match a["log"].as_bool().unwrap() {
            true => (v / lo).ln() / (hi / lo).ln(),
            false => (v - lo) / (hi - lo),
        }
    };
    let e = |k: &str| f[k].as_f64().unwrap();
    let u = e("left") + frac(&doc["x"], x) * (e("right") - e("left"));
    let v = e("bottom") - frac(&doc["panels"][0]["y"], y) * (e("bottom") - e("top"));
    (
        (u * f64::from(w) - 0.5).round() as usize,
        (v * f64::from(h) - 0.5).round() as usize,
    )
}

/// RGB of pixel (i, j) of a PNG.
fn rgb_at(png_bytes: &[u8], (i, j): (usize, usize)) -> [u8; 3] {
    let mut r = png::Decoder::new(std::io::Cursor::new(png_bytes))
        .read_info()
        .unwrap();
    let palette = r.info().palette.clone().map(|p| p.into_owned());
    let width = r.info().width as usize;
    let mut buf = vec![0; r.output_buffer_size()];
    r.next_frame(&mut buf).unwrap();
    match palette {
        Some(p) => {
            let k = 3 * buf[j * width + i] as usize;
            [p[k], p[k + 1], p[k + 2]]
        }
        None => {
            let k = 3 * (j * width + i);
            [buf[k], buf[k + 1], buf[k + 2]]
        }
    }
}

/// The gallery had no read-off: its frames must put a value where the chart drew it.
/// fig3 draws its own read-off (mu 0.4, theta_jam 44.6 deg) as a black dot of radius 5;
/// mapped through the exported frame and axes, that point lands on the dot, at scale 1 and
/// at scale 2 (a frame in logical px would be off by half the picture at scale 2).
#[test]
fn the_read_off_frame_puts_fig3s_jam_point_on_its_dot() {
    for (scale, w, h) in [(1.0, 1000, 950), (2.0, 2000, 1900)] {
        let mut scene = SceneSource::BuiltIn("fig3".into()).load(&[]).unwrap();
        scene.size.scale = scale;
        (scene.size.width_px, scene.size.height_px) = (w, h);
        let r = render(&scene, Formats::Png).unwrap();
        let doc: Value = serde_json::from_str(r.read_off.as_deref().unwrap()).unwrap();
        let data: Value = serde_json::from_slice(&r.data.bytes).unwrap();
        let (mu, theta) = (
            data["read_off"]["mu"].as_f64().unwrap(),
            data["read_off"]["theta_jam_deg"].as_f64().unwrap(),
        );
        let at = pixel_of(&doc, mu, theta, (w, h));
        let [r_, g, b] = rgb_at(r.png.as_deref().unwrap(), at);
        assert!(
            u32::from(r_) + u32::from(g) + u32::from(b) < 120,
            "scale {scale}: pixel {at:?} is {:?}, not the dot's ink",
            [r_, g, b]
        );
        // The frame's corner is the axis corner: (0.1, 10 deg) is on the frame's ink too.
        let corner = pixel_of(&doc, 0.1, 10.0, (w, h));
        let [r_, g, b] = rgb_at(r.png.as_deref().unwrap(), corner);
        assert!(
            u32::from(r_) + u32::from(g) + u32::from(b) < 200,
            "{corner:?}"
        );
    }
}

/// The time series, the min-norm trace, the work-precision chart and the stability matrix
/// had no read-off: every built-in scene has one now, with a frame per panel inside the
/// picture, and a `points` chart's points name rows it carries (the matrix, drawn without
/// axes, records its frame itself: without it the read-off would be missing).
#[test]
fn every_built_in_scene_has_a_read_off_with_frames_and_rows() {
    for (name, doc) in built_in_read_offs() {
        let panels = doc["panels"].as_array().unwrap();
        assert!(!panels.is_empty(), "{name}");
        for p in panels {
            let f = |k: &str| p["frame"][k].as_f64().unwrap();
            assert!(
                0.0 <= f("left") && f("left") < f("right") && f("right") <= 1.0,
                "{name}: {p}"
            );
            assert!(
                0.0 <= f("top") && f("top") < f("bottom") && f("bottom") <= 1.0,
                "{name}: {p}"
            );
            if doc["kind"] == "points" {
                let rows = doc["rows"].as_array().unwrap().len();
                let points = p["points"].as_array().unwrap();
                assert!(!points.is_empty(), "{name}: a panel without points");
                for pt in points {
                    assert!((pt[2].as_u64().unwrap() as usize) < rows, "{name}: {pt}");
                }
            }
        }
    }
}

/// The keys of an axis the page reads (`frac`, `plot`, the text).
const AXIS: &[&str] = &["param", "min", "max", "log"];

/// The keys of a frame the page reads (the panel under the pointer, the crosshair).
const FRAME: &[&str] = &["left", "top", "right", "bottom"];

/// What `gallery.js` reads of a read-off of one kind, besides `kind` and each panel's `frame`
/// and `y` axis (every kind's). A path names a key in the read-off, `[]` every element of a
/// list; the keys the script reads under names the read-off gives (a jam map's column
/// `x.param`, a series' column a panel's `quantity` names) are checked in
/// [`named_reads`].
struct Reads {
    kind: &'static str,
    /// The keys every read-off of the kind has.
    keys: &'static [&'static str],
    /// The axes among them, each with the keys of [`AXIS`].
    axes: &'static [&'static str],
    /// Keys some read-offs of the kind leave out (the script tests for them).
    optional: &'static [&'static str],
}

const READS: &[Reads] = &[
    Reads {
        kind: "jam_map",
        keys: &[
            "model",
            "x",
            "columns.theta_jam_deg",
            "columns.x_jam_mm",
            "columns.reach_deg",
            "columns.status",
            "disc.radius_mm",
            "disc.palm_offset_mm",
        ],
        axes: &["x"],
        optional: &[],
    },
    Reads {
        kind: "sweep",
        keys: &[
            "x",
            "panels[].quantity",
            "series[].label",
            "series[].layer",
            "series[].line",
            "series[].at",
        ],
        axes: &["x"],
        optional: &[],
    },
    Reads {
        kind: "grid",
        keys: &["model", "x", "grid.x", "grid.y", "grid.cells"],
        axes: &["x"],
        optional: &[],
    },
    Reads {
        kind: "panels",
        keys: &[
            "model",
            "panels[].x",
            "panels[].quantity",
            "panels[].sweep",
            "sweeps[].param",
            "sweeps[].at",
            "sweeps[].fixed",
            "sweeps[].series[].label",
        ],
        axes: &["panels[].x"],
        optional: &[],
    },
    Reads {
        kind: "points",
        keys: &["crosshair", "panels[].x", "panels[].points", "rows"],
        axes: &["panels[].x"],
        optional: &["cell"],
    },
];

/// The values at `path` in `doc` (`[]`: each element of a list, which must not be empty), or
/// what is missing.
fn at_path<'a>(doc: &'a Value, path: &str) -> Result<Vec<&'a Value>, String> {
    let mut here = vec![doc];
    for seg in path.split('.') {
        let (key, each) = match seg.strip_suffix("[]") {
            Some(k) => (k, true),
            None => (seg, false),
        };
        let mut next = Vec::new();
        for v in here {
            let v = v
                .get(key)
                .ok_or_else(|| format!("no `{key}` of `{path}`"))?;
            match (each, v.as_array()) {
                (false, _) => next.push(v),
                (true, Some(a)) if !a.is_empty() => next.extend(a),
                (true, _) => return Err(format!("`{key}` of `{path}` is not a list of any")),
            }
        }
        here = next;
    }
    Ok(here)
}

/// Every path [`READS`] gives for `r`, axes and frames expanded to their keys.
fn paths(r: &Reads) -> Vec<String> {
    let mut paths: Vec<String> = ["kind".to_string()].into();
    paths.extend(r.keys.iter().map(|k| k.to_string()));
    paths.extend(FRAME.iter().map(|k| format!("panels[].frame.{k}")));
    for axis in r.axes.iter().chain(&["panels[].y"]) {
        paths.extend(AXIS.iter().map(|k| format!("{axis}.{k}")));
    }
    paths
}

/// What the page reads of `doc` under names `doc` gives, missing: a jam map's column named by
/// its `x.param`; a sweep's series' column each panel's `quantity` names (read of every
/// series); a panel's sweep (`sweep`, an index) and its `quantity`, a column of one of its
/// series; a map's cells, one per kept cell; a point's row.
fn named_reads(doc: &Value) -> Vec<String> {
    let mut missing = Vec::new();
    let mut need = |ok: bool, what: String| {
        if !ok {
            missing.push(what);
        }
    };
    let panels = doc["panels"].as_array().map_or(&[][..], Vec::as_slice);
    let len = |v: &Value| v.as_array().map(Vec::len);
    match doc["kind"].as_str() {
        Some("jam_map") => {
            let param = doc["x"]["param"].as_str().unwrap_or_default();
            let n = len(&doc["columns"]["theta_jam_deg"]);
            need(len(&doc["columns"][param]) == n, format!("columns.{param}"));
        }
        Some("sweep") => {
            for q in panels
                .iter()
                .map(|p| p["quantity"].as_str().unwrap_or_default())
            {
                for s in doc["series"].as_array().into_iter().flatten() {
                    need(len(&s[q]) == len(&s["at"]), format!("series[].{q}"));
                }
            }
        }
        Some("panels") => {
            for p in panels {
                let (q, sweep) = (p["quantity"].as_str().unwrap_or_default(), &p["sweep"]);
                let s = &doc["sweeps"][sweep.as_u64().unwrap_or(u64::MAX) as usize];
                need(s.is_object(), format!("sweeps[{sweep}]"));
                let series = s["series"].as_array().into_iter().flatten();
                let of = |e: &Value| len(&e[q]) == len(&s["at"]);
                need(
                    series.clone().any(of),
                    format!("sweeps[{sweep}].series[].{q}"),
                );
            }
        }
        Some("grid") => {
            let g = &doc["grid"];
            let n = len(&g["x"]).unwrap_or(0) * len(&g["y"]).unwrap_or(0);
            for (q, cells) in g["cells"].as_object().into_iter().flatten() {
                need(len(cells) == Some(n), format!("grid.cells.{q}: {n} cells"));
            }
        }
        Some("points") => {
            let rows = len(&doc["rows"]).unwrap_or(0);
            for p in panels.iter().flat_map(|p| p["points"].as_array()).flatten() {
                let row = p[2].as_u64().map(|i| i as usize);
                need(row.is_some_and(|i| i < rows), format!("rows[{}]", p[2]));
            }
        }
        _ => need(false, "a kind".into()),
    }
    missing
}

/// What `doc` lacks of what the page reads of its kind.
fn unwritten(doc: &Value) -> Vec<String> {
    let Some(r) = READS.iter().find(|r| doc["kind"] == r.kind) else {
        return vec![format!("kind {}", doc["kind"])];
    };
    let mut missing: Vec<String> = (paths(r).iter())
        .filter_map(|p| at_path(doc, p).err())
        .collect();
    missing.extend(named_reads(doc));
    missing
}

/// Whether `c` may be part of a JavaScript identifier.
fn ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '$'
}

/// The identifier at the start of `s`, if any.
fn leading_ident(s: &str) -> Option<&str> {
    let end = s.find(|c: char| !ident(c)).unwrap_or(s.len());
    (end > 0).then(|| &s[..end])
}

/// The members `js` reads of `object` where it is a whole word: `KEY` of `c.KEY` (not of
/// `fc.KEY`) for `c`; of `c.panels[p].KEY` for `c.panels[`.
fn members<'a>(js: &'a str, object: &str) -> BTreeSet<&'a str> {
    let mut found = BTreeSet::new();
    for (i, _) in js.match_indices(object) {
        if js[..i].chars().next_back().is_some_and(ident) {
            continue;
        }
        let mut rest = &js[i + object.len()..];
        if object.ends_with('[') {
            let Some(close) = rest.find(']') else {
                continue;
            };
            rest = &rest[close + 1..];
        }
        found.extend(rest.strip_prefix('.').and_then(leading_ident));
    }
    found
}

/// The keys of a path, without `[]`.
fn segs(path: &str) -> impl Iterator<Item = &str> {
    path.split('.').map(|s| s.trim_end_matches("[]"))
}

/// What `js` reads of a read-off that [`READS`] does not list, and what it lists that `js`
/// does not read: the chart's keys (`c.KEY`) and a panel's (`c.panels[p].KEY`, `pa.KEY`)
/// must be listed, and every key of every path appear as `.KEY`.
fn unlisted(js: &str) -> Vec<String> {
    let all: Vec<&str> = (READS.iter())
        .flat_map(|r| r.keys.iter().chain(r.optional))
        .chain(&["kind", "panels[].frame", "panels[].y"])
        .copied()
        .collect();
    let top: BTreeSet<&str> = all.iter().filter_map(|p| segs(p).next()).collect();
    let panel: BTreeSet<&str> = (all.iter())
        .filter_map(|p| segs(p.strip_prefix("panels[].")?).next())
        .collect();
    let mut problems: Vec<String> = (members(js, "c").into_iter())
        .filter(|k| !top.contains(k))
        .map(|k| format!("the script reads c.{k}, which no kind lists"))
        .collect();
    let of_panels = members(js, "c.panels[")
        .into_iter()
        .chain(members(js, "pa"));
    problems.extend(
        of_panels
            .filter(|k| !panel.contains(k))
            .map(|k| format!("the script reads a panel's {k}, which no kind lists")),
    );
    let dotted: BTreeSet<&str> = js.split('.').skip(1).filter_map(leading_ident).collect();
    let listed: BTreeSet<&str> = (all.iter().flat_map(|p| segs(p)))
        .chain(AXIS.iter().chain(FRAME).copied())
        .collect();
    problems.extend(
        (listed.into_iter())
            .filter(|k| !dotted.contains(k))
            .map(|k| format!("the script never reads .{k}, listed as read")),
    );
    problems
}

/// gallery.js reads the read-off's keys by name, and the types write them: for every built-in
/// scene, every key the script reads of its kind is in its read-off, and every kind has a
/// scene; the script reads no key of the chart or of a panel that the list leaves out, and
/// every listed key is read by it.
#[test]
fn gallery_js_reads_only_keys_the_read_off_types_write() {
    let js = super::GALLERY_JS;
    assert_eq!(
        unlisted(js),
        Vec::<String>::new(),
        "gallery.js against the list"
    );
    let mut kinds = BTreeSet::new();
    let mut optional = BTreeSet::new();
    for (name, doc) in built_in_read_offs() {
        assert_eq!(unwritten(&doc), Vec::<String>::new(), "{name}");
        let r = READS.iter().find(|r| doc["kind"] == r.kind).unwrap();
        kinds.insert(r.kind);
        optional.extend(r.optional.iter().filter(|k| at_path(&doc, k).is_ok()));
    }
    let listed = READS.iter().map(|r| r.kind).collect();
    assert_eq!(
        kinds, listed,
        "a kind without a built-in scene is not checked"
    );
    let all_optional = READS.iter().flat_map(|r| r.optional).collect();
    assert_eq!(optional, all_optional, "an optional key no scene writes");
}

/// The checks above fail where they should: a read-off without a key the page reads, with a
/// column a panel names left out or a point naming a row it lacks; a script that reads a key
/// the list does not give, or no longer reads one it gives.
#[test]
fn the_key_checks_fail_on_a_missing_key_and_an_unlisted_read() {
    let docs = built_in_read_offs();
    let doc = |name: &str| docs.iter().find(|(n, _)| n == name).unwrap().1.clone();
    let mut fig3 = doc("fig3");
    fig3["disc"]
        .as_object_mut()
        .unwrap()
        .remove("palm_offset_mm");
    assert_eq!(
        unwritten(&fig3),
        ["no `palm_offset_mm` of `disc.palm_offset_mm`"]
    );
    let mut fig6 = doc("fig6");
    let quantity = fig6["panels"][0]["quantity"].as_str().unwrap().to_string();
    fig6["series"][0].as_object_mut().unwrap().remove(&quantity);
    assert_eq!(unwritten(&fig6), [format!("series[].{quantity}")]);
    let mut fig4 = doc("fig4");
    fig4["rows"].as_array_mut().unwrap().clear();
    assert!(unwritten(&fig4).iter().any(|m| m.starts_with("rows[")));
    let js = super::GALLERY_JS;
    let reads_more = js.replace("var d = c.disc", "var d = c.disc || c.geometry");
    assert_eq!(
        unlisted(&reads_more),
        ["the script reads c.geometry, which no kind lists"]
    );
    let reads_less = js.replace("col.reach_deg", "col.reach");
    assert_eq!(
        unlisted(&reads_less),
        ["the script never reads .reach_deg, listed as read"]
    );
}
