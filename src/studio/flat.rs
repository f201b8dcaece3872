//! The flat-folded view: the pattern folded flat by the layer solver (Flat-Folder's method,
//! Akitaya, Demaine & Ku 2023), seen from above, as `foldcam fold-flat --png` draws it: every
//! cell of the overlap arrangement filled with the colour of the face on top, darker where
//! more layers lie.

use serde::Serialize;

use super::document::Document;
use super::error::{Stage, StudioError};
use crate::check::layers::{DEFAULT_MAX_STATES, FlatFolding, KawasakiTolerance, LayerOptions};
use crate::render::top_view::{cell_colour, deepest_layers};

/// One cell as drawn.
#[derive(Clone, Debug, Serialize)]
pub struct FlatCell {
    /// Outline and holes, folded coordinates (pattern unit, y up).
    pub rings: Vec<Vec<[f64; 2]>>,
    /// Layers of paper in the cell.
    pub layers: usize,
    /// The face seen from above.
    pub top: usize,
    /// True when that face shows the paper's back.
    pub flipped: bool,
    /// Fill shaded by depth (`#rrggbb`), as the PNG of `fold-flat`.
    pub fill: String,
    /// Fill of the X-ray view (layer count only).
    pub xray: String,
}

/// A flat-folded state as the page draws it.
#[derive(Clone, Debug, Serialize)]
pub struct FlatView {
    /// Number of valid layer orders (decimal: counts pass 10^80).
    pub states: String,
    /// False when counting stopped at the cap.
    pub exact: bool,
    /// The state shown, from 0.
    pub state: u64,
    /// Most layers in a cell.
    pub deepest: usize,
    /// Cells covered by paper.
    pub cells: Vec<FlatCell>,
    /// Folded edges `[x0, y0, x1, y1]`, with `true` on the folded outline.
    pub segments: Vec<([f64; 4], bool)>,
}

fn hex(c: [u8; 3]) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// Folds `doc` flat and returns state `state`, as `foldcam fold-flat DOC --state STATE`.
///
/// # Errors
/// The messages `foldcam fold-flat` prints: a pattern that is not locally flat-foldable
/// within the `kawasaki` tolerance, one without a layer order, or a state number past the
/// count.
pub fn flat_view(
    doc: &Document,
    state: u64,
    kawasaki: KawasakiTolerance,
) -> Result<FlatView, StudioError> {
    let name = &doc.name;
    let cp = doc.cleaned(true)?.pattern;
    let options = LayerOptions {
        max_states: Some(DEFAULT_MAX_STATES),
        kawasaki,
        time_limit: Some(std::time::Duration::from_secs(
            crate::limits::STUDIO_LAYER_SECONDS,
        )),
        ..LayerOptions::default()
    };
    let folding =
        FlatFolding::new(&cp, &options).map_err(|e| StudioError::about(Stage::Fold, name, e))?;
    let report = folding.solver.report();
    let view = folding
        .top_view(u128::from(state))
        .map_err(|e| StudioError::about(Stage::Fold, name, e))?;
    let deepest = deepest_layers(&view);
    Ok(FlatView {
        states: report.states.clone(),
        exact: report.exact,
        state,
        deepest,
        cells: view
            .cells
            .iter()
            .map(|c| FlatCell {
                rings: c
                    .rings
                    .iter()
                    .map(|r| r.iter().map(|p| [p.x, p.y]).collect())
                    .collect(),
                layers: c.layers,
                top: c.top.index(),
                flipped: c.top_flipped,
                fill: hex(cell_colour(c, deepest, false)),
                xray: hex(cell_colour(c, deepest, true)),
            })
            .collect(),
        segments: view
            .segments
            .iter()
            .map(|([a, b], outline)| ([a.x, a.y, b.x, b.y], *outline))
            .collect(),
    })
}
