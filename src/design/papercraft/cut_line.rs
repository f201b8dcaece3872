//! Cut lines (Ōgaki 2016, §3.2 Step 1): uniform Catmull–Rom splines through the points the user picked on
//! the reference mesh. The curve passes through every point, and its ends are the first and
//! last points, which cut lines share at the network's vertices.
//!
//! Segment i between points P_i and P_{i+1} is the uniform Catmull–Rom cubic
//! `C(t) = ½ [2P_i + (P_{i+1} − P_{i−1}) t + (2P_{i−1} − 5P_i + 4P_{i+1} − P_{i+2}) t² +
//! (−P_{i−1} + 3P_i − 3P_{i+1} + P_{i+2}) t³]`, t ∈ [0, 1]. The thesis does not say how the
//! end segments get their outer neighbours; we reflect: `P_{−1} = 2P_0 − P_1` and
//! `P_n = 2P_{n−1} − P_{n−2}`. With that choice, reversing the points traces the same curve
//! backwards (the thesis reverses cut lines this way when building the network).
//!
//! [`CutLine::sample`] samples the curve and projects every sample onto the reference mesh, so
//! the sampled cut line lies on the mesh (the spline itself may leave it between points).

use glam::DVec3;

use super::PapercraftError;
use crate::mesh::ReferenceMesh;

/// A cut line: the points it passes through, in order (mesh units).
#[derive(Clone, Debug, PartialEq)]
pub struct CutLine {
    points: Vec<DVec3>,
}

impl CutLine {
    /// A cut line through `points`; `index` names it in errors. Needs 2 finite points.
    pub fn new(index: usize, points: Vec<DVec3>) -> Result<Self, PapercraftError> {
        if points.len() < 2 {
            return Err(PapercraftError::ShortCutLine {
                line: index,
                points: points.len(),
            });
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(PapercraftError::NonFinite {
                what: format!("cut line {index}"),
            });
        }
        Ok(CutLine { points })
    }

    /// The points the curve passes through.
    pub fn points(&self) -> &[DVec3] {
        &self.points
    }

    /// First point (the curve's start).
    pub fn start(&self) -> DVec3 {
        self.points[0]
    }

    /// Last point (the curve's end).
    pub fn end(&self) -> DVec3 {
        self.points[self.points.len() - 1]
    }

    /// The same curve traced the other way.
    pub fn reversed(&self) -> CutLine {
        CutLine {
            points: self.points.iter().rev().copied().collect(),
        }
    }

    /// Number of cubic segments (points − 1); the parameter runs over `[0, segments]`.
    pub fn segments(&self) -> usize {
        self.points.len() - 1
    }

    /// The curve at parameter `s ∈ [0, segments]` (clamped): segment `⌊s⌋`, local t = s − ⌊s⌋.
    /// At integer `s` it returns point `s` exactly, so cut lines sharing an end share it.
    pub fn at(&self, s: f64) -> DVec3 {
        let n = self.segments();
        let s = s.clamp(0.0, n as f64);
        let i = (s.floor() as usize).min(n - 1);
        let t = s - i as f64;
        if t == 0.0 {
            return self.points[i];
        }
        if t == 1.0 {
            return self.points[i + 1];
        }
        let p = |k: isize| self.point_ext(k);
        let i = i as isize;
        catmull_rom(p(i - 1), p(i), p(i + 1), p(i + 2), t)
    }

    /// Point `k` with the reflected phantom points before the start and after the end.
    fn point_ext(&self, k: isize) -> DVec3 {
        let n = self.points.len() as isize;
        if k < 0 {
            2.0 * self.points[0] - self.points[1]
        } else if k >= n {
            2.0 * self.points[(n - 1) as usize] - self.points[(n - 2) as usize]
        } else {
            self.points[k as usize]
        }
    }

    /// `per_segment` samples per cubic segment (at least 1) plus the end point, each projected
    /// onto `mesh`. The ends are projected too, so cut lines sharing an end point still share
    /// the projected end.
    pub fn sample(&self, mesh: &ReferenceMesh, per_segment: usize) -> Vec<DVec3> {
        let per = per_segment.max(1);
        let count = self.segments() * per;
        (0..=count)
            .map(|k| mesh.project(self.at(k as f64 / per as f64)).point)
            .collect()
    }
}

/// The uniform Catmull–Rom cubic between `p1` (t = 0) and `p2` (t = 1).
pub fn catmull_rom(p0: DVec3, p1: DVec3, p2: DVec3, p3: DVec3, t: f64) -> DVec3 {
    let (t2, t3) = (t * t, t * t * t);
    0.5 * (2.0 * p1
        + (p2 - p0) * t
        + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2
        + (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * t3)
}
