//! A stopwatch that never panics: `std::time::Instant::now()` panics on
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elapsed_time_grows_with_the_wall_clock() {
        let watch = Stopwatch::start();
        std::thread::sleep(Duration::from_millis(20));
        assert!(watch.elapsed() >= Duration::from_millis(20));
    }
}
