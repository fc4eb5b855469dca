//! `jamchart table`: the paper's Table 1 recomputed beside the printed numbers.

use std::fmt::Write;

use clap::Args;
use serde::Serialize;

use crate::csv_out::{Dec, dec, to_csv};

use super::args::TableFormat;
use crate::error::Result;
use crate::minnorm::{self, MinNormSettings};
use crate::paper::TABLE1;
use crate::scene::SceneParams;
use crate::statics;

/// Flags of `table`.
#[derive(Debug, Clone, Args)]
pub struct TableArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = TableFormat::Text)]
    pub format: TableFormat,
}

/// One recomputed row of Table 1.
#[derive(Debug, Clone, Serialize)]
pub struct TableRow {
    pub mu: f64,
    /// Closed-form theta_jam in deg.
    pub theta_jam_deg: f64,
    /// Closed-form x_jam in mm.
    pub x_jam_mm: f64,
    /// The paper's first-model theta_jam in deg, as printed.
    pub paper_theta_jam_deg: f64,
    /// The paper's first-model x_jam in mm, as printed.
    pub paper_x_jam_mm: f64,
    /// (paper - ours) / ours for x_jam, in percent.
    pub x_rel_diff_pct: f64,
    /// r cot(theta/2) of the paper's printed (truncated) theta, in mm: what the printed x should
    /// be.
    pub x_of_paper_theta_mm: f64,
    /// The paper's second-model (min-norm) x_jam in mm, as printed.
    pub paper_min_norm_x_jam_mm: f64,
    /// The paper's second-model theta_jam in deg, as printed.
    pub paper_min_norm_theta_jam_deg: f64,
    /// Known erratum of the printed row.
    pub erratum: Option<&'static str>,
    /// Our min-norm theta_jam in deg (translational formulation, default settings).
    pub min_norm_theta_jam_deg: Option<f64>,
    /// Our min-norm x_jam in mm.
    pub min_norm_x_jam_mm: Option<f64>,
    /// Our min-norm theta_jam minus the closed form's, in deg.
    pub min_norm_theta_diff_deg: Option<f64>,
}

/// Table 1 recomputed with the paper's parameters (the defaults) for each printed mu.
pub fn rows() -> Vec<TableRow> {
    TABLE1
        .iter()
        .map(|row| {
            let p = SceneParams::default().with_mu(row.mu);
            let s = statics::solve(&p);
            // The paper's parameters always jam on the palm (checked by the golden test).
            let theta = s.theta_jam_deg.unwrap_or(f64::NAN);
            let x = s.x_jam_mm.unwrap_or(f64::NAN);
            // Valid parameters and default settings: the min-norm model cannot refuse them.
            let mn = minnorm::palm::solve(&p, &MinNormSettings::default()).ok();
            let mn_theta = mn.as_ref().and_then(|m| m.theta_jam_deg);
            TableRow {
                mu: row.mu,
                theta_jam_deg: theta,
                x_jam_mm: x,
                paper_theta_jam_deg: row.statics_theta_jam_deg,
                paper_x_jam_mm: row.statics_x_jam_mm,
                x_rel_diff_pct: 100.0 * (row.statics_x_jam_mm - x) / x,
                x_of_paper_theta_mm: p.disc_position_mm(row.statics_theta_jam_deg.to_radians()),
                paper_min_norm_x_jam_mm: row.min_norm_x_jam_mm,
                paper_min_norm_theta_jam_deg: row.min_norm_theta_jam_deg,
                erratum: row.erratum,
                min_norm_theta_jam_deg: mn_theta,
                min_norm_x_jam_mm: mn.as_ref().and_then(|m| m.x_jam_mm),
                min_norm_theta_diff_deg: mn_theta.zip(s.theta_jam_deg).map(|(a, b)| a - b),
            }
        })
        .collect()
}

pub fn run(a: &TableArgs) -> Result<String> {
    let rows = rows();
    Ok(match a.format {
        TableFormat::Json => {
            serde_json::to_string_pretty(&rows).expect("plain structs serialise") + "\n"
        }
        TableFormat::Csv => String::from_utf8(csv(&rows)).expect("CSV of UTF-8 strings"),
        TableFormat::Text => markdown(&rows),
    })
}

/// The rows as CSV, the columns of the JSON keys.
fn csv(rows: &[TableRow]) -> Vec<u8> {
    /// [`TableRow`] with its numbers as plain decimals.
    #[derive(Serialize)]
    struct Row {
        mu: Dec,
        theta_jam_deg: Dec,
        x_jam_mm: Dec,
        paper_theta_jam_deg: Dec,
        paper_x_jam_mm: Dec,
        x_rel_diff_pct: Dec,
        x_of_paper_theta_mm: Dec,
        paper_min_norm_x_jam_mm: Dec,
        paper_min_norm_theta_jam_deg: Dec,
        erratum: Option<&'static str>,
        min_norm_theta_jam_deg: Option<Dec>,
        min_norm_x_jam_mm: Option<Dec>,
        min_norm_theta_diff_deg: Option<Dec>,
    }
    to_csv(rows.iter().map(|r| Row {
        mu: Dec(r.mu),
        theta_jam_deg: Dec(r.theta_jam_deg),
        x_jam_mm: Dec(r.x_jam_mm),
        paper_theta_jam_deg: Dec(r.paper_theta_jam_deg),
        paper_x_jam_mm: Dec(r.paper_x_jam_mm),
        x_rel_diff_pct: Dec(r.x_rel_diff_pct),
        x_of_paper_theta_mm: Dec(r.x_of_paper_theta_mm),
        paper_min_norm_x_jam_mm: Dec(r.paper_min_norm_x_jam_mm),
        paper_min_norm_theta_jam_deg: Dec(r.paper_min_norm_theta_jam_deg),
        erratum: r.erratum,
        min_norm_theta_jam_deg: dec(r.min_norm_theta_jam_deg),
        min_norm_x_jam_mm: dec(r.min_norm_x_jam_mm),
        min_norm_theta_diff_deg: dec(r.min_norm_theta_diff_deg),
    }))
}

fn markdown(rows: &[TableRow]) -> String {
    let mut s = String::from(
        "Table 1 (m = 1 kg, r = 10 mm, F = 200 N, g = 9.806 m/s^2): closed form against the paper\n\n\
         | mu | theta_jam [deg] | paper theta [deg] | x_jam [mm] | paper x [mm] | x diff [%] | \
         r cot(paper theta/2) [mm] | paper min-norm theta [deg] | paper min-norm x [mm] | \
         min-norm theta [deg] | min-norm x [mm] | min-norm - closed theta [deg] |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    let mut notes = Vec::new();
    for r in rows {
        let mark = if r.erratum.is_some() { " (*)" } else { "" };
        let _ = writeln!(
            s,
            "| {:.2} | {:.3} | {:.1} | {:.3} | {:.2}{mark} | {:+.2} | {:.2} | {:.1} | {:.2} | {} | {} | {} |",
            r.mu,
            r.theta_jam_deg,
            r.paper_theta_jam_deg,
            r.x_jam_mm,
            r.paper_x_jam_mm,
            r.x_rel_diff_pct,
            r.x_of_paper_theta_mm,
            r.paper_min_norm_theta_jam_deg,
            r.paper_min_norm_x_jam_mm,
            r.min_norm_theta_jam_deg
                .map_or("-".into(), |v| format!("{v:.6}")),
            r.min_norm_x_jam_mm
                .map_or("-".into(), |v| format!("{v:.4}")),
            r.min_norm_theta_diff_deg
                .map_or("-".into(), |v| format!("{v:+.1e}")),
        );
        if let Some(e) = r.erratum {
            notes.push(format!("(*) mu = {:.2}: erratum: {e}", r.mu));
        }
    }
    s.push_str(
        "\nThe paper's theta is the closed form truncated (not rounded) to 0.1 deg and its x is r cot(theta/2) of \
         that truncated theta.\n",
    );
    for n in notes {
        s.push_str(&n);
        s.push('\n');
    }
    s
}
