//! Polygon pop-up cards (Mitani & Suzuki 2004) from a `.popup.toml` design: fitting when
//! asked, the replay of its operations with the pop-up check, the crease pattern and the
//! card's own checks — what `foldcam popup poly` does before it writes anything.

use super::card::{card_holds, take_fit};
use super::note::BuildNote;
use super::summary::SummaryLine;
use super::{DesignFile, DesignKind, Progress, SourceError};
use crate::design::popup::fit::fit_design;
use crate::design::popup::polygon::{
    Design, PolygonCard, Replay, crease_pattern, fold_card, holds_paper, parse_design,
};
use crate::pattern::{CreasePattern, Face, FoldedState};

/// Most failing faces listed when the card would not pop up.
const PROBLEMS_SHOWN: usize = 40;

/// Options of a polygon card; the default is `foldcam popup poly`'s.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PolyOptions {
    /// Grow the back sheet until the card, folded shut, holds every face; refuse when it
    /// cannot.
    pub fit: bool,
}

/// A polygon card that pops up, its crease pattern, and the card folded shut.
#[derive(Clone, Debug)]
pub struct PolyDesign {
    /// The design as replayed (fitted when asked).
    pub design: Design,
    /// The card after every operation.
    pub card: PolygonCard,
    /// Its crease pattern (valleys +90°, mountains −90°, cuts).
    pub pattern: CreasePattern,
    /// The card folded shut (opening 0°).
    pub closed: FoldedState,
    /// What `foldcam popup poly` prints when it has written the card.
    pub summary: Vec<SummaryLine>,
}

impl PolyDesign {
    /// The card's folded state at an opening angle, degrees (0 shut, 90 standing).
    pub fn fold_at(&self, opening_deg: f64) -> FoldedState {
        fold_card(&self.card, &self.pattern, opening_deg).state
    }

    /// As one design (no folded state: the command writes the pattern alone).
    pub fn into_design(self) -> super::Design {
        super::Design {
            kind: DesignKind::PopupPolygon,
            made: "polygon pop-up card (Mitani & Suzuki 2004)",
            pattern: self.pattern,
            folded: None,
            summary: self.summary,
            sheets: 1,
        }
    }
}

/// Builds the card `file` (a `.popup.toml`) describes.
///
/// # Errors
/// Bad input naming the file and the place; [`SourceError::NotMade`] with the operation after
/// which the card became invalid, a lost piece, or a fit that cannot hold the card.
pub fn build(
    file: &DesignFile<'_>,
    options: &PolyOptions,
    progress: &mut dyn Progress,
) -> Result<PolyDesign, SourceError> {
    let path = file.name;
    let design = parse_design(file.text()?).map_err(|e| SourceError::input(path, e))?;
    let design = if options.fit {
        take_fit(path, fit_design(&design), "back sheet", progress)?
    } else {
        design
    };
    progress.note(BuildNote::Replaying {
        operations: design.operations.len(),
    });
    let replay = design.replay().map_err(|e| SourceError::input(path, e))?;
    if !replay.report.passed() {
        return Err(SourceError::NotMade {
            lines: failure_lines(&file.display(), &replay),
        });
    }
    let card = replay.card;
    let mut pattern = crease_pattern(&card).map_err(|e| SourceError::input(path, e))?;
    super::title_from(&mut pattern, path);
    let closed = fold_card(&card, &pattern, 0.0).state;
    let hint = "join every face to the card through a fold (move or grow the face that is cut \
                free)";
    let paper = |f: &Face| holds_paper(&card, &pattern, f);
    card_holds(path, &pattern, &closed, options.fit, hint, paper, progress)?;
    let (w, d, h) = card.size_mm();
    let faces = card
        .faces()
        .iter()
        .filter(|f| !f.polygon.is_empty())
        .count();
    let summary = vec![SummaryLine::PolygonCard {
        file: path.display().to_string(),
        operations: design.operations.len(),
        faces,
        width_mm: w,
        base_mm: d,
        back_mm: h,
    }];
    Ok(PolyDesign {
        design,
        card,
        pattern,
        closed,
        summary,
    })
}

/// The operation after which the card became invalid and the failing faces.
fn failure_lines(name: &str, replay: &Replay) -> Vec<String> {
    let after = replay.became_invalid_after.unwrap_or(0);
    let mut lines = vec![format!(
        "{name}: the card would not pop up; it became invalid at operation {after}"
    )];
    for problem in replay.report.problems.iter().take(PROBLEMS_SHOWN) {
        let face = problem.piece.face;
        let from = if face >= 2 {
            format!(" (operation {})", face - 1)
        } else {
            String::new()
        };
        lines.push(format!("  {problem}{from}"));
    }
    if replay.report.problems.len() > PROBLEMS_SHOWN {
        lines.push(format!(
            "  … and {} more faces",
            replay.report.problems.len() - PROBLEMS_SHOWN
        ));
    }
    lines
}
