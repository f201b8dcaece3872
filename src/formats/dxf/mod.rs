//! Reading crease patterns drawn in DXF (what CAD programs, ORIPA and laser software export),
//! with the `dxf` crate: R12 and R2000 or later.
//!
//! Entities read, in model space: `LINE`, `LWPOLYLINE` and 2D `POLYLINE` (with bulges),
//! `ARC`, `CIRCLE`, `ELLIPSE`, `SPLINE` (NURBS, rational too; fit points only when there are
//! no control points), and `INSERT` of blocks (base point, scale, rotation, column and row
//! arrays, nested up to [`MAX_NESTING`] deep). Curves are flattened into chords within
//! [`CHORD_TOLERANCE_MM`] ([`curves`]); each chord becomes an edge. Text, dimensions, hatches,
//! meshes, points and paper-space entities are skipped with a warning. Entities must lie in
//! the xy plane (extrusion along ±z; −z mirrors x, as AutoCAD's arbitrary-axis rule says).
//!
//! Assignments come from the layer name, else the colour ([`assign`] has the table).
//!
//! Units: `$INSUNITS` (R2000 and later) converts to millimetres; `0` (unitless) and R12
//! files, which have no `$INSUNITS`, give a unitless pattern that commands needing a size
//! scale with `--size` or `--scale`.
//!
//! Then, as for SVG, the segments are planarised and line ends within the snapping tolerance
//! joined ([`crate::formats::snap`]).

pub(crate) mod assign;
pub(crate) mod curves;

use std::collections::{BTreeMap, HashMap};

use dxf::entities::{Entity, EntityType};
use dxf::enums::Units as DxfUnits;
use glam::{DAffine2, DVec2};

use super::{Finding, FindingKind, Imported, ParseError, ReadOptions, snap};
use crate::geom::tolerance::RELATIVE;
use crate::pattern::{Assignment, CreasePattern, MAX_COORDINATE, Units};

/// Largest chord deviation when flattening curves, in millimetres (in drawing units for a
/// unitless drawing), as for SVG.
pub const CHORD_TOLERANCE_MM: f64 = 0.01;

/// Deepest nesting of block references followed.
pub const MAX_NESTING: usize = 16;

/// Most copies one `INSERT` array (columns × rows) makes.
pub const MAX_ARRAY_COPIES: usize = 100_000;

/// Most entity copies all block inserts of a drawing place together (nested arrays
/// multiply): [`crate::limits::MAX_BLOCK_COPIES`].
pub use crate::limits::MAX_BLOCK_COPIES;

/// Most edges read from one file.
pub const MAX_SEGMENTS: usize = super::svg::MAX_SEGMENTS;

/// Parses a DXF drawing with default options.
pub fn read_str(text: &str) -> Result<Imported, ParseError> {
    read_str_with(text, &ReadOptions::default())
}

/// Parses a DXF drawing (see the module docs); `options.snap` sets the snapping tolerance in
/// millimetres (drawing units when unitless).
///
/// # Errors
/// Text the `dxf` crate cannot read, an entity with impossible numbers (naming its type,
/// handle and layer), more than [`MAX_SEGMENTS`] segments, or nothing drawn.
pub fn read_str_with(text: &str, options: &ReadOptions) -> Result<Imported, ParseError> {
    let drawing = dxf::Drawing::load(&mut text.as_bytes())
        .map_err(|e| ParseError::new("file", format!("not a readable DXF drawing: {e}")))?;
    let (units, scale) = units(&drawing);
    let mut reader = Reader {
        pattern: CreasePattern {
            units,
            ..CreasePattern::default()
        },
        tol: CHORD_TOLERANCE_MM / scale,
        blocks: drawing.blocks().map(|b| (b.name.as_str(), b)).collect(),
        layers: drawing
            .layers()
            .map(|l| (l.name.to_ascii_uppercase(), l.color.index()))
            .collect(),
        skipped: BTreeMap::new(),
        by_colour: BTreeMap::new(),
        missing_blocks: BTreeMap::new(),
        curves: 0,
        copies: 0,
    };
    let top = Context {
        transform: DAffine2::from_scale(DVec2::splat(scale)),
        layer: None,
        colour: None,
        depth: 0,
    };
    for entity in drawing.entities() {
        if entity.common.is_in_paper_space {
            *reader.skipped.entry("paper-space entities").or_default() += 1;
            continue;
        }
        reader.entity(entity, &top)?;
    }
    if reader.pattern.edges.is_empty() {
        return Err(ParseError::new(
            "file",
            "the DXF draws no lines, polylines, arcs, circles, ellipses or splines in model space",
        ));
    }
    let warnings = reader.warnings();
    let pattern = reader.pattern;
    let tolerance = merge_tolerance(&pattern);
    let snap = options.snap.unwrap_or_else(|| snap::default_snap(&pattern));
    super::finish_drawing(pattern, Some(tolerance), Some(snap), "drawn", warnings)
}

/// Merge tolerance, as for SVG: [`super::svg::MERGE_TOLERANCE`] of the larger of the
/// diagonal and the largest coordinate magnitude.
fn merge_tolerance(cp: &CreasePattern) -> f64 {
    super::svg::merge_tolerance(cp)
}

/// The pattern's units and the factor from drawing units to them.
fn units(drawing: &dxf::Drawing) -> (Units, f64) {
    let mm = match drawing.header.default_drawing_units {
        DxfUnits::Inches => 25.4,
        DxfUnits::Feet => 304.8,
        DxfUnits::Millimeters => 1.0,
        DxfUnits::Centimeters => 10.0,
        DxfUnits::Meters => 1000.0,
        DxfUnits::Microinches => 25.4e-6,
        DxfUnits::Mils => 25.4e-3,
        DxfUnits::Yards => 914.4,
        DxfUnits::Nanometers => 1e-6,
        DxfUnits::Microns => 1e-3,
        DxfUnits::Decimeters => 100.0,
        DxfUnits::USSurveyFeet => 1200.0 / 3937.0 * 1000.0,
        DxfUnits::USSurveyInch => 1000.0 / 39.37,
        _ => return (Units::Unitless, 1.0),
    };
    (Units::Millimetres, mm)
}

/// Where an entity is drawn from: the transform of the enclosing inserts, and the layer and
/// colour that `0`-layer and `BYBLOCK` entities inside a block take from the insert.
#[derive(Clone)]
struct Context<'a> {
    transform: DAffine2,
    layer: Option<&'a str>,
    colour: Option<Colour>,
    depth: usize,
}

/// A resolved colour.
#[derive(Clone, Copy)]
enum Colour {
    Index(u8),
    True(u32),
}

struct Reader<'a> {
    pattern: CreasePattern,
    /// Chord tolerance in drawing units.
    tol: f64,
    blocks: HashMap<&'a str, &'a dxf::Block>,
    layers: HashMap<String, Option<u8>>,
    skipped: BTreeMap<&'static str, usize>,
    /// Layers whose entities were read by colour, with counts.
    by_colour: BTreeMap<String, usize>,
    missing_blocks: BTreeMap<String, usize>,
    curves: usize,
    /// Entity copies placed through block inserts so far (a copy of an empty block counts
    /// one): bounded by [`MAX_BLOCK_COPIES`].
    copies: u64,
}

impl<'a> Reader<'a> {
    fn entity(&mut self, entity: &'a Entity, ctx: &Context<'a>) -> Result<(), ParseError> {
        let at = |message: String| ParseError::new(place(entity), message);
        let normal_z = normal(entity);
        if normal_z.is_some_and(|z| z.abs() < 1.0 - RELATIVE) {
            *self
                .skipped
                .entry("entities not in the xy plane")
                .or_default() += 1;
            return Ok(());
        }
        // AutoCAD's arbitrary-axis rule: an extrusion of −z mirrors the entity's x.
        let ocs = if normal_z.is_some_and(|z| z < 0.0) {
            DAffine2::from_scale(DVec2::new(-1.0, 1.0))
        } else {
            DAffine2::IDENTITY
        };
        let t = ctx.transform;
        let wcs = ctx.transform * ocs;
        let xy = |p: &dxf::Point| DVec2::new(p.x, p.y);
        match &entity.specific {
            EntityType::Insert(insert) => return self.insert(entity, insert, ctx),
            EntityType::Line(l) => {
                let a = self.assignment(entity, ctx);
                self.chain(
                    &[t.transform_point2(xy(&l.p1)), t.transform_point2(xy(&l.p2))],
                    a,
                )
            }
            EntityType::LwPolyline(p) => {
                let points: Vec<(DVec2, f64)> = p
                    .vertices
                    .iter()
                    .map(|v| (DVec2::new(v.x, v.y), v.bulge))
                    .collect();
                let a = self.assignment(entity, ctx);
                self.polyline(&points, p.is_closed(), wcs, a)
            }
            EntityType::Polyline(p) if p.is_polyface_mesh() || p.is_3d_polygon_mesh() => {
                *self.skipped.entry("polygon meshes").or_default() += 1;
                Ok(())
            }
            EntityType::Polyline(p) => {
                let points: Vec<(DVec2, f64)> =
                    p.vertices().map(|v| (xy(&v.location), v.bulge)).collect();
                let a = self.assignment(entity, ctx);
                let frame = if p.is_3d_polyline() { t } else { wcs };
                self.polyline(&points, p.is_closed(), frame, a)
            }
            EntityType::Arc(arc) => {
                check_radius(arc.radius).map_err(at)?;
                let start = arc.start_angle.to_radians();
                let sweep = curves::ccw_sweep(start, arc.end_angle.to_radians());
                let pts = curves::arc(xy(&arc.center), arc.radius, start, sweep, self.tol);
                self.curve(entity, ctx, wcs, &pts)
            }
            EntityType::Circle(c) => {
                check_radius(c.radius).map_err(at)?;
                let pts = curves::arc(
                    xy(&c.center),
                    c.radius,
                    0.0,
                    std::f64::consts::TAU,
                    self.tol,
                );
                self.curve(entity, ctx, wcs, &pts)
            }
            EntityType::Ellipse(e) => {
                let major = DVec2::new(e.major_axis.x, e.major_axis.y);
                if !(major.length() > 0.0 && e.minor_axis_ratio > 0.0 && e.minor_axis_ratio <= 1.0)
                {
                    return Err(at(format!(
                        "major axis of length {} and axis ratio {}: expected a positive length \
                         and a ratio in (0, 1]",
                        major.length(),
                        e.minor_axis_ratio
                    )));
                }
                let pts = curves::ellipse(
                    xy(&e.center),
                    major,
                    e.minor_axis_ratio,
                    e.start_parameter,
                    e.end_parameter,
                    self.tol,
                );
                self.curve(entity, ctx, wcs, &pts)
            }
            EntityType::Spline(s) => {
                let pts = spline_points(s, self.tol).map_err(at)?;
                self.curve(entity, ctx, t, &pts)
            }
            other => {
                *self.skipped.entry(kind_name(other)).or_default() += 1;
                Ok(())
            }
        }
        .map_err(|message| ParseError::new(place(entity), message))
    }

    /// Adds a flattened curve (points in the entity's frame, mapped by `frame`).
    fn curve(
        &mut self,
        entity: &Entity,
        ctx: &Context<'a>,
        frame: DAffine2,
        pts: &[DVec2],
    ) -> Result<(), String> {
        self.curves += 1;
        let a = self.assignment(entity, ctx);
        let mapped: Vec<DVec2> = pts.iter().map(|&p| frame.transform_point2(p)).collect();
        self.chain(&mapped, a)
    }

    /// Adds a polyline with bulges (in the entity's frame, mapped by `frame`).
    fn polyline(
        &mut self,
        points: &[(DVec2, f64)],
        closed: bool,
        frame: DAffine2,
        a: Assignment,
    ) -> Result<(), String> {
        let n = points.len();
        let spans = if closed { n } else { n.saturating_sub(1) };
        let mut chain: Vec<DVec2> = points.first().map(|p| p.0).into_iter().collect();
        for i in 0..spans {
            let (p, b) = points[i];
            let q = points[(i + 1) % n].0;
            if b != 0.0 {
                self.curves += 1;
            }
            chain.extend(curves::bulge(p, q, b, self.tol).into_iter().skip(1));
        }
        let mapped: Vec<DVec2> = chain.iter().map(|&p| frame.transform_point2(p)).collect();
        self.chain(&mapped, a)
    }

    /// Adds one edge per consecutive pair of points.
    fn chain(&mut self, pts: &[DVec2], a: Assignment) -> Result<(), String> {
        for w in pts.windows(2) {
            for p in w {
                if !(p.is_finite() && p.abs().max_element() <= MAX_COORDINATE) {
                    return Err(format!(
                        "point ({}, {}) lies outside ±{MAX_COORDINATE:e} mm",
                        p.x, p.y
                    ));
                }
            }
            if w[0] == w[1] {
                continue;
            }
            if self.pattern.edges.len() >= MAX_SEGMENTS {
                return Err(format!(
                    "the drawing has more than {MAX_SEGMENTS} line segments, the most read"
                ));
            }
            self.pattern.add_segment(w[0], w[1], a);
        }
        Ok(())
    }

    /// Follows a block reference.
    fn insert(
        &mut self,
        entity: &'a Entity,
        insert: &'a dxf::entities::Insert,
        ctx: &Context<'a>,
    ) -> Result<(), ParseError> {
        let Some(block) = self.blocks.get(insert.name.as_str()).copied() else {
            *self.missing_blocks.entry(insert.name.clone()).or_default() += 1;
            return Ok(());
        };
        if ctx.depth >= MAX_NESTING {
            return Err(ParseError::new(
                place(entity),
                format!(
                    "block \"{}\" is nested more than {MAX_NESTING} inserts deep (or refers to \
                     itself)",
                    insert.name
                ),
            ));
        }
        let scale = DVec2::new(insert.x_scale_factor, insert.y_scale_factor);
        if !(scale.is_finite() && scale.x != 0.0 && scale.y != 0.0) {
            return Err(ParseError::new(
                place(entity),
                format!("scale {} × {}: expected non-zero numbers", scale.x, scale.y),
            ));
        }
        let rotation = insert.rotation.to_radians();
        let base = DVec2::new(insert.location.x, insert.location.y);
        let origin = DVec2::new(block.base_point.x, block.base_point.y);
        let layer = own_layer(entity, ctx);
        let colour = own_colour(entity).or(ctx.colour);
        let columns = insert.column_count.max(1);
        let rows = insert.row_count.max(1);
        let copies = usize::from(columns.unsigned_abs()) * usize::from(rows.unsigned_abs());
        if copies > MAX_ARRAY_COPIES {
            return Err(ParseError::new(
                place(entity),
                format!(
                    "an array of {columns} × {rows} copies of block \"{}\", more than the \
                     {MAX_ARRAY_COPIES} read",
                    insert.name
                ),
            ));
        }
        // Every copy costs its entities (at least one), counted before they are read: nested
        // arrays multiply, and blocks that draw nothing cost time all the same.
        let per_copy = block.entities.len().max(1) as u64;
        for r in 0..rows {
            for c in 0..columns {
                self.copies += per_copy;
                if self.copies > MAX_BLOCK_COPIES {
                    return Err(ParseError::new(
                        place(entity),
                        format!(
                            "the block inserts place more than {MAX_BLOCK_COPIES} entity copies \
                             (nested arrays multiply: here {columns} × {rows} copies of block \
                             \"{}\" at depth {}), the most read",
                            insert.name,
                            ctx.depth + 1
                        ),
                    ));
                }
                let offset = DVec2::new(
                    f64::from(c) * insert.column_spacing,
                    f64::from(r) * insert.row_spacing,
                );
                let local = DAffine2::from_translation(base)
                    * DAffine2::from_angle(rotation)
                    * DAffine2::from_translation(offset)
                    * DAffine2::from_scale(scale)
                    * DAffine2::from_translation(-origin);
                let inner = Context {
                    transform: ctx.transform * local,
                    layer: Some(layer),
                    colour,
                    depth: ctx.depth + 1,
                };
                for e in &block.entities {
                    self.entity(e, &inner)?;
                }
            }
        }
        Ok(())
    }

    /// The entity's assignment: by layer name, else by colour (see [`assign`]).
    fn assignment(&mut self, entity: &Entity, ctx: &Context<'a>) -> Assignment {
        let layer = own_layer(entity, ctx);
        if let Some(a) = assign::layer_assignment(layer) {
            return a;
        }
        *self.by_colour.entry(layer.to_string()).or_default() += 1;
        let colour = match own_colour(entity) {
            Some(c) => Some(c),
            None if entity.common.color.is_by_block() => ctx.colour,
            None => self
                .layers
                .get(&layer.to_ascii_uppercase())
                .copied()
                .flatten()
                .map(Colour::Index),
        };
        match colour {
            Some(Colour::True(rgb)) => assign::rgb_assignment(rgb),
            Some(Colour::Index(i)) => assign::aci_assignment(i),
            None => Assignment::Boundary,
        }
    }

    fn warnings(&self) -> Vec<Finding> {
        let mut out = Vec::new();
        for (kind, n) in &self.skipped {
            out.push(FindingKind::DxfEntities.warning(format!(
                "{n} {kind} were ignored (creases are lines and curves)"
            )));
        }
        for (name, n) in &self.missing_blocks {
            out.push(FindingKind::DxfEntities.warning(format!(
                "{n} insert(s) of block \"{name}\", which the file does not define, were ignored"
            )));
        }
        if !self.by_colour.is_empty() {
            let named: Vec<String> = self
                .by_colour
                .iter()
                .map(|(l, n)| format!("\"{l}\" ({n})"))
                .collect();
            out.push(FindingKind::DxfLayersByColour.warning(format!(
                "layer(s) {} have no crease name (MOUNTAIN, VALLEY, BOUNDARY, CUT, FLAT, …): \
                 their entities were read by colour",
                named.join(", ")
            )));
        }
        if self.curves > 0 {
            out.push(FindingKind::CurvesFlattened.warning(format!(
                "{} curve(s) were flattened into straight edges (within {CHORD_TOLERANCE_MM} \
                 mm); creases are straight",
                self.curves
            )));
        }
        out
    }
}

/// The entity's layer, or the insert's for entities on layer `0` inside a block.
fn own_layer<'a>(entity: &'a Entity, ctx: &Context<'a>) -> &'a str {
    match ctx.layer {
        Some(outer) if entity.common.layer == "0" => outer,
        _ => entity.common.layer.as_str(),
    }
}

/// The entity's own colour: true colour, else an index; `None` for `BYLAYER`/`BYBLOCK`.
fn own_colour(entity: &Entity) -> Option<Colour> {
    let c = &entity.common;
    if c.color_24_bit > 0 {
        return Some(Colour::True(c.color_24_bit as u32 & 0xff_ffff));
    }
    c.color.index().map(Colour::Index)
}

/// The z of an entity's extrusion direction, for the entities that have one.
fn normal(entity: &Entity) -> Option<f64> {
    let v = match &entity.specific {
        EntityType::Arc(a) => &a.normal,
        EntityType::Circle(c) => &c.normal,
        EntityType::LwPolyline(p) => &p.extrusion_direction,
        EntityType::Polyline(p) if !p.is_3d_polyline() => &p.normal,
        EntityType::Line(l) => &l.extrusion_direction,
        EntityType::Insert(i) => &i.extrusion_direction,
        _ => return None,
    };
    let len = (v.x * v.x + v.y * v.y + v.z * v.z).sqrt();
    (len > 0.0).then(|| v.z / len)
}

fn check_radius(r: f64) -> Result<(), String> {
    if r.is_finite() && r > 0.0 && r <= MAX_COORDINATE {
        Ok(())
    } else {
        Err(format!(
            "radius {r}: expected a positive number up to {MAX_COORDINATE:e}"
        ))
    }
}

/// The flattened points of a spline: from its control points, or through its fit points.
fn spline_points(s: &dxf::entities::Spline, tol: f64) -> Result<Vec<DVec2>, String> {
    let xy = |p: &dxf::Point| DVec2::new(p.x, p.y);
    if s.control_points.is_empty() {
        if s.fit_points.len() < 2 {
            return Err("a spline without control points and with fewer than 2 fit points".into());
        }
        return Ok(s.fit_points.iter().map(xy).collect());
    }
    let control: Vec<DVec2> = s.control_points.iter().map(xy).collect();
    let degree = usize::try_from(s.degree_of_curve).map_err(|_| {
        format!(
            "degree {}: expected a positive whole number",
            s.degree_of_curve
        )
    })?;
    let curve = curves::Nurbs {
        degree,
        knots: &s.knot_values,
        control: &control,
        weights: if s.weight_values.iter().all(|&w| w == 1.0) {
            &[]
        } else {
            &s.weight_values
        },
    };
    curve.check()?;
    Ok(curve.flatten(tol))
}

/// Names an entity for an error message: type, handle and layer.
fn place(entity: &Entity) -> String {
    format!(
        "{} (handle {:X}) on layer \"{}\"",
        kind_name(&entity.specific),
        entity.common.handle.0,
        entity.common.layer
    )
}

/// The DXF type name of an entity.
fn kind_name(e: &EntityType) -> &'static str {
    match e {
        EntityType::Line(_) => "LINE",
        EntityType::LwPolyline(_) => "LWPOLYLINE",
        EntityType::Polyline(_) => "POLYLINE",
        EntityType::Arc(_) => "ARC",
        EntityType::Circle(_) => "CIRCLE",
        EntityType::Ellipse(_) => "ELLIPSE",
        EntityType::Spline(_) => "SPLINE",
        EntityType::Insert(_) => "INSERT",
        EntityType::Text(_) | EntityType::MText(_) => "text entities",
        EntityType::RotatedDimension(_)
        | EntityType::RadialDimension(_)
        | EntityType::DiameterDimension(_)
        | EntityType::AngularThreePointDimension(_)
        | EntityType::OrdinateDimension(_) => "dimensions",
        EntityType::ModelPoint(_) => "points",
        EntityType::Solid(_) | EntityType::Trace(_) | EntityType::Wipeout(_) => "filled areas",
        EntityType::Image(_) => "images",
        _ => "other entities",
    }
}
