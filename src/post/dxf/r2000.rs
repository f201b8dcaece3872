//! DXF R2000 (AC1015): handles and owners for every table, record, block and object.
//!
//! Handles are fixed for the structure (below 0x20), counted up from [`FIRST_LAYER`] for the
//! layers and from [`FIRST_ENTITY`] (or past the last layer, with more than 15 layers) for
//! the entities, so `$HANDSEED` is known before the header is written.

use super::super::number::Grid;
use super::writer::Pairs;
use super::{LayerName, Shape, extents};

const VPORT_TABLE: u32 = 0x1;
const LTYPE_TABLE: u32 = 0x2;
const LAYER_TABLE: u32 = 0x3;
const STYLE_TABLE: u32 = 0x4;
const VIEW_TABLE: u32 = 0x5;
const UCS_TABLE: u32 = 0x6;
const APPID_TABLE: u32 = 0x7;
const DIMSTYLE_TABLE: u32 = 0x8;
const BLOCK_RECORD_TABLE: u32 = 0x9;
const ROOT_DICT: u32 = 0xA;
const GROUP_DICT: u32 = 0xB;
const LAYOUT_DICT: u32 = 0xC;
const MODEL_LAYOUT: u32 = 0xD;
const PAPER_LAYOUT: u32 = 0xE;
const ACTIVE_VPORT: u32 = 0x10;
const LTYPE_BYBLOCK: u32 = 0x11;
const LTYPE_BYLAYER: u32 = 0x12;
const LTYPE_CONTINUOUS: u32 = 0x13;
const STANDARD_STYLE: u32 = 0x14;
const ACAD_APPID: u32 = 0x15;
const STANDARD_DIMSTYLE: u32 = 0x16;
const MODEL_RECORD: u32 = 0x17;
const PAPER_RECORD: u32 = 0x18;
const MODEL_BLOCK: u32 = 0x19;
const MODEL_ENDBLK: u32 = 0x1A;
const PAPER_BLOCK: u32 = 0x1B;
const PAPER_ENDBLK: u32 = 0x1C;
/// Layer `0`; the operation layers follow.
const FIRST_LAYER: u32 = 0x20;
/// The first entity; the rest follow.
const FIRST_ENTITY: u32 = 0x30;

/// The handle of the first entity: [`FIRST_ENTITY`], or the one after the last layer.
fn first_entity(names: &[LayerName]) -> u32 {
    (FIRST_LAYER + 1 + names.len() as u32).max(FIRST_ENTITY)
}

/// The whole R2000 file.
pub fn document(shapes: &[Shape], names: &[LayerName], grid: &Grid) -> String {
    let mut out = Pairs::new(grid);
    let first = first_entity(names);
    header(&mut out, shapes, first);
    out.section("CLASSES").end_section();
    tables(&mut out, names);
    blocks(&mut out);
    out.section("ENTITIES");
    for (i, shape) in shapes.iter().enumerate() {
        entity(&mut out, shape, names, first + i as u32);
    }
    out.end_section();
    objects(&mut out);
    out.finish()
}

/// Version, next handle, units (4 = mm), metric, extents.
fn header(out: &mut Pairs, shapes: &[Shape], first_entity: u32) {
    let (lo, hi) = extents(shapes);
    out.section("HEADER").pair(9, "$ACADVER").pair(1, "AC1015");
    out.pair(9, "$HANDSEED")
        .handle(5, first_entity + shapes.len() as u32);
    out.pair(9, "$INSUNITS").pair(70, 4);
    out.pair(9, "$MEASUREMENT").pair(70, 1);
    out.pair(9, "$EXTMIN").point3(10, lo);
    out.pair(9, "$EXTMAX").point3(10, hi);
    out.end_section();
}

/// The nine symbol tables.
fn tables(out: &mut Pairs, names: &[LayerName]) {
    out.section("TABLES");
    table(out, "VPORT", VPORT_TABLE, 1);
    vport(out);
    out.pair(0, "ENDTAB");
    table(out, "LTYPE", LTYPE_TABLE, 3);
    linetypes(out);
    out.pair(0, "ENDTAB");
    layers(out, names);
    table(out, "STYLE", STYLE_TABLE, 1);
    style(out);
    out.pair(0, "ENDTAB");
    table(out, "VIEW", VIEW_TABLE, 0);
    out.pair(0, "ENDTAB");
    table(out, "UCS", UCS_TABLE, 0);
    out.pair(0, "ENDTAB");
    table(out, "APPID", APPID_TABLE, 1);
    record(
        out,
        "APPID",
        ACAD_APPID,
        APPID_TABLE,
        "AcDbRegAppTableRecord",
    );
    out.pair(2, "ACAD").pair(70, 0);
    out.pair(0, "ENDTAB");
    dimstyles(out);
    block_records(out);
    out.end_section();
}

/// A table head.
fn table(out: &mut Pairs, name: &str, handle: u32, count: usize) {
    out.pair(0, "TABLE")
        .pair(2, name)
        .handle(5, handle)
        .handle(330, 0);
    out.pair(100, "AcDbSymbolTable").pair(70, count);
}

/// The start of a table record: type, handle, owner, subclass markers.
fn record(out: &mut Pairs, kind: &str, handle: u32, owner: u32, subclass: &str) {
    out.pair(0, kind).handle(5, handle).handle(330, owner);
    out.pair(100, "AcDbSymbolTableRecord").pair(100, subclass);
}

/// The `*Active` viewport, looking at the origin.
fn vport(out: &mut Pairs) {
    record(
        out,
        "VPORT",
        ACTIVE_VPORT,
        VPORT_TABLE,
        "AcDbViewportTableRecord",
    );
    out.pair(2, "*Active").pair(70, 0);
    for (code, value) in [(10, "0.0"), (20, "0.0"), (11, "1.0"), (21, "1.0")] {
        out.pair(code, value);
    }
    for (code, value) in [(12, "0.0"), (22, "0.0"), (40, "100.0"), (41, "1.5")] {
        out.pair(code, value);
    }
}

/// `ByBlock`, `ByLayer` and `Continuous`.
fn linetypes(out: &mut Pairs) {
    let types = [
        (LTYPE_BYBLOCK, "ByBlock", ""),
        (LTYPE_BYLAYER, "ByLayer", ""),
        (LTYPE_CONTINUOUS, "Continuous", "Solid line"),
    ];
    for (handle, name, description) in types {
        record(out, "LTYPE", handle, LTYPE_TABLE, "AcDbLinetypeTableRecord");
        out.pair(2, name).pair(70, 0).pair(3, description);
        out.pair(72, 65).pair(73, 0).pair(40, "0.0");
    }
}

/// Layer `0` and the job's layers.
fn layers(out: &mut Pairs, names: &[LayerName]) {
    table(out, "LAYER", LAYER_TABLE, names.len() + 1);
    layer(out, FIRST_LAYER, "0", 7);
    for (i, l) in names.iter().enumerate() {
        layer(out, FIRST_LAYER + 1 + i as u32, &l.name, l.aci);
    }
    out.pair(0, "ENDTAB");
}

/// One layer record: continuous lines, default weight, plotted.
fn layer(out: &mut Pairs, handle: u32, name: &str, aci: u8) {
    record(out, "LAYER", handle, LAYER_TABLE, "AcDbLayerTableRecord");
    out.pair(2, name)
        .pair(70, 0)
        .pair(62, aci)
        .pair(6, "Continuous");
    out.pair(290, 1).pair(370, -3);
}

/// The `Standard` text style.
fn style(out: &mut Pairs) {
    record(
        out,
        "STYLE",
        STANDARD_STYLE,
        STYLE_TABLE,
        "AcDbTextStyleTableRecord",
    );
    out.pair(2, "Standard")
        .pair(70, 0)
        .pair(40, "0.0")
        .pair(41, "1.0");
    out.pair(50, "0.0")
        .pair(71, 0)
        .pair(42, "2.5")
        .pair(3, "txt")
        .pair(4, "");
}

/// The `Standard` dimension style (its handle group is 105).
fn dimstyles(out: &mut Pairs) {
    table(out, "DIMSTYLE", DIMSTYLE_TABLE, 1);
    out.pair(100, "AcDbDimStyleTable");
    out.pair(0, "DIMSTYLE").handle(105, STANDARD_DIMSTYLE);
    out.handle(330, DIMSTYLE_TABLE)
        .pair(100, "AcDbSymbolTableRecord");
    out.pair(100, "AcDbDimStyleTableRecord")
        .pair(2, "Standard")
        .pair(70, 0);
    out.pair(0, "ENDTAB");
}

/// Model and paper space records, each pointing to its layout.
fn block_records(out: &mut Pairs) {
    table(out, "BLOCK_RECORD", BLOCK_RECORD_TABLE, 2);
    let spaces = [
        (MODEL_RECORD, "*Model_Space", MODEL_LAYOUT),
        (PAPER_RECORD, "*Paper_Space", PAPER_LAYOUT),
    ];
    for (handle, name, layout) in spaces {
        record(
            out,
            "BLOCK_RECORD",
            handle,
            BLOCK_RECORD_TABLE,
            "AcDbBlockTableRecord",
        );
        out.pair(2, name).handle(340, layout);
    }
    out.pair(0, "ENDTAB");
}

/// The model and paper space blocks, empty (entities live in the ENTITIES section).
fn blocks(out: &mut Pairs) {
    out.section("BLOCKS");
    let spaces = [
        (
            MODEL_BLOCK,
            MODEL_ENDBLK,
            MODEL_RECORD,
            "*Model_Space",
            false,
        ),
        (
            PAPER_BLOCK,
            PAPER_ENDBLK,
            PAPER_RECORD,
            "*Paper_Space",
            true,
        ),
    ];
    for (begin, end, owner, name, paper) in spaces {
        out.pair(0, "BLOCK").handle(5, begin).handle(330, owner);
        out.pair(100, "AcDbEntity");
        if paper {
            out.pair(67, 1);
        }
        out.pair(8, "0")
            .pair(100, "AcDbBlockBegin")
            .pair(2, name)
            .pair(70, 0);
        out.point3(10, (0, 0)).pair(3, name).pair(1, "");
        out.pair(0, "ENDBLK").handle(5, end).handle(330, owner);
        out.pair(100, "AcDbEntity");
        if paper {
            out.pair(67, 1);
        }
        out.pair(8, "0").pair(100, "AcDbBlockEnd");
    }
    out.end_section();
}

/// One stroke as a light-weight polyline in model space.
fn entity(out: &mut Pairs, shape: &Shape, names: &[LayerName], handle: u32) {
    out.pair(0, "LWPOLYLINE")
        .handle(5, handle)
        .handle(330, MODEL_RECORD);
    out.pair(100, "AcDbEntity")
        .pair(8, names[shape.layer].name.as_str());
    out.pair(100, "AcDbPolyline").pair(90, shape.points.len());
    out.pair(70, u8::from(shape.closed)).pair(43, "0.0");
    for &p in &shape.points {
        out.point(10, p);
    }
}

/// The root dictionary, the (empty) group dictionary and the layouts.
fn objects(out: &mut Pairs) {
    out.section("OBJECTS");
    dictionary(
        out,
        ROOT_DICT,
        0,
        &[("ACAD_GROUP", GROUP_DICT), ("ACAD_LAYOUT", LAYOUT_DICT)],
    );
    dictionary(out, GROUP_DICT, ROOT_DICT, &[]);
    let layouts = [("Model", MODEL_LAYOUT), ("Layout1", PAPER_LAYOUT)];
    dictionary(out, LAYOUT_DICT, ROOT_DICT, &layouts);
    layout(out, MODEL_LAYOUT, "Model", 0, MODEL_RECORD);
    layout(out, PAPER_LAYOUT, "Layout1", 1, PAPER_RECORD);
    out.end_section();
}

/// A hard-owner dictionary of `entries`.
fn dictionary(out: &mut Pairs, handle: u32, owner: u32, entries: &[(&str, u32)]) {
    out.pair(0, "DICTIONARY")
        .handle(5, handle)
        .handle(330, owner);
    out.pair(100, "AcDbDictionary").pair(281, 1);
    for &(name, entry) in entries {
        out.pair(3, name).handle(350, entry);
    }
}

/// A layout with default plot settings, bound to its block record.
fn layout(out: &mut Pairs, handle: u32, name: &str, order: u8, record: u32) {
    out.pair(0, "LAYOUT")
        .handle(5, handle)
        .handle(330, LAYOUT_DICT);
    out.pair(100, "AcDbPlotSettings")
        .pair(1, "")
        .pair(2, "")
        .pair(4, "")
        .pair(6, "");
    for code in [40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 140, 141] {
        out.pair(code, "0.0");
    }
    out.pair(142, "1.0")
        .pair(143, "1.0")
        .pair(70, 688)
        .pair(72, 1)
        .pair(73, 0);
    out.pair(74, 5)
        .pair(7, "")
        .pair(75, 16)
        .pair(147, "1.0")
        .pair(148, "0.0");
    out.pair(149, "0.0")
        .pair(100, "AcDbLayout")
        .pair(1, name)
        .pair(70, 1);
    out.pair(71, order).point(10, (0, 0)).point(11, (0, 0));
    out.point3(12, (0, 0)).point3(14, (0, 0)).point3(15, (0, 0));
    out.pair(146, "0.0").point3(13, (0, 0));
    out.pair(16, "1.0").pair(26, "0.0").pair(36, "0.0");
    out.pair(17, "0.0").pair(27, "1.0").pair(37, "0.0");
    out.pair(76, 0).handle(330, record);
}
