//! The fabrication plan: toolpaths placed on the bed, split into sides, ordered, totalled.
//!
//! [`plan`] runs the whole pipeline: millimetres required, toolpaths from
//! [`super::geometry::toolpaths_with_warnings`], then [`plan_toolpaths`]:
//! 1. **Sides** ([`super::sides`]): one job `front`, or with `two_sided` a `front` job
//!    (mountains and everything else) and a `back` job (valleys, then all cuts), mirrored
//!    about the sheet's vertical centre line, both with registration marks.
//! 2. **Placement** ([`super::placement`]): the content's bounding box plus the margin, in the
//!    bed's origin corner, converted to machine coordinates; stored in [`Setup::to_machine`].
//! 3. **Order** ([`super::order`](mod@super::order)): precedence groups, nearest neighbour, 2-opt/Or-opt,
//!    joining, each job from the machine origin.
//! 4. **Statistics** ([`super::stats`]) and **warnings** (the material's design limits,
//!    checked with [`crate::check::check`]).
//!
//! Cost: O(n log n) in the number of toolpaths plus bounded improvement work, and the check's
//! O(E log d).

use glam::{DAffine2, DVec2};

use super::placement::{bounds_of, place_with, transform_paths, union};
use super::sides::{mirror, registration_marks, split};
use super::stats::{perforated_crease_mm, plan_stats};
use super::{
    FabError, FabPlan, PlanAbout, PlanOptions, PlanWarning, PlanWarningKind, Setup, Side, Toolpath,
    geometry, order,
};
use crate::check::{CheckOptions, FindingKind, check};
use crate::machine::{Bed, MachineProfile, Material, load_material, shipped_materials};
use crate::pattern::CreasePattern;

/// Plans `cp` (millimetres) for `machine` and `material`. The warnings list the design
/// limits the pattern exceeds, then the geometry's remarks (creases too short for a dash, …).
///
/// Errors: [`FabError::Unitless`] for a pattern without a physical size,
/// [`FabError::NothingToDo`] when no edge maps to an operation, [`FabError::DoesNotFit`]
/// when the pattern with its margins is larger than the bed, and the geometry's errors.
///
/// ```
/// use foldcam::{Assignment, PlanOptions, PlanOverrides, load_machine, load_material, plan};
/// let cp = foldcam::design::classic::MiuraOri::default().build()?;
/// let machine = load_machine("grbl-diode")?;
/// let card = load_material("card-300gsm")?;
/// let options = PlanOptions::for_machine(&machine, &card, &PlanOverrides::default())?;
/// let p = plan(&cp, &machine, &card, &options)?;
/// // Every boundary edge is cut by some toolpath, and the job lies on the bed.
/// let realised: Vec<_> = p.jobs.iter().flat_map(|j| &j.paths).flat_map(|t| &t.edges).collect();
/// for (i, e) in cp.edges.iter().enumerate() {
///     if e.assignment == Assignment::Boundary {
///         assert!(realised.iter().any(|r| r.index() == i), "boundary edge {i}");
///     }
/// }
/// let on_bed = |v: &foldcam::geom::DVec2| v.x >= 0.0 && v.y >= 0.0
///     && v.x <= machine.bed.width_mm && v.y <= machine.bed.height_mm;
/// assert!(p.jobs[0].paths.iter().flat_map(|t| &t.strokes).flatten().all(on_bed));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn plan(
    cp: &CreasePattern,
    machine: &MachineProfile,
    material: &Material,
    opts: &PlanOptions,
) -> Result<FabPlan, FabError> {
    cp.require_millimetres()?;
    opts.validate()?;
    let size = cp.bounds().map_or(0.0, |(lo, hi)| (hi - lo).max_element());
    opts.check_size("the pattern", size)?;
    let (paths, remarks) = geometry::toolpaths_with_warnings(cp, opts)?;
    let mut plan = plan_toolpaths(cp, paths, machine, material, opts)?;
    plan.warnings.extend(opts.notes.iter().cloned());
    plan.warnings.extend(remarks);
    plan.warnings.extend(facets_only_warning(cp, opts));
    Ok(plan)
}

/// A warning for a pattern whose only lines besides its outline are facet (F) lines that the
/// plan skips: the sheet is cut out but nothing on it is folded or weakened.
fn facets_only_warning(cp: &CreasePattern, opts: &PlanOptions) -> Option<PlanWarning> {
    let counts = crate::check::AssignmentCounts::of(cp);
    let creases = counts.mountain + counts.valley + counts.unassigned;
    (creases == 0 && counts.flat > 0 && opts.mapping.flat.is_none()).then(|| {
        PlanWarningKind::FacetsOnly.says(format!(
            "the pattern has no creases, only {} facet (flat) line(s), which the plan skips: only \
             the outline is cut (--flat mark or --flat score machines them)",
            counts.flat
        ))
    })
}

/// Plans given toolpaths of `cp` (pattern coordinates, mm, as [`geometry::toolpaths`] makes
/// them): everything [`plan`] does after the geometry.
pub fn plan_toolpaths(
    cp: &CreasePattern,
    mut paths: Vec<Toolpath>,
    machine: &MachineProfile,
    material: &Material,
    opts: &PlanOptions,
) -> Result<FabPlan, FabError> {
    cp.require_millimetres()?;
    for p in &mut paths {
        p.strokes.retain(|s| !s.is_empty());
    }
    if paths.iter().all(|p| p.strokes.is_empty()) {
        return Err(FabError::NothingToDo);
    }
    let mut warnings = design_limit_warnings(cp, material);
    warnings.extend(design_limit_advice(cp, material, &warnings));
    let (jobs, naive) = if opts.two_sided {
        two_sided_jobs(cp, paths, &machine.bed, opts, &mut warnings)?
    } else {
        one_sided_job(cp, paths, &machine.bed, opts)?
    };
    let mut plan = FabPlan {
        jobs,
        settings: material.settings,
        stats: Default::default(),
        warnings,
        mapping: opts.mapping,
        overrides: Vec::new(),
        about: PlanAbout {
            source: cp.meta.title.clone(),
            material: material.name.clone(),
            dash_mm: opts.perforation.cut_mm,
            bridge_mm: opts.perforation.bridge_mm,
        },
    };
    let crease_mm = perforated_crease_mm(cp, &opts.mapping);
    plan.stats = plan_stats(&plan, naive, crease_mm, machine);
    Ok(plan)
}

/// One job `front`; returns it with the naive travel.
fn one_sided_job(
    cp: &CreasePattern,
    paths: Vec<Toolpath>,
    bed: &Bed,
    opts: &PlanOptions,
) -> Result<(Vec<Setup>, f64), FabError> {
    let extent = content_extent(cp, &paths)?;
    let to_machine = place_with(extent, bed, opts.margin_mm, opts.placement)?;
    let (job, naive) = make_job("front", Side::Front, to_machine, paths, opts);
    Ok((vec![job], naive))
}

/// Jobs `front` and `back` with registration marks; returns them with the naive travel.
fn two_sided_jobs(
    cp: &CreasePattern,
    paths: Vec<Toolpath>,
    bed: &Bed,
    opts: &PlanOptions,
    warnings: &mut Vec<PlanWarning>,
) -> Result<(Vec<Setup>, f64), FabError> {
    let extent = content_extent(cp, &paths)?;
    let marks = registration_marks(extent);
    let sheet = union(Some(extent), bounds_of(&marks)).unwrap_or(extent);
    let to_machine = place_with(sheet, bed, opts.margin_mm, opts.placement)?;
    let flipped = to_machine * mirror((sheet.0.x + sheet.1.x) / 2.0);
    let (front, back) = split(cp, paths);
    if back.is_empty() {
        warnings.push(
            PlanWarningKind::EmptyBack
                .says("two-sided: nothing to do from the back (no valley, no cut)"),
        );
    }
    let (front, naive_front) = make_job(
        "front",
        Side::Front,
        to_machine,
        with_marks(&marks, front),
        opts,
    );
    let (back, naive_back) = make_job("back", Side::Back, flipped, with_marks(&marks, back), opts);
    Ok((vec![front, back], naive_front + naive_back))
}

/// `marks` followed by `paths`, containers shifted accordingly.
fn with_marks(marks: &[Toolpath], paths: Vec<Toolpath>) -> Vec<Toolpath> {
    let shift = marks.len();
    let mut out = marks.to_vec();
    out.extend(paths.into_iter().map(|mut p| {
        p.container = p.container.map(|c| c + shift);
        p
    }));
    out
}

/// Transforms and orders `paths` into a job; also returns the travel of the given order.
fn make_job(
    name: &str,
    side: Side,
    to_machine: DAffine2,
    mut paths: Vec<Toolpath>,
    opts: &PlanOptions,
) -> (Setup, f64) {
    transform_paths(&mut paths, &to_machine);
    let naive = order::travel_mm(&paths, DVec2::ZERO);
    let job = Setup {
        name: name.to_owned(),
        side,
        to_machine,
        paths: order::order(paths, DVec2::ZERO, opts.optimize),
    };
    (job, naive)
}

/// The pattern's bounds together with every toolpath point (kerf offsets and lead-ins may
/// reach past the pattern).
fn content_extent(cp: &CreasePattern, paths: &[Toolpath]) -> Result<(DVec2, DVec2), FabError> {
    union(cp.bounds(), bounds_of(paths)).ok_or(FabError::NothingToDo)
}

/// The check options of `material`'s design limits alone (no flat-foldability).
fn limit_options(material: &Material) -> CheckOptions {
    CheckOptions {
        flat_foldability: false,
        ..material.check_options()
    }
}

/// Whether `cp` keeps within `material`'s design limits.
fn meets_design_limits(cp: &CreasePattern, material: &Material) -> bool {
    check(cp, &limit_options(material)).passed()
}

/// What to do about the limit warnings `warnings` (from [`design_limit_warnings`]; `None`
/// when there are none): the limits only warn, so the job is written; the shipped materials
/// whose limits the pattern meets; and how to see the creases and vertices beyond the limits
/// (`check` lists them, `preview --check` rings them).
fn design_limit_advice(
    cp: &CreasePattern,
    material: &Material,
    warnings: &[PlanWarning],
) -> Option<PlanWarning> {
    if warnings.is_empty() {
        return None;
    }
    let fitting: Vec<&str> = shipped_materials()
        .into_iter()
        .filter(|&name| name != material.name)
        .filter(|&name| load_material(name).is_ok_and(|m| meets_design_limits(cp, &m)))
        .collect();
    let others = match fitting.as_slice() {
        [] => "change the pattern (no shipped material's limits allow it)".to_string(),
        names => format!(
            "change the pattern or take a shipped material whose limits it meets: {} (`foldcam \
             list materials`)",
            names.join(", ")
        ),
    };
    let l = &material.limits;
    let limits = format!(
        "--min-vertex-angle {} --max-fold-angle {}",
        l.min_vertex_angle_deg, l.max_fold_angle_deg
    );
    Some(PlanWarningKind::LimitAdvice.says(format!(
        "{}'s limits only warn, so the job was written all the same (no option is needed to \
         allow them); to keep within them, {others}; `foldcam check PATTERN {limits}` lists the \
         vertices and creases beyond them, `foldcam preview PATTERN --check {limits} -o PNG` \
         rings them on a picture",
        material.name
    )))
}

/// One warning per design limit of `material` that `cp` exceeds, with counts.
pub fn design_limit_warnings(cp: &CreasePattern, material: &Material) -> Vec<PlanWarning> {
    let opts = limit_options(material);
    let report = check(cp, &opts);
    let mut out = Vec::new();
    let angles = report.of_kind(FindingKind::VertexAngle).count();
    if let (true, Some(l)) = (angles > 0, opts.min_vertex_angle_deg) {
        let worst = report
            .summary
            .smallest_crease_angle
            .as_ref()
            .map(|m| m.degrees);
        out.push(PlanWarningKind::VertexAngleLimit.says(format!(
            "{angles} vertices have creases closer than {l}°, the smallest angle {} allows{}",
            material.name,
            worst.map_or(String::new(), |w| format!(" (smallest {w:.1}°)"))
        ))
        .on(report
            .of_kind(FindingKind::VertexAngle)
            .filter_map(|f| f.edge)));
    }
    let folds: Vec<_> = report.of_kind(FindingKind::FoldAngle).collect();
    if let (false, Some(l)) = (folds.is_empty(), opts.max_fold_angle_deg) {
        let unknown = folds
            .iter()
            .filter_map(|f| cp.edges.get(f.edge?.index()))
            .filter(|e| e.fold_angle.is_none())
            .count();
        let note = if unknown > 0 {
            format!(" ({unknown} of them have no stored fold angle and count as folded flat)")
        } else {
            String::new()
        };
        out.push(
            PlanWarningKind::FoldAngleLimit
                .says(format!(
                    "{} edges fold further than {l}°, the largest fold angle {} allows{note}",
                    folds.len(),
                    material.name
                ))
                .on(folds.iter().filter_map(|f| f.edge)),
        );
    }
    out
}
