//! Planning an opened pattern for a machine and material, as `foldcam cut` and `foldcam plan`
//! do with the same options, and the plan as the front end draws it.

use glam::DVec2;
use serde::Serialize;

use super::document::Document;
use super::error::{Stage, StudioError};
use crate::fab::PlanSettings;
use crate::fab::{FabPlan, PlanStats};
use crate::machine::{MachineProfile, Material};
use crate::pattern::{CreasePattern, Scale};

/// What to plan for: the profiles (shipped or uploaded, never read from a path a request
/// names), the size and the plan overrides.
#[derive(Clone, Debug)]
pub struct PlanChoice {
    /// The machine.
    pub machine: MachineProfile,
    /// The material.
    pub material: Material,
    /// Longer side of the pattern in millimetres (as `--size`), for unitless patterns or to
    /// rescale; `None` keeps the file's size.
    pub size: Option<f64>,
    /// The overrides of `cut`'s options.
    pub settings: PlanSettings,
}

/// A plan with the profile and the pattern it was made from.
#[derive(Clone, Debug)]
pub struct Planned {
    /// The machine.
    pub machine: MachineProfile,
    /// The plan.
    pub plan: FabPlan,
    /// The cleaned, sized pattern (pattern millimetres).
    pub pattern: CreasePattern,
}

/// Plans `doc` as `foldcam cut DOC -m MACHINE -x MATERIAL [--size S] [options]` would; a
/// paper craft's edge numbers are marked as `foldcam papercraft DESIGN --job` marks them
/// (unless the settings choose an operation for flat lines).
///
/// # Errors
/// The message `foldcam cut` prints for the same input, naming the option for a setting out
/// of range.
pub fn plan_document(doc: &Document, choice: &PlanChoice) -> Result<Planned, StudioError> {
    let machine = choice.machine.clone();
    let material = &choice.material;
    let mut options = choice
        .settings
        .options(&machine, material)
        .map_err(|e| StudioError::named(Stage::Plan, e))?;
    // A paper craft's edge numbers are marked as `foldcam papercraft --job` marks them.
    if choice.settings.flat.is_none() && doc.design.as_ref().is_some_and(|d| d.labels) {
        crate::fab::mark_labels(&mut options, &machine, material);
    }
    let cleaned = doc.cleaned(false)?;
    let mut pattern = cleaned.pattern;
    if let Some(size) = choice.size {
        pattern
            .scale_to(Scale::Size(size))
            .map_err(|e| StudioError::about(Stage::Request, &doc.name, e))?;
    }
    pattern
        .require_millimetres()
        .map_err(|e| StudioError::about(Stage::Plan, &doc.name, e))?;
    let plan = crate::fab::plan(&pattern, &machine, material, &options)
        .map_err(|e| StudioError::about(Stage::Plan, &doc.name, e))?;
    Ok(Planned {
        machine,
        plan,
        pattern,
    })
}

/// One toolpath as drawn: its operation, layer colour and strokes (machine mm).
#[derive(Clone, Debug, Serialize)]
pub struct PathView {
    /// Operation name.
    pub op: &'static str,
    /// Layer colour of the operation (the colour of our SVG and LightBurn layers).
    pub colour: &'static str,
    /// Strokes, machine mm.
    pub strokes: Vec<Vec<[f64; 2]>>,
}

/// One job as drawn.
#[derive(Clone, Debug, Serialize)]
pub struct JobView {
    /// `front` or `back`.
    pub name: String,
    /// Toolpaths in execution order.
    pub paths: Vec<PathView>,
    /// Tool-off moves between consecutive strokes, each `[x0, y0, x1, y1]`, machine mm.
    pub travel: Vec<[f64; 4]>,
    /// The sheet's pattern edges placed on the bed, each `[x0, y0, x1, y1]`, machine mm.
    pub sheet: Vec<[f64; 4]>,
}

/// The plan as the front end draws it.
#[derive(Clone, Debug, Serialize)]
pub struct PlanView {
    /// Machine name.
    pub machine: String,
    /// Bed width and depth, mm.
    pub bed: [f64; 2],
    /// True when machine +y points down the drawing.
    pub y_flipped: bool,
    /// True when the machine takes G-code (else DXF/SVG/LightBurn only).
    pub gcode: bool,
    /// Jobs.
    pub jobs: Vec<JobView>,
    /// Lengths per operation, pierces, travel and time.
    pub stats: PlanStats,
    /// The plan's remarks, each with its kind and the pattern edges it is about.
    pub warnings: Vec<crate::fab::PlanWarning>,
}

impl PlanView {
    /// The view of a plan.
    pub fn new(p: &Planned) -> PlanView {
        let m = &p.machine;
        let jobs = p
            .plan
            .jobs
            .iter()
            .map(|job| {
                let pt = |q: &DVec2| [q.x, q.y];
                let mut travel = Vec::new();
                let mut last: Option<DVec2> = None;
                for stroke in job.paths.iter().flat_map(|t| &t.strokes) {
                    if let (Some(a), Some(b)) = (last, stroke.first())
                        && a != *b
                    {
                        travel.push([a.x, a.y, b.x, b.y]);
                    }
                    last = stroke.last().copied().or(last);
                }
                let sheet = p
                    .pattern
                    .edges
                    .iter()
                    .map(|e| {
                        let a = job
                            .to_machine
                            .transform_point2(p.pattern.vertices[e.vertices[0].index()]);
                        let b = job
                            .to_machine
                            .transform_point2(p.pattern.vertices[e.vertices[1].index()]);
                        [a.x, a.y, b.x, b.y]
                    })
                    .collect();
                JobView {
                    name: job.name.clone(),
                    paths: job
                        .paths
                        .iter()
                        .map(|t| PathView {
                            op: t.op.name(),
                            colour: crate::post::layer_style(t.op).hex,
                            strokes: t
                                .strokes
                                .iter()
                                .map(|s| s.iter().map(pt).collect())
                                .collect(),
                        })
                        .collect(),
                    travel,
                    sheet,
                }
            })
            .collect();
        PlanView {
            machine: m.name.clone(),
            bed: [m.bed.width_mm, m.bed.height_mm],
            y_flipped: m.bed.y_flipped,
            gcode: m.emits_gcode(),
            jobs,
            stats: p.plan.stats.clone(),
            warnings: p.plan.warnings.clone(),
        }
    }
}
