//! Whether a folded form is its crease pattern folded without stretching.

use foldcam::pattern::{CreasePattern, FoldedState};

/// Panics naming the edge when an edge of `folded` differs from its flat length in `flat` by
/// more than `relative` of that length (1e-9 mm at the least).
pub fn assert_isometric(flat: &CreasePattern, folded: &FoldedState, relative: f64, what: &str) {
    assert_eq!(folded.edges.len(), flat.edges.len(), "{what}: edge counts");
    for e in &flat.edges {
        let [a, b] = e.vertices;
        let flat_mm = flat.position(a).distance(flat.position(b));
        let folded_mm = folded.positions[a.index()].distance(folded.positions[b.index()]);
        assert!(
            (folded_mm - flat_mm).abs() <= (relative * flat_mm).max(1e-9),
            "{what}: edge {a:?}-{b:?} is {flat_mm} mm flat, {folded_mm} mm folded"
        );
    }
}
