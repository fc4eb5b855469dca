//! The command line: flags (clap derive) merged over a TOML file, validated, then one function
//! per subcommand. Nothing here computes physics.

mod accuracy;
mod args;
mod dynamics;
mod min_norm;
pub mod render;
mod solve;
mod stability;
mod table;

use std::io::Write;

use clap::{Parser, Subcommand};

pub use args::{ModelChoice, OutputFormat, SceneArgs, TableFormat};

use crate::error::Error;

/// Predicts where a pushed circular workpiece jams and draws design charts.
///
/// A palm hinged at the origin closes and pushes a disc along the ground; jamchart computes the palm
/// angle theta_jam (deg) and disc position x_jam (mm) at which the disc jams. Lengths in mm, forces
/// in N, mass in kg, gravity in m/s^2, angles in degrees.
#[derive(Debug, Parser)]
#[command(name = "jamchart", version, propagate_version = true)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Read off theta_jam and x_jam for one set of parameters.
    ///
    /// Prints the palm angle theta_jam (deg) at which the disc stops sliding and jams, and the
    /// disc position x_jam (mm, hinge to contact) where that happens, for each requested model.
    /// Parameters come from the defaults (the paper's), then --config FILE, then the flags.
    Solve(solve::SolveArgs),
    /// Recompute the paper's Table 1 beside the printed numbers.
    ///
    /// The paper's parameters (m = 1 kg, r = 10 mm, F = 200 N, g = 9.806 m/s^2) for
    /// mu = 0.45 ... 0.15, with the relative difference to the printed values and the known
    /// erratum of the mu = 0.30 row marked.
    Table(table::TableArgs),
    /// Draw the design charts (scenes in charts/) as SVG, PNG and data.
    ///
    /// Each scene charts/NAME.toml names its chart kind, parameters, axes and layers; render
    /// writes DIR/NAME.svg, NAME.png and the data behind the chart (NAME.csv or .json), each
    /// atomically (temporary file, then rename). The pictures are byte-identical for any thread
    /// count: the font is embedded and the PNG carries no metadata.
    Render(render::RenderArgs),
    /// Error against run time of every model, against the physical reference.
    ///
    /// Every way of answering (closed form; min-norm by its exact path and by clarabel at each
    /// tolerance; the simulation by each integrator, tolerance and contact stiffness): the error
    /// of x_jam and theta_jam against the scene's physical reference (closed form at F, or
    /// r/mu-like rigid limit for the motion drive), the integration error against the same
    /// model at a tight tolerance, the median wall time of --runs answers, steps and
    /// evaluations; a failure is a row with its reason. Then what a 400 x 400 map costs by
    /// each model and its error against the closed form.
    Accuracy(accuracy::AccuracyArgs),
    /// Numerical stability: a matrix of stiff and extreme cases through every method.
    ///
    /// Contact stiffness from 1 mm to 0.01 um of penetration, stiction velocity 1e-3 mm/s,
    /// mu 0.01-2 and unequal or zero, radius 0.1 mm-1 m, mass 1e-6-100 kg, omega 0.1-3600
    /// deg/s, start angles near the jam, 0 and 180 deg, a push barely able to move the disc;
    /// each answer classed correct / inaccurate_flagged / failed_named / wrong_unflagged
    /// against the case's physical reference. The chart is the scene `stability`.
    Stability(stability::StabilityArgs),
}

/// Runs the command line and returns the process exit code: 0 success, 2 bad input or failure.
pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(e),
    };
    let result = match &cli.command {
        Command::Solve(a) => solve::run(a),
        Command::Table(a) => table::run(a),
        Command::Render(a) => render::run(a),
        Command::Accuracy(a) => accuracy::run(a),
        Command::Stability(a) => stability::run(a),
    };
    match result {
        Ok(text) => {
            let mut out = std::io::stdout().lock();
            // A closed pipe (`| head`) is not an error worth a message.
            let _ = out.write_all(text.as_bytes()).and_then(|_| out.flush());
            0
        }
        Err(e) => {
            eprintln!("jamchart: {}", describe(&e));
            2
        }
    }
}

/// Help and version go to stdout as clap prints them; usage errors become one line.
fn clap_exit(e: clap::Error) -> i32 {
    use clap::error::ErrorKind;
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = e.print();
            0
        }
        // `jamchart` alone: the help is the answer, but it is still a usage error.
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            eprint!("{}", e.render());
            2
        }
        _ => {
            let rendered = e.render().to_string();
            let first = rendered.lines().next().unwrap_or("invalid arguments");
            let first = first.strip_prefix("error: ").unwrap_or(first);
            // Keep clap's list of accepted values on the one line: it says what to type instead.
            let values = rendered
                .lines()
                .map(str::trim)
                .find(|l| l.starts_with("[possible values:"))
                .map_or(String::new(), |v| format!(" {v}"));
            eprintln!("jamchart: {first}{values}; see 'jamchart --help'");
            2
        }
    }
}

/// The error message, with the flag that sets a key named beside the key.
fn describe(e: &Error) -> String {
    match e {
        Error::InvalidValue { key, value, reason } => match args::flag_for_key(key) {
            Some(flag) => format!("invalid {key} = {value} (flag {flag}): {reason}"),
            None => e.to_string(),
        },
        _ => e.to_string(),
    }
}
