//! TOML text to settings, with messages that name the key (with its section), quote the value
//! as written (cut to a readable length) and say what is expected.
//!
//! Three checks serde alone does not make:
//! - a number written beyond the range of f64 (`1e400`, `1e-400`) is refused as written, never
//!   read as `inf` or `0`;
//! - a wrong type names its key: the path comes from `serde_path_to_error`;
//! - a section or nested settings table given as an array (`scene = [1, 2]`) is refused: serde
//!   would fill the struct's fields in order. Found by serialising the result back and
//!   looking for arrays in the input where the settings have a table.

use std::ops::Range;
use std::path::Path;

use serde::Serialize;
use serde::de::DeserializeOwned;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

use crate::error::{Error, QUOTE_MAX_CHARS, Result, cut};
use crate::settings::decl::float_range_problem;

/// A hint where TOML refuses a value at byte `at` of `text` that is a range or a distribution
/// written without quotes (`mu = 0.12:0.3`, which TOML reads as a broken number): what to
/// write instead. Empty otherwise.
///
/// The hint quotes the line back, so it is given only where the line is that mistake: a bare
/// key and a value that reads as a range or a distribution. The file may be anything
/// (`--config .env`, `/proc/self/environ` as a scene's base), and a hint that echoed any line
/// printed a password and the environment.
fn unquoted_range_hint(text: &str, at: usize) -> String {
    let line_start = text[..at.min(text.len())].rfind('\n').map_or(0, |i| i + 1);
    let line = text[line_start..].lines().next().unwrap_or("");
    let Some((key, value)) = line.split_once('=') else {
        return String::new();
    };
    let (key, value) = (key.trim(), value.split('#').next().unwrap_or("").trim());
    let bare_key = !key.is_empty()
        && key.len() <= QUOTE_MAX_CHARS
        && key
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    let uncertain = value.len() <= QUOTE_MAX_CHARS
        && crate::uncertain::Uncertain::parse(value).is_ok_and(|u| u.is_uncertain());
    match bare_key && uncertain {
        true => format!(" (a range or a distribution is a string in a file: {key} = \"{value}\")"),
        false => String::new(),
    }
}

/// Parses TOML text into `T` (see the module doc); errors carry file, line and column.
pub fn parse_toml<T: DeserializeOwned + Serialize>(text: &str, path: &Path) -> Result<T> {
    let at = |span: Option<Range<usize>>, message: String| {
        let (line, column) = span.map_or((1, 1), |s| line_column(text, s.start));
        Error::Config {
            path: path.to_path_buf(),
            line,
            column,
            message: message.trim().replace('\n', " "),
        }
    };
    let mut doc = DeTable::parse(text).map_err(|e| {
        let hint = e
            .span()
            .map_or(String::new(), |s| unquoted_range_hint(text, s.start));
        at(e.span(), cut_quotes(e.message()) + &hint)
    })?;
    expand_aliases(doc.get_mut(), "");
    if let Some((key, span, problem)) = float_problems(doc.get_ref(), "") {
        return Err(at(
            Some(span.clone()),
            format!("{key} = {} {problem}", cut(&text[span])),
        ));
    }
    let mut input: toml::Value =
        toml::from_str(text).map_err(|e| at(e.span(), cut_quotes(e.message())))?;
    if let toml::Value::Table(t) = &mut input {
        crate::settings::expand_aliases("", t);
    }
    let value: T = serde_path_to_error::deserialize(toml::Deserializer::from(doc.clone()))
        .map_err(|e| {
            let key = e.path().to_string();
            let inner = e.into_inner();
            let span = inner.span();
            let key = match key.as_str() {
                "" | "." => span
                    .clone()
                    .and_then(|s| key_at(doc.get_ref(), s.start, "")),
                _ => Some(key),
            };
            if let Some(k) = key.as_deref().and_then(|k| seq_for_struct::<T>(&input, k)) {
                return at(span_of(doc.get_ref(), &k), not_a_table(&k));
            }
            let message = cut_quotes(inner.message());
            // A table's span is its header: quote values only. (Inside `[chart]`, an internally
            // tagged enum, serde keeps no path: the message alone names the key there.)
            let is_table = key.as_deref().is_some_and(|k| {
                k.split('.')
                    .try_fold(&input, |v, part| v.get(part))
                    .is_some_and(toml::Value::is_table)
            });
            let written = span
                .clone()
                .map(|s| text[s].trim().to_string())
                .filter(|w| Some(w.as_str()) != key.as_deref().and_then(|k| k.rsplit('.').next()))
                .filter(|_| !is_table);
            at(span, keyed(key.as_deref(), written.as_deref(), &message))
        })?;
    if let Some(key) = array_for_table(&input, &value, "") {
        return Err(at(span_of(doc.get_ref(), &key), not_a_table(&key)));
    }
    Ok(value)
}

/// A declared alias in `t` (at the dotted `section`) replaced by the keys it sets, each with the
/// alias' span (`[scene] mu = 0.3` sets mu_ground and mu_palm, a key given as well wins), as
/// [`crate::settings::expand_aliases`] does for tables without spans.
fn expand_aliases(t: &mut DeTable, section: &str) {
    for alias in crate::settings::all().filter(|d| d.section == section && !d.sets.is_empty()) {
        let Some(k) = t.keys().find(|k| k.get_ref() == alias.key).cloned() else {
            continue;
        };
        let v = t.remove(&k).expect("the key was just found");
        for set in alias.sets {
            if !t.keys().any(|k| k.get_ref() == set) {
                let key = Spanned::new(k.span(), std::borrow::Cow::Borrowed(*set));
                t.insert(key, v.clone());
            }
        }
    }
    for (k, v) in t.iter_mut() {
        if let DeValue::Table(inner) = v.get_mut() {
            let path = join(section, k.get_ref());
            expand_aliases(inner, &path);
        }
    }
}

/// `key = written: message`, or the parts of it that are known.
///
/// An unknown key that is a key of another section says where it belongs: a file written before
/// the dynamics settings were grouped by role (`[dynamics] stiffness_n_per_mm_e = ...`) is told
/// `dynamics.contact.stiffness_n_per_mm_e`.
pub fn keyed(key: Option<&str>, written: Option<&str>, message: &str) -> String {
    let moved = key
        .filter(|_| message.starts_with("unknown field"))
        .and_then(|k| {
            let (section, last) = k.rsplit_once('.').unwrap_or(("", k));
            crate::settings::moved(section, last)
        });
    let message = match moved {
        Some(place) => format!("unknown key here; it belongs in [{}]: {place}", {
            place.rsplit_once('.').map_or("", |(s, _)| s)
        }),
        None => in_our_words(key, message),
    };
    // A file's text is quoted only where it is a number or true/false (see
    // `Error::file_message`): a string, a list or a table may hold anything.
    let written = written.filter(|w| {
        toml::from_str::<toml::Table>(&format!("v = {w}")).is_ok_and(|t| {
            matches!(
                t.get("v"),
                Some(toml::Value::Integer(_) | toml::Value::Float(_) | toml::Value::Boolean(_))
            )
        })
    });
    if let Some(k) = key.filter(|k| !k.split('.').all(key_shaped)) {
        // Not a mistyped setting but the file's own text: an environment file's `API_TOKEN`
        // (`[API_TOKEN] x = 1` too). The section is named where it is a setting's form.
        let at = match k.rsplit_once('.') {
            Some((section, _)) if section.split('.').all(key_shaped) => {
                format!("{}.", cut(section))
            }
            _ => String::new(),
        };
        return format!(
            "{at}<key>: {message} (the key is not repeated: a setting's key is lowercase \
             letters, digits and _)"
        );
    }
    match (key, written) {
        (Some(k), Some(w)) => format!("{} = {}: {message}", cut(k), cut(w)),
        (Some(k), None) => format!("{}: {message}", cut(k)),
        _ => message.to_string(),
    }
}

/// Whether a file's key may be quoted in a message: every key of a scene is lowercase letters,
/// digits and `_` (`stiffness_n_per_mm_e`), so a typo of one is too; anything else, such as
/// `DATABASE_URL` from an environment file given as `--config`, is the file's text and may be
/// a secret's name.
fn key_shaped(k: &str) -> bool {
    (1..=64).contains(&k.len())
        && k.bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_')
}

/// serde's message said in the tool's words: "a number", not "f64"; "one of ...", with the
/// nearest where a key or a word is misspelt (`raduis_mm`: did you mean radius_mm?), and the
/// keys of a section with its aliases (`mu`), which serde does not list. A message serde did
/// not write is left as it is.
fn in_our_words(key: Option<&str>, message: &str) -> String {
    let ticked = |s: &str| -> Vec<String> {
        s.split('`')
            .skip(1)
            .step_by(2)
            .map(str::to_string)
            .collect()
    };
    if let Some(rest) = message.strip_prefix("unknown field ") {
        let mut words = ticked(rest);
        let given = match words.is_empty() {
            true => return message.to_string(),
            false => words.remove(0),
        };
        // The section's aliases set several keys at once: `[scene] mu` sets both frictions.
        let section = key.and_then(|k| k.rsplit_once('.')).map_or("", |(s, _)| s);
        let aliases = crate::settings::all()
            .filter(|d| d.section == section && !d.sets.is_empty())
            .map(|d| d.key.to_string());
        let mut known: Vec<String> = aliases.chain(words).collect();
        known.dedup();
        let nearest = crate::ask::nearest(&given, known.iter().map(String::as_str));
        let mean = nearest.map_or(".".to_string(), |n| format!("; did you mean {n}?"));
        return match known.is_empty() {
            true => format!("unknown key{}", mean.trim_end_matches('.')),
            false => format!("unknown key{mean} The keys here: {}", known.join(", ")),
        };
    }
    if let Some(rest) = message.strip_prefix("unknown variant ") {
        let mut words = ticked(rest);
        if words.is_empty() {
            return message.to_string();
        }
        let given = words.remove(0);
        let nearest = crate::ask::nearest(&given, words.iter().map(String::as_str));
        let mean = nearest.map_or(".".to_string(), |n| format!("; did you mean {n}?"));
        // The word itself is not quoted: a file's text may be anything (see `keyed`).
        return format!("not one of {}{mean}", words.join(", "));
    }
    if let Some(rest) = message.strip_prefix("missing field ") {
        let field = rest.trim_matches('`');
        return format!("{field} is missing: a required key");
    }
    if let Some(rest) = message.strip_prefix("invalid type: ") {
        let Some((found, expected)) = rest.rsplit_once(", expected ") else {
            return message.to_string();
        };
        return format!(
            "expected {}, found {}",
            wanted(expected),
            found_words(found)
        );
    }
    if let Some(rest) = message.strip_prefix("invalid value: ")
        && let Some((found, expected)) = rest.rsplit_once(", expected ")
    {
        return format!(
            "expected {}, found {}",
            wanted(expected),
            found_words(found)
        );
    }
    message.to_string()
}

/// What serde expected, in the tool's words.
fn wanted(expected: &str) -> String {
    match expected.trim() {
        "f64" | "f32" | "a f64" | "a float" => "a number".into(),
        "u8" | "u16" | "u32" | "u64" | "usize" | "i32" | "i64" | "an integer" => {
            "a whole number".into()
        }
        "a boolean" | "bool" => "true or false".into(),
        "a sequence" => "a list [...]".into(),
        "a map" | "struct" => "a table".into(),
        e if e.starts_with("struct ") || e.starts_with("a map") => "a table".into(),
        e => e.to_string(),
    }
}

/// What serde found, in the tool's words: `string "ten"` is the string "ten".
fn found_words(found: &str) -> String {
    let found = found.trim();
    let value = |prefix: &str| found.strip_prefix(prefix).map(|v| v.trim_matches('`'));
    // The text itself is not quoted: it may be anything (see `keyed`).
    if value("string ").is_some() {
        return "text".into();
    }
    if let Some(v) = value("integer ").or_else(|| value("floating point ")) {
        return format!("the number {v}");
    }
    if let Some(v) = value("boolean ") {
        return v.to_string();
    }
    match found {
        "sequence" => "a list".into(),
        "map" => "a table".into(),
        f => f.to_string(),
    }
}

/// The refusal of an array where settings have a table; the array is not quoted, it may hold
/// anything (see `keyed`).
pub fn not_a_table(key: &str) -> String {
    format!(
        "{key}: expected a table ([{key}] with one key per line, or {key} = {{ ... }}), found \
         an array"
    )
}

/// Where serde failed inside an array that stands for a table: the dotted key of that array.
///
/// serde fills a struct's fields in order from an array (`qp = [1, 2]` fails only because 1
/// is not a bool). Put an empty table in the array's place: if `T` then reads past that key,
/// the key wanted a table; a key that wants an array fails at the key itself.
pub fn seq_for_struct<T: DeserializeOwned>(input: &toml::Value, err_path: &str) -> Option<String> {
    let key = err_path.split_once('[').map_or(err_path, |(k, _)| k);
    let mut probe = input.clone();
    let mut slot = &mut probe;
    for part in key.split('.') {
        slot = slot.as_table_mut()?.get_mut(part)?;
    }
    if !slot.is_array() {
        return None;
    }
    *slot = toml::Value::Table(toml::Table::new());
    match serde_path_to_error::deserialize::<_, T>(probe) {
        Ok(_) => Some(key.to_string()),
        // A key that wants an array refuses the table at the key itself, and so does a key
        // that is not known at all.
        Err(e) => {
            let message = e.inner().to_string();
            let refused_here = e.path().to_string() == key
                && (message.contains("invalid type: map") || message.contains("unknown field"));
            (!refused_here).then(|| key.to_string())
        }
    }
}

/// The dotted path of the first array in `input` where `value`, serialised, has a table.
pub fn array_for_table<T: Serialize>(
    input: &toml::Value,
    value: &T,
    prefix: &str,
) -> Option<String> {
    let back = toml::Value::try_from(value).ok()?;
    first_array_for_table(input, &back, prefix)
}

fn first_array_for_table(input: &toml::Value, back: &toml::Value, prefix: &str) -> Option<String> {
    match (input, back) {
        (toml::Value::Array(_), toml::Value::Table(_)) => Some(prefix.to_string()),
        (toml::Value::Table(i), toml::Value::Table(b)) => i.iter().find_map(|(k, v)| {
            b.get(k)
                .and_then(|bv| first_array_for_table(v, bv, &join(prefix, k)))
        }),
        (toml::Value::Array(i), toml::Value::Array(b)) => i
            .iter()
            .zip(b)
            .enumerate()
            .find_map(|(n, (iv, bv))| first_array_for_table(iv, bv, &format!("{prefix}[{n}]"))),
        _ => None,
    }
}

/// The first float written beyond f64's range: its dotted key, span and what is wrong.
fn float_problems(t: &DeTable, prefix: &str) -> Option<(String, Range<usize>, &'static str)> {
    t.iter().find_map(|(k, v)| {
        let key = join(prefix, k.get_ref());
        value_float_problem(v, key)
    })
}

fn value_float_problem(
    v: &Spanned<DeValue>,
    key: String,
) -> Option<(String, Range<usize>, &'static str)> {
    match v.get_ref() {
        DeValue::Float(f) => {
            let raw = f.as_str().replace('_', "");
            let x: f64 = raw.parse().ok()?;
            float_range_problem(&raw, x).map(|p| (key, v.span(), p))
        }
        DeValue::Table(t) => float_problems(t, &key),
        DeValue::Array(a) => a
            .iter()
            .enumerate()
            .find_map(|(n, e)| value_float_problem(e, format!("{key}[{n}]"))),
        _ => None,
    }
}

fn join(prefix: &str, k: &str) -> String {
    if prefix.is_empty() {
        k.to_string()
    } else {
        format!("{prefix}.{k}")
    }
}

/// The dotted key whose key or value spans byte `offset`, innermost.
fn key_at(t: &DeTable, offset: usize, prefix: &str) -> Option<String> {
    t.iter().find_map(|(k, v)| {
        let key = join(prefix, k.get_ref());
        if k.span().contains(&offset) {
            return Some(key);
        }
        if !v.span().contains(&offset) {
            return None;
        }
        match v.get_ref() {
            DeValue::Table(inner) => key_at(inner, offset, &key).or(Some(key)),
            _ => Some(key),
        }
    })
}

/// The span of the value at a dotted key (array indices are not followed).
fn span_of(t: &DeTable, key: &str) -> Option<Range<usize>> {
    let (head, rest) = match key.split_once('.') {
        Some((h, r)) => (h, Some(r)),
        None => (key, None),
    };
    let (_, v) = t.iter().find(|(k, _)| k.get_ref() == head)?;
    match (rest, v.get_ref()) {
        (None, _) => Some(v.span()),
        (Some(r), DeValue::Table(inner)) => span_of(inner, r).or(Some(v.span())),
        (Some(_), _) => Some(v.span()),
    }
}

/// Quoted parts of a parser's message (`"..."`, `` `...` ``) cut to a readable length, and
/// toml's "wanted string or table" (an enum) said as what is expected.
pub fn cut_quotes(message: &str) -> String {
    let message = message
        .trim()
        .replace('\n', " ")
        .replace("wanted string or table", "expected a string or a table");
    let mut out = String::new();
    let mut rest = message.as_str();
    while let Some(start) = rest.find(['"', '`']) {
        let q = &rest[start..start + 1];
        out.push_str(&rest[..=start]);
        let after = &rest[start + 1..];
        match after.find(q) {
            Some(end) => {
                out.push_str(&cut(&after[..end]));
                out.push_str(q);
                rest = &after[end + 1..];
            }
            None => {
                out.push_str(&cut(after));
                return out;
            }
        }
    }
    out.push_str(rest);
    out
}

/// 1-based line and column of the value at dotted `key` in TOML `text` (of its table's header
/// when the key is not written there); None when the text does not parse.
pub fn key_line_column(text: &str, key: &str) -> Option<(usize, usize)> {
    let doc = DeTable::parse(text).ok()?;
    span_of(doc.get_ref(), key).map(|s| line_column(text, s.start))
}

/// 1-based line and column of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `mu = 0.12:0.3` unquoted said only "invalid float, expected nothing".
    #[test]
    fn an_unquoted_range_in_a_file_says_to_quote_it() {
        let e = parse_toml::<toml::Table>("[scene]\nmu = 0.12:0.3\n", Path::new("s.toml"))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("s.toml:2:") && e.contains("mu = \"0.12:0.3\""),
            "{e}"
        );
        let e = parse_toml::<toml::Table>("mu = normal(0.2,0.03)\n", Path::new("s.toml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("mu = \"normal(0.2,0.03)\""), "{e}");
        assert_eq!(unquoted_range_hint("mu = 0.2x\n", 5), "");
    }

    /// The hint quoted the refused line back whatever it held: `--config .env` printed a
    /// database password, `/proc/self/environ` as a config or a scene's base the whole
    /// environment. Only a line that is the mistake it names (a bare key and a range or a
    /// distribution) is quoted; every other message names the file, line and column alone.
    #[test]
    fn a_file_that_is_not_toml_is_never_quoted() {
        let secret = "s3cr3t-Pa55";
        for text in [
            format!("DATABASE_URL=postgres://admin:{secret}@db:5432/app\nDEBUG=1\n"),
            format!("SHELL=/bin/bash\0PASSWORD={secret}\0HOME=/root\0"),
            format!("[scene]\nmu = 0.1:{secret}\n"),
            format!("[scene]\nmu = normal({secret})\n"),
            format!("key with spaces = 0.1:0.3 {secret}\n"),
            format!("TOKEN = {secret}:0.3\n"),
        ] {
            let e = parse_toml::<toml::Table>(&text, Path::new(".env"))
                .unwrap_err()
                .to_string();
            assert!(e.starts_with(".env:"), "{e}");
            assert!(!e.contains(secret) && !e.contains("admin"), "{e}");
            assert!(!e.contains("a range or a distribution"), "{e}");
        }
    }
}
