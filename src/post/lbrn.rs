//! LightBurn project (`.lbrn2`): one layer (`CutSetting`) per operation carrying the
//! material's speed, power and passes — and one per settings override of the plan (the cells
//! of a calibration grid, see [`super::layers`]) carrying its own — and the job's lines as
//! `Path` shapes.
//!
//! Format facts followed (LightBurn 1.7, `FormatVersion="1"`, the condensed `.lbrn2` form):
//! the root `LightBurnProject` with `AppVersion` and `FormatVersion`; each layer a
//! `<CutSetting type="Cut">` whose settings are child elements with a `Value` attribute:
//! `index`, `name`, `minPower`/`maxPower` (per cent), `speed` (mm/s), `numPasses`,
//! `priority` (the layer order), `runBlower` (air assist), and for perforation `perforate`
//! (1 on), `perfLen` (cut length, mm) and `perfSkip` (gap, mm). Shapes are
//! `<Shape Type="Path" CutIndex="n">` with an identity `<XForm>1 0 0 1 0 0</XForm>`, a
//! `<VertList>` of `Vx y` vertices and a `<PrimList>` of `La b` lines; coordinates are
//! millimetres with y up from the bed's front-left corner.
//!
//! **Perforations** are written as LightBurn perforations: each perforated crease is one path
//! along the crease from the start of its first dash to the end of its last (the vertex
//! clearances left out): every point of every dash in order, so a curved crease keeps its
//! shape (a bridge is drawn as the straight chord between two dashes, off the curve by at most
//! b²/8r for a bridge b on a radius r), on a layer with `perforate` on and the layer's own
//! mean dash and gap as `perfLen` and `perfSkip`, so LightBurn lays the dashes at the
//! controller's pace.

use std::fmt::Write as _;

use glam::DVec2;

use super::PostError;
use super::layers::{Layer, layers};
use super::number::fixed;
use crate::fab::{FabPlan, Job, Operation, Toolpath};
use crate::machine::MachineProfile;

/// The LightBurn version whose project format is written.
pub const LIGHTBURN_APP_VERSION: &str = "1.7.08";
/// Decimals of coordinates and settings.
const DECIMALS: usize = 4;
/// Most layers in a project: LightBurn's colour layers 00–29.
pub const MAX_LAYERS: usize = 30;

/// The LightBurn project of `job` on `machine`.
pub fn write(plan: &FabPlan, job: &Job, machine: &MachineProfile) -> Result<String, PostError> {
    let to_drawing = machine.bed.to_machine().inverse();
    let mut out = String::new();
    let _ = writeln!(out, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        out,
        r#"<LightBurnProject AppVersion="{LIGHTBURN_APP_VERSION}" FormatVersion="1" MaterialHeight="0" MirrorX="False" MirrorY="False">"#
    );
    let layers = layers(plan, job);
    if layers.len() > MAX_LAYERS {
        return Err(PostError::TooManyLayers {
            job: job.name.clone(),
            layers: layers.len(),
            limit: MAX_LAYERS,
        });
    }
    for (index, l) in layers.iter().enumerate() {
        let paths: Vec<&Toolpath> = job.paths.iter().filter(|p| l.holds(plan, p)).collect();
        cut_setting(&mut out, plan, machine, l, index, &paths);
    }
    let mut shapes = 0;
    for path in &job.paths {
        let Some(index) = super::layers::layer_of(&layers, plan, path) else {
            continue;
        };
        let lines: Vec<Vec<DVec2>> = if path.op == Operation::Perforate {
            perforated_line(path).into_iter().collect()
        } else {
            path.strokes.clone()
        };
        for line in lines {
            let line: Vec<DVec2> = line
                .iter()
                .map(|&p| to_drawing.transform_point2(p))
                .collect();
            if shape(&mut out, index, &line) {
                shapes += 1;
            }
        }
    }
    if shapes == 0 {
        return Err(PostError::EmptyJob {
            job: job.name.clone(),
        });
    }
    out.push_str("</LightBurnProject>\n");
    Ok(out)
}

/// The path a perforated crease runs along: every point of every dash in order, from the
/// first dash's start to the last dash's end (repeated points once).
fn perforated_line(path: &Toolpath) -> Option<Vec<DVec2>> {
    let mut points: Vec<DVec2> = path.strokes.iter().flatten().copied().collect();
    points.dedup();
    (points.len() >= 2).then_some(points)
}

/// Mean dash length and mean gap of the perforation toolpaths, mm.
pub fn perforation_layout(paths: &[&Toolpath]) -> (f64, f64) {
    let (mut dash, mut dashes, mut gap, mut gaps) = (0.0, 0usize, 0.0, 0usize);
    for p in paths {
        for s in &p.strokes {
            dash += crate::fab::stats::stroke_length(s);
            dashes += 1;
        }
        for w in p.strokes.windows(2) {
            if let (Some(a), Some(b)) = (w[0].last(), w[1].first()) {
                gap += a.distance(*b);
                gaps += 1;
            }
        }
    }
    let mean = |sum: f64, n: usize| if n > 0 { sum / n as f64 } else { 0.0 };
    (mean(dash, dashes), mean(gap, gaps))
}

/// The `CutSetting` of layer `l` (number `index`), whose toolpaths are `paths`.
fn cut_setting(
    out: &mut String,
    plan: &FabPlan,
    machine: &MachineProfile,
    l: &Layer,
    index: usize,
    paths: &[&Toolpath],
) {
    let op = l.op;
    let s = l.settings(plan, Some(machine));
    let speed_mm_s = s.speed_mm_min.min(machine.max_feed_mm_min) / 60.0;
    let power = fixed(s.power.clamp(0.0, 1.0) * 100.0, DECIMALS);
    let value = |out: &mut String, key: &str, v: &str| {
        let _ = writeln!(out, r#"    <{key} Value="{v}"/>"#);
    };
    out.push_str("  <CutSetting type=\"Cut\">\n");
    value(out, "index", &index.to_string());
    value(out, "name", &l.name);
    value(out, "minPower", &power);
    value(out, "maxPower", &power);
    value(out, "speed", &fixed(speed_mm_s, DECIMALS));
    value(out, "numPasses", &s.passes.to_string());
    value(out, "priority", &index.to_string());
    value(
        out,
        "runBlower",
        if machine.air_for(op) { "1" } else { "0" },
    );
    if op == Operation::Perforate {
        let (dash, gap) = perforation_layout(paths);
        value(out, "perforate", "1");
        value(out, "perfLen", &fixed(dash, DECIMALS));
        value(out, "perfSkip", &fixed(gap, DECIMALS));
    }
    out.push_str("  </CutSetting>\n");
}

/// One `Path` shape of `points` on layer `index`; false when it has no length.
fn shape(out: &mut String, index: usize, points: &[DVec2]) -> bool {
    let mut pts: Vec<DVec2> = points.to_vec();
    pts.dedup();
    if pts.len() < 2 {
        return false;
    }
    let closed = pts.len() > 2 && pts[0] == pts[pts.len() - 1];
    if closed {
        pts.pop();
    }
    let _ = writeln!(out, r#"  <Shape Type="Path" CutIndex="{index}">"#);
    out.push_str("    <XForm>1 0 0 1 0 0</XForm>\n    <VertList>");
    for p in &pts {
        let _ = write!(out, "V{} {}", fixed(p.x, DECIMALS), fixed(p.y, DECIMALS));
    }
    out.push_str("</VertList>\n    <PrimList>");
    let n = pts.len();
    let segments = if closed { n } else { n - 1 };
    for i in 0..segments {
        let _ = write!(out, "L{} {}", i, (i + 1) % n);
    }
    out.push_str("</PrimList>\n  </Shape>\n");
    true
}
