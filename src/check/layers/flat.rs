//! Folding a pattern flat into one chosen layer order: the steps `foldcam fold-flat` and the
//! studio's flat view share (local checks first, then the layer solver, then one state).

use super::{LayerError, LayerOptions, LayerSolver, LocalFaults, TopView, local_faults, refusal};
use crate::check::Finding;
use crate::pattern::{CreasePattern, FoldedState};

/// The state cap per independent component both front ends count to by default (the count
/// is then a lower bound and states beyond it cannot be chosen).
pub const DEFAULT_MAX_STATES: u64 = 1_000_000;

/// Why a pattern has no flat-folded state to give.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FlatFoldError {
    /// A local fault (Kawasaki beyond the tolerance, Maekawa, an odd vertex) stops the solver.
    #[error("{}", refusal(.0))]
    NotLocallyFlat(Finding),
    /// The layer problem could not be set up (no faces, an inconsistent folded form, a limit).
    #[error(transparent)]
    Solver(#[from] LayerError),
    /// No layer order exists; the message says where.
    #[error("{0}")]
    NoLayerOrder(String),
    /// The state asked for is past the count.
    #[error(
        "there is no state {state} ({states} state(s){})",
        if *exact { "" } else { ", counting stopped at the state cap: raise it" }
    )]
    NoState {
        /// The state asked for (0-based).
        state: u128,
        /// The count (decimal), a lower bound when not `exact`.
        states: String,
        /// False when the cap stopped the count.
        exact: bool,
    },
}

/// A pattern's layer problem, solved and known to have a state, ready to give any of them.
pub struct FlatFolding {
    /// The solver, its report counting the states.
    pub solver: LayerSolver,
    /// The local checks run first (their rounding faults were let through).
    pub local: LocalFaults,
}

impl FlatFolding {
    /// Runs the local checks on `cp` (planar, faces traced) within `options.kawasaki`, then
    /// the layer solver.
    ///
    /// # Errors
    /// The first local fault that stops the solver, the solver's refusal, or the
    /// contradiction that leaves no layer order.
    pub fn new(cp: &CreasePattern, options: &LayerOptions) -> Result<FlatFolding, FlatFoldError> {
        let local = local_faults(cp, options.kawasaki);
        if let Some(f) = local.first_refusal() {
            return Err(FlatFoldError::NotLocallyFlat(f.clone()));
        }
        let solver = LayerSolver::new(cp, options)?;
        if let Some(c) = &solver.report().contradiction {
            return Err(FlatFoldError::NoLayerOrder(c.message.clone()));
        }
        Ok(FlatFolding { solver, local })
    }

    /// State `k` (0-based) of `cp` (the pattern this was built from) as a folded state.
    ///
    /// # Errors
    /// [`FlatFoldError::NoState`] when `k` is past the count.
    pub fn state(&self, cp: &CreasePattern, k: u128) -> Result<FoldedState, FlatFoldError> {
        self.solver
            .folded_state(cp, k)
            .ok_or_else(|| self.no_state(k))
    }

    /// State `k` (0-based) seen from above.
    ///
    /// # Errors
    /// [`FlatFoldError::NoState`] when `k` is past the count.
    pub fn top_view(&self, k: u128) -> Result<TopView, FlatFoldError> {
        self.solver.top_view(k).ok_or_else(|| self.no_state(k))
    }

    fn no_state(&self, state: u128) -> FlatFoldError {
        let report = self.solver.report();
        FlatFoldError::NoState {
            state,
            states: report.states.clone(),
            exact: report.exact,
        }
    }
}
