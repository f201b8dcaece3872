//! Pattern checks: local flat-foldability (Kawasaki, Maekawa), vertex angles, edge lengths and
//! fold angles, collected into a [`CheckReport`].
//!
//! # What is checked
//! - **Kawasaki** at every interior vertex: with the creases sorted counter-clockwise and
//!   α₀ … αₙ₋₁ the sector angles between consecutive ones, the alternating sum
//!   Σ (−1)ⁱ αᵢ must be 0, i.e. the even sectors and the odd sectors each sum to 180°. The
//!   reported error is half the alternating sum, |Σ even − 180°|: rotating one crease by that
//!   angle fixes the vertex, and a crease rotated by δ from a flat-foldable position gives an
//!   error of exactly δ. An odd number of creases fails outright (quantity
//!   [`Quantity::Creases`]); such vertices are not checked for Maekawa, which an odd degree
//!   cannot satisfy either.
//! - **Maekawa** at every interior vertex of even degree whose creases are all mountain or
//!   valley: |M − V| = 2. Vertices with an unassigned crease are skipped and counted in
//!   [`CheckSummary::maekawa_skipped_unassigned`].
//! - **Vertex angle** (Tachi's δ_corner) at every vertex: the smallest sector between
//!   neighbouring spokes where both are creases or one is a crease and the other is an outline
//!   (B or C), against [`CheckOptions::min_vertex_angle_deg`]. The sector between two outline
//!   edges is never counted (it may be the outside of the sheet).
//! - **Short edges** (any assignment) against [`CheckOptions::min_edge_length`]; the shortest
//!   edge is always in the summary.
//! - **Fold angles** where known: |angle| > [`CheckOptions::max_fold_angle_deg`] fails.
//!
//! # What applies ([`applies`])
//! Kawasaki and Maekawa are about folding flat: they run only at interior vertices whose
//! creases are all meant to fold flat (fold angle ±180°, or a crease without a stored angle).
//! A vertex with a crease folding to less than 180° belongs to a 3D target and is counted in
//! [`CheckSummary::vertices_3d`] instead; for such patterns [`check_with_frame`] checks the
//! developability of the 3D frame when there is one ([`developability`]). The fabrication
//! limits apply to every pattern. [`CheckReport::runs`] says which checks ran and why.
//!
//! # Creases and interior vertices
//! Creases are the edges that fold: mountain, valley and unassigned. Flat facet lines (F) and
//! joins (J) do not fold and are ignored by Kawasaki, Maekawa and the vertex angle. A vertex is
//! interior when none of its edges is a boundary or cut and it does not lie on the unbounded
//! face of the planar graph ([`crate::pattern::faces::find_faces`]), so patterns without any
//! boundary edge are handled too. Vertices without creases are skipped.
//!
//! # Contract and cost
//! The pattern must be validated and planar (as after [`crate::pattern::planarize()`]); on a
//! non-planar pattern the results are still defined but the interior test may be wrong.
//! Angles are in degrees, lengths in the pattern's unit. The cost is O(E log d) for the fans
//! and faces plus a parallel pass over the vertices; nothing is allocated per vertex unless it
//! fails a check.

pub(crate) mod applies;
pub(crate) mod developability;
mod edges;
mod flat_foldability;
pub mod fold3d;
pub mod layers;
mod report;
mod runs;
mod vertex;

use glam::DVec2;
use rayon::prelude::*;
use serde::Serialize;

use crate::pattern::faces::find_faces_with;
use crate::pattern::vertex_fan::VertexFans;
use crate::pattern::{CreasePattern, EdgeId, FoldedState, VertexId};

pub use applies::{CheckRun, fold_angles_lost};
pub use report::{
    AssignmentCounts, CheckSummary, EdgeMeasure, TEXT_FINDINGS_PER_KIND, VertexMeasure,
    finding_line,
};

/// Which checks to run and their limits.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CheckOptions {
    /// Kawasaki and Maekawa at interior vertices.
    pub flat_foldability: bool,
    /// Tolerance of Kawasaki's error (half the alternating sum of sector angles), degrees.
    pub kawasaki_tolerance_deg: f64,
    /// Smallest allowed angle between neighbouring creases at a vertex, degrees (Tachi's
    /// δ_corner); `None` disables the check.
    pub min_vertex_angle_deg: Option<f64>,
    /// Largest allowed |fold angle|, degrees; mountains and valleys without a stored angle
    /// count as fully folded (±180°). `None` disables the check.
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

/// The kind of a finding, in the order findings are listed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
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
    /// No valid layer order exists (the global check of [`layers`]); one finding per face
    /// named by the contradiction.
    LayerOrder,
    /// A face of the 3D frame is stretched or bent: the frame does not unfold onto the
    /// pattern.
    Developability,
}

impl FindingKind {
    /// Every kind, in listing order.
    pub const ALL: [FindingKind; 7] = [
        FindingKind::Kawasaki,
        FindingKind::Maekawa,
        FindingKind::VertexAngle,
        FindingKind::ShortEdge,
        FindingKind::FoldAngle,
        FindingKind::LayerOrder,
        FindingKind::Developability,
    ];

    /// The snake-case name used in text and JSON.
    pub fn name(self) -> &'static str {
        match self {
            FindingKind::Kawasaki => "kawasaki",
            FindingKind::Maekawa => "maekawa",
            FindingKind::VertexAngle => "vertex_angle",
            FindingKind::ShortEdge => "short_edge",
            FindingKind::FoldAngle => "fold_angle",
            FindingKind::LayerOrder => "layer_order",
            FindingKind::Developability => "developability",
        }
    }
}

/// What [`Finding::value`] and [`Finding::limit`] measure.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// An angle in degrees.
    Degrees,
    /// A length in the pattern's unit.
    Length,
    /// A number of creases (Kawasaki at an odd-degree vertex: the value is the degree, the
    /// limit 0 stands for "any even number").
    Creases,
    /// |M − V| (Maekawa: the limit is 2).
    MountainValleyDifference,
    /// A number of valid layer orders (the limit is 1).
    States,
    /// A dimensionless ratio (developability: a distance change relative to the face's size).
    Ratio,
}

/// Mountain and valley counts at a vertex (Maekawa findings).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct MvCounts {
    /// Mountain creases.
    pub mountains: u32,
    /// Valley creases.
    pub valleys: u32,
}

/// One failed check.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Finding {
    /// What failed.
    pub kind: FindingKind,
    /// The vertex concerned, if any.
    pub vertex: Option<VertexId>,
    /// The edge concerned, if any (for a vertex-angle finding: a crease of the narrowest
    /// sector).
    pub edge: Option<EdgeId>,
    /// Where to look, in pattern coordinates (the vertex, or the edge's midpoint).
    pub position: DVec2,
    /// The measured quantity (see [`Finding::quantity`]).
    pub value: f64,
    /// The limit it was compared with.
    pub limit: f64,
    /// What `value` and `limit` measure.
    pub quantity: Quantity,
    /// Mountain and valley counts, for Maekawa findings.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mv_counts: Option<MvCounts>,
    /// A readable account, with the measured value and the limit.
    pub message: String,
    /// What to do about it.
    pub hint: String,
}

impl Finding {
    /// How far the finding is from passing, in its own quantity (larger is worse); an
    /// odd-degree vertex is infinitely bad.
    pub fn severity(&self) -> f64 {
        match (self.kind, self.quantity) {
            (_, Quantity::Creases) => f64::INFINITY,
            (FindingKind::VertexAngle | FindingKind::ShortEdge, _) => self.limit - self.value,
            _ => (self.value - self.limit).abs(),
        }
    }
}

/// The result of [`check`].
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct CheckReport {
    /// Every failure, sorted by kind, then from the worst to the least bad.
    pub findings: Vec<Finding>,
    /// Faults that do not fail the check: Kawasaki errors the layer solver accepted as the
    /// drawing's rounding ([`layers::check_layers`]); empty after the local checks alone.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<Finding>,
    /// Kawasaki and Maekawa faults at the 3D-target vertices no check judged (see
    /// [`CheckReport::unchecked_vertices`]): not failures, as a 3D target need not fold flat,
    /// but the same faults a check of the pattern finds when a format without fold angles
    /// (`.cp`, `.opx`) reads every crease as folding flat. Empty when a 3D frame was checked.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub unchecked_faults: Vec<Finding>,
    /// Counts and extremes of the whole pattern.
    pub summary: CheckSummary,
    /// The options the checks ran with.
    pub options: CheckOptions,
    /// Each family of checks: whether it ran, over how much, and why.
    pub runs: Vec<applies::CheckRun>,
    /// Interior vertices whose foldability no check judged: a crease there folds to less
    /// than 180° (Kawasaki and Maekawa describe folding flat only) and no 3D frame was
    /// compared for developability. Vertices where Kawasaki and Maekawa hold all the same
    /// ([`CheckSummary::vertices_3d_flat`]) count too: their creases fold flat, but whether
    /// they reach the 3D form the file asks for was not checked. A report that passes with such vertices has not shown
    /// that the pattern folds ([`CheckReport::checked_folding`]).
    pub unchecked_vertices: usize,
}

impl CheckReport {
    /// True when nothing failed.
    pub fn passed(&self) -> bool {
        self.findings.is_empty()
    }

    /// True when every interior vertex's folding was judged by a check that ran (folding
    /// flat, or the 3D frame's developability): a pass then says the pattern folds locally.
    pub fn checked_folding(&self) -> bool {
        self.unchecked_vertices == 0
    }

    /// The findings of one kind.
    pub fn of_kind(&self, kind: FindingKind) -> impl Iterator<Item = &Finding> {
        self.findings.iter().filter(move |f| f.kind == kind)
    }
}

/// Runs the checks (see the module docs for what each one means) on a pattern without a 3D
/// frame.
///
/// ```
/// use foldcam::check::FindingKind;
/// use foldcam::{CheckOptions, check, load};
/// let good = load("examples/patterns/flat-vertex.fold".as_ref())?.pattern;
/// assert!(check(&good, &CheckOptions::default()).passed());
/// // One crease turned 5° and two mountains with two valleys: Kawasaki and Maekawa fail.
/// let bad = load("examples/patterns/broken-vertex.fold".as_ref())?.pattern;
/// let report = check(&bad, &CheckOptions::default());
/// assert_eq!(report.of_kind(FindingKind::Kawasaki).count(), 1);
/// assert_eq!(report.of_kind(FindingKind::Maekawa).count(), 1);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn check(cp: &CreasePattern, opts: &CheckOptions) -> CheckReport {
    check_with_frame(cp, None, opts)
}

/// Runs the checks; `folded`, the pattern's 3D frame (same vertices), adds the
/// developability check.
pub fn check_with_frame(
    cp: &CreasePattern,
    folded: Option<&FoldedState>,
    opts: &CheckOptions,
) -> CheckReport {
    let fans = VertexFans::new(cp);
    let interior = if opts.flat_foldability {
        interior_mask(cp, &fans)
    } else {
        Vec::new()
    };
    let ctx = vertex::Context {
        cp,
        fans: &fans,
        interior: &interior,
        opts,
        framed: folded.is_some(),
    };
    let mut vertices = (0..cp.vertices.len())
        .into_par_iter()
        .fold(vertex::Tally::default, |acc, v| {
            acc.add(&ctx, VertexId::new(v))
        })
        .reduce(vertex::Tally::default, vertex::Tally::merge);
    let edge_tally = edges::check_edges(cp, opts);
    let mut findings = std::mem::take(&mut vertices.findings);
    let mut unchecked_faults = std::mem::take(&mut vertices.faults_3d);
    sort_findings(&mut unchecked_faults);
    findings.extend(edge_tally.findings);
    let develop = folded.map(|f| {
        let faces = match (&f.faces, &cp.faces) {
            (Some(faces), _) | (None, Some(faces)) => faces.clone(),
            (None, None) => find_faces_with(cp, &fans).faces,
        };
        developability::check_faces(cp, &f.positions, &faces)
    });
    if let Some(d) = &develop {
        findings.extend(d.findings.iter().cloned());
    }
    sort_findings(&mut findings);
    let runs = runs::describe(cp, opts, &vertices, develop.as_ref());
    let summary = CheckSummary {
        vertices: cp.vertices.len(),
        edges: cp.edges.len(),
        interior_vertices_checked: vertices.checked,
        assignments: AssignmentCounts::of(cp),
        shortest_edge: edge_tally.shortest,
        smallest_crease_angle: vertices.smallest_angle,
        largest_fold_angle: edge_tally.largest_fold,
        maekawa_skipped_unassigned: vertices.maekawa_skipped,
        flat_foldability_checked: opts.flat_foldability,
        vertices_3d: vertices.vertices_3d,
        vertices_3d_flat: vertices.vertices_3d_flat,
        largest_developability_error: develop.as_ref().map(|d| d.largest_error),
    };
    let developed = develop.is_some();
    CheckReport {
        findings,
        warnings: Vec::new(),
        unchecked_faults,
        unchecked_vertices: if developed || !opts.flat_foldability {
            0
        } else {
            summary.vertices_3d
        },
        summary,
        options: opts.clone(),
        runs,
    }
}

/// Sorts by kind, then worst first, then by vertex and edge id for a stable order.
fn sort_findings(findings: &mut [Finding]) {
    findings.sort_by(|a, b| {
        a.kind
            .cmp(&b.kind)
            .then(b.severity().total_cmp(&a.severity()))
            .then(a.vertex.cmp(&b.vertex))
            .then(a.edge.cmp(&b.edge))
    });
}

/// Marks interior vertices: no boundary or cut edge and not on the unbounded face. Faces are
/// traced only when some vertex could be interior.
fn interior_mask(cp: &CreasePattern, fans: &VertexFans) -> Vec<bool> {
    let n = cp.vertices.len();
    let mut mask: Vec<bool> = (0..n)
        .into_par_iter()
        .map(|v| {
            let spokes = fans.of(VertexId::new(v));
            !spokes.is_empty()
                && spokes
                    .iter()
                    .all(|s| !cp.edges[s.edge.index()].assignment.is_boundary_like())
        })
        .collect();
    if mask.iter().any(|&m| m) {
        let outer = find_faces_with(cp, fans).outer_vertex_mask(n);
        for (m, o) in mask.iter_mut().zip(outer) {
            *m &= !o;
        }
    }
    mask
}
