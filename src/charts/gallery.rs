//! `index.html` beside the rendered charts: each chart with its title, the parameters that made
//! it, the command that reproduces it and links to its pictures and data. Plain HTML with inline
//! CSS and one inline plain-JS script, nothing fetched: it opens from the folder (file://) in
//! any browser.
//!
//! Every chart kind has a read-off (jam maps, sweeps, the universal chart, contour maps, the
//! V-locator's capacity map, optimum and robust charts, the time series, the min-norm trace,
//! the work-precision chart and the stability matrix): its [`super::readoff`] JSON sits beside
//! the picture; the script (`gallery.js`) shows the values under the pointer (of the panel
//! under it, where stacked panels have their own x axes; of the nearest point or cell where
//! the chart is a table of points) with crosshair lines to the axes, and pins a copyable
//! read-off on a click or tap.
//!
//! On a phone (a window at most 640 px wide) the live line is two lines of small type at the
//! window's bottom, scrolling inside itself for the rest: a longer one covered a third of the
//! picture it reads off (161 of 844 px on the V-locator's optimum chart). The pinned read-offs
//! below the picture hold the whole text.
//!
//! `jamchart accuracy --out-dir` writes the same page for its error-time chart, which is not a
//! scene ([`Entry`] is any chart's section; [`Entry::of_scene`] a scene's): its read-off is
//! the nearest point's row of `accuracy.csv` ([`super::error_time::read_off`]).
//!
//! The page lists every chart in the folder, however many renders wrote it: each chart's section
//! sits between `<!-- chart NAME -->` and `<!-- /chart -->`, and a render (or an accuracy run)
//! keeps the sections of the previous page whose pictures are still in the folder
//! ([`index_html`]).

use std::fmt::Write;

use super::spec::Scene;

/// One chart's section: a rendered scene ([`Entry::of_scene`]) or a chart drawn by another
/// command (`jamchart accuracy`'s error-time chart), and the names of the files written for it.
pub struct Entry<'a> {
    /// The chart's name: its file stem and its section's id (e.g. `fig3`).
    pub name: String,
    /// The chart's title.
    pub title: String,
    /// The chart kind (`kinds.rs`), or what drew a chart that is not a scene.
    pub kind: String,
    /// A sentence under the name, where the chart needs one (e.g. why it is not hash-checked).
    pub note: Option<&'a str>,
    /// The heading of the parameter table ("scene", "V-block") and the parameters by their
    /// TOML keys.
    pub parameters: (&'static str, toml::Table),
    /// File names in the output folder, data first.
    pub files: Vec<String>,
    /// The command that reproduces the chart, as a user would type it.
    pub command: String,
    /// The read-off data as the page embeds it ([`super::readoff::ReadOffData::to_json`]); None
    /// for a chart without one.
    pub read_off: Option<&'a str>,
}

impl<'a> Entry<'a> {
    /// The section of a rendered scene: its name, title and kind, and the parameters its chart
    /// was drawn with (a V-locator chart's V-block and ranges, else the palm scene's).
    pub fn of_scene(scene: &Scene, files: Vec<String>, command: String) -> Entry<'a> {
        Entry {
            name: scene.name.clone(),
            title: scene.title.clone(),
            kind: scene.chart.kind().to_string(),
            note: None,
            parameters: scene.chart.parameters(&scene.input()),
            files,
            command,
            read_off: None,
        }
    }
}

/// Opens a chart's section: `<!-- chart NAME -->`.
const OPEN: &str = "<!-- chart ";
/// Closes a chart's section.
const CLOSE: &str = "<!-- /chart -->\n";

/// The gallery page: the sections of `entries` (this render), those of `previous` (the page
/// this render replaces) for charts not rendered now whose picture is still among `files` (the
/// file names in the folder), and a bare section for any other picture in `files`; by name.
pub fn index_html(entries: &[Entry], previous: Option<&str>, files: &[String]) -> String {
    let mut sections: Vec<(String, String)> = entries
        .iter()
        .map(|e| {
            let mut s = String::new();
            section(&mut s, e);
            (e.name.clone(), s)
        })
        .collect();
    let has_picture = |name: &str| {
        ["png", "svg", "pdf"]
            .iter()
            .any(|ext| files.contains(&format!("{name}.{ext}")))
    };
    for (name, html) in previous.map(sections_of).unwrap_or_default() {
        if has_picture(&name) && !sections.iter().any(|(n, _)| *n == name) {
            sections.push((name, html));
        }
    }
    let mut bare: Vec<&str> = files
        .iter()
        .filter_map(|f| f.strip_suffix(".png").or_else(|| f.strip_suffix(".svg")))
        .filter(|n| !sections.iter().any(|(s, _)| s == n))
        .collect();
    bare.dedup();
    for name in bare {
        let mine: Vec<&String> = files
            .iter()
            .filter(|f| f.rsplit_once('.').is_some_and(|(stem, _)| stem == name))
            .collect();
        sections.push((name.to_string(), bare_section(name, &mine)));
    }
    sections.sort_by(|a, b| a.0.cmp(&b.0));
    let mut s = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>jamchart charts</title>\n<style>\n\
         body { font-family: sans-serif; margin: 2em auto; max-width: 1100px; color: #222; padding: 0 0.5em; }\n\
         nav a { margin-right: 1em; }\n\
         section { border-top: 1px solid #ccc; padding: 1em 0; }\n\
         img { max-width: 100%; border: 1px solid #ddd; }\n\
         table { border-collapse: collapse; font-size: 0.9em; margin: 0.5em 0; }\n\
         td, th { padding: 0.15em 0.8em 0.15em 0; text-align: left; }\n\
         code { background: #f3f3f3; padding: 0 0.2em; }\n\
         figure.readoff { margin: 0; }\n\
         .plot { position: relative; display: inline-block; max-width: 100%; cursor: crosshair; }\n\
         .plot img { display: block; }\n\
         .plot svg.crosshair { position: absolute; left: 0; top: 0; width: 100%; height: 100%; pointer-events: none; }\n\
         .live { font-family: monospace; font-size: 0.85em; min-height: 2.6em; margin: 0.3em 0; overflow-wrap: anywhere; \
         white-space: pre-wrap; position: sticky; bottom: 0; background: #fff; border-top: 1px solid #ddd; padding: 0.2em 0; }\n\
         ul.pins li { white-space: pre-wrap; margin: 0.3em 0; }\n\
         ul.pins button { padding: 0.3em 0.9em; }\n\
         ul.pins { font-size: 0.85em; padding-left: 1.2em; }\n\
         ul.pins code { overflow-wrap: anywhere; }\n\
         @media (max-width: 640px) { .live { font-size: 0.7em; line-height: 1.25; min-height: 0; \
         max-height: 2.5em; overflow-y: auto; margin: 0; padding: 0.1em 0; } }\n\
         </style>\n</head>\n<body>\n<h1>jamchart charts</h1>\n\
         <p>Lengths in mm, forces in N, mass in kg, angles in degrees. Each chart's data is \
         beside it (CSV; maps also JSON).</p>\n<nav>",
    );
    for (name, _) in &sections {
        let n = escape(name);
        let _ = write!(s, "<a href=\"#{n}\">{n}</a>");
    }
    s.push_str("</nav>\n");
    for (_, html) in &sections {
        s.push_str(html);
    }
    let _ = write!(s, "<script>\n{READ_OFF_JS}</script>\n");
    s.push_str("</body>\n</html>\n");
    s
}

/// The read-off script, inline so that the page works from disk with nothing fetched.
pub(crate) const READ_OFF_JS: &str = include_str!("gallery.js");

/// The chart sections of a page written by [`index_html`]: name and HTML, markers included.
fn sections_of(page: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut rest = page;
    while let Some(i) = rest.find(OPEN) {
        let from = &rest[i..];
        let Some(end) = from.find(CLOSE) else { break };
        let html = &from[..end + CLOSE.len()];
        let name = html[OPEN.len()..]
            .split_once(" -->")
            .map(|(n, _)| unescape(n))
            .unwrap_or_default();
        if !name.is_empty() {
            out.push((name, html.to_string()));
        }
        rest = &from[end + CLOSE.len()..];
    }
    out
}

/// A section for a picture in the folder that no run of this gallery recorded (put there by
/// hand, or drawn by an older jamchart): its name and files, no parameters.
fn bare_section(name: &str, files: &[&String]) -> String {
    let n = escape(name);
    let mut s = format!("{OPEN}{n} -->\n<section id=\"{n}\">\n<h2>{n}</h2>\n");
    let picture = ["png", "svg"]
        .iter()
        .find_map(|ext| files.iter().find(|f| f.ends_with(&format!(".{ext}"))));
    if let Some(p) = picture {
        let p = escape(p);
        let _ = writeln!(
            s,
            "<a href=\"{p}\"><img src=\"{p}\" alt=\"{n}\" loading=\"lazy\"></a>"
        );
    }
    let links: Vec<String> = files
        .iter()
        .map(|f| format!("<a href=\"{0}\">{0}</a>", escape(f)))
        .collect();
    let _ = write!(
        s,
        "<p>Files: {}</p>\n<p>Not drawn by <code>jamchart render</code> or <code>jamchart \
         sweep</code> into this folder's gallery: its parameters are not recorded here.</p>\n\
         </section>\n{CLOSE}",
        links.join(" · ")
    );
    s
}

fn section(s: &mut String, e: &Entry) {
    let (name, title) = (escape(&e.name), escape(&e.title));
    let _ = writeln!(
        s,
        "{OPEN}{name} -->\n<section id=\"{name}\">\n<h2>{title}</h2>\n<p><code>{name}</code>, chart kind <code>{}</code></p>",
        escape(&e.kind)
    );
    if let Some(note) = e.note {
        let _ = writeln!(s, "<p>{}</p>", escape(note));
    }
    let picture = ["png", "svg"]
        .iter()
        .find_map(|ext| e.files.iter().find(|f| f.ends_with(&format!(".{ext}"))));
    match (picture, e.read_off) {
        (Some(p), Some(json)) => read_off_figure(s, &name, &escape(p), &title, json),
        (Some(p), None) => {
            let p = escape(p);
            let _ = writeln!(
                s,
                "<a href=\"{p}\"><img src=\"{p}\" alt=\"{title}\" loading=\"lazy\"></a>"
            );
        }
        (None, _) => {}
    }
    let links: Vec<String> = e
        .files
        .iter()
        .map(|f| format!("<a href=\"{0}\">{0}</a>", escape(f)))
        .collect();
    let _ = writeln!(s, "<p>Files: {}</p>", links.join(" · "));
    let _ = writeln!(s, "<p>Reproduce: <code>{}</code></p>", escape(&e.command));
    let (what, table) = &e.parameters;
    let _ = writeln!(
        s,
        "<table>\n<tr><th>{what} parameter</th><th>value</th></tr>"
    );
    for (k, v) in table {
        let v = match v {
            toml::Value::String(t) => t.clone(),
            toml::Value::Float(f) => crate::settings::number_text(*f),
            other => other.to_string(),
        };
        let _ = writeln!(
            s,
            "<tr><td><code>{}</code></td><td>{}</td></tr>",
            escape(k),
            escape(&v)
        );
    }
    s.push_str("</table>\n</section>\n");
    s.push_str(CLOSE);
}

/// A picture with a read-off: the picture under a crosshair overlay, its data as JSON (`</` is
/// escaped so that no value can end the script element), the live read-off and the pinned ones.
/// The live line sticks to the window's bottom while its figure is in view: on a phone a tall
/// chart's read-off would otherwise be written below the picture, off the screen; there it
/// is at most two lines high (see the module docs).
fn read_off_figure(s: &mut String, name: &str, picture: &str, alt: &str, json: &str) {
    let json = json.replace("</", "<\\/");
    let _ = write!(
        s,
        "<figure class=\"readoff\" data-chart=\"{name}\">\n\
         <div class=\"plot\"><img src=\"{picture}\" alt=\"{alt}\">\
         <svg class=\"crosshair\" viewBox=\"0 0 1000 1000\" preserveAspectRatio=\"none\"></svg></div>\n\
         <script type=\"application/json\" class=\"readoff-data\">{json}</script>\n\
         <p class=\"live\" id=\"readoff-{name}\" aria-live=\"polite\">Point at the chart \
         to read it off; click or tap to pin the values.</p>\n\
         <figcaption><ul class=\"pins\"></ul></figcaption>\n\
         </figure>\n"
    );
}

/// `t` with the escapes of [`escape`] undone.
fn unescape(t: &str) -> String {
    t.replace("&quot;", "\"")
        .replace("&gt;", ">")
        .replace("&lt;", "<")
        .replace("&amp;", "&")
}

/// `t` with the HTML metacharacters escaped.
fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn page_links_every_file_and_escapes_titles() {
        let mut scene = crate::charts::builtin::scene_names()
            .first()
            .map(|n| {
                crate::charts::SceneSource::BuiltIn(n.clone())
                    .load(&[])
                    .unwrap()
            })
            .unwrap();
        scene.title = "a <b> & c".into();
        let e = Entry::of_scene(
            &scene,
            vec!["x.csv".into(), "x.svg".into(), "x.png".into()],
            "jamchart render x".into(),
        );
        let html = index_html(&[e], None, &[]);
        assert!(html.contains("a &lt;b&gt; &amp; c"), "{html}");
        assert!(html.contains("<img src=\"x.png\""), "{html}");
        for f in ["x.csv", "x.svg", "x.png"] {
            assert!(html.contains(&format!("<a href=\"{f}\">{f}</a>")), "{f}");
        }
        assert!(
            html.contains("<code>force_n</code></td><td>200</td>"),
            "{html}"
        );
    }

    fn built_in(name: &str) -> Scene {
        crate::charts::SceneSource::BuiltIn(name.into())
            .load(&[])
            .unwrap()
    }

    fn entry<'a>(scene: &Scene) -> Entry<'a> {
        Entry::of_scene(
            scene,
            ["csv", "svg", "png"]
                .map(|ext| format!("{}.{ext}", scene.name))
                .into(),
            format!("jamchart render {}", scene.name),
        )
    }

    /// A second `render fig3` into the same folder replaced index.html with fig3 alone: the
    /// page keeps the sections of the charts still in the folder, adds a bare one for a
    /// picture no render recorded, and drops a chart whose pictures are gone.
    #[test]
    fn a_second_render_keeps_every_chart_of_the_folder_in_the_page() {
        let (fig3, fig7a, fig7b) = (built_in("fig3"), built_in("fig7a"), built_in("fig7b"));
        let first = index_html(&[entry(&fig7a), entry(&fig7b)], None, &[]);
        let files: Vec<String> = ["fig3.png", "fig7a.png", "fig7a.csv", "sweep_mu.svg"]
            .map(String::from)
            .into();
        let second = index_html(&[entry(&fig3)], Some(&first), &files);
        for name in ["fig3", "fig7a", "sweep_mu"] {
            assert!(
                second.contains(&format!("<section id=\"{name}\">")),
                "{name} missing:\n{second}"
            );
        }
        // fig7b's pictures are no longer in the folder.
        assert!(!second.contains("id=\"fig7b\""), "{second}");
        // The kept section is the one the first render wrote, parameters and all.
        let kept = &sections_of(&first)[0];
        assert_eq!(kept.0, "fig7a");
        assert!(second.contains(&kept.1));
        // A third render keeps them again: the page is stable under re-rendering.
        let third = index_html(&[entry(&fig3)], Some(&second), &files);
        assert_eq!(third, second);
    }

    /// The gallery had no read-off: a chart with read-off data gets a figure the page's script
    /// finds (picture, crosshair overlay, its JSON, the live line), the script is inline (the
    /// page works from file:// with nothing fetched), a `</script>` inside the data cannot end
    /// its element, and the command that reproduces the chart is shown.
    #[test]
    fn a_chart_with_read_off_data_gets_the_read_off_figure_and_script() {
        let fig3 = built_in("fig3");
        let json = r#"{"kind":"jam_map","x":{"label":"</script><b>"}}"#;
        let e = Entry {
            read_off: Some(json),
            ..entry(&fig3)
        };
        let html = index_html(&[e], None, &[]);
        assert!(
            html.contains("<figure class=\"readoff\" data-chart=\"fig3\">"),
            "{html}"
        );
        assert!(html.contains("<svg class=\"crosshair\""), "{html}");
        assert!(html.contains(r#"{"label":"<\/script><b>"}"#), "{html}");
        assert_eq!(html.matches("</script>").count(), 2, "data and script only");
        assert!(html.contains("id=\"readoff-fig3\""), "{html}");
        assert!(html.contains(READ_OFF_JS), "the script is inline");
        assert!(!html.contains("src=\"http"), "nothing is fetched");
        assert!(
            html.contains("<p>Reproduce: <code>jamchart render fig3</code></p>"),
            "{html}"
        );
        // Without read-off data the picture stays a plain link.
        let plain = index_html(&[entry(&fig3)], None, &[]);
        assert!(!plain.contains("<figure"), "{plain}");
        assert!(plain.contains("<a href=\"fig3.png\"><img"), "{plain}");
    }

    /// The V-block charts' sections listed the palm scene's parameters (mu 0.4, 1 kg, 200 N)
    /// while the charts show a V-block: they list the V-block's own.
    #[test]
    fn v_block_sections_show_the_v_blocks_parameters() {
        for name in ["vlocator-capacity", "vlocator-optimum", "vlocator-robust"] {
            let scene = built_in(name);
            let html = index_html(&[entry(&scene)], None, &[]);
            assert!(html.contains("V-block parameter"), "{html}");
            assert!(
                html.contains("<code>mass_kg</code></td><td>1</td>"),
                "{html}"
            );
            assert!(!html.contains("force_n"), "{html}");
        }
    }

    /// The section of a V-block robust chart drawn for a friction range of 0.1 to 0.25 under a
    /// 20 N load listed the locator's defaults, mu 0.3 and load 0, which that chart does not
    /// use: the table comes from the chart's own input, in either form of the range.
    #[test]
    fn a_robust_v_block_section_lists_the_range_and_load_it_is_drawn_for() {
        let mut scene = built_in("vlocator-robust");
        let crate::charts::ChartSpec::VlocatorRobust(s) = &mut scene.chart else {
            panic!("a robust chart")
        };
        s.mu = None;
        s.mu_center = Some(0.175);
        s.width_max = Some(0.15);
        s.load_n = crate::figures::vlocator_robust::Interval::point(20.0);
        let html = index_html(&[entry(&scene)], None, &[]);
        for row in [
            "<code>mu_center</code></td><td>0.175</td>",
            "<code>width_max</code></td><td>0.15</td>",
            "<code>load_n</code></td><td>20</td>",
            "<code>load_angle_deg</code></td><td>-10:10</td>",
        ] {
            assert!(html.contains(row), "{row} missing:\n{html}");
        }
        assert!(!html.contains("mu_left"), "{html}");
        let range = built_in("vlocator-robust-range");
        let html = index_html(&[entry(&range)], None, &[]);
        for row in [
            "<code>mu</code></td><td>0.1:0.25</td>",
            "<code>load_n</code></td><td>20</td>",
            "<code>mass_kg</code></td><td>0.4</td>",
        ] {
            assert!(html.contains(row), "{row} missing:\n{html}");
        }
    }

    /// The gallery's `#readoff=NAME:X:Y` link was documented only in a comment of the script:
    /// the guide says how to write one, in the script's own form.
    #[test]
    fn the_read_off_link_is_documented_in_the_guide() {
        let guide = include_str!("../guide.md");
        assert!(READ_OFF_JS.contains("readoff=NAME:X[:Y][;NAME:X...]"));
        for form in [
            "index.html#readoff=NAME:X:Y",
            "`NAME@P:X:Y`",
            "#readoff=fig3:0.3;fig7a:20",
        ] {
            assert!(guide.contains(form), "the guide does not show {form}");
        }
    }
}
