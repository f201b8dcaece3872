//! `foldcam demo`: the pipeline end to end on bundled examples.
//!
//! Generates the classic patterns, adds the sample files bundled in the binary (from
//! `examples/patterns/`), and for each: writes FOLD, SVG and `.cp`, reads every file back and
//! compares it with the original, checks it, and draws a preview with faults ringed; then
//! plans three of them for a laser, a fiber laser and a pen plotter, writes the G-code, reads
//! it back on the simulated machine, checks coverage and draws the toolpath.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result, bail};
use foldcam::check::{CheckOptions, check};
use foldcam::design::classic::{MiuraOri, SquareTwist, Waterbomb, Yoshimura};
use foldcam::formats::{self, Format, write_atomic};
use foldcam::pattern::{Assignment, CreasePattern, PlanarizeOptions, Units, planarize};
use foldcam::render::{PreviewOptions, preview_png};

use super::Outcome;
use super::demo_jobs::{DemoIndex, WrittenJob, write_job};

/// Sample files compiled into the binary, so the demo runs from any folder.
const SAMPLES: &[(&str, &str)] = &[
    (
        "flat-vertex.fold",
        include_str!("../../examples/patterns/flat-vertex.fold"),
    ),
    (
        "broken-vertex.fold",
        include_str!("../../examples/patterns/broken-vertex.fold"),
    ),
    (
        "preliminary-base.cp",
        include_str!("../../examples/patterns/preliminary-base.cp"),
    ),
];

/// Run the whole pipeline on bundled examples.
#[derive(clap::Args)]
#[command(after_help = "Example:\n  foldcam demo --out demo-out")]
pub struct Args {
    /// Folder for the results (created if missing).
    #[arg(value_name = "DIR", long, default_value = "foldcam-demo")]
    pub out: PathBuf,
    /// Preview width in pixels.
    #[arg(value_name = "PX", long, default_value_t = 900)]
    pub width: u32,
}

/// Runs the demo.
pub fn run(args: Args) -> Result<Outcome> {
    super::outputs::no_stdout(&args.out, "the demo's folder of results")?;
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("{}: cannot create the folder", args.out.display()))?;
    let start = Instant::now();
    let mut cases = classics()?;
    for (name, text) in SAMPLES {
        let format = Format::from_path(Path::new(name)).context("sample extension")?;
        let mut imported =
            formats::parse(format, text).map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
        planarize(&mut imported.pattern, &PlanarizeOptions::default())
            .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
        if imported.pattern.units == Units::Unitless {
            let size = super::args::ScaleArgs {
                scale: None,
                size: Some(UNITLESS_SIZE_MM),
            };
            size.apply(&mut imported.pattern, None)?;
        }
        let stem = name.rsplit_once('.').map_or(*name, |(s, _)| s);
        cases.push((stem.to_string(), imported.pattern));
    }
    outln!(
        "{:<22} {:>6} {:>6}  {:<9} {:<28} preview",
        "pattern",
        "verts",
        "edges",
        "check",
        "round trips (fold svg cp)"
    );
    let mut failures = Vec::new();
    for (name, cp) in &cases {
        let trips = round_trips(&args.out, name, cp)?;
        let report = check(cp, &CheckOptions::default());
        let png = preview_png(
            cp,
            &PreviewOptions {
                width: args.width,
                ..PreviewOptions::default()
            },
            &report.findings,
        )
        .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
        let png_path = args.out.join(format!("{name}.png"));
        write_atomic(&png_path, &png).with_context(|| png_path.display().to_string())?;
        let verdict = if report.passed() && !report.checked_folding() {
            format!("pass, {} not checked", report.unchecked_vertices)
        } else if report.passed() {
            "pass".to_string()
        } else {
            format!("{} faults", report.findings.len())
        };
        outln!(
            "{:<22} {:>6} {:>6}  {:<9} {:<28} {}",
            name,
            cp.vertices.len(),
            cp.edges.len(),
            verdict,
            trips.join(" "),
            png_path.display()
        );
        if trips.iter().any(|t| t != "ok") {
            failures.push(name.clone());
        }
    }
    outln!(
        "\n{} patterns in {:.2} s; files in {}/ (broken-vertex is meant to fail its check)",
        cases.len(),
        start.elapsed().as_secs_f64(),
        args.out.display()
    );
    if !failures.is_empty() {
        bail!("round trip lost data for: {}", failures.join(", "));
    }
    let mut index = DemoIndex::default();
    for (name, _) in &cases {
        index.picture(
            format!("{name}.png"),
            format!("{name}: crease pattern, faults ringed"),
        );
    }
    machine_jobs(&args.out, &mut index, &cases)?;
    popup_card(&args.out, &mut index, args.width)?;
    super::demo_tessellation::dome(&args.out, &mut index, args.width)?;
    super::demo_tessellation::mask(&args.out, &mut index, args.width)?;
    super::demo_papercraft::vase(&args.out, &mut index, args.width)?;
    super::demo_fold3d::miura(&args.out, &mut index, args.width)?;
    index.write(&args.out)?;
    outln!(
        "{}: every job with its machine, material, time and toolpath, and every picture",
        args.out.join("index.html").display()
    );
    Ok(Outcome::Done)
}

/// Size given to unitless samples (ORIPA files), as `--size` would: SVG and G-code need one.
const UNITLESS_SIZE_MM: f64 = 150.0;

fn classics() -> Result<Vec<(String, CreasePattern)>> {
    Ok(vec![
        ("miura-ori".into(), MiuraOri::default().build()?),
        ("square-twist".into(), SquareTwist::default().build()?),
        ("waterbomb".into(), Waterbomb::default().build()?),
        ("yoshimura".into(), Yoshimura::default().build()?),
    ])
}

/// Writes the pattern in each format, reads it back and compares; "ok" or what differs.
fn round_trips(dir: &Path, name: &str, cp: &CreasePattern) -> Result<Vec<String>> {
    let mut out = Vec::new();
    for ext in ["fold", "svg", "cp"] {
        let path = dir.join(format!("{name}.{ext}"));
        formats::save(&path, cp, None)?;
        let back = formats::load(&path)?.pattern;
        out.push(compare(cp, &back, ext == "cp"));
    }
    Ok(out)
}

/// Compares edge counts per assignment and total crease length. `.cp` cannot tell flat from
/// unassigned and has no cut type, so those are compared as one class there.
fn compare(a: &CreasePattern, b: &CreasePattern, cp_vocabulary: bool) -> String {
    let class = |k: Assignment| match (cp_vocabulary, k) {
        (true, Assignment::Cut) => Assignment::Boundary,
        (true, Assignment::Unassigned | Assignment::Join) => Assignment::Flat,
        _ => k,
    };
    let summary = |p: &CreasePattern| {
        let mut counts = std::collections::BTreeMap::new();
        for e in p.edge_ids() {
            let k = class(p.edges[e.index()].assignment);
            *counts.entry(k).or_insert(0.0) += p.edge_length(e);
        }
        counts
    };
    let (sa, sb) = (summary(a), summary(b));
    if a.edges.len() != b.edges.len() {
        return format!("edges {}≠{}", a.edges.len(), b.edges.len());
    }
    let scale = a
        .bounds()
        .map_or(1.0, |(lo, hi)| lo.distance(hi).max(1e-12));
    let same = sa.len() == sb.len()
        && sa
            .iter()
            .zip(&sb)
            .all(|((ka, la), (kb, lb))| ka == kb && (la - lb).abs() <= 1e-6 * scale);
    if same {
        "ok".into()
    } else {
        "lengths differ".into()
    }
}

/// Machine jobs for three classics: planned, written, read back by the simulated machine and
/// checked against the pattern; the toolpath drawn.
fn machine_jobs(
    dir: &Path,
    index: &mut DemoIndex,
    cases: &[(String, CreasePattern)],
) -> Result<()> {
    let jobs = [
        ("miura-ori", "grbl-diode", "card-300gsm"),
        ("square-twist", "linuxcnc-fiber", "stainless-0.5"),
        ("yoshimura", "grbl-pen-plotter", "paper-160gsm"),
    ];
    outln!(
        "\n{:<14} {:<17} {:<15} {:>9} {:>8} {:>9}  sim / coverage",
        "pattern",
        "machine",
        "material",
        "burn mm",
        "pierces",
        "time"
    );
    for (name, machine_name, material_name) in jobs {
        let Some((_, cp)) = cases.iter().find(|(n, _)| n == name) else {
            continue;
        };
        let WrittenJob {
            run,
            clean,
            edges_off,
            ..
        } = write_job(dir, index, name, cp, machine_name, material_name)?;
        let verdict = if clean {
            "clean / all edges as planned".to_string()
        } else {
            format!("{} violations / {edges_off} edges off", run.violation_count)
        };
        outln!(
            "{:<14} {:<17} {:<15} {:>9.0} {:>8} {:>8.0}s  {}",
            name,
            machine_name,
            material_name,
            run.burn_length_mm,
            run.pierces,
            run.time_s,
            verdict
        );
        if !clean {
            bail!("{name} on {machine_name}: the simulated machine found problems");
        }
    }
    outln!(
        "machine jobs and toolpath pictures are in {}/",
        dir.display()
    );
    Ok(())
}

/// The bundled voxel house and building mesh (Mitani, Suzuki & Uno 2003): made into cards (the mesh
/// through the paper's mesh conversion), checked, unfolded into crease patterns, drawn standing and opening, and cut from card
/// on the diode laser through the simulated machine.
fn popup_card(dir: &Path, index: &mut DemoIndex, width: u32) -> Result<()> {
    use foldcam::design::popup::voxel::{
        ConvertOptions, MeshPlacement, card_from_depths, depth_field_from_mesh, parse_voxel_card,
    };
    let text = include_str!("../../examples/popup/house.voxel.txt");
    let house = parse_voxel_card(text).map_err(|e| anyhow::anyhow!("house.voxel.txt: {e}"))?;
    show_card(dir, index, width, "popup-house", &house)?;
    let obj = include_bytes!("../../examples/popup/building.obj");
    let mesh = foldcam::mesh::parse_obj(obj).map_err(|e| anyhow::anyhow!("building.obj: {e}"))?;
    let (field, _) = depth_field_from_mesh(&mesh, &MeshPlacement::default())
        .map_err(|e| anyhow::anyhow!("building.obj: {e}"))?;
    let (mut building, report) = card_from_depths(&field, 2.0, &ConvertOptions::default())
        .map_err(|e| anyhow::anyhow!("building.obj: {e}"))?;
    building.set_margin_mm(10.0)?;
    outln!(
        "building.obj: {} faces seen from the front; filling under overhangs added {} voxels, {} rows became windows, {} thin tops left out",
        mesh.faces().len(),
        report.added_cells,
        report.window_rows,
        report.tops_omitted
    );
    show_card(dir, index, width, "popup-building", &building)
}

fn show_card(
    dir: &Path,
    index: &mut DemoIndex,
    width: u32,
    name: &str,
    card: &foldcam::design::popup::voxel::VoxelCard,
) -> Result<()> {
    use foldcam::design::popup::voxel::{check_popup, crease_pattern, fold_card};
    use foldcam::render::{render_folded_png, render_gif};
    if !check_popup(card).passed() {
        bail!("{name}: the bundled card does not pop up");
    }
    let cp = crease_pattern(card).map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
    formats::save(&dir.join(format!("{name}.fold")), &cp, None)?;
    let view = super::popup::card_view(width.min(640));
    let held = |angle: f64| foldcam::design::popup::as_held(&fold_card(card, &cp, angle).state);
    let standing = render_folded_png(
        &held(90.0),
        &view.clone().with_key("card opened to 90°", "mm"),
    )?;
    write_atomic(&dir.join(format!("{name}.png")), &standing).context("png")?;
    let frames: Vec<_> = (0..=12)
        .map(|k| held(10.0 + 80.0 * f64::from(k) / 12.0))
        .collect();
    let view = view.with_key("card opening from 10° to 90°", "mm");
    let gif = render_gif(&frames, &view, 100)?;
    write_atomic(&dir.join(format!("{name}.gif")), &gif).context("gif")?;
    index.picture(format!("{name}.png"), format!("{name}: the card standing"));
    index.picture(format!("{name}.gif"), format!("{name}: the card opening"));
    let job = write_job(dir, index, name, &cp, "grbl-diode", "card-300gsm")?;
    let clean = job.clean;
    outln!(
        "\n{name} (voxel pop-up, Mitani, Suzuki & Uno 2003): {} × {} × {} voxels, pops up; {} creases and cuts; \
         {} {}; {name}.png and .gif show it standing and opening",
        card.nx(),
        card.ny(),
        card.nz(),
        cp.edges.len(),
        job.file,
        if clean { "clean" } else { "NOT clean" }
    );
    if !clean {
        bail!("{name}: the simulated machine found problems");
    }
    Ok(())
}
