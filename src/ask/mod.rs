//! Every question a face asks of the library, and its answer: typed in, typed out.
//!
//! The command line, the Python package and the HTTP API (`jamchart serve`) are faces over these types: each
//! builds a question from what its user gave (flags, keywords, a JSON body), calls `answer`,
//! and shows the answer (text, a Python object, JSON). None decides, checks or formats anything
//! another face needs: that is here.
//!
//! | question | answer | command line | Python |
//! |---|---|---|---|
//! | [`SolveQuestion`] | [`SolveAnswer`] | `jamchart solve` | `jamchart.solve` (one push, a range, a distribution) |
//! | [`DesignQuestion`] | [`DesignAnswer`] | `jamchart design` | `jamchart.design` |
//! | [`VlocatorQuestion`] | [`VlocatorAnswer`] | `jamchart vlocator` | `jamchart.vlocator` |
//! | [`RenderQuestion`] | [`RenderAnswer`] | `jamchart render` | `jamchart.render` |
//! | [`ReadOff`] | the chart's read-off | `render --read-off` | `jamchart.render(read_off=...)` |
//!
//! ## Building a question
//!
//! Each question is `Deserialize` from [`Keywords`]: the flat keys of the settings (the
//! Python keywords, the JSON keys of an HTTP body, the bare keys of `--set`), each a number, a
//! name, a switch, a list, or the command line's text of a range or a distribution
//! (`"0.12:0.3"`, `"normal(0.21,0.03)"`), plus the question's own keys (`model`, `before_mm`,
//! `x_target_mm`, ...). `from_keywords` does the same and keeps the library's typed
//! [`crate::Error`] (its key, value and reason), which a face turns into its own refusal.
//! The command line builds the same questions from its flags and `--config` file, through
//! the same checks.
//!
//! ## The answer
//!
//! Every answer is `Serialize`: its serde form is the command line's `--format json`
//! document, field for field. `text` gives the command line's report in a face's
//! vocabulary ([`Words`]): `--palm-length` on the command line, `palm_length_mm` elsewhere;
//! `headline` its one-line verdict.

mod design;
mod design_text;
mod keywords;
mod model_text;
mod read_off;
mod render;
mod solve;
mod solve_box_text;
mod solve_text;
mod vlocator;
mod vlocator_robust;
mod vlocator_text;

pub use crate::uncertain::Flow;
pub use crate::uncertain::dist::Progress;
pub(crate) use design::DESIGN_KEYS;
pub use design::{DesignAnswer, DesignQuestion, DesignReport, SimCheck};
pub use keywords::Keywords;
pub(crate) use keywords::nearest;
pub use read_off::ReadOff;
pub use render::{RenderAnswer, RenderQuestion};
pub use solve::{
    BoxAnswer, BoxRecord, DistAsk, DynamicsRecord, Models, PushAnswer, PushRecord, SolveAnswer,
    SolveQuestion, Trace,
};
pub(crate) use solve::{DIST_KEYS, MODEL_SAMPLES, STATICS_SAMPLES};
pub(crate) use vlocator::GEOMETRY_KEYS;
pub use vlocator::{PointReport, VlocatorAnswer, VlocatorQuestion};
pub use vlocator_robust::{GivenV, RobustReport};

use crate::config::Config;
use crate::error::Result;
use crate::uncertain::UncertainSet;

/// How a face names a setting in the text it shows: its own vocabulary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Words {
    /// The command line's flags: `--palm-length`, `--method nonsmooth`.
    Flags,
    /// The settings' keys, as a parameter file, a Python call and a JSON body spell them:
    /// `palm_length_mm`, `method = "nonsmooth"`.
    Keys,
}

impl Words {
    /// Setting `key` as this face names it: its flag (`--palm-length`) or its key
    /// (`palm_length_mm`).
    pub fn name(self, key: &str) -> String {
        match self {
            Words::Flags => flag(key),
            Words::Keys => key.to_string(),
        }
    }

    /// Setting `key` given `value`: `--method nonsmooth`, or `method = "nonsmooth"` (a
    /// choice's name quoted, anything else as written).
    pub fn given(self, key: &str, value: &str) -> String {
        let choice = || {
            crate::settings::all()
                .any(|d| d.key == key && matches!(d.kind, crate::settings::Kind::Choice(_)))
        };
        match self {
            Words::Flags => format!("{} {value}", flag(key)),
            Words::Keys if key == "model" || choice() => format!("{key} = \"{value}\""),
            Words::Keys => format!("{key} = {value}"),
        }
    }

    /// `text` (a setting's documentation, a message) in this face's words: each `--flag` of
    /// a setting named by its key where keys are spoken (`--mu-ground` -> `mu_ground`); a
    /// flag no setting declares is left as written.
    pub fn speak(self, text: &str) -> String {
        if self == Words::Flags {
            return text.to_string();
        }
        let mut out = String::with_capacity(text.len());
        let mut rest = text;
        while let Some(at) = rest.find("--") {
            out.push_str(&rest[..at]);
            let tail = &rest[at + 2..];
            let len = tail
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
                .unwrap_or(tail.len());
            let name = tail[..len].trim_end_matches('-');
            match decls().find(|d| d.flag == Some(name)) {
                Some(d) if !name.is_empty() => out.push_str(d.key),
                _ => out.push_str(&rest[at..at + 2 + name.len()]),
            }
            rest = &tail[name.len()..];
        }
        out.push_str(rest);
        out
    }

    /// Where a setting without a flag of its own is set: `in the [dynamics] section of
    /// --config` on the command line; nothing more elsewhere (the key is set as any other).
    pub fn file_only(self, section: &str) -> String {
        match self {
            Words::Flags => format!(" in the [{section}] section of --config"),
            Words::Keys => String::new(),
        }
    }
}

/// Every declared setting a face may name: the questions' own keys, then the settings'.
fn decls() -> impl Iterator<Item = &'static crate::settings::Decl> {
    let own = DIST_KEYS.iter().chain(DESIGN_KEYS).chain(GEOMETRY_KEYS);
    own.chain(crate::settings::all())
}

/// `--flag` of setting `key`: its own declared flag, the flag of a question's own key, or the
/// key spelt as a flag.
fn flag(key: &str) -> String {
    let decl = decls().find(|d| d.key == key || d.path_is(key));
    match decl.and_then(|d| d.flag) {
        Some(f) => format!("--{f}"),
        None => format!("--{}", key.replace('_', "-")),
    }
}

/// The palm scene of a question: `base` (the defaults, or a parameter file's config and its
/// ranges and distributions) with `over` merged in (a table shaped like a parameter file:
/// flags, keywords), the ranges and distributions of `[scene]` taken out (the config holds
/// their nominal values) and everything checked before anything is computed.
pub(crate) fn palm_scene(
    base: (Config, UncertainSet),
    mut over: toml::Table,
) -> Result<(Config, UncertainSet)> {
    let (config, mut uncertain) = base;
    if let Some(scene) = over.get_mut("scene").and_then(toml::Value::as_table_mut) {
        let given = crate::uncertain::take(scene, crate::config::scene_decls())?;
        uncertain.override_by(scene, given);
    }
    let config = config.overlay(&over)?;
    config.validate()?;
    Ok((config, uncertain))
}
