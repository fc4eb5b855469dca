//! `--set key=value`: one key of a scene file replaced before the scene is read.
//!
//! A dotted key names its section (`chart.x_axis.count=51`, `dynamics.series.after_jam_s=0.3`,
//! `size.width_px=2000`); a bare key is a declared setting of `[scene]`, `[min_norm]` or
//! `[dynamics.*]` (keys are unique: `mu_palm=0.6`), or a top-level key (`title`, `base`, `style`). `mu` sets both frictions,
//! as the paper's single mu. The value is TOML (`0.6`, `51`, `"log"`, `[1.0, 2.0]`); a bare word
//! is a string (`scale=log`).

use std::str::FromStr;

use crate::error::{Error, Result};
use crate::limits::MAX_KEY_PARTS;
use crate::settings;

/// One `key=value` override.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// The key as typed, e.g. `mu_palm` or `chart.x_axis.count`.
    pub key: String,
    /// The value, parsed as TOML.
    pub value: toml::Value,
}

impl FromStr for Setting {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<Self, String> {
        let (key, raw) = s
            .split_once('=')
            .ok_or_else(|| format!("'{s}' is not key=value (e.g. mu_palm=0.6)"))?;
        let key = key.trim();
        if key.is_empty() || key.split('.').any(str::is_empty) {
            return Err(format!("'{s}' has an empty key"));
        }
        if key.split('.').nth(MAX_KEY_PARTS).is_some() {
            return Err(format!(
                "{}: a key has at most {MAX_KEY_PARTS} dotted parts (e.g. chart.x_axis.count)",
                crate::error::cut(key)
            ));
        }
        let raw = raw.trim();
        // `1e400` would otherwise become the string "1e400" (toml refuses the overflow).
        if let Some(problem) = raw
            .replace('_', "")
            .parse::<f64>()
            .ok()
            .and_then(|v| crate::settings::decl::float_range_problem(raw, v))
        {
            return Err(format!("{key} = {} {problem}", crate::error::cut(raw)));
        }
        let value = toml::from_str::<toml::Table>(&format!("v = {raw}"))
            .ok()
            .and_then(|mut t| t.remove("v"))
            .or_else(|| whole_beyond_i64(raw).map(toml::Value::Float))
            .unwrap_or_else(|| toml::Value::String(raw.to_string()));
        Ok(Setting {
            key: key.to_string(),
            value,
        })
    }
}

/// A whole number too large for TOML's integers (`99999999999999999999999999`), as the float it
/// reads as: kept as the string it was typed, it was echoed with all its digits.
fn whole_beyond_i64(raw: &str) -> Option<f64> {
    let digits = raw.strip_prefix(['+', '-']).unwrap_or(raw).replace('_', "");
    (!digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()))
        .then(|| raw.replace('_', "").parse::<f64>().ok())
        .flatten()
}

impl std::fmt::Display for Setting {
    /// `KEY=VALUE` as it reads back (the gallery's command to reproduce a chart is made of
    /// it), a number as short as that allows: toml writes 1e308 with 309 digits, and the
    /// warnings that name a `--set` quoted them all. A whole float keeps its `.0`, so that it
    /// reads back as a float.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.value {
            toml::Value::Float(v) => {
                let t = crate::settings::number_text(v);
                let point = if t.contains(['.', 'e', 'n']) {
                    ""
                } else {
                    ".0"
                };
                write!(f, "{}={t}{point}", self.key)
            }
            _ => write!(f, "{}={}", self.key, self.value),
        }
    }
}

/// The top-level keys of a scene file that are values, not sections.
const TOP_LEVEL: &[&str] = &["title", "base", "style"];

/// The full paths a setting writes, e.g. `["scene", "mu_palm"]`: a dotted key as written, a
/// bare key at its declared section (an alias at each key it sets).
fn paths(key: &str, value: &toml::Value) -> Result<Vec<Vec<String>>> {
    if key.contains('.') || TOP_LEVEL.contains(&key) {
        return Ok(vec![key.split('.').map(str::to_string).collect()]);
    }
    let Some(decl) = settings::find(key) else {
        let bare: Vec<&str> = settings::palm_family()
            .filter(|d| d.section == "scene")
            .map(|d| d.key)
            .collect();
        return Err(Error::invalid(
            &format!("--set {key}"),
            value,
            format!(
                "not a scene key; bare keys are {}, {}, and the keys of [dynamics.*] and \
                 [min_norm] (jamchart settings lists them); other keys take their section, \
                 e.g. chart.x_axis.count",
                bare.join(", "),
                TOP_LEVEL.join(", ")
            ),
        ));
    };
    let keys = if decl.sets.is_empty() {
        vec![decl.key]
    } else {
        decl.sets.to_vec()
    };
    Ok(keys
        .into_iter()
        .map(|k| {
            decl.section
                .split('.')
                .chain([k])
                .map(str::to_string)
                .collect()
        })
        .collect())
}

/// Applies `settings` in order to a scene file's table; sections and inline tables on the way
/// are created when missing.
pub fn apply(table: &mut toml::Table, settings: &[Setting]) -> Result<()> {
    for s in settings {
        for path in paths(&s.key, &s.value)? {
            let (last, parents) = path.split_last().expect("keys are not empty");
            let mut t = &mut *table;
            for p in parents {
                let entry = t
                    .entry(p.clone())
                    .or_insert_with(|| toml::Value::Table(toml::Table::new()));
                t = entry.as_table_mut().ok_or_else(|| {
                    Error::invalid(
                        &format!("--set {}", s.key),
                        &s.value,
                        format!("{p} is a value, not a section"),
                    )
                })?;
            }
            t.insert(last.clone(), s.value.clone());
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(s: &str) -> Setting {
        s.parse().unwrap()
    }

    /// The warning on `render fig7b --set force_n=1e308` quoted the value with 309 digits:
    /// a setting reads as it was typed, and back as the same value.
    #[test]
    fn a_setting_shows_its_number_short_and_reads_back() {
        for (typed, shown) in [
            ("force_n=1e308", "force_n=1e308"),
            ("chart.x_min_mm=-1e308", "chart.x_min_mm=-1e308"),
            ("mu_palm=0.6", "mu_palm=0.6"),
            ("force_n=200.0", "force_n=200.0"),
            ("chart.x_axis.count=51", "chart.x_axis.count=51"),
            ("force_n=inf", "force_n=inf"),
            // Beyond TOML's integers: the float it reads as, not its 26 digits.
            ("force_n=99999999999999999999999999", "force_n=1e26"),
            ("force_n=-1_000_000_000_000_000_000_000", "force_n=-1e21"),
        ] {
            let s = set(typed);
            assert_eq!(s.to_string(), shown);
            assert_eq!(set(shown), s, "{shown}");
        }
    }

    #[test]
    fn values_parse_as_toml_and_bare_words_as_strings() {
        assert_eq!(set("mu_palm=0.6").value, toml::Value::Float(0.6));
        assert_eq!(
            set("chart.x_axis.count = 51").value,
            toml::Value::Integer(51)
        );
        assert_eq!(set("scale=log").value, toml::Value::String("log".into()));
        assert!("mu_palm".parse::<Setting>().is_err());
        assert!("a..b=1".parse::<Setting>().is_err());
    }

    #[test]
    fn bare_keys_find_their_section_and_dotted_keys_create_theirs() {
        let mut t: toml::Table = toml::from_str("[chart]\nx_axis = { count = 401 }\n").unwrap();
        let sets = [
            set("mu=0.3"),
            set("after_jam_s=0.1"),
            set("chart.x_axis.count=51"),
            set("title=hello"),
        ];
        apply(&mut t, &sets).unwrap();
        assert_eq!(t["scene"]["mu_ground"].as_float(), Some(0.3));
        assert_eq!(t["scene"]["mu_palm"].as_float(), Some(0.3));
        assert_eq!(t["dynamics"]["series"]["after_jam_s"].as_float(), Some(0.1));
        assert_eq!(t["chart"]["x_axis"]["count"].as_integer(), Some(51));
        assert_eq!(t["title"].as_str(), Some("hello"));
    }

    #[test]
    fn unknown_bare_key_is_refused_with_the_known_ones() {
        let mut t = toml::Table::new();
        let msg = apply(&mut t, &[set("radious_mm=3")])
            .unwrap_err()
            .to_string();
        assert!(
            msg.contains("radious_mm") && msg.contains("radius_mm"),
            "{msg}"
        );
        let msg = apply(&mut t, &[set("title=a"), set("title.x=1")])
            .unwrap_err()
            .to_string();
        assert!(msg.contains("not a section"), "{msg}");
    }
}
