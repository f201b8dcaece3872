//! Calibration grid: short perforated creases over ranges of dash, bridge, power and speed,
//! each in a coupon of its own labelled with its values, so one burn shows which perforation
//! folds cleanly in a sheet; the chosen values go into the material profile as they are
//! labelled (dash and bridge are the material's `[perforation] cut_mm` and `bridge_mm`, the
//! material left between dashes, kerf accounted as in any plan).
//!
//! **Cells.** Every combination of the value lists, in the order power, speed, dash, bridge
//! (bridge varying fastest). A cell is a coupon `crease_mm` wide: its outline is cut (plotted
//! on a plotter), a valley crease runs across it from side to side `FLAP_MM` below its top
//! edge, perforated with the cell's dash and bridge (vertex clearances as the material sets
//! them), and two lines of single-stroke digits ([`crate::geom::stroke_digits`]) are marked
//! under the crease: `DASH BRIDGE` (mm) on the upper line, `POWER SPEED` (power in per cent
//! of the machine's range, speed in mm/min) on the lower; a plotter's lower line shows only
//! the speed. The crease's toolpaths run with the cell's speed and power through a
//! [`SettingsOverride`] (named `cell-N`, N from 1), so the G-code carries them and DXF, SVG
//! and LightBurn output give every cell a layer of its own; outlines and labels run with the
//! material's `cut` and `mark` settings.
//!
//! **Layout.** Cells in rows as many as fit the bed's width (at most one row per power and
//! speed), first cell top left, `GAP_MM` apart.
//!
//! **Defaults** ([`TestGridOptions::around`]): three dashes from half to one and a half times
//! the material's, three bridges likewise (at least the material's least web), three powers
//! from 0.2 below to 0.2 above the material's perforation power (within 0.05..=1; the
//! material's only on a plotter), and the material's perforation speed (on a plotter its
//! `plot` speed, at which it draws everything).

use glam::DVec2;

use super::stats::plan_stats;
use super::{
    FabError, FabPlan, Operation, PlanOptions, PlanWarning, PlanWarningKind, SettingsOverride,
    Toolpath, geometry,
};
use crate::geom::stroke_digits;
use crate::machine::{MachineKind, MachineProfile, Material, OperationMapping, OperationSettings};
use crate::pattern::{Assignment, CreasePattern, EdgeId};

/// Most cells in one grid.
pub const MAX_CELLS: usize = 400;
/// Most values in one list.
pub const MAX_VALUES: usize = 20;
/// Space between cells, mm.
pub const GAP_MM: f64 = 3.0;
/// Distance from the crease to the cell's top edge, mm (the flap folded to test the crease).
pub const FLAP_MM: f64 = 8.0;
/// Distance of the labels from the cell's left and bottom edges, mm.
const LABEL_INSET_MM: f64 = 2.0;
/// Space between the two label lines, and between the labels and the crease, mm.
const LABEL_LEADING_MM: f64 = 1.5;
/// Shortest default crease (cell width), mm.
const MIN_DEFAULT_CREASE_MM: f64 = 30.0;
/// Default creases hold this many perforation periods of the longest dash and bridge.
const DEFAULT_PERIODS: f64 = 4.0;
/// How far the default powers reach below and above the material's.
const DEFAULT_POWER_SPREAD: f64 = 0.2;
/// Lowest default power.
const MIN_DEFAULT_POWER: f64 = 0.05;

/// What to burn: the values tried and the cell geometry.
#[derive(Clone, Debug, PartialEq)]
pub struct TestGridOptions {
    /// Dash lengths, mm (> 0).
    pub dash_mm: Vec<f64>,
    /// Bridge lengths (material left between dashes), mm (> 0).
    pub bridge_mm: Vec<f64>,
    /// Powers as fractions of the machine's range (0..=1).
    pub power: Vec<f64>,
    /// Speeds, mm/min (> 0).
    pub speed_mm_min: Vec<f64>,
    /// Crease length = cell width, mm.
    pub crease_mm: f64,
    /// Height of the label digits, mm.
    pub label_mm: f64,
    /// Distance from the bed's origin corner, mm.
    pub margin_mm: f64,
}

/// One cell of a grid.
#[derive(Clone, Debug, PartialEq)]
pub struct Cell {
    /// Number, from 1 (the override is `cell-N`).
    pub number: usize,
    /// Dash length asked, mm.
    pub dash_mm: f64,
    /// Bridge asked (material left), mm.
    pub bridge_mm: f64,
    /// Power, fraction of the machine's range.
    pub power: f64,
    /// Speed, mm/min.
    pub speed_mm_min: f64,
    /// The two label lines, top first.
    pub label: [String; 2],
    /// The cell's crease in the grid pattern.
    pub crease: EdgeId,
}

/// A planned calibration grid.
#[derive(Clone, Debug)]
pub struct TestGrid {
    /// The grid as a crease pattern (outlines boundary, creases valley, labels flat), mm.
    pub pattern: CreasePattern,
    /// The plan: one job, one settings override per cell.
    pub plan: FabPlan,
    /// The cells, in the order of the overrides.
    pub cells: Vec<Cell>,
}

/// Why a grid could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TestGridError {
    /// A list of values is empty, too long or holds a value out of range.
    #[error("{what}: {message}")]
    Values {
        /// The list, e.g. `dash`.
        what: &'static str,
        /// What is wrong.
        message: String,
    },
    /// Too many combinations.
    #[error("{cells} cells asked for; at most {MAX_CELLS}: give fewer values")]
    TooManyCells {
        /// The number of combinations.
        cells: usize,
    },
    /// A label does not fit its cell.
    #[error(
        "cell label {text:?} is {width:.1} mm wide at {height} mm; the cell leaves {room:.1} mm: \
         lengthen the crease (--crease) or lower the label height"
    )]
    LabelTooWide {
        /// The label line.
        text: String,
        /// Its width, mm.
        width: f64,
        /// The digit height, mm.
        height: f64,
        /// Room in the cell, mm.
        room: f64,
    },
    /// Planning failed (the grid does not fit the bed, the machine cannot mark, …).
    #[error(transparent)]
    Fab(#[from] FabError),
}

/// `count` values evenly from `from` to `to` (just `from` when `count` is 1), rounded to
/// `step`.
pub fn spread(from: f64, to: f64, count: usize, step: f64) -> Vec<f64> {
    let round = |v: f64| (v / step).round() * step;
    if count <= 1 {
        return vec![round(from)];
    }
    let mut out: Vec<f64> = (0..count)
        .map(|i| round(from + (to - from) * i as f64 / (count - 1) as f64))
        .collect();
    out.dedup();
    out
}

impl TestGridOptions {
    /// The defaults around `material`'s perforation on `machine` (see the module docs).
    pub fn around(material: &Material, machine: &MachineProfile) -> Self {
        let p = &material.perforation;
        // As the machine takes them: a plotter draws at the plot settings.
        let s = machine.settings_for(&material.settings, Operation::Perforate);
        let dash_mm = spread((p.cut_mm / 2.0).max(p.min_dash_mm), p.cut_mm * 1.5, 3, 0.01);
        let bridge_mm = spread(
            (p.bridge_mm / 2.0).max(p.min_web_mm),
            p.bridge_mm * 1.5,
            3,
            0.01,
        );
        let power = if machine.kind == MachineKind::Plotter {
            vec![s.power]
        } else {
            spread(
                (s.power - DEFAULT_POWER_SPREAD).max(MIN_DEFAULT_POWER),
                (s.power + DEFAULT_POWER_SPREAD).min(1.0),
                3,
                0.01,
            )
        };
        let period = dash_mm.iter().copied().fold(0.0, f64::max)
            + bridge_mm.iter().copied().fold(0.0, f64::max);
        let crease = DEFAULT_PERIODS * period + 2.0 * p.vertex_clearance_mm;
        TestGridOptions {
            dash_mm,
            bridge_mm,
            power,
            speed_mm_min: vec![s.speed_mm_min],
            crease_mm: (crease / 5.0).ceil().max(MIN_DEFAULT_CREASE_MM / 5.0) * 5.0,
            label_mm: 3.0,
            margin_mm: 5.0,
        }
    }

    /// Checks every list and number; the combinations in cell order (power, speed, dash,
    /// bridge).
    fn combinations(&self) -> Result<Vec<[f64; 4]>, TestGridError> {
        let positive = |v: f64| v.is_finite() && v > 0.0 && v <= 1e6;
        // (list, values, fractions rather than positive numbers, what a value must be)
        let lists: [(&'static str, &Vec<f64>, bool, &str); 4] = [
            ("dash", &self.dash_mm, false, "a positive length in mm"),
            ("bridge", &self.bridge_mm, false, "a positive length in mm"),
            ("power", &self.power, true, "a fraction from 0 to 1"),
            (
                "speed",
                &self.speed_mm_min,
                false,
                "a positive speed in mm/min",
            ),
        ];
        for (what, values, fraction, expected) in lists {
            let ok = |v: f64| {
                if fraction {
                    (0.0..=1.0).contains(&v)
                } else {
                    positive(v)
                }
            };
            let bad = |message: String| TestGridError::Values { what, message };
            if values.is_empty() || values.len() > MAX_VALUES {
                return Err(bad(format!(
                    "{} values given; expected 1 to {MAX_VALUES}",
                    values.len()
                )));
            }
            if let Some(v) = values.iter().find(|v| !ok(**v)) {
                return Err(bad(format!("{v}: expected {expected}")));
            }
        }
        for (what, v) in [("crease", self.crease_mm), ("label height", self.label_mm)] {
            if !(positive(v) && v <= 1000.0) {
                return Err(TestGridError::Values {
                    what,
                    message: format!("{v}: expected a positive length up to 1000 mm"),
                });
            }
        }
        if !(self.margin_mm.is_finite() && self.margin_mm >= 0.0) {
            return Err(TestGridError::Values {
                what: "margin",
                message: format!("{}: expected a length of at least 0 mm", self.margin_mm),
            });
        }
        let cells =
            self.power.len() * self.speed_mm_min.len() * self.dash_mm.len() * self.bridge_mm.len();
        if cells > MAX_CELLS {
            return Err(TestGridError::TooManyCells { cells });
        }
        let mut out = Vec::with_capacity(cells);
        for &power in &self.power {
            for &speed in &self.speed_mm_min {
                for &dash in &self.dash_mm {
                    for &bridge in &self.bridge_mm {
                        out.push([dash, bridge, power, speed]);
                    }
                }
            }
        }
        Ok(out)
    }

    /// Height of a cell, mm: two label lines, the space above them, the flap.
    fn cell_height(&self) -> f64 {
        LABEL_INSET_MM + 2.0 * self.label_mm + 2.0 * LABEL_LEADING_MM + FLAP_MM
    }
}

/// A number with at most two decimals, trailing zeros dropped (`1.5`, `2`, `0.75`).
pub fn short_number(v: f64) -> String {
    let s = format!("{:.2}", (v * 100.0).round() / 100.0);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

/// The two label lines of a cell.
fn label(dash: f64, bridge: f64, power: f64, speed: f64, plotter: bool) -> [String; 2] {
    let top = format!("{} {}", short_number(dash), short_number(bridge));
    let speed = format!("{}", speed.round());
    let bottom = if plotter {
        speed
    } else {
        format!("{} {speed}", (power * 100.0).round())
    };
    [top, bottom]
}

/// Builds and plans the calibration grid for `machine` and `material` (see the module docs).
///
/// # Errors
/// [`TestGridError`]: values out of range, too many cells, a label wider than its cell, or a
/// plan that fails (the grid larger than the bed, a machine that cannot perforate, mark or
/// cut/plot).
pub fn test_grid(
    machine: &MachineProfile,
    material: &Material,
    opts: &TestGridOptions,
) -> Result<TestGrid, TestGridError> {
    let combos = opts.combinations()?;
    let plotter = machine.kind == MachineKind::Plotter;
    let mut plan_opts = PlanOptions::from_material(material);
    plan_opts.mapping = OperationMapping {
        mountain: None,
        valley: Some(Operation::Perforate),
        unassigned: None,
        flat: Some(Operation::Mark),
        boundary: Some(Operation::Cut),
    };
    plan_opts.adapt_to_machine(machine)?;
    plan_opts.margin_mm = opts.margin_mm;
    plan_opts.check_size("a calibration cell (--crease)", opts.crease_mm)?;
    let (w, h) = (opts.crease_mm, opts.cell_height());
    let per_row = (opts.dash_mm.len() * opts.bridge_mm.len()).max(1);
    let room = machine.bed.width_mm - 2.0 * opts.margin_mm + GAP_MM;
    let columns = ((room / (w + GAP_MM)).floor() as usize).clamp(1, per_row);
    let rows = combos.len().div_ceil(columns);
    let mut pattern = CreasePattern::new();
    let mut paths: Vec<Toolpath> = Vec::new();
    let mut cells = Vec::with_capacity(combos.len());
    let mut warnings: Vec<PlanWarning> = Vec::new();
    for (i, &[dash, bridge, power, speed]) in combos.iter().enumerate() {
        let (col, row) = (i % columns, i / columns);
        let corner = DVec2::new(
            col as f64 * (w + GAP_MM),
            (rows - 1 - row) as f64 * (h + GAP_MM),
        );
        let text = label(dash, bridge, power, speed, plotter);
        let cell = cell_pattern(corner, w, h, opts.label_mm, &text)?;
        let mut cell_opts = plan_opts.clone();
        let perf = &mut cell_opts.perforation;
        perf.cut_mm = dash;
        perf.bridge_mm = bridge;
        // As `cut` checks the material's perforation with its options laid over it.
        perf.check_limits().map_err(FabError::from)?;
        let (cell_paths, remarks) = geometry::toolpaths_with_warnings(&cell, &cell_opts)?;
        let shift = pattern.edges.len();
        append(&mut pattern, &cell);
        warnings.extend(remarks.into_iter().map(|r| {
            PlanWarning {
                text: format!("cell {}: {}", i + 1, r.text),
                edges: r
                    .edges
                    .iter()
                    .map(|e| EdgeId::new(e.index() + shift))
                    .collect(),
                ..r
            }
        }));
        paths.extend(cell_paths.into_iter().map(|mut p| {
            for e in &mut p.edges {
                *e = EdgeId::new(e.index() + shift);
            }
            p
        }));
        cells.push(Cell {
            number: i + 1,
            dash_mm: dash,
            bridge_mm: bridge,
            power,
            speed_mm_min: speed,
            label: text,
            crease: EdgeId::new(shift + CREASE_EDGE),
        });
    }
    let mut plan = super::plan::plan_toolpaths(&pattern, paths, machine, material, &plan_opts)?;
    plan.overrides = cells
        .iter()
        .map(|c| SettingsOverride {
            name: format!("cell-{}", c.number),
            edges: vec![c.crease],
            settings: OperationSettings {
                speed_mm_min: c.speed_mm_min,
                power: c.power,
                passes: material.settings.perforate.passes,
            },
        })
        .collect();
    plan.stats = plan_stats(
        &plan,
        plan.stats.naive_travel_mm,
        plan.stats.crease_mm,
        machine,
    );
    plan.warnings.extend(plan_opts.notes.iter().cloned());
    plan.warnings.extend(warnings);
    if !super::operations::can_mark(machine, material) {
        plan.warnings
            .push(PlanWarningKind::InvisibleMarks.says(format!(
                "{} has no visible mark on {} (mark power 0): the cell labels will not show",
                material.name, machine.name
            )));
    }
    Ok(TestGrid {
        pattern,
        plan,
        cells,
    })
}

/// Fold angle stored on the coupons' creases, degrees (valley, folded by hand to a right angle).
const COUPON_FOLD_DEG: f64 = 90.0;
/// Index of the crease among a cell pattern's edges (after the six outline edges).
const CREASE_EDGE: usize = 6;

/// One cell at `corner`: the outline (six boundary edges, the crease's ends splitting the
/// sides), the crease (valley), the label strokes (flat).
fn cell_pattern(
    corner: DVec2,
    w: f64,
    h: f64,
    label_mm: f64,
    text: &[String; 2],
) -> Result<CreasePattern, TestGridError> {
    let mut cp = CreasePattern::new();
    let at = |x: f64, y: f64| corner + DVec2::new(x, y);
    let yc = h - FLAP_MM;
    let ring: Vec<_> = [
        at(0.0, 0.0),
        at(w, 0.0),
        at(w, yc),
        at(w, h),
        at(0.0, h),
        at(0.0, yc),
    ]
    .into_iter()
    .map(|p| cp.add_vertex(p))
    .collect();
    for (k, &v) in ring.iter().enumerate() {
        cp.add_edge(v, ring[(k + 1) % ring.len()], Assignment::Boundary);
    }
    let crease = cp.add_edge(ring[5], ring[2], Assignment::Valley);
    // Coupons are folded by hand to a right angle, not flat: no fold-angle warning.
    cp.edges[crease.index()].fold_angle = Some(COUPON_FOLD_DEG);
    let room = w - 2.0 * LABEL_INSET_MM;
    for (line, s) in text.iter().enumerate() {
        let width = stroke_digits::text_width(s, label_mm);
        if width > room {
            return Err(TestGridError::LabelTooWide {
                text: s.clone(),
                width,
                height: label_mm,
                room,
            });
        }
        let y = LABEL_INSET_MM + (1 - line) as f64 * (label_mm + LABEL_LEADING_MM);
        let strokes =
            stroke_digits::text_strokes(s, at(LABEL_INSET_MM, y), label_mm).map_err(|c| {
                TestGridError::Values {
                    what: "label",
                    message: format!("{c:?} cannot be drawn"),
                }
            })?;
        for stroke in strokes {
            let ids: Vec<_> = stroke.iter().map(|&p| cp.add_vertex(p)).collect();
            for pair in ids.windows(2) {
                cp.add_edge(pair[0], pair[1], Assignment::Flat);
            }
        }
    }
    Ok(cp)
}

/// Appends `part`'s vertices and edges to `into`, ids shifted.
fn append(into: &mut CreasePattern, part: &CreasePattern) {
    let shift = into.vertices.len();
    into.vertices.extend_from_slice(&part.vertices);
    for e in &part.edges {
        let a = crate::pattern::VertexId::new(e.vertices[0].index() + shift);
        let b = crate::pattern::VertexId::new(e.vertices[1].index() + shift);
        let id = into.add_edge(a, b, e.assignment);
        into.edges[id.index()].fold_angle = e.fold_angle;
    }
}
