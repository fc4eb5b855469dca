//! `jamchart accuracy`: the work-precision report of the dynamics' integrators.

use std::fmt::Write as _;
use std::io::IsTerminal;
use std::path::PathBuf;

use clap::{ArgAction, Args};

use super::args::parse_f64;
use super::args::{SceneArgs, TableFormat};
use super::dynamics::DynamicsArgs;
use serde::Serialize;

use crate::atomic::{Output, check_all, write_all};
use crate::csv_out::{Dec, dec, to_csv};
use crate::dynamics::accuracy::{Study, StudySettings, run_study};
use crate::error::{Error, Result};
use crate::limits::MAX_TOLERANCES;
use crate::minnorm::tolerance::{ToleranceRow, tolerance_study};
use crate::model::JamStatus;

/// Flags of `accuracy`.
#[derive(Debug, Clone, Args)]
pub struct AccuracyArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub dynamics: DynamicsArgs,
    /// Relative tolerances to try, comma-separated, at most 64 [default: 1e-2,1e-3,...,1e-9].
    ///
    /// Given once: a second --tolerances is refused like any repeated flag.
    #[arg(long, value_name = "LIST", value_delimiter = ',', action = ArgAction::Set, value_parser = parse_f64)]
    pub tolerances: Option<Vec<f64>>,
    /// Timed runs per point, 1 to 1000; the median is reported [default: 5].
    #[arg(long, value_name = "N")]
    pub runs: Option<usize>,
    /// Tolerance of the reference solutions [default: 1e-11].
    #[arg(long, value_name = "RTOL", value_parser = parse_f64)]
    pub reference_rtol: Option<f64>,
    /// Output format on stdout.
    #[arg(long, value_enum, default_value_t = TableFormat::Text)]
    pub format: TableFormat,
    /// clarabel tolerances of the min-norm part, comma-separated, at most 64; "none" skips it
    /// [default: 1e-2,1e-3,...,1e-10].
    ///
    /// The min-norm model solved by clarabel alone at each tol_feas = tol_gap = tol_infeas,
    /// its theta_jam compared with the closed form (translational formulation).
    #[arg(long, value_name = "LIST", value_delimiter = ',', action = ArgAction::Set)]
    pub min_norm_tolerances: Option<Vec<String>>,
    /// Also write accuracy.md, accuracy_integrators.csv (the log-log chart's data), accuracy.json and
    /// accuracy_min_norm.csv here.
    #[arg(long, value_name = "DIR")]
    pub out_dir: Option<PathBuf>,
}

/// The files of `--out-dir`.
const OUT_FILES: [&str; 4] = [
    "accuracy.md",
    // Not accuracy.csv: render's accuracy scene writes that name with another schema.
    "accuracy_integrators.csv",
    "accuracy.json",
    "accuracy_min_norm.csv",
];

pub fn run(a: &AccuracyArgs) -> Result<String> {
    // Everything is validated before anything is computed: flags, the study, the output paths.
    let config = a.scene.resolve_with(|c| a.dynamics.apply(c))?;
    let defaults = StudySettings::default();
    let settings = StudySettings {
        tolerances: a.tolerances.clone().unwrap_or(defaults.tolerances),
        runs: a.runs.unwrap_or(defaults.runs),
        reference_rtol: a.reference_rtol.unwrap_or(defaults.reference_rtol),
    };
    settings.validate()?;
    let min_norm_tols = min_norm_tolerances(a.min_norm_tolerances.as_deref())?;
    let out_paths: Vec<PathBuf> = a
        .out_dir
        .iter()
        .flat_map(|d| OUT_FILES.map(|f| d.join(f)))
        .collect();
    check_all(out_paths.iter().map(PathBuf::as_path))?;
    let bar = std::io::stderr().is_terminal().then(|| {
        // The length comes with the first progress call.
        let b = indicatif::ProgressBar::no_length();
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "accuracy {bar:30} {pos}/{len} points, {elapsed}",
        ) {
            b.set_style(style);
        }
        b
    });
    let study = run_study(
        &config.scene,
        &config.dynamics,
        &settings,
        &mut |done, total| {
            if let Some(b) = &bar {
                b.set_length(total as u64);
                b.set_position(done as u64);
            }
        },
    )?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let min_norm = tolerance_study(&config.scene, &config.min_norm, &min_norm_tols)?;
    let mut md = markdown(&study, settings.runs);
    md.push_str(&min_norm_markdown(&min_norm));
    let csv = csv(&study);
    let mut doc = serde_json::to_value(&study).expect("plain structs serialise");
    doc["min_norm_tolerance"] = serde_json::to_value(&min_norm).expect("plain structs serialise");
    let json = serde_json::to_string_pretty(&doc).expect("JSON values serialise") + "\n";
    if !out_paths.is_empty() {
        let mn_csv = min_norm_csv(&min_norm);
        let contents = [md.as_bytes(), &csv, json.as_bytes(), &mn_csv];
        let set: Vec<Output> = out_paths
            .iter()
            .zip(contents)
            .map(|(path, bytes)| Output { path, bytes })
            .collect();
        write_all(&set)?;
    }
    Ok(match a.format {
        TableFormat::Text => md,
        TableFormat::Csv => String::from_utf8(csv).expect("CSV of UTF-8 strings"),
        TableFormat::Json => json,
    })
}

/// The min-norm tolerances from `--min-norm-tolerances` ("none" = none; default 1e-2..1e-10),
/// each in (0, 1), at most [`MAX_TOLERANCES`].
fn min_norm_tolerances(arg: Option<&[String]>) -> Result<Vec<f64>> {
    let Some(list) = arg else {
        return Ok((2..=10).map(|k| 10f64.powi(-k)).collect());
    };
    if list.len() == 1 && list[0].trim() == "none" {
        return Ok(Vec::new());
    }
    let key = "--min-norm-tolerances";
    if list.len() > MAX_TOLERANCES {
        return Err(Error::invalid(
            key,
            format!("{} values", list.len()),
            format!("at most {MAX_TOLERANCES} tolerances"),
        ));
    }
    list.iter()
        .map(|v| {
            let reason = "a comma-separated list of numbers in (0, 1), or none";
            let t = parse_f64(v.trim())
                .map_err(|why| Error::invalid(key, v, format!("{why}; {reason}")))?;
            if !(t > 0.0 && t < 1.0) {
                return Err(Error::invalid(key, v, reason));
            }
            Ok(t)
        })
        .collect()
}

fn min_norm_markdown(rows: &[ToleranceRow]) -> String {
    if rows.is_empty() {
        return String::new();
    }
    let mut s = String::from(
        "\nMin-norm program: clarabel tolerance against the error of theta_jam (closed form as \
         reference, translational formulation, exact path off)\n\n\
         | tol | status | theta_jam [deg] | error [deg] | solves | clarabel iterations | undetermined |\n\
         |---:|---|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {:.0e} | {} | {} | {} | {} | {} | {} |",
            r.tol,
            r.status,
            r.theta_jam_deg.map_or("-".into(), |t| format!("{t:.9}")),
            opt(r.error_deg, 2),
            r.solves,
            r.iterations,
            r.undetermined_solves
        );
    }
    s
}

/// The min-norm tolerance study as CSV, one row per tolerance.
fn min_norm_csv(rows: &[ToleranceRow]) -> Vec<u8> {
    /// One clarabel tolerance.
    #[derive(Serialize)]
    struct Row {
        tol: Dec,
        status: JamStatus,
        theta_jam_deg: Option<Dec>,
        error_deg: Option<Dec>,
        solves: u32,
        iterations: u32,
        undetermined_solves: u32,
    }
    to_csv(rows.iter().map(|r| Row {
        tol: Dec(r.tol),
        status: r.status,
        theta_jam_deg: dec(r.theta_jam_deg),
        error_deg: dec(r.error_deg),
        solves: r.solves,
        iterations: r.iterations,
        undetermined_solves: r.undetermined_solves,
    }))
}

fn opt(v: Option<f64>, prec: usize) -> String {
    v.map_or("-".into(), |v| format!("{v:.prec$e}"))
}

fn markdown(study: &Study, runs: usize) -> String {
    let mut s = String::from("Work-precision of the dynamics' integrators (error of x_jam)\n\n");
    for r in &study.references {
        let _ = writeln!(
            s,
            "- reference {} at rtol {:e}: {} x_jam = {} mm ({} steps){}",
            r.method.as_str(),
            r.rtol,
            r.status,
            r.x_jam_mm.map_or("-".into(), |x| format!("{x:.9}")),
            r.steps,
            r.reason
                .as_ref()
                .map_or(String::new(), |why| format!(": {why}"))
        );
    }
    if let Some(d) = study.references_rel_diff {
        let _ = writeln!(s, "- the two references differ by {d:.2e} (relative)");
    }
    let _ = writeln!(
        s,
        "\nEach row is compared with the other method's reference where that one jams (column \
         'reference'); times are medians of {runs} runs.\n\n\
         | method | rtol | status | x_jam [mm] | reference | error [mm] | rel. error | time [ms] | steps | rejected | rhs evals | Jacobian evals |\n\
         |---|---:|---|---:|---|---:|---:|---:|---:|---:|---:|---:|"
    );
    let mut failures = Vec::new();
    for r in &study.rows {
        let _ = writeln!(
            s,
            "| {} | {:.0e} | {} | {} | {} | {} | {} | {:.3} | {} | {} | {} | {} |",
            r.method.as_str(),
            r.rtol,
            r.status,
            r.x_jam_mm.map_or("-".into(), |x| format!("{x:.6}")),
            r.reference.map_or("-", |m| m.as_str()),
            opt(r.error_mm, 2),
            opt(r.rel_error, 2),
            r.median_time_s * 1e3,
            r.steps,
            r.rejected_steps,
            r.rhs_evals,
            r.jacobian_evals
        );
        if let Some(why) = r.reason.as_ref().filter(|_| r.error_mm.is_none()) {
            failures.push(format!(
                "- {} at rtol {:e}: {why}",
                r.method.as_str(),
                r.rtol
            ));
        }
    }
    if !failures.is_empty() {
        s.push_str("\nFailures:\n");
        for f in failures {
            s.push_str(&f);
            s.push('\n');
        }
    }
    s
}

/// One row per point: the data of the log-log chart (rel_error against median_time_s).
fn csv(study: &Study) -> Vec<u8> {
    /// One integrator at one rtol.
    #[derive(Serialize)]
    struct Row<'a> {
        method: &'static str,
        rtol: Dec,
        status: JamStatus,
        x_jam_mm: Option<Dec>,
        error_mm: Option<Dec>,
        rel_error: Option<Dec>,
        reference: Option<&'static str>,
        median_time_s: Dec,
        runs: usize,
        steps: u64,
        rejected_steps: u64,
        rhs_evals: u64,
        jacobian_evals: u64,
        reason: Option<&'a str>,
    }
    to_csv(study.rows.iter().map(|r| Row {
        method: r.method.as_str(),
        rtol: Dec(r.rtol),
        status: r.status,
        x_jam_mm: dec(r.x_jam_mm),
        error_mm: dec(r.error_mm),
        rel_error: dec(r.rel_error),
        reference: r.reference.map(|m| m.as_str()),
        median_time_s: Dec(r.median_time_s),
        runs: r.runs,
        steps: r.steps,
        rejected_steps: r.rejected_steps,
        rhs_evals: r.rhs_evals,
        jacobian_evals: r.jacobian_evals,
        reason: r.reason.as_deref(),
    }))
}
