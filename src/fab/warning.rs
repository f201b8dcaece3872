//! What a plan has to say about the pattern it was made from: each remark is a
//! [`PlanWarning`] with its [`PlanWarningKind`] for programs, its text for people and the
//! pattern edges it is about, so the studio can ring them on the pattern.

use std::fmt;

use serde::Serialize;

use crate::pattern::EdgeId;

/// What a plan warning is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum PlanWarningKind {
    /// The options were changed to suit the machine (a plotter draws what would be cut or
    /// scored).
    AdaptedToMachine,
    /// A hole smaller than the kerf is cut on the drawn line, without kerf compensation.
    HoleBelowKerf,
    /// A closed contour has no straight side long enough for a holding tab.
    NoRoomForTab,
    /// Creases too short for a perforation dash after the vertex clearances, left uncut.
    CreasesTooShort,
    /// A crease that would need more perforation dashes than a plan allows, left uncut.
    TooManyDashes,
    /// The pattern has only facet (flat) lines besides its outline: only the outline is cut.
    FacetsOnly,
    /// Vertices whose creases lie closer than the material's smallest vertex angle.
    VertexAngleLimit,
    /// Creases folding further than the material's largest fold angle.
    FoldAngleLimit,
    /// What to do about the design-limit warnings (they only warn: the job is written).
    LimitAdvice,
    /// Two-sided work with nothing to do from the back.
    EmptyBack,
    /// The material shows no mark on this machine (calibration grid labels).
    InvisibleMarks,
}

/// One remark of a plan.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlanWarning {
    /// What it is about.
    pub kind: PlanWarningKind,
    /// The remark for a person, one sentence.
    pub text: String,
    /// The pattern edges it is about, when it is about some (empty otherwise).
    pub edges: Vec<EdgeId>,
}

impl PlanWarningKind {
    /// A warning of this kind saying `text`, about no edge in particular.
    pub fn says(self, text: impl Into<String>) -> PlanWarning {
        PlanWarning {
            kind: self,
            text: text.into(),
            edges: Vec::new(),
        }
    }
}

impl PlanWarning {
    /// The same warning about `edges`.
    pub fn on(mut self, edges: impl IntoIterator<Item = EdgeId>) -> PlanWarning {
        self.edges.extend(edges);
        self
    }
}

impl fmt::Display for PlanWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}
