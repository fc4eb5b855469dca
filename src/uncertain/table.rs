//! Uncertain values in a table of overrides (flags, `--set`, a file's section): each one taken
//! out, checked against its setting and replaced by its nominal point, so the settings structs
//! keep plain numbers.

use super::{Uncertain, UncertainInput, UncertainSet};
use crate::error::{Error, Result};
use crate::settings::Decl;

/// Takes the uncertain values out of `table`, the overrides of one section (`[scene]`, the
/// locator's), whose settings are `decls`: each is checked against its declaration and
/// replaced by its nominal value. A range or distribution given to a setting that does not
/// take one is refused, naming the settings that do.
pub(crate) fn take(
    table: &mut toml::Table,
    decls: impl Iterator<Item = &'static Decl> + Clone,
) -> Result<UncertainSet> {
    let mut set = UncertainSet::default();
    // Numbers only (the common question): nothing to take.
    if !table.values().any(toml::Value::is_str) {
        return Ok(set);
    }
    for decl in decls.clone() {
        let Some(toml::Value::String(text)) = table.get(decl.key) else {
            continue;
        };
        let value = match Uncertain::parse(text) {
            Ok(value) => value,
            // A range or a distribution written wrong (`normal(0.2`) is refused with what is
            // wrong, under the key as written: the settings struct said only "expected a
            // number" of `mu_ground`.
            Err(why) if decl.uncertain && text.contains(['(', ':']) => {
                return Err(Error::invalid(decl.key, text, why));
            }
            // Not our syntax: the settings struct refuses the string with its own message.
            Err(_) => continue,
        };
        if !decl.uncertain {
            return Err(Error::invalid(
                decl.key,
                text,
                format!(
                    "{} takes a single number; a range or a distribution is taken by {}",
                    decl.key,
                    takers(decls.clone())
                ),
            ));
        }
        value.check(decl)?;
        table.insert(decl.key.to_string(), toml::Value::Float(value.nominal()));
        if !value.is_uncertain() {
            continue;
        }
        let keys: Vec<&'static str> = if decl.sets.is_empty() {
            vec![decl.key]
        } else {
            // A key given as well takes precedence over the alias for itself.
            let own = |k: &&str| table.contains_key(*k);
            decl.sets.iter().copied().filter(|k| !own(k)).collect()
        };
        set.inputs.push(UncertainInput {
            name: decl.key,
            keys,
            value,
        });
    }
    Ok(set)
}

/// `mu, mu_ground, mu_palm, mass_kg and force_n`: the settings of `decls` that take uncertainty.
fn takers(decls: impl Iterator<Item = &'static Decl>) -> String {
    let names: Vec<&str> = decls.filter(|d| d.uncertain).map(|d| d.key).collect();
    match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        Some((last, _)) => last.to_string(),
        None => "no setting here".into(),
    }
}
