//! Polygon model to depth field (Mitani, Suzuki & Uno 2003, §3.1): the mesh rendered orthographically from the
//! front on the CPU, keeping per cell the depth of the nearest surface, as the paper read
//! OpenGL's depth buffer.
//!
//! The mesh's x runs along the card's fold. With [`UpAxis::Z`] its z is up and the viewer
//! looks from −y (the usual front view of z-up modellers); with [`UpAxis::Y`] its y is up and
//! the viewer looks from +z (y-up modellers). The cell is the mesh's x extent over the
//! resolution; the card is as high as the mesh, and its back sheet cuts the mesh at
//! [`MeshPlacement::keep_depth`] of its depth from the front (the paper kept the front half).
//! Each cell samples its centre: the depth there is rounded to whole cells.

use glam::{DVec2, DVec3};

use super::DepthField;
use crate::geom::tolerance::{RELATIVE, ROUNDOFF};
use crate::mesh::PolyMesh;

/// Which mesh axis points up.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum UpAxis {
    /// z up, front view from −y.
    #[default]
    Z,
    /// y up, front view from +z.
    Y,
}

/// How the mesh is laid on the card.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshPlacement {
    /// The mesh's up axis.
    pub up: UpAxis,
    /// Cells along the fold (the paper: 80).
    pub resolution: usize,
    /// Part of the mesh's depth, from its front, that stands out of the card, in (0, 1]
    /// (the paper: 0.5).
    pub keep_depth: f64,
}

impl Default for MeshPlacement {
    fn default() -> Self {
        MeshPlacement {
            up: UpAxis::Z,
            resolution: 80,
            keep_depth: 0.5,
        }
    }
}

/// Why a mesh cannot be laid on a card.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PlacementError {
    /// The mesh has no width along x or no height.
    #[error("the mesh is flat: it needs a width along x and a height to stand on a card")]
    Flat,
    /// Resolution or depth fraction out of range.
    #[error("resolution must be 1..=20000 cells and the kept depth in (0, 1], got {0} and {1}")]
    BadPlacement(usize, f64),
    /// The card would need more cells than a card allows.
    #[error("the mesh needs {nx} × {ny} × {nz} cells at this resolution; lower the resolution")]
    TooLarge {
        /// Cells along the fold.
        nx: usize,
        /// Cells of depth.
        ny: usize,
        /// Cells of height.
        nz: usize,
    },
}

/// The mesh's front-view depth per cell, and the cell size in mesh units.
pub fn depth_field_from_mesh(
    mesh: &PolyMesh,
    placement: &MeshPlacement,
) -> Result<(DepthField, f64), PlacementError> {
    let keep = placement.keep_depth;
    let nx = placement.resolution;
    let keep_ok = keep > 0.0 && keep <= 1.0;
    if !((1..=super::super::MAX_CELLS_PER_AXIS).contains(&nx) && keep_ok) {
        return Err(PlacementError::BadPlacement(nx, keep));
    }
    // (along the fold, towards the viewer, up)
    let to_view = |p: DVec3| match placement.up {
        UpAxis::Z => DVec3::new(p.x, -p.y, p.z),
        UpAxis::Y => DVec3::new(p.x, p.z, p.y),
    };
    let (lo, hi) = mesh.bounds();
    let corners = [to_view(lo), to_view(hi)];
    let lo = corners[0].min(corners[1]);
    let hi = corners[0].max(corners[1]);
    let cell = (hi.x - lo.x) / nx as f64;
    let solid = cell > 0.0 && hi.z > lo.z;
    if !solid {
        return Err(PlacementError::Flat);
    }
    let back = hi.y - keep * (hi.y - lo.y);
    // One more cell of base in front of the nearest point: a face on the base's front edge
    // would have no base to stand on.
    let ny = ((hi.y - back) / cell).ceil() as usize + 1;
    // And one more row of back sheet above the highest point.
    let nz = ((hi.z - lo.z) / cell).ceil() as usize + 1;
    let max = super::super::MAX_CELLS_PER_AXIS;
    if ny > max || nz > max || nx * (ny + nz) > super::super::MAX_PATTERN_CELLS {
        return Err(PlacementError::TooLarge { nx, ny, nz });
    }
    // Depth in cells per front-view cell, −∞ where nothing is seen.
    let mut nearest = vec![f64::NEG_INFINITY; nx * nz];
    for tri in mesh.triangles() {
        let p = tri.map(|q| {
            let v = to_view(q);
            // Pixel coordinates with cell centres on integers, and depth in cells.
            DVec3::new(
                (v.x - lo.x) / cell - 0.5,
                (v.z - lo.z) / cell - 0.5,
                (v.y - back) / cell,
            )
        });
        raster(&p, nx, nz, |x, z, depth| {
            let slot = &mut nearest[x * nz + z];
            *slot = slot.max(depth);
        });
    }
    let depths = nearest
        .into_iter()
        .map(|d| d.round().clamp(0.0, ny as f64) as u16)
        .collect();
    Ok((DepthField { nx, ny, nz, depths }, cell))
}

/// Calls `hit(x, z, depth)` for every cell centre inside the projected triangle `p` (x, z in
/// cells; edges inclusive, so neighbouring triangles leave no gaps). Triangles seen edge-on
/// are skipped: they hide nothing a neighbour does not.
fn raster(p: &[DVec3; 3], nx: usize, nz: usize, mut hit: impl FnMut(usize, usize, f64)) {
    let q = p.map(|v| DVec2::new(v.x, v.y));
    let area = (q[1] - q[0]).perp_dot(q[2] - q[0]);
    if area.abs() < ROUNDOFF {
        return;
    }
    let min = q[0].min(q[1]).min(q[2]);
    let max = q[0].max(q[1]).max(q[2]);
    let x0 = min.x.ceil().max(0.0) as usize;
    let z0 = min.y.ceil().max(0.0) as usize;
    let x1 = (max.x.floor()).min(nx as f64 - 1.0);
    let z1 = (max.y.floor()).min(nz as f64 - 1.0);
    if x1 < 0.0 || z1 < 0.0 {
        return;
    }
    let eps = RELATIVE * area.abs();
    for z in z0..=z1 as usize {
        for x in x0..=x1 as usize {
            let c = DVec2::new(x as f64, z as f64);
            let w = [
                (q[2] - q[1]).perp_dot(c - q[1]) / area,
                (q[0] - q[2]).perp_dot(c - q[2]) / area,
                (q[1] - q[0]).perp_dot(c - q[0]) / area,
            ];
            if w.iter().all(|&w| w >= -eps) {
                hit(x, z, w[0] * p[0].z + w[1] * p[1].z + w[2] * p[2].z);
            }
        }
    }
}
