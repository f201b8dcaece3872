//! DXF R12 (AC1009): no handles, no `$INSUNITS`; `LINE` and `POLYLINE` entities only.

use super::super::number::Grid;
use super::writer::Pairs;
use super::{LayerName, Shape, extents};

/// The whole R12 file.
pub fn document(shapes: &[Shape], names: &[LayerName], grid: &Grid) -> String {
    let mut out = Pairs::new(grid);
    header(&mut out, shapes);
    tables(&mut out, names);
    out.section("BLOCKS").end_section();
    out.section("ENTITIES");
    for shape in shapes {
        entity(&mut out, shape, names);
    }
    out.end_section();
    out.finish()
}

/// Version and extents.
fn header(out: &mut Pairs, shapes: &[Shape]) {
    let (lo, hi) = extents(shapes);
    out.section("HEADER").pair(9, "$ACADVER").pair(1, "AC1009");
    out.pair(9, "$EXTMIN").point3(10, lo);
    out.pair(9, "$EXTMAX").point3(10, hi);
    out.end_section();
}

/// The continuous line type and the layers: `0` and the job's.
fn tables(out: &mut Pairs, names: &[LayerName]) {
    out.section("TABLES");
    out.pair(0, "TABLE").pair(2, "LTYPE").pair(70, 1);
    out.pair(0, "LTYPE").pair(2, "CONTINUOUS").pair(70, 0);
    out.pair(3, "Solid line")
        .pair(72, 65)
        .pair(73, 0)
        .pair(40, "0.0");
    out.pair(0, "ENDTAB");
    out.pair(0, "TABLE")
        .pair(2, "LAYER")
        .pair(70, names.len() + 1);
    layer(out, "0", 7);
    for l in names {
        layer(out, &l.name, l.aci);
    }
    out.pair(0, "ENDTAB");
    out.end_section();
}

/// One layer table entry.
fn layer(out: &mut Pairs, name: &str, aci: u8) {
    out.pair(0, "LAYER").pair(2, name).pair(70, 0);
    out.pair(62, aci).pair(6, "CONTINUOUS");
}

/// A two-point open stroke as `LINE`, anything else as `POLYLINE`.
fn entity(out: &mut Pairs, shape: &Shape, names: &[LayerName]) {
    let layer = names[shape.layer].name.as_str();
    if let ([a, b], false) = (shape.points.as_slice(), shape.closed) {
        out.pair(0, "LINE").pair(8, layer);
        out.point3(10, *a).point3(11, *b);
        return;
    }
    out.pair(0, "POLYLINE").pair(8, layer).pair(66, 1);
    out.point3(10, (0, 0)).pair(70, u8::from(shape.closed));
    for &p in &shape.points {
        out.pair(0, "VERTEX").pair(8, layer).point3(10, p);
    }
    out.pair(0, "SEQEND").pair(8, layer);
}
