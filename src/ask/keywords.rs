//! [`Keywords`]: a question's values by key, flat, as a Python call or a JSON body gives them;
//! placed at their sections of a parameter file's tree, each checked against its declaration.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::settings::{Decl, Kind};
use crate::uncertain::Uncertain;

/// A question's values by key, flat: what a Python call's keywords, an HTTP body's JSON object
/// or a TOML table give.
///
/// Each key is a declared setting's (`radius_mm`, `mu`, `rtol`: `jamchart settings` lists
/// them) or one of the question's own (`model`, `before_mm`, `x_target_mm`, ...). A value
/// is a number, a name, a switch, a list of numbers, or the command line's text of a range or
/// a distribution (`"0.12:0.3"`, `"normal(0.21,0.03)"`) for a setting that takes one.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Keywords(pub toml::Table);

impl Keywords {
    /// Keywords from `(key, value)` pairs.
    pub fn new(pairs: impl IntoIterator<Item = (String, toml::Value)>) -> Self {
        Keywords(pairs.into_iter().collect())
    }

    /// Keywords of a JSON object (an HTTP body): each value a number, a string, a switch, a
    /// list or an object (a table, for `set` and `read_off`). A null is refused: leave the
    /// key out for its default.
    pub fn from_json(json: serde_json::Value) -> Result<Self> {
        let serde_json::Value::Object(map) = json else {
            return Err(Error::invalid(
                "body",
                json_kind(&json),
                "give a JSON object of keys to values, e.g. {\"mu\": 0.3}",
            ));
        };
        let pairs = map.into_iter().map(|(key, value)| {
            let value = toml_of_json(&key, value)?;
            Ok((key, value))
        });
        Ok(Keywords(pairs.collect::<Result<_>>()?))
    }

    /// Takes the question's own key `key` out, if given.
    pub(crate) fn take(&mut self, key: &str) -> Option<toml::Value> {
        self.0.remove(key)
    }

    /// Takes out `key`, a list of numbers (or one number).
    pub(crate) fn take_numbers(&mut self, key: &str) -> Result<Option<Vec<f64>>> {
        let Some(v) = self.take(key) else {
            return Ok(None);
        };
        let number = |v: &toml::Value| match v {
            toml::Value::Float(x) => Some(*x),
            toml::Value::Integer(i) => Some(*i as f64),
            _ => None,
        };
        let numbers = match &v {
            toml::Value::Array(items) => items.iter().map(number).collect(),
            one => number(one).map(|x| vec![x]),
        };
        numbers
            .map(Some)
            .ok_or_else(|| Error::invalid(key, shown(&v), "give a number or a list of numbers"))
    }

    /// Takes out `key`, a whole number >= `least`.
    pub(crate) fn take_count(&mut self, key: &str, least: u64) -> Result<Option<u64>> {
        match self.take(key) {
            None => Ok(None),
            Some(toml::Value::Integer(i)) if i >= 0 && i as u64 >= least => Ok(Some(i as u64)),
            Some(v) => Err(Error::invalid(
                key,
                shown(&v),
                format!("{key} is a whole number >= {least}"),
            )),
        }
    }

    /// Takes out `key`, one number.
    pub(crate) fn take_number(&mut self, key: &str) -> Result<Option<f64>> {
        match self.take(key) {
            None => Ok(None),
            Some(toml::Value::Float(x)) => Ok(Some(x)),
            Some(toml::Value::Integer(i)) => Ok(Some(i as f64)),
            Some(v) => Err(Error::invalid(key, shown(&v), "give a number")),
        }
    }

    /// Takes out `key`, a name.
    pub(crate) fn take_name(&mut self, key: &str) -> Result<Option<String>> {
        match self.take(key) {
            None => Ok(None),
            Some(toml::Value::String(s)) => Ok(Some(s)),
            Some(v) => Err(Error::invalid(key, shown(&v), "give a name")),
        }
    }

    /// Takes out `key`, a switch.
    pub(crate) fn take_switch(&mut self, key: &str) -> Result<Option<bool>> {
        match self.take(key) {
            None => Ok(None),
            Some(toml::Value::Boolean(b)) => Ok(Some(b)),
            Some(v) => Err(Error::invalid(key, shown(&v), "give true or false")),
        }
    }

    /// The keys left, as a table shaped like a parameter file: each a setting of `family`,
    /// placed at its section and checked against its declaration (a number in its range, a
    /// range or distribution only where the setting takes one, a name among its choices). A
    /// key of no setting is refused, naming the nearest of `family`'s keys and `own` (the
    /// question's keys, taken already).
    pub(crate) fn into_overrides(
        self,
        family: impl Iterator<Item = &'static Decl> + Clone,
        own: &[&'static str],
    ) -> Result<toml::Table> {
        let mut table = toml::Table::new();
        for (key, value) in self.0 {
            let Some(decl) = family.clone().find(|d| d.key == key || d.path_is(&key)) else {
                let known = family.clone().map(|d| d.key).chain(own.iter().copied());
                return Err(Error::UnknownKey {
                    nearest: nearest(&key, known).map(str::to_string),
                    key: crate::error::cut(&key),
                });
            };
            let value = checked(decl, value)?;
            decl.section_in(&mut table)
                .insert(decl.key.to_string(), value);
        }
        Ok(table)
    }
}

/// A JSON value as the TOML value of key `key`.
fn toml_of_json(key: &str, value: serde_json::Value) -> Result<toml::Value> {
    use serde_json::Value as J;
    Ok(match value {
        J::Null => {
            return Err(Error::invalid(
                key,
                "null",
                "give a value, or leave the key out for its default",
            ));
        }
        J::Bool(b) => toml::Value::Boolean(b),
        J::Number(n) => match (n.as_i64(), n.as_f64()) {
            (Some(i), _) => toml::Value::Integer(i),
            (None, Some(x)) => toml::Value::Float(x),
            (None, None) => return Err(Error::invalid(key, n, "give a number a double holds")),
        },
        J::String(s) => toml::Value::String(s),
        J::Array(items) => toml::Value::Array(
            items
                .into_iter()
                .map(|v| toml_of_json(key, v))
                .collect::<Result<_>>()?,
        ),
        J::Object(map) => toml::Value::Table(
            map.into_iter()
                .map(|(k, v)| {
                    let v = toml_of_json(&format!("{key}.{k}"), v)?;
                    Ok((k, v))
                })
                .collect::<Result<_>>()?,
        ),
    })
}

/// What kind of JSON value `v` is, for a message.
fn json_kind(v: &serde_json::Value) -> &'static str {
    match v {
        serde_json::Value::Null => "null",
        serde_json::Value::Bool(_) => "a switch",
        serde_json::Value::Number(_) => "a number",
        serde_json::Value::String(_) => "a string",
        serde_json::Value::Array(_) => "a list",
        serde_json::Value::Object(_) => "an object",
    }
}

/// `value` of setting `decl`, checked as a flag's value is: a number against its range (an
/// integer read as a number), the text of a range or distribution parsed.
fn checked(decl: &Decl, value: toml::Value) -> Result<toml::Value> {
    let key = &decl.path();
    match (decl.kind, value) {
        (Kind::Real | Kind::OptionalReal | Kind::Derived, toml::Value::Integer(i)) => {
            checked(decl, toml::Value::Float(i as f64))
        }
        (Kind::Real | Kind::OptionalReal | Kind::Derived, toml::Value::Float(x)) => {
            decl.check_real(x)?;
            Ok(toml::Value::Float(x))
        }
        (Kind::Real | Kind::OptionalReal | Kind::Derived, toml::Value::String(text)) => {
            match Uncertain::parse(&text) {
                Ok(Uncertain::Point { value }) => checked(decl, toml::Value::Float(value)),
                // Checked against the setting where the scene's ranges are taken out.
                Ok(_) => Ok(toml::Value::String(text)),
                Err(why) => Err(Error::invalid(key, &text, why)),
            }
        }
        (Kind::Real | Kind::OptionalReal | Kind::Derived, v) => Err(Error::invalid(
            key,
            shown(&v),
            match decl.uncertain {
                true => format!(
                    "give a number, or a range or distribution as text: {}",
                    crate::settings::flags::uncertain_forms(decl)
                ),
                false => "give a number".to_string(),
            },
        )),
        (Kind::Count, toml::Value::Integer(i)) if i >= 0 => Ok(toml::Value::Integer(i)),
        (Kind::Count, v) => Err(Error::invalid(key, shown(&v), "give a whole number >= 0")),
        (Kind::Switch, toml::Value::Boolean(b)) => Ok(toml::Value::Boolean(b)),
        (Kind::Switch, v) => Err(Error::invalid(key, shown(&v), "give true or false")),
        (Kind::Choice(names), toml::Value::String(s)) if names.contains(&s.as_str()) => {
            Ok(toml::Value::String(s))
        }
        (Kind::Choice(names), v) => Err(Error::invalid(
            key,
            shown(&v),
            format!("give one of {}", names.join(", ")),
        )),
        (Kind::Section, v) => Err(Error::invalid(key, shown(&v), "a section, not a value")),
    }
}

/// A value as a message quotes it: a string bare, anything else as TOML writes it.
pub(crate) fn shown(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        v => v.to_string(),
    }
}

/// The key of `known` nearest `key` by edit distance, where one is near enough to be a typo.
pub(crate) fn nearest<'k>(key: &str, known: impl Iterator<Item = &'k str>) -> Option<&'k str> {
    known
        .map(|k| (edit_distance(key, k), k))
        .filter(|(d, k)| *d <= 2.max(key.len() / 4) || k.starts_with(key))
        .min()
        .map(|(_, k)| k)
}

/// Levenshtein distance between two keys (short ASCII words).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn overrides(pairs: &[(&str, toml::Value)]) -> Result<toml::Table> {
        let kw = Keywords::new(pairs.iter().map(|(k, v)| (k.to_string(), v.clone())));
        kw.into_overrides(crate::settings::palm_family(), &["model"])
    }

    #[test]
    fn each_key_goes_to_its_section() {
        let t = overrides(&[
            ("radius_mm", toml::Value::Integer(12)),
            ("rtol", toml::Value::Float(1e-6)),
        ])
        .unwrap();
        assert_eq!(t["scene"]["radius_mm"].as_float(), Some(12.0));
        assert_eq!(t["dynamics"]["integrator"]["rtol"].as_float(), Some(1e-6));
    }

    /// A range with a NaN end was once dropped on the way to the scene, which then answered
    /// the default friction: every end is checked where it is read.
    #[test]
    fn a_range_with_a_non_finite_end_is_refused_naming_the_key() {
        for text in ["0.1:nan", "0.1:inf", "normal(nan,1)"] {
            let e = overrides(&[("mu", toml::Value::String(text.into()))]).unwrap_err();
            assert!(
                matches!(&e, Error::InvalidValue { key, .. } if key == "mu"),
                "{text}: {e}"
            );
        }
    }

    #[test]
    fn an_unknown_key_names_the_nearest() {
        let e = overrides(&[("raduis_mm", toml::Value::Float(3.0))]).unwrap_err();
        assert!(
            matches!(&e, Error::UnknownKey { nearest: Some(n), .. } if n == "radius_mm"),
            "{e}"
        );
        let e = overrides(&[("modell", toml::Value::Float(3.0))]).unwrap_err();
        assert!(
            matches!(&e, Error::UnknownKey { nearest: Some(n), .. } if n == "model"),
            "{e}"
        );
    }

    #[test]
    fn wrong_types_are_refused_naming_the_key() {
        for (key, v) in [
            ("radius_mm", toml::Value::Boolean(true)),
            ("method", toml::Value::Float(1.0)),
            ("method", toml::Value::String("euler".into())),
            ("max_steps", toml::Value::Float(1.5)),
        ] {
            let e = overrides(&[(key, v)]).unwrap_err();
            assert!(
                matches!(&e, Error::InvalidValue { key: k, .. } if k.ends_with(key)),
                "{key}: {e}"
            );
        }
    }
}
