//! An up-front estimate of the time and memory of one tessellation solve (Tachi 2014: the
//! generalized Newton–Raphson iterations on the star-tuck constraints), printed before the
//! work starts.
//!
//! The model is empirical: the unknowns grow with the mesh's faces (about five vertices per
//! face with star tucks), each iteration factors a sparse system whose fill grows faster than
//! its size, and larger meshes take more iterations; together the time of one solve grows as
//! about `faces^1.8`. The constants were measured on the release build on a two-core machine
//! with gently curved quad grids of 100 to 2,025 faces at the stainless limits (0.06 s to
//! 3.4 s, 10 to 85 MB, 5 to 14 iterations). A solve that fails its limits is retried with each
//! smaller face shrink of the ladder, which multiplies the time by up to that many tries.

use crate::design::estimate::Estimate;

/// Seconds of one solve per `faces^SOLVE_TIME_EXPONENT`, measured (see the module docs).
pub const SECONDS_PER_FACE_POWER: f64 = 3.8e-6;
/// Exponent of the face count in the time of one solve, measured.
pub const SOLVE_TIME_EXPONENT: f64 = 1.8;
/// Bytes per mesh face, measured.
pub const BYTES_PER_FACE: f64 = 38e3;
/// Memory of the program before the solve, bytes.
pub const BASE_BYTES: f64 = 8e6;

/// The estimate for one solve over a mesh of `faces` faces.
pub fn solve_estimate(faces: usize) -> Estimate {
    let f = faces as f64;
    Estimate {
        seconds: SECONDS_PER_FACE_POWER * f.powf(SOLVE_TIME_EXPONENT),
        bytes: BASE_BYTES + BYTES_PER_FACE * f,
    }
}

#[cfg(test)]
mod tests {
    use super::solve_estimate;

    #[test]
    fn twenty_thousand_faces_are_announced_as_minutes_not_seconds() {
        // The measured grids, within a factor of two, and the extrapolation.
        let grid45 = solve_estimate(2025).seconds;
        assert!((1.7..6.8).contains(&grid45), "{grid45}");
        assert!(solve_estimate(20_000).seconds > 120.0);
    }
}
