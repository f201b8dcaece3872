//! A part's shape for packing (outline and tabs) and the shape turned to one angle.

use glam::DVec2;

use super::raster::Solid;
use crate::design::papercraft::parts::Part;

/// A part's shape for packing, in part coordinates: its outline and tab polygons, and the
/// edges that bound them (outline edges and the tabs' free edges).
pub(super) struct Shape {
    pub(super) rings: Vec<Vec<DVec2>>,
    pub(super) edges: Vec<[DVec2; 2]>,
    pub(super) area: f64,
}

impl Shape {
    pub(super) fn of(part: &Part) -> Shape {
        let mut rings = vec![part.outline.clone()];
        rings.extend(part.tabs.iter().map(|t| part.tab_polygon(t)));
        let n = part.outline.len();
        let mut edges: Vec<[DVec2; 2]> = (0..n)
            .map(|i| [part.outline[i], part.outline[(i + 1) % n]])
            .collect();
        for tab in &part.tabs {
            let (a, b) = (part.point(tab.from), part.point(tab.from + tab.len));
            let [oa, ob] = tab.outer;
            edges.extend([[a, oa], [oa, ob], [ob, b]]);
        }
        Shape {
            rings,
            edges,
            area: part.area(),
        }
    }

    /// The shape turned by `angle` and moved so that its bounding box starts at the origin,
    /// with its solid cells of spacing `cell` mm.
    pub(super) fn turned(&self, angle: f64, cell: f64) -> Turned {
        let rot = DVec2::from_angle(angle);
        let lo = self
            .rings
            .iter()
            .flatten()
            .fold(DVec2::splat(f64::INFINITY), |lo, &p| lo.min(rot.rotate(p)));
        let map = |p: DVec2| rot.rotate(p) - lo;
        let rings: Vec<Vec<DVec2>> = self
            .rings
            .iter()
            .map(|r| r.iter().map(|&p| map(p)).collect())
            .collect();
        let size = rings.iter().flatten().fold(DVec2::ZERO, |hi, &p| hi.max(p));
        let edges: Vec<[DVec2; 2]> = self.edges.iter().map(|e| [map(e[0]), map(e[1])]).collect();
        Turned {
            angle,
            lo,
            size,
            solid: Solid::new(&edges, &rings, size, cell),
            edges,
            rings,
        }
    }
}

/// A shape at one angle, its bounding box from the origin to `size`.
pub(super) struct Turned {
    pub(super) angle: f64,
    /// The turned part's bounding-box corner that was moved to the origin.
    pub(super) lo: DVec2,
    pub(super) size: DVec2,
    pub(super) edges: Vec<[DVec2; 2]>,
    pub(super) rings: Vec<Vec<DVec2>>,
    pub(super) solid: Solid,
}
