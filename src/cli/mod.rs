//! The command line: flags (clap derive) merged over a TOML file, validated, then one function
//! per subcommand. Nothing here computes physics.

mod accuracy;
mod args;
mod design;
mod gallery;
#[cfg(test)]
mod help_tests;
mod manifest;
mod progress;
pub(crate) mod render;
#[cfg(feature = "serve")]
mod serve;
mod shell;
mod solve;
mod stability;
mod sweep;
mod table;
mod terminal;
mod threads;
mod vlocator;

use std::io::Write;

use clap::{Parser, Subcommand};

use crate::error::{self, Error};

/// Predicts where a pushed circular workpiece jams and draws design charts.
///
/// A palm hinged at the origin closes and pushes a disc along the ground; jamchart computes the palm
/// angle theta_jam (deg) and disc position x_jam (mm) at which the disc jams. Lengths in mm, forces
/// in N, mass in kg, gravity in m/s^2, angles in degrees.
#[derive(Debug, Parser)]
#[command(name = "jamchart", version = version(), propagate_version = true)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

/// `--version`: the crate version, the git commit it was built from ("unknown" without git)
/// and the chart format ([`crate::charts::CHART_FORMAT`]): together they decide a chart's bytes.
fn version() -> String {
    format!(
        "{} (commit {}, chart format {})",
        env!("CARGO_PKG_VERSION"),
        env!("JAMCHART_GIT_COMMIT"),
        crate::charts::CHART_FORMAT
    )
}

/// The subcommands: what each one runs with.
#[derive(Debug)]
pub enum Command {
    /// `jamchart solve`, with its flags.
    Solve(solve::SolveArgs),
    /// `jamchart design`, with its flags.
    Design(design::DesignArgs),
    /// `jamchart table`, with its flags.
    Table(table::TableArgs),
    /// `jamchart render`, with its flags.
    Render(render::RenderArgs),
    /// `jamchart sweep`, with its flags.
    Sweep(sweep::SweepArgs),
    /// `jamchart scenes`, with its flags.
    Scenes(render::ScenesArgs),
    /// `jamchart settings`, which takes no flags.
    Settings,
    /// `jamchart accuracy`, with its flags.
    Accuracy(accuracy::AccuracyArgs),
    /// `jamchart stability`, with its flags.
    Stability(stability::StabilityArgs),
    /// `jamchart vlocator`, with its flags.
    Vlocator(vlocator::VlocatorArgs),
    /// `jamchart serve`, with its flags.
    #[cfg(feature = "serve")]
    Serve(serve::ServeArgs),
    /// `jamchart completions`, with its flags.
    Completions(shell::CompletionsArgs),
    /// `jamchart man`, with its flags.
    Man(shell::ManArgs),
}

/// The subcommands as clap lists them: each one's name and help text. Each one's flags are
/// added to it only when it runs or its help is shown ([`Command`]'s `augment_subcommands`,
/// by clap's `defer`): the settings' flags of every subcommand, their help texts formatted,
/// took 2.6 M instructions, most of a `jamchart --version`, in every run.
#[derive(Subcommand)]
enum Listed {
    /// Read off theta_jam and x_jam for one set of parameters.
    ///
    /// Prints the palm angle theta_jam (deg) at which the disc stops sliding and jams, and the
    /// disc position x_jam (mm, hinge to contact) where that happens, for each requested model.
    /// Parameters come from the defaults (the paper's), then --config FILE, then the flags.
    Solve,
    /// Inverse questions over friction, push and mass ranges: the least push, the largest
    /// friction, the palm length.
    ///
    /// For a target position --x-target MM: the least push that carries the disc there without
    /// jamming at any friction of the range (the closed form at the corner that jams
    /// earliest: frictions and mass high, push low); the largest friction the push allows;
    /// and the palm length that keeps the latest jam (frictions and mass low, push high) on
    /// the palm. Each closed form is checked by the nonsmooth simulation (force drive). A
    /// target no push reaches is an answer, not an error.
    Design,
    /// Recompute the paper's Table 1 beside the printed numbers.
    ///
    /// The paper's parameters (m = 1 kg, r = 10 mm, F = 200 N, g = 9.806 m/s^2) for
    /// mu = 0.45 ... 0.15, with the relative difference to the printed values and the known
    /// erratum of the mu = 0.30 row marked.
    Table,
    /// Draw the design charts (built-in scenes or your own) as SVG, PNG and data.
    ///
    /// Each scene names its chart kind, parameters, axes and layers (`jamchart scenes` lists the
    /// built-in ones; `jamchart scenes --keys` documents the keys); render writes DIR/NAME.svg, NAME.png
    /// and the data behind the chart (NAME.csv; maps also NAME.json), each atomically (temporary
    /// file, then rename), and DIR/index.html, a gallery of every chart in DIR (this run's and
    /// earlier ones') with the parameters it was drawn with and links. The pictures are byte-identical for any thread count: the font is embedded and
    /// the PNG carries no metadata. --bless writes DIR/SHA256SUMS of the pictures; --check
    /// re-renders and exits 1 naming each picture whose bytes differ from it.
    Render,
    /// Draw x_jam and theta_jam against one or two parameters, without a scene file.
    ///
    /// One axis: both against it, with the F -> infinity limit (CSV, SVG, PNG). Two axes: a map
    /// of x_jam over both (JSON, SVG, PNG); the chart joins DIR/index.html, the folder's
    /// gallery, as render's do. The other parameters come from the defaults (the paper's), then
    /// --config FILE, then the flags. Closed-form statics.
    Sweep,
    /// List the scenes render draws: name, chart kind and title, one line each.
    Scenes,
    /// List every setting: flag, TOML key, unit, default, valid values and meaning.
    ///
    /// The keys of a parameter file (--config) and of a scene file's scene, min_norm and
    /// dynamics.* sections, as a Markdown table; `--set KEY=VALUE` takes the bare key.
    Settings,
    /// Error against run time of every model, against the physical reference.
    ///
    /// Every way of answering (closed form; min-norm by its exact path and by clarabel at each
    /// tolerance; the simulation by each integrator, tolerance and contact stiffness): the error
    /// of x_jam and theta_jam against the scene's physical reference (closed form at F, or
    /// r/mu-like rigid limit for the motion drive), the integration error against the same
    /// model at a tight tolerance, the median wall time of --runs answers, steps and
    /// evaluations; a failure is a row with its reason. Then what a 400 x 400 map costs by
    /// each model and its error against the closed form.
    Accuracy,
    /// Numerical stability: a matrix of stiff and extreme cases through every method.
    ///
    /// Contact stiffness from 1 mm to 0.01 um of penetration, stiction velocity 1e-3 mm/s,
    /// mu 0.01-2 and unequal or zero, radius 0.1 mm-1 m, mass 1e-6-100 kg, omega 0.1-3600
    /// deg/s, start angles near the jam, 0 and 180 deg, a push barely able to move the disc;
    /// each answer classed correct / inaccurate_flagged / failed_named / wrong_unflagged
    /// against the case's physical reference. The chart is the scene `stability-matrix`.
    Stability,
    /// Hold a disc in a V-block: verdict, flank forces, holding capacity, optimum angle.
    ///
    /// A disc of weight m g in a V of two flat flanks (a symmetric V by --included-angle, any
    /// V by --flank-angles), with an external force P at --load-angle, at the centre or at a
    /// rim point. Prints whether the V holds it (wedged, slips, unloaded, lifts_off or held), the
    /// minimum-norm flank forces (N), the largest load P_max (N) held in that direction and
    /// the included angle that best survives errors in load and friction.
    ///
    /// With a range (--mu 0.12:0.3, --mu-left 0.1:0.2, --mu-right 0.3:0.5, --mass 0.3:2, --load
    /// 20:30, --load-angle -10:10) it designs the V over the whole box instead: the window of
    /// included angles that holds every load and weight without self-locking at any friction of
    /// the ranges, the most robust angle in it, or, when no single V works, what would open a
    /// window; and the verdict of your V (if given) and of the standard 60/90/120 deg V-blocks
    /// over the box. A distribution is refused: a robust V holds every value of a range.
    Vlocator,
    /// Serve the live design page and the HTTP API until Ctrl-C.
    ///
    /// The page (GET /) is a design calculator: the scene's settings with their units and
    /// ranges, the answer of `solve` as you type (a number, a range lo:hi or a distribution
    /// normal(m,s) in any field), the universal chart with your point or box marked, and a
    /// V-block tab. The API answers POST /api/v1/solve, /api/v1/design and /api/v1/vlocator
    /// with a JSON body of the Python keywords ({"mu": 0.3, "radius_mm": 12.5}) by the same
    /// JSON document as --format json, and GET /api/v1/render/SCENE.svg?KEY=VALUE draws a
    /// built-in scene (.png, .json, .csv too). No request reads or writes a file. The guide
    /// (`jamchart guide`, the crate docs) lists every route.
    #[cfg(feature = "serve")]
    Serve,
    /// Print a shell completion script (bash, zsh, fish, elvish, powershell).
    ///
    /// bash: `jamchart completions bash > ~/.local/share/bash-completion/completions/jamchart`;
    /// zsh: `jamchart completions zsh > ~/.zfunc/_jamchart` with ~/.zfunc in $fpath before
    /// compinit; fish: `jamchart completions fish > ~/.config/fish/completions/jamchart.fish`.
    Completions,
    /// Print the man page (roff), made from these help texts.
    ///
    /// `jamchart man > jamchart.1 && man ./jamchart.1`; `--out-dir DIR` writes jamchart.1 and a
    /// page per subcommand (jamchart-render.1, ...) for a man1 folder of $MANPATH.
    Man,
}

impl Subcommand for Command {
    fn augment_subcommands(cmd: clap::Command) -> clap::Command {
        // In the listed order (completions and man pages keep it).
        let listed = Listed::augment_subcommands(clap::Command::new("jamchart"));
        let subs = listed.get_subcommands().cloned();
        subs.fold(cmd, |cmd, sub| cmd.subcommand(deferred(sub)))
    }

    fn augment_subcommands_for_update(cmd: clap::Command) -> clap::Command {
        Self::augment_subcommands(cmd)
    }

    fn has_subcommand(name: &str) -> bool {
        Listed::has_subcommand(name)
    }
}

/// Each subcommand that takes flags: its name, its [`Command`] and the type of its flags,
/// listed once for both ways (the flags added when the subcommand is built, read back when
/// it runs).
macro_rules! with_flags {
    ($($(#[$attr:meta])* $name:literal => $variant:ident($args:ty),)*) => {
        /// Listed subcommand `sub`, its flags added when it is built.
        fn deferred(sub: clap::Command) -> clap::Command {
            match sub.get_name() {
                $($(#[$attr])* $name => sub.defer(flags::<$args>),)*
                _ => sub,
            }
        }

        /// Subcommand `name` with its flags read from `sub`; None for a name that takes none.
        fn read_flags(
            name: &str,
            sub: &mut clap::ArgMatches,
        ) -> Option<Result<Command, clap::Error>> {
            use clap::FromArgMatches;
            match name {
                $($(#[$attr])* $name => {
                    Some(<$args>::from_arg_matches_mut(sub).map(Command::$variant))
                })*
                _ => None,
            }
        }
    };
}

with_flags! {
    "solve" => Solve(solve::SolveArgs),
    "design" => Design(design::DesignArgs),
    "table" => Table(table::TableArgs),
    "render" => Render(render::RenderArgs),
    "sweep" => Sweep(sweep::SweepArgs),
    "scenes" => Scenes(render::ScenesArgs),
    "accuracy" => Accuracy(accuracy::AccuracyArgs),
    "stability" => Stability(stability::StabilityArgs),
    "vlocator" => Vlocator(vlocator::VlocatorArgs),
    #[cfg(feature = "serve")]
    "serve" => Serve(serve::ServeArgs),
    "completions" => Completions(shell::CompletionsArgs),
    "man" => Man(shell::ManArgs),
}

/// Subcommand `c` (as [`Listed`] made it) with the flags of `A`, its texts kept: `A`'s own
/// (its doc comment, made for the contributor) would replace them, where the derive that
/// built every subcommand at once set the listed ones after.
fn flags<A: clap::Args>(c: clap::Command) -> clap::Command {
    let (about, long_about) = (c.get_about().cloned(), c.get_long_about().cloned());
    let c = A::augment_args(c);
    let c = match about {
        Some(text) => c.about(text),
        None => c.about(None::<&str>),
    };
    match long_about {
        Some(text) => c.long_about(text),
        None => c.long_about(None::<&str>),
    }
}

impl clap::FromArgMatches for Command {
    fn from_arg_matches(matches: &clap::ArgMatches) -> Result<Self, clap::Error> {
        Self::from_arg_matches_mut(&mut matches.clone())
    }

    fn from_arg_matches_mut(matches: &mut clap::ArgMatches) -> Result<Self, clap::Error> {
        use clap::error::ErrorKind;
        let Some((name, mut sub)) = matches.remove_subcommand() else {
            return Err(clap::Error::raw(
                ErrorKind::MissingSubcommand,
                "a subcommand is required",
            ));
        };
        match (read_flags(&name, &mut sub), name.as_str()) {
            (Some(command), _) => command,
            (None, "settings") => Ok(Command::Settings),
            (None, _) => Err(clap::Error::raw(
                ErrorKind::InvalidSubcommand,
                format!("no subcommand {name}"),
            )),
        }
    }

    fn update_from_arg_matches(&mut self, matches: &clap::ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(matches)?;
        Ok(())
    }
}

/// What a command ends with: its text for stdout, and whether what it checks was found broken.
pub enum Done {
    /// The work is done (exit 0).
    Ok(String),
    /// The work is done and what it checks did not hold (`render --check`: charts changed),
    /// exit 1; `summary` goes to stderr as the one-line `jamchart: ...` message.
    Failed {
        /// The full report, for stdout.
        text: String,
        /// One line naming what failed.
        summary: String,
    },
}

impl From<String> for Done {
    fn from(text: String) -> Self {
        Done::Ok(text)
    }
}

/// Runs the command line and returns the process exit code: 0 success, 1 a check that found
/// changes (`render --check`), 2 bad input or failure.
pub fn main() -> i32 {
    let (cli, name) = match parse(std::env::args_os()) {
        Ok(parsed) => parsed,
        Err(e) => return clap_exit(e),
    };
    // The server writes no file, and its Ctrl-C lets the answers in flight finish: it handles
    // the signals itself.
    #[cfg(feature = "serve")]
    let serving = matches!(cli.command, Command::Serve(_));
    #[cfg(not(feature = "serve"))]
    let serving = false;
    if !serving {
        crate::atomic::install_signal_cleanup();
    }
    let pool = match threads::start() {
        Ok(pool) => pool,
        Err(e) => {
            terminal::diagnostic(&format!("jamchart: {}", describe(&e, &name)));
            return 2;
        }
    };
    #[cfg(feature = "serve")]
    if let Command::Serve(a) = &cli.command {
        return match serve::run(a, pool) {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("jamchart: {}", terminal::safe(&describe(&e, &name)));
                2
            }
        };
    }
    let result: crate::error::Result<Done> = pool.run(|| match &cli.command {
        Command::Solve(a) => solve::run(a).map(Done::from),
        Command::Design(a) => design::run(a).map(Done::from),
        Command::Table(a) => table::run(a).map(Done::from),
        Command::Render(a) => render::run(a),
        Command::Scenes(a) => render::list(a).map(Done::from),
        Command::Settings => Ok(Done::from(crate::settings::reference())),
        Command::Sweep(a) => sweep::run(a).map(Done::from),
        Command::Accuracy(a) => accuracy::run(a).map(Done::from),
        Command::Stability(a) => stability::run(a).map(Done::from),
        Command::Vlocator(a) => vlocator::run(a).map(Done::from),
        Command::Completions(a) => shell::completions(a).map(Done::from),
        Command::Man(a) => shell::man(a).map(Done::from),
        #[cfg(feature = "serve")]
        Command::Serve(_) => Err(Error::Defect("serve runs outside the pool".into())),
    });
    match result {
        Ok(done) => {
            let (text, code) = match &done {
                Done::Ok(text) => (text, 0),
                Done::Failed { text, .. } => (text, 1),
            };
            let printed = print(text);
            if let Done::Failed { summary, .. } = &done {
                terminal::diagnostic(&format!("jamchart: {summary}"));
            }
            // A lost answer (exit 2) outranks a failed check (exit 1).
            printed.max(code)
        }
        Err(e) => {
            terminal::diagnostic(&format!("jamchart: {}", describe(&e, &name)));
            2
        }
    }
}

/// Prints each line as `jamchart: warning: <line>` on stderr: for values that are valid but
/// likely a mistake, where the answer still follows.
pub(crate) fn warn(lines: &[String]) {
    for l in lines {
        terminal::diagnostic(&format!("jamchart: warning: {l}"));
    }
}

/// An answer's `--format json` document: its serde form, pretty, with a final newline.
fn json(answer: &impl serde::Serialize) -> String {
    serde_json::to_string_pretty(answer).expect("answers serialise") + "\n"
}

/// Writes the answer to stdout (control characters escaped: [`terminal::safe`]) and returns
/// the exit code: a failed write (a full disk, `> /dev/full`) lost the answer and is an error,
/// once reported as success with an empty file. A closed pipe (`| head`) is the reader's
/// choice and not worth a message.
fn print(text: &str) -> i32 {
    let mut out = std::io::stdout().lock();
    let text = terminal::safe(text);
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Ok(()) => 0,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => 0,
        Err(e) => {
            terminal::diagnostic(&format!(
                "jamchart: writing the answer to standard output: {e}"
            ));
            2
        }
    }
}

/// Help and version go to stdout as clap prints them; usage errors become one line.
fn clap_exit(e: clap::Error) -> i32 {
    use clap::error::ErrorKind;
    match e.kind() {
        // Help lost to a full disk (`--help > /dev/full`) exited 0, as `print` says.
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => match e.print() {
            Ok(()) => 0,
            Err(err) if err.kind() == std::io::ErrorKind::BrokenPipe => 0,
            Err(err) => {
                terminal::diagnostic(&format!(
                    "jamchart: writing the help to standard output: {err}"
                ));
                2
            }
        },
        // `jamchart` alone: the help is the answer, but it is still a usage error.
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let help = e.render().to_string();
            terminal::diagnostic(help.strip_suffix('\n').unwrap_or(&help));
            2
        }
        _ => {
            let mut rendered = e.render().to_string();
            // clap quotes the value whole: a 20 kB `--set` key made a 20 kB message.
            if let Some(clap::error::ContextValue::String(v)) =
                e.get(clap::error::ContextKind::InvalidValue)
            {
                rendered = rendered.replace(&format!("'{v}'"), &format!("'{}'", error::cut(v)));
            }
            terminal::diagnostic(&format!("jamchart: {}", one_line(&rendered)));
            2
        }
    }
}

/// clap's usage error as one line, keeping what says what to type instead: the accepted values,
/// the missing arguments and the "did you mean" tips (`tip: a similar argument exists: ...`).
fn one_line(rendered: &str) -> String {
    let mut lines = rendered.lines().map(str::trim);
    let first = lines.next().unwrap_or("invalid arguments");
    let mut text = first.strip_prefix("error: ").unwrap_or(first).to_string();
    // "the following required arguments were not provided:" lists them on the next lines.
    let listed = text.ends_with(':');
    for line in lines.take_while(|l| !l.starts_with("Usage:")) {
        // A listed argument is a flag (`--x-target <MM>`) or a positional (`<PARAM=...>...`).
        let argument = listed && (line.starts_with('<') || line.starts_with('-'));
        if line.starts_with("[possible values:") || argument {
            text = format!("{} {line}", text.trim_end_matches(':'));
        } else if let Some(tip) = line.strip_prefix("tip: ") {
            text = format!("{text}; {tip}");
        }
    }
    format!("{text}; see 'jamchart --help'")
}

/// The whole command line with every subcommand's flags added (for help, completions, man
/// pages and the messages that name a flag); a run parses with `Cli::command()`, which adds
/// the flags of the subcommand it runs only.
pub(crate) fn command() -> clap::Command {
    use clap::CommandFactory;
    let mut cmd = Cli::command();
    cmd.build();
    cmd
}

/// The command line parsed, and the name of its subcommand.
fn parse(args: impl IntoIterator<Item = std::ffi::OsString>) -> Result<(Cli, String), clap::Error> {
    use clap::{CommandFactory, FromArgMatches};
    let mut matches = Cli::command().try_get_matches_from(args)?;
    let name = matches.subcommand_name().unwrap_or_default().to_string();
    let cli = Cli::from_arg_matches_mut(&mut matches).map_err(|e| e.format(&mut Cli::command()))?;
    Ok((cli, name))
}

/// The commands' own flags that set a key a message may name (the settings' flags are
/// declared with the settings).
fn own_flags() -> impl Iterator<Item = &'static crate::settings::Decl> + Clone {
    let own: [&'static [crate::settings::Decl]; 5] = [
        accuracy::ACCURACY_FLAGS,
        stability::STABILITY_FLAGS,
        crate::ask::DESIGN_KEYS,
        crate::ask::DIST_KEYS,
        crate::ask::GEOMETRY_KEYS,
    ];
    own.into_iter().flatten()
}

/// The error message of subcommand `command`, with the flags of that command that set the key
/// named beside the key.
fn describe(e: &Error, command: &str) -> String {
    match e {
        Error::InvalidValue { key, value, reason } => {
            let cli = crate::cli::command();
            let sub = cli.find_subcommand(command);
            let takes = |flag: &str| {
                sub.is_some_and(|c| c.get_arguments().any(|a| a.get_long() == Some(flag)))
            };
            match crate::settings::flags_naming(key, own_flags(), takes) {
                Some(flag) => format!("invalid {key} = {value} (flag {flag}): {reason}"),
                None => e.to_string(),
            }
        }
        // A cost names the key that sets it; the command line names its flag.
        Error::TooLong { key, .. } | Error::TooLarge { key, .. } => {
            let cli = crate::cli::command();
            let sub = cli.find_subcommand(command);
            let takes = |flag: &str| {
                sub.is_some_and(|c| c.get_arguments().any(|a| a.get_long() == Some(flag)))
            };
            match crate::settings::flags_naming(key, own_flags(), takes) {
                Some(flag) => e
                    .to_string()
                    .replace(&format!("(set by {key})"), &format!("(set by {flag})")),
                None => e.to_string(),
            }
        }
        _ => e.to_string(),
    }
}
