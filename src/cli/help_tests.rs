//! Help texts against the code (issue 22): every documented default is the code's `Default`,
//! every scene a help text names exists, and `vlocator --help` describes the JSON it prints.

use clap::{CommandFactory, Parser};

use super::{Cli, Command};
use crate::config::Config;
use crate::locator::LocatorParams;

/// The required arguments of a subcommand, so that one flag can be added to a valid call.
fn call(sub: &str) -> Vec<String> {
    let mut v = vec!["jamchart".to_string(), sub.to_string()];
    if sub == "sweep" {
        v.push("mu=0.1:0.5".into());
    }
    // design's one required flag.
    if sub == "design" {
        v.push("--x-target=40".into());
    }
    v
}

/// Defaults written in words, where no value is meant (the flag is then simply left out).
const WORDS: [(&str, &str, &str); 2] = [
    ("stability", "cases", "every case"),
    ("sweep", "name", "sweep_PARAM or map_PARAM_PARAM"),
];

/// Every `[default: X]` of a help text.
fn documented(help: &str) -> Vec<String> {
    help.split("[default: ")
        .skip(1)
        .filter_map(|rest| rest.split_once(']').map(|(d, _)| d.trim().to_string()))
        .collect()
}

/// `v` as a float, if it is a number.
fn number(v: &toml::Value) -> Option<f64> {
    v.as_float().or_else(|| v.as_integer().map(|i| i as f64))
}

/// The value of `key` in section `section` (dotted) of `table`.
fn lookup<'a>(table: &'a toml::Table, section: &str, key: &str) -> Option<&'a toml::Value> {
    let mut t = table;
    for part in section.split('.') {
        t = t.get(part)?.as_table()?;
    }
    t.get(key)
}

/// The code's default of a declared setting's flag against the text its help documents.
fn check_declared(sub: &str, long: &str, text: &str) -> Option<Result<(), String>> {
    let in_locator = sub == "vlocator";
    let decl = crate::settings::all()
        .find(|d| d.flag == Some(long) && (d.section == "locator") == in_locator)?;
    let defaults: toml::Table = if in_locator {
        toml::Table::try_from(LocatorParams::default()).expect("serialises")
    } else {
        toml::Table::try_from(Config::default()).expect("serialises")
    };
    let value = text
        .strip_suffix(decl.unit)
        .filter(|_| !decl.unit.is_empty())
        .unwrap_or(text)
        .trim();
    let keys: Vec<&str> = if decl.sets.is_empty() {
        vec![decl.key]
    } else {
        decl.sets.to_vec()
    };
    let section = if in_locator { "" } else { decl.section };
    for key in keys {
        let code = if section.is_empty() {
            defaults.get(key)
        } else {
            lookup(&defaults, section, key)
        };
        let Some(code) = code else {
            return Some(Err(format!("no default for {section}.{key}")));
        };
        let same = match (number(code), value.parse::<f64>()) {
            (Some(c), Ok(v)) => (c - v).abs() <= 1e-12 * c.abs().max(1.0),
            _ => code.as_str().map_or(code.to_string(), String::from) == value,
        };
        if !same {
            return Some(Err(format!(
                "documents {value:?}, the code's Default has {key} = {code}"
            )));
        }
    }
    Some(Ok(()))
}

/// `vlocator`'s geometry flags: the documented default gives the default V.
fn check_vlocator_geometry(long: &str, value: &str) -> Result<(), String> {
    let value = value.strip_suffix(" deg").unwrap_or(value);
    let cli = Cli::try_parse_from(["jamchart", "vlocator", &format!("--{long}"), value])
        .map_err(|e| e.to_string())?;
    let Command::Vlocator(a) = cli.command else {
        return Err("not vlocator".into());
    };
    let (p, _) = a.params_uncertain().map_err(|e| e.to_string())?;
    if p == LocatorParams::default() {
        Ok(())
    } else {
        Err(format!("gives {p:?}, not the default V"))
    }
}

/// Help texts said `[default: ..]` by hand beside the code's `Default`, and could drift from it
/// (`solve -h` once dropped the `--mu` default; the accuracy report's flags were hand-written).
/// Every default a help text documents is checked against the code: a declared setting's
/// against the serialised `Default` of its struct, a clap default by parsing it, vlocator's
/// geometry by the V it gives; any other hand-written default fails here.
#[test]
fn documented_defaults_are_the_code_defaults() {
    let cmd = Cli::command();
    let mut checked = 0;
    let mut problems = Vec::new();
    for sub in cmd.get_subcommands() {
        let name = sub.get_name();
        for arg in sub.get_arguments() {
            let Some(long) = arg.get_long() else { continue };
            let id = arg.get_id().as_str();
            let help = [arg.get_help(), arg.get_long_help()]
                .iter()
                .flatten()
                .map(|h| h.to_string())
                .collect::<Vec<_>>()
                .join("\n");
            for text in documented(&help) {
                checked += 1;
                let verdict = if WORDS.contains(&(name, id, text.as_str())) {
                    Ok(())
                } else if let Some(v) = check_declared(name, long, &text) {
                    v
                } else if name == "vlocator" && matches!(long, "included-angle" | "flank-angles") {
                    check_vlocator_geometry(long, &text)
                } else {
                    Err("a hand-written default: derive it from the code's Default".into())
                };
                if let Err(why) = verdict {
                    problems.push(format!("{name} --{long} [default: {text}]: {why}"));
                }
            }
            // clap's own defaults (made from the code, e.g. the accuracy report's): they parse.
            let defaults: Vec<String> = arg
                .get_default_values()
                .iter()
                .map(|v| v.to_string_lossy().into_owned())
                .collect();
            if !defaults.is_empty() && arg.get_action().takes_values() {
                checked += 1;
                let mut argv = call(name);
                argv.push(format!("--{long}={}", defaults.join(",")));
                if let Err(e) = Cli::try_parse_from(&argv) {
                    problems.push(format!("{name} --{long}: default does not parse: {e}"));
                }
            }
        }
    }
    assert!(
        checked > 60,
        "only {checked} defaults found: is the parsing right?"
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// `solve -h` (the short help) shows the `--mu` default.
#[test]
fn solve_short_help_shows_the_mu_default() {
    let mut cmd = Cli::command();
    let help = cmd
        .find_subcommand_mut("solve")
        .expect("solve")
        .render_help()
        .to_string();
    let flat = help.split_whitespace().collect::<Vec<_>>().join(" ");
    let mu = flat
        .split("--mu <MU>")
        .nth(1)
        .and_then(|r| r.split("--mu-ground").next())
        .expect("--mu in solve -h");
    assert!(mu.contains("[default: 0.4]"), "--mu <MU>{mu}");
}

/// `stability --help` named the scene `stability`, which does not exist (it is
/// `stability-matrix`): every scene a help text names is a built-in scene.
#[test]
fn every_scene_named_in_help_exists() {
    let scenes = crate::charts::builtin::scene_names();
    let mut cmd = Cli::command();
    let mut named = 0;
    for sub in cmd.get_subcommands_mut() {
        let help = sub.render_long_help().to_string();
        let flat = help.split_whitespace().collect::<Vec<_>>().join(" ");
        for rest in flat.split("the scene `").skip(1) {
            let name = rest.split('`').next().unwrap_or("");
            named += 1;
            assert!(
                scenes.iter().any(|s| s == name),
                "{} --help names the scene {name:?}; the scenes are {scenes:?}",
                sub.get_name()
            );
        }
    }
    assert!(named >= 1, "no scene named in any help text");
}

/// `vlocator --help` described solve's JSON (`{"inputs": ..., "results": [...]}`): its help
/// names exactly the top-level keys `vlocator --format json` prints.
#[test]
fn vlocator_help_describes_the_json_it_prints() {
    let cli = Cli::try_parse_from(["jamchart", "vlocator", "--format", "json"]).unwrap();
    let Command::Vlocator(a) = cli.command else {
        panic!("parsed as vlocator");
    };
    let json: serde_json::Value = serde_json::from_str(&super::vlocator::run(&a).unwrap()).unwrap();
    let keys: Vec<&String> = json.as_object().expect("an object").keys().collect();
    let help = long_help("vlocator");
    let line: String = help
        .split("- json:")
        .nth(1)
        .expect("the json value is documented")
        .split("[default")
        .next()
        .unwrap()
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    let documented: Vec<&str> = line.split('"').skip(1).step_by(2).collect();
    assert_eq!(
        documented,
        keys.iter().map(|k| k.as_str()).collect::<Vec<_>>(),
        "{line}"
    );
}

/// `sweep --help`'s parameter list is made from `GridParam::all()` (issue 18: written by
/// hand, it missed palm_offset_mm and push_ratio until a commit added them): every parameter
/// a sweep takes is listed on a line of its own with its quantity and unit, and the palm
/// angle, which a sweep cannot vary, is not.
#[test]
fn sweep_help_lists_every_parameter_a_sweep_takes() {
    let help = long_help("sweep");
    let listed: Vec<&str> = help
        .split("PARAM is one of:")
        .nth(1)
        .expect("the parameter list")
        .lines()
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    let all: Vec<&str> = crate::grid::GridParam::all()
        .map(crate::grid::GridParam::as_str)
        .filter(|p| *p != "theta_deg")
        .collect();
    assert!(all.contains(&"push_ratio") && all.contains(&"palm_offset_mm"));
    for p in &all {
        let line = help
            .lines()
            .find(|l| l.split_whitespace().next() == Some(p))
            .unwrap_or_else(|| panic!("sweep --help does not list {p}:\n{help}"));
        let unit = crate::grid::GridParam::named(p).unwrap().decl().unit;
        assert!(line.contains(&format!("({unit})")), "{line}");
    }
    assert_eq!(listed, all, "{help}");
    // Each listed parameter is one the axis parser takes.
    for p in all {
        assert!(
            Cli::try_parse_from(["jamchart", "sweep", &format!("{p}=1:2")]).is_ok(),
            "{p}"
        );
    }
}

/// The `--help` text of subcommand `sub`.
fn long_help(sub: &str) -> String {
    Cli::command()
        .find_subcommand_mut(sub)
        .expect("a subcommand")
        .render_long_help()
        .to_string()
}
