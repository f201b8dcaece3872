//! How much of each file's crease length a perforation plan cuts: the table of issue-style
//! figures for patterns written by other tools (Origami Simulator's SVGs and FOLD files,
//! Rabbit Ear's, Flat-Folder's originals) and the bundled examples.
//!
//! ```text
//! cargo run --release --example perforated_share -- [--size MM] [--machine M] [--material X] FILE|DIR…
//! ```
//!
//! Each file is read and cleaned as `foldcam plan` reads it, sized to `--size` (default
//! 200 mm, the longer side), planned with the material's defaults (default `linuxcnc-fiber`
//! and `stainless-0.5`), and one row printed: the length of the creases the material
//! perforates, the dash length (toolpaths), their share, and how many creases got no dash.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use foldcam::fab::{Operation, PlanOptions, PlanOverrides, plan};
use foldcam::formats;
use foldcam::machine::{load_machine, load_material};
use foldcam::pattern::{Assignment, PlanarizeOptions, Scale, planarize};

fn main() -> ExitCode {
    let mut size = 200.0;
    let (mut machine_name, mut material_name) =
        ("linuxcnc-fiber".to_string(), "stainless-0.5".to_string());
    let mut inputs = Vec::new();
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--size" => size = args.next().and_then(|s| s.parse().ok()).unwrap_or(size),
            "--machine" => machine_name = args.next().unwrap_or(machine_name),
            "--material" => material_name = args.next().unwrap_or(material_name),
            other => inputs.push(PathBuf::from(other)),
        }
    }
    let (Ok(machine), Ok(material)) = (load_machine(&machine_name), load_material(&material_name))
    else {
        eprintln!("perforated_share: unknown machine or material");
        return ExitCode::from(2);
    };
    let Ok(options) = PlanOptions::for_machine(&machine, &material, &PlanOverrides::default())
    else {
        eprintln!("perforated_share: the material does not fit the machine");
        return ExitCode::from(2);
    };
    let mut files: Vec<PathBuf> = Vec::new();
    for input in inputs {
        if input.is_dir() {
            let mut listed: Vec<PathBuf> = std::fs::read_dir(&input)
                .into_iter()
                .flatten()
                .flatten()
                .map(|e| e.path())
                .filter(|p| formats::Format::from_path(p).is_some())
                .collect();
            listed.sort();
            files.extend(listed);
        } else {
            files.push(input);
        }
    }
    println!("| file | crease mm | dashes mm | perforated | creases without a dash |");
    println!("|---|---:|---:|---:|---:|");
    for file in &files {
        match row(file, size, &machine, &material, &options) {
            Ok(r) => println!("{r}"),
            Err(e) => println!("| {} | {e} | | | |", name(file)),
        }
    }
    ExitCode::SUCCESS
}

fn name(p: &Path) -> String {
    p.file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}

fn row(
    file: &Path,
    size: f64,
    machine: &foldcam::machine::MachineProfile,
    material: &foldcam::machine::Material,
    options: &PlanOptions,
) -> Result<String, String> {
    let mut cp = formats::load(file).map_err(|e| e.to_string())?.pattern;
    planarize(&mut cp, &PlanarizeOptions::default()).map_err(|e| e.to_string())?;
    cp.scale_to(Scale::Size(size)).map_err(|e| e.to_string())?;
    let crease: f64 = cp
        .edge_ids()
        .filter(|&e| {
            let m = &options.mapping;
            let op = match cp.edges[e.index()].assignment {
                Assignment::Mountain => m.mountain,
                Assignment::Valley => m.valley,
                Assignment::Unassigned => m.unassigned,
                Assignment::Flat => m.flat,
                _ => None,
            };
            op == Some(Operation::Perforate)
        })
        .map(|e| cp.edge_length(e))
        .sum();
    if crease == 0.0 {
        return Err("no crease to perforate".into());
    }
    let p = plan(&cp, machine, material, options).map_err(|e| e.to_string())?;
    let dashes: f64 = p
        .jobs
        .iter()
        .flat_map(|j| &j.paths)
        .filter(|t| t.op == Operation::Perforate)
        .flat_map(|t| &t.strokes)
        .map(|s| s.windows(2).map(|w| w[0].distance(w[1])).sum::<f64>())
        .sum();
    let uncut: usize = p
        .warnings
        .iter()
        .filter(|w| w.kind == foldcam::fab::PlanWarningKind::CreasesTooShort)
        .map(|w| {
            w.text
                .split_whitespace()
                .next()
                .and_then(|n| n.parse().ok())
                .unwrap_or(1)
        })
        .sum();
    Ok(format!(
        "| {} | {crease:.0} | {dashes:.0} | {:.1}% | {uncut} |",
        name(file),
        100.0 * dashes / crease
    ))
}
