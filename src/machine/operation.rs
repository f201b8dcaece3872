//! What a toolpath does to the sheet: the operations a machine profile configures and a plan
//! assigns to edges.

use serde::Serialize;

/// What a toolpath does to the sheet.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Operation {
    /// Surface marking: registration marks, flat lines when asked for.
    Mark,
    /// Partial-depth score along a crease.
    Score,
    /// Dashed through-cuts along a crease.
    Perforate,
    /// Through-cut (outline, holes, slits).
    Cut,
    /// Pen plotting.
    Plot,
}

impl Operation {
    /// Every operation, in execution-group order (marks first, cuts last).
    pub const ALL: [Operation; 5] = [
        Operation::Mark,
        Operation::Plot,
        Operation::Score,
        Operation::Perforate,
        Operation::Cut,
    ];

    /// Lower-case name, as used in profiles, layers and the command line.
    pub fn name(self) -> &'static str {
        match self {
            Operation::Mark => "mark",
            Operation::Score => "score",
            Operation::Perforate => "perforate",
            Operation::Cut => "cut",
            Operation::Plot => "plot",
        }
    }

    /// Parses a name given by [`Operation::name`].
    pub fn from_name(s: &str) -> Option<Operation> {
        Operation::ALL.into_iter().find(|o| o.name() == s)
    }

    /// Parses what a user may choose for a kind of line: an operation's name, or `skip`
    /// (`None`: the lines are not machined), as `--mountain` and the studio's settings take it.
    ///
    /// # Errors
    /// Any other word, with the words allowed.
    pub fn choice(s: &str) -> Result<Option<Operation>, String> {
        if s == "skip" {
            return Ok(None);
        }
        Operation::from_name(s).map(Some).ok_or_else(|| {
            format!("{s:?} is not an operation (mark, score, perforate, cut, plot, skip)")
        })
    }
}
