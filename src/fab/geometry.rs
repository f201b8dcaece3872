//! PLACEHOLDER (fab-geometry work): the toolpaths of a pattern before ordering.

use super::{FabError, PlanOptions, Toolpath};
use crate::pattern::CreasePattern;

/// Every toolpath of `cp` in pattern coordinates (mm), unordered: perforation dashes laid out
/// per crease with vertex clearances, scores and marks as polylines, cut contours chained,
/// kerf-offset, with tabs and lead-ins.
pub fn toolpaths(_cp: &CreasePattern, _opts: &PlanOptions) -> Result<Vec<Toolpath>, FabError> {
    todo!()
}
