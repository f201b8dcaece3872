//! Tessellation design files (`NAME.tess.toml`): a mesh and the options `foldcam tessellate`
//! builds an origami tessellation (Tachi 2014) from, so that a design made in the studio is
//! rebuilt by the command line exactly:
//!
//! ```toml
//! mesh = "dome.obj"          # relative to this file's folder
//! [tessellation]
//! tuck = "truncated"         # star, truncated, twisted, twist (as --tuck)
//! layout = "auto"            # auto, checkerboard, digon
//! shrink = 0.7               # left out: the shrinks 0.8 … 0.4 are tried in turn
//! truncation = 0.3
//! twist = 15.0               # degrees
//! max_fold_angle = 165.0     # degrees (180 − δ_fold)
//! min_vertex_angle = 30.0    # degrees (δ_corner)
//! ground = false
//! fit = 0.5                  # left out: no surface fit
//! remesh = "auto"            # auto, never, only
//! remesh_faces = 60          # left out: as many faces as the mesh has
//! max_iterations = 200
//! ```
//!
//! Every key of `[tessellation]` may be left out: it then keeps the command line's value
//! (its option, the material's limits, or the default). This module never reads the mesh:
//! the caller finds it (the command line beside the design, the studio among the files given
//! with it).

use std::path::PathBuf;

use serde::Deserialize;

use super::tessellate::TessellationOptions;
use super::{DesignFile, SourceError};
use crate::design::tessellation::{Remesh, TuckKind, TuckLayout};

/// The ending of a tessellation design file.
pub const EXTENSION: &str = ".tess.toml";

/// The options a design file (or the command line) sets; `None` leaves the value as it was.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TessSettings {
    /// Tuck structure.
    pub tuck: Option<TuckKind>,
    /// Gap layout.
    pub layout: Option<TuckLayout>,
    /// One face shrink in (0, 1] instead of the ladder.
    pub shrink: Option<f64>,
    /// Initial size of the flat n-gon, fraction in (0, 1).
    pub truncation: Option<f64>,
    /// Initial twist, degrees.
    pub twist_deg: Option<f64>,
    /// Fold-angle limit, degrees.
    pub max_fold_angle_deg: Option<f64>,
    /// Vertex-angle limit, degrees.
    pub min_vertex_angle_deg: Option<f64>,
    /// Ground contact.
    pub ground: Option<bool>,
    /// Surface-fit weight in [0, 1].
    pub fit: Option<f64>,
    /// Re-triangulation.
    pub remesh: Option<Remesh>,
    /// Faces of the re-triangulation.
    pub remesh_faces: Option<usize>,
    /// Newton iteration cap.
    pub max_iterations: Option<usize>,
}

impl TessSettings {
    /// Sets the values given here in `options`.
    pub fn apply_to(&self, options: &mut TessellationOptions) {
        let o = options;
        o.tuck = self.tuck.unwrap_or(o.tuck);
        o.layout = self.layout.unwrap_or(o.layout);
        o.shrink = self.shrink.or(o.shrink);
        o.truncation = self.truncation.unwrap_or(o.truncation);
        o.twist_deg = self.twist_deg.unwrap_or(o.twist_deg);
        o.max_fold_angle_deg = self.max_fold_angle_deg.unwrap_or(o.max_fold_angle_deg);
        o.min_vertex_angle_deg = self.min_vertex_angle_deg.unwrap_or(o.min_vertex_angle_deg);
        o.ground = self.ground.unwrap_or(o.ground);
        o.fit = self.fit.or(o.fit);
        o.remesh = self.remesh.unwrap_or(o.remesh);
        o.remesh_faces = self.remesh_faces.or(o.remesh_faces);
        o.max_iterations = self.max_iterations.unwrap_or(o.max_iterations);
    }

    /// Every value of `options`, as a design file saves them.
    pub fn all_of(options: &TessellationOptions) -> TessSettings {
        TessSettings {
            tuck: Some(options.tuck),
            layout: Some(options.layout),
            shrink: options.shrink,
            truncation: Some(options.truncation),
            twist_deg: Some(options.twist_deg),
            max_fold_angle_deg: Some(options.max_fold_angle_deg),
            min_vertex_angle_deg: Some(options.min_vertex_angle_deg),
            ground: Some(options.ground),
            fit: options.fit,
            remesh: Some(options.remesh),
            remesh_faces: options.remesh_faces,
            max_iterations: Some(options.max_iterations),
        }
    }
}

/// A tessellation design as read.
#[derive(Clone, Debug, PartialEq)]
pub struct TessDesign {
    /// The mesh, relative to the design's folder.
    pub mesh: PathBuf,
    /// The options it sets.
    pub settings: TessSettings,
}

/// The file's layout (see the module docs).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileRepr {
    mesh: String,
    #[serde(default)]
    tessellation: OptionsRepr,
}

#[derive(Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct OptionsRepr {
    tuck: Option<String>,
    layout: Option<String>,
    shrink: Option<f64>,
    truncation: Option<f64>,
    twist: Option<f64>,
    max_fold_angle: Option<f64>,
    min_vertex_angle: Option<f64>,
    ground: Option<bool>,
    fit: Option<f64>,
    remesh: Option<String>,
    remesh_faces: Option<usize>,
    max_iterations: Option<usize>,
}

/// The name of `tuck` in files and on the command line (`--tuck`).
pub fn tuck_name(tuck: TuckKind) -> &'static str {
    match tuck {
        TuckKind::Star => "star",
        TuckKind::Truncated => "truncated",
        TuckKind::Twisted => "twisted",
        TuckKind::TwistFold => "twist",
    }
}

/// The tuck named `name` (as `--tuck`).
pub fn tuck_by_name(name: &str) -> Option<TuckKind> {
    [
        TuckKind::Star,
        TuckKind::Truncated,
        TuckKind::Twisted,
        TuckKind::TwistFold,
    ]
    .into_iter()
    .find(|&t| tuck_name(t) == name)
}

/// The layout named `name` (as `--layout`).
pub fn layout_by_name(name: &str) -> Option<TuckLayout> {
    [
        TuckLayout::Auto,
        TuckLayout::Checkerboard,
        TuckLayout::Digon,
    ]
    .into_iter()
    .find(|l| l.to_string() == name)
}

/// The name of `remesh` in files.
pub fn remesh_name(remesh: Remesh) -> &'static str {
    match remesh {
        Remesh::Never => "never",
        Remesh::Auto => "auto",
        Remesh::Only => "only",
    }
}

/// The re-triangulation choice named `name`.
pub fn remesh_by_name(name: &str) -> Option<Remesh> {
    [Remesh::Never, Remesh::Auto, Remesh::Only]
        .into_iter()
        .find(|&r| remesh_name(r) == name)
}

/// Reads a design file.
///
/// # Errors
/// Bad input naming the file and the key (or line) and what is accepted there.
pub fn parse(file: &DesignFile<'_>) -> Result<TessDesign, SourceError> {
    let repr: FileRepr =
        toml::from_str(file.text()?).map_err(|e| SourceError::input(file.name, e))?;
    let bad = |key: &str, what: &str| {
        SourceError::input(file.name, format!("[tessellation] {key}: expected {what}"))
    };
    let t = repr.tessellation;
    let named =
        |value: &Option<String>, key: &str, what: &str, find: &dyn Fn(&str) -> bool| match value {
            Some(v) if !find(v) => Err(bad(key, what)),
            _ => Ok(()),
        };
    named(&t.tuck, "tuck", "star, truncated, twisted or twist", &|v| {
        tuck_by_name(v).is_some()
    })?;
    named(&t.layout, "layout", "auto, checkerboard or digon", &|v| {
        layout_by_name(v).is_some()
    })?;
    named(&t.remesh, "remesh", "auto, never or only", &|v| {
        remesh_by_name(v).is_some()
    })?;
    for (key, value) in [
        ("max_fold_angle", t.max_fold_angle),
        ("min_vertex_angle", t.min_vertex_angle),
    ] {
        if value.is_some_and(|v| !(v.is_finite() && (0.0..=180.0).contains(&v))) {
            return Err(bad(key, "an angle between 0 and 180 degrees"));
        }
    }
    for (key, value) in [
        ("shrink", t.shrink),
        ("truncation", t.truncation),
        ("twist", t.twist),
        ("fit", t.fit),
    ] {
        if value.is_some_and(|v| !v.is_finite()) {
            return Err(bad(key, "a finite number"));
        }
    }
    if repr.mesh.trim().is_empty() {
        return Err(SourceError::input(file.name, "mesh: names no file"));
    }
    Ok(TessDesign {
        mesh: PathBuf::from(repr.mesh),
        settings: TessSettings {
            tuck: t.tuck.as_deref().and_then(tuck_by_name),
            layout: t.layout.as_deref().and_then(layout_by_name),
            shrink: t.shrink,
            truncation: t.truncation,
            twist_deg: t.twist,
            max_fold_angle_deg: t.max_fold_angle,
            min_vertex_angle_deg: t.min_vertex_angle,
            ground: t.ground,
            fit: t.fit,
            remesh: t.remesh.as_deref().and_then(remesh_by_name),
            remesh_faces: t.remesh_faces,
            max_iterations: t.max_iterations,
        },
    })
}

/// The design file for `mesh` (a file name beside the design) built with `options`: every
/// option written out, so that the command line rebuilds it whatever its own defaults.
/// `note` (one line, e.g. the material the limits came from) becomes a comment.
pub fn write_design(mesh: &str, options: &TessellationOptions, note: Option<&str>) -> String {
    let s = TessSettings::all_of(options);
    let mut out = String::from(
        "# foldcam tessellation design (Tachi 2014): `foldcam tessellate THIS_FILE -o out.fold`\n",
    );
    if let Some(note) = note {
        out.push_str(&format!("# {}\n", note.replace(['\n', '\r'], " ")));
    }
    out.push_str(&format!("mesh = {}\n\n[tessellation]\n", quoted(mesh)));
    let mut line = |key: &str, value: String| out.push_str(&format!("{key} = {value}\n"));
    line("tuck", quoted(tuck_name(options.tuck)));
    line("layout", quoted(&options.layout.to_string()));
    if let Some(shrink) = s.shrink {
        line("shrink", format!("{shrink:?}"));
    }
    line("truncation", format!("{:?}", options.truncation));
    line("twist", format!("{:?}", options.twist_deg));
    line(
        "max_fold_angle",
        format!("{:?}", options.max_fold_angle_deg),
    );
    line(
        "min_vertex_angle",
        format!("{:?}", options.min_vertex_angle_deg),
    );
    line("ground", options.ground.to_string());
    if let Some(fit) = options.fit {
        line("fit", format!("{fit:?}"));
    }
    line("remesh", quoted(remesh_name(options.remesh)));
    if let Some(faces) = options.remesh_faces {
        line("remesh_faces", faces.to_string());
    }
    line("max_iterations", options.max_iterations.to_string());
    out
}

/// A TOML basic string.
fn quoted(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    fn read(text: &str) -> Result<TessDesign, SourceError> {
        parse(&DesignFile {
            name: Path::new("t.tess.toml"),
            bytes: text.as_bytes(),
        })
    }

    #[test]
    fn written_options_read_back_equal() {
        let options = TessellationOptions {
            tuck: TuckKind::TwistFold,
            layout: TuckLayout::Digon,
            shrink: Some(0.65),
            truncation: 0.25,
            twist_deg: -12.5,
            max_fold_angle_deg: 150.0,
            min_vertex_angle_deg: 1.0 / 3.0,
            ground: true,
            fit: Some(0.1),
            max_iterations: 77,
            remesh: Remesh::Only,
            remesh_faces: Some(40),
            // A run's time limit is the command's, not the design's: not saved.
            time_limit_s: TessellationOptions::default().time_limit_s,
        };
        let text = write_design("my \"mesh\".obj", &options, Some("from stainless-0.5"));
        let d = read(&text).unwrap();
        assert_eq!(d.mesh, PathBuf::from("my \"mesh\".obj"));
        let mut back = TessellationOptions::default();
        d.settings.apply_to(&mut back);
        assert_eq!(back, options);
    }

    #[test]
    fn left_out_keys_keep_the_given_values() {
        let d = read("mesh = \"a.obj\"\n[tessellation]\ntuck = \"truncated\"\n").unwrap();
        let mut o = TessellationOptions {
            max_fold_angle_deg: 120.0,
            ..TessellationOptions::default()
        };
        d.settings.apply_to(&mut o);
        assert_eq!(o.tuck, TuckKind::Truncated);
        assert_eq!(o.max_fold_angle_deg, 120.0);
        assert_eq!(o.shrink, None);
    }

    #[test]
    fn bad_values_name_the_key() {
        let e = read("mesh = \"a.obj\"\n[tessellation]\ntuck = \"spiral\"\n").unwrap_err();
        assert!(e.to_string().contains("tuck"), "{e}");
        let e = read("mesh = \"a.obj\"\n[tessellation]\nmax_fold_angle = 190\n").unwrap_err();
        assert!(e.to_string().contains("max_fold_angle"), "{e}");
        let e = read("mesh = \"a.obj\"\n[tessellation]\nshrnk = 0.5\n").unwrap_err();
        assert!(e.to_string().contains("shrnk"), "{e}");
        assert!(read("[tessellation]\n").is_err());
    }
}
