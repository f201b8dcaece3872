//! Progress on standard error for steps that can take more than a second (indicatif): a bar
//! where the amount of work is known, a spinner with the elapsed time where it is not. Both
//! draw nothing when standard error is not a terminal, so logs and pipes stay clean.

use std::time::{Duration, Instant};

use foldcam::check::layers::LayerProgress;
use foldcam::design::source::tessellate::{SolvePlan, SolveTracker};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A bar over `len` units of work, labelled `what`.
pub fn bar(len: u64, what: &str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(len), target());
    let style = ProgressStyle::with_template("{msg} [{bar:32}] {percent}% {elapsed} (eta {eta})")
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> ");
    bar.set_style(style);
    bar.set_message(what.to_string());
    bar
}

/// A bar over a solve's `len` iterations whose message says where the tessellation stands
/// ([`SolveTracker::status`]: the solve of the schedule, the residual, the time left).
fn solve_bar(len: u64) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(len), target());
    let style = ProgressStyle::with_template("[{bar:24}] iteration {pos}/{len} {elapsed}: {msg}")
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> ");
    bar.set_style(style);
    bar
}

/// Runs a layer search `work` (its options holding `progress`) on a scoped thread while a
/// spinner says where it is ([`LayerProgress::describe`]: the stage, the component, the
/// states found so far), and returns what `work` returned.
pub fn watching_layers<T: Send>(progress: &LayerProgress, work: impl FnOnce() -> T + Send) -> T {
    let bar = spinner("searching layer orders");
    let out = std::thread::scope(|s| {
        let worker = s.spawn(work);
        while !worker.is_finished() {
            bar.set_message(format!("layer orders: {}", progress.describe()));
            std::thread::sleep(Duration::from_millis(100));
        }
        worker.join()
    });
    bar.finish_and_clear();
    out.unwrap_or_else(|panic| std::panic::resume_unwind(panic))
}

/// A spinner for work of unknown length, labelled `what`, ticking on its own.
pub fn spinner(what: &str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(None, target());
    let style = ProgressStyle::with_template("{spinner} {msg} {elapsed}")
        .unwrap_or_else(|_| ProgressStyle::default_spinner());
    bar.set_style(style);
    bar.set_message(what.to_string());
    bar.enable_steady_tick(Duration::from_millis(120));
    bar
}

/// Standard error, or nowhere with `--quiet`.
fn target() -> ProgressDrawTarget {
    if super::say::quiet() {
        ProgressDrawTarget::hidden()
    } else {
        ProgressDrawTarget::stderr()
    }
}

/// What a design build ([`foldcam::design::source`]) says while it runs, on standard error:
/// notes as `foldcam: …` lines, long work as a spinner, or as a bar over `iterations` when
/// the solver's iterations are counted (each iteration's line printed above the bar).
#[derive(Default)]
pub struct DesignProgress {
    /// The solver's iteration cap, when a bar should count iterations.
    pub iterations: Option<u64>,
    bar: Option<ProgressBar>,
    /// Where a tessellation stands, and when it started (set on `busy`).
    tracker: Option<(SolveTracker, Option<Instant>)>,
}

impl DesignProgress {
    /// A bar over each solve's iterations of `plan`, with the solve, the residual and the
    /// time left in its message.
    pub fn solving(plan: SolvePlan) -> DesignProgress {
        DesignProgress {
            iterations: Some(plan.max_iterations as u64),
            bar: None,
            tracker: Some((SolveTracker::new(plan), None)),
        }
    }
}

impl foldcam::design::source::Progress for DesignProgress {
    fn note(&mut self, note: foldcam::design::source::BuildNote) {
        // Every text line of a note (curvature advice holds several) after `foldcam: `.
        let text = note.to_string();
        let print = || {
            for line in text.lines() {
                errln!("foldcam: {line}");
            }
        };
        match &self.bar {
            Some(bar) => bar.suspend(print),
            None => print(),
        }
    }

    fn busy(&mut self, what: &str) {
        self.bar = Some(match (self.iterations, &mut self.tracker) {
            (Some(n), Some((_, started))) => {
                *started = Some(Instant::now());
                solve_bar(n)
            }
            (Some(n), None) => bar(n, what),
            (None, _) => spinner(what),
        });
    }

    fn idle(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }

    fn next_solve(&mut self) {
        if let Some((tracker, Some(started))) = &mut self.tracker {
            tracker.next_solve(started.elapsed().as_secs_f64());
        }
    }

    fn iteration(&mut self, it: &foldcam::design::tessellation::Iteration) {
        let line = foldcam::design::source::tessellate::iteration_line(it);
        match &self.bar {
            Some(bar) => {
                bar.set_position(it.index as u64);
                if let Some((tracker, Some(started))) = &mut self.tracker {
                    tracker.iteration(it, started.elapsed().as_secs_f64());
                    bar.set_message(tracker.status());
                }
                bar.suspend(|| errln!("{line}"));
            }
            None => errln!("{line}"),
        }
    }
}
