//! The shared G-code writer: header, toolpath groups, passes, strokes, trailer.

use glam::DVec2;

use super::super::PostError;
use super::super::number::{Grid, fixed};
use super::Flavour;
use crate::fab::{FabPlan, Operation, Setup, Toolpath};
use crate::machine::control::AIR_OFF;
use crate::machine::sync_links;
use crate::machine::{MachineProfile, OperationSettings};

/// Units and distance mode, written once at the top of every program.
const HEADER: [&str; 2] = ["G21", "G90"];

/// `lines` without those equal to one of `written` (case, blanks and comments aside).
fn without(lines: &[String], written: &[String]) -> Vec<String> {
    let done: Vec<String> = written.iter().map(|l| super::normalize(l)).collect();
    lines
        .iter()
        .filter(|l| !done.contains(&super::normalize(l)))
        .cloned()
        .collect()
}

/// Decimals of printed feeds and powers.
const WORD_DECIMALS: usize = 3;

/// A program under construction.
struct Program<'a> {
    lines: Vec<String>,
    flavour: &'a dyn Flavour,
    grid: Grid,
    /// Where the tool is, in grid counts, once known.
    at: Option<(i64, i64)>,
    /// The modal feed last written.
    feed: Option<String>,
    /// Strokes burned so far.
    burned: usize,
    /// ` F…` for travel moves, when the dialect needs it.
    travel_feed: String,
    /// Air assist is on.
    air: bool,
    /// The feed of the moves linking two burns of one pass (`G1` with the tool off), when the
    /// machine links them so ([`MachineProfile::links_burns_with_feed_moves`]).
    link_feed: Option<String>,
    /// Shortest end piece of a burn and how far merging one may move the path, in grid counts,
    /// and LinuxCNC's tangent limit in radians (see [`sync_links`]), when the machine links
    /// burns with feed moves.
    tidy: Option<(f64, f64, f64)>,
}

/// Feed written on travel moves when the dialect shares `G0`'s feed with `G1`.
fn travel_feed(machine: &MachineProfile) -> String {
    fixed(
        machine.travel_feed_mm_min.min(machine.max_feed_mm_min),
        WORD_DECIMALS,
    )
}

/// How one toolpath is burned: the printed feed and power, and the passes.
struct Burn {
    feed: String,
    power: String,
    passes: u32,
}

impl<'a> Program<'a> {
    /// An empty program for `machine` in `flavour`, tool off, position unknown.
    fn new(flavour: &'a dyn Flavour, grid: Grid, machine: &MachineProfile) -> Self {
        Program {
            lines: Vec::new(),
            flavour,
            grid,
            at: None,
            feed: None,
            burned: 0,
            travel_feed: if flavour.travel_sets_feed() {
                format!(" F{}", travel_feed(machine))
            } else {
                String::new()
            },
            air: false,
            link_feed: machine
                .links_burns_with_feed_moves()
                .then(|| travel_feed(machine)),
            tidy: machine.links_burns_with_feed_moves().then(|| {
                (
                    sync_links::MIN_PIECE_MM / machine.resolution_mm,
                    sync_links::max_deviation_mm(machine) / machine.resolution_mm,
                    sync_links::tangent_limit_rad(machine),
                )
            }),
        }
    }
}

/// The whole program for `job`; inputs already validated.
pub fn write(
    plan: &FabPlan,
    job: &Setup,
    machine: &MachineProfile,
    flavour: &dyn Flavour,
    grid: Grid,
) -> Result<String, PostError> {
    let mut p = Program::new(flavour, grid, machine);
    p.header(plan, job, machine, true);
    let mut group = None;
    for path in &job.paths {
        let burn = burn(plan.settings_of(path, machine), machine);
        p.toolpath(path, &burn, machine, &mut group);
    }
    if p.burned == 0 {
        return Err(PostError::EmptyJob {
            job: job.name.clone(),
        });
    }
    p.trailer(machine);
    Ok(p.lines.join("\n") + "\n")
}

/// The program tracing `outline` for framing (see [`super::frame`]): the header, a travel to
/// its first point, then its points burned at `lit` (speed and power; one pass) or, when
/// `lit` is `None`, visited with travel moves (tool off), then the trailer.
pub fn write_frame(
    plan: &FabPlan,
    job: &Setup,
    outline: &[DVec2],
    lit: Option<OperationSettings>,
    machine: &MachineProfile,
    flavour: &dyn Flavour,
    grid: Grid,
) -> Result<String, PostError> {
    let mut p = Program::new(flavour, grid, machine);
    p.header(plan, job, machine, false);
    let Some(points) = p.snap(outline) else {
        return Err(PostError::EmptyJob {
            job: job.name.clone(),
        });
    };
    p.lines
        .push(flavour.comment("frame: the job's bounding box"));
    match lit {
        Some(s) => p.stroke(&points, &burn(s, machine)),
        None => {
            for &q in &points {
                p.travel(q);
            }
        }
    }
    p.trailer(machine);
    Ok(p.lines.join("\n") + "\n")
}

/// The header's lines about the plan: its source and material, then one line per operation of
/// `job` with the settings it runs with (power when the dialect burns with it, speed, passes,
/// and dash and gap for a perforation), and how many toolpaths run with settings of their own.
fn about(plan: &FabPlan, job: &Setup, machine: &MachineProfile, power: bool) -> Vec<String> {
    let source = plan
        .about
        .source
        .as_deref()
        .unwrap_or("a pattern without a name");
    let material = match plan.about.material.as_str() {
        "" => "not named",
        m => m,
    };
    let mut lines = vec![plain(&format!("source: {source}, material: {material}"))];
    let mut seen: Vec<Operation> = Vec::new();
    let mut own = 0;
    for path in &job.paths {
        if plan.override_of(path).is_some() {
            own += 1;
            continue;
        }
        if seen.contains(&path.op) {
            continue;
        }
        seen.push(path.op);
        let s = plan.settings_of(path, machine);
        let b = burn(s, machine);
        let mut line = format!("{}:", path.op.name());
        if power {
            line += &format!(" power {} (S{}),", fixed(s.power, 3), b.power);
        }
        line += &format!(
            " speed {} mm/min, {} pass{}",
            b.feed,
            b.passes,
            if b.passes == 1 { "" } else { "es" }
        );
        if path.op == Operation::Perforate {
            line += &format!(
                ", dash {} mm, gap {} mm",
                fixed(plan.about.dash_mm, WORD_DECIMALS),
                fixed(plan.about.bridge_mm, WORD_DECIMALS)
            );
        }
        lines.push(line);
    }
    if own > 0 {
        lines.push(format!(
            "{own} toolpath(s) with settings of their own, see their layers"
        ));
    }
    lines
}

/// `text` as every dialect's comment reader takes it: ASCII (`×` becomes `x`, `°` `d`, any other
/// character beyond ASCII `?`), without `;` (a comment of its own on GRBL and Marlin, and
/// where LinuxCNC would end a parenthesised one) or `%` (LinuxCNC's program delimiter).
fn plain(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            '×' => 'x',
            '°' => 'd',
            ';' => ',',
            '%' => '?',
            c if c.is_ascii() => c,
            _ => '?',
        })
        .collect()
}

/// Feed and power of settings `s` on `machine`.
fn burn(s: OperationSettings, machine: &MachineProfile) -> Burn {
    let feed = s.speed_mm_min.min(machine.max_feed_mm_min);
    let power = machine.power.min + s.power * (machine.power.max - machine.power.min);
    Burn {
        feed: fixed(feed, WORD_DECIMALS),
        power: fixed(power, WORD_DECIMALS),
        passes: s.passes,
    }
}

impl Program<'_> {
    /// Title comment, what the firmware must be set to, the source and material, the settings
    /// of each operation, units, absolute mode, arming (laser at zero or pen up), then
    /// the profile's preamble without the lines already written. A framing job (`settings`
    /// false) names the source and material only.
    fn header(&mut self, plan: &FabPlan, job: &Setup, machine: &MachineProfile, settings: bool) {
        let title = format!("foldcam: job {} for machine {}", job.name, machine.name);
        self.lines.push(self.flavour.comment(&title));
        if let Some(note) = self.flavour.expectation() {
            self.lines.push(self.flavour.comment(&note));
        }
        let mut about = about(plan, job, machine, self.flavour.uses_power());
        if !settings {
            about.truncate(1);
        }
        for line in about {
            self.lines.push(self.flavour.comment(&line));
        }
        let mut written: Vec<String> = HEADER.iter().map(|s| s.to_string()).collect();
        written.extend(self.flavour.start());
        self.lines.extend(written.iter().cloned());
        let preamble = without(&machine.preamble, &written);
        self.lines.extend(preamble);
    }

    /// Tool safe, air off, the profile's postamble without the lines already written, and
    /// the program end (once, last).
    fn trailer(&mut self, machine: &MachineProfile) {
        let mut written = self.flavour.finish();
        if self.air {
            written.push(AIR_OFF.to_string());
        }
        self.lines.extend(written.iter().cloned());
        written.extend(self.flavour.tool_off());
        let end = self.flavour.program_end();
        written.extend(end.map(str::to_string));
        self.lines.extend(without(&machine.postamble, &written));
        if let Some(end) = end {
            self.lines.push(end.to_string());
        }
    }

    /// All passes of one toolpath, after its group comment when the operation changes (and,
    /// between groups, the air switched and a plotter's pen-change pause).
    fn toolpath(
        &mut self,
        path: &Toolpath,
        burn: &Burn,
        machine: &MachineProfile,
        group: &mut Option<Operation>,
    ) {
        let mut strokes: Vec<_> = path.strokes.iter().filter_map(|s| self.snap(s)).collect();
        if let Some((min_piece, deviation, _)) = self.tidy {
            for s in &mut strokes {
                sync_links::tidy_ends(s, min_piece, deviation);
            }
        }
        if strokes.is_empty() {
            return;
        }
        if *group != Some(path.op) {
            // A group before this one was written: the pen changes between layers.
            if group.is_some() && machine.pauses_between_layers() {
                let note = format!("change the pen for layer {}, then resume", path.op.name());
                self.lines.push(self.flavour.comment(&note));
                self.lines
                    .extend(machine.control.pen_change.iter().cloned());
            }
            self.lines.push(self.flavour.comment(path.op.name()));
            let air = machine.air_for(path.op);
            if air != self.air {
                let word = match (&machine.control.air_assist, air) {
                    (Some(a), true) => a.on,
                    _ => AIR_OFF,
                };
                self.lines.push(word.to_string());
                self.air = air;
            }
            *group = Some(path.op);
        }
        for _ in 0..burn.passes {
            for (i, stroke) in strokes.iter().enumerate() {
                if i > 0 && self.at != Some(stroke[0]) {
                    self.link(&strokes[i - 1], stroke);
                }
                self.stroke(stroke, burn);
            }
        }
    }

    /// `stroke` in grid counts without repeated points, or `None` if it has no length.
    fn snap(&self, stroke: &[DVec2]) -> Option<Vec<(i64, i64)>> {
        let mut points: Vec<_> = stroke
            .iter()
            .map(|p| (self.grid.snap(p.x), self.grid.snap(p.y)))
            .collect();
        points.dedup();
        (points.len() >= 2).then_some(points)
    }

    /// Travel to the stroke's start if needed, switch the tool on, burn, switch it off.
    fn stroke(&mut self, points: &[(i64, i64)], burn: &Burn) {
        if self.at != Some(points[0]) {
            self.travel(points[0]);
        }
        self.lines.extend(self.flavour.tool_on(&burn.power));
        for (i, &p) in points[1..].iter().enumerate() {
            let mut line = format!("G1 {}", self.xy(p));
            if i == 0
                && let Some(word) = self.flavour.burn_word(&burn.power)
            {
                line = format!("{line} {word}");
            }
            if self.feed.as_deref() != Some(burn.feed.as_str()) {
                line = format!("{line} F{}", burn.feed);
                self.feed = Some(burn.feed.clone());
            }
            self.lines.push(line);
        }
        self.at = points.last().copied();
        self.lines.extend(self.flavour.tool_off());
        self.burned += 1;
    }

    /// Tool-off feed moves at the travel feed from the end of burn `prev` to the start of burn
    /// `next`, between two burns of one pass, where the machine links burns so: leaving and
    /// arriving along the burns ([`sync_links::link`]); elsewhere nothing (the next stroke
    /// travels there).
    fn link(&mut self, prev: &[(i64, i64)], next: &[(i64, i64)]) {
        let (Some(feed), Some((min_piece, _, tangent))) = (self.link_feed.clone(), self.tidy)
        else {
            return;
        };
        for to in sync_links::link(prev, next, min_piece, tangent) {
            let mut line = format!("G1 {}", self.xy(to));
            if self.feed.as_deref() != Some(feed.as_str()) {
                line = format!("{line} F{feed}");
                self.feed = Some(feed.clone());
            }
            self.lines.push(line);
            self.at = Some(to);
        }
    }

    /// A tool-off move to `to`.
    fn travel(&mut self, to: (i64, i64)) {
        let words = self.flavour.travel_words();
        let line = format!("G0 {}{words}{}", self.xy(to), self.travel_feed);
        self.lines.push(line);
        if !self.travel_feed.is_empty() {
            self.feed = None;
        }
    }

    /// `X… Y…` of a grid point.
    fn xy(&self, (x, y): (i64, i64)) -> String {
        format!("X{} Y{}", self.grid.print(x), self.grid.print(y))
    }
}
