//! The library's questions and answers (`jamchart::ask`), built from keywords as a JSON body or
//! a Python call gives them: each answer's serde form is the command line's `--format json`
//! document for the same inputs, so every face answers alike.

use jamchart::Error;
use jamchart::ask::{DesignQuestion, SolveAnswer, SolveQuestion, VlocatorQuestion, Words};

use crate::common::cli::{SHAFT, json_of, timeless};

/// The shaft's flags as the keys of a JSON body.
const SHAFT_KEYS: &str =
    r#""radius_mm": 12.5, "mass_kg": 0.4, "force_n": 40, "palm_length_mm": 80"#;

#[test]
fn a_json_body_asks_solve_what_its_flags_ask() {
    for (body, flags) in [
        (
            format!(r#"{{"mu": 0.21, {SHAFT_KEYS}}}"#),
            vec!["--mu", "0.21"],
        ),
        (
            format!(r#"{{"mu": "0.12:0.3", {SHAFT_KEYS}}}"#),
            vec!["--mu", "0.12:0.3"],
        ),
        (
            format!(r#"{{"mu": "normal(0.21,0.03)", "before_mm": [50, 60], {SHAFT_KEYS}}}"#),
            vec!["--mu", "normal(0.21,0.03)", "--before", "50,60"],
        ),
        (
            r#"{"model": "all", "mu": 0.3}"#.to_string(),
            vec!["--model", "all", "--mu", "0.3"],
        ),
        (
            r#"{"model": "min_norm", "mu": "0.2:0.4", "samples": 30}"#.to_string(),
            vec!["--model", "min-norm", "--mu", "0.2:0.4", "--samples", "30"],
        ),
    ] {
        let question: SolveQuestion = serde_json::from_str(&body).unwrap();
        let answer = serde_json::to_value(question.answer().unwrap()).unwrap();
        let mut args = vec!["solve"];
        args.extend(&flags);
        if body.contains("radius_mm") {
            args.extend(SHAFT);
        }
        assert_eq!(timeless(answer), json_of(&args), "{body}");
    }
}

#[test]
fn a_json_body_asks_design_and_vlocator_what_their_flags_ask() {
    let body = format!(r#"{{"x_target_mm": 50, "mu": "0.12:0.3", {SHAFT_KEYS}}}"#);
    let question: DesignQuestion = serde_json::from_str(&body).unwrap();
    let mut args = vec!["design", "--x-target", "50", "--mu", "0.12:0.3"];
    args.extend(SHAFT);
    assert_eq!(
        serde_json::to_value(question.answer().unwrap()).unwrap(),
        json_of(&args)
    );
    for (body, args) in [
        (
            r#"{"included_angle_deg": 70, "mu": 0.25, "load_n": 5}"#,
            vec![
                "vlocator",
                "--included-angle",
                "70",
                "--mu",
                "0.25",
                "--load",
                "5",
            ],
        ),
        (
            r#"{"mu": "0.1:0.25", "load_n": 20, "mass_kg": 0.4}"#,
            vec![
                "vlocator", "--mu", "0.1:0.25", "--load", "20", "--mass", "0.4",
            ],
        ),
        (
            r#"{"flank_angles": [30, 60], "load_n": 5, "rotation": "blocked"}"#,
            vec![
                "vlocator",
                "--flank-angles",
                "30,60",
                "--load",
                "5",
                "--rotation",
                "blocked",
            ],
        ),
    ] {
        let question: VlocatorQuestion = serde_json::from_str(body).unwrap();
        let answer = serde_json::to_value(question.answer().unwrap()).unwrap();
        assert_eq!(answer, json_of(&args), "{body}");
    }
}

/// A TOML table is keywords too: a parameter file's `[scene]` keys, flat.
#[test]
fn a_toml_table_asks_the_same_question() {
    let question: SolveQuestion = toml::from_str("mu = \"0.12:0.3\"\nradius_mm = 12.5\n").unwrap();
    assert_eq!(question.uncertain.inputs[0].name, "mu");
    assert_eq!(question.config.scene.radius_mm, 12.5);
}

/// Bad keywords are the library's typed errors, with the key, the value and the reason a face
/// shows (or the nearest key of a typo).
#[test]
fn bad_keywords_are_typed_errors_naming_the_key() {
    let refused = |body: &str| SolveQuestion::from_keywords(serde_json::from_str(body).unwrap());
    match refused(r#"{"raduis_mm": 10}"#) {
        Err(Error::UnknownKey { key, nearest }) => {
            assert_eq!(
                (key.as_str(), nearest.as_deref()),
                ("raduis_mm", Some("radius_mm"))
            );
        }
        other => panic!("{other:?}"),
    }
    for (body, key) in [
        (r#"{"mu": "0.1:nan"}"#, "mu"),
        (r#"{"mu": -1}"#, "mu"),
        (r#"{"radius_mm": "10:12"}"#, "radius_mm"),
        (r#"{"mu": true}"#, "mu"),
        (r#"{"model": "adams"}"#, "model"),
        (r#"{"samples": -3}"#, "samples"),
        (r#"{"quantiles": [1.5]}"#, "quantiles"),
        (r#"{"method": "euler"}"#, "dynamics.integrator.method"),
    ] {
        match refused(body) {
            Err(Error::InvalidValue { key: k, .. }) => assert_eq!(k, key, "{body}"),
            other => panic!("{body}: {other:?}"),
        }
    }
    // Two ways to set the push: a conflict of the two keys, not a value of either.
    match refused(r#"{"force_n": 10, "push_ratio": 3}"#) {
        Err(
            e @ Error::Conflict {
                flag: "push_ratio", ..
            },
        ) => assert_eq!(
            e.to_string(),
            "force_n and push_ratio both set the push: give one of them"
        ),
        other => panic!("{other:?}"),
    }
    // A sample count says the least it takes: one sample, where a seed may be 0.
    for body in [r#"{"samples": true}"#, r#"{"samples": 0}"#] {
        let e = refused(body).unwrap_err().to_string();
        assert!(e.ends_with("samples is a whole number >= 1"), "{body}: {e}");
    }
    assert!(refused(r#"{"seed": 0}"#).is_ok());
    // Deserialising says the same, as text.
    let e = serde_json::from_str::<SolveQuestion>(r#"{"mu": -1}"#).unwrap_err();
    assert!(e.to_string().starts_with("invalid mu = -1: "), "{e}");
}

/// The text of an answer names the settings in a face's words: flags on the command line,
/// keys elsewhere.
#[test]
fn an_answers_text_names_settings_in_a_faces_words() {
    let question: SolveQuestion =
        serde_json::from_str(r#"{"mu": 0.05, "palm_length_mm": 40}"#).unwrap();
    let answer = question.answer().unwrap();
    let (flags, keys) = (answer.text(Words::Flags), answer.text(Words::Keys));
    assert!(
        flags.contains("(--palm-length)") && flags.contains("(--mu)"),
        "{flags}"
    );
    assert!(
        keys.contains("(palm_length_mm)") && keys.contains("(mu)"),
        "{keys}"
    );
    assert!(!keys.contains("--"), "{keys}");
}

/// `SolveQuestion::from_numbers` sets a scene's numbers in place on the default config, without
/// the keyword map: it asks what `from_keywords` asks of the same keys given the same numbers,
/// field for field, and refuses what it refuses in the same words. Every key a number may be
/// given to (each of `[scene]`, the alias `mu` beside `mu_ground` and `mu_palm`, `push_ratio`
/// beside `force_n`, `theta_deg` and a typo that no question takes) alone, in pairs and in
/// longer draws, with edge values: NaN, both zeros, the least subnormal, 1e308, the infinities,
/// numbers out of range and a key given twice.
#[test]
fn a_question_of_numbers_is_the_keyword_maps_question() {
    let keys: Vec<&str> = jamchart::Param::all()
        .map(|p| p.as_str())
        .chain(["raduis_mm"])
        .collect();
    let values = [
        0.3,
        -0.0,
        0.0,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        5e-324,
        1e308,
        -1.0,
        7.0,
        90.0,
        200.0,
        1e-300,
        179.9,
    ];
    let mut outcomes = 0;
    let mut same = |numbers: &[(&str, f64)]| {
        let fast = SolveQuestion::from_numbers(numbers);
        let pairs = numbers
            .iter()
            .map(|&(k, x)| (k.to_string(), toml::Value::Float(x)));
        let general = SolveQuestion::from_keywords(jamchart::ask::Keywords::new(pairs));
        match (&fast, &general) {
            (Ok(a), Ok(b)) => {
                assert_eq!(format!("{a:?}"), format!("{b:?}"), "{numbers:?}");
                // A face that keeps the scene asks the same question again.
                let again = SolveQuestion::of_scene(a.config.scene);
                assert_eq!(format!("{a:?}"), format!("{again:?}"), "{numbers:?}");
                let answer = |q: &SolveQuestion| match q
                    .answer()
                    .map(|a| timeless(serde_json::to_value(a).unwrap()))
                {
                    Ok(v) => v.to_string(),
                    Err(e) => format!("refused: {e}"),
                };
                assert_eq!(answer(a), answer(b), "{numbers:?}");
                // The outcome a face shows before the record is the record's, or the same
                // refusal.
                match (a.outcome(), a.answer()) {
                    (Ok(Some(o)), Ok(SolveAnswer::Push(full))) => {
                        let r = &full.results[0].solution;
                        let bits = |x: Option<f64>| x.map(f64::to_bits);
                        assert_eq!(
                            (o.model, o.status, bits(o.theta_jam_deg), bits(o.x_jam_mm)),
                            (r.model, r.status, bits(r.theta_jam_deg), bits(r.x_jam_mm)),
                            "{numbers:?}"
                        );
                        outcomes += 1;
                    }
                    (Err(e), Err(f)) => assert_eq!(e.to_string(), f.to_string(), "{numbers:?}"),
                    (o, full) => panic!("{numbers:?}: outcome {o:?}, answer {full:?}"),
                }
                assert_eq!(
                    a.warnings(Words::Keys),
                    b.warnings(Words::Keys),
                    "{numbers:?}"
                );
            }
            (Err(a), Err(b)) => {
                assert_eq!(format!("{a:?}"), format!("{b:?}"), "{numbers:?}");
                assert_eq!(a.to_string(), b.to_string(), "{numbers:?}");
            }
            _ => panic!("{numbers:?}: {fast:?} against {general:?}"),
        }
        fast.is_ok()
    };
    let mut answered = 0;
    assert!(same(&[]));
    for &k in &keys {
        for &x in &values {
            answered += usize::from(same(&[(k, x)]));
        }
    }
    for (i, &a) in keys.iter().enumerate() {
        for &b in &keys[i..] {
            for (j, &x) in values.iter().enumerate() {
                let y = values[(j * 5 + 3) % values.len()];
                answered += usize::from(same(&[(a, x), (b, y)]));
                answered += usize::from(same(&[(b, y), (a, x)]));
            }
        }
    }
    // Longer draws (a fixed xorshift): up to six keys, a key now and then given twice.
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = |n: usize| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % n as u64) as usize
    };
    for _ in 0..3000 {
        let len = 1 + next(6);
        let numbers: Vec<(&str, f64)> = (0..len)
            .map(|_| (keys[next(keys.len())], values[next(values.len())]))
            .collect();
        answered += usize::from(same(&numbers));
    }
    // The comparisons answered questions, not only refusals.
    assert!(answered > 1000, "{answered} questions answered");
    assert!(outcomes > 1000, "{outcomes} outcomes compared");
}
