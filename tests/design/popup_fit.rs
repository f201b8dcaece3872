//! `--fit` makes a pop-up card that reaches beyond its outline when folded shut hold every
//! face: checked on the bundled examples that overhang (the building mesh and the Taj Mahal
//! design) and over a sweep of mesh resolutions, thin-top widths and bump-removal elements.
//!
//! The expected reach is derived from the model itself, not from the fitting code: closing a
//! 90° card (Mitani, Suzuki & Uno 2003, eq. 6 at θ = 180°) takes a point standing `y` in front
//! of the back sheet and `z` above the base to `y + z` above the central fold, so a card
//! closes within its outline when no face reaches past the taller half of the sheet.

use crate::bin;

use bin::{foldcam, repo_file};

use std::path::Path;

fn example(name: &str) -> String {
    repo_file(&format!("examples/popup/{name}"))
}

/// Pieces of the card written to `out` (re-read from the file) cut free on every side,
/// counted by the library's flood over the re-read pattern (as in tests/design/popup_integrity.rs).
fn loose_in(out: &Path) -> usize {
    let cp = foldcam::formats::load(out).unwrap().pattern;
    foldcam::design::popup::loose_pieces(&cp).len()
}

/// Whole millimetres of paper `--fit` adds at a time.
const STEP_MM: f64 = 1.0;

/// A voxel card as `--save-voxels` writes it (the text format of examples/popup/README.txt),
/// read here without the library's reader.
struct Voxels {
    cell_mm: f64,
    ny: usize,
    nz: usize,
    margin_mm: f64,
    /// Rows bottom-up: per column (depth, window, top left out).
    rows: Vec<Vec<(usize, bool, bool)>>,
}

fn read_voxels(path: &Path) -> Voxels {
    let text = std::fs::read_to_string(path).unwrap();
    let mut v = Voxels {
        cell_mm: 0.0,
        ny: 0,
        nz: 0,
        margin_mm: 0.0,
        rows: Vec::new(),
    };
    let mut in_rows = false;
    for line in text.lines().map(|l| l.split('#').next().unwrap().trim()) {
        if line.is_empty() {
            continue;
        }
        if in_rows {
            v.rows.push(
                line.split_whitespace()
                    .map(|t| {
                        let digits: String = t.chars().take_while(char::is_ascii_digit).collect();
                        (digits.parse().unwrap(), t.contains('w'), t.contains('t'))
                    })
                    .collect(),
            );
            continue;
        }
        let mut words = line.split_whitespace();
        match (words.next(), words.next()) {
            (Some("cell_mm"), Some(x)) => v.cell_mm = x.parse().unwrap(),
            (Some("depth"), Some(x)) => v.ny = x.parse().unwrap(),
            (Some("height"), Some(x)) => v.nz = x.parse().unwrap(),
            (Some("margin_mm"), Some(x)) => v.margin_mm = x.parse().unwrap(),
            (Some("rows"), None) => in_rows = true,
            other => panic!("unexpected line {other:?}"),
        }
    }
    v.rows.reverse();
    v
}

impl Voxels {
    /// How far above the central fold the closed card's faces reach, mm: a row of depth d at
    /// level z has its front face (unless a window) from z to z + 1 at y = d and its top face
    /// (unless left out, where the row above is shallower) at z + 1 out to y = d, both reaching
    /// d + z + 1 cells once closed.
    fn closed_reach_mm(&self) -> f64 {
        let mut reach = 0usize;
        for (z, row) in self.rows.iter().enumerate() {
            for (x, &(d, window, no_top)) in row.iter().enumerate() {
                let above = self.rows.get(z + 1).map_or(0, |r| r[x].0);
                let front = d > 0 && !window;
                let top = d > above && !no_top;
                if front || top {
                    reach = reach.max(d + z + 1);
                }
            }
        }
        reach as f64 * self.cell_mm
    }

    /// The taller half of the sheet, closed: base or back sheet plus the margin, mm.
    fn half_mm(&self) -> f64 {
        self.ny.max(self.nz) as f64 * self.cell_mm + self.margin_mm
    }

    /// The sheet's height (base + back + two margins), mm.
    fn sheet_height_mm(&self) -> f64 {
        (self.ny + self.nz) as f64 * self.cell_mm + 2.0 * self.margin_mm
    }
}

/// The height of the crease pattern's sheet in a written FOLD file, mm.
fn sheet_height(fold: &Path) -> f64 {
    let cp = foldcam::formats::load(fold).unwrap().pattern;
    let (lo, hi) = cp.bounds().unwrap();
    hi.y - lo.y
}

/// Builds `args` with `--fit`; when written (exit 0), checks that it has no loose piece, that
/// the saved voxel model closes
/// within its outline, that the written sheet is the model's, and that any paper added was
/// no more than the shortfall rounded up to whole millimetres; when refused (exit 1), that
/// nothing was written and the message says where. Returns whether it was written.
fn assert_fits(label: &str, args: &[&str], dir: &Path, margin_mm: f64) -> bool {
    let (out, vox) = (dir.join("card.fold"), dir.join("card.voxel.txt"));
    let _ = std::fs::remove_file(&out);
    let _ = std::fs::remove_file(&vox);
    let mut all = args.to_vec();
    all.extend([
        "--fit",
        "-o",
        "card.fold",
        "--save-voxels",
        "card.voxel.txt",
    ]);
    let o = foldcam(&all, dir);
    let (stdout, stderr) = (
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr),
    );
    match o.status.code() {
        Some(0) => {
            assert_eq!(loose_in(&out), 0, "{label}: loose pieces\n{stdout}");
            let v = read_voxels(&vox);
            let (reach, half) = (v.closed_reach_mm(), v.half_mm());
            assert!(
                reach <= half + 1e-6,
                "{label}: reaches {reach} mm, half {half} mm"
            );
            assert!(
                (sheet_height(&out) - v.sheet_height_mm()).abs() < 1e-6,
                "{label}"
            );
            if v.margin_mm > margin_mm {
                // Grown: by the shortfall at the given margin, rounded up to a whole step.
                let short = reach - (half - v.margin_mm + margin_mm);
                let added = v.margin_mm - margin_mm;
                assert!(
                    short > 0.0 && added >= short && added < short + STEP_MM,
                    "{label}"
                );
                assert!(stderr.contains("--fit added"), "{label}: {stderr}");
            }
            true
        }
        Some(1) => {
            assert!(
                !out.exists() && !vox.exists(),
                "{label}: refused but written"
            );
            assert!(
                stdout.contains("would not pop up") || stdout.contains(" at x = "),
                "{label}: {stdout}"
            );
            false
        }
        _ => panic!("{label}: {stderr}"),
    }
}

/// The building mesh at the defaults reaches past its 92 mm half when closed (its 41-cell-high
/// tower stands up to 21 cells out); `--fit` grows the 10 mm margin by the shortfall.
#[test]
fn fit_grows_the_building_card_until_it_closes_within_its_outline() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = example("building.obj");
    let plain = foldcam(&["popup", "voxel", &mesh, "-o", "plain.fold"], dir.path());
    assert_eq!(plain.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&plain.stderr).contains("beyond"));
    let args = ["popup", "voxel", mesh.as_str()];
    assert!(assert_fits("building --fit", &args, dir.path(), 10.0));
    let v = read_voxels(&dir.path().join("card.voxel.txt"));
    assert!(v.margin_mm > 10.0, "nothing added: {}", v.margin_mm);
}

/// The maximum over a design's faces of `at + the polygon's far coordinate` (z on vertical
/// planes at y = at, y on horizontal planes at z = at): how far the closed card reaches, mm.
fn design_reach(toml_text: &str) -> f64 {
    let design: toml::Value = toml::from_str(toml_text).unwrap();
    let grid = design["card"]
        .get("grid")
        .and_then(toml::Value::as_float)
        .unwrap_or(1.0);
    let num = |v: &toml::Value| {
        v.as_float()
            .or_else(|| v.as_integer().map(|i| i as f64))
            .unwrap()
    };
    design["operation"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|op| {
            op.get("add")
                .and_then(toml::Value::as_str)
                .unwrap_or("face")
                == "face"
        })
        .map(|op| {
            let unit = match op.get("units").and_then(toml::Value::as_str) {
                Some("grid") => grid,
                _ => 1.0,
            };
            let far = op["polygon"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| num(&p[1]))
                .fold(f64::MIN, f64::max);
            (num(&op["at"]) + far) * unit
        })
        .fold(0.0, f64::max)
}

/// The Taj Mahal design's 100 mm back sheet is 22 mm short of its minarets closed; `--fit`
/// makes it as high as the design reaches (122 mm from its own numbers), and the design with
/// that height closes without a warning while one a millimetre lower still warns.
#[test]
fn fit_grows_the_taj_mahal_back_sheet_to_what_the_design_reaches() {
    let dir = tempfile::tempdir().unwrap();
    let path = example("taj-mahal.popup.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let reach = design_reach(&text);
    assert!(reach > 100.0, "{reach}");
    let o = foldcam(
        &["popup", "poly", &path, "--fit", "-o", "taj.fold"],
        dir.path(),
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("--fit added"));
    // Base 70 mm plus the grown back sheet.
    let back = sheet_height(&dir.path().join("taj.fold")) - 70.0;
    assert!(
        back >= reach - 1e-6 && back < reach + STEP_MM,
        "back {back}, reach {reach}"
    );
    for (height, warns) in [(back, false), (back - 1.0, true)] {
        let edited = text.replacen("height = 100.0", &format!("height = {height:.1}"), 1);
        assert_ne!(edited, text);
        std::fs::write(dir.path().join("t.popup.toml"), edited).unwrap();
        let o = foldcam(
            &["popup", "poly", "t.popup.toml", "-o", "t.fold"],
            dir.path(),
        );
        assert_eq!(o.status.code(), Some(0));
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.contains("beyond"), warns, "height {height}: {err}");
    }
}

/// Every resolution, thin-top width and bump-removal element of the sweep gives, with
/// `--fit`, a card that closes within its outline or an explicit refusal; the paper's 3 × 3
/// element and the README's 5 × 5 both build at every resolution.
#[test]
fn building_sweep_with_fit_closes_within_the_outline() {
    let dir = tempfile::tempdir().unwrap();
    let mesh = example("building.obj");
    for morphology in ["3", "5"] {
        for resolution in ["80", "160", "320"] {
            for thin in ["0", "1", "2"] {
                let label = format!(
                    "building --morphology {morphology} --resolution {resolution} --thin-top {thin}"
                );
                let args = [
                    "popup",
                    "voxel",
                    mesh.as_str(),
                    "--morphology",
                    morphology,
                    "--resolution",
                    resolution,
                    "--thin-top",
                    thin,
                ];
                assert!(
                    assert_fits(&label, &args, dir.path(), 10.0),
                    "{label}: refused"
                );
            }
        }
    }
}
