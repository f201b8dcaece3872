//! Ordering of toolpaths: precedence, permutation, travel, joining.

use foldcam::fab::{ContourRole, Operation, Toolpath};
use foldcam::fab::{order, ranks, travel_mm};
use foldcam::pattern::EdgeId;
use glam::DVec2;
use proptest::prelude::*;

/// A deterministic generator of numbers in [0, 1) (fixed seeds, no extra dependency).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn point(&mut self, size: f64) -> DVec2 {
        DVec2::new(self.next() * size, self.next() * size)
    }
}

fn line(op: Operation, points: Vec<DVec2>, id: usize) -> Toolpath {
    Toolpath {
        op,
        strokes: vec![points],
        role: ContourRole::None,
        container: None,
        edges: vec![EdgeId::new(id)],
    }
}

/// A closed square contour (counter-clockwise, first point repeated).
fn square(
    centre: DVec2,
    half: f64,
    role: ContourRole,
    container: Option<usize>,
    id: usize,
) -> Toolpath {
    let c = [
        (-1.0, -1.0),
        (1.0, -1.0),
        (1.0, 1.0),
        (-1.0, 1.0),
        (-1.0, -1.0),
    ];
    Toolpath {
        op: Operation::Cut,
        strokes: vec![
            c.iter()
                .map(|&(x, y)| centre + DVec2::new(x, y) * half)
                .collect(),
        ],
        role,
        container,
        edges: vec![EdgeId::new(id)],
    }
}

fn scattered_segments(n: usize, seed: u64, size: f64) -> Vec<Toolpath> {
    let mut rng = Lcg(seed);
    (0..n)
        .map(|i| {
            let a = rng.point(size);
            let b = a + (rng.point(10.0) - 5.0);
            line(Operation::Score, vec![a, b], i)
        })
        .collect()
}

/// Every `id` of the input appears exactly once in the output's edges.
fn assert_permutation(out: &[Toolpath], n: usize) {
    let mut seen = vec![0; n];
    for e in out.iter().flat_map(|p| &p.edges) {
        seen[e.index()] += 1;
    }
    assert!(
        seen.iter().all(|&c| c == 1),
        "edges lost or duplicated: {seen:?}"
    );
}

/// Whether `got` is `want` run forwards, backwards, or (a closed loop) from another vertex.
fn same_up_to_direction(got: &Toolpath, want: &Toolpath) -> bool {
    let mut rev = want.clone();
    rev.strokes.reverse();
    rev.strokes.iter_mut().for_each(|s| s.reverse());
    if got.strokes == want.strokes || got.strokes == rev.strokes {
        return true;
    }
    let (g, w) = (&got.strokes[0], &want.strokes[0]);
    let ring = &w[..w.len() - 1];
    got.strokes.len() == 1
        && g.len() == w.len()
        && (0..ring.len()).any(|k| (0..ring.len()).all(|i| g[i] == ring[(i + k) % ring.len()]))
}

/// Groups in order, every contour after the toolpaths it contains.
fn assert_precedence(out: &[Toolpath]) {
    let group = |p: &Toolpath| Operation::ALL.iter().position(|&o| o == p.op).unwrap();
    for w in out.windows(2) {
        assert!(
            group(&w[0]) <= group(&w[1]),
            "{:?} after {:?}",
            w[1].op,
            w[0].op
        );
    }
    for (i, p) in out.iter().enumerate() {
        if let Some(c) = p.container {
            assert!(i < c, "toolpath {i} comes after its container {c}");
            assert_eq!(out[c].op, Operation::Cut);
        }
    }
}

/// Mixed operations, outer contours with holes, and a hole inside an island inside a hole.
fn mixed_job(seed: u64) -> Vec<Toolpath> {
    let mut rng = Lcg(seed);
    let mut paths = Vec::new();
    let ops = [
        Operation::Mark,
        Operation::Plot,
        Operation::Score,
        Operation::Perforate,
    ];
    for i in 0..60 {
        let a = rng.point(200.0);
        paths.push(line(
            ops[i % 4],
            vec![a, a + DVec2::new(3.0, 1.0)],
            paths.len(),
        ));
    }
    for part in 0..3 {
        let c = DVec2::new(60.0 + 70.0 * part as f64, 100.0);
        let outer = paths.len();
        paths.push(square(c, 30.0, ContourRole::Outer, None, outer));
        for k in 0..4 {
            let off = DVec2::new(
                if k % 2 == 0 { -12.0 } else { 12.0 },
                if k < 2 { -12.0 } else { 12.0 },
            );
            let id = paths.len();
            paths.push(square(c + off, 4.0, ContourRole::Hole, Some(outer), id));
        }
    }
    // An island: outer contour inside a hole, with its own hole.
    let big = paths.len();
    paths.push(square(
        DVec2::new(100.0, 300.0),
        50.0,
        ContourRole::Outer,
        None,
        big,
    ));
    let hole = paths.len();
    paths.push(square(
        DVec2::new(100.0, 300.0),
        30.0,
        ContourRole::Hole,
        Some(big),
        hole,
    ));
    let island = paths.len();
    paths.push(square(
        DVec2::new(100.0, 300.0),
        20.0,
        ContourRole::Outer,
        Some(hole),
        island,
    ));
    let inner = paths.len();
    paths.push(square(
        DVec2::new(100.0, 300.0),
        5.0,
        ContourRole::Hole,
        Some(island),
        inner,
    ));
    // Shuffle deterministically, renumbering containers.
    let n = paths.len();
    let mut perm: Vec<usize> = (0..n).collect();
    for i in (1..n).rev() {
        perm.swap(i, (rng.next() * (i + 1) as f64) as usize);
    }
    let mut new_pos = vec![0; n];
    for (new, &old) in perm.iter().enumerate() {
        new_pos[old] = new;
    }
    perm.iter()
        .map(|&old| {
            let mut p = paths[old].clone();
            p.container = p.container.map(|c| new_pos[c]);
            p
        })
        .collect()
}

#[test]
fn precedence_holds_with_nested_contours() {
    for optimize in [true, false] {
        let out = order(mixed_job(3), DVec2::ZERO, optimize);
        assert_precedence(&out);
        let n = out.iter().flat_map(|p| &p.edges).count();
        assert_permutation(&out, n);
    }
}

#[test]
fn outer_contours_come_last_without_islands() {
    let paths: Vec<Toolpath> = mixed_job(5)
        .into_iter()
        .filter(|p| p.edges[0].index() < 75)
        .collect();
    // Drop the island group (ids ≥ 75) and renumber: keep only paths whose containers survive.
    let ids: Vec<usize> = paths.iter().map(|p| p.edges[0].index()).collect();
    let paths: Vec<Toolpath> = paths
        .into_iter()
        .map(|mut p| {
            p.container = p
                .container
                .and_then(|c| ids.iter().position(|&i| i == c).filter(|_| c < 75));
            p
        })
        .collect();
    let out = order(paths, DVec2::ZERO, true);
    let first_outer = out
        .iter()
        .position(|p| p.role == ContourRole::Outer)
        .unwrap();
    assert!(
        out[first_outer..]
            .iter()
            .all(|p| p.role == ContourRole::Outer)
    );
    assert!(
        out[..first_outer]
            .iter()
            .all(|p| p.role != ContourRole::Outer)
    );
    assert_eq!(
        out.iter().filter(|p| p.role == ContourRole::Outer).count(),
        3
    );
}

#[test]
fn ranks_put_containers_after_contents() {
    let paths = mixed_job(11);
    let r = ranks(&paths);
    for (i, p) in paths.iter().enumerate() {
        if let Some(c) = p.container {
            assert!(r[i] < r[c]);
        }
    }
}

#[test]
fn containers_cycle_or_out_of_range_do_not_hang_or_panic() {
    let mut a = square(DVec2::ZERO, 1.0, ContourRole::Hole, Some(1), 0);
    let b = square(DVec2::ONE, 1.0, ContourRole::Hole, Some(0), 1);
    let c = square(DVec2::ONE * 5.0, 1.0, ContourRole::Hole, Some(99), 2);
    a.container = Some(1);
    let out = order(vec![a, b, c], DVec2::ZERO, true);
    assert_permutation(&out, 3);
}

#[test]
fn strokes_are_preserved_up_to_direction() {
    let input = mixed_job(7);
    let out = order(input.clone(), DVec2::ZERO, true);
    assert_eq!(out.len(), input.len(), "no joins expected here");
    for p in &out {
        let want = input.iter().find(|q| q.edges == p.edges).unwrap();
        assert!(same_up_to_direction(p, want), "{p:?} is not {want:?}");
    }
}

#[test]
fn unoptimised_order_keeps_pattern_order_within_groups() {
    let input = scattered_segments(50, 1, 100.0);
    let out = order(input.clone(), DVec2::ZERO, false);
    assert_eq!(out, input);
}

#[test]
fn optimised_travel_beats_pattern_order_on_scattered_segments() {
    for seed in 1..6 {
        let input = scattered_segments(2000, seed, 500.0);
        let naive = travel_mm(&input, DVec2::ZERO);
        let out = order(input, DVec2::ZERO, true);
        let planned = travel_mm(&out, DVec2::ZERO);
        assert!(planned <= naive, "seed {seed}: {planned} > {naive}");
        assert!(planned < naive / 5.0, "seed {seed}: {planned} vs {naive}");
    }
}

#[test]
fn alternating_far_apart_paths_are_regrouped() {
    let input: Vec<Toolpath> = (0..200)
        .map(|i| {
            let x = if i % 2 == 0 { 0.0 } else { 1000.0 };
            let y = (i / 2) as f64;
            line(
                Operation::Perforate,
                vec![DVec2::new(x, y), DVec2::new(x + 0.5, y)],
                i,
            )
        })
        .collect();
    let naive = travel_mm(&input, DVec2::ZERO);
    let out = order(input, DVec2::ZERO, true);
    let planned = travel_mm(&out, DVec2::ZERO);
    assert!(naive > 199.0 * 999.0);
    assert!(planned < 3000.0, "{planned}");
}

#[test]
fn reversal_and_rotation_are_used() {
    // A segment whose end is near the origin, and a square entered near its far corner.
    let seg = line(
        Operation::Score,
        vec![DVec2::new(50.0, 0.0), DVec2::new(1.0, 0.0)],
        0,
    );
    let sq = square(DVec2::new(60.0, 60.0), 10.0, ContourRole::Outer, None, 1);
    let out = order(vec![sq, seg], DVec2::ZERO, true);
    assert_eq!(out[0].strokes[0][0], DVec2::new(1.0, 0.0));
    assert_eq!(out[1].strokes[0][0], DVec2::new(50.0, 50.0));
    assert_eq!(out[1].strokes[0].last(), Some(&DVec2::new(50.0, 50.0)));
}

#[test]
fn contours_with_lead_ins_keep_their_entry() {
    let mut sq = square(DVec2::new(60.0, 60.0), 10.0, ContourRole::Outer, None, 0);
    sq.strokes[0].insert(0, DVec2::new(75.0, 75.0)); // lead-in: no longer a closed stroke
    let given = sq.clone();
    let out = order(vec![sq], DVec2::ZERO, true);
    assert_eq!(out[0], given);
}

#[test]
fn continuing_paths_are_joined() {
    let p = |x: f64| DVec2::new(x, 10.0);
    // Three pieces of one line, shuffled and one reversed, plus a separate line.
    let input = vec![
        line(Operation::Score, vec![p(2.0), p(3.0)], 0),
        line(Operation::Score, vec![p(2.0), p(1.0)], 1),
        line(Operation::Score, vec![p(0.0), p(1.0)], 2),
        line(
            Operation::Score,
            vec![DVec2::new(0.0, 50.0), DVec2::new(5.0, 50.0)],
            3,
        ),
    ];
    let out = order(input, DVec2::ZERO, true);
    assert_eq!(out.len(), 2);
    assert_eq!(out[0].strokes, vec![vec![p(0.0), p(1.0), p(2.0), p(3.0)]]);
    assert_permutation(&out, 4);
}

#[test]
fn different_operations_are_not_joined() {
    let a = line(Operation::Score, vec![DVec2::ZERO, DVec2::X], 0);
    let b = line(Operation::Perforate, vec![DVec2::X, DVec2::X * 2.0], 1);
    assert_eq!(order(vec![a, b], DVec2::ZERO, true).len(), 2);
}

#[test]
fn empty_toolpaths_are_kept() {
    let mut empty = line(Operation::Score, vec![], 1);
    empty.strokes.clear();
    let out = order(
        vec![
            line(Operation::Score, vec![DVec2::ZERO, DVec2::X], 0),
            empty,
        ],
        DVec2::ZERO,
        true,
    );
    assert_permutation(&out, 2);
}

#[test]
fn travel_counts_moves_between_strokes() {
    let mut p = line(
        Operation::Perforate,
        vec![DVec2::new(3.0, 4.0), DVec2::new(6.0, 4.0)],
        0,
    );
    p.strokes
        .push(vec![DVec2::new(6.0, 8.0), DVec2::new(6.0, 9.0)]);
    assert_eq!(travel_mm(&[p], DVec2::ZERO), 5.0 + 4.0);
}

#[test]
fn many_paths_are_all_kept() {
    let input = scattered_segments(20_000, 9, 2000.0);
    let naive = travel_mm(&input, DVec2::ZERO);
    let out = order(input, DVec2::ZERO, true);
    assert_permutation(&out, 20_000);
    assert!(travel_mm(&out, DVec2::ZERO) < naive / 10.0);
}

fn arb_toolpath(id: usize) -> impl Strategy<Value = Toolpath> {
    let op = prop::sample::select(Operation::ALL.to_vec());
    let pt = (0.0..300.0f64, 0.0..300.0f64).prop_map(|(x, y)| DVec2::new(x, y));
    (op, prop::collection::vec(pt, 1..5), 0..3u8, 1.0..20.0f64).prop_map(
        move |(op, pts, kind, r)| match (op, kind) {
            (Operation::Cut, 0) => square(pts[0], r, ContourRole::Outer, None, id),
            (Operation::Cut, 1) => square(pts[0], r, ContourRole::Hole, None, id),
            _ => line(op, pts, id),
        },
    )
}

fn arb_job() -> impl Strategy<Value = Vec<Toolpath>> {
    (1..40usize)
        .prop_flat_map(|n| (0..n).map(arb_toolpath).collect::<Vec<_>>())
        .prop_flat_map(|paths| {
            let n = paths.len();
            (
                Just(paths),
                prop::collection::vec(prop::option::of(0..n), n),
            )
        })
        .prop_map(|(mut paths, links)| {
            // Holes get a container among the outer contours, when one is drawn.
            for (i, link) in links.into_iter().enumerate() {
                let target = link.filter(|&c| c != i && paths[c].role == ContourRole::Outer);
                if paths[i].role == ContourRole::Hole {
                    paths[i].container = target;
                }
            }
            paths
        })
}

proptest! {
    #[test]
    fn random_jobs_keep_precedence_and_every_toolpath(paths in arb_job(), optimize: bool) {
        let n = paths.len();
        let out = order(paths.clone(), DVec2::ZERO, optimize);
        assert_precedence(&out);
        assert_permutation(&out, n);
        if out.len() == n {
            for p in &out {
                let want = paths.iter().find(|q| q.edges == p.edges).unwrap();
                prop_assert!(same_up_to_direction(p, want));
            }
        }
        let last_outer = out.iter().rposition(|p| p.role == ContourRole::Outer);
        let last_hole = out.iter().rposition(|p| p.role == ContourRole::Hole);
        if let (Some(o), Some(h)) = (last_outer, last_hole) {
            prop_assert!(h < o, "a hole after the last outer contour");
        }
    }
}
