//! An up-front estimate of a tessellation's time and memory (Tachi 2014: the generalized
//! Newton–Raphson iterations on the star-tuck constraints), printed before the work starts:
//! the time from the solver's measured history ([`LadderEstimate`]), the memory of one solve
//! from the face count ([`solve_bytes`], which the studio also reserves before solving).

use crate::design::estimate::about;
use crate::design::tessellation::TuckKind;

/// Bytes per mesh face, measured on the release build with gently curved quad grids of 100
/// to 2,025 faces at the stainless limits (10 to 85 MB).
pub const BYTES_PER_FACE: f64 = 38e3;
/// Memory of the program before the solve, bytes.
pub const BASE_BYTES: f64 = 8e6;

/// The memory one solve over a mesh of `faces` faces takes, bytes (the ladder's solves run
/// one after another).
pub fn solve_bytes(faces: usize) -> f64 {
    BASE_BYTES + BYTES_PER_FACE * faces as f64
}

/// What the solver's measured history says a whole face-shrink ladder takes (every solve until
/// a usable result, or all of them), by tuck kind and solved face count: iterations × seconds
/// per iteration.
///
/// The history is `examples/tessellation_survey.rs` (saddles of three curvatures, a height
/// field, a cylinder, a torus patch, a bell, spherical and UV caps of 408 to 10,092 faces, a
/// Stanford bunny patch; release build, two cores, 0.5 mm stainless limits): the iterations of
/// every ladder that ended before the time limit (median and largest), and the seconds per
/// iteration (the ladder's time over its iterations, so unfolding and the intersection check
/// are included) fitted as `a · faces^b` over the solved face counts 138 to 2,022, within a
/// factor of 1.5 (twisted stars, twist folds) to 2.3 (truncated stars) of every run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LadderEstimate {
    /// The tuck kind.
    pub kind: TuckKind,
    /// Faces of the first triangulation solved.
    pub faces: usize,
    /// Iterations a ladder of this kind took in the history: median and largest.
    pub iterations: (usize, usize),
    /// Seconds per iteration at `faces`; `None` above [`MAX_MEASURED_FACES`].
    pub seconds_per_iteration: Option<f64>,
    /// Memory of one solve, bytes ([`solve_bytes`]).
    pub bytes: f64,
}

/// The largest solved face count the history covers (a smaller mesh is no slower per
/// iteration than the smallest measured, so the fit is used below the range too).
pub const MAX_MEASURED_FACES: usize = 2_100;

/// `(a, b, median iterations, largest iterations)` of [`LadderEstimate`] per tuck kind.
fn history(kind: TuckKind) -> (f64, f64, usize, usize) {
    match kind {
        TuckKind::Star => (1.54e-5, 1.23, 129, 966),
        TuckKind::Truncated => (2.47e-5, 1.05, 116, 515),
        TuckKind::Twisted => (3.07e-5, 1.20, 228, 751),
        TuckKind::TwistFold => (4.99e-5, 1.00, 22, 156),
    }
}

/// The [`LadderEstimate`] of `kind` tucks on a first triangulation of `faces` faces.
pub fn ladder_estimate(kind: TuckKind, faces: usize) -> LadderEstimate {
    let (a, b, median, most) = history(kind);
    LadderEstimate {
        kind,
        faces,
        iterations: (median, most),
        seconds_per_iteration: (faces <= MAX_MEASURED_FACES)
            .then(|| a * (faces.max(1) as f64).powf(b)),
        bytes: solve_bytes(faces),
    }
}

impl LadderEstimate {
    /// Seconds of a typical ladder and of the longest measured, when the face count is
    /// within the history.
    pub fn seconds(&self) -> Option<(f64, f64)> {
        self.seconds_per_iteration
            .map(|s| (s * self.iterations.0 as f64, s * self.iterations.1 as f64))
    }
}

impl std::fmt::Display for LadderEstimate {
    /// "about 4 s, up to about 31 s (star tucks took 129 iterations, at most 966, on the
    /// measured meshes; 33 ms each at 800 faces) and 38 MB".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (median, most) = self.iterations;
        match (self.seconds(), self.seconds_per_iteration) {
            (Some((typical, longest)), Some(each)) => write!(
                f,
                "{}, up to {} ({} tucks took {median} iterations, at most {most}, on the \
                 measured meshes; {:.0} ms each at {} faces) and {:.0} MB",
                about(typical),
                about(longest),
                self.kind,
                1e3 * each,
                self.faces,
                self.bytes / 1e6
            ),
            _ => write!(
                f,
                "time not known: no measured history at {} faces (measured up to \
                 {MAX_MEASURED_FACES}; {} tucks took {median} iterations, at most {most}); \
                 {:.0} MB",
                self.faces,
                self.kind,
                self.bytes / 1e6
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{LadderEstimate, TuckKind, ladder_estimate, solve_bytes};

    /// The history's own runs, re-read through the model: the star ladder on the 2,028-face
    /// 52° cap (solved on 804 faces, 966 iterations, 31.6 s) lies within its range, the
    /// 216-face saddle (64 iterations, 0.7 s) too; a face count outside the history is said
    /// to be unknown, not guessed.
    #[test]
    fn the_ladder_estimate_brackets_the_measured_runs_and_says_when_it_cannot() {
        let cap = ladder_estimate(TuckKind::Star, 804);
        let (typical, longest) = cap.seconds().expect("measured");
        assert!(typical < 31.6 && 31.6 < 1.5 * longest, "{cap}");
        let saddle = ladder_estimate(TuckKind::Star, 216);
        let (typical, _) = saddle.seconds().expect("measured");
        assert!((0.2..3.0).contains(&typical), "{saddle}");
        let big: LadderEstimate = ladder_estimate(TuckKind::TwistFold, 10_092);
        assert_eq!(big.seconds(), None);
        assert!(big.to_string().starts_with("time not known"), "{big}");
        assert!(cap.to_string().contains("966"), "{cap}");
    }

    /// The memory model: the measured 85 MB at 2,025 faces within a factor of two.
    #[test]
    fn a_solve_of_two_thousand_faces_takes_tens_of_megabytes() {
        let mb = solve_bytes(2025) / 1e6;
        assert!((42.0..170.0).contains(&mb), "{mb}");
    }
}
