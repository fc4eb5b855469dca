//! One declared setting ([`Decl`]): what values it takes, what kind of value it holds, the
//! traits of the structs that hold them, and how a number a user writes is read.
//!
//! The parameter structs declare their fields with these; the families that gather every
//! declaration, and what is derived from them, are one floor up ([`super`]).

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::numbers::floats_away;

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
        (!self.accepts(v)).then(|| format!("must be {}", self.describe()))
    }

    /// Whether `v` is valid: [`Check::refuse`] without its words, for a pass over many values.
    #[inline]
    pub(crate) fn accepts(&self, v: f64) -> bool {
        Self::within(self.bounds(), v)
    }

    /// Whether `v` is finite and within `bounds` ([`Check::bounds`]): two comparisons, each
    /// false for NaN.
    #[inline(always)]
    fn within((lo, hi): (f64, f64), v: f64) -> bool {
        (v >= lo) & (v <= hi)
    }

    /// The index of the first value in `values` that [`Check::accepts`] refuses, if any. A
    /// block's values are all checked before any is looked at alone, against bounds read
    /// once, so that the comparisons run in vector lanes, and the blocks are shared by the
    /// thread pool: a column of a million values is one pass over memory, split between the
    /// cores.
    pub(crate) fn first_refused(&self, values: &[f64]) -> Option<usize> {
        const BLOCK: usize = 4096;
        let bounds = self.bounds();
        let refused = |v: f64| !Self::within(bounds, v);
        // One block is looked through on this thread: the pool's hand-over costs more.
        if values.len() <= BLOCK {
            return values.iter().position(|&v| refused(v));
        }
        let (b, block) = values
            .par_chunks(BLOCK)
            .enumerate()
            .find_first(|(_, block)| Self::any_refused(bounds, block))?;
        block
            .iter()
            .position(|&v| refused(v))
            .map(|i| b * BLOCK + i)
    }

    /// Whether any of `block` lies outside `bounds`: every value is compared (no early way
    /// out), so that the comparisons run in vector lanes, AVX2's four where the processor has
    /// it (3.9 instructions a value for the baseline's two lanes' 9, a column from Python).
    #[inline]
    fn any_refused(bounds: (f64, f64), block: &[f64]) -> bool {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the processor has AVX2, checked just above.
            return unsafe { Self::any_refused_avx2(bounds, block) };
        }
        Self::any_refused_in(bounds, block)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn any_refused_avx2(bounds: (f64, f64), block: &[f64]) -> bool {
        Self::any_refused_in(bounds, block)
    }

    #[inline(always)]
    fn any_refused_in(bounds: (f64, f64), block: &[f64]) -> bool {
        block
            .iter()
            .fold(0u32, |n, &v| n + u32::from(!Self::within(bounds, v)))
            > 0
    }

    /// The valid values as a closed interval of finite numbers: an open bound moved to the
    /// next number inward, an infinite one to the largest finite number, so that "finite and
    /// within" is two comparisons a value.
    #[inline]
    fn bounds(&self) -> (f64, f64) {
        let (lo, with_lo, hi, with_hi) = self.limits();
        let lo = if with_lo { lo } else { floats_away(lo, 1) };
        let hi = if with_hi { hi } else { floats_away(hi, -1) };
        (lo.max(-f64::MAX), hi.min(f64::MAX))
    }

    /// The bounds as the words say them: lower, whether it is valid itself, upper, whether
    /// it is.
    #[inline]
    fn limits(&self) -> (f64, bool, f64, bool) {
        let inf = f64::INFINITY;
        match *self {
            Check::Finite | Check::Typed => (-inf, true, inf, true),
            Check::AtLeast(lo) => (lo, true, inf, true),
            Check::Above(lo) => (lo, false, inf, true),
            Check::Open(lo, hi) => (lo, false, hi, false),
            Check::OpenClosed(lo, hi) => (lo, false, hi, true),
            Check::Closed(lo, hi) => (lo, true, hi, true),
            Check::CloseOpen(lo, hi) => (lo, true, hi, false),
            Check::CountAtLeast(lo) => (lo as f64, true, inf, true),
        }
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
    /// The table of this setting's section in `table` (`dynamics.integrator`), made where
    /// missing: where its key goes in a config file's tree.
    pub(crate) fn section_in<'t>(&self, table: &'t mut toml::Table) -> &'t mut toml::Table {
        let mut t = table;
        for part in self.section.split('.') {
            t = t
                .entry(part.to_string())
                .or_insert_with(|| toml::Value::Table(toml::Table::new()))
                .as_table_mut()
                .expect("sections are tables");
        }
        t
    }

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

    /// Whether `name` is this setting's [`Decl::path`], compared without building the path:
    /// a lookup by name runs for every cell a grid sets.
    pub(crate) fn path_is(&self, name: &str) -> bool {
        match self.section {
            "scene" | "locator" | "" => self.key == name,
            section => {
                name.strip_prefix(section)
                    .and_then(|rest| rest.strip_prefix('.'))
                    == Some(self.key)
            }
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
    #[inline]
    pub(crate) fn check_real(&self, v: f64) -> Result<()> {
        // The comparisons alone where the value is fine: every question checks each of its
        // numbers, and the words of a refusal are built only for one.
        match self.check.accepts(v) {
            true => Ok(()),
            false => Err(self.refusal(v)),
        }
    }

    /// The error of a number [`Decl::check_real`] refuses.
    #[cold]
    fn refusal(&self, v: f64) -> Error {
        let why = self.check.refuse(v).unwrap_or_default();
        Error::invalid(&self.path(), number_text(v), self.reason(&why))
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

impl Decl {
    /// The flags that set this setting, e.g. `--mu-ground or --mu`: its own and those of the
    /// aliases in `family` that set it.
    pub(crate) fn flags(&self, family: impl Iterator<Item = &'static Decl>) -> Option<String> {
        self.flags_taken(family, |_| true)
    }

    /// As [`Decl::flags`], keeping the flags a command takes (`takes` of the flag without
    /// its dashes).
    pub(crate) fn flags_taken(
        &self,
        family: impl Iterator<Item = &'static Decl>,
        takes: impl Fn(&str) -> bool,
    ) -> Option<String> {
        let aliases = family
            .filter(|a| a.sets.contains(&self.key) && a.section == self.section)
            .filter_map(|a| a.flag);
        let all: Vec<String> = (self.flag.into_iter().chain(aliases))
            .filter(|f| takes(f))
            .map(|f| format!("--{f}"))
            .collect();
        (!all.is_empty()).then(|| all.join(" or "))
    }
}

/// The flag of the declaration of `key` in `decls`, for a clap attribute (`long = flag!(..)`):
/// evaluated at compile time, so that a key without a declared flag fails the build.
pub(crate) const fn flag_of(decls: &[Decl], key: &str) -> &'static str {
    let mut i = 0;
    while i < decls.len() {
        if let Some(flag) = decls[i].flag
            && same(decls[i].key, key)
        {
            return flag;
        }
        i += 1;
    }
    panic!("the key has no declared flag")
}

/// `a == b`, in a `const fn`.
pub(crate) const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// Parses a count flag: a whole number >= 0, written out (`100000`, not `1e5`), with a message
/// that says so instead of the standard library's "invalid digit found in string".
pub fn parse_count(s: &str) -> std::result::Result<u64, String> {
    s.trim()
        .parse()
        .map_err(|e: std::num::ParseIntError| match e.kind() {
            std::num::IntErrorKind::PosOverflow => format!(
                "{} is more than a count can hold ({})",
                crate::error::cut(s),
                u64::MAX
            ),
            _ => format!(
                "{} is not a whole number >= 0 (write it out, e.g. 100000 for 1e5)",
                crate::error::cut(s)
            ),
        })
}

/// [`parse_count`] of a count held as a `usize`.
pub fn parse_count_usize(s: &str) -> std::result::Result<usize, String> {
    let n = parse_count(s)?;
    usize::try_from(n).map_err(|_| {
        format!(
            "{} is more than a count can hold ({})",
            crate::error::cut(s),
            usize::MAX
        )
    })
}

/// Parses a number flag, refusing text that overflows to infinity or underflows to zero, so that
/// a message quotes what was written (`1e400`), never what it became (`inf`).
///
/// The words `inf`, `infinity` and `nan` are passed on: each setting's check says whether it
/// takes them.
pub fn parse_f64(s: &str) -> std::result::Result<f64, String> {
    let v: f64 = s.trim().parse().map_err(|_| {
        format!(
            "{} is not a number{}",
            crate::error::cut(s),
            not_a_number_hint(s)
        )
    })?;
    match float_range_problem(s.trim(), v) {
        Some(problem) => Err(format!("{} {problem}", crate::error::cut(s))),
        None => Ok(v),
    }
}

/// What a number that does not parse may have meant: a range written with a dash (`0.12-0.3`:
/// ranges are LOW:HIGH) or a unit after the number (`40N`: each setting's unit is fixed by its
/// name and flag). Empty when neither.
fn not_a_number_hint(s: &str) -> String {
    let t = s.trim();
    let number_end = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == '+' || c == 'e'))
        .unwrap_or(t.len());
    let (number, rest) = t.split_at(number_end);
    if let Some((lo, hi)) = t.split_once('-').filter(|(lo, _)| !lo.is_empty())
        && lo.parse::<f64>().is_ok()
        && hi.parse::<f64>().is_ok()
    {
        return format!(" (a range is written LOW:HIGH: {lo}:{hi})");
    }
    if !rest.is_empty() && number.parse::<f64>().is_ok() && rest.chars().all(char::is_alphabetic) {
        return format!(
            " (the unit is fixed by the setting's name, as --help says: write {number}, not {t})"
        );
    }
    String::new()
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A count flag's value: a whole number written out; a negative, an exponent, a fraction
    /// and a number past the count's range each refused with what is wrong with it.
    #[test]
    fn a_count_is_a_whole_number_written_out() {
        assert_eq!(parse_count(" 100000 "), Ok(100_000));
        assert_eq!(parse_count_usize("0"), Ok(0));
        for bad in ["-1", "1e3", "2.5", "", "ten"] {
            let e = parse_count(bad).unwrap_err();
            assert!(e.contains("is not a whole number >= 0"), "{bad}: {e}");
            assert!(parse_count_usize(bad).is_err(), "{bad}");
        }
        let e = parse_count("99999999999999999999999").unwrap_err();
        assert!(
            e.contains("is more than a count can hold (18446744073709551615)"),
            "{e}"
        );
    }

    /// `path_is` answers as comparing with the built path does, for every declaration against
    /// every declaration's path and key, and against near misses: a section without its dot,
    /// a path cut short or run on, another section's key.
    #[test]
    fn a_path_is_recognised_without_building_it() {
        let decls: Vec<&Decl> = crate::settings::all().collect();
        let mut names: Vec<String> = Vec::new();
        for d in &decls {
            let path = d.path();
            names.extend([
                path.clone(),
                d.key.to_string(),
                format!("{}{}", d.section, d.key),
                format!("{path}x"),
                path[..path.len() - 1].to_string(),
                format!("x.{}", d.key),
                format!("{}.", d.section),
            ]);
        }
        let mut matched = 0;
        for d in &decls {
            for name in &names {
                assert_eq!(
                    d.path_is(name),
                    d.path() == *name,
                    "{} vs {name:?}",
                    d.path()
                );
                matched += usize::from(d.path_is(name));
            }
        }
        assert!(matched >= decls.len(), "{matched} of {}", decls.len());
    }

    /// The blockwise search finds the first value the check refuses, wherever it lies in its
    /// block, for every kind of check: the bounds themselves, just past them, NaN and the
    /// infinities.
    #[test]
    fn the_first_refused_value_is_found_blockwise() {
        let checks = [
            Check::Finite,
            Check::AtLeast(0.0),
            Check::Above(0.0),
            Check::Open(0.0, 180.0),
            Check::OpenClosed(0.0, 1.0),
            Check::Closed(-1.0, 1.0),
            Check::CloseOpen(0.0, 1.0),
            Check::CountAtLeast(2),
        ];
        let odd = [
            -1.0,
            0.0,
            -0.0,
            1.0,
            2.0,
            180.0,
            1.0 + f64::EPSILON,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for check in checks {
            let fine = [0.5, 0.75, 3.0]
                .into_iter()
                .find(|&v| check.accepts(v))
                .expect("a valid value");
            let mut refused = 0;
            for at in [0, 1, 4_095, 4_096, 4_097, 7_777, 9_999] {
                for &v in &odd {
                    let mut values = vec![fine; 10_000];
                    values[at] = v;
                    let want = values.iter().position(|&v| !check.accepts(v));
                    assert_eq!(check.first_refused(&values), want, "{check:?}: {v} at {at}");
                    refused += usize::from(want.is_some());
                }
            }
            assert!(refused > 0, "{check:?} refuses some of the odd values");
            assert_eq!(check.first_refused(&vec![fine; 1000]), None);
        }
        // Each bound as the check says it: in or out.
        assert!(Check::AtLeast(0.0).accepts(0.0) && !Check::Above(0.0).accepts(0.0));
        assert!(Check::Closed(-1.0, 1.0).accepts(1.0) && !Check::CloseOpen(0.0, 1.0).accepts(1.0));
        assert!(
            !Check::Open(0.0, 180.0).accepts(180.0) && Check::OpenClosed(0.0, 1.0).accepts(1.0)
        );
        assert!(!Check::Finite.accepts(f64::NAN) && !Check::AtLeast(0.0).accepts(f64::INFINITY));
    }

    /// The closed interval of two comparisons accepts what the check's words say, at every
    /// bound and the numbers either side of it, the zeros, the extremes and NaN: finite, and
    /// above (or at) the lower bound and below (or at) the upper.
    #[test]
    fn a_check_is_its_words_at_each_bound() {
        let checks = [
            Check::Finite,
            Check::Typed,
            Check::AtLeast(0.0),
            Check::Above(0.0),
            Check::Above(-f64::MAX),
            Check::Open(0.0, 180.0),
            Check::OpenClosed(0.0, 1.0),
            Check::Closed(-1.0, 1.0),
            Check::CloseOpen(0.0, 1.0),
            Check::CountAtLeast(2),
        ];
        let words = |check: Check, v: f64| {
            let (lo, with_lo, hi, with_hi) = check.limits();
            v.is_finite() && (v > lo || with_lo && v == lo) && (v < hi || with_hi && v == hi)
        };
        let mut values = vec![f64::NAN, 0.0, -0.0, 5e-324, -5e-324];
        for v in [-1.0, 1.0, 2.0, 180.0, f64::MAX, -f64::MAX, f64::INFINITY] {
            values.extend([
                v,
                -v,
                v.next_up(),
                v.next_down(),
                -v.next_up(),
                -v.next_down(),
            ]);
        }
        let mut refused = 0;
        for check in checks {
            for &v in &values {
                assert_eq!(check.accepts(v), words(check, v), "{check:?} of {v:e}");
                refused += usize::from(!check.accepts(v));
            }
        }
        assert!(refused > 0, "some values are refused");
    }
}
