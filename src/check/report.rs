//! The summary of a check and the readable text report.
//!
//! The text lists at most [`TEXT_FINDINGS_PER_KIND`] findings of each kind (the JSON form,
//! via `serde`, keeps all of them), then a final `PASS` or `FAIL` line.

use std::fmt::Write as _;

use glam::DVec2;
use serde::Serialize;

use super::flat_foldability::accepting_tolerance;
use super::{CheckReport, Finding, FindingKind, Quantity};
use crate::limits::KAWASAKI_TOLERANCE;
use crate::pattern::{Assignment, CreasePattern, EdgeId, VertexId};

/// The largest Kawasaki error, in degrees, that the verdict calls a drawing's rounding when it
/// names the tolerance accepting it; beyond it the verdict says the errors are more than that.
const ROUNDING_SIZED_DEG: f64 = 1.0;

/// Findings of each kind listed by [`CheckReport::to_text`]; the rest are counted.
pub const TEXT_FINDINGS_PER_KIND: usize = 50;

/// Number of edges of each assignment.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct AssignmentCounts {
    /// B edges.
    pub boundary: usize,
    /// M edges.
    pub mountain: usize,
    /// V edges.
    pub valley: usize,
    /// F edges.
    pub flat: usize,
    /// U edges.
    pub unassigned: usize,
    /// C edges.
    pub cut: usize,
    /// J edges.
    pub join: usize,
}

impl AssignmentCounts {
    /// Counts the edges of a pattern.
    pub fn of(cp: &CreasePattern) -> Self {
        let mut c = AssignmentCounts::default();
        for e in &cp.edges {
            *c.slot(e.assignment) += 1;
        }
        c
    }

    fn slot(&mut self, a: Assignment) -> &mut usize {
        match a {
            Assignment::Boundary => &mut self.boundary,
            Assignment::Mountain => &mut self.mountain,
            Assignment::Valley => &mut self.valley,
            Assignment::Flat => &mut self.flat,
            Assignment::Unassigned => &mut self.unassigned,
            Assignment::Cut => &mut self.cut,
            Assignment::Join => &mut self.join,
        }
    }

    /// The count for one assignment.
    pub fn get(&self, a: Assignment) -> usize {
        let mut copy = *self;
        *copy.slot(a)
    }
}

/// A measurement taken at a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct VertexMeasure {
    /// The vertex.
    pub vertex: VertexId,
    /// Its position.
    pub position: DVec2,
    /// The angle, degrees.
    pub degrees: f64,
}

/// A measurement taken on an edge.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct EdgeMeasure {
    /// The edge.
    pub edge: EdgeId,
    /// Its midpoint.
    pub position: DVec2,
    /// The value: a length in the pattern's unit, or a signed fold angle in degrees.
    pub value: f64,
}

impl EdgeMeasure {
    /// A measure of `edge` at `position`.
    pub fn new(edge: EdgeId, position: DVec2, value: f64) -> Self {
        EdgeMeasure {
            edge,
            position,
            value,
        }
    }
}

/// Counts and extremes of a checked pattern.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct CheckSummary {
    /// Number of vertices.
    pub vertices: usize,
    /// Number of edges.
    pub edges: usize,
    /// Interior vertices with at least one crease, checked for Kawasaki (and Maekawa).
    pub interior_vertices_checked: usize,
    /// Edges by assignment.
    pub assignments: AssignmentCounts,
    /// The shortest edge (value: its length).
    pub shortest_edge: Option<EdgeMeasure>,
    /// The narrowest sector between neighbouring creases (or a crease and an outline).
    pub smallest_crease_angle: Option<VertexMeasure>,
    /// The largest |fold angle| among edges that have one (value: signed degrees).
    pub largest_fold_angle: Option<EdgeMeasure>,
    /// Interior vertices not checked for Maekawa because a crease there is unassigned.
    pub maekawa_skipped_unassigned: usize,
    /// Whether Kawasaki and Maekawa ran.
    pub flat_foldability_checked: bool,
    /// Interior vertices with creases where Kawasaki and Maekawa do not apply: a crease there
    /// folds to less than 180° (a 3D target).
    pub vertices_3d: usize,
    /// Of [`Self::vertices_3d`], those whose creases satisfy Kawasaki and Maekawa all the
    /// same: they would fold flat; whether they reach the 3D form is still not checked
    /// without a 3D frame ([`CheckReport::unchecked_vertices`]).
    pub vertices_3d_flat: usize,
    /// The largest relative distance change within a face between the pattern and its 3D
    /// frame, when a frame was checked.
    pub largest_developability_error: Option<f64>,
}

impl CheckReport {
    /// A readable report: the summary, one numbered line per finding (at most
    /// [`TEXT_FINDINGS_PER_KIND`] per kind) and a final `PASS` or `FAIL` line. `unit_label`
    /// names the length unit ("mm", "units").
    pub fn to_text(&self, unit_label: &str) -> String {
        let mut out = String::new();
        self.write_summary(&mut out, unit_label);
        for kind in FindingKind::ALL {
            let mut of_kind = self
                .findings
                .iter()
                .enumerate()
                .filter(|(_, f)| f.kind == kind);
            for (i, f) in of_kind.by_ref().take(TEXT_FINDINGS_PER_KIND) {
                out.push_str(&finding_line(i + 1, f));
                out.push('\n');
            }
            let rest = of_kind.count();
            if rest > 0 {
                let _ = writeln!(out, "  … and {rest} more {} findings", kind.name());
            }
        }
        write_listed(&mut out, "warning ", &self.warnings, "warnings");
        write_listed(
            &mut out,
            "3D target ",
            &self.unchecked_faults,
            "at 3D targets",
        );
        out.push_str(&self.verdict());
        out.push('\n');
        out
    }

    fn write_summary(&self, out: &mut String, unit: &str) {
        let s = &self.summary;
        let a = &s.assignments;
        let _ = writeln!(
            out,
            "{} vertices, {} edges (B {}, M {}, V {}, F {}, U {}, C {}, J {})",
            s.vertices,
            s.edges,
            a.boundary,
            a.mountain,
            a.valley,
            a.flat,
            a.unassigned,
            a.cut,
            a.join
        );
        for run in &self.runs {
            let verdict = if run.ran { "ran" } else { "not run" };
            let _ = writeln!(out, "{:<17} {verdict}: {}", run.name, run.why);
        }
        if let Some(e) = &s.shortest_edge {
            let _ = writeln!(
                out,
                "shortest edge: {} ({:.4} {unit}) at {}",
                e.edge,
                e.value,
                fmt_point(e.position)
            );
        }
        if let Some(v) = &s.smallest_crease_angle {
            let _ = writeln!(
                out,
                "smallest crease angle: {:.3}° at {} {}",
                v.degrees,
                v.vertex,
                fmt_point(v.position)
            );
        }
        if let Some(e) = &s.largest_fold_angle {
            let _ = writeln!(
                out,
                "largest |fold angle|: {:.3}° on {}",
                e.value.abs(),
                e.edge
            );
        }
        out.push_str(&self.limits_line(unit));
    }

    fn limits_line(&self, unit: &str) -> String {
        let o = &self.options;
        let show = |v: Option<f64>, suffix: &str| match v {
            Some(v) => format!("{v}{suffix}"),
            None => "off".to_string(),
        };
        format!(
            "limits: Kawasaki tolerance {}°, min vertex angle {}, max fold angle {}, min edge {}\n",
            o.kawasaki_tolerance_deg,
            show(o.min_vertex_angle_deg, "°"),
            show(o.max_fold_angle_deg, "°"),
            show(o.min_edge_length, &format!(" {unit}")),
        )
    }

    /// The final line: `PASS (checked: …)`, `PASS, but NOT CHECKED at …` when some interior
    /// vertices' folding was not judged ([`CheckReport::checked_folding`]), or `FAIL: …`.
    pub fn verdict(&self) -> String {
        let unchecked = self.not_checked();
        if !self.passed() {
            let counts: Vec<String> = FindingKind::ALL
                .iter()
                .filter_map(|&k| {
                    let n = self.of_kind(k).count();
                    (n > 0).then(|| format!("{} {n}", k.name()))
                })
                .collect();
            let tail = unchecked.map_or(String::new(), |u| format!("; NOT CHECKED at {u}"));
            return format!(
                "FAIL: {} findings ({}){}{tail}",
                self.findings.len(),
                counts.join(", "),
                self.tolerance_note()
            );
        }
        let ran = self.ran_list();
        let warned = match self.warnings.len() {
            0 => String::new(),
            n => format!(" with {n} warning(s)"),
        };
        match unchecked {
            Some(u) => {
                let ran = ran.replace("checked: nothing applied", "nothing else was checked");
                format!("PASS{warned}, but NOT CHECKED at {u}; {ran}")
            }
            None => format!("PASS{warned} ({ran})"),
        }
    }

    /// The --kawasaki-tolerance that accepts every Kawasaki finding (all measured in degrees,
    /// within the option's range): offered as the drawing's precision up to
    /// [`ROUNDING_SIZED_DEG`], named as more than rounding beyond it; else nothing.
    fn tolerance_note(&self) -> String {
        let mut errors = self
            .of_kind(FindingKind::Kawasaki)
            .map(|f| match f.quantity {
                Quantity::Degrees => Some(f.value),
                _ => None,
            });
        let Some(Some(first)) = errors.next() else {
            return String::new();
        };
        let worst = errors.try_fold(first, |w, e| e.map(|e| w.max(e)));
        let (Some(worst), Some(t)) = (worst, worst.and_then(accepting_tolerance)) else {
            return String::new();
        };
        if worst <= ROUNDING_SIZED_DEG {
            format!(
                "; if the drawing is only this precise, {} {t:.4} accepts every Kawasaki error \
                 (the largest {worst:.4}°)",
                KAWASAKI_TOLERANCE.option
            )
        } else {
            format!(
                "; the Kawasaki errors reach {worst:.4}°, more than a drawing's rounding ({} \
                 {t:.4} would accept them all)",
                KAWASAKI_TOLERANCE.option
            )
        }
    }

    /// `checked: name (count), …` over the families that ran, or `checked: nothing applied`.
    fn ran_list(&self) -> String {
        let ran: Vec<String> = (self.runs.iter())
            .filter(|r| r.ran)
            .map(|r| format!("{} ({})", r.name, r.count))
            .collect();
        if ran.is_empty() {
            "checked: nothing applied".to_string()
        } else {
            format!("checked: {}", ran.join(", "))
        }
    }

    /// `N of M interior vertices: …why…` when some vertices' folding was not judged.
    fn not_checked(&self) -> Option<String> {
        if self.checked_folding() {
            return None;
        }
        let s = &self.summary;
        let interior = s.interior_vertices_checked + s.vertices_3d;
        let faults = match self.unchecked_faults.len() {
            0 => String::new(),
            n => format!(
                "; the \"3D target\" lines list {n} Kawasaki or Maekawa fault(s) there, no \
                 failure for a 3D target, a failure if it were to fold flat"
            ),
        };
        let flat_anyway = match s.vertices_3d_flat {
            0 => String::new(),
            n if n == self.unchecked_vertices => "; Kawasaki and Maekawa hold there all the \
                                                  same (the creases fold flat; the 3D form is \
                                                  not checked)"
                .to_string(),
            n => format!(
                "; Kawasaki and Maekawa hold at {n} of them all the same (their creases fold \
                 flat; the 3D form is not checked)"
            ),
        };
        Some(format!(
            "{} of {interior} interior vertices: they are 3D targets (a crease folds to less \
             than 180°) and no 3D frame came to compare{flat_anyway}{faults}; a FOLD file with its \
             folded frame is checked, --allow-unchecked accepts this",
            self.unchecked_vertices
        ))
    }
}

/// Lists at most [`TEXT_FINDINGS_PER_KIND`] of `list`, each line after `prefix`, then how
/// many more (`… and N more {more}`).
fn write_listed(out: &mut String, prefix: &str, list: &[Finding], more: &str) {
    for (i, f) in list.iter().enumerate().take(TEXT_FINDINGS_PER_KIND) {
        let _ = writeln!(out, "{prefix}{}", finding_line(i + 1, f));
    }
    if list.len() > TEXT_FINDINGS_PER_KIND {
        let _ = writeln!(
            out,
            "  … and {} more {more}",
            list.len() - TEXT_FINDINGS_PER_KIND
        );
    }
}

/// One line: the finding's number (its place in the report's list, from 1: the number
/// `preview --check` writes beside its ring), kind, element, position, message, hint.
pub fn finding_line(number: usize, f: &Finding) -> String {
    let element = match (f.vertex, f.edge) {
        (Some(v), _) => v.to_string(),
        (None, Some(e)) => e.to_string(),
        (None, None) => "-".to_string(),
    };
    format!(
        "#{number:<3} {:<12} {:<8} at {}: {}; hint: {}",
        f.kind.name(),
        element,
        fmt_point(f.position),
        f.message,
        f.hint
    )
}

/// Half a unit in the last place [`fmt_point`] prints (three decimals): smaller values print
/// as zero.
const HALF_LAST_DIGIT: f64 = 5e-4;

fn fmt_point(p: DVec2) -> String {
    // Values that print as zero print without a sign.
    let clean = |x: f64| if x.abs() < HALF_LAST_DIGIT { 0.0 } else { x };
    format!("({:.3}, {:.3})", clean(p.x), clean(p.y))
}
