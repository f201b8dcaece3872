//! Perforation: dashes of through-cut laid out along each crease, with uncut clearances at
//! its end vertices so that dashes of neighbouring lines never merge.
//!
//! # Layout along one crease
//! A crease of length `L` keeps an uncut end zone of length `e` at both ends, with
//! `e = max(c₀, c₁, b₀)`: the larger of its two end clearances (using the larger at both ends
//! keeps the dash pattern symmetric about the crease middle, so the crease folds the same way
//! from either end), and never less than a nominal bridge `b₀`, since tears start at the ends
//! of a perforated line. On the remaining length `A = L − 2e` it places `n` dashes of length
//! `d` and `n − 1` bridges of length `b`, so `n·d + (n − 1)·b = A` exactly; the end zones are
//! the first and last bridges. With the nominal cut `d₀`, bridge `b₀`, period `p₀ = d₀ + b₀` and
//! duty cycle `D = d₀ / p₀`, the period is stretched to `p = A / (n − 1 + D)` and split as
//! `d = D·p`, `b = (1 − D)·p`: the duty cycle stays exactly nominal and
//! `n = round((A + b₀) / p₀)` makes `p` the closest to `p₀`. `n` is then lowered until
//! `d ≥ min_dash`; a crease with `A < min_dash` gets no dash ([`NoDashes::TooShort`]).
//! A single dash (`n = 1`) fills `A`.
//!
//! Lengths are measured along the crease: a crease may be a chain of edges (a polyline or a
//! flattened curve, see [`super::creases`]), and the caller maps distances back onto it.
//!
//! # Closed creases
//! A crease that closes on itself without meeting another line (a circle) has no end and
//! needs no clearance: [`layout_closed`] places `n = round(L / p₀)` periods of length
//! `p = L / n` all round, each a bridge of `(1 − D)·p` centred on the period's start and a
//! dash of `D·p`, lowering `n` until `d ≥ min_dash`.
//!
//! # Clearance at a vertex
//! Let `W = min_web + kerf`: every cut is `kerf` wide, so two cut centre lines `W` apart leave
//! `min_web` of material between them. Take another line leaving the same vertex at ray
//! angle `θ ∈ (0, π]` from the crease; our dashes start at distance `c` from the vertex.
//! - If that line is perforated too, its dashes also start at `c' ≥ c(θ)` (the rule is
//!   symmetric). Points at distances `s ≥ c`, `t ≥ c` on the two rays are
//!   `√(s² + t² − 2st·cos θ)` apart, least at `s = t = c` (for θ ≤ π/2 a point at `s` is
//!   `s·tan θ ≥ 2c·sin(θ/2)` from the other ray's part beyond `c`), so the dash ends are
//!   `2c·sin(θ/2)` apart and [`dashed_clearance`] is `c ≥ W / (2 sin(θ/2))`.
//! - If it is continuous from the vertex (outline, cut, score: [`super::operations::is_continuous_weakening`]),
//!   a dash point at `c` is `c·sin θ` from it for θ < π/2 and `c` (the vertex) otherwise, so
//!   [`continuous_clearance`] is `c ≥ W / sin θ` below a right angle and `c ≥ W` above.
//!   At a boundary vertex this keeps dashes off the outline (kerf offset only moves the outer
//!   cut further away).
//!
//! Every line at the vertex is checked, not only the neighbours, and `c ≥ vertex_clearance`,
//! measured in toolpath terms: with kerf compensation the vertex clearance grows by `kerf/2`
//! ([`crate::machine::Perforation::for_kerf`]), so the metal between the vertex and the dash's
//! burnt end is the clearance asked. Lines that neither cut nor score (marks, pen lines,
//! skipped edges) are ignored, and do not end a crease either (see [`super::creases`]).
//!
//! Limits: only lines sharing a vertex are considered; two parallel creases closer than `W`
//! without a common vertex are not detected. Ends where the angle is so small that `c`
//! exceeds half the crease leave it uncut (with a warning).

use std::f64::consts::FRAC_PI_2;

use super::Operation;
use crate::machine::Perforation;

/// Floor of the shortest dash, in mm, when the profile allows any length: keeps a dash
/// count finite on a zero `min_dash_mm` (1 pm, far below any machine's resolution).
const DASH_FLOOR_MM: f64 = 1e-9;

/// Most dashes on one crease: a bound against absurd inputs (a kilometre of crease with
/// micrometre dashes), far above any real sheet.
pub const MAX_DASHES: usize = 1_000_000;

/// Dashes fitted to one crease; positions are distances from its first vertex, mm.
#[derive(Clone, Debug, PartialEq)]
pub struct DashLayout {
    /// Uncut length kept at each end, mm.
    pub end_mm: f64,
    /// Length of every dash, mm.
    pub dash_mm: f64,
    /// Length of every bridge between two dashes, mm.
    pub bridge_mm: f64,
    /// `(start, end)` of every dash, increasing.
    pub dashes: Vec<(f64, f64)>,
}

/// Why a crease gets no dashes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NoDashes {
    /// After the end clearances, less than the shortest dash is left.
    TooShort {
        /// Length left between the end zones, mm (negative when they overlap).
        available_mm: f64,
        /// The end zone used at both ends, mm.
        end_mm: f64,
    },
    /// More than [`MAX_DASHES`] dashes would be needed.
    TooMany {
        /// The number needed.
        count: f64,
    },
}

/// The clearance from a vertex at which dashes may start so that they stay `web_mm` (centre
/// to centre) from the dashes of another perforated line at ray angle `angle` (radians,
/// folded into [0, π]). Infinite for a zero angle.
pub fn dashed_clearance(angle: f64, web_mm: f64) -> f64 {
    let s = 2.0 * (fold_angle(angle) / 2.0).sin();
    if s > 0.0 { web_mm / s } else { f64::INFINITY }
}

/// The clearance from a vertex at which dashes may start so that they stay `web_mm` from a
/// line that is cut or scored all the way to the vertex, at ray angle `angle` (radians).
pub fn continuous_clearance(angle: f64, web_mm: f64) -> f64 {
    let a = fold_angle(angle);
    let s = if a >= FRAC_PI_2 { 1.0 } else { a.sin() };
    if s > 0.0 { web_mm / s } else { f64::INFINITY }
}

/// The clearance one neighbouring line of `kind` at ray angle `angle` requires.
pub fn clearance_for(kind: Option<Operation>, continuous: bool, angle: f64, web_mm: f64) -> f64 {
    if continuous {
        continuous_clearance(angle, web_mm)
    } else if kind == Some(Operation::Perforate) {
        dashed_clearance(angle, web_mm)
    } else {
        0.0
    }
}

/// Folds any angle (radians) into the ray angle in [0, π].
fn fold_angle(angle: f64) -> f64 {
    let a = angle.rem_euclid(std::f64::consts::TAU);
    if a > std::f64::consts::PI {
        std::f64::consts::TAU - a
    } else {
        a
    }
}

/// Fits dashes to a crease of `length_mm` whose ends need `clearance_mm`; both end zones get
/// the larger clearance, and at least a nominal bridge (see the module docs for the
/// formulas).
pub fn layout(
    length_mm: f64,
    clearance_mm: [f64; 2],
    perf: &Perforation,
) -> Result<DashLayout, NoDashes> {
    let end_mm = clearance_mm[0].max(clearance_mm[1]).max(perf.bridge_mm);
    let available = length_mm - 2.0 * end_mm;
    let min_dash = perf
        .min_dash_mm
        .max(f64::EPSILON * length_mm.abs())
        .max(DASH_FLOOR_MM);
    // Written so that a NaN length also counts as too short.
    if available.is_nan() || available < min_dash {
        return Err(NoDashes::TooShort {
            available_mm: available,
            end_mm,
        });
    }
    let period0 = perf.cut_mm + perf.bridge_mm;
    let duty = perf.cut_mm / period0;
    let nominal = ((available + perf.bridge_mm) / period0).round();
    // Most dashes that keep d = D·A/(n − 1 + D) ≥ min_dash.
    let longest_allowed = (duty * available / min_dash + 1.0 - duty).floor();
    let n = nominal.min(longest_allowed).max(1.0);
    if n > MAX_DASHES as f64 {
        return Err(NoDashes::TooMany { count: n });
    }
    let period = available / (n - 1.0 + duty);
    let (dash, bridge) = if n == 1.0 {
        (available, 0.0)
    } else {
        (duty * period, (1.0 - duty) * period)
    };
    let dashes = (0..n as usize)
        .map(|i| {
            let start = end_mm + i as f64 * period;
            (start, (start + dash).min(length_mm - end_mm))
        })
        .collect();
    Ok(DashLayout {
        end_mm,
        dash_mm: dash,
        bridge_mm: bridge,
        dashes,
    })
}

/// Fits dashes all round a closed crease of `length_mm` that meets no other line (see the
/// module docs); positions are distances from an arbitrary start, each dash within
/// `[0, length_mm]`.
pub fn layout_closed(length_mm: f64, perf: &Perforation) -> Result<DashLayout, NoDashes> {
    let period0 = perf.cut_mm + perf.bridge_mm;
    let duty = perf.cut_mm / period0;
    let min_dash = perf.min_dash_mm.max(DASH_FLOOR_MM);
    // Written so that a NaN length also counts as too short.
    if length_mm.is_nan() || duty * length_mm < min_dash {
        return Err(NoDashes::TooShort {
            available_mm: length_mm,
            end_mm: 0.0,
        });
    }
    let nominal = (length_mm / period0).round();
    let longest_allowed = (duty * length_mm / min_dash).floor();
    let n = nominal.min(longest_allowed).max(1.0);
    if n > MAX_DASHES as f64 {
        return Err(NoDashes::TooMany { count: n });
    }
    let period = length_mm / n;
    let (dash, bridge) = (duty * period, (1.0 - duty) * period);
    let dashes = (0..n as usize)
        .map(|i| {
            let start = i as f64 * period + bridge / 2.0;
            (start, (start + dash).min(length_mm))
        })
        .collect();
    Ok(DashLayout {
        end_mm: bridge / 2.0,
        dash_mm: dash,
        bridge_mm: bridge,
        dashes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn perf() -> Perforation {
        Perforation {
            cut_mm: 3.0,
            bridge_mm: 1.0,
            min_dash_mm: 0.5,
            min_web_mm: 0.4,
            vertex_clearance_mm: 1.0,
        }
    }

    #[test]
    fn exact_fit_and_nominal_duty() {
        let l = layout(50.0, [1.0, 2.0], &perf()).unwrap();
        assert_eq!(l.end_mm, 2.0);
        let n = l.dashes.len() as f64;
        let total = n * l.dash_mm + (n - 1.0) * l.bridge_mm;
        assert!((total - 46.0).abs() < 1e-9);
        assert!((l.dash_mm / (l.dash_mm + l.bridge_mm) - 0.75).abs() < 1e-12);
        assert!((l.dashes.last().unwrap().1 - 48.0).abs() < 1e-9);
    }

    #[test]
    fn end_zones_are_at_least_a_bridge() {
        let l = layout(50.0, [0.0, 0.2], &perf()).unwrap();
        assert_eq!(l.end_mm, 1.0);
        assert_eq!(l.dashes[0].0, 1.0);
    }

    #[test]
    fn short_crease_gets_one_dash_or_none() {
        assert_eq!(
            layout(3.0, [1.0, 1.0], &perf()).unwrap().dashes,
            vec![(1.0, 2.0)]
        );
        assert!(matches!(
            layout(2.2, [1.0, 1.0], &perf()),
            Err(NoDashes::TooShort { .. })
        ));
        assert!(matches!(
            layout(10.0, [f64::INFINITY, 1.0], &perf()),
            Err(NoDashes::TooShort { .. })
        ));
    }

    #[test]
    fn closed_creases_are_dashed_all_round_at_nominal_duty() {
        let circumference = std::f64::consts::TAU * 10.0;
        let l = layout_closed(circumference, &perf()).unwrap();
        // 62.83 mm / 4 mm periods: 16 periods.
        assert_eq!(l.dashes.len(), 16);
        let cut: f64 = l.dashes.iter().map(|(a, b)| b - a).sum();
        assert!((cut / circumference - 0.75).abs() < 1e-12);
        // The bridges, including the one across the start, are all equal.
        let gaps: Vec<f64> = l
            .dashes
            .windows(2)
            .map(|w| w[1].0 - w[0].1)
            .chain([circumference - l.dashes[15].1 + l.dashes[0].0])
            .collect();
        assert!(
            gaps.iter().all(|g| (g - l.bridge_mm).abs() < 1e-9),
            "{gaps:?}"
        );
        assert!(matches!(
            layout_closed(0.6, &perf()),
            Err(NoDashes::TooShort { .. })
        ));
    }

    #[test]
    fn clearances_match_the_chord_and_sine_formulas() {
        let right = std::f64::consts::FRAC_PI_2;
        assert!((dashed_clearance(right, 1.0) - 1.0 / 2f64.sqrt()).abs() < 1e-12);
        assert_eq!(continuous_clearance(2.0, 1.0), 1.0);
        assert!((continuous_clearance(0.5, 1.0) - 1.0 / 0.5f64.sin()).abs() < 1e-12);
        assert_eq!(dashed_clearance(0.0, 1.0), f64::INFINITY);
        // A reflex gap is the same pair of rays as its complement.
        assert!(
            (dashed_clearance(5.0, 1.0) - dashed_clearance(std::f64::consts::TAU - 5.0, 1.0)).abs()
                < 1e-12
        );
    }
}
