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

use super::creases::{
    COLLINEAR_SINE, Chain, chain_edges, crease_joins, machined_degrees, polyline_joins,
    weakening_degrees,
};
use super::operations::is_continuous_weakening;
use super::perforation::{NoDashes, clearance_for, layout, layout_closed};
use super::{ContourRole, Operation, PlanOptions, PlanWarning, PlanWarningKind, Toolpath};
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
    /// Number of lines at each vertex that the plan machines or that are the outline (where
    /// score, mark and pen polylines end).
    pub machined: Vec<usize>,
    /// Number of lines at each vertex that weaken the sheet (where perforated creases end).
    pub weakening: Vec<usize>,
}

impl<'a> LineContext<'a> {
    /// Gathers the context.
    pub fn new(cp: &'a CreasePattern, fans: &'a VertexFans, ops: &'a [Option<Operation>]) -> Self {
        LineContext {
            cp,
            fans,
            ops,
            machined: machined_degrees(cp, ops),
            weakening: weakening_degrees(cp, ops),
        }
    }

    /// The chains of edges mapped to `op` (perforated creases straight, others as polylines).
    pub fn chains(&self, op: Operation) -> Vec<Chain> {
        let include = |e: EdgeId| self.ops[e.index()] == Some(op);
        let same_op = |a: EdgeId, b: EdgeId| self.ops[a.index()] == self.ops[b.index()];
        if op == Operation::Perforate {
            chain_edges(self.cp, include, |v, a, b| {
                same_op(a, b) && crease_joins(self.cp, &self.weakening, v, a, b)
            })
        } else {
            chain_edges(self.cp, include, |v, a, b| {
                same_op(a, b) && polyline_joins(self.cp, &self.machined, v, a, b)
            })
        }
    }

    /// The clearance the crease ending at `v` along edge `e` needs there, in toolpath terms
    /// (from the vertex to where the dash's centre line may start): the largest of the vertex
    /// clearance `vertex_mm` and what every other line at `v` requires (see
    /// [`super::perforation`]; webs are measured between the kerf's edges).
    pub fn end_clearance(&self, v: VertexId, e: EdgeId, vertex_mm: f64, opts: &PlanOptions) -> f64 {
        let web = opts.perforation.min_web_mm + opts.kerf_mm;
        let spokes = self.fans.of(v);
        let Some(own) = spokes.iter().find(|s| s.edge == e) else {
            return vertex_mm;
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
            .fold(vertex_mm, f64::max)
    }

    /// The perforation toolpath of one crease (a chain of edges), or why it gets no dash.
    pub fn perforate(&self, chain: &Chain, opts: &PlanOptions) -> Result<Toolpath, Uncut> {
        let (first, last) = (chain.vertices[0], chain.vertices[chain.vertices.len() - 1]);
        let points = chain.points(self.cp);
        let length = polyline::length(&points);
        // Bridges and vertex clearances are material left: the toolpath layout takes the
        // kerf into account when contours are kerf-compensated too.
        let perf = opts.toolpath_perforation();
        let fit = if chain.closed {
            layout_closed(length, &perf)
        } else {
            let clear = [
                self.end_clearance(first, chain.edges[0], perf.vertex_clearance_mm, opts),
                self.end_clearance(
                    last,
                    chain.edges[chain.edges.len() - 1],
                    perf.vertex_clearance_mm,
                    opts,
                ),
            ];
            layout(length, clear, &perf)
        };
        let fit = fit.map_err(|why| Uncut {
            edges: chain.edges.clone(),
            length_mm: length,
            why,
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

/// A perforated crease left without a dash.
#[derive(Clone, Debug, PartialEq)]
pub struct Uncut {
    /// The crease's edges, in walk order.
    pub edges: Vec<EdgeId>,
    /// Its length along the chain, mm.
    pub length_mm: f64,
    /// Why no dash fits.
    pub why: NoDashes,
}

/// Most crease names listed in the warning about creases left uncut.
const UNCUT_NAMES_LISTED: usize = 8;

/// The warnings about creases left without a dash: one line for all those too short (their
/// number, total and longest length, and the first few by name), one per crease that would
/// need too many dashes. `min_dash_mm` is the shortest dash asked for.
pub fn uncut_warnings(uncut: &[Uncut], min_dash_mm: f64) -> Vec<PlanWarning> {
    let short: Vec<&Uncut> = uncut
        .iter()
        .filter(|u| matches!(u.why, NoDashes::TooShort { .. }))
        .collect();
    let mut out = Vec::new();
    if !short.is_empty() {
        let total: f64 = short.iter().map(|u| u.length_mm).sum();
        let longest = short.iter().map(|u| u.length_mm).fold(0.0, f64::max);
        let mut names: Vec<String> = short
            .iter()
            .take(UNCUT_NAMES_LISTED)
            .map(|u| edge_names(&u.edges))
            .collect();
        if short.len() > UNCUT_NAMES_LISTED {
            names.push(format!("and {} more", short.len() - UNCUT_NAMES_LISTED));
        }
        let (count, them) = if short.len() == 1 {
            ("1 crease".to_string(), "it")
        } else {
            (format!("{} creases", short.len()), "them")
        };
        out.push(
            PlanWarningKind::CreasesTooShort
                .says(format!(
                    "{count} ({total:.1} mm in all, the longest {longest:.2} mm) too short for a \
             perforation dash of at least {min_dash_mm:.2} mm after the vertex clearances: left \
             uncut, so the sheet is not weakened along {them} ({}); a smaller --clearance or \
             --min-dash, or --dash for shorter dashes, may fit one",
                    names.join(", ")
                ))
                .on(short.iter().flat_map(|u| u.edges.iter().copied())),
        );
    }
    for u in uncut {
        if let NoDashes::TooMany { count } = u.why {
            out.push(
                PlanWarningKind::TooManyDashes
                    .says(format!(
                        "crease {} ({:.2} mm) would need {count:.0} perforation dashes: left uncut",
                        edge_names(&u.edges),
                        u.length_mm
                    ))
                    .on(u.edges.iter().copied()),
            );
        }
    }
    out
}

/// Every perforation, score, mark and pen toolpath of the pattern, with warnings for creases
/// left without dashes (see [`uncut_warnings`]).
pub fn line_toolpaths(
    ctx: &LineContext,
    opts: &PlanOptions,
    warnings: &mut Vec<PlanWarning>,
) -> Vec<Toolpath> {
    let mut out = Vec::new();
    let mut uncut = Vec::new();
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
                    Err(u) => uncut.push(u),
                }
            } else {
                out.push(ctx.polyline(op, &chain));
            }
        }
    }
    warnings.extend(uncut_warnings(&uncut, opts.perforation.min_dash_mm));
    out
}
