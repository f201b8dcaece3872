//! What the pop-up checks of both card models say about a vertical face that does not stand
//! up. Both run two floods over the pattern (Mitani, Suzuki & Uno 2003, §2.6, for voxel
//! cards; Mitani & Suzuki 2004, §3.6, for polygon cards): (a) from the back sheet and (b) from
//! the base sheet. A vertical face must be reached by both; one reached by neither floats
//! (cut off from both sheets), one reached by only one is held from one side only and is not
//! raised when the card opens.

/// Why a vertical face fails the pop-up check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PopupProblem {
    /// Reached by neither flood: cut off from both sheets.
    Floating,
    /// Reached only from the back sheet (flood a): it hangs and is not pushed up.
    HeldFromBackOnly,
    /// Reached only from the base sheet (flood b): it is not pulled up.
    HeldFromBaseOnly,
}

impl PopupProblem {
    /// The verdict for a face that flood (a) from the back sheet does or does not reach
    /// (`from_back`), and flood (b) from the base sheet (`from_base`): `None` when both do.
    pub fn from_floods(from_back: bool, from_base: bool) -> Option<PopupProblem> {
        match (from_back, from_base) {
            (true, true) => None,
            (false, false) => Some(PopupProblem::Floating),
            (true, false) => Some(PopupProblem::HeldFromBackOnly),
            (false, true) => Some(PopupProblem::HeldFromBaseOnly),
        }
    }

    /// What is wrong, as the end of a sentence about the face ("… floats: cut off from both
    /// sheets").
    pub fn describe(self) -> &'static str {
        match self {
            PopupProblem::Floating => "floats: cut off from both sheets",
            PopupProblem::HeldFromBackOnly => "is held from the back sheet only",
            PopupProblem::HeldFromBaseOnly => "is held from the base sheet only",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_face_reached_by_both_floods_has_no_problem() {
        assert_eq!(PopupProblem::from_floods(true, true), None);
        let all = [(false, false), (true, false), (false, true)]
            .map(|(a, b)| PopupProblem::from_floods(a, b).unwrap());
        // Three different verdicts, three different sentences.
        assert_eq!(
            all,
            [
                PopupProblem::Floating,
                PopupProblem::HeldFromBackOnly,
                PopupProblem::HeldFromBaseOnly
            ]
        );
        let words = all.map(PopupProblem::describe);
        assert!(words[0] != words[1] && words[1] != words[2] && words[0] != words[2]);
    }
}
