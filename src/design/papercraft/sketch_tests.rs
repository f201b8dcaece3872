use glam::{DVec2, DVec3};

use super::*;
use crate::design::papercraft::design::parse_design;
use crate::mesh::parse_obj;

const VASE_OBJ: &[u8] = include_bytes!("../../../examples/papercraft/vase.obj");
const VASE_TOML: &str = include_str!("../../../examples/papercraft/vase.craft.toml");

fn vase() -> (ReferenceMesh, Design, f64) {
    let poly = parse_obj(VASE_OBJ).unwrap();
    let area = poly.area();
    (
        ReferenceMesh::new(&poly).unwrap(),
        parse_design(VASE_TOML).unwrap(),
        area,
    )
}

fn sorted(mut v: Vec<usize>) -> Vec<usize> {
    v.sort_unstable();
    v
}

#[test]
fn the_vase_drawing_closes_the_gores_the_design_lists() {
    // The example lists its eight gores by hand (meridians 0-7, foot 8-15, rim 16-23); the
    // traced faces must be exactly those loops, and the foot and rim rings must be holes
    // (the vase mesh is open at both ends).
    let (mesh, design, _) = vase();
    let sketch = Sketch::from_design(&design);
    let found = regions(&mesh, &sketch.cut_lines().unwrap());
    assert!(found.open.is_empty(), "{:?}", found.open);
    let mut got: Vec<Vec<usize>> = found.loops.iter().map(|l| sorted(l.clone())).collect();
    let mut want: Vec<Vec<usize>> = (design.patches.iter())
        .map(|p| sorted(p.cut_lines.clone()))
        .collect();
    got.sort();
    want.sort();
    assert_eq!(got, want);
    let mut holes: Vec<Vec<usize>> = found.holes.iter().map(|l| sorted(l.clone())).collect();
    holes.sort();
    assert_eq!(
        holes,
        vec![(8..16).collect::<Vec<_>>(), (16..24).collect::<Vec<_>>()]
    );
}

#[test]
fn a_line_with_a_loose_end_bounds_nothing() {
    let (mesh, design, _) = vase();
    let mut sketch = Sketch::from_design(&design);
    // From the foot end of meridian 0 half-way up gore 0: one end on a vertex, one loose.
    let from = sketch.lines[0][0];
    let to = DVec3::new(36.0, 15.0, 50.0);
    let line = snap_line(&mesh, &sketch.lines, &[from, to], 1.0).unwrap();
    sketch.lines.push(line);
    let found = regions(&mesh, &sketch.cut_lines().unwrap());
    assert_eq!(found.open, vec![24]);
    assert_eq!(found.loops.len(), 8);
}

#[test]
fn snapping_joins_near_ends_and_puts_points_on_the_mesh() {
    let (mesh, design, _) = vase();
    let sketch = Sketch::from_design(&design);
    let foot = sketch.lines[0][0];
    let rim = sketch.lines[1][sketch.lines[1].len() - 1];
    let middle = DVec3::new(45.0, 10.0, 50.0); // off the surface
    let near_foot = foot + DVec3::new(0.3, 0.2, 0.1);
    let line = snap_line(&mesh, &sketch.lines, &[near_foot, middle, rim], 0.5).unwrap();
    assert_eq!(line[0], foot);
    assert_eq!(line[2], rim);
    assert!(mesh.project(line[1]).distance < 1e-9);
    assert!(line[1].distance(middle) > 1.0);
    // Out of reach, an end stays where it was clicked (projected).
    let far = snap_line(&mesh, &sketch.lines, &[near_foot, middle], 0.1).unwrap();
    assert_ne!(far[0], foot);
    // Two clicks on one point make no line.
    assert!(snap_line(&mesh, &sketch.lines, &[foot, near_foot], 0.5).is_err());
}

#[test]
fn placed_patches_are_kept_and_build_as_the_example_does() {
    // With its placed patches, the drawing's design builds the same parts as the example
    // file itself (the patch numbering may differ, so areas are compared sorted).
    let (mesh, design, _) = vase();
    let eval = Sketch::from_design(&design).evaluate(&mesh).unwrap();
    assert!(
        eval.regions
            .iter()
            .all(|r| r.patch.is_some() && r.residual.is_none())
    );
    let made = eval.made.unwrap();
    let direct = design.build(&mesh).unwrap();
    let areas = |m: &Made| {
        let mut a: Vec<f64> = m.parts.iter().map(|p| p.area()).collect();
        a.sort_by(f64::total_cmp);
        a
    };
    let (got, want) = (areas(&made), areas(&direct));
    assert_eq!(got.len(), 8);
    for (g, w) in got.iter().zip(&want) {
        assert!((g - w).abs() <= 1e-6 * w, "{g} vs {w}");
    }
    // The text written is a design file that parses back to the same cut lines.
    let again = parse_design(&eval.text).unwrap();
    assert_eq!(again.cut_lines.len(), design.cut_lines.len());
    for (a, b) in again.cut_lines.iter().zip(&design.cut_lines) {
        assert_eq!(a.points, b.points);
    }
}

#[test]
fn fitted_patches_cover_the_vase_as_its_surface_does() {
    // Without the placed patches every gore is fitted. The unrolled parts (outlines only)
    // must have about the mesh's surface area: each fitted cylinder follows the gore to
    // within its residual, so their areas differ by a few percent at most.
    let (mesh, design, mesh_area) = vase();
    let mut sketch = Sketch::from_design(&design);
    sketch.placed.clear();
    let eval = sketch.evaluate(&mesh).unwrap();
    for r in &eval.regions {
        assert!(r.error.is_none(), "{r:?}");
        assert!(r.residual.unwrap() < 5.0, "{r:?}");
    }
    let made = eval.made.unwrap();
    assert_eq!(made.parts.len(), 8);
    let outline_area: f64 = (made.parts.iter())
        .map(|p| {
            let o = &p.outline;
            (0..o.len())
                .map(|i| o[i].perp_dot(o[(i + 1) % o.len()]))
                .sum::<f64>()
                .abs()
                / 2.0
        })
        .sum();
    let ratio = outline_area / mesh_area;
    assert!((0.95..1.05).contains(&ratio), "ratio {ratio}");
    assert!(eval.self_overlapping.is_empty());
}

#[test]
fn removing_a_line_drops_its_patches_and_renumbers() {
    let (_, design, _) = vase();
    let mut sketch = Sketch::from_design(&design);
    sketch.remove_line(1).unwrap();
    assert_eq!(sketch.lines.len(), 23);
    // Meridian 1 bounds gores 0 and 1; the other six stay, renumbered past line 1.
    assert_eq!(sketch.placed.len(), 6);
    assert!(
        sketch
            .placed
            .iter()
            .all(|p| p.cut_lines.iter().all(|&e| e < 23))
    );
    assert_eq!(sketch.placed[0].cut_lines, vec![9, 2, 17, 1]);
    assert!(sketch.remove_line(23).is_err());
}

#[test]
fn a_bow_tie_crosses_itself_and_a_square_does_not() {
    let p = |x: f64, y: f64| DVec2::new(x, y);
    let square = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
    let bow_tie = [p(0.0, 0.0), p(1.0, 1.0), p(1.0, 0.0), p(0.0, 1.0)];
    assert!(!outline_crosses_itself(&square));
    assert!(outline_crosses_itself(&bow_tie));
}

#[test]
fn painting_gives_each_gore_an_eighth_of_the_vase() {
    // The eight gores are congruent (turns of one another by 45°), so each region's painted
    // area must be an eighth of the mesh's, and (nearly) every triangle is painted (the
    // meridians run along the mesh's edges: no triangle is divided).
    let (mesh, design, mesh_area) = vase();
    let lines = Sketch::from_design(&design).cut_lines().unwrap();
    let found = regions(&mesh, &lines);
    let paint = crate::design::papercraft::paint::paint_regions(&mesh, &lines, &found);
    let mut area = vec![0.0; found.loops.len()];
    let mut unpainted = 0.0;
    let area_of = |[a, b, c]: [DVec3; 3]| (b - a).cross(c - a).length() / 2.0;
    let mut add = |region: Option<usize>, here: f64| match region {
        Some(r) => area[r] += here,
        None => unpainted += here,
    };
    let divided: std::collections::HashSet<usize> =
        paint.pieces.iter().map(|p| p.triangle).collect();
    for (t, l) in paint.triangles.iter().enumerate() {
        if !divided.contains(&t) {
            add(*l, area_of(mesh.triangle(t)));
        }
    }
    for p in &paint.pieces {
        add(p.region, area_of(p.corners));
    }
    assert!(
        unpainted < 0.001 * mesh_area,
        "{unpainted} of {mesh_area} unpainted"
    );
    let worst = area
        .iter()
        .map(|a| (a / mesh_area - 0.125).abs())
        .fold(0.0, f64::max);
    assert!(worst < 0.01, "an area {worst} of the mesh's off an eighth");
}
