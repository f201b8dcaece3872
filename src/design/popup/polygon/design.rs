//! Design files: the user's operations of Mitani & Suzuki (2004), §3.1, replayed on a [`PolygonCard`].
//!
//! A design is a TOML file: the card size, then operations in order. Each operation places a
//! vertical (y = `at`) or horizontal (z = `at`) reference plane, gives a polygon on it and adds
//! it as a face (§3.2) or as an opening (§3.3, eq. 6).
//!
//! ```toml
//! [card]
//! width = 120.0     # mm along the central fold
//! depth = 60.0      # mm of base sheet in front of the fold
//! height = 80.0     # mm of back sheet above the fold
//! grid = 5.0        # optional: mm per grid unit, for operations with units = "grid"
//!
//! [[operation]]
//! plane = "vertical"          # "vertical" (y = at) or "horizontal" (z = at)
//! at = 30.0                   # position of the reference plane
//! polygon = [[40, 0], [80, 0], [80, 30], [40, 30]]   # (x, z) on vertical, (x, y) on horizontal
//! add = "face"                # "face" (default) or "opening"
//! units = "mm"                # "mm" (default) or "grid": `at` and points in grid units
//! ```
//!
//! Unknown keys are errors. Errors name the operation (1-based) and the problem; the caller
//! adds the file name.

use glam::DVec2;
use serde::Deserialize;
use thiserror::Error;

use super::check::{PopupReport, check_popup};
use super::model::{FaceKind, PolygonCard, PolygonError};

/// Most operations in one design.
pub const MAX_OPERATIONS: usize = 10_000;

/// Most polygon points in one design, all operations together.
pub const MAX_DESIGN_POINTS: usize = 1_000_000;

/// Why a design cannot be replayed.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum DesignError {
    /// Not valid TOML or not the design schema (the message holds the line).
    #[error("{0}")]
    Syntax(String),
    /// The card size is refused.
    #[error("[card]: {0}")]
    Card(PolygonError),
    /// An operation uses grid units but `[card] grid` is missing or not positive.
    #[error("operation {0}: units = \"grid\" needs a finite positive [card] grid size (mm)")]
    NoGrid(usize),
    /// An operation is refused by the model.
    #[error("operation {index}: {source}")]
    Operation {
        /// 1-based operation index.
        index: usize,
        /// The problem.
        source: PolygonError,
    },
    /// More than [`MAX_OPERATIONS`] operations.
    #[error("{0} operations, more than the {MAX_OPERATIONS} allowed")]
    TooMany(usize),
    /// More than [`MAX_DESIGN_POINTS`] polygon points in all.
    #[error("{0} polygon points in all, more than the {MAX_DESIGN_POINTS} allowed")]
    TooManyPoints(usize),
}

/// The card section.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CardSize {
    /// Millimetres along the fold.
    pub width: f64,
    /// Millimetres of base sheet.
    pub depth: f64,
    /// Millimetres of back sheet.
    pub height: f64,
    /// Grid size in millimetres for operations in grid units.
    pub grid: Option<f64>,
}

/// Whether an operation adds a face or an opening.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Add {
    /// A face on the reference plane (§3.2).
    #[default]
    Face,
    /// An opening in the reference plane (§3.3).
    Opening,
}

/// The unit of an operation's numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Units {
    /// Millimetres.
    #[default]
    Mm,
    /// Multiples of `[card] grid`.
    Grid,
}

/// One operation of §3.1.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Operation {
    /// The reference plane's kind.
    pub plane: PlaneName,
    /// Its position: y for vertical, z for horizontal.
    pub at: f64,
    /// Points on the plane: (x, z) on vertical planes, (x, y) on horizontal ones.
    pub polygon: Vec<[f64; 2]>,
    /// Face or opening.
    #[serde(default)]
    pub add: Add,
    /// Millimetres or grid units.
    #[serde(default)]
    pub units: Units,
}

/// The name of a reference plane's kind in a design file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PlaneName {
    /// y = at.
    Vertical,
    /// z = at.
    Horizontal,
}

/// A parsed design file.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Design {
    /// The card size.
    pub card: CardSize,
    /// The operations, in order.
    #[serde(default, rename = "operation")]
    pub operations: Vec<Operation>,
}

/// The outcome of [`Design::replay`].
#[derive(Clone, Debug, PartialEq)]
pub struct Replay {
    /// The card after every operation.
    pub card: PolygonCard,
    /// The pop-up check of the final card.
    pub report: PopupReport,
    /// When the final card fails: the 1-based operation after which it last turned from
    /// passing to failing (the blank card passes, so at least 1); `None` when it passes.
    pub became_invalid_after: Option<usize>,
}

/// Parses a design file.
pub fn parse_design(text: &str) -> Result<Design, DesignError> {
    let design: Design = toml::from_str(text).map_err(|e| DesignError::Syntax(e.to_string()))?;
    if design.operations.len() > MAX_OPERATIONS {
        return Err(DesignError::TooMany(design.operations.len()));
    }
    let points: usize = design.operations.iter().map(|o| o.polygon.len()).sum();
    if points > MAX_DESIGN_POINTS {
        return Err(DesignError::TooManyPoints(points));
    }
    Ok(design)
}

impl Design {
    /// Builds the card, applying every operation in order.
    pub fn build(&self) -> Result<PolygonCard, DesignError> {
        self.run(|_, _| {})
    }

    /// Builds the card and runs the pop-up check. When the final card fails, the design is
    /// replayed once more with a check after every operation to find after which operation
    /// the card last turned from passing to failing (quadratic, but only for failing designs).
    pub fn replay(&self) -> Result<Replay, DesignError> {
        let card = self.build()?;
        let report = check_popup(&card);
        if report.passed() {
            return Ok(Replay {
                card,
                report,
                became_invalid_after: None,
            });
        }
        let mut last_valid = 0;
        self.run(|index, card| {
            if check_popup(card).passed() {
                last_valid = index;
            }
        })?;
        Ok(Replay {
            card,
            report,
            became_invalid_after: Some(last_valid + 1),
        })
    }

    /// Applies the operations in order, calling `after(index, card)` after each (1-based).
    fn run(&self, mut after: impl FnMut(usize, &PolygonCard)) -> Result<PolygonCard, DesignError> {
        let c = &self.card;
        let mut card = PolygonCard::new(c.width, c.depth, c.height).map_err(DesignError::Card)?;
        for (i, op) in self.operations.iter().enumerate() {
            let index = i + 1;
            let scale = match op.units {
                Units::Mm => 1.0,
                Units::Grid => c
                    .grid
                    .filter(|g| g.is_finite() && *g > 0.0)
                    .ok_or(DesignError::NoGrid(index))?,
            };
            let kind = match op.plane {
                PlaneName::Vertical => FaceKind::Vertical,
                PlaneName::Horizontal => FaceKind::Horizontal,
            };
            let points: Vec<DVec2> = op.polygon.iter().map(|&p| DVec2::from(p) * scale).collect();
            let result = match op.add {
                Add::Face => card.add_face(kind, op.at * scale, &points),
                Add::Opening => card.add_opening(kind, op.at * scale, &points),
            };
            result.map_err(|source| DesignError::Operation { index, source })?;
            after(index, &card);
        }
        Ok(card)
    }
}
