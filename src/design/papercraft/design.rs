//! The design file (TOML): what the user did in the thesis's interface — the cut lines'
//! points (Ōgaki 2016, §3.2 Step 1), each patch's loop of cut lines and its directrix control points and
//! ruling direction (Step 2) — plus the making parameters. [`Design::build`] runs the whole
//! chain: network, walls, trimming, parts with tabs, packing, one pattern per sheet.
//!
//! ```toml
//! mesh = "vase.obj"        # reference mesh, relative to the design file
//! scale = 1.0              # millimetres per mesh unit
//! wall_length = 15.0       # k of §3.4, mesh units
//! tolerance = 0.05         # real-boundary polyline tolerance, mesh units
//! label_height = 4.0       # edge-label digits, millimetres (0: no labels)
//! [sheet]                  # millimetres
//! width = 210.0
//! height = 297.0
//! [tabs]                   # millimetres, degrees
//! width = 6.0
//! angle = 45.0
//! [[cut_lines]]
//! points = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
//! [[patches]]
//! cut_lines = [0, 1, 2, 1]
//! directrix = [[...], ...] # at least 5 control points (degree 4)
//! ruling = [0.0, 0.0, 1.0]
//! [[auto_patches]]         # §3.5: generated to meet existing patches without a gap
//! cut_lines = [4, 5, 6, 1]
//! plane = { point = [0.0, 0.0, 0.0], normal = [1.0, 0.0, 0.0] }  # Step 1
//! from = [{ patch = 0, cut_line = 1 }]  # Step 2: P_exist and the wall between them
//! control_points = 9       # optional; by default chosen from the tolerance
//! extend = 15.0            # optional; default wall_length (§5.2.1's first limit)
//! ```
//!
//! Patches are numbered placed first, then automatic ones in file order; an automatic patch
//! grows from any patch numbered before it, so chains of them close a model ring by ring.

use glam::DVec3;
use serde::Deserialize;

use super::PapercraftError;
use super::bspline::BSpline;
use super::cut_line::CutLine;
use super::cylinder::CylinderPatch;
use super::labels::{add_labels, make_upright};
use super::layout::{Placement, SheetSpec, pack, sheet_pattern};
use super::neighbour::{Neighbour, NeighbourSpec, Plane, boundary_gap, neighbour_patch};
use super::network::Network;
use super::parts::{Part, TabStyle, add_tabs};
use super::trim::real_boundary;
use super::walls::Walls;
use crate::mesh::ReferenceMesh;
use crate::pattern::CreasePattern;

/// Default `merge` distance (mesh units): end points closer than 10⁻⁶ are typed-in copies of
/// one point.
const DEFAULT_MERGE: f64 = 1e-6;

/// Most cut lines, patches or points per list a design may hold.
pub const MAX_ITEMS: usize = 10_000;

/// A parsed design file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Design {
    /// Reference mesh path, relative to the design file.
    pub mesh: String,
    /// Millimetres per mesh unit.
    #[serde(default = "one")]
    pub scale: f64,
    /// Sweep length k of the boundary walls (mesh units).
    pub wall_length: f64,
    /// Real-boundary polyline tolerance (mesh units).
    pub tolerance: f64,
    /// End points closer than this are one network vertex (mesh units).
    #[serde(default = "small")]
    pub vertex_tolerance: f64,
    /// Height of the edge labels' digits, millimetres (default 4; 0 for none).
    #[serde(default = "four")]
    pub label_height: f64,
    /// Samples per cut-line segment for the patch directions n_p.
    #[serde(default = "eight")]
    pub samples: usize,
    /// Sheet size.
    pub sheet: SheetToml,
    /// Tab style.
    pub tabs: TabsToml,
    /// Cut lines.
    pub cut_lines: Vec<CutLineToml>,
    /// Placed patches.
    pub patches: Vec<PatchToml>,
    /// Automatically generated patches (§3.5), numbered after the placed ones.
    #[serde(default)]
    pub auto_patches: Vec<AutoPatchToml>,
}

fn one() -> f64 {
    1.0
}
fn small() -> f64 {
    DEFAULT_MERGE
}
fn eight() -> usize {
    8
}

/// `[sheet]`, millimetres.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SheetToml {
    /// Width.
    pub width: f64,
    /// Height.
    pub height: f64,
    /// Border (default 8).
    #[serde(default = "eight_f")]
    pub margin: f64,
    /// Gap between parts (default 4).
    #[serde(default = "four")]
    pub gap: f64,
}

fn eight_f() -> f64 {
    8.0
}
fn four() -> f64 {
    4.0
}

/// `[tabs]`, millimetres and degrees.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TabsToml {
    /// Width.
    pub width: f64,
    /// Slope of the ends, degrees.
    #[serde(default = "forty_five")]
    pub angle: f64,
    /// Longest root (default 40).
    #[serde(default = "forty")]
    pub max_length: f64,
}

fn forty_five() -> f64 {
    45.0
}
fn forty() -> f64 {
    40.0
}

/// `[[cut_lines]]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CutLineToml {
    /// Points the Catmull–Rom spline passes through.
    pub points: Vec<[f64; 3]>,
}

/// `[[patches]]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PatchToml {
    /// The cut lines round the patch, in order.
    pub cut_lines: Vec<usize>,
    /// Directrix control points (degree-4 B-spline).
    pub directrix: Vec<[f64; 3]>,
    /// Ruling direction.
    pub ruling: [f64; 3],
}

/// `[[auto_patches]]`: an automatically generated neighbouring patch (§3.5).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AutoPatchToml {
    /// The cut lines round the patch, in order.
    pub cut_lines: Vec<usize>,
    /// Step 1: the plane holding the directrix; its normal is the ruling direction.
    pub plane: PlaneToml,
    /// Step 2: the existing patches and the walls between them and this one.
    pub from: Vec<FromToml>,
    /// Control points of the fitted directrix (default: chosen from the tolerance).
    pub control_points: Option<usize>,
    /// Extension of the swept boundary at each end, mesh units (default: wall_length).
    pub extend: Option<f64>,
}

/// `plane = { point, normal }`, mesh units.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaneToml {
    /// A point on the plane.
    pub point: [f64; 3],
    /// Its normal.
    pub normal: [f64; 3],
}

/// `from = [{ patch, cut_line }]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FromToml {
    /// P_exist's index.
    pub patch: usize,
    /// The cut line between P_exist and the new patch.
    pub cut_line: usize,
}

/// How an automatic patch came out: its fit and the measured gaps to its P_exists.
#[derive(Clone, Debug, PartialEq)]
pub struct AutoReport {
    /// Patch index.
    pub patch: usize,
    /// Control points of the fitted directrix.
    pub control_points: usize,
    /// Largest distance of a swept boundary point from the directrix (mesh units).
    pub fit_residual: f64,
    /// `(P_exist, cut line, gap)`: the largest 3D distance between where the two patches
    /// cross the cut line's wall ribs, 64 ribs per cut-line segment (mesh units).
    pub gaps: Vec<(usize, usize, f64)>,
}

/// What [`Design::build`] makes.
#[derive(Clone, Debug)]
pub struct Made {
    /// Parts (one per patch), millimetres; their labels read upright as placed.
    pub parts: Vec<Part>,
    /// Where each part went.
    pub placements: Vec<Placement>,
    /// One crease pattern per sheet.
    pub sheets: Vec<CreasePattern>,
    /// One report per automatic patch.
    pub auto: Vec<AutoReport>,
    /// Shared cut lines whose label fits on neither or only one of their parts.
    pub unlabelled: Vec<usize>,
    /// Every cut line two parts share, with its length on each ([`super::parts::seams`]).
    pub seams: Vec<super::parts::Seam>,
    /// The patches, placed then automatic (mesh units).
    pub patches: Vec<CylinderPatch>,
}

/// Parses a design file.
pub fn parse_design(text: &str) -> Result<Design, PapercraftError> {
    let design: Design =
        toml::from_str(text).map_err(|e| PapercraftError::BadParameter(e.to_string()))?;
    if design.cut_lines.len() > MAX_ITEMS
        || design.patches.len() + design.auto_patches.len() > MAX_ITEMS
    {
        return Err(PapercraftError::BadParameter(format!(
            "more than {MAX_ITEMS} cut lines or patches"
        )));
    }
    let positive = |v: f64| v.is_finite() && v > 0.0;
    if !positive(design.scale) || !(1..=1000).contains(&design.samples) {
        return Err(PapercraftError::BadParameter(
            "scale must be > 0 and samples in 1..=1000".into(),
        ));
    }
    Ok(design)
}

fn points(list: &[[f64; 3]]) -> Result<Vec<DVec3>, PapercraftError> {
    if list.len() > MAX_ITEMS {
        return Err(PapercraftError::BadParameter(format!(
            "more than {MAX_ITEMS} points in a list"
        )));
    }
    Ok(list.iter().map(|&p| DVec3::from_array(p)).collect())
}

impl Design {
    /// The first steps of the chain: the cut lines (§3.2 Step 1), their network with the
    /// placed and automatic patches as faces (§3.3) and the boundary walls (§3.4).
    pub fn network_and_walls(
        &self,
        mesh: &ReferenceMesh,
    ) -> Result<(Network, Walls), PapercraftError> {
        let lines = self
            .cut_lines
            .iter()
            .enumerate()
            .map(|(i, c)| CutLine::new(i, points(&c.points)?))
            .collect::<Result<Vec<_>, _>>()?;
        let loops: Vec<Vec<usize>> = (self.patches.iter().map(|p| p.cut_lines.clone()))
            .chain(self.auto_patches.iter().map(|p| p.cut_lines.clone()))
            .collect();
        let network = Network::build(&lines, &loops, self.vertex_tolerance)?;
        let walls = Walls::build(mesh, &lines, &network, self.wall_length, self.samples)?;
        Ok((network, walls))
    }

    /// Runs the chain on the reference mesh.
    pub fn build(&self, mesh: &ReferenceMesh) -> Result<Made, PapercraftError> {
        let (network, walls) = self.network_and_walls(mesh)?;
        let patch_count = self.patches.len() + self.auto_patches.len();
        let mut parts = Vec::with_capacity(patch_count);
        let mut built = Vec::with_capacity(patch_count);
        for (p, spec) in self.patches.iter().enumerate() {
            let what = format!("patch {p} directrix");
            let ruling = DVec3::from_array(spec.ruling);
            if !ruling.is_finite() {
                return Err(PapercraftError::NonFinite {
                    what: format!("patch {p} ruling"),
                });
            }
            let patch =
                CylinderPatch::new(BSpline::directrix(points(&spec.directrix)?, &what)?, ruling)?;
            let boundary = real_boundary(mesh, &network, &walls, p, &patch, self.tolerance)?;
            parts.push(Part::from_boundary(p, &boundary, self.scale));
            built.push(patch);
        }
        let mut auto = Vec::with_capacity(self.auto_patches.len());
        for (i, spec) in self.auto_patches.iter().enumerate() {
            let p = self.patches.len() + i;
            let made = self.auto_patch(mesh, &network, &walls, &built, p, spec)?;
            let boundary = real_boundary(mesh, &network, &walls, p, &made.patch, self.tolerance)?;
            parts.push(Part::from_boundary(p, &boundary, self.scale));
            let gaps = spec
                .from
                .iter()
                .map(|f| {
                    let count = 64 * walls.segments(f.cut_line);
                    let gap = boundary_gap(
                        mesh,
                        &walls,
                        f.cut_line,
                        &built[f.patch],
                        &made.patch,
                        count,
                    )
                    .unwrap_or(f64::INFINITY);
                    (f.patch, f.cut_line, gap)
                })
                .collect();
            auto.push(AutoReport {
                patch: p,
                control_points: made.control_points,
                fit_residual: made.fit_residual,
                gaps,
            });
            built.push(made.patch);
        }
        let style = TabStyle {
            width: self.tabs.width,
            angle_deg: self.tabs.angle,
            max_length: self.tabs.max_length,
        };
        add_tabs(&mut parts, &network, &style)?;
        let seams = super::parts::seams(&parts);
        let spec = SheetSpec {
            width: self.sheet.width,
            height: self.sheet.height,
            margin: self.sheet.margin,
            gap: self.sheet.gap,
        };
        // Packed first (labels lie inside the outlines, so they do not change the packing),
        // so that every label can be written level on its sheet.
        let placements = pack(&parts, &spec)?;
        let mut angles = vec![0.0; parts.len()];
        for pl in &placements {
            if let Some(a) = angles.get_mut(pl.part) {
                *a = pl.angle;
            }
        }
        let unlabelled = add_labels(&mut parts, &network, self.label_height, &angles);
        for pl in &placements {
            make_upright(&mut parts[pl.part], pl.angle);
        }
        let count = placements.iter().map(|p| p.sheet + 1).max().unwrap_or(0);
        let sheets = (0..count)
            .map(|s| sheet_pattern(&parts, &placements, s))
            .collect();
        Ok(Made {
            parts,
            placements,
            sheets,
            auto,
            unlabelled,
            seams,
            patches: built,
        })
    }

    /// Generates automatic patch `p` from its spec (§3.5 Steps 1–3).
    fn auto_patch(
        &self,
        mesh: &ReferenceMesh,
        network: &Network,
        walls: &Walls,
        built: &[CylinderPatch],
        p: usize,
        spec: &AutoPatchToml,
    ) -> Result<Neighbour, PapercraftError> {
        let plane = Plane {
            point: DVec3::from_array(spec.plane.point),
            normal: DVec3::from_array(spec.plane.normal),
        };
        if !(plane.point.is_finite() && plane.normal.is_finite()) {
            return Err(PapercraftError::NonFinite {
                what: format!("patch {p} plane"),
            });
        }
        let spec = NeighbourSpec {
            plane,
            from: spec.from.iter().map(|f| (f.patch, f.cut_line)).collect(),
            control_points: spec.control_points,
            extend: spec.extend.unwrap_or(self.wall_length),
            samples: 4 * self.samples,
        };
        neighbour_patch(
            mesh,
            network,
            walls,
            |q| built.get(q),
            p,
            &spec,
            self.tolerance,
        )
    }
}
