//! Settings read from a TOML table over a base: the merge behind scene files' sections,
//! `--set` and flags, with refusals that name the dotted key and quote the value as written.

use serde::Serialize;

use super::{array_for_table, cut_quotes, keyed, not_a_table, seq_for_struct};
use crate::error::{Error, Result};

/// A refused settings table: the dotted key at fault (with its section) and the message, which
/// names it with the value as written.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Refusal {
    /// The dotted key, e.g. `chart.x_axis.count`; the section alone when no key is at fault.
    pub key: String,
    /// `key = value: what is expected`.
    pub message: String,
}

/// Settings `T` read from `table`, which stands at `[section]`; a refusal names the dotted key
/// and quotes the value as `written` has it (cut to a readable length).
///
/// A wrong type is named by the path `serde_path_to_error` keeps; an array where `T` has a
/// table (serde would fill the struct's fields in order) is refused.
pub(crate) fn read_section<T>(
    table: &toml::Table,
    written: &toml::Table,
    section: &str,
) -> std::result::Result<T, Refusal>
where
    T: Serialize + serde::de::DeserializeOwned,
{
    let dotted = |k: &str| match (k, section) {
        ("" | ".", _) => section.to_string(),
        (_, "") => k.to_string(),
        _ => format!("{section}.{k}"),
    };
    let quoted = |k: &str| {
        value_at(written, k)
            .filter(|v| !v.is_table())
            .map_or(String::new(), toml::Value::to_string)
    };
    let merged = toml::Value::Table(table.clone());
    let value: T = serde_path_to_error::deserialize(merged.clone()).map_err(|e| {
        let path = e.path().to_string();
        if let Some(k) = seq_for_struct::<T>(&merged, &path) {
            let key = dotted(&k);
            return Refusal {
                message: not_a_table(&key),
                key,
            };
        }
        let key = dotted(&path);
        let written = Some(quoted(&path)).filter(|w| !w.is_empty());
        let message = cut_quotes(e.into_inner().message().trim());
        Refusal {
            message: keyed(Some(&key), written.as_deref(), &message),
            key,
        }
    })?;
    if let Some(key) = array_for_table(&toml::Value::Table(written.clone()), &value, section) {
        return Err(Refusal {
            message: not_a_table(&key),
            key,
        });
    }
    Ok(value)
}

/// `base` with the override table of `[section]` merged in (nested sections key by key,
/// aliases such as `mu` expanded); unknown keys are refused, a key of another section with its
/// place named.
///
/// Keys the base leaves out (optional settings such as `dynamics.integrator.atol`) are known by
/// the section's struct, which refuses typos when the merged table is read back.
pub(crate) fn overlay<T>(base: &T, overrides: &toml::Table, section: &str) -> Result<T>
where
    T: Serialize + serde::de::DeserializeOwned,
{
    let mut over = overrides.clone();
    crate::settings::expand_aliases(section, &mut over);
    let mut table = toml::Table::try_from(base).expect("settings serialise to a table");
    crate::settings::merge(&mut table, &over);
    read_section(&table, &over, section).map_err(|r| Error::Refused {
        key: r.key,
        message: r.message,
    })
}

/// The value at a dotted key of a table (array indices are not followed).
fn value_at<'a>(t: &'a toml::Table, key: &str) -> Option<&'a toml::Value> {
    let (head, rest) = match key.split_once('.') {
        Some((h, r)) => (h, Some(r)),
        None => (key, None),
    };
    match (t.get(head)?, rest) {
        (v, None) => Some(v),
        (toml::Value::Table(inner), Some(r)) => value_at(inner, r),
        (v, Some(_)) => Some(v),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::DynamicsParams;
    use crate::minnorm::MinNormSettings;
    use crate::scene::SceneParams;

    #[test]
    fn overrides_replace_only_their_keys_and_refuse_typos() {
        let mut t = toml::Table::new();
        t.insert("force_n".into(), toml::Value::Float(50.0));
        let p = overlay(&SceneParams::default(), &t, "scene").unwrap();
        assert_eq!(p.force_n, 50.0);
        assert_eq!(p.radius_mm, 10.0);
        t.insert("radus_mm".into(), toml::Value::Float(5.0));
        let msg = overlay(&SceneParams::default(), &t, "scene")
            .unwrap_err()
            .to_string();
        assert!(msg.contains("scene") && msg.contains("radus_mm"), "{msg}");
    }

    #[test]
    fn dynamics_override_replaces_its_key_and_refuses_typos() {
        let t: toml::Table = toml::from_str("series = { after_jam_s = 0.2 }\n").unwrap();
        let base = DynamicsParams {
            series: crate::dynamics::SeriesSettings { after_jam_s: 0.0 },
            drive: crate::dynamics::DriveSettings {
                omega_deg_s: 10.0,
                ..Default::default()
            },
            ..Default::default()
        };
        let d = overlay(&base, &t, "dynamics").unwrap();
        assert!((d.series.after_jam_s - 0.2).abs() < 1e-15);
        // Nested sections merge key by key: the base's other keys stay.
        assert_eq!(d.drive.omega_deg_s, 10.0);
        // An optional key the base leaves out is still known.
        let t: toml::Table = toml::from_str("integrator = { atol = 1e-7 }\n").unwrap();
        let d = overlay(&DynamicsParams::default(), &t, "dynamics").unwrap();
        assert_eq!(d.integrator.atol, Some(1e-7));
        let t: toml::Table = toml::from_str("series = { after_jam = 0.2 }\n").unwrap();
        let msg = overlay(&DynamicsParams::default(), &t, "dynamics")
            .unwrap_err()
            .to_string();
        assert!(
            msg.contains("dynamics.series") && msg.contains("after_jam"),
            "{msg}"
        );
    }

    /// A file written before the dynamics settings were grouped by role names each key's new
    /// place; `[scene] mu` sets both frictions, as `--mu` and `--set mu` do.
    #[test]
    fn a_key_in_its_old_section_is_refused_with_its_new_place_and_mu_is_an_alias() {
        let t: toml::Table = toml::from_str("stiffness_n_per_mm_e = 1e6\n").unwrap();
        let msg = overlay(&DynamicsParams::default(), &t, "dynamics")
            .unwrap_err()
            .to_string();
        assert!(
            msg.contains("it belongs in [dynamics.contact]: dynamics.contact.stiffness_n_per_mm_e"),
            "{msg}"
        );
        let t: toml::Table = toml::from_str("mu = 0.2\nmu_palm = 0.5\n").unwrap();
        let p = overlay(&SceneParams::default(), &t, "scene").unwrap();
        assert_eq!((p.mu_ground, p.mu_palm), (0.2, 0.5));
    }

    /// Regression: a `[dynamics]` override of the wrong type said `invalid dynamics
    /// = invalid type: unit variant, expected string only`; an array stood in for a table.
    #[test]
    fn overrides_of_the_wrong_type_name_the_key_and_value() {
        let t: toml::Table = toml::from_str("integrator = { rtol = \"x\" }\n").unwrap();
        let msg = overlay(&DynamicsParams::default(), &t, "dynamics")
            .unwrap_err()
            .to_string();
        assert!(
            msg.starts_with("dynamics.integrator.rtol: expected a number, found text"),
            "{msg}"
        );
        let t: toml::Table = toml::from_str("qp = [1, 2]\n").unwrap();
        let msg = overlay(&MinNormSettings::default(), &t, "min_norm")
            .unwrap_err()
            .to_string();
        assert!(msg.contains("min_norm.qp: expected a table"), "{msg}");
    }
}
