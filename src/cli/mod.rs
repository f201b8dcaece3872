//! Command-line front end: argument parsing and one file per subcommand. Each subcommand
//! returns an [`Outcome`] or an error; [`run`] prints errors as `foldcam: <file>: <problem>` and
//! maps them to exit codes (0 done, 1 a check failed, 2 bad usage or input, or results that
//! could not be written to standard output). Every line goes through [`say`]'s writer; every
//! file through [`outputs`].

#[macro_use]
mod say;
mod args;
mod check;
mod convert;
mod cut;
mod demo;
mod demo_fold3d;
mod demo_jobs;
mod demo_papercraft;
mod demo_tessellation;
mod design_output;
mod fab_args;
mod fold;
mod fold3d;
mod fold_flat;
mod generate;
mod input;
mod list;
mod outputs;
mod papercraft;
mod pipe;
mod plan;
mod popup;
mod popup_input;
mod popup_poly;
mod preview;
mod progress;
mod serve;
mod shell;
mod simulate;
mod tessellate;
mod testgrid;

use std::process::ExitCode;

use clap::{CommandFactory, Parser, Subcommand};

/// What a successful subcommand reports to the shell.
pub enum Outcome {
    /// Everything passed.
    Done,
    /// The work was done but a check failed (exit 1).
    CheckFailed,
}

#[derive(Parser)]
#[command(
    name = "foldcam",
    version,
    about = "Crease patterns to machine files: import, convert, check and preview fold designs",
    long_about = "foldcam reads crease patterns (FOLD 1.2, Origami Simulator and Rabbit Ear SVG, \
                  ORIPA .cp and .opx, DXF), cleans them into planar graphs, checks flat-foldability \
                  (per vertex and by global layer order) and fabrication limits, folds them in 3D, \
                  draws previews and writes them back; it plans them for laser cutters and pen \
                  plotters (perforations, scores, cuts with kerf) and writes G-code, DXF, SVG or \
                  LightBurn projects, checked on a simulated machine. `foldcam serve` opens the \
                  same in the browser.\n\n\
                  Exit status: 0 success, 1 a check failed, 2 bad usage or bad input.",
    after_help = "Examples:\n  foldcam demo\n  foldcam generate miura -o miura.fold\n  \
                  foldcam convert pattern.cp pattern.fold\n  foldcam check pattern.fold --min-vertex-angle 30\n  \
                  foldcam preview pattern.svg -o pattern.png --check\n  \
                  foldcam cut pattern.fold -m grbl-diode -x card-300gsm -o job.gcode\n  \
                  foldcam simulate job.gcode -m grbl-diode --png toolpath.png"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Say only results, warnings and errors (no notes of files written, no progress bars).
    #[arg(long, short, global = true)]
    quiet: bool,
    /// Also say how long the command took and every cause of an error.
    #[arg(long, short, global = true, conflicts_with = "quiet")]
    verbose: bool,
}

#[derive(Subcommand)]
enum Command {
    /// Convert between FOLD, SVG, ORIPA .cp and .opx, and from DXF (formats from the extensions).
    Convert(convert::Args),
    /// Check flat-foldability (Kawasaki, Maekawa) and fabrication limits.
    Check(check::Args),
    /// Draw a crease pattern as a PNG.
    Preview(preview::Args),
    /// Generate a classic pattern: Miura-ori (or a square grid), square twist, waterbomb, Yoshimura.
    Generate(generate::Args),
    /// Plan a pattern for a machine and material and write G-code, DXF, SVG or a LightBurn project.
    Cut(cut::Args),
    /// Print what cutting a pattern would do: lengths, pierces, travel, time.
    Plan(plan::Args),
    /// Run a G-code job on a simulated machine (violations, time, coverage, toolpath PNG).
    Simulate(simulate::Args),
    /// Design pop-up cards (origamic architecture).
    #[command(subcommand)]
    Popup(popup::Command),
    /// Fold a crease pattern flat: write its folded form with a layer order, and a picture.
    FoldFlat(fold_flat::Args),
    /// Fold a sheet step by step from a script (Miyazaki et al. 1992) and write its crease pattern.
    Fold(fold::Args),
    /// Fold any pattern in 3D with a compliant simulation (bar-and-hinge model).
    Fold3d(fold3d::Args),
    /// Make paper-craft parts from developable patches and cut lines on a mesh.
    Papercraft(papercraft::Args),
    /// Run the whole pipeline on bundled examples and write the results to a folder.
    Demo(demo::Args),
    /// Make a freeform origami tessellation (star tucks) from an OBJ/STL mesh.
    Tessellate(tessellate::Args),
    /// List the shipped machine or material profiles.
    List(list::Args),
    /// Write a calibration grid of perforated creases over dash, bridge, power and speed.
    Testgrid(testgrid::Args),
    /// Open patterns in the browser: the local web studio (check, fold in 3D, plan, cut).
    Serve(serve::Args),
    /// Print a shell completion script (bash, zsh, fish, powershell, elvish).
    Completions(shell::CompletionsArgs),
    /// Print the manual page (roff), or write one page per command into a folder.
    Man(shell::ManArgs),
}

impl Command {
    /// `--to` of the commands that write files.
    fn to(&self) -> Option<String> {
        let to = match self {
            Command::Convert(a) => &a.stdout,
            Command::Cut(a) => &a.stdout,
            Command::Fold(a) => &a.stdout,
            Command::Fold3d(a) => &a.stdout,
            Command::FoldFlat(a) => &a.stdout,
            Command::Generate(a) => &a.stdout,
            Command::Papercraft(a) => &a.stdout,
            Command::Preview(a) => &a.stdout,
            Command::Simulate(a) => &a.stdout,
            Command::Tessellate(a) => &a.stdout,
            Command::Testgrid(a) => &a.stdout,
            Command::Popup(popup::Command::Voxel(a)) => &a.stdout,
            Command::Popup(popup::Command::Poly(a)) => &a.stdout,
            Command::Check(_)
            | Command::Plan(_)
            | Command::Demo(_)
            | Command::List(_)
            | Command::Serve(_)
            | Command::Completions(_)
            | Command::Man(_) => return None,
        };
        to.to.clone()
    }
}

/// Parses the command line, runs the subcommand and returns its exit code.
pub fn run() -> ExitCode {
    pipe::quiet_on_broken_pipe();
    // A run stopped by Ctrl-C or SIGTERM leaves no temporary files behind and writes nothing.
    let _ = ctrlc::set_handler(|| {
        foldcam::formats::remove_pending_temporaries();
        errln!("foldcam: interrupted; nothing more was written");
        std::process::exit(130);
    });
    let cli = Cli::parse();
    say::set(cli.quiet, cli.verbose);
    pipe::set_to(cli.command.to());
    let started = std::time::Instant::now();
    let result = match cli.command {
        Command::Convert(a) => convert::run(a),
        Command::Check(a) => check::run(a),
        Command::Preview(a) => preview::run(a),
        Command::Generate(a) => generate::run(a),
        Command::Cut(a) => cut::run(a),
        Command::Plan(a) => plan::run(a),
        Command::Simulate(a) => simulate::run(a),
        Command::Popup(c) => popup::run(c),
        Command::Papercraft(a) => papercraft::run(a),
        Command::Demo(a) => demo::run(a),
        Command::Tessellate(a) => tessellate::run(a),
        Command::Fold(a) => fold::run(a),
        Command::List(a) => list::run(a),
        Command::FoldFlat(a) => fold_flat::run(a),
        Command::Fold3d(a) => fold3d::run(a),
        Command::Testgrid(a) => testgrid::run(a),
        Command::Serve(a) => serve::run(a),
        Command::Completions(a) => shell::completions(a, Cli::command()),
        Command::Man(a) => shell::man(a, Cli::command()),
    };
    if say::verbose() {
        errln!("foldcam: took {:.2} s", started.elapsed().as_secs_f64());
    }
    // Results that did not reach standard output make the run fail, whatever the command said.
    let result = match (result, say::finish()) {
        (Ok(_), Err(e)) => Err(anyhow::anyhow!(
            "standard output: {e}: the results were not all written"
        )),
        (result, _) => result,
    };
    match result {
        Ok(Outcome::Done) => ExitCode::SUCCESS,
        Ok(Outcome::CheckFailed) => ExitCode::from(1),
        Err(e) => {
            errln!("foldcam: {}", message(&e));
            if say::verbose() {
                for (i, cause) in e.chain().enumerate() {
                    errln!("  cause {i}: {cause}");
                }
            }
            ExitCode::from(2)
        }
    }
}

/// The error and its causes joined with ": ", leaving out a cause whose text the message
/// already holds (library errors often print their source themselves).
fn message(e: &anyhow::Error) -> String {
    let mut text = String::new();
    for cause in e.chain() {
        let part = cause.to_string();
        if !text.contains(&part) {
            if !text.is_empty() {
                text.push_str(": ");
            }
            text.push_str(&part);
        }
    }
    text
}
