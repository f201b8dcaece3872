//! Kawasaki's and Maekawa's conditions at one interior vertex.
//!
//! Both work on the vertex's crease spokes (mountain, valley, unassigned) in counter-clockwise
//! order. Kawasaki: with sector angles αᵢ between crease i and crease i + 1 (the last sector
//! wraps round to crease 0), the alternating sum S = Σ (−1)ⁱ αᵢ must vanish. Rotating crease i
//! counter-clockwise by δ grows αᵢ₋₁ and shrinks αᵢ, changing S by 2(−1)ⁱ⁻¹δ, so rotating
//! crease i by δᵢ = (−1)ⁱ S/2 repairs the vertex; the reported error is |S|/2. Maekawa: the
//! numbers of mountains and valleys differ by exactly two.

use std::f64::consts::TAU;

use super::{Finding, FindingKind, MvCounts, Quantity};
use crate::limits::KAWASAKI_TOLERANCE;
use crate::pattern::vertex_fan::Spoke;
use crate::pattern::{Assignment, CreasePattern, VertexId};

/// True for spokes whose edge folds (M, V, U).
#[inline]
pub(super) fn is_crease(cp: &CreasePattern, s: &Spoke) -> bool {
    cp.edges[s.edge.index()].assignment.may_fold()
}

/// The crease spokes of a fan, counter-clockwise.
#[inline]
fn creases<'a>(cp: &'a CreasePattern, fan: &'a [Spoke]) -> impl Iterator<Item = &'a Spoke> + 'a {
    fan.iter().filter(move |s| is_crease(cp, s))
}

/// Alternating sum S = Σ (−1)ⁱ αᵢ of the sectors between consecutive angles (radians, sorted
/// ascending in [0, 2π)), and the number of angles. Streams: no allocation.
pub(super) fn alternating_sum(angles: impl Iterator<Item = f64>) -> (f64, usize) {
    let mut first = None;
    let mut prev = 0.0;
    let mut sum = 0.0;
    let mut n = 0usize;
    for a in angles {
        match first {
            None => first = Some(a),
            Some(_) => {
                let sign = if (n - 1).is_multiple_of(2) { 1.0 } else { -1.0 };
                sum += sign * (a - prev);
            }
        }
        prev = a;
        n += 1;
    }
    if let Some(a0) = first {
        let sign = if (n - 1).is_multiple_of(2) { 1.0 } else { -1.0 };
        sum += sign * (a0 + TAU - prev);
    }
    (sum, n)
}

/// Kawasaki's condition at `v` (an interior vertex with at least one crease).
pub(super) fn kawasaki(
    cp: &CreasePattern,
    v: VertexId,
    fan: &[Spoke],
    tolerance_deg: f64,
) -> Option<Finding> {
    let (sum, n) = alternating_sum(creases(cp, fan).map(|s| s.angle));
    let position = cp.position(v);
    if n % 2 == 1 {
        return Some(odd_degree(v, position, n));
    }
    let error_deg = (sum / 2.0).abs().to_degrees();
    if error_deg <= tolerance_deg {
        return None;
    }
    let hint = format!(
        "{} ({})",
        rotation_hint(cp, v, fan, sum),
        tolerance_hint(error_deg)
    );
    Some(Finding {
        kind: FindingKind::Kawasaki,
        vertex: Some(v),
        edge: None,
        position,
        value: error_deg,
        limit: tolerance_deg,
        quantity: Quantity::Degrees,
        mv_counts: None,
        message: format!(
            "alternate sector angles sum to {:.4}° and {:.4}° instead of 180° (error {:.4}°, \
             tolerance {}°)",
            180.0 + (sum / 2.0).to_degrees(),
            180.0 - (sum / 2.0).to_degrees(),
            error_deg,
            tolerance_deg
        ),
        hint,
    })
}

/// The smallest Kawasaki tolerance, rounded up to the four decimals the report prints, that
/// accepts an error of `error_deg`; `None` beyond [`KAWASAKI_TOLERANCE`]'s range (an error
/// that large is no rounding).
pub(super) fn accepting_tolerance(error_deg: f64) -> Option<f64> {
    let t = (error_deg * 1e4).ceil() / 1e4;
    let t = if t < error_deg { t + 1e-4 } else { t };
    (t <= KAWASAKI_TOLERANCE.max).then_some(t.max(KAWASAKI_TOLERANCE.min))
}

/// The option that would change the verdict, named for both front ends (the CLI's
/// `--kawasaki-tolerance`, the studio's Kawasaki tolerance field), with the value that passes.
fn tolerance_hint(error_deg: f64) -> String {
    match accepting_tolerance(error_deg) {
        Some(t) => format!(
            "or, if the drawing is only this precise, accept it with a Kawasaki tolerance of \
             {t:.4}°: {} {t:.4} on the command line, the Kawasaki tolerance field in the studio",
            KAWASAKI_TOLERANCE.option
        ),
        None => format!(
            "no Kawasaki tolerance accepts it: {} takes at most {}°, an error this large is no \
             rounding",
            KAWASAKI_TOLERANCE.option, KAWASAKI_TOLERANCE.max
        ),
    }
}

fn odd_degree(v: VertexId, position: glam::DVec2, n: usize) -> Finding {
    Finding {
        kind: FindingKind::Kawasaki,
        vertex: Some(v),
        edge: None,
        position,
        value: n as f64,
        limit: 0.0,
        quantity: Quantity::Creases,
        mv_counts: None,
        message: format!(
            "{n} creases meet at this interior vertex; folding flat needs an even number"
        ),
        hint: "add or remove a crease at this vertex (an odd degree fails Kawasaki and Maekawa)"
            .to_string(),
    }
}

/// Names the crease whose rotation by |S|/2 keeps the most room in the sector it shrinks.
fn rotation_hint(cp: &CreasePattern, v: VertexId, fan: &[Spoke], sum: f64) -> String {
    let spokes: Vec<&Spoke> = creases(cp, fan).collect();
    let n = spokes.len();
    let sector = |i: usize| {
        let next = spokes[(i + 1) % n].angle + if i + 1 == n { TAU } else { 0.0 };
        next - spokes[i].angle
    };
    let half = sum / 2.0;
    let best = (0..n)
        .map(|i| {
            let delta = if i % 2 == 0 { half } else { -half };
            let shrunk = if delta > 0.0 {
                sector(i)
            } else {
                sector((i + n - 1) % n)
            };
            (i, delta, shrunk - delta.abs())
        })
        .max_by(|a, b| a.2.total_cmp(&b.2));
    match best {
        Some((i, delta, _)) => format!(
            "rotate crease {} about {v} by {:.4}° {}",
            spokes[i].edge,
            delta.abs().to_degrees(),
            if delta > 0.0 {
                "counter-clockwise"
            } else {
                "clockwise"
            }
        ),
        None => String::new(),
    }
}

/// Outcome of Maekawa's check at one vertex.
pub(super) enum Maekawa {
    /// |M − V| = 2.
    Pass,
    /// A crease is unassigned: not checked.
    Skipped,
    /// It fails.
    Fail(Box<Finding>),
}

/// Maekawa's condition at `v` (an interior vertex of even degree).
pub(super) fn maekawa(cp: &CreasePattern, v: VertexId, fan: &[Spoke]) -> Maekawa {
    let Some((m, vv)) = mountains_and_valleys(cp, fan) else {
        return Maekawa::Skipped;
    };
    let diff = i64::from(m) - i64::from(vv);
    if diff.abs() == 2 {
        return Maekawa::Pass;
    }
    Maekawa::Fail(Box::new(Finding {
        kind: FindingKind::Maekawa,
        vertex: Some(v),
        edge: None,
        position: cp.position(v),
        value: diff.abs() as f64,
        limit: 2.0,
        quantity: Quantity::MountainValleyDifference,
        mv_counts: Some(MvCounts {
            mountains: m,
            valleys: vv,
        }),
        message: format!(
            "{m} mountains and {vv} valleys: |M − V| = {} instead of 2",
            diff.abs()
        ),
        hint: maekawa_hint(m, vv),
    }))
}

/// The mountains and valleys among the creases of `fan`; `None` when one is neither.
fn mountains_and_valleys(cp: &CreasePattern, fan: &[Spoke]) -> Option<(u32, u32)> {
    let (mut m, mut v) = (0u32, 0u32);
    for s in creases(cp, fan) {
        match cp.edges[s.edge.index()].assignment {
            Assignment::Mountain => m += 1,
            Assignment::Valley => v += 1,
            _ => return None,
        }
    }
    Some((m, v))
}

/// Whether the creases of `fan` satisfy Kawasaki (within `tolerance_deg`) and Maekawa, every
/// crease assigned, without building findings: for vertices that fold to 3D targets, where
/// failing either is no fault ([`super::vertex`] counts those that would fold flat anyway).
pub(super) fn creases_fold_flat(cp: &CreasePattern, fan: &[Spoke], tolerance_deg: f64) -> bool {
    let (sum, n) = alternating_sum(creases(cp, fan).map(|s| s.angle));
    n % 2 == 0
        && (sum / 2.0).abs().to_degrees() <= tolerance_deg
        && mountains_and_valleys(cp, fan).is_some_and(|(m, v)| m.abs_diff(v) == 2)
}

fn plural(n: u32) -> &'static str {
    if n == 1 { "" } else { "s" }
}

/// How many creases to flip, and which way, to reach |M − V| = 2 (even degree).
fn maekawa_hint(m: u32, v: u32) -> String {
    let diff = i64::from(m) - i64::from(v);
    if diff > 2 {
        let k = (diff - 2) / 2;
        format!("flip {k} of the {m} mountain{} to valley", plural(m))
    } else if diff < -2 {
        let k = (-diff - 2) / 2;
        format!("flip {k} of the {v} valley{} to mountain", plural(v))
    } else {
        format!(
            "flip one of the {m} mountain{} to valley, or one of the {v} valley{} to mountain",
            plural(m),
            plural(v)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alternating_sum_of_right_angles_is_zero() {
        let q = std::f64::consts::FRAC_PI_2;
        let (s, n) = alternating_sum([0.0, q, 2.0 * q, 3.0 * q].into_iter());
        assert_eq!(n, 4);
        assert!(s.abs() < 1e-12);
    }

    #[test]
    fn two_straight_creases_and_a_kink() {
        let (s, _) = alternating_sum([0.0, std::f64::consts::PI].into_iter());
        assert!(s.abs() < 1e-12);
        // Sectors 100° and 260°: S = −160°, error 80°.
        let (s, _) = alternating_sum([0.0, 100f64.to_radians()].into_iter());
        assert!((s.to_degrees() + 160.0).abs() < 1e-9);
    }

    #[test]
    fn maekawa_hints_name_the_flip() {
        assert_eq!(maekawa_hint(4, 0), "flip 1 of the 4 mountains to valley");
        assert_eq!(maekawa_hint(0, 6), "flip 2 of the 6 valleys to mountain");
        assert!(maekawa_hint(2, 2).starts_with("flip one of the 2 mountains"));
    }
}
