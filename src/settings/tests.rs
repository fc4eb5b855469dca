use std::collections::HashSet;

use super::*;
use crate::config::Config;

/// A bare key names one setting (`--set KEY=...`, the key-to-flag map in errors), so keys are
/// unique across the family's sections, and so are flags.
#[test]
fn keys_and_flags_are_unique_across_sections() {
    let mut keys = HashSet::new();
    let mut flags = HashSet::new();
    for d in palm_family() {
        assert!(keys.insert(d.key), "key {} declared twice", d.key);
        if let Some(f) = d.flag {
            assert!(flags.insert(f), "flag --{f} declared twice");
        }
        assert!(!d.summary().is_empty(), "{} has no doc", d.key);
    }
}

/// Every declared key is a key of the parameter file, at its section: the declaration and the
/// struct's serde keys are one list (the macro makes both), checked here through the file.
#[test]
fn every_declaration_is_a_key_of_its_section_and_back() {
    let table = toml::Table::try_from(Config::default()).unwrap();
    let mut written = Vec::new();
    fn walk(t: &toml::Table, prefix: &str, out: &mut Vec<String>) {
        for (k, v) in t {
            let path = if prefix.is_empty() {
                k.clone()
            } else {
                format!("{prefix}.{k}")
            };
            match v {
                toml::Value::Table(inner) => walk(inner, &path, out),
                _ => out.push(path),
            }
        }
    }
    walk(&table, "", &mut written);
    for d in palm_family().filter(|d| d.sets.is_empty()) {
        let path = format!("{}.{}", d.section, d.key);
        // Optional keys left unset are not written.
        let optional = matches!(d.kind, Kind::OptionalReal);
        assert!(
            optional || written.contains(&path),
            "{path} is declared but not a key of the file"
        );
    }
    for path in &written {
        let key = path.rsplit('.').next().unwrap();
        assert!(find(key).is_some(), "{path} is written but not declared");
    }
    for d in palm_family().filter(|d| !d.sets.is_empty()) {
        for k in d.sets {
            let target = find(k).unwrap_or_else(|| panic!("alias {} sets unknown {k}", d.key));
            assert_eq!(target.section, d.section, "alias {} sets {k}", d.key);
        }
    }
}

/// Every default the docs give is the code's: each declaration's default text parses back to
/// the value `Default` holds.
#[test]
fn every_documented_default_is_the_defaults_value() {
    let table = toml::Table::try_from(Config::default()).unwrap();
    for d in palm_family().filter(|d| d.sets.is_empty()) {
        let text = d.default_text();
        let mut t = &table;
        for part in d.section.split('.') {
            t = t[part].as_table().unwrap();
        }
        match t.get(d.key) {
            None => assert!(text.is_empty(), "{}: unset default shows {text}", d.key),
            Some(v) => {
                let parsed: toml::Value = toml::from_str::<toml::Table>(&format!("v = {text}"))
                    .map(|mut t| t.remove("v").unwrap())
                    .unwrap_or_else(|_| toml::Value::String(text.clone()));
                let same = match (v, &parsed) {
                    (toml::Value::Float(a), toml::Value::Float(b)) => a == b,
                    (toml::Value::Float(a), toml::Value::Integer(b)) => *a == *b as f64,
                    _ => v == &parsed,
                };
                assert!(same, "{}: docs say {text}, Default holds {v}", d.key);
            }
        }
    }
}

/// The guide's parameter table and charts/README.md's list of `[scene]` keys are the
/// declarations': `jamchart settings` prints the reference, and the guide holds it verbatim.
/// When this fails, paste `jamchart settings` into src/guide.md's "Every setting" section.
#[test]
fn the_guide_holds_the_reference_table() {
    let readme = include_str!("../guide.md");
    let table = reference_table();
    let locator = reference_rows(|s| s == "locator");
    assert!(
        readme.contains(&locator),
        "src/guide.md's V-locator settings table is not `jamchart settings`' second table:\n{locator}"
    );
    assert!(
        readme.contains(&table),
        "src/guide.md's settings table is not `jamchart settings`' output:\n{table}"
    );
}

/// charts/README.md's `[scene]` table is the declarations' too. When this fails, paste the
/// `[scene]` rows of `jamchart settings` there.
#[test]
fn the_charts_readme_holds_the_scene_keys() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/charts/README.md"))
        .expect("charts/README.md");
    let table = reference_rows(|s| s == "scene");
    assert!(
        readme.contains(&table),
        "charts/README.md's [scene] table is not the declarations':\n{table}"
    );
}

/// Each flag's help shows its default and unit, in both registers.
#[test]
fn every_flag_help_gives_its_default_and_unit() {
    let cmd = crate::cli::command();
    let solve = cmd.find_subcommand("solve").unwrap();
    for d in palm_family().filter(|d| d.flag.is_some()) {
        let arg = solve
            .get_arguments()
            .find(|a| a.get_id() == d.key)
            .unwrap_or_else(|| panic!("solve has no flag for {}", d.key));
        let short = arg.get_help().unwrap().to_string();
        let default = d.default_text();
        if !default.is_empty() && d.kind != Kind::Switch {
            assert!(short.contains(&format!("[default: {default}")), "{short}");
        }
        if !matches!(d.unit, "" | "-") {
            assert!(short.contains(d.unit), "{}: {short}", d.key);
        }
    }
}

/// The proof of one declaration: a scene parameter declared in `SceneParams` is a flag of
/// `solve`, a `--set` key, a grid axis with its label, a row of the reference and range-checked,
/// with no other edit. Shown with the palm's offset.
#[test]
fn a_declared_scene_parameter_is_a_flag_a_key_an_axis_and_checked() {
    use crate::scene::Param;
    let decl = find("palm_offset_mm").unwrap();
    assert_eq!(flag_for("palm_offset_mm").as_deref(), Some("--palm-offset"));
    let axis = Param::named("palm_offset_mm").unwrap();
    assert_eq!(
        crate::charts::axis_label(axis),
        "palm offset h (mm)",
        "{decl:?}"
    );
    assert!(reference_table().contains("`--palm-offset` | `palm_offset_mm` | mm | 0 |"));
    let p = crate::scene::SceneParams {
        palm_offset_mm: -1.0,
        ..Default::default()
    };
    let msg = p.validate().unwrap_err().to_string();
    assert!(
        msg.contains("palm_offset_mm = -1") && msg.contains(">= 0"),
        "{msg}"
    );
}

/// `--mu 0.12-0.3` and `--force 40N` said only "is not a number": they say what was meant.
#[test]
fn a_number_that_does_not_parse_says_what_was_probably_meant() {
    use crate::settings::decl::parse_f64;
    let range = parse_f64("0.12-0.3").unwrap_err();
    assert!(
        range.contains("a range is written LOW:HIGH: 0.12:0.3"),
        "{range}"
    );
    let unit = parse_f64("40N").unwrap_err();
    assert!(unit.contains("write 40, not 40N"), "{unit}");
    assert_eq!(parse_f64("abc").unwrap_err(), "abc is not a number");
    assert_eq!(parse_f64("-0.5"), Ok(-0.5));
    assert_eq!(parse_f64("1e-3"), Ok(1e-3));
}

/// `--mu 2.5` warned twice, once per contact: equal frictions are one warning.
#[test]
fn equal_frictions_above_two_warn_once() {
    let p = crate::scene::SceneParams::default().with_mu(2.5);
    let w = p.unit_warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].starts_with("mu_ground and mu_palm are both 2.5"),
        "{w:?}"
    );
    let p = crate::scene::SceneParams { mu_palm: 3.0, ..p };
    assert_eq!(p.unit_warnings().len(), 2);
}

/// A message's key that is a quantity of several settings names each one's flags, once each;
/// a key with words that are no setting (`force_n of case barely_moves`: a stability case
/// derives it) names none, nor does a flag the command does not take.
#[test]
fn a_quantity_of_several_settings_names_each_ones_flags() {
    let none = std::iter::empty;
    let naming = |key: &str| flags_naming(key, none(), |_| true);
    assert_eq!(
        naming("load_n + mass_kg * gravity_m_s2").as_deref(),
        Some("--load, --mass and --gravity")
    );
    assert_eq!(naming("force_n of case barely_moves"), None);
    assert_eq!(flags_naming("radius_mm", none(), |f| f != "radius"), None);
}

/// A mass typed in grams (400 for 0.4 kg) and a palm typed in cm (8 for 80 mm) on a 12.5 mm part
/// are valid numbers, but each draws a warning naming the unit; the paper's scene draws none.
#[test]
fn mass_in_grams_and_palm_in_cm_warn() {
    let paper = crate::scene::SceneParams::default();
    assert!(
        paper.unit_warnings().is_empty(),
        "{:?}",
        paper.unit_warnings()
    );
    let part = crate::scene::SceneParams {
        radius_mm: 12.5,
        mass_kg: 0.4,
        palm_length_mm: 80.0,
        ..paper
    };
    assert!(
        part.unit_warnings().is_empty(),
        "{:?}",
        part.unit_warnings()
    );
    let grams = crate::scene::SceneParams {
        mass_kg: 400.0,
        ..part
    };
    let w = grams.unit_warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].starts_with("mass_kg (--mass) = 400 kg weighs as much as a steel bar"),
        "{w:?}"
    );
    assert!(
        w[0].contains("103.8 m long") && w[0].ends_with("not grams"),
        "{w:?}"
    );
    let cm = crate::scene::SceneParams {
        palm_length_mm: 8.0,
        ..part
    };
    let w = cm.unit_warnings();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("= 8 mm is shorter than the disc's radius (12.5 mm)"),
        "{w:?}"
    );
}
