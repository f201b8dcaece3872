//! The cut-line drawing of the studio's paper-craft editor: the maker draws cut lines on the
//! reference mesh (Ōgaki 2016, §3.2 Step 1: Catmull–Rom curves through clicked points) and
//! the patches follow from them.
//!
//! - [`snap_line`]: the clicked points projected onto the mesh, each end snapped onto an
//!   existing end point within a reach, so lines share the network's vertices (§3.3).
//! - [`regions`]: the regions the cut lines close on the surface. The thesis's user lists each
//!   patch's cut lines by hand; here the faces of the drawing are traced instead: at each
//!   vertex the cut lines leaving it are ordered by angle round the mesh normal, and each face
//!   is walked keeping it on the left (the next cut line is the one after the arriving one,
//!   clockwise). Cut lines with a loose end (after removing those repeatedly) bound no face.
//!   A face whose inside is off the mesh (stepping from its cut lines to the left leaves the
//!   surface) is a hole of an open mesh, not a patch.
//! - [`Sketch::evaluate`]: every region gets a patch — a placed patch of the design the
//!   drawing came from when it has the same cut lines, otherwise a cylinder fitted by
//!   [`super::autofit`] — patches that cannot be trimmed by their walls are reported and left
//!   out, and the rest is written as a design file ([`Sketch::design_text`]) and built by
//!   [`Design::build`], exactly as `foldcam papercraft` builds the saved file.

use std::fmt::Write as _;

use glam::{DVec2, DVec3};

use super::PapercraftError;
use super::autofit::{FittedPatch, fit_cylinder};
use super::cut_line::CutLine;
use super::design::{Design, Made, PatchToml, SheetToml, TabsToml, parse_design};
use super::network::Network;
use super::trim::real_boundary;
use super::walls::Walls;
use crate::mesh::ReferenceMesh;

/// End points closer than this (mesh units) are one vertex; snapped ends are exact copies.
pub const VERTEX_TOLERANCE: f64 = 1e-6;

/// Step taken to the left of a face's cut lines to see whether the face lies on the mesh, as
/// a share of the mesh's bounding-box diagonal.
pub const HOLE_STEP: f64 = 0.01;

/// Rounds of dropping untrimmable patches (each round's walls change with the patches kept).
const MAX_ROUNDS: usize = 4;

/// The making parameters of a design (everything but the cut lines and patches).
#[derive(Clone, Debug)]
pub struct SketchParams {
    /// Millimetres per mesh unit.
    pub scale: f64,
    /// Sweep length k of the walls (mesh units).
    pub wall_length: f64,
    /// Real-boundary tolerance (mesh units).
    pub tolerance: f64,
    /// Edge-label digit height, millimetres.
    pub label_height: f64,
    /// Sheet, millimetres.
    pub sheet: SheetToml,
    /// Tabs, millimetres and degrees.
    pub tabs: TabsToml,
}

impl SketchParams {
    /// Parameters for a mesh of bounding-box diagonal `diagonal` (mesh units, read as
    /// millimetres): walls a tenth of it, A4 sheets, 5 mm tabs.
    pub fn for_diagonal(diagonal: f64) -> SketchParams {
        SketchParams {
            scale: 1.0,
            wall_length: 0.1 * diagonal,
            tolerance: 0.05,
            label_height: 3.0,
            sheet: SheetToml {
                width: 210.0,
                height: 297.0,
                margin: 8.0,
                gap: 4.0,
            },
            tabs: TabsToml {
                width: 5.0,
                angle: 45.0,
                max_length: 25.0,
            },
        }
    }
}

/// A drawing: the mesh's name, the parameters, the cut lines and the placed patches kept from
/// the design it was opened from.
#[derive(Clone, Debug)]
pub struct Sketch {
    /// The mesh file's name, as the design file names it.
    pub mesh_name: String,
    /// Making parameters.
    pub params: SketchParams,
    /// Cut lines: the points each passes through, on the mesh.
    pub lines: Vec<Vec<DVec3>>,
    /// Placed patches of the opened design (kept while their cut lines are).
    pub placed: Vec<PatchToml>,
}

/// One region of the drawing and what became of it.
#[derive(Clone, Debug, PartialEq)]
pub struct RegionReport {
    /// Its cut lines in order round it.
    pub lines: Vec<usize>,
    /// The patch number it has in the design, when it has one.
    pub patch: Option<usize>,
    /// The fitted cylinder's residual (mesh units); `None` for a placed patch.
    pub residual: Option<f64>,
    /// Why it has no patch.
    pub error: Option<String>,
}

/// What [`Sketch::evaluate`] gives.
#[derive(Clone, Debug)]
pub struct Evaluation {
    /// The design file of the drawing (as saved).
    pub text: String,
    /// Every region closed by the cut lines.
    pub regions: Vec<RegionReport>,
    /// Holes of the mesh bounded by cut lines (each its cut lines).
    pub holes: Vec<Vec<usize>>,
    /// Cut lines with a loose end, bounding no region.
    pub open: Vec<usize>,
    /// The built design, or why it failed.
    pub made: Result<Made, PapercraftError>,
    /// Parts (by index) whose unrolled outline crosses itself.
    pub self_overlapping: Vec<usize>,
}

/// Projects `clicked` onto `mesh` and snaps each end onto the nearest end point of `existing`
/// within `reach` (mesh units); the end also snaps onto the line's own start (a closed cut
/// line) when that is within reach and the line has at least 3 points.
///
/// # Errors
/// Fewer than 2 points, a non-finite point, or a line that collapses to one point.
pub fn snap_line(
    mesh: &ReferenceMesh,
    existing: &[Vec<DVec3>],
    clicked: &[DVec3],
    reach: f64,
) -> Result<Vec<DVec3>, PapercraftError> {
    let index = existing.len();
    CutLine::new(index, clicked.to_vec())?;
    let ends: Vec<DVec3> = existing
        .iter()
        .flat_map(|l| [l[0], l[l.len() - 1]])
        .collect();
    let snap = |p: DVec3| {
        ends.iter()
            .copied()
            .filter(|e| e.distance(p) <= reach)
            .min_by(|a, b| a.distance(p).total_cmp(&b.distance(p)))
    };
    let mut points: Vec<DVec3> = clicked.iter().map(|&p| mesh.project(p).point).collect();
    let n = points.len();
    if let Some(e) = snap(points[0]) {
        points[0] = e;
    }
    if let Some(e) = snap(points[n - 1]) {
        points[n - 1] = e;
    } else if n >= 3 && points[n - 1].distance(points[0]) <= reach {
        points[n - 1] = points[0];
    }
    points.dedup_by(|a, b| a.distance(*b) <= VERTEX_TOLERANCE);
    if points.len() < 2 || (points.len() == 2 && points[0] == points[1]) {
        return Err(PapercraftError::ShortCutLine {
            line: index,
            points: points.len().min(1),
        });
    }
    Ok(points)
}

/// The faces of a drawing.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Regions {
    /// Regions on the mesh: their cut lines in order round each.
    pub loops: Vec<Vec<usize>>,
    /// The same regions as half-edges (`2e` along cut line e, `2e + 1` against it), each
    /// region on the left of its half-edges seen from outside.
    pub sides: Vec<Vec<usize>>,
    /// Holes of an open mesh bounded by cut lines.
    pub holes: Vec<Vec<usize>>,
    /// Cut lines with a loose end.
    pub open: Vec<usize>,
}

/// Traces the faces of the cut lines `lines` on `mesh` (see the module text).
pub fn regions(mesh: &ReferenceMesh, lines: &[CutLine]) -> Regions {
    let (vertex_count, ends) = merge_ends(lines);
    let mut alive = vec![true; lines.len()];
    loop {
        let mut degree = vec![0usize; vertex_count];
        for (e, [a, b]) in ends.iter().enumerate() {
            if alive[e] {
                degree[*a] += 1;
                degree[*b] += 1;
            }
        }
        let loose: Vec<usize> = (0..lines.len())
            .filter(|&e| alive[e] && ends[e].iter().any(|&v| degree[v] < 2))
            .collect();
        if loose.is_empty() {
            break;
        }
        loose.into_iter().for_each(|e| alive[e] = false);
    }
    let open: Vec<usize> = (0..lines.len()).filter(|&e| !alive[e]).collect();
    // Half-edge h = 2e runs along cut line e, h = 2e + 1 against it.
    let origin = |h: usize| ends[h / 2][h % 2];
    let mut around: Vec<Vec<(f64, usize)>> = vec![Vec::new(); vertex_count];
    for (e, line) in lines.iter().enumerate().filter(|(e, _)| alive[*e]) {
        let segs = line.segments() as f64;
        for (h, from, toward) in [
            (2 * e, line.start(), line.at(0.25f64.min(segs))),
            (2 * e + 1, line.end(), line.at((segs - 0.25).max(0.0))),
        ] {
            let n = mesh.project(from).normal;
            let x = n.any_orthonormal_vector();
            let y = n.cross(x);
            let d = toward - from;
            around[origin(h)].push((d.dot(y).atan2(d.dot(x)), h));
        }
    }
    for list in &mut around {
        list.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    let next = |h: usize| {
        let twin = h ^ 1;
        let list = &around[origin(twin)];
        let i = list.iter().position(|&(_, x)| x == twin).unwrap_or(0);
        list[(i + list.len() - 1) % list.len()].1
    };
    let diagonal = mesh_diagonal(mesh);
    let mut seen = vec![false; 2 * lines.len()];
    let mut out = Regions {
        open,
        ..Regions::default()
    };
    for start in (0..2 * lines.len()).filter(|h| alive[h / 2]) {
        if seen[start] {
            continue;
        }
        let mut face = Vec::new();
        let mut h = start;
        while !seen[h] {
            seen[h] = true;
            face.push(h);
            h = next(h);
        }
        let off = face
            .iter()
            .filter(|&&h| left_is_off_mesh(mesh, &lines[h / 2], h % 2 == 1, diagonal))
            .count();
        let cut_lines = face.iter().map(|h| h / 2).collect();
        if 2 * off > face.len() {
            out.holes.push(cut_lines);
        } else {
            out.loops.push(cut_lines);
            out.sides.push(face);
        }
    }
    out
}

/// Network vertex count and each line's `[start, end]` vertex, merging ends within
/// [`VERTEX_TOLERANCE`].
fn merge_ends(lines: &[CutLine]) -> (usize, Vec<[usize; 2]>) {
    let mut vertices: Vec<DVec3> = Vec::new();
    let mut find = |p: DVec3| {
        if let Some(v) = vertices
            .iter()
            .position(|q| q.distance(p) <= VERTEX_TOLERANCE)
        {
            v
        } else {
            vertices.push(p);
            vertices.len() - 1
        }
    };
    let ends = lines
        .iter()
        .map(|l| [find(l.start()), find(l.end())])
        .collect();
    (vertices.len(), ends)
}

pub(super) fn mesh_diagonal(mesh: &ReferenceMesh) -> f64 {
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for t in 0..mesh.triangle_count() {
        for p in mesh.triangle(t) {
            lo = lo.min(p);
            hi = hi.max(p);
        }
    }
    (hi - lo).length()
}

/// Whether the point a [`HOLE_STEP`] to the left of the middle of `line` (walked backwards
/// when `reversed`) is off the mesh: its closest mesh point is farther than half the step.
fn left_is_off_mesh(mesh: &ReferenceMesh, line: &CutLine, reversed: bool, diagonal: f64) -> bool {
    let step = HOLE_STEP * diagonal;
    let Some(p) = left_of(mesh, line, reversed, step) else {
        return false;
    };
    mesh.project(p).distance > 0.5 * step
}

/// The point `step` (mesh units) to the left of the middle of `line` in the tangent plane
/// (walked backwards when `reversed`); `None` where the line has no direction.
pub(super) fn left_of(
    mesh: &ReferenceMesh,
    line: &CutLine,
    reversed: bool,
    step: f64,
) -> Option<DVec3> {
    let segs = line.segments() as f64;
    let mid = segs / 2.0;
    let here = mesh.project(line.at(mid));
    let delta = (segs * 0.01).min(mid);
    let mut d = line.at(mid + delta) - line.at(mid - delta);
    if reversed {
        d = -d;
    }
    let left = here.normal.cross(d).try_normalize()?;
    Some(here.point + left * step)
}

impl Sketch {
    /// A drawing of the design `design` (its cut lines, placed patches and parameters; its
    /// automatic patches are fitted again like any region).
    pub fn from_design(design: &Design) -> Sketch {
        Sketch {
            mesh_name: design.mesh.clone(),
            params: SketchParams {
                scale: design.scale,
                wall_length: design.wall_length,
                tolerance: design.tolerance,
                label_height: design.label_height,
                sheet: design.sheet.clone(),
                tabs: design.tabs.clone(),
            },
            lines: (design.cut_lines.iter())
                .map(|c| c.points.iter().map(|&p| DVec3::from_array(p)).collect())
                .collect(),
            placed: design.patches.clone(),
        }
    }

    /// Removes cut line `index`, the placed patches that use it, and renumbers the rest.
    ///
    /// # Errors
    /// When there is no such cut line.
    pub fn remove_line(&mut self, index: usize) -> Result<(), PapercraftError> {
        if index >= self.lines.len() {
            return Err(PapercraftError::BadParameter(format!(
                "cut line {index} does not exist ({} cut lines)",
                self.lines.len()
            )));
        }
        self.lines.remove(index);
        self.placed.retain(|p| !p.cut_lines.contains(&index));
        for p in &mut self.placed {
            p.cut_lines
                .iter_mut()
                .filter(|e| **e > index)
                .for_each(|e| *e -= 1);
        }
        Ok(())
    }

    /// The cut lines as [`CutLine`]s.
    ///
    /// # Errors
    /// A line with fewer than 2 or non-finite points.
    pub fn cut_lines(&self) -> Result<Vec<CutLine>, PapercraftError> {
        (self.lines.iter().enumerate())
            .map(|(i, l)| CutLine::new(i, l.clone()))
            .collect()
    }

    /// The design file holding the cut lines and `patches` (each its loop and cylinder).
    pub fn design_text(&self, patches: &[(Vec<usize>, Vec<DVec3>, DVec3)]) -> String {
        let p = &self.params;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "# Paper craft (Ōgaki 2016) drawn in the foldcam studio: cut lines through clicked\n\
             # points; patches placed or fitted as cylinders. Build: foldcam papercraft FILE -o parts.svg"
        );
        let _ = writeln!(s, "mesh = {}", toml::Value::from(self.mesh_name.as_str()));
        let _ = writeln!(s, "scale = {:?}", p.scale);
        let _ = writeln!(s, "wall_length = {:?}", p.wall_length);
        let _ = writeln!(s, "tolerance = {:?}", p.tolerance);
        let _ = writeln!(s, "vertex_tolerance = {VERTEX_TOLERANCE:?}");
        let _ = writeln!(s, "label_height = {:?}", p.label_height);
        if self.lines.is_empty() {
            let _ = writeln!(s, "cut_lines = []");
        }
        if patches.is_empty() {
            let _ = writeln!(s, "patches = []");
        }
        let sh = &p.sheet;
        let _ = writeln!(
            s,
            "\n[sheet]\nwidth = {:?}\nheight = {:?}\nmargin = {:?}\ngap = {:?}",
            sh.width, sh.height, sh.margin, sh.gap
        );
        let t = &p.tabs;
        let _ = writeln!(
            s,
            "\n[tabs]\nwidth = {:?}\nangle = {:?}\nmax_length = {:?}",
            t.width, t.angle, t.max_length
        );
        for (i, line) in self.lines.iter().enumerate() {
            let _ = writeln!(s, "\n[[cut_lines]] # {i}\npoints = {}", point_list(line));
        }
        for (i, (lines, directrix, ruling)) in patches.iter().enumerate() {
            let _ = writeln!(
                s,
                "\n[[patches]] # {i}\ncut_lines = {lines:?}\ndirectrix = {}\nruling = {}",
                point_list(directrix),
                point(*ruling)
            );
        }
        s
    }

    /// Traces the regions, gives each a patch, drops those their walls cannot trim, writes
    /// the design and builds it (see the module text).
    ///
    /// # Errors
    /// A cut line that is not valid (fewer than 2 or non-finite points).
    pub fn evaluate(&self, mesh: &ReferenceMesh) -> Result<Evaluation, PapercraftError> {
        let lines = self.cut_lines()?;
        let found = regions(mesh, &lines);
        let mut reports: Vec<RegionReport> = Vec::with_capacity(found.loops.len());
        let mut cylinders: Vec<Option<(Vec<DVec3>, DVec3)>> = Vec::new();
        for (r, lp) in found.loops.iter().enumerate() {
            let mut report = RegionReport {
                lines: lp.clone(),
                patch: None,
                residual: None,
                error: None,
            };
            let placed = self.placed.iter().find(|p| same_lines(&p.cut_lines, lp));
            let cylinder = if let Some(p) = placed {
                let directrix = p.directrix.iter().map(|&q| DVec3::from_array(q)).collect();
                Some((directrix, DVec3::from_array(p.ruling)))
            } else {
                let refs: Vec<&CutLine> = lp.iter().map(|&e| &lines[e]).collect();
                match fit_cylinder(mesh, &refs, self.params.wall_length, r) {
                    Ok(FittedPatch {
                        directrix,
                        ruling,
                        residual,
                    }) => {
                        report.residual = Some(residual);
                        Some((directrix, ruling))
                    }
                    Err(e) => {
                        report.error = Some(e.to_string());
                        None
                    }
                }
            };
            reports.push(report);
            cylinders.push(cylinder);
        }
        // Drop the regions whose patch misses a wall, until the kept ones all trim.
        for _ in 0..MAX_ROUNDS {
            let kept: Vec<usize> = (0..reports.len())
                .filter(|&r| cylinders[r].is_some())
                .collect();
            let failures = self.untrimmable(mesh, &lines, &found.loops, &kept, &cylinders);
            if failures.is_empty() {
                break;
            }
            for (r, message) in failures {
                reports[r].error = Some(message);
                cylinders[r] = None;
            }
        }
        let mut patches = Vec::new();
        for (r, report) in reports.iter_mut().enumerate() {
            if let Some((directrix, ruling)) = &cylinders[r] {
                report.patch = Some(patches.len());
                patches.push((report.lines.clone(), directrix.clone(), *ruling));
            }
        }
        let text = self.design_text(&patches);
        let made = parse_design(&text).and_then(|d| d.build(mesh));
        let self_overlapping = match &made {
            Ok(m) => (m.parts.iter().enumerate())
                .filter(|(_, p)| outline_crosses_itself(&p.outline))
                .map(|(i, _)| i)
                .collect(),
            Err(_) => Vec::new(),
        };
        Ok(Evaluation {
            text,
            regions: reports,
            holes: found.holes,
            open: found.open,
            made,
            self_overlapping,
        })
    }

    /// The regions (of `kept`) whose patch cannot be trimmed by its walls, with the reason,
    /// patches numbered in `kept` order; every region of `kept` when the network itself
    /// cannot be built.
    fn untrimmable(
        &self,
        mesh: &ReferenceMesh,
        lines: &[CutLine],
        loops: &[Vec<usize>],
        kept: &[usize],
        cylinders: &[Option<(Vec<DVec3>, DVec3)>],
    ) -> Vec<(usize, String)> {
        let kept_loops: Vec<Vec<usize>> = kept.iter().map(|&r| loops[r].clone()).collect();
        let walls = Network::build(lines, &kept_loops, VERTEX_TOLERANCE).and_then(|network| {
            let walls = Walls::build(
                mesh,
                lines,
                &network,
                self.params.wall_length,
                super::autofit::SAMPLES_PER_SEGMENT,
            )?;
            Ok((network, walls))
        });
        let (network, walls) = match walls {
            Ok(x) => x,
            Err(e) => return kept.iter().map(|&r| (r, e.to_string())).collect(),
        };
        let mut out = Vec::new();
        for (p, &r) in kept.iter().enumerate() {
            let Some((directrix, ruling)) = &cylinders[r] else {
                continue;
            };
            let patch = super::bspline::BSpline::directrix(directrix.clone(), "directrix")
                .and_then(|d| super::cylinder::CylinderPatch::new(d, *ruling))
                .and_then(|c| real_boundary(mesh, &network, &walls, p, &c, self.params.tolerance));
            if let Err(e) = patch {
                out.push((r, e.to_string()));
            }
        }
        out
    }
}

/// Whether two loops hold the same cut lines (as multisets).
fn same_lines(a: &[usize], b: &[usize]) -> bool {
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    a.sort_unstable();
    b.sort_unstable();
    a == b
}

fn point(p: DVec3) -> String {
    format!("[{:?}, {:?}, {:?}]", p.x, p.y, p.z)
}

fn point_list(points: &[DVec3]) -> String {
    let items: Vec<String> = points.iter().map(|&p| point(p)).collect();
    format!("[{}]", items.join(", "))
}

/// Whether two non-adjacent sides of the closed polygon `outline` cross (proper crossings
/// only: touching at a point is not counted).
pub fn outline_crosses_itself(outline: &[DVec2]) -> bool {
    let n = outline.len();
    let side = |i: usize| (outline[i], outline[(i + 1) % n]);
    let orient = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a);
    (0..n).any(|i| {
        (i + 2..n).any(|j| {
            if i == 0 && j == n - 1 {
                return false;
            }
            let ((a, b), (c, d)) = (side(i), side(j));
            let (o1, o2) = (orient(a, b, c), orient(a, b, d));
            let (o3, o4) = (orient(c, d, a), orient(c, d, b));
            o1 * o2 < 0.0 && o3 * o4 < 0.0
        })
    })
}

#[cfg(test)]
#[path = "sketch_tests.rs"]
mod tests;
