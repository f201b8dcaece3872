//! PLACEHOLDER: written by the fold format work.

use super::{Imported, ParseError};
use crate::pattern::{CreasePattern, FoldedState};

/// Parses a file's text.
pub fn read_str(_text: &str) -> Result<Imported, ParseError> {
    todo!()
}

/// Renders a pattern.
pub fn write_string(_pattern: &CreasePattern, _folded: Option<&FoldedState>) -> String {
    todo!()
}
