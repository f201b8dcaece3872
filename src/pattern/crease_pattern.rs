//! The crease pattern: the one model every design source ends in.

use glam::DVec2;

use super::{Assignment, EdgeId, FaceId, PatternError, VertexId};

pub use crate::limits::MAX_COORDINATE;

/// One edge: two vertices, an assignment and an optional target fold angle.
#[derive(Clone, Debug, PartialEq)]
pub struct Edge {
    /// The two end vertices (distinct in a valid pattern).
    pub vertices: [VertexId; 2],
    /// What the edge does.
    pub assignment: Assignment,
    /// Target fold angle in degrees with FOLD's sign: valley positive, mountain negative,
    /// ±180 fully folded; `None` when unknown.
    pub fold_angle: Option<f64>,
}

impl Edge {
    /// An edge with no fold angle.
    pub fn new(a: VertexId, b: VertexId, assignment: Assignment) -> Self {
        Edge {
            vertices: [a, b],
            assignment,
            fold_angle: None,
        }
    }

    /// The same edge with a fold angle in degrees.
    pub fn with_angle(mut self, degrees: f64) -> Self {
        self.fold_angle = Some(degrees);
        self
    }

    /// The end that is not `v` (or `vertices[0]` if `v` is neither).
    pub fn other(&self, v: VertexId) -> VertexId {
        if self.vertices[0] == v {
            self.vertices[1]
        } else {
            self.vertices[0]
        }
    }
}

/// A face: a counter-clockwise outer cycle of vertices and clockwise hole cycles.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Face {
    /// Outer boundary, counter-clockwise (positive area) in the pattern's x-right, y-up frame.
    pub outer: Vec<VertexId>,
    /// Holes, each clockwise. FOLD cannot express holes; the FOLD writer stores them in the
    /// custom key `foldcam:faces_holes`.
    pub holes: Vec<Vec<VertexId>>,
}

impl Face {
    /// A face without holes.
    pub fn simple(outer: Vec<VertexId>) -> Self {
        Face {
            outer,
            holes: Vec::new(),
        }
    }
}

/// The length unit of a pattern's coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Units {
    /// Coordinates are millimetres.
    #[default]
    Millimetres,
    /// Coordinates have no physical size yet (FOLD's `"unit"`, ORIPA files). Commands that
    /// need a size ask for `--size` or `--scale`.
    Unitless,
}

impl Units {
    /// The unit's name in messages, next to a length: `mm` or `units`.
    pub fn label(self) -> &'static str {
        match self {
            Units::Millimetres => "mm",
            Units::Unitless => "units",
        }
    }
}

/// A physical size was needed but the pattern is unitless.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "the pattern has no physical size (FOLD frame_unit \"unit\" or an ORIPA file): give it one, \
     the longer side in mm (the command line's --size MM, the studio's Size field) or mm per \
     unit (--scale MM_PER_UNIT)"
)]
pub struct UnitlessError;

/// Descriptive data and everything read from a file that the model does not interpret, kept
/// so that writing the pattern back loses nothing.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Metadata {
    /// Title (`file_title` / `frame_title`).
    pub title: Option<String>,
    /// Author (`file_author` / `frame_author`).
    pub author: Option<String>,
    /// Description (`file_description` / `frame_description`).
    pub description: Option<String>,
    /// The program that wrote the file (`file_creator`).
    pub creator: Option<String>,
    /// Keys of the file level (including `file_*` keys not listed above, custom `ns:key` keys
    /// and `file_frames`) that the model does not interpret, in file order, written back
    /// verbatim.
    pub file_extra: serde_json::Map<String, serde_json::Value>,
    /// Keys of the key frame not interpreted by the model, written back verbatim.
    pub frame_extra: serde_json::Map<String, serde_json::Value>,
    /// Standard FOLD keys that are derived from the model's topology (`vertices_vertices`,
    /// `edges_faces`, …) and were present in the input: the FOLD writer recomputes them so they
    /// stay consistent after edits.
    pub derived_keys: Vec<String>,
}

impl Metadata {
    /// Drops the per-element arrays (`vertices_*`, `edges_*`, `faces_*` keys and
    /// `faceOrders`/`edgeOrders`) kept from the input: called by operations that renumber
    /// elements, after which such arrays would be stale. Returns the names of dropped keys.
    pub fn drop_per_element_extras(&mut self) -> Vec<String> {
        let per_element = |k: &str| {
            k.starts_with("vertices_")
                || k.starts_with("edges_")
                || k.starts_with("faces_")
                || k == "faceOrders"
                || k == "edgeOrders"
                || k.contains(":vertices_")
                || k.contains(":edges_")
                || k.contains(":faces_")
        };
        let dropped: Vec<String> = self
            .frame_extra
            .keys()
            .filter(|k| per_element(k))
            .cloned()
            .collect();
        for k in &dropped {
            self.frame_extra.remove(k);
        }
        dropped
    }
}

/// A crease pattern: 2D vertices, edges with assignments, optional faces.
///
/// Coordinates are millimetres (x right, y up) unless [`CreasePattern::units`] says
/// [`Units::Unitless`]. Use [`CreasePattern::validate`] after building one from untrusted data;
/// the rest of the library assumes a validated pattern.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct CreasePattern {
    /// Vertex positions.
    pub vertices: Vec<DVec2>,
    /// Edges.
    pub edges: Vec<Edge>,
    /// Faces, when known (FOLD files may carry them; [`super::planarize`](fn@super::planarize) computes them).
    pub faces: Option<Vec<Face>>,
    /// Face stacking order (`faceOrders`: face f above/below g by sign), kept with the faces.
    pub face_orders: Vec<(FaceId, FaceId, i8)>,
    /// Length unit of the coordinates.
    pub units: Units,
    /// Titles and everything else read from the file.
    pub meta: Metadata,
}

impl CreasePattern {
    /// An empty pattern in millimetres.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a vertex and returns its id.
    pub fn add_vertex(&mut self, p: DVec2) -> VertexId {
        self.vertices.push(p);
        VertexId::new(self.vertices.len() - 1)
    }

    /// Adds an edge between two existing vertices and returns its id.
    pub fn add_edge(&mut self, a: VertexId, b: VertexId, assignment: Assignment) -> EdgeId {
        self.edges.push(Edge::new(a, b, assignment));
        EdgeId::new(self.edges.len() - 1)
    }

    /// Adds a segment as two new vertices and an edge (for importers of line drawings;
    /// [`super::planarize`](fn@super::planarize) merges the duplicates afterwards).
    pub fn add_segment(&mut self, a: DVec2, b: DVec2, assignment: Assignment) -> EdgeId {
        let va = self.add_vertex(a);
        let vb = self.add_vertex(b);
        self.add_edge(va, vb, assignment)
    }

    /// Position of a vertex.
    #[inline]
    pub fn position(&self, v: VertexId) -> DVec2 {
        self.vertices[v.index()]
    }

    /// The two end positions of an edge.
    #[inline]
    pub fn segment(&self, e: EdgeId) -> (DVec2, DVec2) {
        let [a, b] = self.edges[e.index()].vertices;
        (self.position(a), self.position(b))
    }

    /// Length of an edge.
    pub fn edge_length(&self, e: EdgeId) -> f64 {
        let (a, b) = self.segment(e);
        a.distance(b)
    }

    /// Iterates over edge ids.
    pub fn edge_ids(&self) -> impl Iterator<Item = EdgeId> + '_ {
        (0..self.edges.len()).map(EdgeId::new)
    }

    /// Iterates over vertex ids.
    pub fn vertex_ids(&self) -> impl Iterator<Item = VertexId> + '_ {
        (0..self.vertices.len()).map(VertexId::new)
    }

    /// Axis-aligned bounds `(min, max)` of the vertices, `None` when there are none.
    pub fn bounds(&self) -> Option<(DVec2, DVec2)> {
        crate::geom::Rect::of(self.vertices.iter().copied()).map(crate::geom::Rect::corners)
    }

    /// Number of edges with each assignment, in [`Assignment::ALL`] order.
    pub fn assignment_counts(&self) -> [usize; 7] {
        let mut counts = [0; 7];
        for e in &self.edges {
            let i = Assignment::ALL
                .iter()
                .position(|&a| a == e.assignment)
                .unwrap_or(0);
            counts[i] += 1;
        }
        counts
    }

    /// For every vertex, the edges incident to it (in edge order).
    pub fn vertex_edges(&self) -> Vec<Vec<EdgeId>> {
        let mut out = vec![Vec::new(); self.vertices.len()];
        for (i, e) in self.edges.iter().enumerate() {
            out[e.vertices[0].index()].push(EdgeId::new(i));
            if e.vertices[1] != e.vertices[0] {
                out[e.vertices[1].index()].push(EdgeId::new(i));
            }
        }
        out
    }

    /// Scales every coordinate by `factor` (used to give a unitless pattern a size), and sets
    /// the units to millimetres.
    pub fn scale_to_mm(&mut self, factor: f64) {
        for p in &mut self.vertices {
            *p *= factor;
        }
        self.units = Units::Millimetres;
    }

    /// Succeeds when the coordinates are millimetres; for a unitless pattern, the error every
    /// command that needs a physical size (cutting, plotting) reports.
    pub fn require_millimetres(&self) -> Result<(), UnitlessError> {
        match self.units {
            Units::Millimetres => Ok(()),
            Units::Unitless => Err(UnitlessError),
        }
    }

    /// Checks the structural invariants: finite coordinates within ±[`MAX_COORDINATE`],
    /// indices in range, edges joining two distinct vertices, fold angles finite and within
    /// [−180°, 180°], faces referring to existing vertices with at least three corners.
    ///
    /// Importers call this so the rest of the library can assume a sound pattern.
    pub fn validate(&self) -> Result<(), PatternError> {
        let n = self.vertices.len();
        for (i, p) in self.vertices.iter().enumerate() {
            if !p.is_finite() {
                return Err(PatternError::NonFiniteCoordinate {
                    vertex: VertexId::new(i),
                });
            }
            if p.abs().max_element() > MAX_COORDINATE {
                return Err(PatternError::CoordinateTooLarge {
                    vertex: VertexId::new(i),
                    value: p.abs().max_element(),
                });
            }
        }
        for (i, e) in self.edges.iter().enumerate() {
            let id = EdgeId::new(i);
            for v in e.vertices {
                if v.index() >= n {
                    return Err(PatternError::VertexOutOfRange {
                        edge: id,
                        vertex: v.0 as usize,
                        count: n,
                    });
                }
            }
            if e.vertices[0] == e.vertices[1] {
                return Err(PatternError::LoopEdge { edge: id });
            }
            if let Some(a) = e.fold_angle
                && !(a.is_finite() && (-180.0..=180.0).contains(&a))
            {
                return Err(PatternError::FoldAngleOutOfRange {
                    edge: id,
                    degrees: a,
                });
            }
        }
        for (i, f) in self.faces.iter().flatten().enumerate() {
            for cycle in std::iter::once(&f.outer).chain(&f.holes) {
                if cycle.len() < if std::ptr::eq(cycle, &f.outer) { 3 } else { 2 } {
                    return Err(PatternError::DegenerateFace {
                        face: FaceId::new(i),
                    });
                }
                if let Some(v) = cycle.iter().find(|v| v.index() >= n) {
                    return Err(PatternError::FaceVertexOutOfRange {
                        face: FaceId::new(i),
                        vertex: v.0 as usize,
                        count: n,
                    });
                }
            }
        }
        Ok(())
    }
}
