//! `jamchart accuracy`: error against run time against the physical reference, the integration
//! error beside it, and what a 400 x 400 map costs by each model.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use clap::{ArgAction, Args};
use serde::Serialize;

use super::args::{SceneArgs, TableFormat, parse_count, parse_count_usize, parse_f64};
use super::gallery::{lock_folder, page, typed_command};
use super::progress::{self, Quiet};
use crate::atomic::{Output, Set, check_all, write_all};
use crate::charts::gallery::Entry;
use crate::csv_out::{Dec, dec};
use crate::dynamics::Method;
use crate::error::{Error, Result};
use crate::models::ModelKind;
use crate::numbers::{angle_deg, length_mm, ratio};
use crate::settings::flags::{DynamicsSet, Flags};
use crate::settings::number_text;
use crate::study::ReferenceKind;
use crate::study::accuracy::{self, AccuracyReport, AccuracyRow, AccuracySettings};
use crate::study::map_cost::{self, MapCostReport, MapCostSettings};

settings! {
    /// The report's own flags, by the key its settings' messages name
    /// ([`AccuracySettings::validate`], [`MapCostSettings::validate`]).
    section = "accuracy";
    aliases ACCURACY_FLAGS {
        tolerances, flag: Some("tolerances");
        methods, flag: Some("methods");
        penetrations_um, flag: Some("penetrations");
        min_norm_tolerances, flag: Some("min-norm-tolerances");
        nonsmooth_steps_deg, flag: Some("nonsmooth-steps");
        converged_step_deg, flag: Some("converged-step");
        runs, flag: Some("runs");
        converged_rtol, flag: Some("converged-rtol");
        max_steps, flag: Some("max-steps");
        cells_per_axis, flag: Some("map-cells");
    }
}

/// Flags of `accuracy`.
#[derive(Debug, Clone, Args)]
pub struct AccuracyArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub dynamics: Flags<DynamicsSet>,
    /// Integrator tolerances rtol = atol, comma-separated, at most 64.
    #[arg(long = flag!(ACCURACY_FLAGS, tolerances), value_name = "LIST", value_delimiter = ',', action = ArgAction::Set,
          value_parser = parse_f64, default_value = list(&defaults().tolerances), allow_hyphen_values = true)]
    pub tolerances: Vec<f64>,
    /// Integrators, comma-separated.
    #[arg(long = flag!(ACCURACY_FLAGS, methods), value_name = "LIST", value_delimiter = ',', action = ArgAction::Set,
          default_value = defaults().methods.iter().map(|m| m.as_str()).collect::<Vec<_>>().join(","))]
    pub methods: Vec<Method>,
    /// Contact stiffnesses beside --stiffness, as penetration in um at --force, at most 8.
    ///
    /// k = F / delta^e; "none" keeps only --stiffness.
    #[arg(long = flag!(ACCURACY_FLAGS, penetrations_um), value_name = "LIST", value_delimiter = ',', action = ArgAction::Set,
          default_value = list(&defaults().penetrations_um), allow_hyphen_values = true)]
    pub penetrations: Vec<String>,
    /// clarabel tolerances of the min-norm rows, comma-separated, at most 64; "none" skips them.
    ///
    /// The exact path is always a row.
    #[arg(long = flag!(ACCURACY_FLAGS, min_norm_tolerances), value_name = "LIST", value_delimiter = ',', action = ArgAction::Set,
          default_value = list(&defaults().min_norm_tolerances), allow_hyphen_values = true)]
    pub min_norm_tolerances: Vec<String>,
    /// Steps of the nonsmooth rows in deg of palm turn, comma-separated, at most 64; "none"
    /// skips them.
    #[arg(long = flag!(ACCURACY_FLAGS, nonsmooth_steps_deg), value_name = "LIST", value_delimiter = ',', action = ArgAction::Set,
          default_value = list(&defaults().nonsmooth_steps_deg), allow_hyphen_values = true)]
    pub nonsmooth_steps: Vec<String>,
    /// Step of the nonsmooth method's converged answer in deg.
    #[arg(long = flag!(ACCURACY_FLAGS, converged_step_deg), value_name = "DEG", value_parser = parse_f64,
          default_value = number_text(defaults().converged_step_deg), allow_hyphen_values = true)]
    pub converged_step: f64,
    /// Timed runs per row, 1 to 1000; the median is reported.
    #[arg(long = flag!(ACCURACY_FLAGS, runs), value_name = "N", default_value_t = defaults().runs, allow_hyphen_values = true,
          value_parser = parse_count_usize)]
    pub runs: usize,
    /// Tolerance of the converged answers the integration error is measured against.
    #[arg(long = flag!(ACCURACY_FLAGS, converged_rtol), value_name = "RTOL", alias = "reference-rtol", value_parser = parse_f64,
          default_value = number_text(defaults().converged_rtol), allow_hyphen_values = true)]
    pub converged_rtol: f64,
    /// Step limit of every simulation.
    #[arg(long = flag!(ACCURACY_FLAGS, max_steps), value_name = "N", default_value_t = defaults().max_steps, allow_hyphen_values = true,
          value_parser = parse_count)]
    pub max_steps: u64,
    /// Cells per axis of the map whose cost is reported, 2 to 2000; 0 skips it.
    ///
    /// The map is mu 0.1-0.8 by F 20-2000 N (log); the statics answer all of it, the min-norm
    /// program 40 of its columns (every F at 40 values of mu) by its exact path and 4 by
    /// clarabel, the simulation 20 x 20 cells, and their time is extrapolated.
    #[arg(long = flag!(ACCURACY_FLAGS, cells_per_axis), value_name = "N", default_value_t = MapCostSettings::default().cells_per_axis,
          allow_hyphen_values = true, value_parser = parse_count_usize)]
    pub map_cells: usize,
    /// Output format on stdout.
    #[arg(long, value_enum, default_value_t = TableFormat::Text)]
    pub format: TableFormat,
    /// Also write accuracy.md, accuracy.csv, accuracy.json, accuracy_map.csv and the chart
    /// accuracy.svg / accuracy.png (wall time: not byte-identical) here, and index.html, the
    /// folder's gallery page with the chart's read-off (a render's charts there are kept).
    #[arg(long, value_name = "DIR")]
    pub out_dir: Option<PathBuf>,
    #[command(flatten)]
    pub quiet: Quiet,
}

/// The files of `--out-dir`, in the order they are written: the gallery page last, with the
/// chart's section and read-off beside those of any charts already in the folder.
const OUT_FILES: [&str; 7] = [
    "accuracy.md",
    "accuracy.csv",
    "accuracy.json",
    "accuracy_map.csv",
    "accuracy.svg",
    "accuracy.png",
    "index.html",
];

/// Why the error-time chart's section is not like a scene's.
const GALLERY_NOTE: &str = "Drawn by jamchart accuracy from measured wall time (median of the \
     runs): the picture and the times differ between machines and runs, so it is not \
     hash-checked. The read-off shows the nearest point's row of accuracy.csv.";

/// The settings the flags default to: their help shows these, derived, never written by hand.
fn defaults() -> AccuracySettings {
    AccuracySettings::default()
}

/// A list default as a flag takes it: `1e-2,1e-4`.
fn list(values: &[f64]) -> String {
    let text: Vec<String> = values.iter().map(|v| number_text(*v)).collect();
    text.join(",")
}

/// Parses a list of numbers where "none" means an empty list.
fn list_or_none(key: &str, list: &[String]) -> Result<Vec<f64>> {
    if list.len() == 1 && list[0].trim() == "none" {
        return Ok(Vec::new());
    }
    list.iter()
        .map(|v| {
            parse_f64(v.trim()).map_err(|why| {
                Error::invalid(
                    key,
                    v,
                    format!("{why}; a comma-separated list of numbers, or none"),
                )
            })
        })
        .collect()
}

/// The report's settings and the map's (None: skipped) from the flags, validated.
fn settings(a: &AccuracyArgs) -> Result<(AccuracySettings, Option<MapCostSettings>)> {
    let settings = AccuracySettings {
        min_norm_tolerances: list_or_none("min_norm_tolerances", &a.min_norm_tolerances)?,
        methods: a.methods.clone(),
        tolerances: a.tolerances.clone(),
        penetrations_um: list_or_none("penetrations_um", &a.penetrations)?,
        nonsmooth_steps_deg: list_or_none("nonsmooth_steps_deg", &a.nonsmooth_steps)?,
        runs: a.runs,
        converged_rtol: a.converged_rtol,
        converged_step_deg: a.converged_step,
        max_steps: a.max_steps,
    };
    settings.validate()?;
    let map = match a.map_cells {
        0 => None,
        cells => {
            let m = MapCostSettings::default();
            let s = MapCostSettings {
                cells_per_axis: cells,
                statics_per_axis: m.statics_per_axis.min(cells),
                min_norm_columns: m.min_norm_columns.min(cells),
                clarabel_columns: m.clarabel_columns.min(cells),
                dynamics_per_axis: m.dynamics_per_axis.min(cells),
                reference_step_deg: a.converged_step,
            };
            s.validate()?;
            Some(s)
        }
    };
    Ok((settings, map))
}

pub fn run(a: &AccuracyArgs) -> Result<String> {
    let config = a.scene.resolve(&[a.dynamics.overrides()], "accuracy")?;
    let (settings, map) = settings(a)?;
    // A penetration so small that its stiffness F / delta^e overflows is refused as the
    // penetration given, not as the --stiffness it turns into.
    let (force, exponent) = (config.scene.force_n, config.dynamics.contact.exponent);
    for um in &settings.penetrations_um {
        let k = crate::study::stiffness_for_penetration(force, um * 1e-3, exponent);
        if !(k.is_finite() && k > 0.0) {
            return Err(Error::invalid(
                "penetrations_um",
                um,
                format!(
                    "at F = {force} N and exponent {exponent} it makes the contact stiffness \
                     F / delta^e overflow; give a larger penetration"
                ),
            ));
        }
    }
    // Every output is checked before anything runs and written all or nothing at the end.
    let out_paths: Vec<PathBuf> = a
        .out_dir
        .iter()
        .flat_map(|d| OUT_FILES.map(|f| d.join(f)))
        .collect();
    check_all(out_paths.iter().map(PathBuf::as_path))?;
    let bar = progress::bar(a.quiet, 0, "accuracy {bar:30} {pos}/{len} rows, {elapsed}");
    let t0 = std::time::Instant::now();
    let report = accuracy::run(&config, &settings, &mut |done, total| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    })?;
    bar.finish_and_clear();
    let map = map.map(|s| map_cost::run(&config, &s)).transpose()?;
    let elapsed = t0.elapsed().as_secs_f64();
    let md = markdown(
        &report,
        map.as_ref(),
        settings.runs,
        elapsed,
        config.scene.force_n,
    );
    let csv = csv_rows(&report)?;
    let json = serde_json::to_string_pretty(&serde_json::json!({
        "accuracy": report,
        "map_cost": map,
        "elapsed_s": elapsed,
    }))
    .expect("plain structs serialise")
        + "\n";
    if let Some(dir) = a.out_dir.as_deref() {
        let map_csv = map.as_ref().map(map_csv).transpose()?.unwrap_or_default();
        let data = crate::figures::error_time::ErrorTimeData::of(&report, &config.scene);
        let drawn = crate::charts::error_time::render(&data)?;
        // Without the map (--map-cells 0) its file is not written.
        let keep = |p: &Path| map.is_some() || !p.ends_with("accuracy_map.csv");
        let files: Vec<String> = OUT_FILES
            .iter()
            .filter(|f| **f != "index.html" && keep(Path::new(f)))
            .map(|f| f.to_string())
            .collect();
        let entry = Entry {
            name: "accuracy".into(),
            title: crate::charts::error_time::TITLE.into(),
            kind: "error_time".into(),
            note: Some(GALLERY_NOTE),
            parameters: (
                "scene",
                toml::Table::try_from(config.scene).unwrap_or_default(),
            ),
            files,
            command: typed_command(),
            read_off: Some(&drawn.read_off),
        };
        // The set begun first makes the folder; the page is built and written under its lock,
        // as a render's (see `gallery`).
        let kept: Vec<&PathBuf> = out_paths.iter().filter(|p| keep(p)).collect();
        let set = Set::begin(kept.iter().map(|p| p.as_path()))?;
        let lock = lock_folder(dir)?;
        let html = page(dir, &[entry])?;
        let contents: [&[u8]; 7] = [
            md.as_bytes(),
            csv.as_bytes(),
            json.as_bytes(),
            map_csv.as_bytes(),
            &drawn.svg,
            &drawn.png,
            html.as_bytes(),
        ];
        let outputs: Vec<Output> = (out_paths.iter().zip(contents))
            .filter(|(path, _)| keep(path))
            .map(|(path, bytes)| Output::bytes(path, bytes))
            .collect();
        set.stage_all(&outputs)?;
        set.commit()?;
        drop(lock);
    }
    Ok(match a.format {
        TableFormat::Text => md,
        TableFormat::Csv => csv,
        TableFormat::Json => json,
    })
}

/// Writes `contents[i]` to `paths[i]` where `keep` says so, all or nothing.
pub(crate) fn write_set(
    paths: &[PathBuf],
    contents: &[&[u8]],
    keep: impl Fn(&std::path::Path) -> bool,
) -> Result<()> {
    let set: Vec<Output> = paths
        .iter()
        .zip(contents)
        .filter(|(path, _)| keep(path))
        .map(|(path, bytes)| Output::bytes(path, bytes))
        .collect();
    write_all(&set)
}

/// The serde spelling of a model (as in JSON and CSV).
pub(crate) fn model_name(m: ModelKind) -> &'static str {
    match m {
        ModelKind::Statics => "statics",
        ModelKind::MinNorm => "min_norm",
        ModelKind::Dynamics => "dynamics",
    }
}

pub(crate) fn fixed(v: Option<f64>, prec: usize) -> String {
    v.map_or("-".into(), |v| crate::numbers::fixed(v, prec))
}

/// The report's opening line: what to design to, from the references and the rows' errors.
///
/// The closed form at F for a push limited to F, with how close the min-norm program comes to
/// it; the simulation's own reference (the rigid limit for a palm driven by motion, the
/// converged rigid dynamics for a push of F) with how close the simulation comes to it at the
/// `[dynamics]` contact (its first curve's floor, as in the floors table).
fn summary(r: &AccuracyReport, force_n: f64) -> String {
    let reference = |kind: ReferenceKind| r.references.iter().find(|x| x.kind == kind);
    let rel = |v: f64| match v {
        v if v >= 1e-4 => format!("{:.2} %", 100.0 * v),
        v => format!("{v:.1e}"),
    };
    let closed = reference(ReferenceKind::ClosedForm);
    let mut s = match closed.and_then(|c| c.x_jam_mm.zip(c.theta_jam_deg)) {
        Some((x, theta)) => format!(
            "Design to x_jam = {x:.3} mm (theta_jam = {theta:.3} deg), the closed form at F = \
             {} N",
            number_text(force_n)
        ),
        None => format!(
            "Nothing to design to at F = {} N: the closed form says {}",
            number_text(force_n),
            closed.map_or("nothing".into(), |c| c.status.to_string())
        ),
    };
    let min_norm = (r.rows.iter())
        .filter(|row| row.model == ModelKind::MinNorm)
        .filter_map(|row| row.x_rel_error)
        .max_by(f64::total_cmp);
    if let Some(e) = min_norm {
        let _ = write!(s, " (the min-norm program within {} of it)", rel(e));
    }
    let simulated = r.rows.iter().find(|row| row.model == ModelKind::Dynamics);
    let own = simulated.and_then(|first| {
        let x = reference(first.reference)?.x_jam_mm?;
        let floor = (r.rows.iter())
            .filter(|row| row.method == first.method && row.penetration_um == first.penetration_um)
            .filter(|row| settled(row))
            .filter_map(|row| row.x_rel_error)
            .min_by(f64::total_cmp);
        let contact = match first.method {
            "nonsmooth" => "with rigid contacts",
            _ => "at the [dynamics] contact",
        };
        Some((first.reference, x, floor, contact))
    });
    match own {
        Some((kind, x, floor, contact)) => {
            let what = match kind {
                ReferenceKind::Rigid => "the rigid limit, for a palm driven by motion",
                _ => "the converged rigid dynamics, for a push of F with inertia",
            };
            let _ = write!(s, ", or to {x:.3} mm, {what}");
            if let Some(f) = floor {
                let _ = write!(
                    s,
                    "; the simulation comes within {} of it {contact}",
                    rel(f)
                );
            }
        }
        None => s.push_str(" (no simulation row has a reference of its own)"),
    }
    s.push_str(".\n");
    s
}

fn markdown(
    r: &AccuracyReport,
    map: Option<&MapCostReport>,
    runs: usize,
    elapsed: f64,
    force_n: f64,
) -> String {
    let mut s = format!(
        "# Error against run time, against the physical reference\n\n{}\n",
        summary(r, force_n)
    );
    s.push_str(
        "Each row answers \"where does it jam\" through the model port. `x error` is against the \
         physical reference of the scene as the row poses it (closed_form: the corrected Eq. 1 \
         at F, for the statics and min-norm; rigid: x_rigid, F -> infinity, r/mu for equal \
         frictions, for the motion drive; rigid_dynamics: the converged rigid simulation, where \
         the disc comes to rest, inertia included, for the force drive). \
         `integration error` is against the same regularised model at the converged tolerance \
         (column `converged by`). Where `x error` stops falling as the tolerance tightens is the \
         model's floor.\n\n",
    );
    for re in &r.references {
        let _ = writeln!(
            s,
            "- reference {}: {} theta_jam = {} deg, x_jam = {} mm",
            re.kind.as_str(),
            re.status,
            fixed(re.theta_jam_deg, 4),
            fixed(re.x_jam_mm, 6)
        );
    }
    for c in &r.converged {
        let at = match (c.rtol, c.step_deg) {
            (Some(r), _) => format!("rtol {r:.0e}"),
            (_, Some(h)) => format!("step {h} deg"),
            _ => String::new(),
        };
        let contact = match (c.method, c.penetration_um) {
            (Method::Nonsmooth, _) => "rigid contacts".to_string(),
            (_, Some(p)) => format!("{p} um"),
            (_, None) => "the [dynamics] stiffness".into(),
        };
        let _ = writeln!(
            s,
            "- converged {} at {at}, {contact}: {} x_jam = {} mm{}",
            c.method.as_str(),
            c.status,
            fixed(c.x_jam_mm, 6),
            c.reason
                .as_ref()
                .map_or(String::new(), |w| format!(": {w}"))
        );
    }
    let timed = match runs {
        1 => "Wall times are of one run of one answer.".to_string(),
        n => format!("Wall times are medians of {n} runs of one answer."),
    };
    let _ = writeln!(
        s,
        "\n{timed}\n\n\
         | model | method | tolerance | penetration [um] | step [deg] | status | theta_jam [deg] | x_jam [mm] | reference | x error | rel. x error | theta error | converged by | integration error | time [ms] | steps | evaluations |\n\
         |---|---|---:|---:|---:|---|---:|---:|---|---:|---:|---:|---|---:|---:|---:|---:|"
    );
    let mut failures = Vec::new();
    for row in &r.rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.4} | {} | {} |",
            model_name(row.model),
            row.method,
            row.tolerance.map_or("-".into(), |t| format!("{t:.0e}")),
            fixed(row.penetration_um, 2),
            row.step_deg.map_or("-".into(), |h| h.to_string()),
            row.status,
            fixed(row.theta_jam_deg, 4),
            fixed(row.x_jam_mm, 6),
            row.reference.as_str(),
            length_mm(row.x_error_mm),
            ratio(row.x_rel_error),
            angle_deg(row.theta_error_deg),
            row.converged_by.map_or("-", Method::as_str),
            length_mm(row.integration_error_mm),
            row.median_time_s * 1e3,
            row.steps,
            row.evaluations
        );
        if let Some(w) = &row.reason {
            failures.push(format!("- {}: {w}", label(row)));
        }
    }
    if !failures.is_empty() {
        s.push_str("\nRows without a trusted answer:\n\n");
        for f in failures {
            s.push_str(&f);
            s.push('\n');
        }
    }
    s.push_str(&floors(r));
    if let Some(m) = map {
        let _ = writeln!(
            s,
            "\n## A {n} x {n} map (mu 0.1-0.8 by F 20-2000 N) by each model\n\n\
             Errors against the closed form at each cell's F for the statics and min-norm, \
             against each cell's converged rigid dynamics (the nonsmooth method at a fine step) \
             for the simulations with the force drive. The min-norm rows answer whole columns (every F \
             of some mu: a column's search starts from its neighbours). Extrapolated rows scale the measured time by the cell count.\n\n\
             | model | method | sampled mu x F | measured [s] | {n} x {n} map [s] | extrapolated | threads | max rel. x error | status mismatches | untrusted cells |\n\
             |---|---|---:|---:|---:|---|---:|---:|---:|---:|",
            n = m.cells_per_axis
        );
        for row in &m.rows {
            let _ = writeln!(
                s,
                "| {} | {} | {kx} x {ky} | {:.3} | {:.1} | {} | {} | {} | {} | {} |",
                model_name(row.model),
                row.method,
                row.measured_s,
                row.full_map_s,
                if row.extrapolated { "yes" } else { "no" },
                row.threads,
                ratio(row.max_x_rel_error),
                row.status_mismatches,
                row.untrusted_cells,
                kx = row.sampled[0],
                ky = row.sampled[1]
            );
        }
    }
    let _ = writeln!(s, "\nThe whole report took {elapsed:.1} s.");
    s
}

fn label(row: &AccuracyRow) -> String {
    let mut s = format!("{} {}", model_name(row.model), row.method);
    if let Some(t) = row.tolerance {
        let _ = write!(s, " at {t:.0e}");
    }
    if let Some(p) = row.penetration_um {
        let _ = write!(s, ", {p:.2} um");
    }
    if let Some(h) = row.step_deg {
        let _ = write!(s, " at step {h} deg");
    }
    s
}

/// Whether a row's error against the physics is its model's, not its integrator's: its
/// integration error is known and no larger than its error. A loose tolerance can land close
/// to the reference by luck (RADAU5 on a 1 um contact at rtol 1e-3 lay 43.9 um from it with an
/// integration error of 149 um), which is no floor.
fn settled(row: &AccuracyRow) -> bool {
    row.integration_error_mm
        .zip(row.x_error_mm)
        .is_some_and(|(integration, error)| integration <= error)
}

/// The floor of each simulated curve: its smallest error against the physics among the rows
/// whose integration error lies within that error, beside the integration error there.
fn floors(r: &AccuracyReport) -> String {
    let mut s = String::from(
        "\n## Floors of the simulation\n\n\
         The smallest error of each curve among its rows whose integration error is no larger \
         than their error (a row closer to the reference by its integrator's error is luck, not \
         a floor).\n\n\
         | method | penetration [um] | reference | smallest rel. x error | at tolerance or step | integration error there |\n\
         |---|---:|---|---:|---:|---:|\n",
    );
    let mut keys: Vec<(&str, u64)> = Vec::new();
    for row in r.rows.iter().filter(|r| r.model == ModelKind::Dynamics) {
        let k = (row.method, row.penetration_um.unwrap_or(0.0).to_bits());
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    for (method, pen) in keys {
        let best = r
            .rows
            .iter()
            .filter(|x| x.method == method && x.penetration_um.unwrap_or(0.0).to_bits() == pen)
            .filter(|x| x.x_rel_error.is_some())
            .filter(|x| settled(x))
            .min_by(|a, b| a.x_rel_error.unwrap().total_cmp(&b.x_rel_error.unwrap()));
        let reference = r
            .rows
            .iter()
            .find(|x| x.method == method)
            .map_or(ReferenceKind::Rigid, |x| x.reference);
        let contact = if method == "nonsmooth" {
            "rigid".to_string()
        } else {
            format!("{:.2}", f64::from_bits(pen))
        };
        let at = best.and_then(|b| {
            b.tolerance
                .map(|t| format!("{t:.0e}"))
                .or(b.step_deg.map(|h| format!("{h} deg")))
        });
        let _ = writeln!(
            s,
            "| {method} | {contact} | {} | {} | {} | {} |",
            reference.as_str(),
            ratio(best.and_then(|b| b.x_rel_error)),
            at.unwrap_or("-".into()),
            length_mm(best.and_then(|b| b.integration_error_mm))
        );
    }
    s
}

fn csv_rows(r: &AccuracyReport) -> Result<String> {
    to_csv(crate::figures::error_time::rows(r).into_iter())
}

/// One row of the map's CSV: the typed row with plain decimals.
#[derive(Serialize)]
struct MapCsvRow {
    model: ModelKind,
    method: &'static str,
    /// Values of mu sampled.
    sampled_mu: usize,
    /// Values of F sampled.
    sampled_f: usize,
    measured_s: Dec,
    full_map_s: Dec,
    extrapolated: bool,
    threads: usize,
    max_x_rel_error: Option<Dec>,
    status_mismatches: usize,
    untrusted_cells: usize,
}

fn map_csv(m: &MapCostReport) -> Result<String> {
    to_csv(m.rows.iter().map(|x| MapCsvRow {
        model: x.model,
        method: x.method,
        sampled_mu: x.sampled[0],
        sampled_f: x.sampled[1],
        measured_s: Dec(x.measured_s),
        full_map_s: Dec(x.full_map_s),
        extrapolated: x.extrapolated,
        threads: x.threads,
        max_x_rel_error: dec(x.max_x_rel_error),
        status_mismatches: x.status_mismatches,
        untrusted_cells: x.untrusted_cells,
    }))
}

/// Rows through the csv crate (one header from the field names).
pub(crate) fn to_csv<T: Serialize>(rows: impl Iterator<Item = T>) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for row in rows {
        w.serialize(row).map_err(|e| Error::Encode {
            what: "CSV",
            detail: e.to_string(),
        })?;
    }
    let bytes = w.into_inner().map_err(|e| Error::Encode {
        what: "CSV",
        detail: e.to_string(),
    })?;
    Ok(String::from_utf8(bytes).expect("the csv crate writes UTF-8 from UTF-8 fields"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::JamStatus;
    use clap::Parser;

    /// The accuracy report's flags carried hand-written `[default: ..]` texts beside the
    /// defaults in `AccuracySettings::default()`; now clap's defaults are made from it, and with
    /// no flag the report runs exactly the default settings.
    #[test]
    fn accuracy_flags_default_to_the_settings_default() {
        let cli = crate::cli::Cli::try_parse_from(["jamchart", "accuracy"]).unwrap();
        let crate::cli::Command::Accuracy(a) = cli.command else {
            panic!("parsed as accuracy");
        };
        let (settings, map) = settings(&a).unwrap();
        assert_eq!(settings, AccuracySettings::default());
        assert_eq!(map, Some(MapCostSettings::default()));
    }

    /// The floors table took each curve's smallest error against the physics
    /// whatever its integration error, so a loose tolerance that landed near the reference by
    /// luck was listed as the floor (RADAU5 on a 1 um contact at rtol 1e-3: 43.9 um from the
    /// reference with an integration error of 149 um). Now only rows whose integration error is
    /// within their error count; a curve with none says so.
    #[test]
    fn floors_skip_rows_whose_integration_error_exceeds_their_error() {
        let row = |rtol: f64, error_um: f64, integration_um: f64| AccuracyRow {
            model: ModelKind::Dynamics,
            method: "radau5",
            tolerance: Some(rtol),
            penetration_um: Some(1.0),
            step_deg: None,
            status: JamStatus::Jams,
            theta_jam_deg: Some(43.6),
            x_jam_mm: Some(25.0 + error_um * 1e-3),
            reference: ReferenceKind::Rigid,
            reference_status: JamStatus::Jams,
            theta_ref_deg: Some(43.6),
            x_ref_mm: Some(25.0),
            x_error_mm: Some(error_um * 1e-3),
            x_rel_error: Some(error_um * 1e-3 / 25.0),
            theta_error_deg: Some(0.0),
            converged_by: Some(Method::Radau5),
            x_converged_mm: Some(25.0 + (error_um - integration_um) * 1e-3),
            integration_error_mm: Some(integration_um * 1e-3),
            median_time_s: 1e-3,
            runs: 1,
            steps: 1,
            evaluations: 1,
            reason: None,
        };
        let report = |rows: Vec<AccuracyRow>| AccuracyReport {
            references: Vec::new(),
            converged: Vec::new(),
            rows,
        };
        let lucky = row(1e-3, 43.9, 149.0);
        let floor = row(1e-6, 52.0, 0.5);
        let text = floors(&report(vec![lucky.clone(), floor]));
        let line = text.lines().find(|l| l.starts_with("| radau5")).unwrap();
        assert!(line.contains("| 1e-6 |"), "{text}");
        assert!(!line.contains("1e-3"), "{text}");
        let text = floors(&report(vec![lucky]));
        let line = text.lines().find(|l| l.starts_with("| radau5")).unwrap();
        assert!(line.ends_with("| - | - | - |"), "{text}");
    }
}
