//! The declared settings as clap flags: [`Flags`] adds one flag per declaration of its sections,
//! with both registers of help made from the declaration, and hands back what was given as a
//! TOML table of overrides, merged like `--set` and a scene file's sections.

use std::marker::PhantomData;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Arg, ArgAction, ArgMatches, Command};

use super::all;
use super::decl::{Decl, Kind, parse_count, parse_f64};
use crate::uncertain::Uncertain;

/// Which declared sections a command's flags come from, and their help heading.
pub(crate) trait FlagSet {
    /// A declaration is a flag of this set when its section starts with one of these.
    const SECTIONS: &'static [&'static str];
    /// The help heading (None: the command's options).
    const HEADING: Option<&'static str>;
}

/// The flags of the scene: frictions, disc, push, palm.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct SceneSet;
impl FlagSet for SceneSet {
    const SECTIONS: &'static [&'static str] = &["scene"];
    const HEADING: Option<&'static str> = None;
}

/// The flags of the dynamic simulation.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct DynamicsSet;
impl FlagSet for DynamicsSet {
    const SECTIONS: &'static [&'static str] = &["dynamics"];
    const HEADING: Option<&'static str> = Some("Dynamics");
}

/// The flags of the min-norm model.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct MinNormSet;
impl FlagSet for MinNormSet {
    const SECTIONS: &'static [&'static str] = &["min_norm"];
    const HEADING: Option<&'static str> = Some("Min-norm");
}

/// The flags of the V-locator.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct LocatorSet;
impl FlagSet for LocatorSet {
    const SECTIONS: &'static [&'static str] = &["locator"];
    const HEADING: Option<&'static str> = None;
}

/// The declared flags of one set, as given on the command line.
#[derive(Debug, Clone)]
pub(crate) struct Flags<S> {
    /// Each given flag's declaration and value, aliases first (a flag for one key given as
    /// well wins over the alias, whatever the order typed).
    given: Vec<(&'static Decl, toml::Value)>,
    set: PhantomData<S>,
}

impl<S> Default for Flags<S> {
    fn default() -> Self {
        Flags {
            given: Vec::new(),
            set: PhantomData,
        }
    }
}

/// The declarations that are flags of `S`.
fn decls<S: FlagSet>() -> impl Iterator<Item = &'static Decl> {
    all().filter(|d| {
        d.flag.is_some()
            && S::SECTIONS
                .iter()
                .any(|s| d.section == *s || d.section.starts_with(&format!("{s}.")))
    })
}

impl<S: FlagSet> Flags<S> {
    /// What was given as a table shaped like a parameter file (`{dynamics: {contact: {...}}}`),
    /// aliases expanded.
    pub(crate) fn overrides(&self) -> toml::Table {
        let mut table = toml::Table::new();
        for (decl, value) in &self.given {
            // An alias given a range keeps its own key: its fields take one draw together
            // (`crate::uncertain::take` expands it).
            let keys: Vec<&str> = if decl.sets.is_empty() || value.is_str() {
                vec![decl.key]
            } else {
                decl.sets.to_vec()
            };
            let t = decl.section_in(&mut table);
            for k in keys {
                t.insert(k.to_string(), value.clone());
            }
        }
        table
    }
}

/// The clap argument of a declaration; `takers` names the flags of its set that take a range.
fn arg(d: &'static Decl, heading: Option<&'static str>, takers: &str) -> Arg {
    let flag = d.flag.expect("only declarations with a flag");
    let default = d.default_text();
    let unit = match d.unit {
        "" | "-" => "",
        u => u,
    };
    let default_note = match (d.kind, default.as_str(), unit) {
        (Kind::Switch, _, _) | (_, "", _) => String::new(),
        (_, _, "") => format!(" [default: {default}]"),
        _ => format!(" [default: {default} {unit}]"),
    };
    let summary = d.summary();
    let short = format!("{}{default_note}", summary.trim_end_matches('.'));
    let key = if d.sets.is_empty() {
        format!("TOML key: {}", d.path())
    } else {
        format!("Sets {}", d.sets.join(" and "))
    };
    let valid = match d.kind {
        Kind::Choice(_) | Kind::Switch => String::new(),
        _ if unit.is_empty() => format!("; {}", d.check.describe()),
        _ => format!("; {}, in {unit}", d.check.describe()),
    };
    let valid = if d.uncertain {
        format!("{valid}; or {}", uncertain_forms(d))
    } else {
        valid
    };
    let details = d.details();
    let long = if details.is_empty() {
        format!("{short}\n\n{key}{valid}")
    } else {
        format!("{short}\n\n{details}\n\n{key}{valid}")
    };
    let a = Arg::new(d.key)
        .long(flag)
        .help(short)
        .long_help(long)
        .help_heading(heading);
    match d.kind {
        Kind::Switch => a.action(ArgAction::SetTrue),
        Kind::Choice(names) => a.value_name(value_name(d)).value_parser(
            PossibleValuesParser::new(names.iter().copied()).map(toml::Value::String),
        ),
        Kind::Count => a
            .value_name(value_name(d))
            .allow_hyphen_values(true)
            .value_parser(|s: &str| -> Result<toml::Value, String> {
                let n = parse_count(s)?;
                i64::try_from(n)
                    .map(toml::Value::Integer)
                    .map_err(|_| format!("{n} is too large"))
            }),
        // `-90:-45` is a value, not a flag: clap's negative numbers are single numbers only.
        _ if d.uncertain => a
            .value_name(value_name(d))
            .allow_hyphen_values(true)
            .value_parser(|s: &str| {
                Uncertain::parse(s).map(|u| match u {
                    Uncertain::Point { value } => toml::Value::Float(value),
                    u => toml::Value::String(u.to_string()),
                })
            }),
        Kind::Real | Kind::OptionalReal | Kind::Derived | Kind::Section => {
            let refusal = format!(
                "--{flag} takes a single number; a range or a distribution is \
                                   taken by {takers}"
            );
            a.value_name(value_name(d))
                .allow_hyphen_values(true)
                .value_parser(move |s: &str| match parse_f64(s) {
                    Ok(v) => Ok(toml::Value::Float(v)),
                    Err(_) if Uncertain::parse(s).is_ok_and(|u| u.is_uncertain()) => {
                        Err(refusal.clone())
                    }
                    Err(e) => Err(e),
                })
        }
    }
}

/// The forms of an uncertain value, for help texts.
pub(crate) const UNCERTAIN_FORMS: &str = "a range LOW:HIGH (worst case over it) or a \
    distribution uniform(LOW,HIGH), normal(MEAN,SD) (truncated at 0) or \
    lognormal(MEDIAN,SIGMA)";

/// The V-locator's forms of an uncertain value: it designs a V over every value of a range,
/// and weighs no distribution.
pub(crate) const RANGE_FORMS: &str = "a range LOW:HIGH (the V is designed to hold every value \
    of it)";

/// The uncertain forms `d` takes: ranges only for the V-locator, else ranges and distributions.
pub(crate) fn uncertain_forms(d: &Decl) -> &'static str {
    match d.section {
        "locator" => RANGE_FORMS,
        _ => UNCERTAIN_FORMS,
    }
}

/// `MM` for a length: the unit in capitals, or the declared value name.
fn value_name(d: &Decl) -> String {
    if !d.value_name.is_empty() {
        return d.value_name.to_string();
    }
    match d.kind {
        Kind::Choice(_) => d.key.to_ascii_uppercase(),
        _ => match d.unit {
            "" | "-" => "NUMBER".to_string(),
            u => u.to_ascii_uppercase(),
        },
    }
}

impl<S: FlagSet> clap::FromArgMatches for Flags<S> {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut flags = Flags::default();
        flags.update_from_arg_matches(m)?;
        Ok(flags)
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        let mut given: Vec<(&'static Decl, toml::Value)> = Vec::new();
        for d in decls::<S>() {
            let value = match d.kind {
                Kind::Switch => m.get_flag(d.key).then(|| {
                    // The flag says the opposite of the default (`--no-verify`).
                    toml::Value::Boolean(d.default_text() != "true")
                }),
                _ => m.get_one::<toml::Value>(d.key).cloned(),
            };
            if let Some(v) = value {
                given.push((d, v));
            }
        }
        // Aliases first: a flag for one key overrides the alias that also sets it.
        given.sort_by_key(|(d, _)| d.sets.is_empty());
        self.given = given;
        Ok(())
    }
}

impl<S: FlagSet> clap::Args for Flags<S> {
    fn augment_args(cmd: Command) -> Command {
        let flags: Vec<String> = decls::<S>()
            .filter(|d| d.uncertain)
            .filter_map(|d| d.flag.map(|f| format!("--{f}")))
            .collect();
        let takers = match flags.is_empty() {
            true => "no flag of this command".to_string(),
            false => flags.join(", "),
        };
        decls::<S>().fold(cmd, |cmd, d| cmd.arg(arg(d, S::HEADING, &takers)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}
