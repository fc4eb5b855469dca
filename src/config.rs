//! TOML parameter sets (`config/*.toml`) turned into the plain structs the models take.
//!
//! Every section is optional and every key has a default, so a partial file works; an unknown key
//! is refused with the file, line and column.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::dynamics::DynamicsParams;
use crate::error::{Error, Result};
use crate::minnorm::MinNormSettings;
use crate::model::SceneParams;

/// A whole parameter file. Each model's issue adds its own section.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Config {
    /// The scene: frictions, disc, push, palm (section `[scene]`).
    pub scene: SceneParams,
    /// The minimum-norm model: formulation, bisection tolerance, program settings (sections
    /// `[min_norm]` and `[min_norm.qp]`).
    pub min_norm: MinNormSettings,
    /// The dynamic simulation: drive, contact, friction, integrator (section `[dynamics]`).
    pub dynamics: DynamicsParams,
}

impl Config {
    /// Checks every section; runs before any computation.
    pub fn validate(&self) -> Result<()> {
        self.scene.validate()?;
        self.min_norm.validate()?;
        self.dynamics.validate()
    }

    /// Reads and parses a TOML file (it is not validated here: flags may still override it).
    pub fn load(path: &Path) -> Result<Config> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io("read", path, e))?;
        parse_toml(&text, path)
    }
}

/// Parses TOML text into `T`, turning the parser's error into one line with file:line:column.
pub fn parse_toml<T: serde::de::DeserializeOwned>(text: &str, path: &Path) -> Result<T> {
    toml::from_str(text).map_err(|e| {
        let (line, column) = e
            .span()
            .map(|s| line_column(text, s.start))
            .unwrap_or((1, 1));
        Error::Config {
            path: path.to_path_buf(),
            line,
            column,
            message: e.message().trim().replace('\n', " "),
        }
    })
}

/// What is wrong with a number written as `raw` that parsed to `v`: None if it is fine.
///
/// Text that overflows to infinity or underflows to zero is refused, so that a message quotes
/// what was written (`1e400`), never what it became (`inf`); the words inf and nan pass.
pub fn float_range_problem(raw: &str, v: f64) -> Option<&'static str> {
    let lower = raw.to_ascii_lowercase();
    if v.is_infinite() && !lower.contains("inf") {
        return Some("is beyond the range of a 64-bit float (the largest is about 1.8e308)");
    }
    let mantissa = lower.split('e').next().unwrap_or("");
    if v == 0.0 && mantissa.bytes().any(|b| (b'1'..=b'9').contains(&b)) {
        return Some(
            "is too small for a 64-bit float: it would become 0 (the smallest is about 5e-324)",
        );
    }
    None
}

/// 1-based line and column of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_key_names_file_line_and_key() {
        let text = "[scene]\nmu_ground = 0.3\nradus_mm = 4\n";
        let err = parse_toml::<Config>(text, Path::new("x.toml")).unwrap_err();
        let msg = err.to_string();
        assert!(msg.starts_with("x.toml:3:1:"), "{msg}");
        assert!(msg.contains("radus_mm"), "{msg}");
    }

    #[test]
    fn partial_file_keeps_defaults() {
        let c: Config = parse_toml("[scene]\nforce_n = 50.0\n", Path::new("p.toml")).unwrap();
        assert_eq!(c.scene.force_n, 50.0);
        assert_eq!(c.scene.radius_mm, SceneParams::default().radius_mm);
    }
}

#[cfg(test)]
mod paper_toml {
    use super::*;

    /// config/paper.toml promises to equal the defaults; this keeps the promise.
    #[test]
    fn paper_toml_equals_the_defaults() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("config/paper.toml");
        let c = Config::load(&path).unwrap();
        assert_eq!(c, Config::default());
        c.validate().unwrap();
    }
}
