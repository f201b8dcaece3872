use foldcam::design::papercraft::CutLine;
use foldcam::design::papercraft::Network;
use foldcam::design::papercraft::PapercraftError;
use glam::DVec3;

use super::support::{cube_lines, cube_patches};

#[test]
fn a_cube_network_is_a_closed_oriented_surface() {
    let (lines, _) = cube_lines();
    let net = Network::build(&lines, &cube_patches(), 1e-9).unwrap();
    net.check_invariants().unwrap();
    assert_eq!(net.vertices().len(), 8);
    // Euler characteristic of a sphere: V − E + F = 2.
    assert_eq!(8 - 12 + net.patch_count() as i64, 2);
    // Closed and consistently oriented: every half-edge has a patch, twins on different ones.
    for h in 0..net.half_edges().len() {
        let (p, q) = (net.half_edges()[h].patch, net.half_edges()[h ^ 1].patch);
        assert!(p.is_some() && q.is_some() && p != q, "half-edge {h}");
    }
    for p in 0..6 {
        assert_eq!(net.neighbours(p).len(), 4, "patch {p}");
        assert_eq!(net.patch_loop(p).len(), 4);
    }
    for v in 0..8 {
        assert_eq!(net.patches_at_vertex(v).len(), 3, "vertex {v}");
    }
}

#[test]
fn loops_chain_head_to_tail_with_reversed_curves() {
    let (lines, _) = cube_lines();
    let net = Network::build(&lines, &cube_patches(), 1e-9).unwrap();
    for p in 0..net.patch_count() {
        let hs = net.patch_loop(p);
        for k in 0..hs.len() {
            let (h, next) = (hs[k], hs[(k + 1) % hs.len()]);
            let line = &lines[h / 2];
            let end = if Network::is_reversed(h) {
                line.start()
            } else {
                line.end()
            };
            let next_line = &lines[next / 2];
            let start = if Network::is_reversed(next) {
                next_line.end()
            } else {
                next_line.start()
            };
            assert_eq!(end, start, "patch {p}: half-edges {h} → {next}");
        }
    }
    // Patch 0 lists cut lines 1 and 4 against their points.
    let reversed: Vec<bool> = net
        .patch_loop(0)
        .iter()
        .map(|&h| Network::is_reversed(h))
        .collect();
    let flips = reversed.iter().filter(|&&r| r).count();
    assert_eq!(
        flips, 2,
        "two of the bottom square's four lines run backwards"
    );
}

#[test]
fn a_seam_used_twice_by_one_patch_builds_a_tube() {
    // Vase body: top circle (closed), seam down, bottom circle (closed), seam back up.
    let circle = |z: f64| -> Vec<DVec3> {
        (0..=8)
            .map(|k| {
                let a = std::f64::consts::TAU * k as f64 / 8.0;
                DVec3::new(a.cos(), a.sin(), z)
            })
            .collect()
    };
    let top = CutLine::new(0, circle(1.0)).unwrap();
    let seam = CutLine::new(
        1,
        vec![DVec3::new(1.0, 0.0, 1.0), DVec3::new(1.0, 0.0, 0.0)],
    )
    .unwrap();
    let bottom = CutLine::new(2, circle(0.0)).unwrap();
    let net = Network::build(&[top, seam, bottom], &[vec![0, 1, 2, 1]], 1e-9).unwrap();
    net.check_invariants().unwrap();
    assert_eq!(net.half_edges()[2].patch, Some(0));
    assert_eq!(net.half_edges()[3].patch, Some(0));
    assert!(net.neighbours(0).is_empty());
    assert_eq!(net.vertices().len(), 2);
}

#[test]
fn an_open_loop_names_the_loose_cut_lines() {
    let (lines, _) = cube_lines();
    // Lines 0 (corners 0-1) and 3 (corners 6-7) do not touch.
    let err = Network::build(&lines, &[vec![0, 3]], 1e-9).unwrap_err();
    assert_eq!(
        err,
        PapercraftError::OpenLoop {
            patch: 0,
            from: 0,
            to: 3
        }
    );
    // A chain that does not come back to its start.
    let err = Network::build(&lines, &[vec![0, 5, 1]], 1e-9).unwrap_err();
    assert_eq!(
        err,
        PapercraftError::OpenLoop {
            patch: 0,
            from: 1,
            to: 0
        }
    );
}

#[test]
fn end_points_merge_within_the_tolerance_only() {
    let a = CutLine::new(0, vec![DVec3::ZERO, DVec3::X, DVec3::Y]).unwrap();
    let b = CutLine::new(
        1,
        vec![DVec3::new(0.0, 1.0 + 1e-7, 0.0), DVec3::new(1e-7, 0.0, 0.0)],
    )
    .unwrap();
    let lines = [a, b];
    assert!(Network::build(&lines, &[vec![0, 1]], 1e-6).is_ok());
    assert!(matches!(
        Network::build(&lines, &[vec![0, 1]], 0.0),
        Err(PapercraftError::OpenLoop { .. })
    ));
    assert!(matches!(
        Network::build(&lines, &[vec![0, 1]], f64::NAN),
        Err(PapercraftError::BadParameter(_))
    ));
}

#[test]
fn bad_sharing_and_bad_indices_are_refused() {
    let (lines, _) = cube_lines();
    let mut patches = cube_patches();
    patches.push(vec![0, 5, 1, 4]);
    assert!(matches!(
        Network::build(&lines, &patches, 1e-9),
        Err(PapercraftError::BadSharing { line: 0, .. })
    ));
    assert!(matches!(
        Network::build(&lines, &[vec![0, 99]], 1e-9),
        Err(PapercraftError::BadLoop { patch: 0, .. })
    ));
    assert!(matches!(
        Network::build(&lines, &[vec![]], 1e-9),
        Err(PapercraftError::BadLoop { patch: 0, .. })
    ));
    // A closed cut line used twice the same way round by one patch.
    let ring = CutLine::new(0, vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::ZERO]).unwrap();
    assert!(matches!(
        Network::build(&[ring], &[vec![0, 0]], 1e-9),
        Err(PapercraftError::BadSharing { line: 0, .. })
    ));
}

#[test]
fn a_moebius_band_cannot_be_oriented() {
    // Two squares glued along two lines with a half twist: A uses both lines forward,
    // B must use one forward and one backward, so one of them conflicts.
    let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
    let lines = [
        CutLine::new(0, vec![p(0.0, 0.0), p(0.0, 1.0)]).unwrap(), // 0: a-b
        CutLine::new(1, vec![p(1.0, 0.0), p(1.0, 1.0)]).unwrap(), // 1: c-d
        CutLine::new(2, vec![p(0.0, 0.0), p(1.0, 0.0)]).unwrap(), // 2: a-c
        CutLine::new(3, vec![p(0.0, 1.0), p(1.0, 1.0)]).unwrap(), // 3: b-d
        CutLine::new(4, vec![p(0.0, 1.0), p(1.0, 0.0)]).unwrap(), // 4: b-c
        CutLine::new(5, vec![p(0.0, 0.0), p(1.0, 1.0)]).unwrap(), // 5: a-d
    ];
    // Patch 0: a→b→d→c→a (0, 3, 1 reversed, 2 reversed); patch 1: a→b→c→d→a (0, 4, 1, 5).
    let err = Network::build(&lines, &[vec![0, 3, 1, 2], vec![0, 4, 1, 5]], 1e-9).unwrap_err();
    assert!(matches!(err, PapercraftError::BadSharing { .. }), "{err}");
}
