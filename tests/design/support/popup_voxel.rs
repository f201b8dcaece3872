//! Helpers of the voxel pop-up tests: samples and the geometric assertions (eq. 1, 2: the
//! faces tile the sheet; at 90° every face lies on the voxel surface).

// Shared by several test crates; each uses only some helpers.
#![allow(dead_code)]

use foldcam::design::popup::voxel::{
    FrontCellProblem, PopupProblem, VoxelCard, fold_card, parse_voxel_card,
};
use foldcam::design::popup::voxel::{Line, Plane, Surface};
use foldcam::geom::signed_area;
use foldcam::pattern::{Assignment, CreasePattern, Face};
use glam::{DVec2, DVec3};

pub fn sample(name: &str) -> VoxelCard {
    let path = format!("{}/examples/popup/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("sample exists");
    parse_voxel_card(&text).expect("sample parses")
}

/// A card with one column of rows `depths` (z = 0 first) at x = 1, windows on `windows`.
pub fn column_card(depths: &[usize], windows: &[usize]) -> VoxelCard {
    let mut card = VoxelCard::new(3, 4, 8, 5.0).unwrap();
    for (z, &d) in depths.iter().enumerate() {
        card.set_depth(1, z, d).unwrap();
    }
    for &z in windows {
        card.set_hole(1, z, true).unwrap();
    }
    card
}

pub fn face_area(cp: &CreasePattern, f: &Face) -> f64 {
    let ring = |c: &Vec<_>| signed_area(c.iter().map(|&v| cp.position(v)));
    ring(&f.outer) + f.holes.iter().map(ring).sum::<f64>()
}

pub fn assert_tiles_sheet(card: &VoxelCard, cp: &CreasePattern) {
    cp.validate().unwrap();
    let (w, h) = card.sheet_mm();
    let total: f64 = cp
        .faces
        .as_ref()
        .unwrap()
        .iter()
        .map(|f| face_area(cp, f))
        .sum();
    assert!(
        (total - w * h).abs() < 1e-6 * w * h,
        "faces cover {total}, sheet {}",
        w * h
    );
    for e in &cp.edges {
        let want = match e.assignment {
            Assignment::Valley => Some(90.0),
            Assignment::Mountain => Some(-90.0),
            _ => None,
        };
        assert_eq!(e.fold_angle, want, "{:?}", e.assignment);
    }
}

pub fn is_grid(t: f64, s: f64) -> bool {
    ((t / s) - (t / s).round()).abs() < 1e-9
}

/// At 90° every folded face is axis-aligned (constant y or constant z) on a cell plane.
pub fn assert_faces_on_voxel_planes(card: &VoxelCard, cp: &CreasePattern) {
    let folded = fold_card(card, cp, 90.0).state;
    let s = card.cell_mm();
    for face in folded.faces.as_ref().unwrap() {
        let pts: Vec<DVec3> = face
            .outer
            .iter()
            .map(|v| folded.positions[v.index()])
            .collect();
        let same = |f: fn(DVec3) -> f64| pts.iter().all(|&p| (f(p) - f(pts[0])).abs() < 1e-9);
        let on_plane =
            (same(|p| p.y) && is_grid(pts[0].y, s)) || (same(|p| p.z) && is_grid(pts[0].z, s));
        assert!(on_plane, "face off the voxel planes: {pts:?}");
    }
}

/// A point a quarter cell along and a quarter cell inside the first edge of pattern face `f`
/// (never on a grid line), and its 3D image at 90°
/// through the affine map fixed by three corners of the folded face.
pub fn inner_point(cp: &CreasePattern, f: &Face, folded: &[DVec3], g: &Face, s: f64) -> DVec3 {
    let p2 = |i: usize| cp.position(f.outer[i]);
    let p3 = |i: usize| folded[g.outer[i].index()];
    let (a, b) = (p2(0), p2(1));
    let d = (b - a).normalize();
    let inner = a + (d + DVec2::new(-d.y, d.x)) * (0.25 * s);
    let c = (2..f.outer.len())
        .find(|&i| (b - a).perp_dot(p2(i) - a).abs() > 1e-9)
        .unwrap();
    let (e1, e2, w) = (b - a, p2(c) - a, inner - a);
    let det = e1.perp_dot(e2);
    let (t1, t2) = (w.perp_dot(e2) / det, e1.perp_dot(w) / det);
    p3(0) + (p3(1) - p3(0)) * t1 + (p3(c) - p3(0)) * t2
}

/// Without windows, every face on a plane y = y0 > 0 is the front of filled cells and every
/// face on z = z0 > 0 the top of filled cells (checked one point inside each face).
pub fn assert_faces_on_solid(card: &VoxelCard, cp: &CreasePattern) {
    let folded = fold_card(card, cp, 90.0).state;
    let s = card.cell_mm();
    let (mut fronts, mut tops) = (0, 0);
    let faces = cp.faces.as_ref().unwrap().iter();
    for (f, g) in faces.zip(folded.faces.as_ref().unwrap()) {
        let q = inner_point(cp, f, &folded.positions, g, s) / s;
        let (x, y, z) = (
            q.x.floor() as usize,
            q.y.floor() as usize,
            q.z.floor() as usize,
        );
        let corner = |i: usize| folded.positions[g.outer[i].index()] / s;
        let vertical = (0..g.outer.len()).all(|i| (corner(i).y - q.y).abs() < 1e-9);
        if vertical && q.y > 0.5 {
            let y0 = q.y.round() as usize;
            assert!(
                card.cell(x, y0 - 1, z) && !card.cell(x, y0, z),
                "front at {q}"
            );
            fronts += 1;
        } else if !vertical && q.z > 0.5 {
            let z0 = q.z.round() as usize;
            assert!(
                card.cell(x, y, z0 - 1) && !card.cell(x, y, z0),
                "top at {q}"
            );
            tops += 1;
        }
    }
    assert!(fronts > 0 && tops > 0, "{fronts} fronts, {tops} tops");
}

/// The pop-up check of §2.6 done literally, cell by cell over the public [`Surface`]: flood
/// (a) from the top-left cell moving left, down and right, flood (b) from the bottom-left cell
/// moving left, up and right, never across a cut. Checked: the front cells and the back-sheet
/// cells not joined, across flat lines, to a back-sheet cell in the top row or (with a margin)
/// above the fold in the first or last column. Returns the failing cells by column then row,
/// as `check_popup` reports them.
pub fn cell_flood_problems(card: &VoxelCard) -> Vec<FrontCellProblem> {
    let s = Surface::new(card);
    let back = Plane::Vertical(0);
    let mut proper = vec![false; s.planes.len()];
    let mut stack: Vec<(usize, usize)> = Vec::new();
    for x in 0..s.nx {
        for r in 0..s.rows {
            let edge = r + 1 == s.rows
                || (card.margin_mm() > 0.0 && (x == 0 || x + 1 == s.nx) && r >= s.ny);
            if edge && s.plane(x as i64, r as i64) == back {
                proper[x * s.rows + r] = true;
                stack.push((x, r));
            }
        }
    }
    while let Some((x, r)) = stack.pop() {
        for (dx, dr) in [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)] {
            let (nx, nr) = (x as i64 + dx, r as i64 + dr);
            if !(0..s.nx as i64).contains(&nx) || !(0..s.rows as i64).contains(&nr) {
                continue;
            }
            let i = nx as usize * s.rows + nr as usize;
            if s.plane(nx, nr) == back && !proper[i] {
                proper[i] = true;
                stack.push((nx as usize, nr as usize));
            }
        }
    }
    let flood = |start: (usize, usize), dr: i64| {
        let mut seen = vec![false; s.planes.len()];
        let mut stack = vec![start];
        seen[start.0 * s.rows + start.1] = true;
        while let Some((x, r)) = stack.pop() {
            let (xi, ri) = (x as i64, r as i64);
            let mut next = Vec::new();
            if x > 0 && s.line_left(xi, ri) != Line::Cut {
                next.push((x - 1, r));
            }
            if x + 1 < s.nx && s.line_left(xi + 1, ri) != Line::Cut {
                next.push((x + 1, r));
            }
            let nr = ri + dr;
            if (0..s.rows as i64).contains(&nr) && s.line_below(xi, ri.max(nr)) != Line::Cut {
                next.push((x, nr as usize));
            }
            for (nx, nr) in next {
                if !std::mem::replace(&mut seen[nx * s.rows + nr], true) {
                    stack.push((nx, nr));
                }
            }
        }
        seen
    };
    let (a, b) = (flood((0, s.rows - 1), -1), flood((0, 0), 1));
    let mut problems = Vec::new();
    for x in 0..s.nx {
        for r in 0..s.rows {
            let Plane::Vertical(depth) = s.plane(x as i64, r as i64) else {
                continue;
            };
            let i = x * s.rows + r;
            let problem = match (a[i], b[i]) {
                _ if depth == 0 && proper[i] => continue,
                (true, true) => continue,
                (false, false) => PopupProblem::Floating,
                (true, false) => PopupProblem::HeldFromBackOnly,
                (false, true) => PopupProblem::HeldFromBaseOnly,
            };
            problems.push(FrontCellProblem {
                x,
                depth: depth as usize,
                z: r + depth as usize - s.ny,
                problem,
            });
        }
    }
    problems
}
