//! The sample surfaces the tessellation survey solves (`examples/tessellation_survey.rs`),
//! checked against their closed forms: every vertex on its surface, the sign and size of the
//! Gaussian curvature (angle defects of the triangulation), the face counts and orientation,
//! and that each is a disk the tessellation accepts.

use foldcam::design::tessellation::samples::{
    SampleSurface, sample_surface, spherical_cap, uv_cap,
};
use foldcam::design::tessellation::steps::disk;
use foldcam::mesh::PolyMesh;
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// Angle defect (2π minus the angle sum) of every vertex; `None` on the boundary.
fn defects(mesh: &PolyMesh) -> Vec<Option<f64>> {
    let p = mesh.positions();
    let mut sum = vec![0.0; p.len()];
    let mut edges = std::collections::HashMap::new();
    for f in mesh.faces() {
        assert_eq!(f.len(), 3, "samples are triangles");
        for i in 0..3 {
            let (a, b, c) = (
                f[i] as usize,
                f[(i + 1) % 3] as usize,
                f[(i + 2) % 3] as usize,
            );
            sum[a] += (p[b] - p[a]).angle_between(p[c] - p[a]);
            *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    let mut boundary = vec![false; p.len()];
    for ((a, b), n) in edges {
        if n == 1 {
            boundary[a] = true;
            boundary[b] = true;
        }
    }
    sum.iter()
        .zip(&boundary)
        .map(|(s, &b)| (!b).then_some(TAU - s))
        .collect()
}

/// The vertex nearest `(x, y)` in plan.
fn nearest(mesh: &PolyMesh, x: f64, y: f64) -> usize {
    let d = |p: &DVec3| (p.x - x).hypot(p.y - y);
    (0..mesh.positions().len())
        .min_by(|&a, &b| d(&mesh.positions()[a]).total_cmp(&d(&mesh.positions()[b])))
        .expect("vertices")
}

/// Outward normals: every face's normal points away from `centre`.
fn faces_point_away_from(mesh: &PolyMesh, centre: DVec3) -> bool {
    let p = mesh.positions();
    mesh.faces().iter().all(|f| {
        let (a, b, c) = (p[f[0] as usize], p[f[1] as usize], p[f[2] as usize]);
        (b - a).cross(c - a).dot((a + b + c) / 3.0 - centre) > 0.0
    })
}

#[test]
fn every_sample_is_a_disk() {
    let mut meshes: Vec<PolyMesh> = [
        SampleSurface::ShallowSaddle,
        SampleSurface::Saddle,
        SampleSurface::SteepSaddle,
        SampleSurface::Waves,
        SampleSurface::Cylinder,
        SampleSurface::Torus,
    ]
    .into_iter()
    .map(|s| sample_surface(s, 4, 10.0))
    .collect();
    meshes.push(uv_cap(24, 9, 60.0, 100.0));
    meshes.push(spherical_cap(12, 6, 60.0, 100.0));
    for m in &meshes {
        disk(m).expect("a disk");
    }
}

/// The saddles `z = (x² − y²)/c` have Gaussian curvature −4/c² at the centre: the centre
/// vertex's defect per unit area grows 4× from shallow to saddle and again to steep.
#[test]
fn saddles_curve_negatively_in_the_ratio_of_their_closed_forms() {
    let centre_defect = |s| {
        let m = sample_surface(s, 6, 10.0);
        let v = nearest(&m, 0.0, 0.0);
        defects(&m)[v].expect("interior")
    };
    let shallow = centre_defect(SampleSurface::ShallowSaddle);
    let saddle = centre_defect(SampleSurface::Saddle);
    let steep = centre_defect(SampleSurface::SteepSaddle);
    assert!(shallow < 0.0 && saddle < shallow && steep < saddle);
    // The defect is K times the vertex's area (to first order): ratios 4 and 4.
    for (ratio, name) in [
        (saddle / shallow, "saddle/shallow"),
        (steep / saddle, "steep/saddle"),
    ] {
        assert!((3.3..4.2).contains(&ratio), "{name}: {ratio}");
    }
    // K = −4/c² times the vertex's area (a third of its six equilateral triangles, edge 10):
    // c = 3ρ with ρ = 60 mm.
    let area = 6.0 * 3f64.sqrt() / 4.0 * 100.0 / 3.0;
    let expected = -4.0 / (180.0f64 * 180.0) * area;
    assert!(
        (saddle / expected - 1.0).abs() < 0.05,
        "{saddle} vs {expected}"
    );
}

/// The height field `0.06 ρ sin(kx) sin(ky)` bulges at (λ/4, λ/4) and is a saddle at the
/// origin; its vertices lie on it.
#[test]
fn the_waves_bulge_and_dip_where_the_sines_say() {
    let m = sample_surface(SampleSurface::Waves, 6, 10.0);
    let (rho, lambda) = (60.0, 90.0);
    let k = TAU / lambda;
    for p in m.positions() {
        let z = 0.06 * rho * (k * p.x).sin() * (k * p.y).sin();
        assert!((p.z - z).abs() < 1e-12);
    }
    let d = defects(&m);
    let top = nearest(&m, lambda / 4.0, lambda / 4.0);
    let middle = nearest(&m, 0.0, 0.0);
    assert!(d[top].expect("interior") > 0.0 && d[middle].expect("interior") < 0.0);
}

/// The cylinder keeps the patch's length across the fold (arc length x) and is developable:
/// every interior defect is tiny beside the shallow saddle's.
#[test]
fn the_cylinder_wraps_without_stretching() {
    let flat = sample_surface(SampleSurface::Cylinder, 6, 10.0);
    let r = 1.5 * 60.0;
    for p in flat.positions() {
        let axis = DVec3::new(0.0, p.y, -r);
        assert!(((*p - axis).length() - r).abs() < 1e-9);
    }
    let shallow = sample_surface(SampleSurface::ShallowSaddle, 6, 10.0);
    let bound = defects(&shallow)[nearest(&shallow, 0.0, 0.0)]
        .expect("interior")
        .abs();
    for d in defects(&flat).into_iter().flatten() {
        assert!(d.abs() < 0.01 * bound, "{d} vs {bound}");
    }
}

/// The torus patch: every vertex at the tube's radius from the centre circle, positive
/// curvature outside (x > 0), negative inside.
#[test]
fn the_torus_patch_curves_both_ways() {
    let m = sample_surface(SampleSurface::Torus, 6, 10.0);
    let (tube, centre) = (60.0, 120.0);
    for p in m.positions() {
        // The centre circle: radius `centre` about the vertical axis through (−centre, 0),
        // at the height of the tube's centre (−tube).
        let q = DVec3::new(p.x + centre, p.y, p.z + tube);
        let ring = q.truncate().length() - centre;
        assert!((ring.hypot(q.z) - tube).abs() < 1e-9);
    }
    let d = defects(&m);
    let outer = nearest(&m, 30.0, 0.0);
    let inner = nearest(&m, -30.0, 0.0);
    assert!(d[outer].expect("interior") > 0.0 && d[inner].expect("interior") < 0.0);
}

/// The UV cap: `segments·(2·rings − 1)` faces, every vertex on the sphere, the rim at the
/// cap angle, faces facing out, and its interior defects adding up to about the cap's total
/// curvature `2π(1 − cos θ)` (less the rim's ring of faces).
#[test]
fn the_uv_cap_lies_on_its_sphere() {
    let (segments, rings, radius) = (24, 9, 100.0);
    let m = uv_cap(segments, rings, 60.0, radius);
    assert_eq!(m.faces().len(), segments * (2 * rings - 1));
    let centre = DVec3::new(0.0, 0.0, -radius);
    for p in m.positions() {
        assert!(((*p - centre).length() - radius).abs() < 1e-9);
        assert!(p.z >= -radius * (1.0 - (PI / 3.0).cos()) - 1e-9);
    }
    assert!(faces_point_away_from(&m, centre));
    let total: f64 = defects(&m).into_iter().flatten().sum();
    // The interior vertices' share: the cap up to the last interior ring (8 of 9) plus half a
    // ring, polar angle 60° · 8.5/9.
    let inner = TAU * (1.0 - (PI / 3.0 * 8.5 / 9.0).cos());
    assert!((total / inner - 1.0).abs() < 0.05, "{total} vs {inner}");
    // The other triangulation of the same cap gives the same total.
    let other = spherical_cap(12, 6, 60.0, radius);
    assert!(faces_point_away_from(&other, centre));
    let other_total: f64 = defects(&other).into_iter().flatten().sum();
    let other_inner = TAU * (1.0 - (PI / 3.0 * 5.5 / 6.0).cos());
    assert!(
        (other_total / other_inner - 1.0).abs() < 0.05,
        "{other_total} vs {other_inner}"
    );
}
