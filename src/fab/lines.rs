//! Toolpaths of the lines that are not cut through: perforated creases (dashes with vertex
//! clearances, see [`super::perforation`]) and score, mark and pen polylines.
//!
//! Creases are chained by [`super::creases`]; each perforated crease becomes one toolpath
//! whose strokes are its dashes, laid out along the chain's arc length and following it
//! (a dash across a polyline vertex keeps that vertex), in order from the crease's first
//! vertex to its last; a closed crease is dashed all round without end clearances. Each
//! score, mark or pen chain becomes one toolpath with a single polyline stroke (closed when
//! the chain closes). Creases too short for a dash produce no toolpath and a warning naming
//! their edges.

use super::creases::{COLLINEAR_SINE, Chain, chain_edges, crease_joins, degrees, polyline_joins};
use super::operations::is_continuous_weakening;
use super::perforation::{NoDashes, clearance_for, layout, layout_closed};
use super::{ContourRole, Operation, PlanOptions, Toolpath};
use crate::geom::polyline;
use crate::pattern::vertex_fan::VertexFans;
use crate::pattern::{CreasePattern, EdgeId, VertexId};

/// What the line toolpaths need to know about the pattern.
pub struct LineContext<'a> {
    /// The pattern.
    pub cp: &'a CreasePattern,
    /// Its vertex fans.
    pub fans: &'a VertexFans,
    /// Operation per edge.
    pub ops: &'a [Option<Operation>],
    /// Number of edges at each vertex.
    pub degree: Vec<usize>,
}

impl<'a> LineContext<'a> {
    /// Gathers the context.
    pub fn new(cp: &'a CreasePattern, fans: &'a VertexFans, ops: &'a [Option<Operation>]) -> Self {
        LineContext {
            cp,
            fans,
            ops,
            degree: degrees(cp),
        }
    }

    /// The chains of edges mapped to `op` (perforated creases straight, others as polylines).
    pub fn chains(&self, op: Operation) -> Vec<Chain> {
        let include = |e: EdgeId| self.ops[e.index()] == Some(op);
        let same_op = |a: EdgeId, b: EdgeId| self.ops[a.index()] == self.ops[b.index()];
        if op == Operation::Perforate {
            chain_edges(self.cp, include, |v, a, b| {
                same_op(a, b) && crease_joins(self.cp, &self.degree, v, a, b)
            })
        } else {
            chain_edges(self.cp, include, |v, a, b| {
                same_op(a, b) && polyline_joins(self.cp, &self.degree, v, a, b)
            })
        }
    }

    /// The clearance the crease ending at `v` along edge `e` needs there: the largest of the
    /// vertex clearance and what every other line at `v` requires.
    pub fn end_clearance(&self, v: VertexId, e: EdgeId, opts: &PlanOptions) -> f64 {
        let perf = &opts.perforation;
        let web = perf.min_web_mm + opts.kerf_mm;
        let spokes = self.fans.of(v);
        let Some(own) = spokes.iter().find(|s| s.edge == e) else {
            return perf.vertex_clearance_mm;
        };
        spokes
            .iter()
            .filter(|s| s.edge != e)
            .map(|s| {
                let continuous = is_continuous_weakening(self.cp, self.ops, s.edge);
                clearance_for(
                    self.ops[s.edge.index()],
                    continuous,
                    s.angle - own.angle,
                    web,
                )
            })
            .fold(perf.vertex_clearance_mm, f64::max)
    }

    /// The perforation toolpath of one crease (a chain of edges), or a warning when it gets
    /// no dash.
    pub fn perforate(&self, chain: &Chain, opts: &PlanOptions) -> Result<Toolpath, String> {
        let (first, last) = (chain.vertices[0], chain.vertices[chain.vertices.len() - 1]);
        let points = chain.points(self.cp);
        let length = polyline::length(&points);
        // Bridges are material left: the toolpath layout takes the kerf into account when
        // contours are kerf-compensated too.
        let perf = if opts.kerf_offset {
            opts.perforation.for_kerf(opts.kerf_mm)
        } else {
            opts.perforation
        };
        let fit = if chain.closed {
            layout_closed(length, &perf)
        } else {
            let clear = [
                self.end_clearance(first, chain.edges[0], opts),
                self.end_clearance(last, chain.edges[chain.edges.len() - 1], opts),
            ];
            layout(length, clear, &perf)
        };
        let fit = fit.map_err(|why| {
            let names = edge_names(&chain.edges);
            match why {
                NoDashes::TooShort { end_mm, .. } => format!(
                    "crease {names} ({length:.2} mm) is too short for a perforation dash of at \
                     least {:.2} mm after {end_mm:.2} mm vertex clearances: left uncut",
                    opts.perforation.min_dash_mm
                ),
                NoDashes::TooMany { count } => format!(
                    "crease {names} ({length:.2} mm) would need {count:.0} perforation dashes: \
                     left uncut"
                ),
            }
        })?;
        let strokes = fit
            .dashes
            .iter()
            .map(|&(s, t)| {
                polyline::drop_straight_points(&polyline::sub_path(&points, s, t), COLLINEAR_SINE)
            })
            .collect();
        Ok(line_path(Operation::Perforate, strokes, chain))
    }

    /// The polyline toolpath of one score, mark or pen chain.
    pub fn polyline(&self, op: Operation, chain: &Chain) -> Toolpath {
        line_path(op, vec![chain.points(self.cp)], chain)
    }
}

fn line_path(op: Operation, strokes: Vec<Vec<glam::DVec2>>, chain: &Chain) -> Toolpath {
    Toolpath {
        op,
        strokes,
        role: ContourRole::None,
        container: None,
        edges: chain.edges.clone(),
    }
}

/// `e3` for one edge, `e3…e7 (5 edges)` for a chain.
pub fn edge_names(edges: &[EdgeId]) -> String {
    match edges {
        [] => String::from("(no edges)"),
        [e] => e.to_string(),
        [first, .., last] => format!("{first}…{last} ({} edges)", edges.len()),
    }
}

/// Every perforation, score, mark and pen toolpath of the pattern, with warnings for creases
/// left without dashes.
pub fn line_toolpaths(
    ctx: &LineContext,
    opts: &PlanOptions,
    warnings: &mut Vec<String>,
) -> Vec<Toolpath> {
    let mut out = Vec::new();
    for op in [
        Operation::Perforate,
        Operation::Score,
        Operation::Mark,
        Operation::Plot,
    ] {
        for chain in ctx.chains(op) {
            if op == Operation::Perforate {
                match ctx.perforate(&chain, opts) {
                    Ok(path) => out.push(path),
                    Err(warning) => warnings.push(warning),
                }
            } else {
                out.push(ctx.polyline(op, &chain));
            }
        }
    }
    out
}
