//! A scene's title naming its values: `{mu}`, `{radius_mm}` or `{chart.load_n}` in a title
//! stand for the value the chart is drawn with, so that a title follows `--set` (and a
//! `--read-off`) instead of contradicting the subtitle under it.
//!
//! `{KEY}` is any `[scene]` key (`mu` for both frictions: one value, or each friction's
//! named), as the user gave it: `0.3`, `normal(0.21,0.03)`, a range as `0.12 to 0.3`;
//! `{chart.KEY}` (dotted for a key inside a table, `{chart.locator.mass_kg}`) is a `[chart]`
//! key as written after `--set`, a range as a scene key's. `{{` and `}}` write a brace.
//!
//! The `[chart]` keys are filled when the scene is read ([`fill_chart_keys`]), the `[scene]`
//! keys whenever its values may have changed ([`fill_scene_keys`]), from the values and
//! uncertain inputs the chart is drawn with.

use crate::error::{Error, Result};
use crate::scene::SceneParams;
use crate::uncertain::{Uncertain, UncertainSet};

/// What a title says about a key it names that the chart has not.
const HOW: &str = "a title names a [scene] key in braces ({mu}, {radius_mm}, ...) or a \
                   [chart] key ({chart.load_n}), and writes a brace as {{ or }}";

/// An uncertain value as a title says it: a range `0.12 to 0.3`, anything else as written.
fn said(u: Uncertain) -> String {
    match u {
        Uncertain::Range { lo, hi } => {
            let t = crate::settings::number_text;
            format!("{} to {}", t(lo), t(hi))
        }
        other => other.to_string(),
    }
}

/// One piece of a title: text, or a key in braces.
enum Piece<'a> {
    Text(&'a str),
    Key(&'a str),
}

/// The pieces of `title`, braces doubled as text; an unmatched brace is an error.
fn pieces(title: &str) -> Result<Vec<Piece<'_>>> {
    let unmatched = || {
        Error::invalid(
            "title",
            format!("\"{title}\""),
            format!("has an unmatched brace; {HOW}"),
        )
    };
    let mut out = Vec::new();
    let mut rest = title;
    while let Some(i) = rest.find(['{', '}']) {
        out.push(Piece::Text(&rest[..i]));
        let (brace, after) = rest[i..].split_at(1);
        if after.starts_with(brace) {
            out.push(Piece::Text(brace));
            rest = &after[1..];
        } else if brace == "{" {
            let end = after.find('}').ok_or_else(unmatched)?;
            out.push(Piece::Key(after[..end].trim()));
            rest = &after[end + 1..];
        } else {
            return Err(unmatched());
        }
    }
    out.push(Piece::Text(rest));
    Ok(out)
}

/// `title` with each `{KEY}` that `value` knows replaced by its text; `keep` says whether
/// an unknown key and the doubled braces stay for a later fill (true) or are an error and
/// single braces (false).
fn fill(title: &str, value: impl Fn(&str) -> Option<String>, keep: bool) -> Result<String> {
    let mut out = String::with_capacity(title.len());
    for piece in pieces(title)? {
        match piece {
            Piece::Text(t) if keep && (t == "{" || t == "}") => {
                out.push_str(t);
                out.push_str(t);
            }
            Piece::Text(t) => out.push_str(t),
            Piece::Key(k) => match value(k) {
                Some(v) => out.push_str(&v),
                None if keep => out.push_str(&format!("{{{k}}}")),
                None => {
                    return Err(Error::invalid(
                        "title",
                        format!("\"{title}\""),
                        format!("{{{k}}} names no key of the scene; {HOW}"),
                    ));
                }
            },
        }
    }
    Ok(out)
}

/// `title` with its `{chart.KEY}`s replaced by `chart`'s values as written (after `--set`);
/// the other keys and doubled braces stay for [`fill_scene_keys`].
pub(super) fn fill_chart_keys(title: &str, chart: &toml::Table) -> Result<String> {
    let value = |key: &str| {
        let path = key.strip_prefix("chart.")?;
        let (first, rest) = path.split_once('.').unwrap_or((path, ""));
        let mut v = chart.get(first)?;
        for part in rest.split('.').filter(|p| !p.is_empty()) {
            v = v.as_table()?.get(part)?;
        }
        // A number as short as it reads back: `20`, not `20.0`.
        Some(match v {
            toml::Value::String(s) => Uncertain::parse(s).map_or_else(|_| s.clone(), said),
            toml::Value::Float(f) => crate::settings::number_text(*f),
            other => other.to_string(),
        })
    };
    fill(title, value, true)
}

/// `title` with its `[scene]` keys replaced by the values the chart is drawn with: an
/// uncertain input as written, a single value as short as it reads back.
pub(super) fn fill_scene_keys(
    title: &str,
    params: &SceneParams,
    uncertain: &UncertainSet,
) -> Result<String> {
    let one = |key: &str| -> Option<String> {
        let input = uncertain.inputs.iter().find(|i| i.keys.contains(&key));
        match input {
            Some(i) => Some(said(i.value)),
            None => params.real(key).map(crate::settings::number_text),
        }
    };
    let value = |key: &str| {
        let decl = crate::config::scene_decls().find(|d| d.key == key)?;
        match decl.sets {
            [] => one(key),
            sets => {
                let each: Vec<(&str, String)> = sets
                    .iter()
                    .map(|k| Some((*k, one(k)?)))
                    .collect::<Option<_>>()?;
                match each.windows(2).all(|w| w[0].1 == w[1].1) {
                    true => each.first().map(|(_, v)| v.clone()),
                    false => Some(
                        (each.iter())
                            .map(|(k, v)| format!("{v} ({})", k.rsplit('_').next().unwrap_or(k)))
                            .collect::<Vec<_>>()
                            .join(", "),
                    ),
                }
            }
        }
    };
    fill(title, value, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shaft() -> SceneParams {
        crate::uncertain::shaft::shaft_25mm()
    }

    /// The uncertain inputs of a `[scene]` table written as TOML.
    fn inputs(scene: &str) -> UncertainSet {
        let mut table: toml::Table = toml::from_str(scene).unwrap();
        crate::uncertain::take(&mut table, crate::config::scene_decls()).unwrap()
    }

    #[test]
    fn scene_keys_name_the_values_drawn_and_braces_double() {
        let p = shaft();
        let t = "r = {radius_mm} mm, μ {mu} {{sic}}";
        assert_eq!(
            fill_scene_keys(t, &p, &inputs("mu = \"normal(0.21,0.03)\"")).unwrap(),
            "r = 12.5 mm, μ normal(0.21,0.03) {sic}"
        );
        assert_eq!(
            fill_scene_keys("μ {mu}", &p.with_mu(0.3), &inputs("mu_palm = \"0.2:0.4\"")).unwrap(),
            "μ 0.3 (ground), 0.2 to 0.4 (palm)"
        );
    }

    #[test]
    fn an_unknown_key_or_a_lone_brace_is_refused_saying_how_to_write_one() {
        let p = shaft();
        for (t, says) in [
            ("r = {radious_mm}", "{radious_mm} names no key"),
            ("a { b", "unmatched brace"),
            ("a } b", "unmatched brace"),
        ] {
            let msg = fill_scene_keys(t, &p, &UncertainSet::default())
                .unwrap_err()
                .to_string();
            assert!(msg.contains(says) && msg.contains("{{ or }}"), "{msg}");
        }
    }

    #[test]
    fn chart_keys_are_filled_first_and_leave_the_rest() {
        let chart: toml::Table =
            toml::from_str("mu = \"0.1:0.25\"\nload_n = 20.0\nlocator = { mass_kg = 0.4 }\n")
                .unwrap();
        let t = "μ {chart.mu}, {chart.load_n} N, {chart.locator.mass_kg} kg, r {radius_mm} {{}}";
        let filled = fill_chart_keys(t, &chart).unwrap();
        assert_eq!(filled, "μ 0.1 to 0.25, 20 N, 0.4 kg, r {radius_mm} {{}}");
        let done = fill_scene_keys(&filled, &shaft(), &UncertainSet::default()).unwrap();
        assert_eq!(done, "μ 0.1 to 0.25, 20 N, 0.4 kg, r 12.5 {}");
        let msg = fill_scene_keys("{chart.nope}", &shaft(), &UncertainSet::default())
            .unwrap_err()
            .to_string();
        assert!(msg.contains("{chart.nope} names no key"), "{msg}");
    }
}
