use foldcam::design::papercraft::BSpline;
use foldcam::design::papercraft::CylinderPatch;
use foldcam::design::papercraft::Network;
use foldcam::design::papercraft::PapercraftError;
use foldcam::design::papercraft::Walls;
use foldcam::design::papercraft::real_boundary;
use foldcam::design::papercraft::{Part, TabStyle, add_tabs};
use foldcam::design::papercraft::{Placement, SheetSpec, pack, part_points, sheet_pattern};
use foldcam::geom::{Crossing, distance_to_point, intersect};
use foldcam::geom::{contains_point, signed_area};
use foldcam::mesh::ReferenceMesh;
use foldcam::pattern::{Assignment, CreasePattern};
use glam::{DVec2, DVec3};

use super::support::{assert_cuts_clean_on_paper, cube_lines, cube_mesh, cube_patches};

const SCALE: f64 = 25.0; // millimetres per mesh unit
const STYLE: TabStyle = TabStyle {
    width: 6.0,
    angle_deg: 45.0,
    max_length: 40.0,
};
const A4: SheetSpec = SheetSpec {
    width: 210.0,
    height: 297.0,
    margin: 8.0,
    gap: 4.0,
};

/// The six faces of a cube of half-side h, each a flat cylinder patch trimmed by the walls.
fn cube_parts(h: f64) -> (Network, Vec<Part>) {
    let mesh = ReferenceMesh::new(&cube_mesh()).unwrap();
    let (lines, _) = cube_lines();
    let network = Network::build(&lines, &cube_patches(), 1e-9).unwrap();
    let walls = Walls::build(&mesh, &lines, &network, 0.5, 8).unwrap();
    let normals = [
        -DVec3::Z,
        DVec3::Z,
        -DVec3::Y,
        DVec3::Y,
        -DVec3::X,
        DVec3::X,
    ];
    let parts = normals
        .iter()
        .enumerate()
        .map(|(p, &n)| {
            let along = if n.x != 0.0 { DVec3::Z } else { DVec3::X };
            let ruling = n.cross(along);
            let control = (0..5)
                .map(|i| h * n + along * (-3.0 + 1.5 * i as f64))
                .collect();
            let patch =
                CylinderPatch::new(BSpline::directrix(control, "face").unwrap(), ruling).unwrap();
            let b = real_boundary(&mesh, &network, &walls, p, &patch, 1e-6).unwrap();
            Part::from_boundary(p, &b, SCALE)
        })
        .collect();
    (network, parts)
}

fn tabbed(h: f64) -> (Network, Vec<Part>) {
    let (network, mut parts) = cube_parts(h);
    add_tabs(&mut parts, &network, &STYLE).unwrap();
    (network, parts)
}

/// Whether the interiors of two simple polygons overlap (shared boundary does not count).
fn interiors_overlap(a: &[DVec2], b: &[DVec2]) -> bool {
    let eps = 1e-7;
    let strictly_inside = |p: DVec2, poly: &[DVec2]| {
        contains_point(poly, p)
            && (0..poly.len())
                .all(|i| distance_to_point(poly[i], poly[(i + 1) % poly.len()], p) > eps)
    };
    // Corners, edge midpoints, and points just inside each edge (for coincident polygons).
    let probes = |poly: &[DVec2]| -> Vec<DVec2> {
        let turn = signed_area(poly.iter().copied()).signum();
        (0..poly.len())
            .flat_map(|i| {
                let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
                let inward = turn * (q - p).perp().normalize() * 1e-4;
                [p, 0.5 * (p + q), 0.5 * (p + q) + inward]
            })
            .collect()
    };
    if probes(a).iter().any(|&p| strictly_inside(p, b))
        || probes(b).iter().any(|&p| strictly_inside(p, a))
    {
        return true;
    }
    (0..a.len()).any(|i| {
        (0..b.len()).any(|j| {
            match intersect(
                a[i],
                a[(i + 1) % a.len()],
                b[j],
                b[(j + 1) % b.len()],
                1e-12,
            ) {
                Crossing::Point { t, u } => t > eps && t < 1.0 - eps && u > eps && u < 1.0 - eps,
                _ => false,
            }
        })
    })
}

fn placed(poly: &[DVec2], pl: &Placement) -> Vec<DVec2> {
    poly.iter().map(|&p| pl.apply(p)).collect()
}

#[test]
fn every_shared_cut_line_gets_tabs_on_one_side_only() {
    let (network, parts) = tabbed(1.1);
    for e in 0..12 {
        let with_tabs: Vec<usize> = parts
            .iter()
            .filter(|p| p.tabs.iter().any(|t| t.half_edge / 2 == e))
            .map(|p| p.patch)
            .collect();
        assert_eq!(with_tabs.len(), 1, "cut line {e}: tabs on {with_tabs:?}");
        // The labelled sides on the two parts have equal lengths (they are glued together).
        let side_length = |h: usize| {
            let part = &parts[network.half_edges()[h].patch.unwrap()];
            let s = part.sides.iter().find(|s| s.half_edge == h).unwrap();
            (0..s.len)
                .map(|k| {
                    part.point(s.start + k)
                        .distance(part.point(s.start + k + 1))
                })
                .sum::<f64>()
        };
        let (a, b) = (side_length(2 * e), side_length(2 * e + 1));
        assert!(
            (a - b).abs() < 1e-9 && (a - 2.2 * SCALE).abs() < 1e-9,
            "{a} vs {b}"
        );
    }
    for part in &parts {
        assert_eq!(part.dropped_tabs, 0);
        // Tab roots cover exactly the tabbed sides.
        for tab in &part.tabs {
            let poly = part.tab_polygon(tab);
            assert!(
                !interiors_overlap(&poly, &part.outline),
                "a tab overlaps its own part"
            );
            let width = distance_to_point(
                part.point(tab.from),
                part.point(tab.from + tab.len),
                tab.outer[0],
            );
            assert!((width - STYLE.width).abs() < 1e-9);
        }
    }
}

#[test]
fn parts_sit_inside_their_sheets_and_nothing_overlaps() {
    let (_, parts) = tabbed(1.1);
    let placements = pack(&parts, &A4).unwrap();
    assert_eq!(placements.len(), parts.len());
    let sheets = 1 + placements.iter().map(|p| p.sheet).max().unwrap();
    assert!(
        sheets < parts.len(),
        "a real packing puts several parts on a sheet"
    );
    for pl in &placements {
        for p in part_points(&parts[pl.part]) {
            let q = pl.apply(p);
            assert!(
                q.x >= A4.margin - 1e-9 && q.x <= A4.width - A4.margin + 1e-9,
                "{q}"
            );
            assert!(
                q.y >= A4.margin - 1e-9 && q.y <= A4.height - A4.margin + 1e-9,
                "{q}"
            );
        }
    }
    // Every polygon (parts and tabs) against every other on the same sheet.
    let mut polys: Vec<(usize, usize, Vec<DVec2>)> = Vec::new();
    for pl in &placements {
        let part = &parts[pl.part];
        polys.push((pl.sheet, pl.part, placed(&part.outline, pl)));
        for tab in &part.tabs {
            polys.push((pl.sheet, pl.part, placed(&part.tab_polygon(tab), pl)));
        }
    }
    for i in 0..polys.len() {
        for j in i + 1..polys.len() {
            if polys[i].0 == polys[j].0 {
                assert!(
                    !interiors_overlap(&polys[i].2, &polys[j].2),
                    "polygons {i} and {j} overlap"
                );
            }
        }
    }
}

#[test]
fn sheet_patterns_cut_clean_on_paper() {
    let (_, parts) = tabbed(1.1);
    let placements = pack(&parts, &A4).unwrap();
    let sheets = 1 + placements.iter().map(|p| p.sheet).max().unwrap();
    for s in 0..sheets {
        let cp: CreasePattern = sheet_pattern(&parts, &placements, s);
        assert!(
            cp.edges
                .iter()
                .any(|e| e.assignment == Assignment::Mountain)
        );
        assert_cuts_clean_on_paper(&format!("cube sheet {s}"), &cp);
    }
}

#[test]
fn bad_styles_and_sheets_are_refused() {
    let (network, mut parts) = cube_parts(1.1);
    let bad = TabStyle {
        width: 0.0,
        ..STYLE
    };
    assert!(matches!(
        add_tabs(&mut parts, &network, &bad),
        Err(PapercraftError::BadParameter(_))
    ));
    let tiny = SheetSpec {
        width: 40.0,
        height: 40.0,
        ..A4
    };
    assert!(matches!(
        pack(&parts, &tiny),
        Err(PapercraftError::PartTooLarge { .. })
    ));
    let nan = SheetSpec {
        width: f64::NAN,
        ..A4
    };
    assert!(matches!(
        pack(&parts, &nan),
        Err(PapercraftError::BadParameter(_))
    ));
}

#[test]
fn the_overlap_check_sees_overlaps_and_ignores_shared_edges() {
    let square = |x: f64, y: f64| {
        vec![
            DVec2::new(x, y),
            DVec2::new(x + 1.0, y),
            DVec2::new(x + 1.0, y + 1.0),
            DVec2::new(x, y + 1.0),
        ]
    };
    assert!(interiors_overlap(&square(0.0, 0.0), &square(0.5, 0.5)));
    assert!(interiors_overlap(&square(0.0, 0.0), &square(0.0, 0.0)));
    assert!(!interiors_overlap(&square(0.0, 0.0), &square(1.0, 0.0)));
    assert!(!interiors_overlap(&square(0.0, 0.0), &square(3.0, 0.0)));
}
