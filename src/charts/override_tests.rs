//! Every override of a scene's values applies or is refused: a single value given with
//! `--set`, or set after the scene was read (as `render --read-off` and Python's `read_off`
//! set it), replaces a range or distribution of the same keys, and the title names the
//! values the chart is drawn with.

use super::*;
use crate::SceneParams;
use crate::figures::Figure;
use crate::figures::models::Live;

fn builtin(name: &str, settings: &[&str]) -> Result<Scene> {
    let settings: Vec<_> = settings.iter().map(|s| s.parse().unwrap()).collect();
    SceneSource::BuiltIn(name.into()).load(&settings)
}

/// The scene's values changed after it was read, as `read_off::apply` changes them, and
/// checked again.
fn read_off(mut scene: Scene, set: impl Fn(SceneParams) -> SceneParams) -> Result<Scene> {
    scene.params = set(scene.params);
    scene.validate_chart().map(|_| scene)
}

fn distributed(scene: &Scene) -> Vec<(&'static str, Vec<&'static str>)> {
    let ChartSpec::JamProbability(spec) = &scene.chart else {
        panic!("{} is a probability chart", scene.name)
    };
    (spec.inputs.inputs.iter())
        .map(|i| (i.name, i.keys.clone()))
        .collect()
}

/// Regression: `render jam-probability --set mu=0.3` (and `mu_ground`, `mu_palm`, `--read-off
/// mu=0.25`, Python's `render`) drew the file's normal(0.2, 0.03), P(50 mm) = 0.1028, while
/// its data's params said 0.3: a single value did not replace the file's distribution. Now
/// it does, and a probability chart left with no distribution is refused saying which value
/// replaced which and what to give instead; a value replacing one friction leaves the other
/// distributed, under that friction's name.
#[test]
fn a_single_value_replaces_the_probability_charts_distribution_or_is_refused() {
    let msg = builtin("jam-probability", &["mu=0.3"])
        .unwrap_err()
        .to_string();
    for part in [
        "--set mu = 0.3",
        "replaces scene.mu = normal(0.2,0.03)",
        "--set mu=normal(0.3,0.03)",
    ] {
        assert!(msg.contains(part), "{part} in {msg}");
    }
    let scene = builtin("jam-probability", &["mu_ground=0.3"]).unwrap();
    assert_eq!(distributed(&scene), [("mu_palm", vec!["mu_palm"])]);
    let ChartSpec::JamProbability(spec) = &scene.chart else {
        unreachable!()
    };
    let data = spec.compute(&scene.input(), &Live).unwrap();
    let p50 = data.read_off.unwrap().probability.value;
    assert!(
        data.params.mu_ground == 0.3 && (p50 - 0.1028).abs() > 0.01,
        "{p50}"
    );

    let read = builtin("jam-probability", &[]).unwrap();
    let msg = read_off(read, |p| p.with_mu(0.25)).unwrap_err().to_string();
    for part in [
        "--read-off = mu=0.25",
        "replaces scene.mu = normal(0.2,0.03)",
        "--set mu=normal(0.25,0.03)",
    ] {
        assert!(msg.contains(part), "{part} in {msg}");
    }
}

/// The universal chart of a range drew the file's range after `--set mu=0.3` or `--read-off
/// mu=0.25`: the single value now replaces the range, and the chart reads off that point.
#[test]
fn a_single_value_replaces_the_universal_charts_range() {
    let range = |s: &Scene| match &s.chart {
        ChartSpec::Universal(u) => u.range.clone(),
        _ => panic!("a universal chart"),
    };
    let file = builtin("universal-range", &[]).unwrap();
    assert_eq!(range(&file).describe(), "mu = 0.12:0.3");
    let set = builtin("universal-range", &["mu=0.3"]).unwrap();
    assert!(range(&set).is_empty());
    let read = read_off(file, |p| p.with_mu(0.25)).unwrap();
    assert!(range(&read).is_empty());
    let ChartSpec::Universal(spec) = &read.chart else {
        unreachable!()
    };
    let data = spec.compute(&read.input(), &Live).unwrap();
    assert!(data.range.is_none());
    assert_eq!(data.read_off.unwrap().at.at[0], 0.25);
}

/// A band is drawn at the scene's values: a `--read-off radius_mm=20` on a sweep with a
/// friction range moved its curves to 20 mm while its band stayed at the file's 10 mm.
#[test]
fn a_band_follows_the_values_set_after_the_scene_was_read() {
    let scene = builtin("fig7b", &["mu=0.12:0.3"]).unwrap();
    let scene = read_off(scene, |p| SceneParams {
        radius_mm: 20.0,
        ..p
    })
    .unwrap();
    let ChartSpec::Sweep(spec) = &scene.chart else {
        panic!("fig7b is a sweep")
    };
    let band = spec.band.as_ref().expect("a band");
    assert_eq!(
        (band.earliest.radius_mm, band.latest.radius_mm),
        (20.0, 20.0)
    );
    assert_eq!(
        (band.earliest.mu_ground, band.latest.mu_ground),
        (0.3, 0.12)
    );
}

/// Regression: `render jam-probability --set 'mu=normal(0.21,0.03)'` was titled
/// "normal(0.2, 0.03)" over a subtitle saying 0.21. A title names the values it states by
/// their keys, and says the values the chart is drawn with, after `--set` and after a
/// `--read-off`.
#[test]
fn the_title_names_the_values_the_chart_is_drawn_with() {
    let title = |name: &str, set: &[&str]| builtin(name, set).unwrap().title;
    let t = title("jam-probability", &["mu=normal(0.21,0.03)"]);
    assert!(
        t.ends_with("radius 12.5 mm with μ normal(0.21,0.03)"),
        "{t}"
    );
    assert!(title("universal-range", &[]).ends_with("with μ 0.12 to 0.3"));
    let t = title("universal-range", &["mu=0.3", "radius_mm=20"]);
    assert!(t.ends_with("radius 20 mm with μ 0.3"), "{t}");
    let read = read_off(builtin("universal-range", &[]).unwrap(), |p| {
        p.with_mu(0.25)
    });
    assert!(read.unwrap().title.ends_with("with μ 0.25"));
    let t = title(
        "vlocator-robust-range",
        &["chart.mu=0.1:0.3", "chart.load_n=25"],
    );
    assert!(t.ends_with("flank friction 0.1 to 0.3, 25 N at 0°"), "{t}");
    let msg = builtin("fig3", &["title=r = {radious_mm}"])
        .unwrap_err()
        .to_string();
    assert!(msg.contains("{radious_mm} names no key"), "{msg}");
}
