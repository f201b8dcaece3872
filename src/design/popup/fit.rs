//! Fitting a card that reaches beyond its own outline when folded shut (`--fit`).
//!
//! Closing a 90° card (Mitani, Suzuki & Uno 2003, eq. 6, at θ = 180°) maps a card point
//! `(x, y, z)` to `(x, y + z)` in the plane of the closed card: a face standing `y` mm in front
//! of the back sheet and `z` mm above the base ends `y + z` mm above the central fold. The
//! closed card's outline is as high as the taller of its two halves (back sheet and base),
//! so a model whose depth plus height exceeds it overhangs there, and only there: every
//! fold runs parallel to the central one, so nothing moves along x, and `y + z ≥ 0` keeps
//! everything above the fold.
//!
//! Fitting keeps the model and grows the paper above it: the back sheet of a polygon design
//! (`[card] height`), or the margin of a voxel card (flat paper on every side; the voxel card
//! has one margin for all four), by the overhang rounded up to [`FIT_STEP_MM`], until the
//! closed card holds every folded vertex. An overhang anywhere but above the outline
//! (which the transform above rules out for a valid card) or one still left after
//! [`FIT_ROUNDS`] rounds is refused with its place.

use super::integrity::{Overhang, closed_overhang};
use super::polygon::{self, Design, DesignError};
use super::voxel::{self, VoxelCard, VoxelError};
use crate::pattern::{FoldedState, PlanarizeError};

/// Paper is added in whole steps of this many millimetres.
pub const FIT_STEP_MM: f64 = 1.0;

/// At most this many rounds of growing and re-folding (one suffices for a valid card; the
/// rest guard against rounding).
pub const FIT_ROUNDS: usize = 4;

/// How far a closed card may reach beyond its outline before it counts, mm: rounding of the
/// folded positions, far below a cut's width.
pub const CLOSED_SLACK_MM: f64 = 1e-6;

/// How far the folded vertices of a closed card reach past each side of its outline, mm (0
/// where they stay inside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reach {
    /// Past the top edge (the far edge of the taller half).
    pub above_mm: f64,
    /// Past the central fold, the sides: anywhere else.
    pub elsewhere_mm: f64,
    /// The farthest vertex and the outline, as [`closed_overhang`] reports them.
    pub overhang: Overhang,
}

/// The reach of `closed` (a card folded shut, opening 0°) past each side of its outline;
/// `None` without an outline.
pub fn closed_reach(closed: &FoldedState) -> Option<Reach> {
    let overhang = closed_overhang(closed)?;
    let (lo, hi) = overhang.outline;
    let mut above: f64 = 0.0;
    let mut elsewhere: f64 = 0.0;
    for p in closed.positions.iter().map(|p| p.truncate()) {
        above = above.max(p.y - hi.y);
        elsewhere = elsewhere.max(lo.y - p.y).max(lo.x - p.x).max(p.x - hi.x);
    }
    Some(Reach {
        above_mm: above,
        elsewhere_mm: elsewhere,
        overhang,
    })
}

/// Why a card could not be fitted.
#[derive(Debug, thiserror::Error)]
pub enum FitError {
    /// The card reaches past a side that more paper above cannot cover (the message names
    /// how far and where).
    #[error("{message}")]
    Unfittable {
        /// The overhang left.
        overhang: Overhang,
        /// What and where, in words.
        message: String,
    },
    /// The card with more paper could not be built.
    #[error("the card with more paper: {0}")]
    Voxel(#[from] VoxelError),
    /// The design with more paper could not be replayed.
    #[error("the design with more paper: {0}")]
    Design(#[from] DesignError),
    /// Its crease pattern could not be built.
    #[error("the card with more paper: {0}")]
    Pattern(#[from] PlanarizeError),
}

impl FitError {
    fn unfittable(o: Overhang) -> Self {
        let size = o.outline.1 - o.outline.0;
        FitError::Unfittable {
            message: format!(
                "folded shut, the card reaches {:.1} mm beyond its {:.1} × {:.1} mm outline at \
                 x = {:.1}, y = {:.1} mm of the closed card, past {}; more paper above the model \
                 does not hold it",
                o.beyond_mm,
                size.x,
                size.y,
                o.at.x,
                o.at.y,
                side(&o)
            ),
            overhang: o,
        }
    }
}

/// Which side of the outline the farthest vertex is past, in words.
fn side(o: &Overhang) -> &'static str {
    let (lo, hi) = o.outline;
    let d = [
        (lo.y - o.at.y, "the central fold"),
        (o.at.y - hi.y, "the top edge"),
        (lo.x - o.at.x, "the left edge"),
        (o.at.x - hi.x, "the right edge"),
    ];
    d.iter()
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map_or("the outline", |x| x.1)
}

/// What fitting did.
#[derive(Clone, Debug, PartialEq)]
pub struct Fitted<T> {
    /// The card (or design) with the paper it needs; unchanged when it already fitted.
    pub card: T,
    /// Paper added above the model, mm (0 when it already fitted).
    pub added_mm: f64,
    /// The overhang before fitting, if there was one.
    pub before: Option<Overhang>,
}

/// Rounds a shortfall up to whole [`FIT_STEP_MM`] steps (at least one).
fn step_up(mm: f64) -> f64 {
    (mm / FIT_STEP_MM).ceil().max(1.0) * FIT_STEP_MM
}

/// Grows `grow(card, mm)` until `closed(card)` holds every folded vertex (see the module
/// docs); refuses an overhang that is not above the outline.
fn fit_with<T: Clone>(
    card: &T,
    closed: impl Fn(&T) -> Result<FoldedState, FitError>,
    grow: impl Fn(&T, f64) -> Result<T, FitError>,
) -> Result<Fitted<T>, FitError> {
    let mut current = card.clone();
    let mut added = 0.0;
    let mut before = None;
    for _ in 0..=FIT_ROUNDS {
        let Some(reach) = closed_reach(&closed(&current)?) else {
            break;
        };
        if reach.overhang.beyond_mm <= CLOSED_SLACK_MM {
            break;
        }
        before.get_or_insert(reach.overhang);
        if reach.elsewhere_mm > CLOSED_SLACK_MM || (added > 0.0 && reach.above_mm <= 0.0) {
            return Err(FitError::unfittable(reach.overhang));
        }
        let more = step_up(reach.above_mm);
        current = grow(&current, more)?;
        added += more;
    }
    if let Some(reach) = closed_reach(&closed(&current)?)
        && reach.overhang.beyond_mm > CLOSED_SLACK_MM
    {
        return Err(FitError::unfittable(reach.overhang));
    }
    Ok(Fitted {
        card: current,
        added_mm: added,
        before,
    })
}

/// Fits a voxel card by growing its margin (see the module docs).
pub fn fit_voxel_card(card: &VoxelCard) -> Result<Fitted<VoxelCard>, FitError> {
    fit_with(
        card,
        |c| {
            let cp = voxel::crease_pattern(c)?;
            Ok(voxel::fold_card(c, &cp, 0.0).state)
        },
        |c, more| {
            let mut grown = c.clone();
            grown.set_margin_mm(c.margin_mm() + more)?;
            Ok(grown)
        },
    )
}

/// Fits a polygon design by growing its back sheet (`[card] height`; see the module docs).
pub fn fit_design(design: &Design) -> Result<Fitted<Design>, FitError> {
    fit_with(
        design,
        |d| {
            let card = d.build()?;
            let cp = polygon::crease_pattern(&card)?;
            Ok(polygon::fold_card(&card, &cp, 0.0).state)
        },
        |d, more| {
            let mut grown = d.clone();
            grown.card.height += more;
            Ok(grown)
        },
    )
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::pattern::{Assignment, Edge, VertexId};

    /// A closed 10 × 10 mm card (outline in z = 0) with one crease out to `tip`.
    fn closed_card(top: f64, tip: (f64, f64)) -> FoldedState {
        let p = [
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, top),
            (0.0, top),
            (5.0, 5.0),
            tip,
        ];
        let edge = |a: usize, b: usize, assignment| Edge {
            vertices: [VertexId::new(a), VertexId::new(b)],
            assignment,
            fold_angle: None,
        };
        FoldedState {
            positions: p.iter().map(|&(x, y)| DVec3::new(x, y, 0.0)).collect(),
            edges: vec![
                edge(0, 1, Assignment::Boundary),
                edge(1, 2, Assignment::Boundary),
                edge(2, 3, Assignment::Boundary),
                edge(3, 0, Assignment::Boundary),
                edge(4, 5, Assignment::Valley),
            ],
            ..FoldedState::default()
        }
    }

    /// The card as a stand-in for a design: its top edge's height and the crease's tip.
    fn fit_top(top: f64, tip: (f64, f64)) -> Result<Fitted<f64>, FitError> {
        fit_with(&top, |&t| Ok(closed_card(t, tip)), |&t, more| Ok(t + more))
    }

    #[test]
    fn a_card_reaching_above_gets_the_shortfall_in_whole_millimetres() {
        let fitted = fit_top(10.0, (5.0, 12.4)).unwrap();
        assert_eq!(fitted.added_mm, 3.0);
        assert_eq!(fitted.card, 13.0);
        assert!((fitted.before.unwrap().beyond_mm - 2.4).abs() < 1e-9);
        let as_is = fit_top(10.0, (5.0, 9.0)).unwrap();
        assert_eq!((as_is.added_mm, as_is.before), (0.0, None));
    }

    #[test]
    fn a_card_reaching_past_a_side_is_refused_with_the_place() {
        let err = fit_top(10.0, (-3.0, 5.0)).unwrap_err().to_string();
        assert!(err.contains("3.0 mm beyond"), "{err}");
        assert!(err.contains("x = -3.0, y = 5.0"), "{err}");
        assert!(err.contains("the left edge"), "{err}");
    }
}
