//! Checks shared by the two pop-up cards once built: the paper holds together and, folded
//! shut, stays within its outline (see [`crate::design::popup::integrity`]), and what `fit`
//! added (see [`crate::design::popup::fit`]).

use std::path::Path;

use super::note::{BuildNote, closed_overhang_text};
use super::{Progress, SourceError};
use crate::design::popup::fit::{CLOSED_SLACK_MM, FitError, Fitted};
use crate::design::popup::integrity::{closed_overhang, loose_pieces_where};
use crate::pattern::{CreasePattern, Face, FoldedState};

/// Most loose pieces listed in a refusal.
const LOOSE_SHOWN: usize = 20;

/// The card `fit` gave back, after saying (as a note) what it added, if anything; `what`
/// names the paper that grew. A fit that cannot hold the card refuses it.
///
/// # Errors
/// [`SourceError::NotMade`] with the fit's reason.
pub fn take_fit<T>(
    input: &Path,
    fit: Result<Fitted<T>, FitError>,
    what: &str,
    progress: &mut dyn Progress,
) -> Result<T, SourceError> {
    let fitted = fit.map_err(|e| SourceError::NotMade {
        lines: vec![format!("{}: {e}", input.display())],
    })?;
    if let Some(o) = fitted.before {
        progress.note(BuildNote::Fitted {
            file: input.display().to_string(),
            beyond_mm: o.beyond_mm,
            at: o.at,
            added_mm: fitted.added_mm,
            to: what.to_string(),
        });
    }
    Ok(fitted.card)
}

/// Checks that a card holds together and closes within its outline. Loose pieces refuse
/// the card ([`SourceError::NotMade`], `hint` saying what to change); an overhang when closed
/// is a warning note, or a refusal when `fit` was asked for (fitting could not hold it).
/// `paper` says which faces of `cp` are paper (not holes).
///
/// # Errors
/// [`SourceError::NotMade`] with the lines `foldcam` prints.
pub fn card_holds(
    input: &Path,
    cp: &CreasePattern,
    closed: &FoldedState,
    fit: bool,
    hint: &str,
    paper: impl Fn(&Face) -> bool,
    progress: &mut dyn Progress,
) -> Result<(), SourceError> {
    let loose = loose_pieces_where(cp, paper);
    if !loose.is_empty() {
        let mut lines = vec![format!(
            "{}: the card would lose {} piece(s): {hint}",
            input.display(),
            loose.len()
        )];
        lines.extend(loose.iter().take(LOOSE_SHOWN).map(|p| format!("  {p}")));
        return Err(SourceError::NotMade { lines });
    }
    let Some(o) = closed_overhang(closed).filter(|o| o.beyond_mm > CLOSED_SLACK_MM) else {
        return Ok(());
    };
    let (lo, hi) = o.outline;
    let file = input.display().to_string();
    let outline_mm = [hi.x - lo.x, hi.y - lo.y];
    if fit {
        let message = closed_overhang_text(&file, o.beyond_mm, outline_mm, o.at);
        Err(SourceError::NotMade {
            lines: vec![format!(
                "{message}: make the model smaller or the card larger"
            )],
        })
    } else {
        progress.note(BuildNote::ClosedOverhang {
            file,
            beyond_mm: o.beyond_mm,
            outline_mm,
            at: o.at,
        });
        Ok(())
    }
}
