//! The global layer-order check: does a locally flat-foldable crease pattern have a way to
//! stack its layers, and how many?
//!
//! The method is Flat-Folder's (Jason Ku's solver; Akitaya, Demaine & Ku, "Computing
//! flat-folded states", 2023), written anew here:
//! 1. fold the pattern flat on paper: place every face by reflecting across creases from a
//!    fixed face ([`folded`]);
//! 2. overlay the folded edges into the cells of the overlap arrangement ([`cells`]);
//! 3. one Boolean variable per pair of overlapping faces, and the taco-taco, taco-tortilla,
//!    tortilla-tortilla and transitivity constraints between them ([`constraints`]);
//! 4. set the orders that mountains and valleys force and propagate, split what is left into
//!    independent components, and count each one by search ([`search`]).
//!
//! The number of states is the product of the components' counts (a decimal string: counts of
//! real designs pass 10^80). It counts what Flat-Folder counts: one face is held fixed, so a
//! mirror image is not counted twice, and unassigned creases fold either way.
//!
//! Contract: the pattern must be planar (after [`crate::pattern::planarize()`]); faces are taken
//! from the pattern when it has them, traced otherwise. Run the local checks
//! ([`super::check`]) first: a vertex that breaks Kawasaki makes the folded form inconsistent,
//! reported as [`LayerError::NotFlat`]. Limits: counting is exponential in the worst case
//! (bounded by [`LayerOptions::max_states`] per component); transitivity constraints are capped
//! at [`constraints::MAX_TRIPLES`].

pub(crate) mod cells;
pub(crate) mod constraints;
mod decimal;
pub(crate) mod flat;
pub(crate) mod folded;
pub(crate) mod progress;
pub(crate) mod rounding;
pub(crate) mod search;
mod verdict;

use glam::DVec2;
use serde::Serialize;

use crate::clock::Deadline;
use crate::pattern::faces::find_faces;
use crate::pattern::{CreasePattern, EdgeId, FaceId, FoldedState, VertexId};
pub use cells::arrange;
use constraints::{Kind, Place, System};
pub use decimal::BigCount;
pub use flat::{DEFAULT_MAX_STATES, FlatFoldError, FlatFolding};
use folded::FoldedFaces;
pub use folded::fold_faces;
pub use progress::{LayerProgress, LayerStage};
pub use rounding::{
    KawasakiTolerance, LocalFaults, PRECISION_DIVISOR, drawing_precision, local_faults,
};
use search::{Count, Engine};
pub use verdict::{LayerCheck, check_layers, flat_fold_warning, meant_to_fold_flat, refusal};

/// The smallest merge distance of the arrangement, relative to the pattern's bounding-box
/// diagonal (the distance itself adapts to the pattern, see [`cells::arrange`]).
pub const RELATIVE_TOLERANCE: f64 = 1e-10;

/// How far apart two folded placements of one vertex may lie, as a share of the shortest
/// edge. Files of other tools carry rounding (coordinates to a few decimals, single
/// precision), every reflection passes it on, and a loop of faces round a vertex that misses
/// Kawasaki by the drawing's rounding ([`rounding`]) lands a little off where it started: Lang's
/// 5-Fold 2-Layer Weave places one vertex 0.16 of its shortest edge apart. Placements closer
/// than half the shortest edge are nearer each other than to any neighbour of the vertex, so
/// they are one point; every face then draws the vertex at its one folded place (see
/// [`folded`]).
pub const VERTEX_AGREEMENT: f64 = 1.0 / 2.0;

fn vertex_agreement(cp: &CreasePattern) -> f64 {
    let shortest = cp
        .edge_ids()
        .map(|e| cp.edge_length(e))
        .filter(|&d| d > 0.0)
        .fold(f64::MAX, f64::min);
    if shortest == f64::MAX {
        0.0
    } else {
        shortest * VERTEX_AGREEMENT
    }
}

/// Options of the layer solver.
#[derive(Clone, Debug, PartialEq)]
pub struct LayerOptions {
    /// Stop counting a component at this many states (its count is then a lower bound and the
    /// report says `exact: false`); `None` counts everything.
    pub max_states: Option<u64>,
    /// Smallest merge distance relative to the bounding-box diagonal.
    pub relative_tolerance: f64,
    /// How much Kawasaki error the local check run first lets through as rounding (by
    /// default fitted to the drawing, see [`rounding`]).
    pub kawasaki: KawasakiTolerance,
    /// Stop with [`LayerError::TimeLimit`] when arranging the folded layers, building the
    /// constraints and counting take longer than this; `None` has no limit.
    pub time_limit: Option<std::time::Duration>,
    /// Where the search is, written as it runs for a front end to show (see
    /// [`LayerProgress`]); `None` reports nothing.
    pub progress: Option<std::sync::Arc<LayerProgress>>,
}

impl Default for LayerOptions {
    fn default() -> Self {
        LayerOptions {
            max_states: None,
            relative_tolerance: RELATIVE_TOLERANCE,
            kawasaki: KawasakiTolerance::Fitted,
            time_limit: None,
            progress: None,
        }
    }
}

/// Why the layer problem could not be set up.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LayerError {
    /// The pattern has no faces (no closed region of paper).
    #[error("the pattern has no faces: the layer order needs closed regions of paper")]
    NoFaces,
    /// Two routes around a vertex fold it to different places.
    #[error(
        "the pattern does not fold flat as a whole: faces {} and {} put vertex {vertex} (at \
         {:.4}, {:.4}) {gap:.3e} apart in the folded form; fix the vertex's angles first \
         (Kawasaki)",
        faces[0], faces[1], position.x, position.y
    )]
    NotFlat {
        /// The two faces that disagree.
        faces: [FaceId; 2],
        /// The vertex.
        vertex: VertexId,
        /// Its position in the pattern.
        position: DVec2,
        /// The distance between its two folded places.
        gap: f64,
    },
    /// The problem exceeds a size limit.
    #[error("the layer problem is too large: {count} {what}, beyond the limit of {limit}")]
    TooLarge {
        /// What was counted.
        what: &'static str,
        /// How many.
        count: usize,
        /// The limit.
        limit: usize,
    },
    /// The work ran past [`LayerOptions::time_limit`].
    #[error(
        "the layer order search stopped at its time limit of {seconds} s while {stage}: raise \
         --time-limit, or check a part of the pattern"
    )]
    TimeLimit {
        /// The limit, seconds.
        seconds: f64,
        /// What was under way.
        stage: &'static str,
    },
}

impl LayerError {
    /// [`LayerError::TimeLimit`] of `deadline` while `stage`.
    pub(crate) fn out_of_time(deadline: &Deadline, stage: &'static str) -> LayerError {
        LayerError::TimeLimit {
            seconds: deadline.limit().unwrap_or_default().as_secs_f64(),
            stage,
        }
    }
}

/// Numbers of constraints by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct ConstraintCounts {
    /// Two folded creases on one segment, same side.
    pub taco_taco: usize,
    /// A folded crease and a face across it.
    pub taco_tortilla: usize,
    /// Two unfolded lines on one segment.
    pub tortilla_tortilla: usize,
    /// Three faces covering one cell.
    pub transitivity: usize,
}

/// One independent component's count.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ComponentStates {
    /// Variables of the component.
    pub variables: usize,
    /// States found (decimal).
    pub states: String,
    /// False when the cap stopped the count.
    pub exact: bool,
}

/// Where and why no layer order exists.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Contradiction {
    /// What failed: `crease` (two creases force opposite orders), `taco_taco`,
    /// `taco_tortilla`, `tortilla_tortilla`, `transitivity`, or `search` (a component with no
    /// state; the faces are those of the last constraint that failed).
    pub kind: &'static str,
    /// The faces concerned.
    pub faces: Vec<FaceId>,
    /// A point of each face near the conflict, in pattern coordinates.
    pub positions: Vec<DVec2>,
    /// The place in the folded form.
    pub folded_position: DVec2,
    /// A readable account.
    pub message: String,
}

/// The result of the layer solver.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LayerReport {
    /// Number of valid layer orders (decimal): the product of the components' counts.
    pub states: String,
    /// False when a per-component cap stopped some count (`states` is then a lower bound).
    pub exact: bool,
    /// Independent components left after propagation.
    pub components: usize,
    /// Each component's count, in order.
    pub component_states: Vec<ComponentStates>,
    /// Faces of the pattern.
    pub faces: usize,
    /// Cells of the overlap arrangement.
    pub cells: usize,
    /// Overlapping face pairs (variables).
    pub variables: usize,
    /// Variables fixed by the creases and propagation before any search.
    pub forced: usize,
    /// Constraints by kind.
    pub constraints: ConstraintCounts,
    /// Why there is no state, when `states` is 0.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contradiction: Option<Contradiction>,
}

impl LayerReport {
    /// True when at least one valid layer order exists.
    pub fn foldable(&self) -> bool {
        self.states != "0"
    }
}

/// One cell of a [`TopView`].
#[derive(Clone, Debug, PartialEq)]
pub struct TopCell {
    /// Outline and holes, folded coordinates.
    pub rings: Vec<Vec<DVec2>>,
    /// The face seen from above.
    pub top: FaceId,
    /// True when that face shows its back side.
    pub top_flipped: bool,
    /// Number of layers in the cell.
    pub layers: usize,
}

/// A folded state seen from above (+z): what to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct TopView {
    /// The cells covered by paper.
    pub cells: Vec<TopCell>,
    /// Segments of the arrangement, with `true` on the folded outline (paper on one side).
    pub segments: Vec<([DVec2; 2], bool)>,
}

/// The solved layer problem of one pattern: folded form, constraints, counts, and the states
/// themselves on demand.
pub struct LayerSolver {
    folded: FoldedFaces,
    arr: cells::Arrangement,
    sys: System,
    /// Values after propagating the creases (−1 unset); empty when contradictory.
    base: Vec<i8>,
    components: Vec<Vec<u32>>,
    counts: Vec<Count>,
    report: LayerReport,
}

/// Counts the layer orders of `cp` (see the module docs).
pub fn solve_layers(cp: &CreasePattern, opts: &LayerOptions) -> Result<LayerReport, LayerError> {
    LayerSolver::new(cp, opts).map(|s| s.report)
}

impl LayerSolver {
    /// Builds and counts the layer problem of `cp`.
    pub fn new(cp: &CreasePattern, opts: &LayerOptions) -> Result<LayerSolver, LayerError> {
        let diag = cp.bounds().map_or(0.0, |(lo, hi)| lo.distance(hi));
        let tol = (diag * opts.relative_tolerance).max(crate::geom::tolerance::ROUNDOFF);
        let traced;
        let cp = if cp.faces.is_some() {
            cp
        } else {
            let mut copy = cp.clone();
            copy.faces = Some(find_faces(cp).faces);
            traced = copy;
            &traced
        };
        let deadline = Deadline::after(opts.time_limit);
        let stage = |s| {
            if let Some(p) = &opts.progress {
                p.set_stage(s);
            }
        };
        stage(LayerStage::Arranging);
        let folded = folded::fold_faces(cp, vertex_agreement(cp).max(tol))?;
        constraints::check_stack(folded.deepest_stack_at_least(tol))?;
        let (arr, _) = cells::arrange_by(cp, &folded, tol, &deadline)?;
        stage(LayerStage::Constraining);
        let sys = constraints::build(cp, &folded, &arr, &deadline)?;
        stage(LayerStage::Counting);
        let mut solver = LayerSolver {
            report: LayerReport {
                states: "0".into(),
                exact: true,
                components: 0,
                component_states: Vec::new(),
                faces: folded.faces.len(),
                cells: arr.cell_faces.len(),
                variables: sys.pairs.len(),
                forced: 0,
                constraints: ConstraintCounts {
                    taco_taco: sys.counts[Kind::TacoTaco as usize],
                    taco_tortilla: sys.counts[Kind::TacoTortilla as usize],
                    tortilla_tortilla: sys.counts[Kind::TortillaTortilla as usize],
                    transitivity: sys.counts[Kind::Transitivity as usize],
                },
                contradiction: None,
            },
            folded,
            arr,
            sys,
            base: Vec::new(),
            components: Vec::new(),
            counts: Vec::new(),
        };
        let solved = solver.solve(opts, &deadline);
        stage(LayerStage::Finished);
        solved?;
        Ok(solver)
    }

    fn solve(&mut self, opts: &LayerOptions, deadline: &Deadline) -> Result<(), LayerError> {
        let mut engine = Engine::new(&self.sys)
            .with_deadline(deadline)
            .with_progress(opts.progress.as_deref());
        for &(lit, e) in &self.sys.forced {
            if !engine.set_literal(lit) {
                let (a, b) = self.sys.faces_of(lit >> 1);
                self.report.contradiction = Some(self.crease_conflict(a, b, e));
                return Ok(());
            }
        }
        if let Err(c) = engine.propagate().and_then(|()| engine.propagate_all()) {
            self.report.contradiction = Some(self.conflict(c, "propagation"));
            return Ok(());
        }
        self.report.forced = engine.value.iter().filter(|&&v| v != -1).count();
        let components = engine.components();
        let cap = opts.max_states.map(u128::from);
        let mut product = BigCount::one();
        let mut exact = true;
        for (i, comp) in components.iter().enumerate() {
            if let Some(p) = &opts.progress {
                p.set_component(i, components.len(), comp.len());
            }
            let count = engine.count(comp, cap, None);
            if engine.timed_out {
                return Err(LayerError::out_of_time(
                    deadline,
                    "counting the layer orders",
                ));
            }
            product.mul(count.states);
            exact &= count.exact;
            self.report.component_states.push(ComponentStates {
                variables: comp.len(),
                states: count.states.to_string(),
                exact: count.exact,
            });
            self.counts.push(count);
            if count.states == 0 {
                let c = engine.last_conflict.unwrap_or(0);
                self.report.contradiction = Some(self.conflict(c, "search"));
                break;
            }
        }
        self.report.components = components.len();
        self.report.states = product.to_string();
        self.report.exact = exact;
        self.base = engine.value.clone();
        self.components = components;
        Ok(())
    }

    /// The report.
    pub fn report(&self) -> &LayerReport {
        &self.report
    }

    /// The folded form (faces placed, folded vertex positions).
    pub fn folded(&self) -> &FoldedFaces {
        &self.folded
    }

    /// Consumes the solver, keeping the report.
    pub fn into_report(self) -> LayerReport {
        self.report
    }

    /// State number `k` (from 0, mixed radix over the components, the first component the
    /// fastest digit) as FOLD `faceOrders`: `(f, g, s)` for every overlapping pair, `s = +1`
    /// when `f` lies on the side of `g`'s normal. `None` when there is no state `k`, or the
    /// counts are not exact.
    pub fn face_orders(&self, k: u128) -> Option<Vec<(FaceId, FaceId, i8)>> {
        self.state_values(k).map(|v| self.orders_of(&v))
    }

    /// True when `orders` (FOLD `faceOrders` on this solver's faces) can be completed to a
    /// valid state: every pair it names is set as it says, and the rest is searched.
    pub fn admits(&self, orders: &[(FaceId, FaceId, i8)]) -> bool {
        if !self.report.foldable() {
            return false;
        }
        let mut engine = Engine::new(&self.sys);
        for &(lit, _) in &self.sys.forced {
            engine.set_literal(lit);
        }
        for &(f, g, s) in orders {
            let g_up = !self.folded.faces[g.index()].flipped;
            let f_above = (s > 0) == g_up;
            let lit = if f_above {
                self.sys.above(f.0, g.0)
            } else {
                self.sys.above(g.0, f.0)
            };
            if let Some(lit) = lit
                && !engine.set_literal(lit)
            {
                return false;
            }
        }
        if engine
            .propagate()
            .and_then(|()| engine.propagate_all())
            .is_err()
        {
            return false;
        }
        engine
            .components()
            .iter()
            .all(|comp| engine.count(comp, Some(1), None).states >= 1)
    }

    /// Values of every variable in state `k` (see [`LayerSolver::face_orders`]).
    fn state_values(&self, k: u128) -> Option<Vec<i8>> {
        if !self.report.foldable() || self.counts.iter().any(|c| !c.exact) {
            return None;
        }
        let mut rest = k;
        let mut digits = Vec::with_capacity(self.counts.len());
        for c in &self.counts {
            digits.push(rest % c.states);
            rest /= c.states;
        }
        if rest != 0 {
            return None;
        }
        let mut engine = Engine::new(&self.sys);
        for (v, &x) in self.base.iter().enumerate() {
            if x != -1 {
                engine.set_literal(((v as u32) << 1) | (1 - x as u32));
            }
        }
        engine.propagate().ok()?;
        for (comp, &d) in self.components.iter().zip(&digits) {
            engine.count(comp, None, Some(d));
        }
        Some(engine.value)
    }

    /// The folded state number `k` of `cp` (the pattern this solver was built from, with its
    /// faces): vertices at their folded places (z = 0), the pattern's edges and faces, and
    /// `faceOrders`. `None` as for [`LayerSolver::face_orders`].
    pub fn folded_state(&self, cp: &CreasePattern, k: u128) -> Option<FoldedState> {
        let orders = self.face_orders(k)?;
        Some(FoldedState {
            positions: self.folded.vertices.iter().map(|p| p.extend(0.0)).collect(),
            edges: cp.edges.clone(),
            faces: cp.faces.clone(),
            face_orders: orders,
        })
    }

    /// The top view of state `k`: every cell with the face seen from above and its number of
    /// layers. `None` as for [`LayerSolver::face_orders`].
    pub fn top_view(&self, k: u128) -> Option<TopView> {
        let value = self.state_values(k)?;
        let above = |a: u32, b: u32| -> bool {
            match self.sys.var(a, b) {
                Some(v) => (value[v as usize] == 1) == (a < b),
                None => false,
            }
        };
        let cells = self
            .arr
            .cell_faces
            .iter()
            .zip(&self.arr.cell_rings)
            .filter(|(faces, _)| !faces.is_empty())
            .map(|(faces, rings)| {
                let top = faces[1..]
                    .iter()
                    .fold(faces[0], |t, &g| if above(g, t) { g } else { t });
                TopCell {
                    rings: rings.clone(),
                    top: FaceId(top),
                    top_flipped: self.folded.faces[top as usize].flipped,
                    layers: faces.len(),
                }
            })
            .collect();
        let edges = self
            .arr
            .segment_ends
            .iter()
            .zip(&self.arr.segment_cells)
            .map(|(&ends, &cells)| (ends, cells.iter().flatten().count() < 2))
            .collect();
        Some(TopView {
            cells,
            segments: edges,
        })
    }

    fn orders_of(&self, value: &[i8]) -> Vec<(FaceId, FaceId, i8)> {
        (0..self.sys.pairs.len())
            .filter(|&v| value[v] != -1)
            .map(|v| {
                let (a, b) = self.sys.faces_of(v as u32);
                let a_above = value[v] == 1;
                let b_up = !self.folded.faces[b as usize].flipped;
                (FaceId(a), FaceId(b), if a_above == b_up { 1 } else { -1 })
            })
            .collect()
    }

    fn place_point(&self, con: &constraints::Constraint) -> DVec2 {
        match con.place {
            Place::Common => self
                .arr
                .cell_faces
                .iter()
                .position(|faces| con.faces.iter().all(|f| faces.binary_search(f).is_ok()))
                .map_or(DVec2::ZERO, |c| self.arr.cell_points[c]),
            Place::Segment(s) => {
                let [a, b] = self.arr.segment_ends[s as usize];
                (a + b) * 0.5
            }
        }
    }

    fn contradiction(
        &self,
        kind: &'static str,
        faces: Vec<FaceId>,
        at: DVec2,
        why: &str,
    ) -> Contradiction {
        let positions = faces
            .iter()
            .map(|f| {
                let t = self.folded.faces[f.index()].transform;
                t.inverse().transform_point2(at)
            })
            .collect::<Vec<_>>();
        let names: Vec<String> = faces.iter().map(|f| f.to_string()).collect();
        let first = positions.first().copied().unwrap_or(at);
        Contradiction {
            kind,
            message: format!(
                "no valid layer order: {why} (faces {}, near ({:.4}, {:.4}) on the pattern)",
                names.join(", "),
                first.x,
                first.y
            ),
            faces,
            positions,
            folded_position: at,
        }
    }

    fn crease_conflict(&self, a: u32, b: u32, e: u32) -> Contradiction {
        let faces = vec![FaceId(a), FaceId(b)];
        let mid = {
            let fa = &self.folded.faces[a as usize];
            fa.outer.iter().copied().sum::<DVec2>() / fa.outer.len().max(1) as f64
        };
        self.contradiction(
            "crease",
            faces,
            mid,
            &format!(
                "crease {} and another crease force opposite orders",
                EdgeId(e)
            ),
        )
    }

    fn conflict(&self, c: u32, stage: &str) -> Contradiction {
        let con = &self.sys.constraint(c);
        let n = match con.kind {
            Kind::TacoTaco | Kind::TortillaTortilla => 4,
            Kind::TacoTortilla | Kind::Transitivity => 3,
        };
        let mut faces: Vec<FaceId> = con.faces[..n].iter().map(|&f| FaceId(f)).collect();
        faces.dedup();
        let (kind, why) = match (stage, con.kind) {
            ("search", _) => (
                "search",
                "every choice left runs into a contradiction; the last one",
            ),
            (_, Kind::TacoTaco) => ("taco_taco", "two folds along one line would cross"),
            (_, Kind::TacoTortilla) => {
                ("taco_tortilla", "a face would have to pass through a fold")
            }
            (_, Kind::TortillaTortilla) => (
                "tortilla_tortilla",
                "two flat lines along one line would cross",
            ),
            (_, Kind::Transitivity) => (
                "transitivity",
                "three faces would have to be stacked in a cycle",
            ),
        };
        self.contradiction(kind, faces, self.place_point(con), why)
    }
}
