//! `foldcam list machines|materials`: the shipped profiles, one line each.

use anyhow::Result;
use foldcam::machine::{self, profile_catalogue};

use super::Outcome;

/// What to list.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum What {
    /// Machine profiles (machines/NAME.toml).
    Machines,
    /// Material profiles (machines/materials/NAME.toml).
    Materials,
}

/// List the shipped machine or material profiles.
#[derive(clap::Args)]
#[command(
    long_about = "Lists the machine or material profiles shipped with foldcam (embedded in the \
                  binary): name, one-line description and the file it comes from. Give a \
                  path to a .toml file instead of a name to use your own profile.",
    after_help = "Examples:\n  foldcam list machines\n  foldcam list materials"
)]
pub struct Args {
    /// machines or materials.
    #[arg(value_enum)]
    pub what: What,
}

/// Prints the list.
pub fn run(args: Args) -> Result<Outcome> {
    let kind = match args.what {
        What::Machines => machine::ProfileKind::Machine,
        What::Materials => machine::ProfileKind::Material,
    };
    let entries = profile_catalogue(kind)?;
    let width = entries.iter().map(|e| e.name.len()).max().unwrap_or(0);
    for e in entries {
        let defaults = match e.defaults.as_str() {
            "" => String::new(),
            d => format!("; by default {d}"),
        };
        outln!(
            "{:width$}  {}{defaults}  [{}]",
            e.name,
            e.description,
            e.source
        );
    }
    Ok(Outcome::Done)
}
