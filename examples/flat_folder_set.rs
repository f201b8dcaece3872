//! Runs the layer-order solver over Flat-Folder's published examples and compares the state
//! counts with Flat-Folder's own (Jason Ku's Flat-Folder; the files and counts are in
//! `../shared/testdata/flat-folder`, MIT licence).
//!
//! ```text
//! cargo run --release --example flat_folder_set -- [--timeout SECONDS] [--filter TEXT] [DIR]
//! cargo run --release --example flat_folder_set -- --explain FILE
//! ```
//!
//! Each pattern runs in a child process (this program with `--one FILE`) so a pattern that
//! exceeds the time cap is stopped cleanly. Where Flat-Folder capped its count (its
//! `limited` column), ours counts with the same cap per component, and both are lower
//! bounds. Prints one line per pattern, then the matches, the differences (listed), the
//! patterns the local checks refuse (with what the layer solver alone finds), the time-outs,
//! the total time and the ten slowest designs.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use foldcam::check::layers::{KawasakiTolerance, LayerOptions, local_faults, solve_layers};
use foldcam::formats;
use foldcam::pattern::{PlanarizeOptions, planarize};

/// One row of Flat-Folder's CSV that we compare with.
struct Row {
    file: PathBuf,
    title: String,
    states: String,
    /// Flat-Folder's per-component cap when it limited the count (its `limited` column;
    /// `None`: an exact count): ours runs with the same cap, so both are lower bounds of the
    /// same kind.
    cap: Option<u64>,
    ff_seconds: f64,
}

pub fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--one") {
        let cap = args.get(2).and_then(|s| s.parse().ok());
        return one(Path::new(args.get(1).map_or("", String::as_str)), cap);
    }
    if args.first().map(String::as_str) == Some("--explain") {
        let near: Vec<f64> = args[2..].iter().filter_map(|a| a.parse().ok()).collect();
        return explain(Path::new(args.get(1).map_or("", String::as_str)), &near);
    }
    let mut timeout = 30.0;
    let mut filter = String::new();
    let mut dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/testdata/flat-folder");
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--timeout" => timeout = it.next().and_then(|s| s.parse().ok()).unwrap_or(timeout),
            "--filter" => filter = it.next().cloned().unwrap_or_default(),
            other => dir = PathBuf::from(other),
        }
    }
    let mut rows = Vec::new();
    for (csv, sub) in [
        ("grids_data.csv", "grids"),
        ("instagram_data.csv", "instagram"),
    ] {
        match read_rows(&dir, csv, sub) {
            Ok(r) => rows.extend(r),
            Err(e) => {
                eprintln!("flat_folder_set: {e}");
                return ExitCode::from(2);
            }
        }
    }
    for entry in std::fs::read_dir(dir.join("unsatisfiable"))
        .into_iter()
        .flatten()
        .flatten()
    {
        rows.push(Row {
            title: entry.file_name().to_string_lossy().into_owned(),
            file: entry.path(),
            states: "0".into(),
            cap: None,
            ff_seconds: 0.0,
        });
    }
    rows.retain(|r| r.file.to_string_lossy().contains(&filter));
    let exe = match std::env::current_exe() {
        Ok(e) => e,
        Err(e) => {
            eprintln!("flat_folder_set: {e}");
            return ExitCode::from(2);
        }
    };
    let (mut matches, mut differ, mut timeouts) = (0, Vec::new(), Vec::new());
    let mut capped_matches = 0;
    let mut local = Vec::new();
    let mut times: Vec<(f64, String, f64)> = Vec::new();
    let start = Instant::now();
    for row in &rows {
        let t0 = Instant::now();
        let out = run_child(&exe, &row.file, row.cap, Duration::from_secs_f64(timeout));
        let secs = t0.elapsed().as_secs_f64();
        let name = row
            .file
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        match out {
            None => {
                println!("TIMEOUT  {name} (Flat-Folder {:.2} s)", row.ff_seconds);
                timeouts.push(name.clone());
            }
            Some(line) => {
                let ours = line.split_whitespace().next().unwrap_or("?").to_string();
                if line.starts_with("local-fail") {
                    println!("LOCAL    {name}: ours {line}, Flat-Folder {}", row.states);
                    local.push(format!("{name}: {line}; Flat-Folder {}", row.states));
                } else if let Some(cap) = row.cap {
                    // Both lower bounds, each component counted up to the same cap.
                    if ours == row.states {
                        capped_matches += 1;
                        println!(
                            "ok ≥     {name}: ≥ {ours} ({secs:.3} s, Flat-Folder {:.3} s), at \
                             most {cap} states per component",
                            row.ff_seconds
                        );
                    } else {
                        println!(
                            "DIFFER ≥ {name}: ours {line}, Flat-Folder ≥ {}, at most {cap} \
                             states per component",
                            row.states
                        );
                        differ.push(format!(
                            "{name} ({}): ours {line}, Flat-Folder ≥ {} (capped at {cap})",
                            row.title, row.states
                        ));
                    }
                } else if ours == row.states {
                    matches += 1;
                    println!(
                        "ok       {name}: {ours} ({secs:.3} s, Flat-Folder {:.3} s)",
                        row.ff_seconds
                    );
                } else {
                    println!("DIFFER   {name}: ours {line}, Flat-Folder {}", row.states);
                    differ.push(format!(
                        "{name} ({}): ours {line}, Flat-Folder {}",
                        row.title, row.states
                    ));
                }
            }
        }
        times.push((secs, name, row.ff_seconds));
        let _ = std::io::stdout().flush();
    }
    times.sort_by(|a, b| b.0.total_cmp(&a.0));
    println!("\n{} patterns, per-file cap {timeout} s", rows.len());
    println!("match: {matches} exact, {capped_matches} lower bounds at Flat-Folder's cap");
    println!("differ: {}", differ.len());
    for d in &differ {
        println!("  {d}");
    }
    println!(
        "refused by the local checks (Kawasaki or Maekawa beyond foldcam's tolerance): {}",
        local.len()
    );
    for l in &local {
        println!("  {l}");
    }
    println!("time out: {} {:?}", timeouts.len(), timeouts);
    println!("total time: {:.1} s", start.elapsed().as_secs_f64());
    let slow: Vec<String> = times
        .iter()
        .filter(|(t, _, ff)| *ff <= 60.0 && *t > 5.0)
        .map(|(t, n, ff)| format!("{n} ({t:.1} s; Flat-Folder {ff:.1} s)"))
        .collect();
    println!(
        "over 5 s here among the designs Flat-Folder finished within 60 s: {}",
        slow.len()
    );
    for s in &slow {
        println!("  {s}");
    }
    println!("ten slowest:");
    for (t, n, ff) in times.iter().take(10) {
        println!("  {t:8.3} s  {n} (Flat-Folder's published time {ff:.2} s)");
    }
    ExitCode::SUCCESS
}

fn read_rows(dir: &Path, csv: &str, sub: &str) -> Result<Vec<Row>, String> {
    let text = std::fs::read_to_string(dir.join(csv)).map_err(|e| format!("{csv}: {e}"))?;
    let files: Vec<PathBuf> = std::fs::read_dir(dir.join(sub))
        .map_err(|e| format!("{sub}: {e}"))?
        .flatten()
        .map(|e| e.path())
        .collect();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name);
    let (Some(num), Some(limited), Some(states), Some(setup), Some(solve)) = (
        col("number").or_else(|| col("Number")),
        col("limited"),
        col("states"),
        col("setup_sec"),
        col("solve_sec"),
    ) else {
        return Err(format!("{csv}: unexpected columns"));
    };
    let mut rows = Vec::new();
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        if cells.len() < header.len() {
            continue;
        }
        // titles hold no commas in these files; the columns line up from the end as well
        let number = cells[num];
        let Some(file) = files.iter().find(|f| {
            f.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with(&format!("{number}_")))
        }) else {
            continue;
        };
        let seconds =
            cells[setup].parse::<f64>().unwrap_or(0.0) + cells[solve].parse::<f64>().unwrap_or(0.0);
        rows.push(Row {
            file: file.clone(),
            title: cells[2].to_string(),
            states: cells[states].to_string(),
            cap: cells[limited].parse().ok(),
            ff_seconds: seconds,
        });
    }
    Ok(rows)
}

/// Runs `exe --one file [cap]`, killing it after `limit`; its first output line, or `None`
/// on time-out.
fn run_child(exe: &Path, file: &Path, cap: Option<u64>, limit: Duration) -> Option<String> {
    let mut child = Command::new(exe)
        .arg("--one")
        .arg(file)
        .args(cap.map(|c| c.to_string()))
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let t0 = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(_)) => break,
            Ok(None) if t0.elapsed() < limit => std::thread::sleep(Duration::from_millis(5)),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                return None;
            }
        }
    }
    let out = child.wait_with_output().ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    Some(
        text.lines()
            .next()
            .unwrap_or("error: no output")
            .to_string(),
    )
}

/// Solves one file (each component counted up to `cap` states, when given) and prints
/// `STATES exact|capped components` or `error: ...`.
fn one(path: &Path, cap: Option<u64>) -> ExitCode {
    let layer_options = LayerOptions {
        max_states: cap,
        ..LayerOptions::default()
    };
    let mut cp = match formats::load(path) {
        Ok(i) => i.pattern,
        Err(e) => {
            println!("error: {e}");
            return ExitCode::SUCCESS;
        }
    };
    let options = PlanarizeOptions {
        tolerance: None,
        faces: true,
    };
    if let Err(e) = planarize(&mut cp, &options) {
        println!("error: {e}");
        return ExitCode::SUCCESS;
    }
    // The local faults the layer check stops at (Kawasaki within the tolerance fitted to the
    // drawing is rounding, as `check --layers` takes it).
    let faults = local_faults(&cp, KawasakiTolerance::Fitted);
    if let Some(f) = faults.first_refusal() {
        // Say what the layer solver alone makes of it, for the report.
        let alone = match solve_layers(&cp, &LayerOptions::default()) {
            Ok(r) => r.states,
            Err(e) => format!("error: {e}"),
        };
        println!(
            "local-fail {} findings (worst {:.4}, allowed {:.4}); the layer solver alone: {alone}",
            faults.refusing.len(),
            f.value,
            f.limit
        );
        return ExitCode::SUCCESS;
    }
    if !faults.rounding.is_empty() {
        eprintln!(
            "rounding: {} Kawasaki errors within the fitted tolerance (largest {:.4}°)",
            faults.rounding.len(),
            faults.rounding.iter().map(|f| f.value).fold(0.0, f64::max)
        );
    }
    match solve_layers(&cp, &layer_options) {
        Ok(r) => {
            println!(
                "{} {} components={} variables={} constraints={:?} comps={:?}",
                r.states,
                if r.exact { "exact" } else { "capped" },
                r.components,
                r.variables,
                r.constraints,
                r.component_states
                    .iter()
                    .map(|c| c.states.clone())
                    .collect::<Vec<_>>()
            );
            // A second line (the set's summary reads only the first): where a
            // contradiction is.
            if let Some(c) = &r.contradiction {
                println!(
                    "contradiction {}: faces {:?} at folded {:?}, pattern {:?}",
                    c.kind, c.faces, c.folded_position, c.positions
                );
            }
        }
        Err(e) => println!("error: {e}"),
    }
    ExitCode::SUCCESS
}

/// Prints, for one file, the merge distance the arrangement settled on as a divisor of the
/// shortest folded edge (Flat-Folder's CSV column `eps` is the divisor it settled on), the
/// numbers of cells and segments, and the solver's counts.
///
/// With `near` = `[x, y, r]` (folded coordinates), also lists the arrangement's segments
/// within `r` of `(x, y)`: their ends, the pattern faces of the cells on either side and the
/// pattern edges along them.
fn explain(path: &Path, near: &[f64]) -> ExitCode {
    let mut cp = match formats::load(path) {
        Ok(i) => i.pattern,
        Err(e) => {
            println!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let options = PlanarizeOptions {
        tolerance: None,
        faces: true,
    };
    if let Err(e) = planarize(&mut cp, &options) {
        println!("error: {e}");
        return ExitCode::from(2);
    }
    // Any gap between two placements of a vertex is let through: this only looks at geometry.
    let folded = match foldcam::check::layers::fold_faces(&cp, f64::MAX) {
        Ok(f) => f,
        Err(e) => {
            println!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let shortest = cp
        .edges
        .iter()
        .zip(&folded.edge_faces)
        .filter_map(|(e, sides)| {
            let f = *sides.iter().flatten().next()?;
            let [a, b] = e.vertices.map(|v| folded.point(&cp, f, v));
            Some(a.distance(b))
        })
        .fold(f64::MAX, f64::min);
    let diag = cp.bounds().map_or(0.0, |(lo, hi)| lo.distance(hi));
    let floor = (diag * foldcam::check::layers::RELATIVE_TOLERANCE).max(1e-12);
    let (arr, tol) = foldcam::check::layers::arrange(&cp, &folded, floor);
    println!(
        "chosen tol {tol:.3e} (shortest / {:.0}): {} cells, {} segments",
        shortest / tol,
        arr.cell_faces.len(),
        arr.segment_cells.len()
    );
    if let [x, y, r] = *near {
        let at = glam::DVec2::new(x, y);
        for (s, &[a, b]) in arr.segment_ends.iter().enumerate() {
            if foldcam::geom::distance_to_point(a, b, at) > r {
                continue;
            }
            let sides =
                arr.segment_cells[s].map(|c| c.map(|c| (c, arr.cell_faces[c as usize].clone())));
            println!(
                "segment {s}: {a:?} - {b:?}\n  edges {:?}\n  left {:?}\n  right {:?}",
                arr.segment_edges[s], sides[0], sides[1]
            );
        }
    }
    one(path, None)
}
