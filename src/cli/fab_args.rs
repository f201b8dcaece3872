//! Arguments shared by `cut` and `plan`: machine, material and plan overrides.

use anyhow::{Context, Result};
use clap::Args;
use foldcam::fab::{Operation, PlanOptions, PlanSettings, parse_offset};
use foldcam::job::Job;
use foldcam::machine::{MachineProfile, Material, load_machine, load_material};

use foldcam::limits;

/// Checks an operation name or `skip` ([`Operation::choice`]) as it is parsed, so that a bad
/// one is refused with clap's usage; the request keeps the name.
fn operation(s: &str) -> Result<String, String> {
    Operation::choice(s).map(|_| s.to_string())
}

/// Checks `X,Y` in mm ([`parse_offset`]) as it is parsed; the request keeps the text.
fn offset(s: &str) -> Result<String, String> {
    parse_offset(s).map(|_| s.to_string())
}

/// Parses a duty cycle strictly between 0 and 1.
fn duty_cycle(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("{s:?} is not a number"))?;
    if v > 0.0 && v < 1.0 {
        Ok(v)
    } else {
        Err(format!(
            "{s} must be between 0 and 1 (the cut share of each period)"
        ))
    }
}

/// The machine and material profiles.
#[derive(Args, Clone, Debug)]
pub struct ProfileArgs {
    /// Machine profile: a shipped name (grbl-diode, marlin-laser, linuxcnc-fiber,
    /// grbl-pen-plotter, lightburn) or a path to a TOML file.
    #[arg(long, short = 'm')]
    pub machine: String,
    #[arg(
        long,
        short = 'x',
        help = "Material profile: a shipped name (stainless-0.5, stainless-0.3, card-300gsm, \
                paper-160gsm, polypropylene-0.5) or a path to a TOML file; it sets the defaults \
                of the options below (operations, kerf, perforation, design limits)",
        long_help = material_long_help()
    )]
    pub material: String,
}

/// The --material help with every shipped material's defaults (card scores its creases,
/// paper and stainless perforate them), read from the profiles themselves.
fn material_long_help() -> String {
    let shipped = foldcam::machine::profile_catalogue(foldcam::machine::ProfileKind::Material)
        .unwrap_or_default();
    let lines: Vec<String> = shipped
        .iter()
        .map(|e| format!("  {}: {}", e.name, e.defaults))
        .collect();
    format!(
        "Material profile: a shipped name or a path to a TOML file. It sets the defaults of the \
         options below (operations per line kind, kerf, perforation, design limits); the shipped \
         materials' (`foldcam list materials`):\n{}",
        lines.join("\n")
    )
}

impl ProfileArgs {
    /// Loads both profiles and resolves the plan options.
    pub fn resolve(&self, fab: &FabArgs) -> Result<(MachineProfile, Material, PlanOptions)> {
        fab.resolve(&self.machine, &self.material)
    }
}

/// Every plan setting a user may override.
#[derive(Args, Clone, Debug)]
pub struct FabArgs {
    /// Operation for mountain creases (mark, score, perforate, cut, plot, skip).
    #[arg(long, value_name = "OP", value_parser = operation)]
    pub mountain: Option<String>,
    /// Operation for valley creases.
    #[arg(long, value_name = "OP", value_parser = operation)]
    pub valley: Option<String>,
    /// Operation for unassigned creases.
    #[arg(long, value_name = "OP", value_parser = operation)]
    pub unassigned: Option<String>,
    /// Operation for flat (facet) lines.
    #[arg(long, value_name = "OP", value_parser = operation)]
    pub flat: Option<String>,
    /// Operation for boundary and cut lines.
    #[arg(long, value_name = "OP", value_parser = operation)]
    pub boundary: Option<String>,
    /// Perforation dash length, mm.
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::DASH.parse(s))]
    pub dash: Option<f64>,
    /// Perforation bridge: the material left between dashes, mm (the kerf is taken into
    /// account unless --no-kerf-offset).
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::BRIDGE.parse(s), conflicts_with = "duty")]
    pub bridge: Option<f64>,
    /// Perforation duty cycle instead of a bridge length: the cut share of each dash period,
    /// between 0 and 1 (exclusive); the bridge becomes dash × (1 − duty) / duty.
    #[arg(long, value_name = "SHARE", value_parser = duty_cycle)]
    pub duty: Option<f64>,
    /// Shortest perforation dash worth cutting, mm.
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::MIN_DASH.parse(s))]
    pub min_dash: Option<f64>,
    /// Least uncut material between two cuts (the web), mm.
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::MIN_WEB.parse(s))]
    pub min_web: Option<f64>,
    /// Uncut material kept around every vertex at least, mm: from the vertex to the burnt
    /// edge of the nearest dash (the kerf is taken into account unless --no-kerf-offset).
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::CLEARANCE.parse(s))]
    pub clearance: Option<f64>,
    /// Kerf width, mm (default from the material).
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::KERF.parse(s))]
    pub kerf: Option<f64>,
    /// Do not compensate the kerf: contours on the drawn lines, perforation bridges and vertex
    /// clearances measured on the beam's centre line.
    #[arg(long)]
    pub no_kerf_offset: bool,
    /// Mountains from the front, valleys from the back: two jobs, the second mirrored, with
    /// registration marks.
    #[arg(long)]
    pub two_sided: bool,
    /// Leave holding tabs of this width in closed contours, mm.
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::TAB_WIDTH.parse(s))]
    pub tabs: Option<f64>,
    /// Spacing between holding tabs, mm.
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::TAB_SPACING.parse(s), default_value_t = foldcam::fab::DEFAULT_TAB_SPACING_MM, requires = "tabs")]
    pub tab_spacing: f64,
    /// Lead-in length on the scrap side of closed contours, mm.
    #[arg(long, value_name = "MM", value_parser = |s: &str| limits::LEAD_IN.parse(s))]
    pub lead_in: Option<f64>,
    /// Distance from the bed origin to the pattern, mm.
    #[arg(long, value_name = "MM", default_value_t = foldcam::fab::DEFAULT_MARGIN_MM, value_parser = |s: &str| limits::MARGIN.parse(s))]
    pub margin: f64,
    /// Keep the pattern's order (no travel optimisation).
    #[arg(long)]
    pub no_optimize: bool,
    /// Where the job goes: the bed's origin corner (the margin away from it) or its centre.
    #[arg(long, value_enum, default_value_t = OriginArg::Corner)]
    pub origin: OriginArg,
    /// Shift the job by X,Y mm (x right, y towards the back of the bed) after placing it.
    #[arg(long, value_name = "X,Y", value_parser = offset, allow_hyphen_values = true)]
    pub offset: Option<String>,
}

/// `--origin`.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum OriginArg {
    /// The bed's origin corner (where the machine homes), the margin away from it.
    Corner,
    /// The centre of the bed.
    Centre,
}

impl FabArgs {
    /// The plan request these arguments make: the library's [`PlanSettings`], which the
    /// studio's requests deserialise into too.
    pub fn settings(&self) -> PlanSettings {
        PlanSettings {
            mountain: self.mountain.clone(),
            valley: self.valley.clone(),
            unassigned: self.unassigned.clone(),
            flat: self.flat.clone(),
            boundary: self.boundary.clone(),
            dash: self.dash,
            bridge: self.bridge,
            duty: self.duty,
            min_dash: self.min_dash,
            min_web: self.min_web,
            clearance: self.clearance,
            kerf: self.kerf,
            no_kerf_offset: self.no_kerf_offset,
            two_sided: self.two_sided,
            tabs: self.tabs,
            tab_spacing: Some(self.tab_spacing),
            lead_in: self.lead_in,
            margin: Some(self.margin),
            no_optimize: self.no_optimize,
            origin: Some(
                match self.origin {
                    OriginArg::Corner => "corner",
                    OriginArg::Centre => "centre",
                }
                .to_string(),
            ),
            offset: self.offset.clone(),
        }
    }

    /// Loads the profiles and resolves the plan options.
    pub fn resolve(
        &self,
        machine: &str,
        material: &str,
    ) -> Result<(MachineProfile, Material, PlanOptions)> {
        let machine = load_machine(machine)?;
        let material = load_material(material)?;
        let options = self.settings().options(&machine, &material)?;
        Ok((machine, material, options))
    }
}

/// Loads, cleans and sizes the input pattern.
pub fn load_pattern(
    path: &std::path::Path,
    frame: &super::input::FrameArg,
    scale: &super::args::ScaleArgs,
) -> Result<foldcam::pattern::CreasePattern> {
    let mut imported = super::input::load(path, frame)?;
    super::input::clean(path, &mut imported, None, false)?;
    scale.apply(&mut imported.pattern, imported.folded.as_mut())?;
    imported
        .pattern
        .require_millimetres()
        .with_context(|| path.display().to_string())?;
    Ok(imported.pattern)
}

/// A pattern file and everything needed to plan it: what `cut` and `plan` share.
#[derive(Args, Clone, Debug)]
pub struct PlanRequest {
    #[arg(help = super::input::pattern_help("Pattern file"))]
    pub input: std::path::PathBuf,
    #[command(flatten)]
    pub frame: super::input::FrameArg,
    #[command(flatten)]
    pub profiles: ProfileArgs,
    #[command(flatten)]
    pub fab: FabArgs,
    #[command(flatten)]
    pub scale: super::args::ScaleArgs,
}

/// A [`PlanRequest`] loaded: the profiles, the resolved options and the sized pattern.
pub struct Loaded {
    /// The machine profile.
    pub machine: MachineProfile,
    /// The material profile.
    pub material: Material,
    /// The plan options (material defaults, overrides, fitted to the machine).
    pub options: PlanOptions,
    /// The cleaned pattern, in millimetres.
    pub pattern: foldcam::pattern::CreasePattern,
}

impl PlanRequest {
    /// Loads the profiles and the pattern (warning when it cannot fold flat).
    pub fn load(&self) -> Result<Loaded> {
        let (machine, material, options) = self.profiles.resolve(&self.fab)?;
        let pattern = load_pattern(&self.input, &self.frame, &self.scale)?;
        if let Some(w) = foldcam::check::layers::flat_fold_warning(&pattern) {
            errln!("foldcam: warning: {}: {w}", self.input.display());
        }
        Ok(Loaded {
            machine,
            material,
            options,
            pattern,
        })
    }

    /// Loads the profiles and the pattern and plans it.
    pub fn plan(&self) -> Result<(MachineProfile, foldcam::fab::FabPlan)> {
        let l = self.load()?;
        let job = Job::plan_with(&l.pattern, &l.machine, &l.material, l.options)
            .with_context(|| self.input.display().to_string())?;
        let plan = job.plan;
        Ok((l.machine, plan))
    }
}
