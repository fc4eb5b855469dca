//! charts/README.md documents the scene format for users: every key the code knows is named
//! there (or, for `[dynamics]` and `[min_norm]`, in config/paper.toml), and every example in it
//! is a scene that loads. A key added to a spec struct without its line in the README fails here.

use std::collections::BTreeSet;
use std::path::Path;

use jamchart::charts::{SceneSource, builtin_scene_names};

fn read(rel: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)).unwrap()
}

/// Every key of `t`, nested tables included (`x_axis` and its `param`, `min`, ...), and the
/// string values of `kind`, `param`, `scale`, `model`, `cost` and the layer lists.
fn names(t: &toml::Table, out: &mut BTreeSet<String>) {
    for (k, v) in t {
        out.insert(k.clone());
        match v {
            toml::Value::Table(inner) => names(inner, out),
            toml::Value::String(s)
                if ["kind", "param", "scale", "model", "cost"].contains(&k.as_str()) =>
            {
                out.insert(s.clone());
            }
            toml::Value::Array(a) => {
                for item in a {
                    match item {
                        toml::Value::String(s) => {
                            out.insert(s.clone());
                        }
                        toml::Value::Table(inner) => names(inner, out),
                        _ => {}
                    }
                }
            }
            _ => {}
        }
    }
}

fn table<T: serde::Serialize>(t: &T) -> toml::Table {
    toml::Table::try_from(t).expect("settings serialise to a table")
}

#[test]
fn every_scene_key_is_documented() {
    let readme = read("charts/README.md");
    let paper = read("config/paper.toml");
    let mut documented_here = BTreeSet::new();
    let mut documented_in_paper = BTreeSet::new();
    for name in builtin_scene_names() {
        let scene = SceneSource::BuiltIn(name).load(&[]).unwrap();
        names(&table(&scene.chart), &mut documented_here);
        names(&table(&scene.params), &mut documented_here);
        names(&table(&scene.size), &mut documented_here);
        names(&table(&scene.dynamics), &mut documented_in_paper);
        names(&table(&scene.min_norm), &mut documented_in_paper);
    }
    documented_here.extend(
        [
            "title", "base", "style", "colour", "print", "scene", "dynamics", "min_norm", "size",
            "chart",
        ]
        .map(String::from),
    );
    let missing: Vec<&String> = documented_here
        .iter()
        .filter(|k| !readme.contains(&format!("`{k}`")) && !readme.contains(&format!("`[{k}]`")))
        .collect();
    assert!(missing.is_empty(), "charts/README.md lacks {missing:?}");
    let missing: Vec<&String> = documented_in_paper
        .iter()
        .filter(|k| {
            !readme.contains(&format!("`{k}`"))
                && !paper.contains(&format!("{k} ="))
                && !paper.contains(&format!("[min_norm.{k}]"))
                && !paper.contains(&format!("[dynamics.{k}]"))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "neither charts/README.md nor config/paper.toml has {missing:?}"
    );
}

#[test]
fn every_readme_example_is_a_scene_that_loads() {
    let readme = read("charts/README.md");
    let dir = tempfile::tempdir().unwrap();
    let examples: Vec<&str> = readme
        .split("```toml\n")
        .skip(1)
        .map(|b| b.split("```").next().unwrap())
        .collect();
    let all_kinds: BTreeSet<&str> = builtin_scene_names()
        .into_iter()
        .map(|n| SceneSource::BuiltIn(n).load(&[]).unwrap().chart.kind())
        .collect();
    assert!(
        examples.len() >= all_kinds.len(),
        "one example per chart kind"
    );
    let mut kinds = BTreeSet::new();
    for (i, text) in examples.iter().enumerate() {
        let path = dir.path().join(format!("example{i}.toml"));
        std::fs::write(&path, text).unwrap();
        let scene = SceneSource::File(path)
            .load(&[])
            .unwrap_or_else(|e| panic!("example {i}: {e}\n{text}"));
        kinds.insert(scene.chart.kind());
    }
    assert_eq!(kinds, all_kinds, "one example per chart kind");
}

/// A kind added to the list in src/charts/kinds.rs needs a built-in scene (so `render` draws
/// it and its hash is checked) and a section of its own in charts/README.md.
#[test]
fn every_chart_kind_has_a_scene_and_a_readme_section() {
    let readme = read("charts/README.md");
    let drawn: BTreeSet<&str> = builtin_scene_names()
        .into_iter()
        .map(|n| SceneSource::BuiltIn(n).load(&[]).unwrap().chart.kind())
        .collect();
    for kind in jamchart::charts::ChartSpec::KINDS {
        assert!(drawn.contains(kind), "no built-in scene draws kind {kind}");
        let heading = format!("#### `kind = \"{kind}\"`");
        assert!(
            readme.contains(&heading),
            "charts/README.md lacks {heading}"
        );
    }
}
