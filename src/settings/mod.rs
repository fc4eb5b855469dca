//! Every setting declared once: its TOML key, flag, chart symbol, unit, default, valid range and
//! doc, in the struct that holds it (`settings!`).
//!
//! From that one declaration come the struct with its serde keys and `Default`, the range check
//! of `validate`, the clap flag and both registers of its help ([`flags`]), `--set` and the
//! sections of scene files (every override is a TOML table merged over the defaults, [`merge`]),
//! the key-to-flag names in error messages ([`flag_for`]), a grid axis and its label
//! ([`crate::scene::Param`]) and the key reference tables (`jamchart settings`, the guide,
//! charts/README.md; a test compares them).
//!
//! Keys are unique across the sections of one family (the palm scene's `[scene]`, `[min_norm]`
//! and `[dynamics.*]`; the V-locator's), so a bare key names one setting: `--set
//! stiffness_n_per_mm_e=1e6` finds `[dynamics.contact]`, and a key written in the wrong section
//! is refused with its right place named.
//!
//! The declaration itself ([`decl`]) sits below the parameter structs that use it; this module
//! gathers their declarations into the two families and derives the rest from them.

pub(crate) mod decl;
pub(crate) mod flags;
#[macro_use]
mod macros;

pub use decl::Numbers;
pub(crate) use decl::{Check, Decl, Declared, Kind, Value, number_text};

/// The palm scene's family: every section of a parameter file, in the order of the key
/// reference. Keys are unique across all of them (a test checks it).
pub(crate) fn palm_family() -> impl Iterator<Item = &'static Decl> + Clone {
    use crate::dynamics::params as d;
    let sections: [&'static [Decl]; 11] = [
        crate::scene::SCENE_ALIASES,
        crate::scene::SceneParams::DECLS,
        crate::minnorm::MinNormSettings::DECLS,
        crate::minnorm::QpSettings::DECLS,
        d::DriveSettings::DECLS,
        d::ContactLaw::DECLS,
        d::FRICTION_ALIASES,
        d::FrictionLaw::DECLS,
        d::IntegratorSettings::DECLS,
        d::Verification::DECLS,
        d::JamReading::DECLS,
    ];
    sections
        .into_iter()
        .flatten()
        .chain(d::SeriesSettings::DECLS)
        .filter(|d| d.kind != Kind::Section)
}

/// The V-locator's family: `vlocator`'s flags and the `locator` tables of its chart scenes.
pub(crate) fn locator_family() -> impl Iterator<Item = &'static Decl> + Clone {
    use crate::locator::params as l;
    l::LOCATOR_ALIASES.iter().chain(l::LocatorParams::DECLS)
}

/// Every declaration of both families.
pub(crate) fn all() -> impl Iterator<Item = &'static Decl> {
    palm_family().chain(locator_family())
}

/// The declaration of a key of the palm family, by its bare key or its dotted path.
pub(crate) fn find(key: &str) -> Option<&'static Decl> {
    palm_family().find(|d| d.key == key || d.path_is(key))
}

/// The flags that set `key` (a bare key or a dotted path), e.g. `--mu-ground or --mu`: its own
/// and those of the aliases that set it.
pub(crate) fn flag_for(key: &str) -> Option<String> {
    flags_naming(key, std::iter::empty(), |_| true)
}

/// The flags a message names beside `key`, among those a command takes (`takes`): a setting's
/// own flag and its aliases' (`--mu-ground or --mu`), searched first among the command's own
/// declarations (`own`: its report flags, e.g. `runs` for `--runs`); for a quantity of several
/// settings (`mass_kg * gravity_m_s2`, every word a declared key) each one's flags (`--mass and
/// --gravity`). None where the command takes no flag for it (`render` sets `radius_mm` by
/// `--set` or a scene file).
pub(crate) fn flags_naming(
    key: &str,
    own: impl Iterator<Item = &'static Decl> + Clone,
    takes: impl Fn(&str) -> bool,
) -> Option<String> {
    let decl = |k: &str| {
        own.clone()
            .find(|d| d.key == k)
            .or_else(|| all().find(|d| d.key == k || d.path_is(k)))
    };
    let flags = |d: &Decl| d.flags_taken(own.clone().chain(all()), &takes);
    if let Some(d) = decl(key) {
        return flags(d);
    }
    let words = key.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '.'));
    let decls: Option<Vec<&Decl>> = words.filter(|w| !w.is_empty()).map(decl).collect();
    let mut parts: Vec<String> = Vec::new();
    for f in decls?.into_iter().filter_map(flags) {
        if !parts.contains(&f) {
            parts.push(f);
        }
    }
    let last = parts.pop()?;
    Some(match parts.is_empty() {
        true => last,
        false => format!("{} and {last}", parts.join(", ")),
    })
}

/// Where an unknown key of section `section` belongs, if it is a key of another section:
/// `dynamics.contact.stiffness_n_per_mm_e`.
pub(crate) fn moved(section: &str, key: &str) -> Option<String> {
    palm_family()
        .find(|d| d.key == key && d.section != section && d.kind != Kind::Derived)
        .map(|d| format!("{}.{}", d.section, d.key))
}

/// `table` with `over` merged in, key by key, into nested tables: what a scene file's section,
/// a `--set` or a flag changes of its base.
pub(crate) fn merge(table: &mut toml::Table, over: &toml::Table) {
    for (k, v) in over {
        match (table.get_mut(k), v) {
            (Some(toml::Value::Table(t)), toml::Value::Table(o)) => merge(t, o),
            _ => {
                table.insert(k.clone(), v.clone());
            }
        }
    }
}

/// `over`'s aliases replaced by the keys they set (`mu = 0.3` in `[scene]` sets `mu_ground` and
/// `mu_palm`, unless they are given too), at the section `section` of the family.
pub(crate) fn expand_aliases(section: &str, over: &mut toml::Table) {
    for alias in all().filter(|d| d.section == section && !d.sets.is_empty()) {
        if let Some(v) = over.remove(alias.key) {
            for k in alias.sets {
                over.entry(k.to_string()).or_insert_with(|| v.clone());
            }
        }
    }
    for (k, v) in over.iter_mut() {
        if let toml::Value::Table(t) = v {
            let inner = if section.is_empty() {
                k.clone()
            } else {
                format!("{section}.{k}")
            };
            expand_aliases(&inner, t);
        }
    }
}

/// One setting as a face documents it (`GET /api/v1/settings`, a form generated from it):
/// the facts of `jamchart settings`' table, each its own field.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SettingDoc {
    /// The key, as a keyword, a JSON body and `--set` give it (`rtol`; keys are unique).
    pub key: String,
    /// Which command's settings: `palm` (solve, design, render) or `locator` (vlocator), or
    /// which question's own keys: `solve`, `design` or `vlocator`.
    pub family: &'static str,
    /// Its section of a parameter file (`scene`, `dynamics.contact`, `locator`).
    pub section: &'static str,
    /// The command line's flag, without its dashes.
    pub flag: Option<&'static str>,
    /// The unit (`mm`, `N`, `-` for a ratio; empty for a choice or a switch).
    pub unit: &'static str,
    /// The default as written in a parameter file (empty where it is derived: see `details`).
    pub default: String,
    /// What kind of value: `number`, `optional_number`, `count`, `switch`, `choice`,
    /// `alias` (a name for several keys, `sets`) or `derived` (a quantity of other keys).
    pub kind: &'static str,
    /// A choice's values.
    pub choices: &'static [&'static str],
    /// The keys an alias sets.
    pub sets: &'static [&'static str],
    /// The valid values in words (`a finite number > 0`), with the range forms it takes.
    pub valid: String,
    /// Whether it takes a range (`lo:hi`).
    pub range: bool,
    /// Whether it takes a distribution (`normal(m,s)`).
    pub distribution: bool,
    /// The chart symbol (`F`) and the quantity in words (`palm push`).
    pub symbol: &'static str,
    /// The quantity in words, for a label.
    pub quantity: &'static str,
    /// The short help, one line.
    pub summary: String,
    /// The rest of the help.
    pub details: String,
}

/// Every setting of both families as [`SettingDoc`]s, in the order of `jamchart settings`,
/// then the questions' own keys (family `solve`, `design` or `vlocator`).
pub fn documented() -> Vec<SettingDoc> {
    let own = [
        ("solve", crate::ask::DIST_KEYS),
        ("design", crate::ask::DESIGN_KEYS),
        ("vlocator", crate::ask::GEOMETRY_KEYS),
    ];
    let families = all()
        .map(|d| {
            (
                if d.section == "locator" {
                    "locator"
                } else {
                    "palm"
                },
                d,
            )
        })
        .chain(
            own.into_iter()
                .flat_map(|(f, decls)| decls.iter().map(move |d| (f, d))),
        );
    families
        .map(|(family, d)| {
            let locator = d.section == "locator";
            SettingDoc {
                key: d.key.to_string(),
                family,
                section: d.section,
                flag: d.flag,
                unit: d.unit,
                default: d.default_text(),
                kind: match d.kind {
                    Kind::Real => "number",
                    Kind::OptionalReal => "optional_number",
                    Kind::Count => "count",
                    Kind::Switch => "switch",
                    Kind::Choice(_) => "choice",
                    Kind::Section | Kind::Derived if !d.sets.is_empty() => "alias",
                    Kind::Section | Kind::Derived if d.unit.is_empty() => "derived",
                    Kind::Section | Kind::Derived => "number",
                },
                choices: match d.kind {
                    Kind::Choice(c) => c,
                    _ => &[],
                },
                sets: d.sets,
                valid: valid_text(d),
                range: d.uncertain,
                distribution: d.uncertain && !locator,
                symbol: d.symbol,
                quantity: d.quantity,
                summary: d.summary(),
                details: d.details(),
            }
        })
        .collect()
}

/// The valid values of `d` in words, with the range forms it takes.
fn valid_text(d: &Decl) -> String {
    match d.kind {
        Kind::Choice(c) => c.join(", "),
        Kind::Switch => "true, false".into(),
        Kind::Derived if d.check == Check::Typed => "see meaning".into(),
        _ if d.uncertain && d.section == "locator" => {
            format!("{}, or a range", d.check.describe())
        }
        _ if d.uncertain => format!("{}, or a range or distribution", d.check.describe()),
        _ => d.check.describe(),
    }
}

/// The key reference as a Markdown table: flag, TOML key, unit, default, valid values, doc.
pub(crate) fn reference_table() -> String {
    reference_rows(|s| s != "locator")
}

/// What `jamchart settings` prints: the palm scene's reference, then the V-locator's.
pub(crate) fn reference() -> String {
    format!(
        "Settings of solve, sweep, render, accuracy and stability (TOML file, scene files, \
         --set):\n\n{}\nSettings of vlocator (a chart scene's [chart] locator table):\n\n{}",
        reference_table(),
        reference_rows(|s| s == "locator")
    )
}

/// The reference of the sections whose name passes `keep` (charts/README.md holds `[scene]`'s).
pub(crate) fn reference_rows(keep: impl Fn(&str) -> bool) -> String {
    let mut out = String::from(
        "| flag | TOML key | unit | default | valid | meaning |\n|---|---|---|---|---|---|\n",
    );
    for d in all().filter(|d| keep(d.section)) {
        let flag = d
            .flag
            .map_or_else(|| "-".to_string(), |f| format!("`--{f}`"));
        let key = if d.sets.is_empty() {
            format!("`{}`", d.path())
        } else {
            format!("`{}` (sets {})", d.key, d.sets.join(", "))
        };
        let valid = valid_text(d);
        let default = match d.default_text() {
            t if t.is_empty() => "see meaning".to_string(),
            t => t,
        };
        out.push_str(&format!(
            "| {flag} | {key} | {} | {default} | {valid} | {} |\n",
            if d.unit.is_empty() { "-" } else { d.unit },
            d.summary()
        ));
    }
    out
}

#[cfg(test)]
mod tests;
