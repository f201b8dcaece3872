//! Where a LinuxCNC laser switches its beam inside a run of burns, and how it travels between
//! them, so that LinuxCNC's trajectory planner does not slow down at the switch.
//!
//! A synchronised output (`M62`/`M63`, `M67`) is attached to the next move and changes as that
//! move starts. LinuxCNC 2.9's planner (`tp.c`) treats such a move specially: a blend arc may
//! not consume it (`tcCanConsume` refuses a segment whose `syncdio` changed), and measured on
//! LinuxCNC 2.9 with `linuxcnc-fiber`'s limits (`../shared/oracles`), a corner into it is not
//! blended at speed: on a 15 mm circle of 0.5 mm chords at 10 m/min, an `M67` at every 8th
//! vertex takes the lap from 3.9 s to 14.6 s (about 76 ms a switch, more than a full stop),
//! while an `M67` that splits a chord into two halves (no corner: LinuxCNC's tangent case,
//! `tpSetupTangent`) costs about 9 ms. A segment that is not consumed also runs no faster than
//! its length per servo period (`tcClampVelocityByLength`; 1 ms here), so a short piece beside
//! the switch slows too.
//!
//! On a curved crease (a polyline of short chords) every dash starts and ends at a corner of
//! the straight link across the bridge. So, on a machine that links burns with feed moves
//! ([`super::MachineProfile::links_burns_with_feed_moves`]), the writer and the time estimate
//! both:
//!
//! - **tidy the ends of each burn** ([`tidy_ends`]): while a first or last piece is shorter
//!   than [`MIN_PIECE_MM`], its inner point is dropped if it lies within the profile's `G64 P`
//!   ([`max_deviation_mm`]) of the line that replaces the two pieces (the dash keeps its ends;
//!   the path moves by no more than LinuxCNC's own blending moves it at every corner), so the
//!   moves beside a switch are as long as the curve allows;
//! - **link tangentially** ([`link`]): the beam-off travel leaves a burn along its last piece
//!   and reaches the next burn along its first piece, turning once where the two lines meet
//!   (a grid point whose legs follow them within three quarters of LinuxCNC's tangent limit,
//!   [`tangent_limit_rad`]), so the move that carries the
//!   switch continues its predecessor without a corner. A link whose ends already continue
//!   the burns (a straight crease) stays one move. Measured on LinuxCNC 2.9: Origami
//!   Simulator's `HexSpiralTess.svg` at 200 mm on `linuxcnc-fiber` and 0.5 mm stainless runs
//!   88.8 s with straight links, 71.4 s with these links alone, and 51.2 s with the ends also
//!   tidied (48.5 s with no power changes at all; merging end pieces under 0.45 mm only:
//!   55.1 s, under 0.7 mm: 53.0 s).
//!
//! All points are grid counts of the machine's resolution (what the writer prints), so the
//! collinearity is exact in the numbers LinuxCNC reads.

use glam::DVec2;

/// A point in grid counts (multiples of the machine's resolution).
pub(crate) type Counts = (i64, i64);

/// A burn's first or last piece shorter than this (mm) is merged with its neighbour while the
/// path allows ([`tidy_ends`]). Measured on LinuxCNC (see the module docs), longer pieces
/// beside a switch run faster, up to about this length.
pub(crate) const MIN_PIECE_MM: f64 = 1.0;

/// How far (mm) the path of a burn may move when a short end piece is merged on `machine`:
/// its `G64 P` (`blend_tolerance_mm`, how far LinuxCNC's blending may leave the path at a
/// corner), or 0.005 mm without one.
pub(crate) fn max_deviation_mm(machine: &super::MachineProfile) -> f64 {
    machine.control.blend_tolerance_mm.unwrap_or(0.005)
}

/// LinuxCNC's servo period (s) as the oracle runs it and LinuxCNC ships it (`SERVO_PERIOD`
/// 1,000,000 ns).
const SERVO_PERIOD_S: f64 = 0.001;

/// The largest angle (radians) between two moves that LinuxCNC 2.9 still joins as tangent, with
/// no corner, on `machine` at its travel feed (`findMaxTangentAngle` in `blendmath.c`:
/// √3/2 × 0.25 × a × servo period / v; 0.0013 rad on `linuxcnc-fiber`).
pub(crate) fn tangent_limit_rad(machine: &super::MachineProfile) -> f64 {
    let v = machine.travel_feed_mm_min.min(machine.max_feed_mm_min) / 60.0;
    0.75_f64.sqrt() * 0.25 * machine.acceleration_mm_s2 * SERVO_PERIOD_S / v
}

fn v(p: Counts) -> DVec2 {
    DVec2::new(p.0 as f64, p.1 as f64)
}

/// Distance (counts) of `b` from the line through `a` and `c`.
fn deviation(a: Counts, b: Counts, c: Counts) -> f64 {
    let (a, b, c) = (v(a), v(b), v(c));
    let d = c - a;
    let len = d.length();
    if len == 0.0 {
        return a.distance(b);
    }
    d.perp_dot(b - a).abs() / len
}

/// The sine of the angle between `d1` and `d2`, or 1 when they point apart or one is zero.
fn turn(d1: DVec2, d2: DVec2) -> f64 {
    let n = d1.length() * d2.length();
    if n == 0.0 || d1.dot(d2) <= 0.0 {
        return 1.0;
    }
    (d1.perp_dot(d2) / n).abs()
}

/// Drops the inner point of a first or last piece shorter than `min_piece` counts when it lies
/// within `max_deviation` counts of the line that replaces the two pieces (see the module
/// docs); the burn keeps its ends and at least one piece.
pub(crate) fn tidy_ends(points: &mut Vec<Counts>, min_piece: f64, max_deviation: f64) {
    let short = |a: Counts, b: Counts| v(a).distance(v(b)) < min_piece;
    while points.len() >= 3
        && short(points[0], points[1])
        && deviation(points[0], points[1], points[2]) <= max_deviation
    {
        points.remove(1);
    }
    while points.len() >= 3 {
        let n = points.len();
        if short(points[n - 2], points[n - 1])
            && deviation(points[n - 3], points[n - 2], points[n - 1]) <= max_deviation
        {
            points.remove(n - 2);
        } else {
            break;
        }
    }
}

/// The grid point at `from` + t·`dir` (unit `dir`) for some t in `lo..=hi` counts whose
/// direction from `from` is closest to `dir`: exactly collinear when a grid point lies on the
/// line there.
fn lead(from: Counts, dir: DVec2, lo: f64, hi: f64) -> Option<Counts> {
    let major = dir.x.abs().max(dir.y.abs());
    if major == 0.0 || hi < lo || hi < 1.0 {
        return None;
    }
    let (first, last) = ((lo * major).ceil().max(1.0), (hi * major).floor());
    let mut best: Option<(f64, Counts)> = None;
    let mut n = first;
    while n <= last {
        let t = n / major;
        let step = (dir * t).round();
        let err = turn(dir, step);
        if best.is_none_or(|(e, _)| err < e) {
            best = Some((err, (from.0 + step.x as i64, from.1 + step.y as i64)));
            if err == 0.0 {
                break;
            }
        }
        n += 1.0;
    }
    best.map(|(_, p)| p)
}

/// The points of the beam-off travel from the end of burn `prev` to the start of burn `next`
/// (both at least two points, in counts), after `prev`'s last point and ending with `next`'s
/// first, so that it leaves `prev` along its last piece and reaches `next` along its first
/// piece (see the module docs), `tangent_rad` being LinuxCNC's tangent limit
/// ([`tangent_limit_rad`]):
///
/// - nothing between when the straight link already does within `tangent_rad` (a straight
///   crease);
/// - else one corner where the line of `prev`'s last piece meets the line of `next`'s first,
///   when that point lies in the middle of the gap (from 0.2 to 0.8 of it along each line):
///   the grid point near it whose two legs are closest to those lines, within three quarters
///   of `tangent_rad`;
/// - else a lead-out and a lead-in, each between half and all of the smaller of a third of
///   the gap and `min_piece` × 2 counts, on grid points along those lines.
pub(crate) fn link(
    prev: &[Counts],
    next: &[Counts],
    min_piece: f64,
    tangent_rad: f64,
) -> Vec<Counts> {
    let (c, q) = (prev[prev.len() - 2], prev[prev.len() - 1]);
    let (p0, p1) = (next[0], next[1]);
    let gap = v(p0) - v(q);
    let out_dir = (v(q) - v(c)).normalize_or_zero();
    let in_dir = (v(p1) - v(p0)).normalize_or_zero();
    let (bends_out, bends_in) = (
        turn(out_dir, gap) > tangent_rad,
        turn(gap, in_dir) > tangent_rad,
    );
    if !bends_out && !bends_in {
        return vec![p0];
    }
    if let Some(x) = corner(q, out_dir, p0, in_dir, 0.75 * tangent_rad) {
        return vec![x, p0];
    }
    let hi = (2.0 * min_piece).min(gap.length() / 3.0);
    let lo = hi / 2.0;
    let mut points = Vec::new();
    if bends_out && let Some(s) = lead(q, out_dir, lo, hi) {
        points.push(s);
    }
    if bends_in && let Some(r) = lead(p0, -in_dir, lo, hi) {
        // The lead-in must stay ahead of the lead-out, or the link would double back.
        let from = points.last().copied().unwrap_or(q);
        if (v(r) - v(from)).dot(gap) > 0.0 {
            points.push(r);
        }
    }
    points.push(p0);
    points
}

/// Half the side (counts) of the square of grid points searched around a link's corner.
const CORNER_SEARCH: i64 = 40;

/// The grid point `x` near where the line from `q` along `out_dir` meets the line into `p0`
/// along `in_dir`, with `q`→`x` along `out_dir` and `x`→`p0` along `in_dir` within
/// `max_rad`, when the lines meet inside the gap (see [`link`]).
fn corner(q: Counts, out_dir: DVec2, p0: Counts, in_dir: DVec2, max_rad: f64) -> Option<Counts> {
    let gap = v(p0) - v(q);
    let det = out_dir.perp_dot(in_dir);
    if det.abs() < 1e-9 {
        return None;
    }
    // q + s·out = p0 − t·in.
    let s = gap.perp_dot(in_dir) / det;
    let t = out_dir.perp_dot(gap) / det;
    let len = gap.length();
    let inside = |d: f64| (0.2 * len..=0.8 * len).contains(&d);
    if !(inside(s) && inside(t)) {
        return None;
    }
    let ideal = (v(q) + out_dir * s).round();
    let mut best: Option<(f64, Counts)> = None;
    for dx in -CORNER_SEARCH..=CORNER_SEARCH {
        for dy in -CORNER_SEARCH..=CORNER_SEARCH {
            let x = (ideal.x as i64 + dx, ideal.y as i64 + dy);
            let err = turn(out_dir, v(x) - v(q)).max(turn(v(p0) - v(x), in_dir));
            if best.is_none_or(|(e, _)| err < e) {
                best = Some((err, x));
            }
        }
    }
    best.filter(|&(e, _)| e <= max_rad).map(|(_, x)| x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// LinuxCNC's tangent limit on `linuxcnc-fiber`: √3/2 × 0.25 × 3000 × 0.001 / 500.
    const LIMIT: f64 = 0.001_299;

    #[test]
    fn a_short_end_piece_on_a_gentle_curve_is_merged_and_a_corner_is_kept() {
        // 0.015 mm then 0.5 mm, turning 0.05 rad: the inner point is 0.0007 mm off.
        let mut gentle = vec![(0, 0), (15, 0), (515, 25)];
        tidy_ends(&mut gentle, 250.0, 5.0);
        assert_eq!(gentle, vec![(0, 0), (515, 25)]);
        // A right angle after 0.1 mm keeps its corner (0.07 mm off the short cut).
        let mut corner = vec![(0, 0), (100, 0), (100, 500)];
        tidy_ends(&mut corner, 250.0, 5.0);
        assert_eq!(corner, vec![(0, 0), (100, 0), (100, 500)]);
    }

    #[test]
    fn a_link_between_dashes_of_a_curve_leaves_and_arrives_along_the_dashes() {
        // Dashes along a circle of radius 15 mm (counts of 0.001 mm): the link turns at both
        // ends when straight.
        let at = |deg: f64| {
            let a = deg.to_radians();
            (
                (15_000.0 * a.cos()).round() as i64,
                (15_000.0 * a.sin()).round() as i64,
            )
        };
        let prev = [at(0.0), at(2.0)];
        let next = [at(6.0), at(8.0)];
        let points = link(&prev, &next, 250.0, LIMIT);
        assert_eq!(points.len(), 2, "{points:?}");
        assert_eq!(points[1], next[0]);
        let d = |a: Counts, b: Counts| v(b) - v(a);
        // One corner: the first leg continues the last piece, the second leads into the
        // first piece, each within three quarters of the tangent limit, and both about half
        // the 1.05 mm gap.
        assert!(turn(d(prev[0], prev[1]), d(prev[1], points[0])) <= 0.75 * LIMIT);
        assert!(turn(d(points[0], next[0]), d(next[0], next[1])) <= 0.75 * LIMIT);
        for w in [prev[1], points[0], next[0]].windows(2) {
            assert!(v(w[0]).distance(v(w[1])) >= 400.0, "{points:?}");
        }
    }

    #[test]
    fn a_link_along_a_straight_crease_stays_one_move() {
        let prev = [(0, 0), (5_000, 0)];
        let next = [(6_000, 0), (11_000, 0)];
        assert_eq!(link(&prev, &next, 250.0, LIMIT), vec![(6_000, 0)]);
    }

    #[test]
    fn the_tangent_limit_is_linuxcncs_on_the_fiber_laser() {
        let m = crate::machine::load_machine("linuxcnc-fiber").unwrap();
        assert!(
            (tangent_limit_rad(&m) - LIMIT).abs() < 1e-6,
            "{}",
            tangent_limit_rad(&m)
        );
    }
}
