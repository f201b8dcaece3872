//! The flat-folded view: the pattern folded flat by the layer solver (Flat-Folder's method,
//! Akitaya, Demaine & Ku 2023), seen from above, as `foldcam fold-flat --png` draws it: every
//! cell of the overlap arrangement filled with the colour of the face on top, darker where
//! more layers lie.

use serde::Serialize;

use super::document::Document;
use crate::check::layers::{KawasakiTolerance, LayerOptions, LayerSolver, local_faults, refusal};
use crate::render::top_view::{cell_colour, deepest_layers};

/// The layer solver's state cap per component, as `foldcam fold-flat`'s default
/// `--max-states`.
pub const MAX_STATES: u64 = 1_000_000;

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
) -> Result<FlatView, String> {
    let name = &doc.name;
    let cp = doc.cleaned(true)?.pattern;
    if let Some(f) = local_faults(&cp, kawasaki).first_refusal() {
        return Err(format!("{name}: {}", refusal(f)));
    }
    let options = LayerOptions {
        max_states: Some(MAX_STATES),
        kawasaki,
        time_limit: Some(std::time::Duration::from_secs(
            crate::limits::STUDIO_LAYER_SECONDS,
        )),
        ..LayerOptions::default()
    };
    let solver = LayerSolver::new(&cp, &options).map_err(|e| format!("{name}: {e}"))?;
    let report = solver.report();
    if let Some(c) = &report.contradiction {
        return Err(format!("{name}: {}", c.message));
    }
    let view = solver.top_view(u128::from(state)).ok_or_else(|| {
        format!(
            "{name}: there is no state {state} ({} state(s){})",
            report.states,
            if report.exact {
                ""
            } else {
                ", counting stopped at the cap"
            }
        )
    })?;
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
