//! `jamchart stability`: the matrix of stiff and extreme cases through every model and method.

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::Args;
use serde::Serialize;

use super::accuracy::{fixed, model_name, to_csv, write_set};
use super::args::{SceneArgs, TableFormat};
use crate::atomic::check_all;
use crate::csv_out::{Dec, dec};
use crate::error::{Error, Result};
use crate::models::ModelKind;
use crate::numbers::length_mm;
use crate::scene::JamStatus;
use crate::settings::flags::{DynamicsSet, Flags};
use crate::study::ReferenceKind;
use crate::study::stability::{self, Class, StabilityReport};

/// Most cases named on the command line (the default matrix has fewer).
const MAX_CASES: usize = 64;

settings! {
    /// The report's own flag, by the key its messages name.
    section = "stability";
    aliases STABILITY_FLAGS {
        cases, flag: Some("cases");
    }
}

/// Flags of `stability`.
#[derive(Debug, Clone, Args)]
pub struct StabilityArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub dynamics: Flags<DynamicsSet>,
    /// Cases to run, comma-separated [default: every case].
    ///
    /// Each case changes the scene and settings given by the other flags (the paper's by
    /// default); an unknown name is refused with the list of cases.
    #[arg(long = flag!(STABILITY_FLAGS, cases), value_name = "LIST", value_delimiter = ',')]
    pub cases: Option<Vec<String>>,
    /// Output format on stdout.
    #[arg(long, value_enum, default_value_t = TableFormat::Text)]
    pub format: TableFormat,
    /// Also write stability.md, stability.csv and stability.json here (the chart is the scene
    /// `stability-matrix`: jamchart render stability-matrix).
    #[arg(long, value_name = "DIR")]
    pub out_dir: Option<PathBuf>,
    #[command(flatten)]
    pub quiet: super::progress::Quiet,
}

pub fn run(a: &StabilityArgs) -> Result<String> {
    let config = a.scene.resolve(&[a.dynamics.overrides()], "stability")?;
    let cases = stability::select(&config, a.cases.as_deref(), MAX_CASES)?;
    // Checked before anything runs, written all or nothing at the end.
    let out_paths: Vec<PathBuf> = a
        .out_dir
        .iter()
        .flat_map(|d| ["stability.md", "stability.csv", "stability.json"].map(|f| d.join(f)))
        .collect();
    check_all(out_paths.iter().map(PathBuf::as_path))?;
    let report = stability::run(&config, &cases, &stability::methods(&config))?;
    // No NaN or infinity may reach a table: a defect, said as one.
    if let Some(r) = report
        .rows
        .iter()
        .find(|r| r.numbers().iter().any(|v| !v.is_finite()))
    {
        return Err(Error::Defect(format!(
            "a non-finite number in case {} by {} {}: {r:?}",
            r.case,
            model_name(r.model),
            r.method
        )));
    }
    if !a.quiet.quiet {
        super::terminal::diagnostic(&format!(
            "jamchart: stability matrix of {} cases x {} methods took {:.1} s on {} threads",
            report.cases.len(),
            report.methods.len(),
            report.elapsed_s,
            rayon::current_num_threads()
        ));
    }
    let md = markdown(&report);
    let csv = csv_rows(&report)?;
    let json = serde_json::to_string_pretty(&report).expect("plain structs serialise") + "\n";
    if !out_paths.is_empty() {
        let contents = [md.as_bytes(), csv.as_bytes(), json.as_bytes()];
        write_set(&out_paths, &contents, |_| true)?;
    }
    Ok(match a.format {
        TableFormat::Text => md,
        TableFormat::Csv => csv,
        TableFormat::Json => json,
    })
}

fn markdown(r: &StabilityReport) -> String {
    let mut s = format!(
        "# Numerical stability on stiff and extreme cases\n\n\
         {} cases x {} methods in {:.1} s ({} threads). Each answer against the case's \
         physical reference (closed_form at F; rigid, x_rigid, for the motion drive; \
         rigid_dynamics, where the rigid disc comes to rest, for the force drive); x error \
         within the allowance is correct. Allowances: 1e-4 of x_ref for the closed form and \
         the min-norm program, 1e-3 for the nonsmooth method (its step), 3 % plus the \
         contact's give for the regularised simulation (its friction's floor).\n\n",
        r.cases.len(),
        r.methods.len(),
        r.elapsed_s,
        rayon::current_num_threads()
    );
    for class in Class::ALL {
        let _ = writeln!(s, "- {}: {}", class.as_str(), r.of_class(class).count());
    }
    s.push_str("\nCases:\n\n");
    for c in &r.cases {
        let _ = writeln!(s, "- {}: {}", c.name, c.what);
    }
    s.push_str(
        "\n| case | model | method | finished | status | x_jam [mm] | reference | x_ref [mm] | x error | allowance | steps | evaluations | time [ms] | class | reason |\n\
         |---|---|---|---|---|---:|---|---:|---:|---:|---:|---:|---:|---|---|\n",
    );
    for row in &r.rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} {} | {} | {} | {} | {} | {} | {:.2} | {} | {} |",
            row.case,
            model_name(row.model),
            row.method,
            if row.finished { "yes" } else { "no" },
            row.status,
            fixed(row.x_jam_mm, 4),
            row.reference.kind.as_str(),
            row.reference.status,
            fixed(row.reference.x_jam_mm, 4),
            length_mm(row.x_error_mm),
            length_mm(row.allowance_mm),
            row.steps,
            row.evaluations,
            row.time_s * 1e3,
            row.class.as_str(),
            row.reason.as_ref().map_or(String::new(), |w| w.to_string())
        );
    }
    s
}

/// One CSV row: the typed row flattened, its reason as a tag and a sentence.
#[derive(Serialize)]
struct CsvRow<'a> {
    case: &'a str,
    model: ModelKind,
    method: &'a str,
    finished: bool,
    status: JamStatus,
    x_jam_mm: Option<Dec>,
    reference: ReferenceKind,
    reference_status: JamStatus,
    x_ref_mm: Option<Dec>,
    x_error_mm: Option<Dec>,
    allowance_mm: Option<Dec>,
    steps: u64,
    evaluations: u64,
    time_s: Dec,
    class: Class,
    reason: Option<&'static str>,
    reason_detail: Option<String>,
}

fn csv_rows(r: &StabilityReport) -> Result<String> {
    to_csv(r.rows.iter().map(|x| CsvRow {
        case: &x.case,
        model: x.model,
        method: x.method,
        finished: x.finished,
        status: x.status,
        x_jam_mm: dec(x.x_jam_mm),
        reference: x.reference.kind,
        reference_status: x.reference.status,
        x_ref_mm: dec(x.reference.x_jam_mm),
        x_error_mm: dec(x.x_error_mm),
        allowance_mm: dec(x.allowance_mm),
        steps: x.steps,
        evaluations: x.evaluations,
        time_s: Dec(x.time_s),
        class: x.class,
        reason: x.reason.as_ref().map(|w| w.tag()),
        reason_detail: x.reason.as_ref().map(|w| w.to_string()),
    }))
}
