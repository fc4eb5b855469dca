//! Monte Carlo work bounded by its estimated time: `solve --model min-norm --samples 10000000`
//! (or the simulation) was accepted and would have run for hours. It is refused at once,
//! naming --samples with the estimate and the limit; a scene whose samples cost more than the
//! default one's (a stiff contact) is estimated from a timed sample.

use super::cli_util::stderr;
use super::run;

#[test]
fn hours_of_sampling_are_refused_before_they_start() {
    let dir = tempfile::tempdir().unwrap();
    let mu = ["--mu", "normal(0.3,0.01)"];
    for model in [
        &["--model", "min-norm", "--samples", "10000000"][..],
        &["--model", "dynamics", "--samples", "10000000"][..],
        &[
            "--model",
            "dynamics",
            "--method",
            "dopri5",
            "--samples",
            "1000000",
        ][..],
        &[
            "--model",
            "dynamics",
            "--stiffness",
            "1e9",
            "--samples",
            "200000",
        ][..],
    ] {
        let args: Vec<&str> = ["solve"].iter().chain(&mu).chain(model).copied().collect();
        let started = std::time::Instant::now();
        let o = run(dir.path(), &args);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {e}");
        assert!(
            e.contains("--samples") && e.contains("over the limit of 10 min"),
            "{e}"
        );
        // Refused before the work: one timed sample at most.
        assert!(started.elapsed().as_secs_f64() < 20.0, "{args:?}");
    }
    // The default count answers.
    let o = run(
        dir.path(),
        &["solve", "--model", "min-norm", "--mu", "normal(0.3,0.01)"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}
