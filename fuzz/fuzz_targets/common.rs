//! What every crease-pattern target asserts: a reader either returns a pattern that passes
//! `CreasePattern::validate` (indices in range, finite coordinates within limits, no loop
//! edges) and that every writer renders without a panic, or an error that says something. Hangs
//! and memory exhaustion are findings too.

use foldcam::formats::{Format, Imported, ParseError, render};

/// Checks a reader's result.
pub fn check(result: Result<Imported, ParseError>) {
    match result {
        Ok(imported) => {
            let cp = &imported.pattern;
            if let Err(e) = cp.validate() {
                panic!("a reader returned an invalid pattern: {e}");
            }
            // A pattern without edges renders to nothing in some formats (the CLI refuses it
            // before writing); what matters here is that no writer panics.
            for format in [Format::Fold, Format::Svg, Format::Cp, Format::Opx] {
                let _ = render(format, cp, imported.folded.as_ref());
            }
        }
        Err(e) => assert!(
            !e.message.trim().is_empty() && !e.place.trim().is_empty(),
            "an error without place or message: {e:?}"
        ),
    }
}
