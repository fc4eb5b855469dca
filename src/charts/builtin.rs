//! The scenes and the parameter set built into the binary, so that `jamchart render` works from
//! any folder and after `cargo install`. The repository's `charts/*.toml` and
//! `config/paper.toml` stay the source: they are compiled in here (the scene files by
//! `build.rs`), and a test checks that every scene file is in with its text.

use crate::config::{Config, parse_toml};

/// The paper's parameter set, `config/paper.toml`: the base of every scene without `base`.
pub const PAPER_TOML: &str = include_str!("../../config/paper.toml");

/// The reference of every scene key, `charts/README.md`: what `jamchart scenes --keys` prints,
/// so an installed binary has it.
pub(crate) const SCENE_KEYS: &str = include_str!("../../charts/README.md");

/// The built-in scenes: name (file stem) and the text of `charts/<name>.toml`, sorted by name;
/// `build.rs` lists every file of charts/.
pub const SCENES: &[(&str, &str)] = include!(concat!(env!("OUT_DIR"), "/scenes.rs"));

/// The names of the built-in scenes, sorted.
pub fn scene_names() -> Vec<String> {
    SCENES.iter().map(|(n, _)| n.to_string()).collect()
}

/// The text of built-in scene `name`.
pub fn scene_text(name: &str) -> Option<&'static str> {
    SCENES.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

/// The built-in paper parameter set, parsed.
pub fn paper_config() -> Config {
    parse_toml(
        PAPER_TOML,
        std::path::Path::new("<built-in config/paper.toml>"),
    )
    .expect("config/paper.toml parses (tested)")
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// A scene file added to charts/ but not compiled in would silently be missing from
    /// `jamchart render`; this lists both.
    #[test]
    fn every_scene_file_is_built_in_with_its_text() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("charts");
        let on_disk = crate::charts::scene_names(&dir).unwrap();
        assert_eq!(on_disk, scene_names());
        for (name, text) in SCENES {
            let file = std::fs::read_to_string(dir.join(format!("{name}.toml"))).unwrap();
            assert_eq!(file, *text, "{name}");
        }
    }

    #[test]
    fn built_in_paper_set_is_the_default() {
        assert_eq!(paper_config(), Config::default());
    }
}
