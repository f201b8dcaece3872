//! How much the program says: `--quiet` keeps to results, warnings and errors; `--verbose`
//! adds how long the command took and every cause of an error. Notes (files written, what a
//! reader or the cleaner did, progress bars) go to standard error through [`note!`]; results
//! go to standard output through [`outln!`] and [`out!`], or to standard error while standard
//! output carries a file (`-o - --to gcode`).
//!
//! Every line the program prints goes through [`out`] or [`err`]: an error writing standard
//! output (a full disk, a device error) is kept and reported by [`finish`] as exit status 2,
//! a closed pipe ends the program quietly (status 0), and standard error's own failures are
//! ignored; none of them panics.

use std::io::{ErrorKind, Write};
use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::{Mutex, PoisonError};

/// 0 quiet, 1 normal, 2 verbose.
static LEVEL: AtomicU8 = AtomicU8::new(1);

/// Sets the level from the global flags.
pub fn set(quiet: bool, verbose: bool) {
    let level = match (quiet, verbose) {
        (true, _) => 0,
        (false, true) => 2,
        (false, false) => 1,
    };
    LEVEL.store(level, Ordering::Relaxed);
}

/// Whether `--quiet` was given.
pub fn quiet() -> bool {
    LEVEL.load(Ordering::Relaxed) == 0
}

/// Whether `--verbose` was given.
pub fn verbose() -> bool {
    LEVEL.load(Ordering::Relaxed) == 2
}

/// Standard output's first write error (other than a closed pipe), reported by [`finish`].
static OUT_ERROR: Mutex<Option<std::io::Error>> = Mutex::new(None);

fn out_error() -> std::sync::MutexGuard<'static, Option<std::io::Error>> {
    OUT_ERROR.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Keeps the first error standard output gave; a closed pipe (`… | head`) ends the program
/// quietly with exit status 0, as Unix tools do.
fn record(e: std::io::Error) {
    if e.kind() == ErrorKind::BrokenPipe {
        std::process::exit(0);
    }
    out_error().get_or_insert(e);
}

/// Writes a result to standard output, or to standard error while standard output carries a
/// file. A write error is kept for [`finish`] (the rest of the results are then dropped)
/// instead of a panic; see [`outln!`].
pub fn out(args: std::fmt::Arguments<'_>) {
    if super::pipe::stdout_taken() {
        err(args);
        return;
    }
    if out_error().is_some() {
        return;
    }
    if let Err(e) = std::io::stdout().lock().write_fmt(args) {
        record(e);
    }
}

/// Writes a message to standard error; an error there has nowhere to be reported and is
/// ignored (the exit status still tells); see [`note!`] and [`errln!`].
pub fn err(args: std::fmt::Arguments<'_>) {
    let _ = std::io::stderr().lock().write_fmt(args);
}

/// Flushes standard output and returns the first error it gave, if any: the command's
/// results did not all arrive.
pub fn finish() -> Result<(), std::io::Error> {
    if let Err(e) = std::io::stdout().lock().flush() {
        record(e);
    }
    match out_error().take() {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// A message on standard error (`eprintln!` arguments), through [`err`].
macro_rules! errln {
    ($($arg:tt)*) => {
        $crate::cli::say::err(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// A note on standard error (`eprintln!` arguments), left out with `--quiet`.
macro_rules! note {
    ($($arg:tt)*) => {
        if !$crate::cli::say::quiet() {
            errln!($($arg)*);
        }
    };
}

/// A result line: on standard output, or on standard error while standard output carries a
/// file; through [`out`], so a full disk is an error and not a panic.
macro_rules! outln {
    ($($arg:tt)*) => {
        $crate::cli::say::out(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// [`outln!`] without the newline.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::cli::say::out(format_args!($($arg)*))
    };
}
