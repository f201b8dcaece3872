//! Where a tessellation cannot meet its limits, and why: per input vertex, before solving
//! (necessary conditions read off the initial pattern) and after (the conditions a solve left
//! unmet), with the input vertex's position so the user can find the place on the mesh.
//!
//! Before solving: every interior vertex of the pattern has `k` angles between neighbouring
//! creases (sectors) that sum to 360° once it is developable (Tachi 2014, eq. 1), so the
//! smallest is at most `360°/k`; a vertex with `360°/k` under the vertex-angle limit (§5)
//! cannot meet it whatever the solver does. The key vertex of a `p`-pointed star has `2p`
//! sectors: a 6-pointed star (the 12-valent pole of a modelling program's sphere in the
//! checkerboard layout) is capped at 30°, under the stainless limit of 30° plus the margin.

use std::f64::consts::PI;

use glam::DVec3;

use super::constraints::{Limits, angle_defects};
use super::geometry::fold_angle;
use super::model::TessMesh;
use crate::pattern::Assignment;

/// The condition a [`Violation`] is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Condition {
    /// More sectors at a vertex than the vertex-angle limit allows (before solving).
    TooManySectors,
    /// Developability, eq. 1.
    Developability,
    /// The fold-angle limit (§5, eq. 3).
    FoldAngle,
    /// A fold of the wrong sign for its mountain/valley assignment.
    FoldSign,
    /// The vertex-angle limit (§5).
    VertexAngle,
}

/// One condition unmet around one input vertex (its tuck and its face corners).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Violation {
    /// The input mesh's vertex.
    pub input_vertex: u32,
    /// Its position on the input mesh, mesh units.
    pub position: DVec3,
    /// The condition.
    pub condition: Condition,
    /// The worst value found there: radians for angles, a count for
    /// [`Condition::TooManySectors`].
    pub value: f64,
    /// The bound it misses, in the same unit.
    pub bound: f64,
}

impl Violation {
    /// One line: where, what, by how much, and what would fix it.
    pub fn describe(&self) -> String {
        let p = self.position;
        let at = format!(
            "input vertex {} at ({:.1}, {:.1}, {:.1})",
            self.input_vertex, p.x, p.y, p.z
        );
        let deg = f64::to_degrees;
        match self.condition {
            Condition::TooManySectors => format!(
                "{at}: {} creases meet at one point, so some angle between them is at most \
                 {:.1} deg < {:.1} deg; a truncated star or twist fold there (Tachi 2014), or \
                 a mesh without this high-valence vertex (valence near 6) fixes it",
                self.value,
                360.0 / self.value,
                deg(self.bound)
            ),
            Condition::Developability => format!(
                "{at}: not developable, angle sum off 360 deg by {:.2e} rad",
                self.value
            ),
            // What measurements support (see the curvature advice, `advice.rs`): a smaller
            // shrink helped; finer faces did not (finer caps needed smaller shrinks, and a
            // 96-face cap failed where 6-face caps with larger defects solved); fold angles
            // do not change with the size of the sheet.
            Condition::FoldAngle => format!(
                "{at}: fold of {:.1} deg beyond the limit {:.1} deg; a smaller face shrink \
                 opens the tucks wider and is what has helped so far; finer faces did not \
                 (finer meshes needed smaller shrinks), and a larger sheet folds to the same \
                 angles; cutting the surface into smaller pieces may help (a guide: the solve \
                 decides)",
                deg(self.value),
                deg(self.bound)
            ),
            Condition::FoldSign => format!(
                "{at}: a crease folds {:.1} deg the wrong way",
                deg(self.value)
            ),
            Condition::VertexAngle => format!(
                "{at}: creases {:.1} deg apart, limit {:.1} deg",
                deg(self.value),
                deg(self.bound)
            ),
        }
    }
}

/// Number of sectors (angles between neighbouring creases) at every vertex of `mesh`.
pub fn sector_counts(mesh: &TessMesh) -> Vec<usize> {
    let mut vertex_of = vec![u32::MAX; mesh.sectors.count];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for (k, &v) in tri.iter().enumerate() {
            vertex_of[mesh.sectors.of_corner[3 * t + k] as usize] = v;
        }
    }
    let mut counts = vec![0; mesh.positions.len()];
    for v in vertex_of {
        counts[v as usize] += 1;
    }
    counts
}

/// Necessary conditions of the initial pattern `mesh` (see the module docs): every interior
/// vertex whose sectors cannot all reach `min_angle` (radians, margin included), worst per
/// input vertex. `input` holds the input mesh's positions.
pub fn before_solving(mesh: &TessMesh, input: &[DVec3], min_angle: f64) -> Vec<Violation> {
    let mut worst: Vec<Option<Violation>> = vec![None; input.len()];
    for (v, &k) in sector_counts(mesh).iter().enumerate() {
        if !mesh.interior[v] || k == 0 || 2.0 * PI / k as f64 >= min_angle {
            continue;
        }
        let iv = mesh.input_vertex[v];
        let found = Violation {
            input_vertex: iv,
            position: input[iv as usize],
            condition: Condition::TooManySectors,
            value: k as f64,
            bound: min_angle,
        };
        let slot = &mut worst[iv as usize];
        if slot.is_none_or(|w| w.value < found.value) {
            *slot = Some(found);
        }
    }
    worst.into_iter().flatten().collect()
}

/// The conditions unmet at `x` (developability within `tolerance` radians, the fold and
/// vertex-angle limits of `limits`), the worst of each condition per input vertex, most
/// severe first within each condition. `input` holds the input mesh's positions.
pub fn after_solving(
    mesh: &TessMesh,
    input: &[DVec3],
    x: &[DVec3],
    limits: &Limits,
    tolerance: f64,
) -> Vec<Violation> {
    let mut out: Vec<Violation> = Vec::new();
    let mut record = |v: u32, condition: Condition, value: f64, bound: f64, worse: bool| {
        let iv = mesh.input_vertex[v as usize];
        let found = Violation {
            input_vertex: iv,
            position: input[iv as usize],
            condition,
            value,
            bound,
        };
        match out
            .iter_mut()
            .find(|w| w.input_vertex == iv && w.condition == condition)
        {
            Some(w) if worse == (value > w.value) => *w = found,
            Some(_) => {}
            None => out.push(found),
        }
    };
    for (v, d) in angle_defects(mesh, x).iter().enumerate() {
        if d.abs() > tolerance {
            record(
                v as u32,
                Condition::Developability,
                d.abs(),
                tolerance,
                true,
            );
        }
    }
    for e in mesh.edges.iter().filter(|e| e.interior) {
        let [i, j, a, b] = mesh.hinge(e).map(|v| x[v as usize]);
        let rho = fold_angle(i, j, a, b).value;
        let sigma = match e.assignment {
            Assignment::Valley => 1.0,
            Assignment::Mountain => -1.0,
            // Free to fold either way (twist folds): only the limit applies.
            Assignment::Unassigned => rho.signum(),
            _ => continue,
        };
        if rho.abs() > limits.max_fold {
            record(
                e.vertices[0],
                Condition::FoldAngle,
                rho.abs(),
                limits.max_fold,
                true,
            );
        }
        if sigma * rho < 0.0 {
            record(e.vertices[0], Condition::FoldSign, rho.abs(), 0.0, true);
        }
    }
    let angles = mesh.sectors.angles(mesh, x);
    let mut vertex_of = vec![0u32; mesh.sectors.count];
    for (t, tri) in mesh.triangles.iter().enumerate() {
        for (k, &v) in tri.iter().enumerate() {
            vertex_of[mesh.sectors.of_corner[3 * t + k] as usize] = v;
        }
    }
    for (s, &angle) in angles.iter().enumerate() {
        if angle < limits.min_vertex_angle {
            record(
                vertex_of[s],
                Condition::VertexAngle,
                angle,
                limits.min_vertex_angle,
                false,
            );
        }
    }
    out.sort_by(|a, b| {
        a.condition.cmp(&b.condition).then_with(|| {
            let severity = |w: &Violation| (w.value - w.bound).abs();
            severity(b).total_cmp(&severity(a))
        })
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fold-angle hint states the numbers in degrees and only the remedy measurements
    /// support: a smaller shrink, not finer faces or a larger sheet.
    #[test]
    fn the_fold_angle_hint_names_only_what_has_helped() {
        let v = Violation {
            input_vertex: 7,
            position: DVec3::new(1.0, -2.0, 3.0),
            condition: Condition::FoldAngle,
            value: 3.0,
            bound: 165f64.to_radians(),
        };
        let text = v.describe();
        // 3 rad = 171.887 deg.
        assert!(
            text.starts_with(
                "input vertex 7 at (1.0, -2.0, 3.0): fold of 171.9 deg beyond the limit 165.0 deg;"
            ),
            "{text}"
        );
        assert!(text.contains("a smaller face shrink"), "{text}");
        assert!(text.contains("finer faces did not"), "{text}");
        assert!(!text.contains("would open"), "{text}");
    }
}
