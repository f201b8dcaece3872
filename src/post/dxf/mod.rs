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
//! One layer per operation present, named and coloured by [`super::layer_style`]. Every
//! stroke is one entity (so perforation dashes stay separate); a stroke whose ends meet is
//! written closed. Coordinates are machine coordinates in mm, printed on a 1e-6 mm grid;
//! repeated points are dropped and strokes of zero length skipped.

mod r12;
mod r2000;
mod writer;

use glam::DVec2;

use super::number::Grid;
use super::{DxfVersion, PostError};
use crate::fab::{Job, Operation};

/// Decimals of printed DXF coordinates (a 1e-6 mm grid).
const DXF_DECIMALS: usize = 6;

/// One stroke ready to draw: grid counts, repeated points removed, closing point dropped.
#[derive(Clone, Debug, PartialEq)]
struct Shape {
    /// The operation (its layer).
    op: Operation,
    /// Vertices in grid counts, at least two.
    points: Vec<(i64, i64)>,
    /// The last vertex joins the first.
    closed: bool,
}

/// The job's drawing in `version`.
pub fn write(job: &Job, version: DxfVersion) -> Result<Vec<u8>, PostError> {
    let grid = Grid::decimal(DXF_DECIMALS);
    let shapes = shapes(job, &grid);
    if shapes.is_empty() {
        return Err(PostError::EmptyJob {
            job: job.name.clone(),
        });
    }
    let text = match version {
        DxfVersion::R2000 => r2000::document(&shapes, &grid),
        DxfVersion::R12 => r12::document(&shapes, &grid),
    };
    Ok(text.into_bytes())
}

/// Every stroke of the job with a length, in order.
fn shapes(job: &Job, grid: &Grid) -> Vec<Shape> {
    let strokes = job
        .paths
        .iter()
        .flat_map(|p| p.strokes.iter().map(|s| (p.op, s)));
    strokes.filter_map(|(op, s)| shape(op, s, grid)).collect()
}

/// `stroke` on the grid, or `None` when it has no length there.
fn shape(op: Operation, stroke: &[DVec2], grid: &Grid) -> Option<Shape> {
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
    Some(Shape { op, points, closed })
}

/// The operations drawn, in [`Operation::ALL`] order.
fn operations(shapes: &[Shape]) -> Vec<Operation> {
    Operation::ALL
        .into_iter()
        .filter(|op| shapes.iter().any(|s| s.op == *op))
        .collect()
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
