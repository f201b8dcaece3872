//! The fabrication plan: what the machine does to each line of a crease pattern.
//!
//! Data flows `CreasePattern` → [`plan()`] → [`FabPlan`] (jobs of ordered toolpaths in
//! machine coordinates) → `post` writers and the `sim` machine. The stages, one module each:
//! [`operations`] (assignment → operation), [`creases`] and [`lines`] (chaining edges),
//! [`perforation`] (dashes per crease with vertex clearances), [`contours`], [`kerf`] and
//! [`tabs`] (cut contours, offsets, tabs, lead-ins), [`geometry`] (all of those together),
//! [`placement`] and [`sides`] (bed placement, two-sided jobs, registration marks), [`order`](mod@order)
//! (precedence and travel), [`stats`], and [`plan`](mod@plan) (the whole pipeline).

pub(crate) mod contours;
pub(crate) mod creases;
pub(crate) mod frame;
pub(crate) mod geometry;
pub(crate) mod kerf;
pub(crate) mod lines;
pub(crate) mod operations;
mod options;
pub(crate) mod order;
pub(crate) mod perforation;
pub(crate) mod placement;
pub(crate) mod plan;
pub(crate) mod settings;
pub(crate) mod sides;
pub(crate) mod stats;
pub(crate) mod tabs;
pub mod testgrid;
pub(crate) mod timing;
pub(crate) mod warning;

pub use frame::bounds;
pub use geometry::{toolpaths, toolpaths_with_warnings};
pub use operations::{label_operation, mark_labels};
pub use options::{DEFAULT_MARGIN_MM, DEFAULT_TAB_SPACING_MM, PlanOverrides};
pub use order::{order, ranks, travel_mm};
pub use placement::{Placement, bed_to_machine, bounds_of, place};
pub use plan::plan;
pub use plan::{design_limit_warnings, plan_toolpaths};
pub use settings::{PlanSettings, parse_offset};
pub use sides::{mirror, registration_marks, split};
pub use warning::{PlanWarning, PlanWarningKind};

use glam::{DAffine2, DVec2};
use serde::Serialize;

pub use crate::machine::Operation;
use crate::machine::{MachineProfile, OperationSettings, SettingsByOperation};
use crate::pattern::EdgeId;

/// What a closed or open cut line is, for ordering and kerf.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ContourRole {
    /// Not a cut contour (creases, marks).
    None,
    /// An open slit (cut edges that do not close): never offset.
    Slit,
    /// A closed contour around a hole: offset inward into the hole, cut before its container.
    Hole,
    /// A closed outer contour: offset outward, cut last.
    Outer,
}

/// One toolpath: one or more strokes of one operation, each a polyline burned from its first
/// point to its last with the tool on; the tool is off between strokes.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Toolpath {
    /// The operation.
    pub op: Operation,
    /// The burns, in order. Coordinates are machine coordinates, mm.
    pub strokes: Vec<Vec<DVec2>>,
    /// Cut contour role.
    pub role: ContourRole,
    /// Index (in the job's `paths`) of the contour directly around this one (for holes, and
    /// for islands inside holes), if any: it must be cut after this one.
    pub container: Option<usize>,
    /// The pattern edges this toolpath realises (for coverage checks).
    pub edges: Vec<EdgeId>,
}

/// Which face of the sheet faces the tool.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    /// The pattern as drawn faces up.
    Front,
    /// The sheet turned over (mirrored about a vertical axis).
    Back,
}

/// One setup: what the machine does without the sheet being turned (a one-sided job has one,
/// a two-sided job a front and a back; [`crate::job::Job`] posts and checks each).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Setup {
    /// Name for files and messages, e.g. `front`.
    pub name: String,
    /// Which side faces the tool.
    pub side: Side,
    /// Pattern millimetres → machine coordinates (placement on the bed, y flip, mirroring).
    #[serde(skip)]
    pub to_machine: DAffine2,
    /// Toolpaths in execution order.
    pub paths: Vec<Toolpath>,
}

/// Totals of a plan, for `foldcam plan` and reports.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PlanStats {
    /// Burn length per operation, mm.
    pub length_mm: Vec<(Operation, f64)>,
    /// Number of tool-on events.
    pub pierces: usize,
    /// Travel (tool off) length, mm, in the planned order.
    pub travel_mm: f64,
    /// Travel length of the unoptimised order, mm (for comparison).
    pub naive_travel_mm: f64,
    /// Estimated job time, seconds (all jobs).
    pub time_s: f64,
    /// Length of the creases the mapping perforates, mm (0 when none is).
    pub crease_mm: f64,
    /// Length of their perforation dashes (toolpaths, each once), mm.
    pub perforated_mm: f64,
}

impl PlanStats {
    /// The share of the perforated creases' length that their dashes cut (toolpath length,
    /// so a little less than the burnt length with kerf compensation), or `None` when the plan
    /// perforates nothing.
    pub fn perforated_share(&self) -> Option<f64> {
        (self.crease_mm > 0.0).then(|| self.perforated_mm / self.crease_mm)
    }
}

/// The fabrication plan.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FabPlan {
    /// One job, or two for two-sided work (front, then back).
    pub jobs: Vec<Setup>,
    /// Speed, power and passes per operation.
    pub settings: SettingsByOperation,
    /// Totals.
    pub stats: PlanStats,
    /// Remarks (skipped edges, vertex-angle warnings, …), each with the edges it is about.
    pub warnings: Vec<PlanWarning>,
    /// The operation per assignment the plan was made with: every edge it maps to an
    /// operation should be realised by some toolpath of some job (the coverage check counts
    /// the ones that are not, such as creases left without a dash).
    pub mapping: crate::machine::OperationMapping,
    /// Settings of their own for some edges' toolpaths (the cells of a calibration grid,
    /// [`testgrid`]); empty for an ordinary plan. Writers give each entry a layer of its own.
    pub overrides: Vec<SettingsOverride>,
    /// Where the plan came from, for the files' headers.
    pub about: PlanAbout,
}

/// What a plan's files say about it in their headers: the source and the material.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PlanAbout {
    /// The pattern's name: its title (a generator's or design's, or the file's own title);
    /// `None` when the pattern has none.
    pub source: Option<String>,
    /// The material profile's name.
    pub material: String,
    /// Perforation dash length the plan was made with, mm.
    pub dash_mm: f64,
    /// Perforation bridge (the gap between dashes), mm.
    pub bridge_mm: f64,
}

/// Speed, power and passes of their own for the toolpaths of some edges, instead of their
/// operation's.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SettingsOverride {
    /// Short name for layers and messages (letters, digits, `-`, `_` and `.`), e.g. `cell-4`.
    pub name: String,
    /// The pattern edges whose toolpaths run with these settings (a toolpath belongs to the
    /// entry holding its first edge).
    pub edges: Vec<EdgeId>,
    /// The settings (used as they are, also on a plotter).
    pub settings: OperationSettings,
}

impl FabPlan {
    /// The index in [`FabPlan::overrides`] of the entry `path` runs with, if any.
    pub fn override_of(&self, path: &Toolpath) -> Option<usize> {
        let first = path.edges.first()?;
        self.overrides.iter().position(|o| o.edges.contains(first))
    }

    /// The speed, power and passes `path` runs with on `machine`: its override's, or its
    /// operation's as the machine takes them ([`MachineProfile::settings_for`]: a plotter
    /// draws everything at the `plot` settings).
    pub fn settings_of(&self, path: &Toolpath, machine: &MachineProfile) -> OperationSettings {
        match self.override_of(path) {
            Some(i) => self.overrides[i].settings,
            None => machine.settings_for(&self.settings, path.op),
        }
    }
}

/// Holding tabs: short uncut gaps left in closed contours so parts stay in the sheet.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Tabs {
    /// Gap length, mm.
    pub width_mm: f64,
    /// Roughly one tab per this much contour length, at least one per contour, mm.
    pub spacing_mm: f64,
}

/// How to plan: every choice a user may change, resolved (material defaults overridden by
/// the command line).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PlanOptions {
    /// Operation per assignment.
    pub mapping: crate::machine::OperationMapping,
    /// Perforation geometry.
    pub perforation: crate::machine::Perforation,
    /// Kerf width, mm (closed contours are offset by half of it).
    pub kerf_mm: f64,
    /// Compensate the kerf: offset closed contours by half of it (outward for outer contours,
    /// inward for holes) and measure perforation bridges and vertex clearances between the
    /// kerf's edges ([`PlanOptions::toolpath_perforation`]).
    pub kerf_offset: bool,
    /// The machine's coordinate resolution, mm: kerf-offset contours keep no side shorter
    /// than this (set by [`PlanOptions::adapt_to_machine`]; 0.001 from the material alone).
    pub resolution_mm: f64,
    /// Mountains from the front, valleys from the back (second job mirrored), with
    /// registration marks.
    pub two_sided: bool,
    /// Holding tabs in closed contours.
    pub tabs: Option<Tabs>,
    /// Lead-in length on the scrap side of closed contours, mm.
    pub lead_in_mm: Option<f64>,
    /// Distance from the bed origin corner to the pattern, mm.
    pub margin_mm: f64,
    /// Order toolpaths to shorten travel (off: pattern order, for comparisons).
    pub optimize: bool,
    /// What [`PlanOptions::adapt_to_machine`] changed, for the plan's warnings.
    pub notes: Vec<PlanWarning>,
    /// Corner or centre of the bed, and an offset.
    pub placement: placement::Placement,
}

/// [`PlanOptions::resolution_mm`] before a machine is known, mm.
pub const DEFAULT_RESOLUTION_MM: f64 = 0.001;

impl PlanOptions {
    /// The material's defaults: its mapping, perforation and kerf, one side, no tabs or
    /// lead-ins, 5 mm margin, optimised order.
    pub fn from_material(material: &crate::machine::Material) -> Self {
        PlanOptions {
            mapping: material.mapping,
            perforation: material.perforation,
            kerf_mm: material.kerf_mm,
            kerf_offset: true,
            resolution_mm: DEFAULT_RESOLUTION_MM,
            two_sided: false,
            tabs: None,
            lead_in_mm: None,
            margin_mm: DEFAULT_MARGIN_MM,
            optimize: true,
            notes: Vec::new(),
            placement: placement::Placement::default(),
        }
    }
}

impl PlanOptions {
    /// The perforation in toolpath terms: with kerf compensation, bridges and vertex
    /// clearances measured between the kerf's edges ([`crate::machine::Perforation::for_kerf`]);
    /// without it, on the beam's centre line.
    pub fn toolpath_perforation(&self) -> crate::machine::Perforation {
        if self.kerf_offset {
            self.perforation.for_kerf(self.kerf_mm)
        } else {
            self.perforation
        }
    }

    /// Checks every number against [`crate::limits`] (the ranges the material profiles
    /// accept) and the perforation's lengths against each other, so that no option given on
    /// the command line or by a library caller reaches the planner out of range.
    pub fn validate(&self) -> Result<(), crate::limits::LimitError> {
        use crate::limits::{self, check_length};
        check_length(&limits::KERF, self.kerf_mm)?;
        check_length(&limits::MARGIN, self.margin_mm)?;
        self.perforation.check_limits()?;
        if let Some(t) = &self.tabs {
            check_length(&limits::TAB_WIDTH, t.width_mm)?;
            check_length(&limits::TAB_SPACING, t.spacing_mm)?;
        }
        if let Some(l) = self.lead_in_mm {
            check_length(&limits::LEAD_IN, l)?;
        }
        Ok(())
    }

    /// Refuses a piece `size_mm` across (`what`: the pattern's longer side, a calibration
    /// cell's width) smaller than the kerf: what `cut` and `testgrid` both check.
    pub fn check_size(&self, what: &'static str, size_mm: f64) -> Result<(), FabError> {
        if size_mm < self.kerf_mm {
            return Err(FabError::SmallerThanKerf {
                what,
                size_mm,
                kerf_mm: self.kerf_mm,
            });
        }
        Ok(())
    }

    /// Fits the operation mapping to `machine` and takes its resolution. A pen plotter draws what a laser would burn:
    /// scores and cuts become plots, marks stay marks (a second pen), perforations stay
    /// perforations (drawn as dashes); when mountains and valleys would share one operation,
    /// valleys become marks so they come out as a layer of their own (separate SVG layers, a
    /// pen-change pause between them in G-code). Every change is noted in
    /// [`PlanOptions::notes`]. Any other machine must support every operation the mapping
    /// uses.
    pub fn adapt_to_machine(
        &mut self,
        machine: &crate::machine::MachineProfile,
    ) -> Result<(), FabError> {
        let plotter = machine.kind == crate::machine::MachineKind::Plotter;
        self.resolution_mm = machine.resolution_mm;
        let m = &mut self.mapping;
        let mut changed: Vec<String> = Vec::new();
        let mut unsupported: Vec<&'static str> = Vec::new();
        for (name, slot) in [
            ("mountain", &mut m.mountain),
            ("valley", &mut m.valley),
            ("unassigned", &mut m.unassigned),
            ("flat", &mut m.flat),
            ("boundary", &mut m.boundary),
        ] {
            let Some(op) = slot else { continue };
            if plotter && matches!(*op, Operation::Score | Operation::Cut) {
                changed.push(format!("{name} {} drawn as plot", op.name()));
                *op = Operation::Plot;
            } else if !machine.supports(*op) && !unsupported.contains(&op.name()) {
                unsupported.push(op.name());
            }
        }
        if plotter && m.mountain.is_some() && m.valley == m.mountain {
            changed.push("valleys drawn as mark, a layer of their own".into());
            m.valley = Some(Operation::Mark);
            if m.unassigned == m.mountain {
                m.unassigned = Some(Operation::Mark);
            }
        }
        if !changed.is_empty() {
            self.notes
                .push(PlanWarningKind::AdaptedToMachine.says(format!(
                    "{} is a plotter: {}",
                    machine.name,
                    changed.join(", ")
                )));
        }
        if unsupported.is_empty() {
            Ok(())
        } else {
            Err(FabError::Unsupported {
                machine: machine.name.clone(),
                operations: unsupported.join(" or "),
            })
        }
    }
}

/// Why a plan could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FabError {
    /// A setting is out of range (see [`crate::limits`]).
    #[error(transparent)]
    Limit(#[from] crate::limits::LimitError),
    /// The pattern has no physical size.
    #[error(transparent)]
    Unitless(#[from] crate::pattern::UnitlessError),
    /// The pattern is larger than the bed.
    #[error(
        "the pattern ({width:.1} × {height:.1} mm with margins) does not fit the bed of \
         {bed_width:.1} × {bed_height:.1} mm: make it smaller (--size on the command line, \
         the Size field in the studio) or use a larger machine"
    )]
    DoesNotFit {
        /// Pattern width plus margins, mm.
        width: f64,
        /// Pattern height plus margins, mm.
        height: f64,
        /// Bed width, mm.
        bed_width: f64,
        /// Bed height, mm.
        bed_height: f64,
    },
    /// The machine cannot do an operation the mapping asks for.
    #[error(
        "machine {machine} cannot {operations}: choose other operations (--mountain, --valley, \
         --flat, --boundary) or another machine"
    )]
    Unsupported {
        /// The machine profile's name.
        machine: String,
        /// The operations it lacks, joined with "or".
        operations: String,
    },
    /// No edge maps to an operation.
    #[error(
        "nothing to do: no edge of the pattern maps to an operation (the material skips its \
         lines; --mountain, --valley, --flat or --boundary choose an operation for them)"
    )]
    NothingToDo,
    /// A plan option is out of range.
    #[error("--{option} {message}")]
    BadOption {
        /// The option, as on the command line (e.g. `margin`).
        option: &'static str,
        /// What is wrong with its value.
        message: String,
    },
    /// A piece to cut is smaller than the beam that cuts it.
    #[error(
        "{what} is {size_mm} mm across, smaller than the kerf of {kerf_mm} mm: cutting it would \
         leave nothing but the kerf's width; make it larger (--size, the studio's Size field) or \
         the kerf smaller (--kerf, the studio's Kerf field)"
    )]
    SmallerThanKerf {
        /// What was measured (`the pattern`, `a calibration cell (--crease)`).
        what: &'static str,
        /// Its size, mm (the longer side of its bounding box).
        size_mm: f64,
        /// The kerf, mm.
        kerf_mm: f64,
    },
    /// A geometric step failed (named).
    #[error("{step}: {message}")]
    Geometry {
        /// The step, e.g. `kerf offset`.
        step: &'static str,
        /// What went wrong.
        message: String,
    },
}
