//! Standard input and output, as Unix tools and vpype use them: `-` as an input reads standard
//! input in the format `--from` names, `-` as an output writes standard output in the format
//! `--to` names (`foldcam convert - out.fold --from cp < in.cp`, `foldcam cut in.fold -m
//! grbl-diode -x card-300gsm -o - --to gcode | head`). While standard output carries a file,
//! every message goes to standard error.
//!
//! A closed pipe (`… | head -1`) ends the program quietly with exit status 0, as Unix tools
//! do, instead of a panic (exit 101).

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, Ordering};

use anyhow::{Context, Result, anyhow, bail};
use foldcam::formats::{self, Format, Imported};

/// What `-` stands for in file arguments.
pub const STDIO: &str = "-";

/// `--to` as given.
static TO: OnceLock<Option<String>> = OnceLock::new();
/// The name standing for standard output once an output `-` was resolved (`-.EXT`).
static STDOUT_NAME: OnceLock<PathBuf> = OnceLock::new();
/// Whether standard output carries a file (then messages go to standard error).
static STDOUT_TAKEN: AtomicBool = AtomicBool::new(false);

/// `--to`, for the commands that write files (`--from` is read with the input, in
/// `input::FrameArg`).
#[derive(clap::Args, Clone, Debug, Default)]
pub struct ToArg {
    /// Format of an output given as `-` (standard output), by its extension: fold, svg, cp,
    /// opx; gcode, nc, ngc, dxf, svg, lbrn2 for jobs; png for pictures.
    #[arg(long, value_name = "FORMAT")]
    pub to: Option<String>,
}

/// Records `--to` (once, at start-up).
pub fn set_to(to: Option<String>) {
    let _ = TO.set(to);
}

/// Whether `path` is `-`.
pub fn is_stdio(path: &Path) -> bool {
    path.as_os_str() == STDIO
}

/// Whether standard output carries a file, so results and messages belong on standard error.
pub fn stdout_taken() -> bool {
    STDOUT_TAKEN.load(Ordering::Relaxed)
}

/// A file name a command uses for standard output: `-` becomes `-.EXT` with the extension
/// `--to` names (so the format is chosen as for any file), other names stay as they are.
pub fn output(path: &Path) -> Result<PathBuf> {
    if !is_stdio(path) {
        return Ok(path.to_path_buf());
    }
    let to = TO.get().cloned().flatten().ok_or_else(|| {
        anyhow!(
            "-: writing to standard output needs --to FORMAT (the extension the file would \
             have: fold, svg, cp, opx, gcode, nc, ngc, dxf, lbrn2, png)"
        )
    })?;
    if to.is_empty() || !to.chars().all(|c| c.is_ascii_alphanumeric()) {
        bail!("--to {to}: name a format by its extension, e.g. gcode, svg, fold");
    }
    let name = STDOUT_NAME.get_or_init(|| PathBuf::from(format!("{STDIO}.{to}")));
    STDOUT_TAKEN.store(true, Ordering::Relaxed);
    Ok(name.clone())
}

/// Whether `path` is the name [`output`] gave standard output.
pub fn is_stdout(path: &Path) -> bool {
    STDOUT_NAME.get().is_some_and(|n| n == path)
}

/// Writes `bytes` to standard output.
pub fn write_stdout(bytes: &[u8]) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(bytes).and_then(|()| out.flush()) {
        // The reader went away (`… | head`): done, as Unix tools are.
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => std::process::exit(0),
        other => other.context("standard output"),
    }
}

/// The pattern format `--from` names.
fn from_format(from: Option<&str>) -> Result<Format> {
    let from = from.ok_or_else(|| {
        anyhow!("-: reading standard input needs --from FORMAT (fold, svg, cp, opx or dxf)")
    })?;
    Format::from_path(Path::new(&format!("x.{from}")))
        .ok_or_else(|| anyhow!("--from {from}: expected fold, svg, cp, opx or dxf"))
}

/// Reads a pattern from standard input in the `--from` format (a FOLD file's frame
/// `options.frame`), validated as a file would be ([`formats::load_bytes`]).
pub fn load_stdin(from: Option<&str>, options: &formats::ReadOptions) -> Result<Imported> {
    let format = from_format(from)?;
    let mut bytes = Vec::new();
    std::io::stdin()
        .lock()
        .read_to_end(&mut bytes)
        .context("standard input")?;
    Ok(formats::load_bytes(
        Path::new("standard input"),
        format,
        &bytes,
        options,
    )?)
}

/// Installs a panic hook that exits with status 0 when printing to standard output failed
/// because the reader went away, and reports every other panic as before.
pub fn quiet_on_broken_pipe() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let payload = info.payload();
        let text = payload
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| payload.downcast_ref::<&str>().copied())
            .unwrap_or("");
        if text.starts_with("failed printing to std") && text.contains("Broken pipe") {
            std::process::exit(0);
        }
        previous(info);
    }));
}
