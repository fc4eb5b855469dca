//! Every setting declared once: its TOML key, flag, chart symbol, unit, default, valid range and
//! doc, in the struct that holds it (`settings!`).
//!
//! From that one declaration come the struct with its serde keys and `Default`, the range check
//! of `validate`, the clap flag and both registers of its help ([`flags`]), `--set` and the
//! sections of scene files (every override is a TOML table merged over the defaults, [`merge`]),
//! the key-to-flag names in error messages ([`flag_for`]), a grid axis and its label
//! ([`crate::grid::GridParam`]) and the key reference tables (`jamchart settings`, README,
//! charts/README.md; a test compares them).
//!
//! Keys are unique across the sections of one family (the palm scene's `[scene]`, `[min_norm]`
//! and `[dynamics.*]`; the V-locator's), so a bare key names one setting: `--set
//! stiffness_n_per_mm_e=1e6` finds `[dynamics.contact]`, and a key written in the wrong section
//! is refused with its right place named.

pub(crate) mod flags;
#[macro_use]
mod macros;

use crate::error::{Error, Result};

/// What values a setting takes, for its flag's parser, its help and its range check.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Check {
    /// Any finite number.
    Finite,
    /// A finite number >= the bound.
    AtLeast(f64),
    /// A finite number > the bound.
    Above(f64),
    /// A finite number strictly between the bounds.
    Open(f64, f64),
    /// A finite number > the first bound and <= the second.
    OpenClosed(f64, f64),
    /// A finite number in the closed interval.
    Closed(f64, f64),
    /// A finite number >= the first bound and < the second.
    CloseOpen(f64, f64),
    /// A whole number >= the bound.
    CountAtLeast(u64),
    /// Not a number (a choice or a switch): serde checks it.
    Typed,
}

impl Check {
    /// Why `v` is refused, or None when it is fine.
    pub(crate) fn refuse(&self, v: f64) -> Option<String> {
        let ok = v.is_finite()
            && match *self {
                Check::Finite | Check::Typed => true,
                Check::AtLeast(lo) => v >= lo,
                Check::Above(lo) => v > lo,
                Check::Open(lo, hi) => v > lo && v < hi,
                Check::OpenClosed(lo, hi) => v > lo && v <= hi,
                Check::Closed(lo, hi) => v >= lo && v <= hi,
                Check::CloseOpen(lo, hi) => v >= lo && v < hi,
                Check::CountAtLeast(lo) => v >= lo as f64,
            };
        (!ok).then(|| format!("must be {}", self.describe()))
    }

    /// The valid values in words, e.g. `a finite number > 0`.
    pub(crate) fn describe(&self) -> String {
        match *self {
            Check::Finite => "a finite number".into(),
            Check::AtLeast(lo) => format!("a finite number >= {}", number_text(lo)),
            Check::Above(lo) => format!("a finite number > {}", number_text(lo)),
            Check::Open(lo, hi) => {
                format!("a number in ({}, {})", number_text(lo), number_text(hi))
            }
            Check::OpenClosed(lo, hi) => {
                format!("a number in ({}, {}]", number_text(lo), number_text(hi))
            }
            Check::Closed(lo, hi) => {
                format!("a number in [{}, {}]", number_text(lo), number_text(hi))
            }
            Check::CloseOpen(lo, hi) => {
                format!("a number in [{}, {})", number_text(lo), number_text(hi))
            }
            Check::CountAtLeast(lo) => format!("a whole number >= {lo}"),
            Check::Typed => "one of the values listed".into(),
        }
    }
}

/// The kind of value a setting holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Kind {
    /// A number (f64).
    Real,
    /// A number that may be left unset (`Option<f64>`): its default is derived.
    OptionalReal,
    /// A whole number.
    Count,
    /// A yes/no; its flag sets the opposite of the default.
    Switch,
    /// One of the named values.
    Choice(&'static [&'static str]),
    /// A nested section (e.g. `[min_norm.qp]`): checked with its parent, never a flag.
    Section,
    /// Not a field: a name for several (an alias, `sets`) or a quantity derived from fields
    /// that a grid can vary (the parameter set knows how).
    Derived,
}

/// One declared setting. Built by `settings!`; written by hand only for aliases and derived
/// grid parameters.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Decl {
    /// The TOML key (the field's name), unique within its family.
    pub key: &'static str,
    /// The TOML section, e.g. `scene` or `dynamics.contact`.
    pub section: &'static str,
    /// The long flag without its dashes, if the setting has one.
    pub flag: Option<&'static str>,
    /// The symbol on charts, e.g. `F`.
    pub symbol: &'static str,
    /// The quantity in words, for axis labels, e.g. `palm push`.
    pub quantity: &'static str,
    /// The unit: `-` for a dimensionless number, `` for a choice or a switch.
    pub unit: &'static str,
    /// The doc: its first line is the short help, the rest the long help.
    pub doc: &'static str,
    /// What values are valid.
    pub check: Check,
    /// What kind of value it holds.
    pub kind: Kind,
    /// The default as TOML text (for a derived default, its doc says it).
    pub default: fn() -> String,
    /// For an alias, the keys it sets (in the same section).
    pub sets: &'static [&'static str],
    /// The flag's value name in help, e.g. `MM`.
    pub value_name: &'static str,
    /// Whether it takes a range or a distribution besides a number ([`crate::uncertain`]).
    pub uncertain: bool,
}

impl Decl {
    /// A declaration with nothing set, for struct-update syntax.
    pub(crate) const BASE: Decl = Decl {
        key: "",
        section: "",
        flag: None,
        symbol: "",
        quantity: "",
        unit: "",
        doc: "",
        check: Check::Typed,
        kind: Kind::Derived,
        default: String::new,
        sets: &[],
        value_name: "",
        uncertain: false,
    };

    /// The name an error message uses: the bare key of a family's parameters (`[scene]`, the
    /// locator; also the names of grid axes), the dotted path elsewhere.
    pub(crate) fn path(&self) -> String {
        if matches!(self.section, "scene" | "locator" | "") {
            self.key.to_string()
        } else {
            format!("{}.{}", self.section, self.key)
        }
    }

    /// The short help: the doc's first paragraph, on one line.
    pub(crate) fn summary(&self) -> String {
        let first: Vec<&str> = self
            .doc
            .lines()
            .map(str::trim)
            .skip_while(|l| l.is_empty())
            .take_while(|l| !l.is_empty())
            .collect();
        first.join(" ")
    }

    /// The doc after its first paragraph, each paragraph on one line.
    pub(crate) fn details(&self) -> String {
        let mut lines = self.doc.lines().map(str::trim).skip_while(|l| l.is_empty());
        lines.by_ref().take_while(|l| !l.is_empty()).for_each(drop);
        let rest: Vec<&str> = lines.collect();
        rest.join("\n")
            .split("\n\n")
            .map(|p| p.replace('\n', " "))
            .collect::<Vec<_>>()
            .join("\n\n")
            .trim()
            .to_string()
    }

    /// `0.4`, `motion`, `1e5`: the default as a reader writes it.
    pub(crate) fn default_text(&self) -> String {
        (self.default)()
    }

    /// Checks a number against the declared range; the error names the key and the value.
    pub(crate) fn check_real(&self, v: f64) -> Result<()> {
        match self.check.refuse(v) {
            None => Ok(()),
            Some(why) => Err(Error::invalid(&self.path(), v, self.reason(&why))),
        }
    }

    /// `the disc radius must be a finite number > 0 mm`.
    fn reason(&self, must: &str) -> String {
        let unit = match self.unit {
            "" | "-" => String::new(),
            u => format!(" ({u})"),
        };
        let what = if self.quantity.is_empty() {
            self.key
        } else {
            self.quantity
        };
        format!("{what}{unit} {must}")
    }
}

/// A value a declared field can hold: how it is checked and how a grid reads and sets it.
pub(crate) trait Value {
    /// Its kind.
    const KIND: Kind;
    /// Checks it against `decl`'s range.
    fn check(&self, decl: &Decl) -> Result<()> {
        let _ = decl;
        Ok(())
    }
    /// As a number, where it is one.
    fn real(&self) -> Option<f64> {
        None
    }
    /// Set from a number; false where it is not one.
    fn set_real(&mut self, _v: f64) -> bool {
        false
    }
    /// As a reader writes it.
    fn text(&self) -> String;
}

impl Value for f64 {
    const KIND: Kind = Kind::Real;
    fn check(&self, decl: &Decl) -> Result<()> {
        decl.check_real(*self)
    }
    fn real(&self) -> Option<f64> {
        Some(*self)
    }
    fn set_real(&mut self, v: f64) -> bool {
        *self = v;
        true
    }
    fn text(&self) -> String {
        number_text(*self)
    }
}

impl Value for Option<f64> {
    const KIND: Kind = Kind::OptionalReal;
    fn check(&self, decl: &Decl) -> Result<()> {
        self.map_or(Ok(()), |v| decl.check_real(v))
    }
    fn text(&self) -> String {
        self.map_or_else(String::new, number_text)
    }
}

impl Value for u64 {
    const KIND: Kind = Kind::Count;
    fn check(&self, decl: &Decl) -> Result<()> {
        decl.check_real(*self as f64)
    }
    fn text(&self) -> String {
        self.to_string()
    }
}

impl Value for u32 {
    const KIND: Kind = Kind::Count;
    fn check(&self, decl: &Decl) -> Result<()> {
        decl.check_real(f64::from(*self))
    }
    fn text(&self) -> String {
        self.to_string()
    }
}

impl Value for bool {
    const KIND: Kind = Kind::Switch;
    fn text(&self) -> String {
        self.to_string()
    }
}

/// `1e5` for 100000, `0.4` for 0.4: a default as it is written in the docs.
pub(crate) fn number_text(v: f64) -> String {
    let plain = v.to_string();
    let sci = format!("{v:e}");
    if plain.len() > sci.len() + 1 {
        sci
    } else {
        plain
    }
}

/// A settings struct's number fields, by key: what a grid and an uncertain input set.
pub trait Numbers {
    /// The field `key` as a number, where it is one.
    fn real(&self, key: &str) -> Option<f64>;
    /// Sets the field `key` from a number; false where it is not one.
    fn set_real(&mut self, key: &str, v: f64) -> bool;
}

/// A settings struct: its declarations, in field order.
pub(crate) trait Declared {
    /// Every field's declaration.
    const DECLS: &'static [Decl];
}

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
    palm_family().find(|d| d.key == key || d.path() == key)
}

/// The flags that set `key` (a bare key or a dotted path), e.g. `--mu-ground or --mu`: its own
/// and those of the aliases that set it.
pub(crate) fn flag_for(key: &str) -> Option<String> {
    let decl = find(key).or_else(|| locator_family().find(|d| d.key == key))?;
    let own = decl.flag.map(|f| format!("--{f}"));
    let aliases = all()
        .filter(|a| a.sets.contains(&decl.key) && a.section == decl.section)
        .filter_map(|a| a.flag.map(|f| format!("--{f}")));
    let all: Vec<String> = own.into_iter().chain(aliases).collect();
    (!all.is_empty()).then(|| all.join(" or "))
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
        let valid = match d.kind {
            Kind::Choice(c) => c.join(", "),
            Kind::Switch => "true, false".into(),
            _ if d.uncertain && d.section == "locator" => {
                format!("{}, or a range", d.check.describe())
            }
            _ if d.uncertain => format!("{}, or a range or distribution", d.check.describe()),
            _ => d.check.describe(),
        };
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
