//! Checks shared by the two pop-up cards once built: the paper holds together and, folded
//! shut, stays within its outline (see [`crate::design::popup::integrity`]), and what `fit`
//! added (see [`crate::design::popup::fit`]).

use std::path::Path;

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
        progress.note(format!(
            "{}: folded shut, the card reached {:.1} mm beyond its outline (at x = {:.1}, y = \
             {:.1} mm of the closed card); --fit added {:.0} mm to the {what}",
            input.display(),
            o.beyond_mm,
            o.at.x,
            o.at.y,
            fitted.added_mm
        ));
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
    let message = format!(
        "{}: folded shut, the card reaches {:.1} mm beyond its {:.1} × {:.1} mm outline (at \
         x = {:.1}, y = {:.1} mm of the closed card)",
        input.display(),
        o.beyond_mm,
        hi.x - lo.x,
        hi.y - lo.y,
        o.at.x,
        o.at.y
    );
    if fit {
        Err(SourceError::NotMade {
            lines: vec![format!(
                "{message}: make the model smaller or the card larger"
            )],
        })
    } else {
        progress.note(format!("warning: {message}; --fit adds the paper it needs"));
        Ok(())
    }
}
