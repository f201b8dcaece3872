//! Trimming a patch by its boundary walls (Ōgaki 2016, §3.2 Step 3): the "real boundary" (実境界線) is
//! where the patch crosses the walls of its cut lines, and becomes the outline of its part.
//!
//! Each wall is ruled by straight ribs (see [`super::walls`]), so the real boundary along
//! cut line e is traced rib by rib: the rib at parameter s crosses the cylinder
//! `S(u, v) = c(u) + v·d` where, seen along d, the projected rib line meets the orthogonal
//! section c⊥. We scan u for sign changes of the 2D cross product (64 steps per knot span),
//! bisect each to 1e-13, keep crossings inside the rib, and take the one closest to the rib's
//! middle (the cut line itself). `v = (X − c(u))·d` at the crossing point X.
//!
//! The boundary is kept as a polyline at a chosen tolerance: consecutive crossings are split
//! at the middle parameter while the unrolled middle point is farther than the tolerance
//! from the unrolled chord (up to 16 halvings per initial piece). Consecutive walls share
//! their end ribs (the rib at a network vertex runs from `2v − v_s` to `v_s`), so the pieces
//! of the loop meet at the corners.
//!
//! The thesis intersects the patch with the wall surface directly; tracing ribs finds the same
//! curve when every rib crosses the patch. A patch too short to reach a wall gives
//! [`PapercraftError::MissesWall`] (the thesis's first stated limit; extending is not built).

use glam::{DVec2, DVec3};

use super::PapercraftError;
use super::cylinder::CylinderPatch;
use super::network::Network;
use super::walls::Walls;
use crate::geom::segment::distance_to_point;
use crate::geom::tolerance::{RELATIVE, ROUNDOFF_SQUARED, TINY};
use crate::mesh::ReferenceMesh;

/// Bisection stops when the bracket is this share of the parameter (plus an absolute part):
/// about a thousand ulps of f64.
const BISECT_RELATIVE: f64 = 1e-13;

const SCAN_STEPS_PER_SPAN: usize = 64;
const MAX_HALVINGS: u32 = 16;

/// One point of a real boundary.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundaryPoint {
    /// Position in 3D (mesh units).
    pub point: DVec3,
    /// Patch parameters `(u, v)`.
    pub uv: (f64, f64),
    /// Unrolled position.
    pub flat: DVec2,
}

/// The run of a real boundary along one half-edge of the patch's loop.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundarySide {
    /// The half-edge (cut line `half_edge / 2`).
    pub half_edge: usize,
    /// Points from the corner at the half-edge's origin to the corner at its head, both
    /// included.
    pub points: Vec<BoundaryPoint>,
}

/// The real boundary of a patch: one side per half-edge, in loop order.
#[derive(Clone, Debug, PartialEq)]
pub struct RealBoundary {
    /// Sides in the patch loop's order; each side's last point is the next side's first.
    pub sides: Vec<BoundarySide>,
}

impl RealBoundary {
    /// The closed unrolled outline (each corner once).
    pub fn flat_outline(&self) -> Vec<DVec2> {
        self.sides
            .iter()
            .flat_map(|s| s.points[..s.points.len() - 1].iter().map(|p| p.flat))
            .collect()
    }
}

/// Traces the real boundary of `patch` as patch `p` of `network`, refined until the unrolled
/// polyline is within `tolerance` (mesh units, finite and > 0) of the crossing curve at the
/// pieces' middles.
pub fn real_boundary(
    mesh: &ReferenceMesh,
    network: &Network,
    walls: &Walls,
    p: usize,
    patch: &CylinderPatch,
    tolerance: f64,
) -> Result<RealBoundary, PapercraftError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(PapercraftError::BadParameter(format!(
            "boundary tolerance {tolerance} must be finite and positive"
        )));
    }
    let sides = network
        .patch_loop(p)
        .iter()
        .map(|&h| {
            let tracer = Tracer {
                mesh,
                walls,
                patch,
                p,
                line: h / 2,
                tolerance,
            };
            let n = walls.segments(h / 2) as f64;
            let (s0, s1) = if Network::is_reversed(h) {
                (n, 0.0)
            } else {
                (0.0, n)
            };
            Ok(BoundarySide {
                half_edge: h,
                points: tracer.trace(s0, s1)?,
            })
        })
        .collect::<Result<Vec<_>, PapercraftError>>()?;
    Ok(RealBoundary { sides })
}

struct Tracer<'a> {
    mesh: &'a ReferenceMesh,
    walls: &'a Walls,
    patch: &'a CylinderPatch,
    p: usize,
    line: usize,
    tolerance: f64,
}

impl Tracer<'_> {
    fn trace(&self, s0: f64, s1: f64) -> Result<Vec<BoundaryPoint>, PapercraftError> {
        let pieces = 4 * self.walls.segments(self.line);
        let mut out = vec![self.hit(s0)?];
        for k in 1..=pieces {
            let (a, b) = (
                s0 + (s1 - s0) * (k - 1) as f64 / pieces as f64,
                s0 + (s1 - s0) * k as f64 / pieces as f64,
            );
            let end = self.hit(b)?;
            let start = out[out.len() - 1];
            self.refine(a, b, start, end, MAX_HALVINGS, &mut out)?;
            out.push(end);
        }
        Ok(out)
    }

    /// Pushes the points strictly between `start` (at s = a) and `end` (at s = b).
    fn refine(
        &self,
        a: f64,
        b: f64,
        start: BoundaryPoint,
        end: BoundaryPoint,
        depth: u32,
        out: &mut Vec<BoundaryPoint>,
    ) -> Result<(), PapercraftError> {
        if depth == 0 {
            return Ok(());
        }
        let m = 0.5 * (a + b);
        let mid = self.hit(m)?;
        if distance_to_point(start.flat, end.flat, mid.flat) <= self.tolerance {
            return Ok(());
        }
        self.refine(a, m, start, mid, depth - 1, out)?;
        out.push(mid);
        self.refine(m, b, mid, end, depth - 1, out)
    }

    fn hit(&self, s: f64) -> Result<BoundaryPoint, PapercraftError> {
        let (inner, outer) = self.walls.rib(self.mesh, self.line, s);
        let miss = PapercraftError::MissesWall {
            patch: self.p,
            line: self.line,
            s,
        };
        let (u, x) = rib_crossing(self.patch, inner, outer).ok_or(miss)?;
        let v = (x - self.patch.directrix().at(u)).dot(self.patch.ruling());
        Ok(BoundaryPoint {
            point: self.patch.point(u, v),
            uv: (u, v),
            flat: self.patch.unroll(u, v),
        })
    }
}

/// Where the segment `inner → outer` crosses the patch: `(u, point)`, the crossing closest to
/// the segment's middle; `None` if it does not cross within the directrix's domain or runs
/// along the ruling.
pub fn rib_crossing(patch: &CylinderPatch, inner: DVec3, outer: DVec3) -> Option<(f64, DVec3)> {
    let d = patch.ruling();
    let e1 = d.any_orthonormal_vector();
    let e2 = d.cross(e1);
    let flat = |x: DVec3| DVec2::new(x.dot(e1), x.dot(e2));
    let (a, dir) = (flat(inner), flat(outer - inner));
    if dir.length_squared() <= ROUNDOFF_SQUARED * (outer - inner).length_squared().max(TINY) {
        return None;
    }
    let side = |u: f64| dir.perp_dot(flat(patch.directrix().at(u)) - a);
    let steps = patch.directrix().spans() * SCAN_STEPS_PER_SPAN;
    let u_at = |k: usize| patch.u_max() * k as f64 / steps as f64;
    let mut best: Option<(f64, f64)> = None;
    let mut consider = |u: f64| {
        let t = dir.dot(flat(patch.directrix().at(u)) - a) / dir.length_squared();
        if (-RELATIVE..=1.0 + RELATIVE).contains(&t)
            && best.is_none_or(|(_, bt)| (t - 0.5).abs() < (bt - 0.5).abs())
        {
            best = Some((u, t));
        }
    };
    let mut f0 = side(0.0);
    if f0 == 0.0 {
        consider(0.0);
    }
    for k in 1..=steps {
        let f1 = side(u_at(k));
        if f1 == 0.0 {
            consider(u_at(k));
        } else if f0 * f1 < 0.0 {
            consider(bisect(&side, u_at(k - 1), u_at(k), f0));
        }
        f0 = f1;
    }
    best.map(|(u, t)| (u, inner + t * (outer - inner)))
}

fn bisect(f: &impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, f_lo: f64) -> f64 {
    let sign = f_lo.signum();
    while hi - lo > BISECT_RELATIVE * (1.0 + hi.abs()) {
        let m = 0.5 * (lo + hi);
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if fm.signum() == sign { lo = m } else { hi = m }
    }
    0.5 * (lo + hi)
}
