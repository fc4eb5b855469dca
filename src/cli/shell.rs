//! `jamchart completions SHELL` and `jamchart man`: made from the clap definitions, so they
//! list exactly the subcommands and flags the binary takes.

use std::path::PathBuf;

use clap::{Args, CommandFactory};

use super::Cli;
use crate::atomic::{Output, write_all};
use crate::error::{Error, Result};

/// Flags of `completions`.
#[derive(Debug, Clone, Args)]
pub struct CompletionsArgs {
    /// The shell to complete in.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
}

/// The completion script for `a.shell`.
///
/// A positional whose possible values are hidden from its help takes them as candidates, not
/// as its only values (render's scenes: a built-in name, or any scene file): bash offers the
/// names and falls back to files, zsh gets files beside the names (clap's script offers the
/// names alone), fish gets the names added (clap's script completes no positional).
pub fn completions(a: &CompletionsArgs) -> Result<String> {
    let mut cmd = Cli::command();
    let mut out = Vec::new();
    clap_complete::generate(a.shell, &mut cmd, "jamchart", &mut out);
    let mut script = utf8(out)?;
    for (sub, names) in candidates(&cmd) {
        let names = names.join(" ");
        match a.shell {
            clap_complete::Shell::Zsh => {
                script = script.replace(
                    &format!(":({names})'"),
                    &format!(
                        ":{{_alternative \"names:built-in name:({names})\" \"files:file:_files\"}}'"
                    ),
                )
            }
            clap_complete::Shell::Fish => script.push_str(&format!(
                "complete -c jamchart -n \"__fish_jamchart_using_subcommand {sub}\" -a \"{names}\"\n"
            )),
            _ => {}
        }
    }
    Ok(script)
}

/// Each subcommand's candidates of a positional (possible values hidden from its help), by
/// the subcommand's name.
fn candidates(cmd: &clap::Command) -> Vec<(String, Vec<String>)> {
    cmd.get_subcommands()
        .flat_map(|sub| {
            sub.get_positionals()
                .filter(|a| a.is_hide_possible_values_set())
                .map(|a| {
                    let values = a.get_possible_values();
                    let names = values.iter().map(|v| v.get_name().to_string());
                    (sub.get_name().to_string(), names.collect())
                })
        })
        .collect()
}

/// Flags of `man`.
#[derive(Debug, Clone, Args)]
pub struct ManArgs {
    /// Write jamchart.1 and a page per subcommand (jamchart-render.1, ...) into this folder
    /// instead of printing jamchart.1.
    #[arg(long, value_name = "DIR")]
    pub out_dir: Option<PathBuf>,
}

/// The man pages: `jamchart.1`, then one per subcommand (`jamchart-render.1`, ...), as file
/// name and roff.
fn pages() -> Result<Vec<(String, Vec<u8>)>> {
    let mut cmd = Cli::command().disable_help_subcommand(true);
    // Built, the subcommands carry their display names (`jamchart-render`): the pages' names.
    cmd.build();
    let mut cmds = vec![cmd.clone()];
    cmds.extend(
        cmd.get_subcommands()
            .filter(|s| !s.is_hide_set())
            .map(|s| s.clone().override_usage(synopsis(s))),
    );
    cmds.into_iter()
        .map(|c| {
            let man = clap_mangen::Man::new(c);
            let mut roff = Vec::new();
            man.render(&mut roff)
                .map_err(|e| Error::io("write", man.get_filename(), e))?;
            Ok((man.get_filename(), roff))
        })
        .collect()
}

/// A subcommand's synopsis with the values of its flags: `jamchart solve [--model
/// <statics|min-norm|dynamics|all>] [--mu <MU>] ...` (clap_mangen's lists the flags alone).
/// A flag with named values lists them, any other its value name.
fn synopsis(cmd: &clap::Command) -> String {
    let name = cmd.get_bin_name().unwrap_or_else(|| cmd.get_name());
    let mut words = vec![name.to_string()];
    // Flags first, then the positionals, as clap's usage writes them.
    let (positionals, flags): (Vec<&clap::Arg>, Vec<&clap::Arg>) = cmd
        .get_arguments()
        .filter(|a| !a.is_hide_set())
        .partition(|a| a.is_positional());
    for a in flags.into_iter().chain(positionals) {
        let names = a.get_value_names().map(|n| n.join(" "));
        let values: Vec<String> = match a.is_hide_possible_values_set() {
            true => Vec::new(),
            false => (a.get_possible_values().iter())
                .filter(|v| !v.is_hide_set())
                .map(|v| v.get_name().to_string())
                .collect(),
        };
        let value = match values.is_empty() {
            true => names.unwrap_or_else(|| a.get_id().as_str().to_ascii_uppercase()),
            false => values.join("|"),
        };
        let takes = a.get_num_args().is_some_and(|n| n.takes_values());
        let word = match (a.get_short(), a.get_long()) {
            _ if a.is_positional() => value,
            (Some(s), Some(l)) => format!("-{s}|--{l}"),
            (None, Some(l)) if takes => format!("--{l} <{value}>"),
            (None, Some(l)) => format!("--{l}"),
            (Some(s), None) => format!("-{s}"),
            (None, None) => continue,
        };
        let many = a.is_positional() && a.get_num_args().is_some_and(|n| n.max_values() > 1);
        let dots = if many { "..." } else { "" };
        words.push(match a.is_required_set() {
            true => format!("{word}{dots}"),
            false => format!("[{word}]{dots}"),
        });
    }
    words.join(" ")
}

/// `jamchart man`: jamchart.1 on stdout, or every page into `--out-dir`.
pub fn man(a: &ManArgs) -> Result<String> {
    let pages = pages()?;
    let Some(dir) = &a.out_dir else {
        let (_, roff) = pages.into_iter().next().expect("the main page comes first");
        return utf8(roff);
    };
    let paths: Vec<PathBuf> = pages.iter().map(|(name, _)| dir.join(name)).collect();
    let set: Vec<Output> = paths
        .iter()
        .zip(&pages)
        .map(|(path, (_, roff))| Output::bytes(path, roff))
        .collect();
    write_all(&set)?;
    Ok(paths
        .iter()
        .map(|p| format!("{}\n", super::terminal::path(p)))
        .collect())
}

fn utf8(bytes: Vec<u8>) -> Result<String> {
    String::from_utf8(bytes).map_err(|e| {
        Error::io(
            "write",
            "the generated text",
            std::io::Error::new(std::io::ErrorKind::InvalidData, e),
        )
    })
}
