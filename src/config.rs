//! TOML parameter sets (`config/*.toml`) turned into the plain structs the models take.
//!
//! Every section is optional and every key has a default, so a partial file works; an unknown key
//! is refused with the file, line and column.

mod file;
mod merge;
mod read;

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::dynamics::DynamicsParams;
use crate::error::{Error, Result};
use crate::minnorm::MinNormSettings;
use crate::scene::SceneParams;
use crate::uncertain::UncertainSet;
pub use file::{MAX_INPUT_BYTES, MAX_PAGE_BYTES, read_regular, regular_or_missing};
pub(crate) use merge::{Refusal, overlay, read_section};
pub use read::{
    array_for_table, cut_quotes, key_line_column, keyed, not_a_table, parse_toml, seq_for_struct,
};

/// A whole parameter file: the scene and each model's own section.
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

    /// This config with `over` (shaped like a parameter file: `{scene: {...}, dynamics:
    /// {contact: {...}}}`) merged in: what flags and `--set` change. Not validated here.
    pub fn overlay(&self, over: &toml::Table) -> Result<Config> {
        match self.with_scene_numbers(over) {
            Some(config) => Ok(config),
            None => overlay(self, over, ""),
        }
    }

    /// [`Config::overlay`] where `over` holds nothing but numbers of `[scene]` (`{scene = {mu =
    /// 0.3}}`, the common question): each number set in place, an alias's keys first and then
    /// the keys given themselves, which win, as the merge of [`overlay`] has it. The same
    /// config without the round trip through TOML (serialise every section, merge, read it
    /// back), which costs a scalar answer from Python 20 times the closed form's work. None
    /// where `over` asks anything else, which takes the round trip.
    fn with_scene_numbers(&self, over: &toml::Table) -> Option<Config> {
        let scene = match (over.len(), over.get("scene")) {
            (0, _) => return Some(self.clone()),
            (1, Some(toml::Value::Table(scene))) => scene,
            _ => return None,
        };
        let mut numbers = Vec::with_capacity(scene.len());
        for (key, value) in scene {
            let toml::Value::Float(x) = *value else {
                return None;
            };
            numbers.push((scene_decls().find(|d| d.key == key)?, x));
        }
        let mut out = self.clone();
        set_scene_numbers(&mut out.scene, &numbers)?;
        Some(out)
    }

    /// Reads and parses a TOML file (it is not validated here: flags may still override it).
    pub fn load(path: &Path) -> Result<Config> {
        let text = read_text(path)?;
        parse_toml(&text, path).map_err(|first| every_mistake(&text, path).unwrap_or(first))
    }

    /// Reads a TOML file whose `[scene]` may give ranges or distributions as strings (`mu =
    /// "0.12:0.3"`): the config with their nominal values, and the uncertain inputs.
    pub(crate) fn load_uncertain(path: &Path) -> Result<(Config, UncertainSet)> {
        let text = read_text(path)?;
        let (nominal, set) = take_scene_uncertain(&text, path)?;
        let read = nominal.as_deref().unwrap_or(&text);
        parse_toml(read, path)
            .map(|c| (c, set))
            .map_err(|first| every_mistake(read, path).unwrap_or(first))
    }
}

/// Every mistake of a parameter file that serde refused, each key read alone over the
/// defaults and placed at its line (serde stopped at the first: of a typo and a wrong value in
/// `[scene]` only one was told); None when the text is not TOML or has one mistake only, whose
/// first report stands.
fn every_mistake(text: &str, path: &Path) -> Option<Error> {
    let table: toml::Table = toml::from_str(text).ok()?;
    let alone = |key: String, value: toml::Value| -> Option<Error> {
        let mut one = toml::Table::new();
        let dotted = key.clone();
        match key.split_once('.') {
            Some((section, k)) => {
                let inner = toml::Table::from_iter([(k.to_string(), value)]);
                one.insert(section.to_string(), toml::Value::Table(inner));
            }
            None => {
                one.insert(key, value);
            }
        }
        let e = Config::default().overlay(&one).err()?;
        let (line, column) = key_line_column(text, &dotted).unwrap_or((1, 1));
        Some(Error::Config {
            path: path.to_path_buf(),
            line,
            column,
            message: e.file_message(),
        })
    };
    let mut errors = Vec::new();
    for (k, v) in &table {
        match v.as_table() {
            Some(section) => errors.extend(
                (section.iter()).filter_map(|(kk, vv)| alone(format!("{k}.{kk}"), vv.clone())),
            ),
            None => errors.extend(alone(k.clone(), v.clone())),
        }
    }
    (errors.len() > 1).then(|| Error::in_file_order(path, errors))
}

/// Sets `numbers` (each a setting of `[scene]` or an alias of some, and its number) in `scene`
/// as the merge of [`overlay`] does: an alias's keys first, then the keys given themselves,
/// which win (`mu = 0.3, mu_ground = 0.5` gives mu_palm 0.3 and mu_ground 0.5). Unchecked.
/// None where a setting is no number of the scene (`scene` is then partly set).
pub(crate) fn set_scene_numbers(
    scene: &mut SceneParams,
    numbers: &[(&'static crate::settings::Decl, f64)],
) -> Option<()> {
    for aliases in [true, false] {
        for &(decl, x) in numbers {
            let keys = match (decl.sets, aliases) {
                ([], false) => std::slice::from_ref(&decl.key),
                (keys, true) if !keys.is_empty() => keys,
                _ => continue,
            };
            for k in keys {
                // False for a key of no number field (every field of the scene is one).
                scene.set_real(k, x).then_some(())?;
            }
        }
    }
    Some(())
}

/// The settings of `[scene]` and its aliases: where uncertain inputs of the palm scene are.
pub(crate) fn scene_decls() -> impl Iterator<Item = &'static crate::settings::Decl> + Clone {
    crate::settings::palm_family().filter(|d| d.section == "scene")
}

/// `text`'s `[scene]` with its ranges and distributions taken out, each replaced by its nominal
/// value: the text to read instead (None when it gave none) and the uncertain inputs. A bad value
/// is an error at its line and column in `path`; a text that is not TOML is left to the reader,
/// which says where. Parameter files (`--config`) and chart scene files both come through here.
pub(crate) fn take_scene_uncertain(
    text: &str,
    path: &Path,
) -> Result<(Option<String>, UncertainSet)> {
    let Ok(mut raw) = toml::from_str::<toml::Table>(text) else {
        return Ok((None, UncertainSet::default()));
    };
    let Some(scene) = raw.get_mut("scene").and_then(toml::Value::as_table_mut) else {
        return Ok((None, UncertainSet::default()));
    };
    let set = crate::uncertain::take(scene, scene_decls()).map_err(|e| {
        let key = match &e {
            Error::InvalidValue { key, .. } => format!("scene.{key}"),
            _ => "scene".into(),
        };
        let (line, column) = key_line_column(text, &key).unwrap_or((1, 1));
        Error::Config {
            path: path.to_path_buf(),
            line,
            column,
            message: e.file_message(),
        }
    })?;
    // The nominal values stand in the text the reader reads, so its checks still apply.
    let nominal = (!set.is_empty()).then(|| toml::to_string(&raw).expect("a table serialises"));
    Ok((nominal, set))
}

/// Reads a settings or scene file: a regular file of at most [`MAX_INPUT_BYTES`] (see
/// [`read_regular`]).
pub fn read_text(path: &Path) -> Result<String> {
    read_regular(path, MAX_INPUT_BYTES, "give a TOML file")
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

    /// The scene's numbers set in place give the config the round trip through TOML gives,
    /// field for field (NaN and signed zeros by their bits), for every number of `[scene]`
    /// and its aliases, an alias with its own key given as well, and tables it leaves to the
    /// round trip (a string, an integer, another section).
    #[test]
    fn scene_numbers_set_in_place_are_the_round_trip() {
        let base = Config::default();
        let debug = |c: &Config| format!("{c:?}");
        let mut tables: Vec<toml::Table> = vec![toml::Table::new()];
        let values = [0.3, -0.0, f64::NAN, f64::INFINITY, 5e-324, 1e308, 7.0];
        for (i, d) in scene_decls().enumerate() {
            let x = values[i % values.len()];
            let scene = toml::Table::from_iter([(d.key.to_string(), toml::Value::Float(x))]);
            tables.push(toml::Table::from_iter([("scene".into(), scene.into())]));
        }
        tables
            .push(toml::from_str("[scene]\nmu = 0.3\nmu_ground = 0.5\nforce_n = 40.0\n").unwrap());
        for over in &tables {
            let shortcut = base.with_scene_numbers(over);
            let round_trip = overlay(&base, over, "");
            match (&shortcut, &round_trip) {
                (Some(a), Ok(b)) => assert_eq!(debug(a), debug(b), "{over}"),
                (None, _) => {}
                (Some(_), Err(e)) => panic!("{over}: set in place, refused by the round trip: {e}"),
            }
        }
        let taken = tables
            .iter()
            .filter(|t| base.with_scene_numbers(t).is_some())
            .count();
        assert!(taken > scene_decls().count(), "{taken} tables set in place");
        // Left to the round trip: what it reads or refuses in its own words.
        for text in [
            "[scene]\nmass_kg = 2\n",
            "[scene]\nmu = \"0.3\"\n",
            "[scene]\nraduis_mm = 1.0\n",
            "[dynamics]\nrtol = 1e-6\n",
            "[scene]\nmu = 0.3\n[min_norm]\n",
        ] {
            let over: toml::Table = toml::from_str(text).unwrap();
            assert!(base.with_scene_numbers(&over).is_none(), "{text}");
        }
    }

    fn err(text: &str) -> String {
        parse_toml::<Config>(text, Path::new("c.toml"))
            .unwrap_err()
            .to_string()
    }

    /// A parameter file's typo and wrong value in one section came one at a time (serde stops
    /// at the first): both are reported, in file order, each at its line.
    #[test]
    fn every_mistake_of_a_parameter_file_is_reported() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("c.toml");
        std::fs::write(&path, "[scene]\nraduis_mm = 12\nmass_kg = true\n").unwrap();
        let e = Config::load(&path).unwrap_err().to_string();
        let lines: Vec<&str> = e.lines().collect();
        assert!(lines[0].starts_with("2 mistakes in "), "{e}");
        assert!(
            lines[1].contains(":2:13: ") && lines[1].contains("did you mean radius_mm?"),
            "{e}"
        );
        assert!(
            lines[2].contains(":3:11: ") && lines[2].contains("expected a number"),
            "{e}"
        );
        // One mistake keeps its own report.
        std::fs::write(&path, "[scene]\nraduis_mm = 12\n").unwrap();
        let e = Config::load(&path).unwrap_err().to_string();
        assert!(
            !e.contains("mistakes in") && e.contains("did you mean radius_mm?"),
            "{e}"
        );
    }

    /// `mu = "normal(0.2"` in a file was refused as `scene.mu_ground = "normal(0.2": expected
    /// a number`: the alias' other key, and not what is wrong. It names the key as written
    /// and the missing parenthesis.
    #[test]
    fn a_broken_distribution_says_what_is_wrong_with_it() {
        let e = take_scene_uncertain("[scene]\nmu = \"normal(0.2\"\n", Path::new("c.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("c.toml:2:6: "), "{e}");
        assert!(
            e.contains("mu = normal(0.2") && !e.contains("mu_ground"),
            "{e}"
        );
        assert!(e.contains("a ')' is missing"), "{e}");
    }

    /// Regression: `scene = [1, 2]` ran with mu_ground = 1, mu_palm = 2, serde
    /// filling the struct's fields in order from the array. Any settings table given as an
    /// array is refused, however its elements happen to fit.
    #[test]
    fn a_section_must_be_a_table() {
        for (text, key) in [
            ("scene = [1, 2]\n", "scene"),
            ("scene = [0.3]\n", "scene"),
            ("[min_norm]\nqp = [true, 50]\n", "min_norm.qp"),
            ("[min_norm]\nqp = [1, 2]\n", "min_norm.qp"),
            ("dynamics = []\n", "dynamics"),
        ] {
            let msg = err(text);
            assert!(
                msg.contains(&format!("{key} = ")) && msg.contains("expected a table"),
                "{text}: {msg}"
            );
        }
    }

    /// Regression: `radius_mm = "ten"` said `invalid type: string "ten", expected
    /// f64` without the key, `drive = 3` said only `wanted string or table`.
    #[test]
    fn wrong_types_name_the_key_with_its_section_and_value() {
        for (text, says) in [
            (
                "[scene]\nradius_mm = \"ten\"\n",
                "c.toml:2:13: scene.radius_mm: ",
            ),
            (
                "[dynamics.drive]\nmode = 3\n",
                "c.toml:2:8: dynamics.drive.mode = 3: ",
            ),
            (
                "[min_norm.qp]\nmax_iter = -1\n",
                "min_norm.qp.max_iter = -1: ",
            ),
            (
                "[dynamics.verification]\nverify = 1.5\n",
                "dynamics.verification.verify = 1.5: ",
            ),
        ] {
            let msg = err(text);
            assert!(
                msg.contains(says) && msg.contains("expected"),
                "{text}: {msg}"
            );
        }
    }

    /// Regression: a 50 MB value was echoed whole on one stderr line.
    #[test]
    fn long_values_are_cut_in_messages() {
        let long = "a".repeat(5_000_000);
        for text in [
            format!("[scene]\nradius_mm = \"{long}\"\n"),
            format!("[scene]\n{long} = 1\n"),
            format!("[dynamics]\ndrive = \"{long}\"\n"),
        ] {
            let msg = err(&text);
            assert!(msg.len() < 600, "{} bytes: {:.200}", msg.len(), msg);
            // A key is cut; a value is not quoted at all (`Error::file_message`).
            assert!(!msg.contains(&"a".repeat(100)), "{msg}");
        }
    }

    /// Regression: `1e400` was reported as `inf` (and `1e-400` read as 0).
    #[test]
    fn numbers_out_of_f64_range_are_quoted_as_written() {
        for (text, written) in [
            (
                "[scene]\nradius_mm = 1e400\n",
                "scene.radius_mm = 1e400 is beyond",
            ),
            (
                "[scene]\nforce_n = -1_0e400\n",
                "scene.force_n = -1_0e400 is beyond",
            ),
            (
                "[dynamics]\nrtol = 1e-400\n",
                "dynamics.rtol = 1e-400 is too small",
            ),
        ] {
            let msg = err(text);
            assert!(msg.contains(written) && !msg.contains("inf"), "{msg}");
        }
        // The word inf is passed on, for validate() to judge.
        let c: Config = parse_toml("[scene]\nforce_n = inf\n", Path::new("c.toml")).unwrap();
        assert!(c.scene.force_n.is_infinite());
    }

    /// `[scene] mu` sets both frictions, as `--mu` and `--set mu` do (it was once
    /// refused in a file); a key given as well wins, and a mistake in it is named on its line.
    #[test]
    fn scene_mu_in_a_file_sets_both_frictions() {
        let c: Config =
            parse_toml("[scene]\nmu = 0.3\nmu_palm = 0.5\n", Path::new("m.toml")).unwrap();
        assert_eq!((c.scene.mu_ground, c.scene.mu_palm), (0.3, 0.5));
        let msg = err("[scene]\nmu = \"high\"\n");
        assert!(msg.starts_with("c.toml:2:"), "{msg}");
        assert!(msg.contains("mu_"), "{msg}");
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
