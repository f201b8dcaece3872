//! Every vertical face of a voxel card stands: checked on the FOLD file `foldcam popup voxel`
//! writes, by a walk of its own over the written crease pattern, not by the library's check.
//!
//! The oracle reads the file's faces (`faces_vertices` and `foldcam:faces_holes`), edges and
//! assignments only. Faces are vertical or horizontal by the parity of the 90° folds between
//! them and the base (the face at the sheet's bottom-left corner; the pattern has the back sheet
//! on top, y up). Then the two floods of Mitani & Suzuki (2004), §3.6, over faces: (a) from the
//! back sheet (the face at the top-left corner), vertical to horizontal across a valley only,
//! horizontal to vertical across a mountain only; (b) from the base, vertical to horizontal
//! across a mountain, horizontal to vertical across a valley. Mitani, Suzuki & Uno (2003) ask
//! the same of every vertical face of a voxel card (flags a and b): reached by both. Apart from
//! the floods the oracle also counts the vertical faces whose folds all lie on one side (all
//! above the face or all below it): a face held by one crease, or along one edge.

use std::collections::{HashMap, VecDeque};
use std::path::Path;

use foldcam::design::popup::voxel::crease_pattern;
use serde_json::Value;

use crate::bin::foldcam;

/// A torus of major radius 1 and minor radius 0.25 (as npm's `primitive-torus` makes it), its
/// ring in the x-y plane, `around` × `tube` quads split in triangles: seen from +z (the front
/// view of `--up y`) its hole faces the viewer.
fn torus_obj(around: usize, tube: usize) -> String {
    let (major, minor) = (1.0f64, 0.25f64);
    let mut obj = String::new();
    for j in 0..=tube {
        let v = j as f64 / tube as f64 * std::f64::consts::TAU;
        for i in 0..=around {
            let u = i as f64 / around as f64 * std::f64::consts::TAU;
            let r = major + minor * v.cos();
            let (x, y, z) = (r * u.cos(), r * u.sin(), minor * v.sin());
            obj.push_str(&format!("v {x:.6} {y:.6} {z:.6}\n"));
        }
    }
    let id = |i: usize, j: usize| j * (around + 1) + i + 1;
    for j in 1..=tube {
        for i in 1..=around {
            let (a, b, c, d) = (id(i - 1, j), id(i - 1, j - 1), id(i, j - 1), id(i, j));
            obj.push_str(&format!("f {a} {b} {d}\nf {b} {c} {d}\n"));
        }
    }
    obj
}

/// What the oracle finds in a written card.
#[derive(Debug, Default)]
struct Standing {
    /// Faces the oracle calls vertical, the back sheet included.
    vertical: usize,
    /// Vertical faces (not the back sheet) missed by flood (a) or (b): (area mm², bounding box
    /// x0, x1, y0, y1 on the pattern).
    unheld: Vec<(f64, [f64; 4])>,
    /// Vertical faces (not the back sheet) whose folds all lie above them or all below them.
    one_sided: Vec<(f64, [f64; 4])>,
}

fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

fn indices(v: &Value) -> Vec<usize> {
    v.as_array()
        .expect("array")
        .iter()
        .map(|x| x.as_u64().expect("index") as usize)
        .collect()
}

/// The oracle (see the module docs) on a FOLD text.
fn standing(fold: &str) -> Standing {
    let root: Value = serde_json::from_str(fold).expect("FOLD is JSON");
    let coords: Vec<[f64; 2]> = root["vertices_coords"]
        .as_array()
        .expect("vertices")
        .iter()
        .map(|p| {
            let p = numbers(p);
            [p[0], p[1]]
        })
        .collect();
    let edges: Vec<Vec<usize>> = root["edges_vertices"]
        .as_array()
        .expect("edges")
        .iter()
        .map(indices)
        .collect();
    let kinds: Vec<&str> = root["edges_assignment"]
        .as_array()
        .expect("assignments")
        .iter()
        .map(|a| a.as_str().expect("assignment"))
        .collect();
    let outer: Vec<Vec<usize>> = root["faces_vertices"]
        .as_array()
        .expect("faces")
        .iter()
        .map(indices)
        .collect();
    let holes: Vec<Vec<Vec<usize>>> = match root.get("foldcam:faces_holes") {
        Some(h) => h
            .as_array()
            .expect("holes")
            .iter()
            .map(|f| f.as_array().expect("cycles").iter().map(indices).collect())
            .collect(),
        None => vec![Vec::new(); outer.len()],
    };
    let edge_of: HashMap<(usize, usize), usize> = edges
        .iter()
        .enumerate()
        .map(|(e, v)| ((v[0].min(v[1]), v[0].max(v[1])), e))
        .collect();
    let n = outer.len();
    // Per face: (edge, the face lies above the edge). Outer cycles run counter-clockwise and
    // holes clockwise, so the face is on the left of every side.
    let mut sides: Vec<Vec<(usize, bool)>> = vec![Vec::new(); n];
    let mut faces_of_edge: HashMap<usize, Vec<usize>> = HashMap::new();
    for f in 0..n {
        for cycle in std::iter::once(&outer[f]).chain(&holes[f]) {
            for k in 0..cycle.len() {
                let (a, b) = (cycle[k], cycle[(k + 1) % cycle.len()]);
                let e = *edge_of
                    .get(&(a.min(b), a.max(b)))
                    .expect("every face side is an edge of the planar pattern");
                let dx = coords[b][0] - coords[a][0];
                sides[f].push((e, dx > 0.0));
                faces_of_edge.entry(e).or_default().push(f);
            }
        }
    }
    let mut links: Vec<Vec<(usize, &str)>> = vec![Vec::new(); n];
    for (&e, fs) in &faces_of_edge {
        let k = kinds[e];
        assert!(k != "F" && k != "U", "a voxel card has no {k} edges");
        if (k == "M" || k == "V") && fs.len() == 2 {
            links[fs[0]].push((fs[1], k));
            links[fs[1]].push((fs[0], k));
        }
    }
    let (lo, hi) = coords
        .iter()
        .fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        });
    let at_corner = |x: f64, y: f64| {
        (0..n)
            .find(|&f| {
                outer[f]
                    .iter()
                    .any(|&v| (coords[v][0] - x).abs() < 1e-9 && (coords[v][1] - y).abs() < 1e-9)
            })
            .expect("a face at the sheet's corner")
    };
    let (base, back) = (at_corner(lo[0], lo[1]), at_corner(lo[0], hi[1]));
    // Vertical by fold parity from the base; every fold is 90°.
    let mut vertical: Vec<Option<bool>> = vec![None; n];
    vertical[base] = Some(false);
    let mut queue = VecDeque::from([base]);
    while let Some(f) = queue.pop_front() {
        let flipped = !vertical[f].expect("set");
        for &(g, _) in &links[f] {
            match vertical[g] {
                None => {
                    vertical[g] = Some(flipped);
                    queue.push_back(g);
                }
                Some(v) => assert_eq!(v, flipped, "faces {f} and {g}: folds disagree"),
            }
        }
    }
    let vertical: Vec<bool> = vertical
        .into_iter()
        .map(|v| v.expect("every face is joined by folds to the base"))
        .collect();
    let flood = |start: usize, crosses: &dyn Fn(bool, &str) -> bool| {
        let mut seen = vec![false; n];
        seen[start] = true;
        let mut queue = VecDeque::from([start]);
        while let Some(f) = queue.pop_front() {
            for &(g, k) in &links[f] {
                if !seen[g] && crosses(vertical[f], k) {
                    seen[g] = true;
                    queue.push_back(g);
                }
            }
        }
        seen
    };
    let from_back = flood(back, &|v, k| (v && k == "V") || (!v && k == "M"));
    let from_base = flood(base, &|v, k| (v && k == "M") || (!v && k == "V"));
    let place = |f: usize| {
        let ring = &outer[f];
        let mut area = 0.0;
        let mut bbox = [f64::MAX, f64::MIN, f64::MAX, f64::MIN];
        for k in 0..ring.len() {
            let (p, q) = (coords[ring[k]], coords[ring[(k + 1) % ring.len()]]);
            area += (p[0] * q[1] - q[0] * p[1]) / 2.0;
            bbox = [
                bbox[0].min(p[0]),
                bbox[1].max(p[0]),
                bbox[2].min(p[1]),
                bbox[3].max(p[1]),
            ];
        }
        (area, bbox)
    };
    let mut out = Standing {
        vertical: vertical.iter().filter(|&&v| v).count(),
        ..Standing::default()
    };
    for f in (0..n).filter(|&f| vertical[f] && f != back) {
        if !(from_back[f] && from_base[f]) {
            out.unheld.push(place(f));
        }
        let fold_sides: Vec<bool> = sides[f]
            .iter()
            .filter(|&&(e, _)| kinds[e] == "M" || kinds[e] == "V")
            .map(|&(_, above)| above)
            .collect();
        if !(fold_sides.contains(&true) && fold_sides.contains(&false)) {
            out.one_sided.push(place(f));
        }
    }
    out
}

/// `foldcam popup voxel MESH --up y --resolution 80 -o card.fold` in `dir`; the FOLD text.
fn card_from_mesh(dir: &Path, mesh: &str) -> String {
    let out = foldcam(
        &[
            "popup",
            "voxel",
            mesh,
            "--up",
            "y",
            "--resolution",
            "80",
            "-o",
            "card.fold",
        ],
        dir,
    );
    assert!(
        out.status.success(),
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    std::fs::read_to_string(dir.join("card.fold")).expect("card written")
}

#[test]
fn a_torus_card_at_resolution_80_has_no_vertical_face_held_from_one_side() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("torus.obj"), torus_obj(64, 32)).unwrap();
    let found = standing(&card_from_mesh(dir.path(), "torus.obj"));
    // The ring stands: many vertical faces, and none hangs from one side.
    assert!(found.vertical > 100, "{found:?}");
    assert!(found.unheld.is_empty(), "{:?}", found.unheld);
    assert!(found.one_sided.is_empty(), "{:?}", found.one_sided);
}

/// The Stanford bunny (npm `bunny` 1.0.1, Stanford 3D Scanning Repository) is not kept in the
/// repository: its source asks for research use. `.ci/run` fetches the package, writes its
/// `positions` and `cells` as an OBJ and names it in `FOLDCAM_BUNNY_OBJ`.
#[test]
#[ignore = "needs the Stanford bunny as an OBJ in FOLDCAM_BUNNY_OBJ"]
fn the_bunny_card_at_resolution_80_has_no_vertical_face_held_from_one_side() {
    let obj = std::env::var("FOLDCAM_BUNNY_OBJ").expect("FOLDCAM_BUNNY_OBJ names the bunny OBJ");
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(obj, dir.path().join("bunny.obj")).unwrap();
    let found = standing(&card_from_mesh(dir.path(), "bunny.obj"));
    assert!(found.vertical > 100, "{found:?}");
    assert!(found.unheld.is_empty(), "{:?}", found.unheld);
    assert!(found.one_sided.is_empty(), "{:?}", found.one_sided);
}

#[test]
fn the_oracle_finds_a_strip_hinged_only_at_the_central_fold() {
    // The library still creases such a card; written out, the oracle sees the strip.
    let cp = crease_pattern(&crate::popup_voxel::strip_card(5.0)).unwrap();
    let found = standing(&foldcam::formats::fold::write_string(&cp, None));
    let strip = (50.0, [5.0, 10.0, 0.0, 10.0]);
    assert_eq!(found.one_sided, vec![strip]);
    assert_eq!(found.unheld, vec![strip]);
}

#[test]
fn popup_voxel_refuses_the_strip_naming_the_cell_the_place_and_the_paper() {
    let dir = tempfile::tempdir().unwrap();
    let text =
        foldcam::design::popup::voxel::format_voxel_card(&crate::popup_voxel::strip_card(5.0));
    std::fs::write(dir.path().join("strip.voxel.txt"), text).unwrap();
    let out = foldcam(
        &["popup", "voxel", "strip.voxel.txt", "-o", "strip.fold"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(1));
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        said.contains("Mitani, Suzuki & Uno (2003)") && !said.contains("seed"),
        "{said}"
    );
    assert!(
        said.contains(
            "back-sheet cell (x 1, z 0), part of a piece cut free of the back sheet, is held \
             from the base sheet only (on the pattern x 5.0–10.0 mm from the cells' left edge, \
             0.0–5.0 mm above the central fold)"
        ),
        "{said}"
    );
    assert!(!dir.path().join("strip.fold").exists());
}
