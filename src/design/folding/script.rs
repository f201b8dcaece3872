//! The TOML fold script: a sheet, then fold steps run one after the other.
//!
//! ```toml
//! title = "Waterbomb base"          # optional
//!
//! [sheet]                           # exactly one of:
//! square = 150                      #   side, mm
//! # rectangle = [210, 297]          #   width and height, mm
//! # polygon = [[0, 0], [100, 0], [50, 80]]   # corners of a simple polygon, mm
//!
//! [snap]                            # optional: drag snapping tolerances (Miyazaki et al. 1992, §2.3 4)
//! vertex = 1.0                      # mm, destination onto a vertex
//! edge = 1.0                        # mm, edge onto edge
//! line = 1.0                        # mm, fold line through two vertices
//! angle = 3.0                       # degrees, fold angle to multiples of 30° / 45°
//!
//! [[step]]
//! name = "fold in half"             # optional
//! bend = { line = [[0, 75], [150, 75]], moving = [75, 150] }
//!
//! [[step]]
//! drag = { from = [150, 0], to = [0, 150], mountain = false, pick = 1.0 }
//!
//! [[step]]
//! fold = { line = [[0, 0], [0, 75]], moving = [10, 10], angle = 90, layers = "outer" }
//!
//! [[step]]
//! tuck = { line = [[75, 75], [0, 0]], moving = [0, 50] }
//! ```
//!
//! Points are `[x, y]` (z = 0) or `[x, y, z]`, millimetres, in space (where the paper is now,
//! not where it was on the flat sheet). Every step but `drag` takes the fold `line` (two
//! points in one layer plane) and a point `moving` on the side that moves.
//! - `bend`: turn 180°; `mountain = true` turns away from the layer's normal (behind, for a
//!   flat model seen from +z), otherwise towards it (valley).
//! - `fold`: turn by `angle` degrees, positive towards the normal (valley seen from +z).
//! - `tuck`: tuck in symmetrically (the lower half of the moving layers turns up, the upper
//!   half down).
//! - `drag`: move the vertex nearest `from` (within `pick` mm, default 1) to `to`; the fold
//!   follows the paper's rule, with snapping; `mountain` as for `bend` when `to` lies in the
//!   layer's plane. With `edge = true`, when no vertex is that near, the nearest point of an
//!   edge moves instead.
//!
//! `layers` (bend, fold, tuck) is `"all"` (default: every face reaching the moving side),
//! `"outer"` (the outermost face at `moving` on the side the fold turns to — the top one for a
//! tuck — plus the faces the moving-face search adds), a number `n` (the `n`-th face from that
//! side, so the outer `n` layers at `moving`), or `"back"` / `-n` (counted from the back, the
//! side away from the layer's normal).

use glam::{DVec2, DVec3};
use serde::Deserialize;

use super::drag::{Drag, Snap};
use super::operation::{Fold, Layers, Turn};
use super::{FoldError, Folding};

/// The pick radius of a `drag` step that gives none, millimetres.
pub const DEFAULT_PICK_RADIUS: f64 = 1.0;

/// A parsed fold script.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Script {
    /// Title of the model.
    pub title: Option<String>,
    /// The sheet.
    pub sheet: SheetSpec,
    /// Snapping tolerances for drags.
    #[serde(default)]
    pub snap: SnapSpec,
    /// The steps in order.
    #[serde(default, rename = "step")]
    pub steps: Vec<StepSpec>,
}

/// The `[sheet]` table: exactly one shape.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SheetSpec {
    /// Side of a square, mm.
    pub square: Option<f64>,
    /// Width and height, mm.
    pub rectangle: Option<[f64; 2]>,
    /// Corners of a simple polygon (convex or not), mm.
    pub polygon: Option<Vec<[f64; 2]>>,
}

/// The `[snap]` table.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SnapSpec {
    /// Destination onto a vertex, mm.
    pub vertex: f64,
    /// Edge onto edge, mm.
    pub edge: f64,
    /// Fold line through two vertices, mm.
    pub line: f64,
    /// Fold angle, degrees.
    pub angle: f64,
}

impl SnapSpec {
    /// The tolerances as the simulator takes them.
    pub fn to_snap(&self) -> Snap {
        Snap {
            vertex: self.vertex,
            edge: self.edge,
            line: self.line,
            angle_deg: self.angle,
        }
    }
}

impl From<Snap> for SnapSpec {
    fn from(s: Snap) -> SnapSpec {
        SnapSpec {
            vertex: s.vertex,
            edge: s.edge,
            line: s.line,
            angle: s.angle_deg,
        }
    }
}

impl Default for SnapSpec {
    fn default() -> Self {
        SnapSpec::from(Snap::default())
    }
}

/// One `[[step]]`: a name and exactly one operation.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StepSpec {
    /// Optional name.
    pub name: Option<String>,
    /// Bend (180°).
    pub bend: Option<LineSpec>,
    /// Fold up by an angle.
    pub fold: Option<LineSpec>,
    /// Tuck in.
    pub tuck: Option<LineSpec>,
    /// Drag a vertex.
    pub drag: Option<DragSpec>,
}

/// A fold given by its line.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LineSpec {
    /// Two points of the fold line.
    pub line: [Vec<f64>; 2],
    /// A point on the moving side.
    pub moving: Vec<f64>,
    /// Degrees (only for `fold`).
    pub angle: Option<f64>,
    /// Turn away from the normal (only for `bend`).
    #[serde(default)]
    pub mountain: bool,
    /// `"all"`, `"outer"` or a number of outer layers.
    pub layers: Option<LayersSpec>,
}

/// The `layers` key: `"all"`, `"outer"` (= 1) or a count of outer layers.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(untagged)]
pub enum LayersSpec {
    /// `"all"` or `"outer"`.
    Name(String),
    /// The outer `n` layers at the `moving` point.
    Count(i64),
}

/// A drag.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DragSpec {
    /// Near the vertex to pick.
    pub from: Vec<f64>,
    /// Where it goes.
    pub to: Vec<f64>,
    /// Fold behind for a move within the layer plane.
    #[serde(default)]
    pub mountain: bool,
    /// Pick radius, mm (default 1).
    pub pick: Option<f64>,
    /// Pick a point of an edge when no vertex lies within `pick`.
    #[serde(default)]
    pub edge: bool,
}

/// A problem with a script: where (a TOML line, or a step) and what.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ScriptError {
    /// The text is not a valid script.
    #[error("{0}")]
    Syntax(String),
    /// A step is malformed or cannot be folded.
    #[error("step {number}{}: {message}", name.as_ref().map(|n| format!(" (\"{n}\")")).unwrap_or_default())]
    Step {
        /// 1-based step number.
        number: usize,
        /// The step's name.
        name: Option<String>,
        /// What is wrong.
        message: String,
    },
}

/// Parses a script's text (checking the sheet and step shapes, not yet folding).
pub fn parse_script(text: &str) -> Result<Script, ScriptError> {
    let script: Script = toml::from_str(text)
        .map_err(|e| ScriptError::Syntax(e.to_string().trim_end().to_string()))?;
    sheet_outline(&script.sheet)?;
    Ok(script)
}

/// Runs a script: the simulator after every step (step `i` of the result is script step `i`).
pub fn run_script(script: &Script) -> Result<Folding, ScriptError> {
    let outline = sheet_outline(&script.sheet)?;
    let mut folding =
        Folding::new(&outline).map_err(|e| ScriptError::Syntax(format!("[sheet]: {e}")))?;
    let snap = script.snap.to_snap();
    for (i, step) in script.steps.iter().enumerate() {
        apply_step(&mut folding, step, snap).map_err(|message| ScriptError::Step {
            number: i + 1,
            name: step.name.clone(),
            message,
        })?;
    }
    Ok(folding)
}

/// Applies one script step to `folding` as [`run_script`] does, drags snapping with `snap`.
/// On error (the step is malformed or cannot be folded) `folding` is unchanged and the
/// message says why.
pub fn apply_step(folding: &mut Folding, step: &StepSpec, snap: Snap) -> Result<(), String> {
    let result = match action(step, snap)? {
        Action::Fold(f) => folding.fold(&f, step.name.clone()).map(|_| ()),
        Action::Drag(d) => folding.drag(&d, step.name.clone()).map(|_| ()),
    };
    result.map_err(|e: FoldError| e.to_string())
}

/// The sheet outline of a `[sheet]` table.
pub fn sheet_outline(sheet: &SheetSpec) -> Result<Vec<DVec2>, ScriptError> {
    let bad = |m: &str| ScriptError::Syntax(format!("[sheet]: {m}"));
    let positive = |x: f64| x.is_finite() && x > 0.0 && x <= 1e6;
    match (sheet.square, sheet.rectangle, &sheet.polygon) {
        (Some(s), None, None) if positive(s) => Ok(rect(s, s)),
        (None, Some([w, h]), None) if positive(w) && positive(h) => Ok(rect(w, h)),
        (None, None, Some(p)) if p.iter().flatten().all(|x| x.is_finite() && x.abs() <= 1e6) => {
            Ok(p.iter().map(|c| DVec2::new(c[0], c[1])).collect())
        }
        (None, None, None) => Err(bad("give one of square, rectangle or polygon")),
        (Some(_), None, None) | (None, Some(_), None) => {
            Err(bad("sizes must be positive millimetres up to 1e6"))
        }
        (None, None, Some(_)) => Err(bad("polygon corners must be finite millimetres up to ±1e6")),
        _ => Err(bad("give only one of square, rectangle or polygon")),
    }
}

fn rect(w: f64, h: f64) -> Vec<DVec2> {
    vec![
        DVec2::ZERO,
        DVec2::new(w, 0.0),
        DVec2::new(w, h),
        DVec2::new(0.0, h),
    ]
}

enum Action {
    Fold(Fold),
    Drag(Drag),
}

fn action(step: &StepSpec, snap: Snap) -> Result<Action, String> {
    match (&step.bend, &step.fold, &step.tuck, &step.drag) {
        (Some(l), None, None, None) => {
            let angle = if l.mountain { -180.0 } else { 180.0 };
            if l.angle.is_some() {
                return Err("bend takes no angle (it is 180°; use fold)".into());
            }
            line_fold(l, Turn::Angle(angle)).map(Action::Fold)
        }
        (None, Some(l), None, None) => {
            let a = l.angle.ok_or("fold needs an angle in degrees")?;
            if l.mountain {
                return Err("fold takes the direction from the angle's sign, not mountain".into());
            }
            line_fold(l, Turn::Angle(a)).map(Action::Fold)
        }
        (None, None, Some(l), None) => {
            if l.angle.is_some() || l.mountain {
                return Err("tuck takes neither angle nor mountain".into());
            }
            line_fold(l, Turn::Tuck).map(Action::Fold)
        }
        (None, None, None, Some(d)) => Ok(Action::Drag(Drag {
            from: point(&d.from, "drag.from")?,
            to: point(&d.to, "drag.to")?,
            pick_radius: match d.pick {
                Some(r) if r.is_finite() && r > 0.0 => r,
                Some(r) => {
                    return Err(format!(
                        "drag.pick must be a positive radius in mm, not {r}"
                    ));
                }
                None => DEFAULT_PICK_RADIUS,
            },
            mountain: d.mountain,
            snap,
            edge_points: d.edge,
        })),
        (None, None, None, None) => Err("give one of bend, fold, tuck or drag".into()),
        _ => Err("give only one of bend, fold, tuck or drag per step".into()),
    }
}

fn line_fold(l: &LineSpec, turn: Turn) -> Result<Fold, String> {
    let layers = match &l.layers {
        None => Layers::All,
        Some(LayersSpec::Name(n)) if n == "all" => Layers::All,
        Some(LayersSpec::Name(n)) if n == "outer" => Layers::Outer(1),
        Some(LayersSpec::Name(n)) if n == "back" => Layers::Back(1),
        Some(LayersSpec::Count(n)) if (1..=100_000).contains(n) => Layers::Outer(*n as usize),
        Some(LayersSpec::Count(n)) if (-100_000..=-1).contains(n) => {
            Layers::Back(n.unsigned_abs() as usize)
        }
        Some(other) => {
            return Err(format!(
                "layers must be \"all\", \"outer\", \"back\" or a count of layers (negative from the back), not {other:?}"
            ));
        }
    };
    Ok(Fold {
        line: [point(&l.line[0], "line[0]")?, point(&l.line[1], "line[1]")?],
        moving: point(&l.moving, "moving")?,
        turn,
        layers,
    })
}

fn point(v: &[f64], what: &str) -> Result<DVec3, String> {
    let p = match v {
        [x, y] => DVec3::new(*x, *y, 0.0),
        [x, y, z] => DVec3::new(*x, *y, *z),
        _ => {
            return Err(format!(
                "{what} must be [x, y] or [x, y, z], found {} numbers",
                v.len()
            ));
        }
    };
    if !p.is_finite() {
        return Err(format!("{what} is not finite"));
    }
    Ok(p)
}

/// The text of `script` in the format [`parse_script`] reads: parsing it gives `script` back
/// (numbers are written in Rust's shortest round-trip form, so every coordinate is exact).
/// Points with z = 0 are written as `[x, y]`; the `[snap]` table is always written.
pub fn write_script(script: &Script) -> String {
    let mut out = String::new();
    if let Some(title) = &script.title {
        out.push_str(&format!("title = {}\n\n", quote(title)));
    }
    out.push_str("[sheet]\n");
    let sheet = &script.sheet;
    if let Some(s) = sheet.square {
        out.push_str(&format!("square = {}\n", number(s)));
    }
    if let Some([w, h]) = sheet.rectangle {
        out.push_str(&format!("rectangle = [{}, {}]\n", number(w), number(h)));
    }
    if let Some(p) = &sheet.polygon {
        let corners: Vec<String> = p.iter().map(|c| point_text(&c[..])).collect();
        out.push_str(&format!("polygon = [{}]\n", corners.join(", ")));
    }
    let s = &script.snap;
    out.push_str(&format!(
        "\n[snap]\nvertex = {}\nedge = {}\nline = {}\nangle = {}\n",
        number(s.vertex),
        number(s.edge),
        number(s.line),
        number(s.angle)
    ));
    for step in &script.steps {
        out.push_str("\n[[step]]\n");
        if let Some(name) = &step.name {
            out.push_str(&format!("name = {}\n", quote(name)));
        }
        let ops = [
            ("bend", &step.bend),
            ("fold", &step.fold),
            ("tuck", &step.tuck),
        ];
        for (key, spec) in ops {
            if let Some(l) = spec {
                out.push_str(&format!("{key} = {}\n", line_text(l)));
            }
        }
        if let Some(d) = &step.drag {
            let mut fields = vec![
                format!("from = {}", point_text(&d.from)),
                format!("to = {}", point_text(&d.to)),
            ];
            if d.mountain {
                fields.push("mountain = true".into());
            }
            if let Some(r) = d.pick {
                fields.push(format!("pick = {}", number(r)));
            }
            if d.edge {
                fields.push("edge = true".into());
            }
            out.push_str(&format!("drag = {{ {} }}\n", fields.join(", ")));
        }
    }
    out
}

fn line_text(l: &LineSpec) -> String {
    let mut fields = vec![
        format!(
            "line = [{}, {}]",
            point_text(&l.line[0]),
            point_text(&l.line[1])
        ),
        format!("moving = {}", point_text(&l.moving)),
    ];
    if let Some(a) = l.angle {
        fields.push(format!("angle = {}", number(a)));
    }
    if l.mountain {
        fields.push("mountain = true".into());
    }
    match &l.layers {
        Some(LayersSpec::Name(n)) => fields.push(format!("layers = {}", quote(n))),
        Some(LayersSpec::Count(n)) => fields.push(format!("layers = {n}")),
        None => {}
    }
    format!("{{ {} }}", fields.join(", "))
}

/// `[x, y]`, or `[x, y, z]` when there is a z other than 0 (or any other count as given).
fn point_text(p: &[f64]) -> String {
    let n = if p.len() == 3 && p[2] == 0.0 {
        2
    } else {
        p.len()
    };
    let parts: Vec<String> = p[..n].iter().map(|&x| number(x)).collect();
    format!("[{}]", parts.join(", "))
}

/// A TOML number that reads back as exactly `x`: Rust's shortest round-trip decimal, with
/// an exponent where an integral value would be too large for a TOML integer.
fn number(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() >= 1e15 {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// A TOML basic string.
fn quote(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::folding::crease::crease_pattern;

    const EXAMPLES: [&str; 4] = [
        include_str!("../../../examples/folding/bird-base.toml"),
        include_str!("../../../examples/folding/paper-airplane.toml"),
        include_str!("../../../examples/folding/preliminary-base.toml"),
        include_str!("../../../examples/folding/waterbomb-base.toml"),
    ];

    #[test]
    fn written_scripts_parse_back_to_the_same_script() {
        for text in EXAMPLES {
            let script = parse_script(text).unwrap();
            let written = write_script(&script);
            let again = parse_script(&written).unwrap_or_else(|e| panic!("{e}\n{written}"));
            assert_eq!(again, script, "{written}");
        }
    }

    #[test]
    fn written_scripts_fold_to_the_same_crease_pattern() {
        for text in EXAMPLES {
            let script = parse_script(text).unwrap();
            let again = parse_script(&write_script(&script)).unwrap();
            let (a, b) = (run_script(&script).unwrap(), run_script(&again).unwrap());
            assert_eq!(crease_pattern(&a).pattern, crease_pattern(&b).pattern);
        }
    }

    #[test]
    fn awkward_names_and_numbers_survive_the_round_trip() {
        let script = Script {
            title: Some("a \"quoted\" title\\ with\ttabs\nand a bell \u{7}".into()),
            sheet: SheetSpec {
                square: None,
                rectangle: None,
                polygon: Some(vec![[0.1, -0.0], [1e-9, 3e15], [2.0 / 3.0, 1e300]]),
            },
            snap: SnapSpec {
                vertex: 0.0,
                edge: 1.0 / 7.0,
                line: 1e16,
                angle: 3.0,
            },
            steps: vec![StepSpec {
                name: Some("ünïcode".into()),
                bend: None,
                fold: Some(LineSpec {
                    line: [vec![1.0, 2.0, 0.0], vec![1.0, 2.0, 0.1 + 0.2]],
                    moving: vec![5.0, 6.0],
                    angle: Some(-90.0),
                    mountain: false,
                    layers: Some(LayersSpec::Count(-2)),
                }),
                tuck: None,
                drag: None,
            }],
        };
        let again: Script = toml::from_str(&write_script(&script)).unwrap();
        assert_eq!(again.title, script.title);
        assert_eq!(again.sheet, script.sheet);
        assert_eq!(again.snap, script.snap);
        let line = &again.steps[0].fold.as_ref().unwrap().line;
        // A zero z is dropped: the reader puts it back.
        assert_eq!(line[0], vec![1.0, 2.0]);
        assert_eq!(line[1], vec![1.0, 2.0, 0.1 + 0.2]);
        assert_eq!(again.steps[0].name, script.steps[0].name);
    }
}
