use super::*;
use crate::config::scene_decls;

fn scene_take(text: &str) -> Result<(toml::Table, UncertainSet)> {
    let mut t: toml::Table = toml::from_str(text).unwrap();
    let set = take(&mut t, scene_decls())?;
    Ok((t, set))
}

#[test]
fn every_form_parses_and_prints_as_written() {
    for (text, want) in [
        ("0.3", Uncertain::Point { value: 0.3 }),
        ("0.12:0.3", Uncertain::Range { lo: 0.12, hi: 0.3 }),
        (
            "uniform(0.12,0.3)",
            Uncertain::Uniform { lo: 0.12, hi: 0.3 },
        ),
        (
            "normal(0.2,0.03)",
            Uncertain::Normal {
                mean: 0.2,
                sd: 0.03,
            },
        ),
        (
            "lognormal(0.2,0.25)",
            Uncertain::LogNormal {
                median: 0.2,
                sigma: 0.25,
            },
        ),
    ] {
        let u = Uncertain::parse(text).unwrap();
        assert_eq!(u, want, "{text}");
        assert_eq!(u.to_string(), text);
    }
    assert_eq!(
        Uncertain::parse(" Normal( 0.2 , 0.03 ) ").unwrap(),
        Uncertain::Normal {
            mean: 0.2,
            sd: 0.03
        }
    );
    for bad in [
        "0.1:inf",
        "normal(0.2)",
        "gauss(0.2,0.1)",
        "0.1:x",
        "normal(0.2,0.1",
    ] {
        assert!(Uncertain::parse(bad).is_err(), "{bad}");
    }
}

/// Bad input: a reversed or empty range, a negative support, a non-positive
/// spread; each refused naming the setting and quoting the value as written.
#[test]
fn bad_ranges_and_distributions_name_the_setting() {
    for (text, key, says) in [
        ("mu = \"0.3:0.12\"", "mu", "reversed"),
        ("mu_palm = \"0.3:0.3\"", "mu_palm", "empty"),
        (
            "mu_ground = \"-0.1:0.3\"",
            "mu_ground",
            "low end -0.1 must be",
        ),
        (
            "force_n = \"uniform(0,50)\"",
            "force_n",
            "low end 0 must be",
        ),
        (
            "mass_kg = \"normal(-1,0.1)\"",
            "mass_kg",
            "mean must be > 0",
        ),
        (
            "mu = \"normal(0.2,0)\"",
            "mu",
            "standard deviation must be > 0",
        ),
        ("mu = \"lognormal(0.2,-1)\"", "mu", "sigma must be > 0"),
    ] {
        let msg = scene_take(text).unwrap_err().to_string();
        let (_, value) = text.split_once(" = ").unwrap();
        assert!(
            msg.contains(&format!("{key} = {}", value.trim_matches('"'))) && msg.contains(says),
            "{text}: {msg}"
        );
    }
}

/// A range given to a setting that takes a single number is refused, naming those that do
/// take one; a string that is not the syntax is left to serde's type error.
#[test]
fn a_range_for_a_point_setting_is_refused() {
    let msg = scene_take("radius_mm = \"10:12\"").unwrap_err().to_string();
    assert!(
        msg.contains("radius_mm = 10:12")
            && msg.contains("takes a single number")
            && msg.contains("mu, mu_ground, mu_palm, mass_kg and force_n"),
        "{msg}"
    );
    let (t, set) = scene_take("radius_mm = \"ten\"").unwrap();
    assert!(set.is_empty() && t["radius_mm"].is_str());
}

/// `mu` is one draw for both frictions, unless one of them is given on its own; the table
/// keeps the nominal values so the point path reads plain numbers.
#[test]
fn take_replaces_by_the_nominal_value_and_an_alias_sets_both() {
    let (t, set) = scene_take("mu = \"0.12:0.3\"\nforce_n = \"normal(40,5)\"").unwrap();
    assert_eq!(t["mu"].as_float(), Some(0.21));
    assert_eq!(t["force_n"].as_float(), Some(40.0));
    assert_eq!(set.inputs.len(), 2);
    assert_eq!(set.inputs[0].keys, ["mu_ground", "mu_palm"]);
    assert_eq!(set.describe(), "mu = 0.12:0.3, force_n = normal(40,5)");
    let p = set.apply(&crate::scene::SceneParams::default(), &[0.2, 35.0]);
    assert_eq!((p.mu_ground, p.mu_palm, p.force_n), (0.2, 0.2, 35.0));
    let (_, set) = scene_take("mu = \"0.12:0.3\"\nmu_palm = 0.5").unwrap();
    assert_eq!(set.inputs[0].keys, ["mu_ground"]);
}

/// Flags over a file: a key the flags set, as a point or a range, leaves the file's input.
#[test]
fn flags_override_the_files_uncertain_inputs_key_by_key() {
    let (_, mut file) = scene_take("mu = \"0.12:0.3\"\nforce_n = \"30:50\"").unwrap();
    let (given, flags) = scene_take("mu_palm = 0.4\nmass_kg = \"0.3:0.5\"").unwrap();
    file.override_by(&given, flags);
    let names: Vec<(&str, Vec<&str>)> = file
        .inputs
        .iter()
        .map(|i| (i.name, i.keys.clone()))
        .collect();
    assert_eq!(
        names,
        [
            ("mu", vec!["mu_ground"]),
            ("force_n", vec!["force_n"]),
            ("mass_kg", vec!["mass_kg"])
        ]
    );
}

#[test]
fn quantile_inverts_cdf_and_normal_is_truncated_at_zero() {
    for u in [
        Uncertain::Uniform { lo: 0.12, hi: 0.3 },
        Uncertain::Normal {
            mean: 0.2,
            sd: 0.03,
        },
        // Half of this normal lies below 0: truncation matters.
        Uncertain::Normal {
            mean: 0.0001,
            sd: 0.1,
        },
        Uncertain::LogNormal {
            median: 0.2,
            sigma: 0.25,
        },
    ] {
        for p in [0.001, 0.1, 0.5, 0.9, 0.999] {
            let x = u.quantile(p);
            assert!(x > 0.0, "{u}: {p} -> {x}");
            assert!(
                (u.cdf(x) - p).abs() < 1e-9,
                "{u}: cdf(quantile({p})) = {}",
                u.cdf(x)
            );
        }
    }
    let n = Uncertain::Normal {
        mean: 0.2,
        sd: 0.03,
    };
    assert!((n.quantile(0.5) - 0.2).abs() < 1e-6);
    // Phi(1) = 0.841344746.
    assert!((n.cdf(0.23) - 0.841_344_746).abs() < 1e-6);
    assert_eq!(n.cdf(-1.0), 0.0);
}

/// The sorted samples are the values of every sample drawn one by one ([`dist::draw`] at its
/// index), sorted: over partial and whole chunks, with samples that have no value, on one
/// thread and on two.
#[test]
fn sorted_samples_are_each_draw_sorted() {
    let set = UncertainSet {
        inputs: vec![
            UncertainInput {
                name: "mu",
                keys: vec!["mu_ground", "mu_palm"],
                value: Uncertain::Normal {
                    mean: 0.2,
                    sd: 0.05,
                },
            },
            UncertainInput {
                name: "force_n",
                keys: vec!["force_n"],
                value: Uncertain::Uniform { lo: 30.0, hi: 50.0 },
            },
        ],
    };
    // No value for a third of the samples, negative and repeated values among the rest.
    let each = |v: &[f64]| Ok((v[1] > 36.6).then(|| ((v[0] - 0.2) * 1e3).round() / v[1]));
    for n in [0, 1, 1000, dist::CHUNK as u64, 3 * dist::CHUNK as u64 + 17] {
        let mut want: Vec<f64> = (0..n)
            .filter_map(|i| each(&dist::draw(&set, 7, i)).unwrap())
            .collect();
        want.sort_by(f64::total_cmp);
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let got = pool
                .install(|| sorted_samples(&set, 7, n, &|_| Flow::Continue(()), each))
                .unwrap();
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&got), bits(&want), "{n} samples on {threads} threads");
        }
    }
}
