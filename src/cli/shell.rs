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
pub fn completions(a: &CompletionsArgs) -> Result<String> {
    let mut cmd = Cli::command();
    let mut out = Vec::new();
    clap_complete::generate(a.shell, &mut cmd, "jamchart", &mut out);
    utf8(out)
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
    cmds.extend(cmd.get_subcommands().filter(|s| !s.is_hide_set()).cloned());
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
    Ok(paths.iter().map(|p| format!("{}\n", p.display())).collect())
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
