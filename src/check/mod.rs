//! PLACEHOLDER: pattern checks (written by the checks work).

use glam::DVec2;
use serde::Serialize;

use crate::pattern::{CreasePattern, EdgeId, VertexId};

/// Which checks to run and their limits.
#[derive(Clone, Debug, PartialEq)]
pub struct CheckOptions {
    /// Kawasaki and Maekawa at interior vertices.
    pub flat_foldability: bool,
    /// Tolerance of Kawasaki's alternating sum, degrees.
    pub kawasaki_tolerance_deg: f64,
    /// Smallest allowed angle between neighbouring creases at a vertex, degrees (Tachi's
    /// δ_corner); `None` disables the check.
    pub min_vertex_angle_deg: Option<f64>,
    /// Largest allowed |fold angle|, degrees; `None` disables the check.
    pub max_fold_angle_deg: Option<f64>,
    /// Shortest allowed edge, in the pattern's unit; `None` only reports the shortest edge.
    pub min_edge_length: Option<f64>,
}

impl Default for CheckOptions {
    fn default() -> Self {
        CheckOptions {
            flat_foldability: true,
            kawasaki_tolerance_deg: 0.01,
            min_vertex_angle_deg: None,
            max_fold_angle_deg: None,
            min_edge_length: None,
        }
    }
}

/// The kind of a finding.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FindingKind {
    /// Kawasaki's theorem fails.
    Kawasaki,
    /// Maekawa's theorem fails.
    Maekawa,
    /// Two neighbouring creases meet at less than the limit.
    VertexAngle,
    /// An edge is shorter than the limit.
    ShortEdge,
    /// A fold angle exceeds the limit.
    FoldAngle,
}

/// One failed check.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Finding {
    /// What failed.
    pub kind: FindingKind,
    /// The vertex concerned, if any.
    pub vertex: Option<VertexId>,
    /// The edge concerned, if any.
    pub edge: Option<EdgeId>,
    /// Where to look, in pattern coordinates.
    pub position: DVec2,
    /// The measured quantity (degrees or length).
    pub value: f64,
    /// The limit it was compared with.
    pub limit: f64,
    /// A readable account.
    pub message: String,
    /// What to do about it.
    pub hint: String,
}

/// The result of [`check`].
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct CheckReport {
    /// Every failure.
    pub findings: Vec<Finding>,
}

impl CheckReport {
    /// True when nothing failed.
    pub fn passed(&self) -> bool {
        self.findings.is_empty()
    }
}

/// Runs the checks.
pub fn check(_cp: &CreasePattern, _opts: &CheckOptions) -> CheckReport {
    todo!()
}
