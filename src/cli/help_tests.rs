//! Help texts against the code: every documented default is the code's `Default`,
//! every scene a help text names exists, and `vlocator --help` describes the JSON it prints.

use clap::Parser;

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

/// A flag's short and long help, one after the other.
fn help_of(arg: &clap::Arg) -> String {
    [arg.get_help(), arg.get_long_help()]
        .iter()
        .flatten()
        .map(|h| h.to_string())
        .collect::<Vec<_>>()
        .join("\n")
}

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
    let question = crate::ask::VlocatorQuestion::new(
        a.included_angle,
        a.flank_angles.as_deref(),
        &a.locator.overrides(),
    )
    .map_err(|e| e.to_string())?;
    let p = question.params;
    if p == LocatorParams::default() {
        Ok(())
    } else {
        Err(format!("gives {p:?}, not the default V"))
    }
}

/// `--rtol -1e-3` was read as the short flags `-1` and `-e` ("unexpected argument '-1'"):
/// clap's negative numbers have no exponent. Every flag that takes a number (or a declared
/// setting's value) takes a value that starts with a hyphen, so that its own check refuses it
/// naming the flag; a flag added without it fails here.
#[test]
fn every_number_flag_takes_a_negative_number_written_with_an_exponent() {
    use std::any::TypeId;
    let numbers = [
        TypeId::of::<f64>(),
        TypeId::of::<u64>(),
        TypeId::of::<usize>(),
        TypeId::of::<toml::Value>(),
    ];
    let cmd = super::command();
    let mut checked = 0;
    for sub in cmd.get_subcommands() {
        for arg in sub.get_arguments() {
            let Some(long) = arg.get_long() else { continue };
            let number = numbers
                .iter()
                .any(|t| arg.get_value_parser().type_id() == *t);
            if !arg.get_action().takes_values() || !arg.get_possible_values().is_empty() || !number
            {
                continue;
            }
            let mut words = call(sub.get_name());
            words.extend([format!("--{long}"), "-1e-3".into()]);
            if let Err(e) = Cli::try_parse_from(&words) {
                assert_ne!(
                    e.kind(),
                    clap::error::ErrorKind::UnknownArgument,
                    "{words:?}: {e}"
                );
            }
            checked += 1;
        }
    }
    assert!(checked > 50, "{checked} number flags checked");
}

/// Help texts said `[default: ..]` by hand beside the code's `Default`, and could drift from it
/// (`solve -h` once dropped the `--mu` default; the accuracy report's flags were hand-written).
/// Every default a help text documents is checked against the code: a declared setting's
/// against the serialised `Default` of its struct, a clap default by parsing it, vlocator's
/// geometry by the V it gives; any other hand-written default fails here.
#[test]
fn documented_defaults_are_the_code_defaults() {
    let cmd = super::command();
    let mut checked = 0;
    let mut problems = Vec::new();
    for sub in cmd.get_subcommands() {
        let name = sub.get_name();
        for arg in sub.get_arguments() {
            let Some(long) = arg.get_long() else { continue };
            let id = arg.get_id().as_str();
            let help = help_of(arg);
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
    let mut cmd = super::command();
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
    let mut cmd = super::command();
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

/// `sweep --help`'s parameter list is made from `Param::all()` (written by
/// hand, it once missed palm_offset_mm and push_ratio): every parameter
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
    let all: Vec<&str> = crate::scene::Param::all()
        .map(crate::scene::Param::as_str)
        .filter(|p| *p != "theta_deg")
        .collect();
    assert!(all.contains(&"push_ratio") && all.contains(&"palm_offset_mm"));
    for p in &all {
        let line = help
            .lines()
            .find(|l| l.split_whitespace().next() == Some(p))
            .unwrap_or_else(|| panic!("sweep --help does not list {p}:\n{help}"));
        let unit = crate::scene::Param::named(p).unwrap().decl().unit;
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
    super::command()
        .find_subcommand_mut(sub)
        .expect("a subcommand")
        .render_long_help()
        .to_string()
}

/// The JSON answer of running `argv` in-process (the commands whose answer is quick), without
/// its wall times (`elapsed_s`).
fn answer(argv: &[String]) -> Result<serde_json::Value, String> {
    let cli = Cli::try_parse_from(argv).map_err(|e| e.to_string())?;
    let out = match &cli.command {
        Command::Solve(a) => super::solve::run(a),
        Command::Design(a) => super::design::run(a),
        Command::Vlocator(a) => super::vlocator::run(a),
        _ => unreachable!("only quick commands are run"),
    };
    let mut doc: serde_json::Value =
        serde_json::from_str(&out.map_err(|e| e.to_string())?).map_err(|e| e.to_string())?;
    without_wall_times(&mut doc);
    Ok(doc)
}

/// `doc` without its `elapsed_s` keys.
fn without_wall_times(doc: &mut serde_json::Value) {
    match doc {
        serde_json::Value::Object(o) => {
            o.remove("elapsed_s");
            o.values_mut().for_each(without_wall_times);
        }
        serde_json::Value::Array(a) => a.iter_mut().for_each(without_wall_times),
        _ => {}
    }
}

/// The value a flag's help documents as its default, as the flag takes it, or None: `[default:
/// X]` (its unit stripped, a vlocator angle's " deg" too), clap's own default, or `--samples`'
/// "(unset: N for the statics" (the cases below use the statics).
fn documented_value(sub: &clap::Command, arg: &clap::Arg) -> Option<String> {
    let long = arg.get_long()?;
    let help = help_of(arg);
    if let Some(text) = documented(&help).into_iter().next() {
        let unit = crate::settings::all()
            .find(|d| {
                d.flag == Some(long) && (d.section == "locator") == (sub.get_name() == "vlocator")
            })
            .map_or("", |d| d.unit);
        let v = text
            .strip_suffix(unit)
            .filter(|_| !unit.is_empty())
            .unwrap_or(&text);
        return Some(v.strip_suffix(" deg").unwrap_or(v).trim().to_string());
    }
    let defaults: Vec<String> = arg
        .get_default_values()
        .iter()
        .map(|v| v.to_string_lossy().into_owned())
        .collect();
    if !defaults.is_empty() {
        return Some(defaults.join(","));
    }
    (long == "samples").then_some(())?;
    help.split("(unset: ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .map(String::from)
}

/// Help texts must match the tool: the first test compares the texts with the
/// code's `Default` structs, but a command could ignore them (a clap default, a constant
/// unset-count, a range's handling of the other flags). Every flag of `solve` (point, range and
/// distribution: `--samples`, `--seed`, `--quantiles`), `design` and `vlocator` (point and
/// ranges) that documents a default gives, set to that default, the same answer as left out.
#[test]
fn every_documented_default_gives_the_answer_of_the_flag_left_out() {
    let cases: [&[&str]; 6] = [
        &["solve", "--format", "json"],
        &[
            "solve", "--format", "json", "--mu", "0.2:0.3", "--force", "150:250",
        ],
        &[
            "solve",
            "--format",
            "json",
            "--mass",
            "normal(1,0.1)",
            "--force",
            "uniform(150,250)",
        ],
        &["design", "--format", "json", "--x-target=40"],
        &[
            "vlocator",
            "--format",
            "json",
            "--load",
            "3",
            "--load-angle",
            "20",
        ],
        &[
            "vlocator",
            "--format",
            "json",
            "--mu",
            "0.2:0.4",
            "--load",
            "2:4",
            "--load-angle",
            "-10:10",
        ],
    ];
    let cmd = super::command();
    let (mut compared, mut problems) = (0, Vec::new());
    // The setting keys a flag sets (`--mu` sets both frictions).
    let keys_of = |sub: &str, long: &str| -> Vec<&'static str> {
        crate::settings::all()
            .find(|d| d.flag == Some(long) && (d.section == "locator") == (sub == "vlocator"))
            .map_or(Vec::new(), |d| match d.sets.is_empty() {
                true => vec![d.key],
                false => d.sets.to_vec(),
            })
    };
    for case in cases {
        let base: Vec<String> = std::iter::once("jamchart")
            .chain(case.iter().copied())
            .map(String::from)
            .collect();
        let want = answer(&base).unwrap_or_else(|e| panic!("{base:?}: {e}"));
        let sub = cmd.find_subcommand(case[0]).expect("a subcommand");
        for arg in sub.get_arguments() {
            let Some(long) = arg.get_long() else { continue };
            let flag = format!("--{long}");
            // Given by the case, or a display choice.
            if case.iter().any(|w| w.starts_with(&flag)) || long == "format" {
                continue;
            }
            // A flag that takes precedence over one of the case's (--mu-ground over --mu)
            // changes the answer by design.
            let given: Vec<&str> = case
                .iter()
                .filter_map(|w| w.strip_prefix("--"))
                .flat_map(|l| keys_of(case[0], l))
                .collect();
            if keys_of(case[0], long).iter().any(|k| given.contains(k)) {
                continue;
            }
            // With a range, vlocator's geometry flags name your V, judged beside the design
            // (their help says so): left out, none is.
            let range = case.iter().any(|w| w.contains(':'));
            if case[0] == "vlocator" && range && matches!(long, "included-angle" | "flank-angles") {
                let help = arg
                    .get_long_help()
                    .map(|h| h.to_string())
                    .unwrap_or_default();
                let flat = help.split_whitespace().collect::<Vec<_>>().join(" ");
                assert!(flat.contains("With a range"), "--{long}: {help}");
                continue;
            }
            let Some(value) = documented_value(sub, arg) else {
                continue;
            };
            if !arg.get_action().takes_values() {
                continue;
            }
            let mut argv = base.clone();
            argv.push(format!("{flag}={value}"));
            compared += 1;
            match answer(&argv) {
                Ok(got) if got == want => {}
                Ok(_) => problems.push(format!("{argv:?}: the answer changes")),
                Err(e) => problems.push(format!("{argv:?}: {e}")),
            }
        }
    }
    eprintln!("{compared} documented defaults compared with the flag left out");
    assert!(
        compared > 40,
        "only {compared} compared: is the parsing right?"
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// Every subcommand that clap lists gets its flags once built (their adding is deferred to the
/// subcommand that runs) and is read back as the command it names: the listing, the deferred
/// flags and the reading each name every subcommand.
#[test]
fn every_listed_subcommand_gets_its_flags_and_reads_back_as_itself() {
    let cmd = super::command();
    let mut named = 0;
    for sub in cmd.get_subcommands().filter(|s| s.get_name() != "help") {
        let name = sub.get_name();
        let flags = sub
            .get_arguments()
            .filter(|a| !matches!(a.get_long(), Some("help" | "version")))
            .count();
        assert_eq!(flags > 0, name != "settings", "{name}: {flags} flags");
        match Cli::try_parse_from(["jamchart", name]) {
            Ok(cli) => {
                let read = format!("{:?}", cli.command).to_lowercase();
                assert!(read.starts_with(name), "{name} read back as {read}");
                named += 1;
            }
            // A subcommand with a required argument refuses the missing one, by name.
            Err(e) => assert_eq!(
                e.kind(),
                clap::error::ErrorKind::MissingRequiredArgument,
                "{name}: {e}"
            ),
        }
    }
    assert!(named >= 10, "{named} subcommands read back");
}
