//! A stopwatch and a deadline that never panic: `std::time::Instant::now()` panics on
//! `wasm32-unknown-unknown` (no clock), so the library times its stages through this.
//! There the elapsed time is always zero: time limits never trigger (iteration limits still
//! bound the work) and reported times read 0.

use std::time::Duration;

/// Time since [`Stopwatch::start`]; zero on targets without a clock.
#[derive(Clone, Copy, Debug)]
pub struct Stopwatch {
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    start: std::time::Instant,
}

impl Stopwatch {
    /// Starts timing now.
    pub fn start() -> Stopwatch {
        Stopwatch {
            #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
            start: std::time::Instant::now(),
        }
    }

    /// Time since the start (zero without a clock).
    pub fn elapsed(&self) -> Duration {
        #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
        let elapsed = self.start.elapsed();
        #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
        let elapsed = Duration::ZERO;
        elapsed
    }
}

/// A time limit on a long computation: [`Deadline::passed`] says when it has run out (a
/// reading of the clock, tens of nanoseconds: cheap beside a step of any search that asks).
/// Without a clock (wasm32) it never passes.
#[derive(Clone, Copy, Debug)]
pub struct Deadline {
    watch: Stopwatch,
    limit: Option<Duration>,
}

impl Deadline {
    /// A deadline `limit` from now; `None` never passes.
    pub fn after(limit: Option<Duration>) -> Deadline {
        Deadline {
            watch: Stopwatch::start(),
            limit,
        }
    }

    /// The limit it was made with.
    pub fn limit(&self) -> Option<Duration> {
        self.limit
    }

    /// Whether the limit has run out.
    pub fn passed(&self) -> bool {
        self.limit.is_some_and(|limit| self.watch.elapsed() > limit)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_deadline_passes_after_its_limit_and_never_without_one() {
        let none = Deadline::after(None);
        let soon = Deadline::after(Some(Duration::from_millis(20)));
        assert!(!soon.passed());
        std::thread::sleep(Duration::from_millis(30));
        assert!(soon.passed());
        assert!(!none.passed());
    }

    #[test]
    fn elapsed_time_grows_with_the_wall_clock() {
        let watch = Stopwatch::start();
        std::thread::sleep(Duration::from_millis(20));
        assert!(watch.elapsed() >= Duration::from_millis(20));
    }
}
