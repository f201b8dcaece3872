//! The face stack update of Miyazaki et al. (1992) §4.5 and the tuck-in conditions: where the moving faces land in
//! the layer order after a bend, a fold-up or a tuck-in (see [`super::operation`]).

use glam::{DAffine3, DVec2, DVec3};

use super::FoldError;
use super::geometry::{contains_oriented, double_area, overlaps, rotation_about};
use super::search::Layer;
use super::state::FaceGroup;
use crate::geom::tolerance::RELATIVE;

/// A tuck-in needs an even number of moving faces whose moving parts pair up mirror-wise
/// (i-th from the bottom with i-th from the top), and no stationary face between the halves
/// covering the place they fold to.
pub(super) fn check_tuck(layer: &Layer, moving: &[bool], tol: f64) -> Result<(), FoldError> {
    let ids: Vec<usize> = (0..moving.len()).filter(|&i| moving[i]).collect();
    if ids.len() % 2 == 1 {
        return Err(FoldError::TuckAsymmetric(format!(
            "{} layers move, an odd number",
            ids.len()
        )));
    }
    let half = ids.len() / 2;
    for i in 0..half {
        let (a, b) = (
            layer.moving_part(ids[i]),
            layer.moving_part(ids[ids.len() - 1 - i]),
        );
        let (area_a, area_b) = (double_area(a), double_area(b));
        let orientation = |area: f64| if area >= 0.0 { 1.0 } else { -1.0 };
        let same = (area_a.abs() - area_b.abs()).abs() <= tol * 1e3
            && a.iter()
                .all(|&p| contains_oriented(b, p, tol * 1e3, orientation(area_b)))
            && b.iter()
                .all(|&p| contains_oriented(a, p, tol * 1e3, orientation(area_a)));
        if !same {
            return Err(FoldError::TuckAsymmetric(
                "the moving parts of mirrored layers differ in shape".into(),
            ));
        }
    }
    let (lo, hi) = (ids[half - 1], ids[half]);
    let landing: Vec<Vec<DVec2>> = ids
        .iter()
        .map(|&i| {
            layer
                .moving_part(i)
                .iter()
                .map(|&p| layer.line.reflect(p))
                .collect()
        })
        .collect();
    for b in (lo + 1..hi).filter(|&b| !moving[b]) {
        let covers = |l: &Vec<DVec2>| {
            [layer.fixed_part(b), layer.moving_part(b)]
                .iter()
                .any(|part| !part.is_empty() && overlaps(l, part, tol))
        };
        if landing.iter().any(covers) {
            return Err(FoldError::TuckBlocked);
        }
    }
    Ok(())
}

/// The stack after a tuck-in: each moving half reversed next to its hinge — the lower half
/// just above the layer its top face came from (including that face's stationary part), the
/// upper half just below the layer its bottom face came from.
pub(super) fn tucked_stack(stack: &[(usize, bool, usize)]) -> Vec<usize> {
    let moving: Vec<(usize, usize)> = stack.iter().filter(|s| s.1).map(|s| (s.0, s.2)).collect();
    let half = moving.len() / 2;
    let (lower, upper) = moving.split_at(half);
    let (Some(&(_, lower_top)), Some(&(_, upper_bottom))) = (lower.last(), upper.first()) else {
        return stack.iter().map(|s| s.0).collect();
    };
    let stationary = |lo: usize, hi: usize| {
        stack
            .iter()
            .filter(move |s| !s.1 && s.2 >= lo && s.2 < hi)
            .map(|s| s.0)
    };
    let mut out: Vec<usize> = stationary(0, lower_top + 1).collect();
    out.extend(lower.iter().rev().map(|m| m.0));
    out.extend(stationary(lower_top + 1, upper_bottom));
    out.extend(upper.iter().rev().map(|m| m.0));
    out.extend(stationary(upper_bottom, usize::MAX));
    out
}

/// The rotation of a fold: its point on the fold line, axis and signed angle (radians).
#[derive(Clone, Copy, Debug)]
pub(super) struct Hinge {
    pub point: DVec3,
    pub axis: DVec3,
    pub angle: f64,
    /// Unit vector in the old plane from the line towards the moving side.
    pub outward: DVec3,
}

impl Hinge {
    pub fn motion(&self) -> DAffine3 {
        rotation_about(self.point, self.axis, self.angle)
    }

    /// The direction a point at `offset` from the hinge point (after the turn) moves in at
    /// the end of the turn.
    pub fn arrival(&self, offset: DVec3) -> DVec3 {
        self.axis.cross(offset) * self.angle.signum()
    }
}

/// Puts a turned block of faces (in their old stack order; `old` is their plane before the
/// turn `rotation`) into the group whose plane they now lie in, on the side they arrive from
/// (`arrival`: the direction they move in at the end of the turn), or into a new group.
pub(super) fn land(
    groups: &mut Vec<FaceGroup>,
    old: (DVec3, DVec3),
    mut block: Vec<usize>,
    rotation: DAffine3,
    arrival: DVec3,
    tol: f64,
) {
    let origin = rotation.transform_point3(old.0);
    let normal = rotation.transform_vector3(old.1).normalize();
    let target = groups.iter().position(|g| {
        normal.dot(g.normal).abs() >= 1.0 - RELATIVE
            && (origin - g.origin).dot(g.normal).abs() <= tol
    });
    let Some(h) = target else {
        groups.push(FaceGroup {
            origin,
            normal,
            stack: block,
        });
        return;
    };
    let g = &mut groups[h];
    if normal.dot(g.normal) < 0.0 {
        block.reverse();
    }
    if arrival.dot(g.normal) <= 0.0 {
        g.stack.extend(block);
    } else {
        block.extend(g.stack.iter().copied());
        g.stack = block;
    }
}
