//! The plan: placement on the bed, two-sided jobs, statistics, errors and warnings.
//!
//! Shared builders live here; each module tests one part.

mod end_to_end;
mod pipeline;
mod placement;
mod sides;
mod stats;

use foldcam::fab::{ContourRole, FabError, Operation, PlanOptions, Side, Toolpath};
use foldcam::fab::{bed_to_machine, bounds_of, place};
use foldcam::fab::{design_limit_warnings, plan_toolpaths};
use foldcam::fab::{mirror, registration_marks, split};
use foldcam::machine::{
    Bed, Corner, DesignLimits, Dialect, MachineProfile, Material, OperationMapping,
    OperationSettings, Perforation, SettingsByOperation,
};
use foldcam::pattern::{Assignment, CreasePattern, EdgeId, Units};
use glam::DVec2;

pub const CORNERS: [Corner; 4] = [
    Corner::BottomLeft,
    Corner::TopLeft,
    Corner::BottomRight,
    Corner::TopRight,
];

pub struct Lcg(pub u64);

impl Lcg {
    pub fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

pub fn bed(origin: Corner, y_flipped: bool) -> Bed {
    Bed {
        width_mm: 400.0,
        height_mm: 300.0,
        origin,
        y_flipped,
    }
}

pub fn machine(bed: Bed) -> MachineProfile {
    MachineProfile {
        name: "test".into(),
        description: "test laser".into(),
        ..MachineProfile::generic_laser(Dialect::Grbl, bed)
    }
}

pub fn settings(speed_mm_min: f64, passes: u32) -> OperationSettings {
    OperationSettings {
        speed_mm_min,
        power: 0.5,
        passes,
    }
}

pub fn material() -> Material {
    Material {
        name: "card".into(),
        description: "test card".into(),
        thickness_mm: 0.3,
        kerf_mm: 0.1,
        settings: SettingsByOperation {
            cut: settings(600.0, 2),
            perforate: settings(1200.0, 1),
            score: settings(3000.0, 1),
            mark: settings(3000.0, 1),
            plot: settings(2000.0, 1),
        },
        perforation: Perforation {
            cut_mm: 2.0,
            bridge_mm: 1.0,
            min_dash_mm: 0.5,
            min_web_mm: 0.5,
            vertex_clearance_mm: 1.0,
        },
        mapping: OperationMapping {
            mountain: Some(Operation::Perforate),
            valley: Some(Operation::Score),
            unassigned: Some(Operation::Score),
            flat: None,
            boundary: Some(Operation::Cut),
        },
        limits: DesignLimits {
            min_vertex_angle_deg: 10.0,
            max_fold_angle_deg: 175.0,
        },
    }
}

/// A square sheet with a mountain and a valley crease and its outline, and the matching
/// toolpaths (what the geometry would produce, in pattern coordinates).
pub fn sheet(size: f64, at: DVec2) -> (CreasePattern, Vec<Toolpath>) {
    let mut cp = CreasePattern::new();
    let c = [DVec2::ZERO, DVec2::X, DVec2::ONE, DVec2::Y].map(|p| at + p * size);
    let v: Vec<_> = c.iter().map(|&p| cp.add_vertex(p)).collect();
    for i in 0..4 {
        cp.add_edge(v[i], v[(i + 1) % 4], Assignment::Boundary);
    }
    let m = cp.add_edge(v[0], v[2], Assignment::Mountain);
    let mid = [
        at + DVec2::new(0.0, size / 2.0),
        at + DVec2::new(size, size / 2.0),
    ];
    let ma = cp.add_vertex(mid[0]);
    let mb = cp.add_vertex(mid[1]);
    let val = cp.add_edge(ma, mb, Assignment::Valley);
    let crease = |op, a: DVec2, b: DVec2, e: EdgeId| Toolpath {
        op,
        strokes: vec![vec![a, b]],
        role: ContourRole::None,
        container: None,
        edges: vec![e],
    };
    let outline = Toolpath {
        op: Operation::Cut,
        strokes: vec![vec![c[0], c[1], c[2], c[3], c[0]]],
        role: ContourRole::Outer,
        container: None,
        edges: (0..4).map(EdgeId::new).collect(),
    };
    let paths = vec![
        crease(Operation::Perforate, c[0], c[2], m),
        crease(Operation::Score, mid[0], mid[1], val),
        outline,
    ];
    (cp, paths)
}

pub fn all_points(paths: &[Toolpath]) -> Vec<DVec2> {
    paths
        .iter()
        .flat_map(|p| &p.strokes)
        .flatten()
        .copied()
        .collect()
}

pub fn inside_bed(p: DVec2, bed: &Bed) -> bool {
    let eps = 1e-9;
    p.x >= -eps && p.y >= -eps && p.x <= bed.width_mm + eps && p.y <= bed.height_mm + eps
}
