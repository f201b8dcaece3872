//! What every crease-pattern target asserts: a reader either returns a pattern that passes
//! `CreasePattern::validate` (indices in range, finite coordinates within limits, no loop
//! edges) and that every writer can render, or an error that says something. Panics, hangs
//! and memory exhaustion are the findings.

use foldcam::formats::{Format, Imported, ParseError, render};

/// Checks a reader's result.
pub fn check(result: Result<Imported, ParseError>) {
    match result {
        Ok(imported) => {
            let cp = &imported.pattern;
            if let Err(e) = cp.validate() {
                panic!("a reader returned an invalid pattern: {e}");
            }
            for format in [Format::Fold, Format::Svg, Format::Cp, Format::Opx] {
                let text = render(format, cp, imported.folded.as_ref());
                assert!(!text.is_empty(), "{format:?} writer wrote nothing");
            }
        }
        Err(e) => assert!(
            !e.message.trim().is_empty() && !e.place.trim().is_empty(),
            "an error without place or message: {e:?}"
        ),
    }
}
