//! How much the program says: `--quiet` keeps to results, warnings and errors; `--verbose`
//! adds how long the command took and every cause of an error. Notes (files written, what a
//! reader or the cleaner did, progress bars) go to standard error through [`note!`]; results
//! go to standard output through [`outln!`] and [`out!`], or to standard error while standard
//! output carries a file (`-o - --to gcode`).

use std::sync::atomic::{AtomicU8, Ordering};

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

/// A note on standard error (`eprintln!` arguments), left out with `--quiet`.
macro_rules! note {
    ($($arg:tt)*) => {
        if !$crate::cli::say::quiet() {
            eprintln!($($arg)*);
        }
    };
}

/// A result line: on standard output, or on standard error while standard output carries a
/// file.
macro_rules! outln {
    ($($arg:tt)*) => {
        if $crate::cli::pipe::stdout_taken() {
            eprintln!($($arg)*);
        } else {
            println!($($arg)*);
        }
    };
}

/// [`outln!`] without the newline.
macro_rules! out {
    ($($arg:tt)*) => {
        if $crate::cli::pipe::stdout_taken() {
            eprint!($($arg)*);
        } else {
            print!($($arg)*);
        }
    };
}
