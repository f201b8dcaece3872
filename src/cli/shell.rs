//! Shell integration: `foldcam completions SHELL` prints a completion script for bash, zsh,
//! fish, PowerShell or elvish (clap_complete), `foldcam man` prints the manual page in roff
//! (clap_mangen), both generated from the same definitions as `--help`.

use std::path::PathBuf;

use anyhow::{Context, Result};
use clap_complete::Shell;

use super::Outcome;

/// Print a shell completion script.
#[derive(clap::Args)]
#[command(
    long_about = "Prints a completion script for SHELL on standard output, generated from the \
                  same definitions as --help. Install it where your shell looks for completions.",
    after_help = "Examples:\n  foldcam completions bash > ~/.local/share/bash-completion/completions/foldcam\n  \
                  foldcam completions zsh > ~/.zfunc/_foldcam      # with fpath+=~/.zfunc before compinit\n  \
                  foldcam completions fish > ~/.config/fish/completions/foldcam.fish\n  \
                  foldcam completions powershell >> $PROFILE"
)]
pub struct CompletionsArgs {
    /// The shell: bash, zsh, fish, powershell or elvish.
    pub shell: Shell,
}

/// Print the manual page.
#[derive(clap::Args)]
#[command(
    long_about = "Prints the manual page of foldcam (roff, for man) on standard output, or \
                  writes one page per command into a folder with --dir (foldcam.1, \
                  foldcam-cut.1, …).",
    after_help = "Examples:\n  foldcam man | man -l -\n  \
                  foldcam man --dir ~/.local/share/man/man1"
)]
pub struct ManArgs {
    /// Write foldcam.1 and one page per command (foldcam-COMMAND.1) into this folder.
    #[arg(long, value_name = "DIR")]
    pub dir: Option<PathBuf>,
}

/// Prints the completion script of `command` for the chosen shell.
pub fn completions(args: CompletionsArgs, mut command: clap::Command) -> Result<Outcome> {
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut command, "foldcam", &mut script);
    super::pipe::write_stdout(&script)?;
    Ok(Outcome::Done)
}

/// Prints the man page of `command`, or writes every page into `--dir`.
pub fn man(args: ManArgs, command: clap::Command) -> Result<Outcome> {
    match args.dir {
        None => {
            let mut page = Vec::new();
            clap_mangen::Man::new(command)
                .render(&mut page)
                .context("man page")?;
            super::pipe::write_stdout(&page)?;
        }
        Some(dir) => {
            super::outputs::no_stdout(&dir, "--dir, a folder of pages,")?;
            std::fs::create_dir_all(&dir).with_context(|| dir.display().to_string())?;
            clap_mangen::generate_to(command, &dir).with_context(|| dir.display().to_string())?;
            note!("foldcam: wrote the manual pages into {}", dir.display());
        }
    }
    Ok(Outcome::Done)
}
