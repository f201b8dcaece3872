//! Which local faults the layer solver lets through as the drawing's rounding.
//!
//! Files from other tools carry rounding: coordinates printed to a few digits, designs
//! computed in single precision, line ends snapped together on import. A vertex whose creases
//! miss Kawasaki's condition by a few hundredths of a degree still folds flat in practice, and
//! Flat-Folder (Akitaya, Demaine & Ku 2023) counts such designs: it works from the folded
//! geometry, with a merge distance scaled to the design's shortest line (the shortest line
//! divided by 300 in its first releases). foldcam judges every vertex on the same scale.
//!
//! # The fitted tolerance
//! Kawasaki's error `E` at a vertex (half the alternating sector sum, radians) is repaired by
//! rotating one crease by `E` (see [`crate::check`](mod@crate::check)); rotating the vertex's shortest crease,
//! of length `ℓ`, moves its far end by `E·ℓ`. The drawing is *precise to* `δ = ℓ_min /
//! `[`PRECISION_DIVISOR`], `ℓ_min` the pattern's shortest edge, so the error is rounding when
//! `E·ℓ ≤ δ`: the vertex closes up by moving a line end no further than the drawing's own
//! precision. That allows `δ/ℓ` radians at each vertex: 0.19° where the shortest crease is the
//! shortest edge, less where the creases are longer. A vertex off by degrees is never
//! rounding (`E·ℓ ≥ E·ℓ_min` exceeds `ℓ_min/300` from `E` = 0.19°).
//!
//! A fixed tolerance in degrees ([`KawasakiTolerance::Degrees`]) replaces the fitted one for
//! users who want the strict local check. Maekawa failures and odd-degree vertices are never
//! rounding.

use serde::{Deserialize, Serialize};

use crate::check::{CheckOptions, CheckReport, Finding, FindingKind, Quantity, check};
use crate::pattern::vertex_fan::VertexFans;
use crate::pattern::{CreasePattern, VertexId};

/// The drawing's precision is its shortest edge divided by this (Flat-Folder's original
/// merge-distance factor).
pub const PRECISION_DIVISOR: f64 = 300.0;

/// Kawasaki errors below this many degrees are not reported at all (the local check's
/// default tolerance): they are floating-point noise or far below any drawing's precision.
pub const NOISE_DEG: f64 = 0.01;

/// How much Kawasaki error the layer solver accepts as rounding.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum KawasakiTolerance {
    /// Fitted to the drawing (see the module docs): the default.
    #[default]
    Fitted,
    /// A fixed tolerance, degrees: every vertex beyond it is refused.
    Degrees(f64),
}

impl KawasakiTolerance {
    /// `Fitted` for `None`, else a fixed tolerance in degrees.
    pub fn from_degrees(degrees: Option<f64>) -> Self {
        degrees.map_or(KawasakiTolerance::Fitted, KawasakiTolerance::Degrees)
    }
}

impl std::fmt::Display for KawasakiTolerance {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            KawasakiTolerance::Fitted => write!(f, "fitted to the drawing"),
            KawasakiTolerance::Degrees(d) => write!(f, "{d}°"),
        }
    }
}

/// The local checks the layer solver needs, sorted: faults it accepts as rounding (each a
/// Kawasaki finding whose `limit` is the tolerance fitted at its vertex) and faults that
/// stop it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LocalFaults {
    /// Kawasaki errors within the tolerance: reported beside the state count.
    pub rounding: Vec<Finding>,
    /// Kawasaki errors beyond it, odd-degree vertices and Maekawa failures, worst first.
    pub refusing: Vec<Finding>,
    /// The drawing's precision, in the pattern's unit (`None` for a fixed tolerance).
    pub precision: Option<f64>,
}

impl LocalFaults {
    /// The fault that stops the layer solver first, if any.
    pub fn first_refusal(&self) -> Option<&Finding> {
        self.refusing.first()
    }
}

/// The drawing's precision: its shortest edge over [`PRECISION_DIVISOR`] (0 for a pattern
/// without edges).
pub fn drawing_precision(cp: &CreasePattern) -> f64 {
    let shortest = cp
        .edge_ids()
        .map(|e| cp.edge_length(e))
        .filter(|&d| d > 0.0)
        .fold(f64::INFINITY, f64::min);
    if shortest.is_finite() {
        shortest / PRECISION_DIVISOR
    } else {
        0.0
    }
}

/// Runs the local flat-foldability checks on `cp` and sorts their faults (see
/// [`LocalFaults`]). With [`KawasakiTolerance::Fitted`], a Kawasaki finding at vertex `v` is
/// rounding when its error times the length of `v`'s shortest crease is at most the drawing's
/// precision.
///
/// The layer solver folds every mountain, valley and unassigned crease flat, whatever fold
/// angle the file stores (a pattern drawn half folded, such as Origami Simulator's creases at
/// half opacity), so Kawasaki and Maekawa are checked at every interior vertex here, not only
/// where the stored angles are ±180° as [`check`] does.
pub fn local_faults(cp: &CreasePattern, tolerance: KawasakiTolerance) -> LocalFaults {
    let floor = match tolerance {
        KawasakiTolerance::Fitted => NOISE_DEG,
        KawasakiTolerance::Degrees(d) => d,
    };
    let options = CheckOptions {
        kawasaki_tolerance_deg: floor,
        ..CheckOptions::default()
    };
    let angled = cp
        .edges
        .iter()
        .any(|e| e.assignment.may_fold() && e.fold_angle.is_some());
    let report = if angled {
        let mut flat = cp.clone();
        for e in &mut flat.edges {
            e.fold_angle = None;
        }
        check(&flat, &options)
    } else {
        check(cp, &options)
    };
    sort_faults(cp, report, tolerance)
}

/// Sorts the Kawasaki and Maekawa findings of `report` (a local check of `cp`) as
/// [`local_faults`] does.
pub fn sort_faults(
    cp: &CreasePattern,
    report: CheckReport,
    tolerance: KawasakiTolerance,
) -> LocalFaults {
    let precision = matches!(tolerance, KawasakiTolerance::Fitted).then(|| drawing_precision(cp));
    let fans = precision.map(|_| VertexFans::new(cp));
    let mut out = LocalFaults {
        precision,
        ..LocalFaults::default()
    };
    for mut f in report.findings {
        match f.kind {
            FindingKind::Maekawa => out.refusing.push(f),
            FindingKind::Kawasaki => {
                let allowed = match (precision, &fans, f.vertex) {
                    (Some(delta), Some(fans), Some(v)) if f.quantity == Quantity::Degrees => {
                        allowed_deg(cp, fans, v, delta)
                    }
                    _ => None,
                };
                match allowed {
                    Some(limit) if f.value <= limit => {
                        f.limit = limit;
                        f.hint = format!(
                            "within the drawing's precision ({:.2e} in the pattern's unit, its \
                             shortest edge / {PRECISION_DIVISOR}): {limit:.4}° allowed at this \
                             vertex; {}",
                            precision.unwrap_or(0.0),
                            f.hint
                        );
                        out.rounding.push(f);
                    }
                    Some(limit) => {
                        f.limit = limit;
                        f.message = format!(
                            "Kawasaki's condition fails by {:.4}°, beyond the {limit:.4}° that \
                             the drawing's precision ({:.2e} in the pattern's unit, its shortest \
                             edge / {PRECISION_DIVISOR}) explains at this vertex",
                            f.value,
                            precision.unwrap_or(0.0)
                        );
                        out.refusing.push(f);
                    }
                    None => out.refusing.push(f),
                }
            }
            _ => {}
        }
    }
    out.refusing
        .sort_by(|a, b| b.severity().total_cmp(&a.severity()));
    out
}

/// The Kawasaki error, degrees, that the drawing's precision `delta` explains at `v`:
/// `delta` over the length of `v`'s shortest crease, as an angle.
fn allowed_deg(cp: &CreasePattern, fans: &VertexFans, v: VertexId, delta: f64) -> Option<f64> {
    let shortest = fans
        .of(v)
        .iter()
        .filter(|s| cp.edges[s.edge.index()].assignment.may_fold())
        .map(|s| cp.edge_length(s.edge))
        .filter(|&d| d > 0.0)
        .fold(f64::INFINITY, f64::min);
    shortest
        .is_finite()
        .then(|| (delta / shortest).to_degrees().max(NOISE_DEG))
}
