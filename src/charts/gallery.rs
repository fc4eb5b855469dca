//! `index.html` beside the rendered charts: each chart with its title, the parameters that made
//! it and links to its pictures and data. Plain HTML with inline CSS, no scripts, nothing fetched:
//! it opens from the folder in any browser.

use std::fmt::Write;

use super::spec::Scene;

/// One rendered scene: the scene and the names of the files written for it (e.g. `fig3.svg`).
pub struct Entry<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// File names in the output folder, data first.
    pub files: Vec<String>,
}

/// The gallery page of `entries`, in their order.
pub fn index_html(entries: &[Entry]) -> String {
    let mut s = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>jamchart charts</title>\n<style>\n\
         body { font-family: sans-serif; margin: 2em auto; max-width: 1100px; color: #222; }\n\
         nav a { margin-right: 1em; }\n\
         section { border-top: 1px solid #ccc; padding: 1em 0; }\n\
         img { max-width: 100%; border: 1px solid #ddd; }\n\
         table { border-collapse: collapse; font-size: 0.9em; margin: 0.5em 0; }\n\
         td, th { padding: 0.15em 0.8em 0.15em 0; text-align: left; }\n\
         code { background: #f3f3f3; padding: 0 0.2em; }\n\
         </style>\n</head>\n<body>\n<h1>jamchart charts</h1>\n\
         <p>Lengths in mm, forces in N, mass in kg, angles in degrees. Each chart's data is \
         beside it (CSV; maps also JSON).</p>\n<nav>",
    );
    for e in entries {
        let n = escape(&e.scene.name);
        let _ = write!(s, "<a href=\"#{n}\">{n}</a>");
    }
    s.push_str("</nav>\n");
    for e in entries {
        section(&mut s, e);
    }
    s.push_str("</body>\n</html>\n");
    s
}

fn section(s: &mut String, e: &Entry) {
    let sc = e.scene;
    let name = escape(&sc.name);
    let _ = writeln!(
        s,
        "<section id=\"{name}\">\n<h2>{}</h2>\n<p><code>{name}</code>, chart kind <code>{}</code></p>",
        escape(&sc.title),
        sc.chart.kind()
    );
    let picture = ["png", "svg"]
        .iter()
        .find_map(|ext| e.files.iter().find(|f| f.ends_with(&format!(".{ext}"))));
    if let Some(p) = picture {
        let p = escape(p);
        let _ = writeln!(
            s,
            "<a href=\"{p}\"><img src=\"{p}\" alt=\"{}\" loading=\"lazy\"></a>",
            escape(&sc.title)
        );
    }
    let links: Vec<String> = e
        .files
        .iter()
        .map(|f| format!("<a href=\"{0}\">{0}</a>", escape(f)))
        .collect();
    let _ = writeln!(s, "<p>Files: {}</p>", links.join(" · "));
    s.push_str("<table>\n<tr><th>parameter</th><th>value</th></tr>\n");
    let p = &sc.params;
    let rows = [
        ("mu_ground", p.mu_ground),
        ("mu_palm", p.mu_palm),
        ("radius_mm", p.radius_mm),
        ("mass_kg", p.mass_kg),
        ("force_n", p.force_n),
        ("gravity_m_s2", p.gravity_m_s2),
        ("start_angle_deg", p.start_angle_deg),
        ("palm_length_mm", p.palm_length_mm),
    ];
    for (k, v) in rows {
        let _ = writeln!(s, "<tr><td><code>{k}</code></td><td>{v}</td></tr>");
    }
    s.push_str("</table>\n</section>\n");
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
        let e = Entry {
            scene: &scene,
            files: vec!["x.csv".into(), "x.svg".into(), "x.png".into()],
        };
        let html = index_html(&[e]);
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
}
