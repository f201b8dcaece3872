//! DXF writer, by hand: R2000 (AC1015) by default, R12 (AC1009) on request.
//!
//! Written directly rather than through the `dxf` crate, whose R2000 output draws seven
//! "invalid table head handle" fixes from `ezdxf audit` and whose R12 output silently drops
//! `LWPOLYLINE`. The R2000 file is minimal but complete: HEADER (`$ACADVER`, `$HANDSEED`,
//! `$INSUNITS` = 4 mm, `$MEASUREMENT` = 1 metric, extents), CLASSES (empty), TABLES with
//! handles and owner handles (VPORT, LTYPE, LAYER, STYLE, VIEW, UCS, APPID, DIMSTYLE,
//! BLOCK_RECORD), BLOCKS (model and paper space), ENTITIES and OBJECTS (the root dictionary,
//! groups and the two layouts). The R12 file has no handles, no `$INSUNITS` (R12 has none)
//! and draws with `LINE` (two-point strokes) and `POLYLINE`/`VERTEX`/`SEQEND`.
//!
//! One layer per operation present (and per settings override, see [`super::layers`]), named
//! as there and coloured by [`super::layer_style`] of its operation. Every
//! stroke is one entity (so perforation dashes stay separate); a stroke whose ends meet is
//! written closed. Coordinates are machine coordinates in mm, printed on a 1e-6 mm grid;
//! repeated points are dropped and strokes of zero length skipped.

mod r12;
mod r2000;
mod writer;

use glam::DVec2;

use super::number::Grid;
use super::{DxfVersion, PostError, layer_style, layers};
use crate::fab::{FabPlan, Setup};

/// Decimals of printed DXF coordinates (a 1e-6 mm grid).
const DXF_DECIMALS: usize = 6;

/// One stroke ready to draw: grid counts, repeated points removed, closing point dropped.
#[derive(Clone, Debug, PartialEq)]
struct Shape {
    /// Index of its layer in the document's [`LayerName`]s.
    layer: usize,
    /// Vertices in grid counts, at least two.
    points: Vec<(i64, i64)>,
    /// The last vertex joins the first.
    closed: bool,
}

/// A DXF layer: its name and AutoCAD Color Index.
#[derive(Clone, Debug, PartialEq)]
struct LayerName {
    name: String,
    aci: u8,
}

/// The job's drawing in `version`.
pub fn write(plan: &FabPlan, job: &Setup, version: DxfVersion) -> Result<Vec<u8>, PostError> {
    let grid = Grid::decimal(DXF_DECIMALS);
    let layers = layers::layers(plan, job);
    let shapes = shapes(plan, job, &layers, &grid);
    if shapes.is_empty() {
        return Err(PostError::EmptyJob {
            job: job.name.clone(),
        });
    }
    // Only the layers some shape is drawn on (a layer's strokes may all round away).
    let used: Vec<usize> = (0..layers.len())
        .filter(|&i| shapes.iter().any(|s| s.layer == i))
        .collect();
    let names: Vec<LayerName> = used
        .iter()
        .map(|&i| LayerName {
            name: layers[i].dxf_name.clone(),
            aci: layer_style(layers[i].op).aci,
        })
        .collect();
    let shapes: Vec<Shape> = shapes
        .into_iter()
        .filter_map(|mut s| {
            s.layer = used.iter().position(|&i| i == s.layer)?;
            Some(s)
        })
        .collect();
    let text = match version {
        DxfVersion::R2000 => r2000::document(&shapes, &names, &grid),
        DxfVersion::R12 => r12::document(&shapes, &names, &grid),
    };
    Ok(text.into_bytes())
}

/// Every stroke of the job with a length, in order, on its layer.
fn shapes(plan: &FabPlan, job: &Setup, layers: &[layers::Layer], grid: &Grid) -> Vec<Shape> {
    let strokes = job.paths.iter().flat_map(|p| {
        let layer = layers::layer_of(layers, plan, p);
        p.strokes.iter().map(move |s| (layer, s))
    });
    strokes
        .filter_map(|(layer, s)| shape(layer?, s, grid))
        .collect()
}

/// `stroke` on the grid, or `None` when it has no length there.
fn shape(layer: usize, stroke: &[DVec2], grid: &Grid) -> Option<Shape> {
    let mut points: Vec<(i64, i64)> = stroke
        .iter()
        .map(|p| (grid.snap(p.x), grid.snap(p.y)))
        .collect();
    points.dedup();
    if points.len() < 2 {
        return None;
    }
    let closed = points.len() > 3 && points.first() == points.last();
    if closed {
        points.pop();
    }
    Some(Shape {
        layer,
        points,
        closed,
    })
}

/// Lower-left and upper-right corners of all shapes, grid counts.
fn extents(shapes: &[Shape]) -> ((i64, i64), (i64, i64)) {
    let all = shapes.iter().flat_map(|s| s.points.iter());
    all.fold(
        ((i64::MAX, i64::MAX), (i64::MIN, i64::MIN)),
        |(lo, hi), p| {
            (
                (lo.0.min(p.0), lo.1.min(p.1)),
                (hi.0.max(p.0), hi.1.max(p.1)),
            )
        },
    )
}
