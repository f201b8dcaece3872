//! Design files: recognise one by its name and content, build it with plain options, and hand
//! back the crease pattern, its folded state and the lines `foldcam` prints about it.
//!
//! The files are those the design commands read: voxel pop-up cards (`.voxel.txt`, a
//! height-map `.png`, or an OBJ/STL mesh; Mitani, Suzuki & Uno 2003), polygon pop-up cards
//! (`.popup.toml`; Mitani & Suzuki 2004), fold scripts (`.toml` with `[sheet]` and `[[step]]`;
//! Miyazaki et al. 1992), paper-craft designs (`.craft.toml`, naming an OBJ/STL mesh; Ōgaki
//! 2016) and meshes made into origami tessellations (Tachi 2014). Nothing here reads a path on
//! disk except [`read_design_file`]: every builder takes the file's bytes, so the command line
//! and the studio (uploads) share them.
//!
//! Each pipeline has its own module with an options struct whose `Default` is the command
//! line's defaults; [`build_design`] chooses the pipeline for the studio. A build either
//! succeeds ([`Design`]: pattern, folded state, summary lines) or fails with a
//! [`SourceError`]: bad input (the message names the file, the place and the limit), or a
//! design that its own check refuses ([`SourceError::NotMade`]: the lines `foldcam` prints
//! before exiting with status 1).

pub(crate) mod card;
pub mod craft;
pub(crate) mod note;
pub mod poly;
pub mod script;
pub(crate) mod summary;
pub mod tess_design;
pub(crate) mod tess_limits;
pub mod tessellate;
pub mod voxel;

use std::path::{Path, PathBuf};

use crate::formats::{FormatError, ParseError};
use crate::mesh::{MeshError, PolyMesh, parse_obj, parse_stl};
use crate::pattern::{CreasePattern, FoldedState};

pub use craft::{CraftDesign, ParsedCraft};
pub use note::BuildNote;
pub use poly::{PolyDesign, PolyOptions};
pub use script::ScriptDesign;
pub use summary::SummaryLine;
pub use tess_limits::{CreaseState, LimitMap, VertexState, limit_map};
pub use tessellate::{TessellationDesign, TessellationOptions};
pub use voxel::{VoxelDesign, VoxelOptions};

/// The kinds of design file foldcam builds patterns from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DesignKind {
    /// A voxel card's text front view (`.voxel.txt`; `foldcam popup voxel` reads any other
    /// name as one too, but a plain `.txt` is not taken for a design here).
    VoxelText,
    /// A height map (`.png`): grey level = how far a point stands out of the card.
    HeightMap,
    /// A polygon mesh (`.obj`, `.stl`): a tessellation or a voxel pop-up card.
    Mesh,
    /// A polygon pop-up card design (`.popup.toml`, or a `.toml` with `[card]`).
    PopupPolygon,
    /// A fold script (a `.toml` with `[sheet]` and `[[step]]`).
    FoldScript,
    /// A paper-craft design (`.craft.toml`, or a `.toml` naming a `mesh`).
    PaperCraft,
    /// A tessellation design (`.tess.toml`, or a `.toml` with `[tessellation]`): a mesh and
    /// the options of `foldcam tessellate` ([`tess_design`]).
    Tessellation,
}

impl DesignKind {
    /// The endings of the files this module recognises (lower case).
    pub const EXTENSIONS: &'static [&'static str] = &[
        ".voxel.txt",
        ".png",
        ".obj",
        ".stl",
        ".popup.toml",
        ".craft.toml",
        ".tess.toml",
        ".toml",
    ];

    /// The kind `name` and its content `bytes` show: the ending first; a plain `.toml` by
    /// its top-level tables (`[tessellation]` a tessellation design, else `mesh` a paper craft, `[card]` a pop-up card, `[sheet]` a fold
    /// script). `None` for any other file (a crease pattern, say).
    pub fn recognise(name: &Path, bytes: &[u8]) -> Option<DesignKind> {
        let lower = name.to_string_lossy().to_ascii_lowercase();
        let ends = |e: &str| lower.ends_with(e);
        if ends(".voxel.txt") {
            Some(DesignKind::VoxelText)
        } else if ends(".png") {
            Some(DesignKind::HeightMap)
        } else if ends(".obj") || ends(".stl") {
            Some(DesignKind::Mesh)
        } else if ends(".popup.toml") {
            Some(DesignKind::PopupPolygon)
        } else if ends(".craft.toml") {
            Some(DesignKind::PaperCraft)
        } else if ends(tess_design::EXTENSION) {
            Some(DesignKind::Tessellation)
        } else if ends(".toml") {
            let table: toml::Table = std::str::from_utf8(bytes).ok()?.parse().ok()?;
            if table.contains_key("tessellation") {
                Some(DesignKind::Tessellation)
            } else if table.contains_key("mesh") {
                Some(DesignKind::PaperCraft)
            } else if table.contains_key("card") {
                Some(DesignKind::PopupPolygon)
            } else if table.contains_key("sheet") || table.contains_key("step") {
                Some(DesignKind::FoldScript)
            } else {
                None
            }
        } else {
            None
        }
    }

    /// Whether the flat lines of the patterns this kind makes are labels to mark on the
    /// sheet (a paper craft's edge numbers), rather than facet lines to skip: `foldcam
    /// papercraft --job` and the studio then mark them where the machine can
    /// ([`crate::fab::mark_labels`]).
    pub fn flat_lines_are_labels(self) -> bool {
        self == DesignKind::PaperCraft
    }

    /// Whether `name`'s ending is one a design file may have (the content may still say
    /// otherwise for a `.toml`).
    pub fn has_design_ending(name: &Path) -> bool {
        let lower = name.to_string_lossy().to_ascii_lowercase();
        Self::EXTENSIONS.iter().any(|e| lower.ends_with(e))
    }
}

/// What to make of a mesh (OBJ or STL) given alone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MeshUse {
    /// A tessellation when the mesh has a boundary (a disk, as Tachi 2014 needs), a voxel
    /// pop-up card when it is closed.
    #[default]
    Auto,
    /// An origami tessellation (Tachi 2014), as `foldcam tessellate`.
    Tessellation,
    /// A voxel pop-up card seen from the front (Mitani, Suzuki & Uno 2003), as `foldcam popup
    /// voxel`.
    PopupCard,
}

impl MeshUse {
    /// The use named `name` (`auto`, `tessellation`, `popup`), as the studio's query says it.
    pub fn from_name(name: &str) -> Option<MeshUse> {
        match name {
            "auto" => Some(MeshUse::Auto),
            "tessellation" | "tessellate" => Some(MeshUse::Tessellation),
            "popup" | "popup-card" => Some(MeshUse::PopupCard),
            _ => None,
        }
    }

    /// The use `Auto` picks for `mesh`.
    pub fn resolve(self, mesh: &PolyMesh) -> MeshUse {
        match self {
            MeshUse::Auto if has_boundary(mesh) => MeshUse::Tessellation,
            MeshUse::Auto => MeshUse::PopupCard,
            other => other,
        }
    }
}

/// Whether some edge of `mesh` borders only one face (the mesh is open).
pub fn has_boundary(mesh: &PolyMesh) -> bool {
    let mut uses = std::collections::HashMap::<(u32, u32), u32>::new();
    for face in mesh.faces() {
        for (k, &a) in face.iter().enumerate() {
            let b = face[(k + 1) % face.len()];
            *uses.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    uses.values().any(|&n| n == 1)
}

/// A design file's name (as the user gave it: it names the file in every message and its
/// ending chooses the reader) and its content.
#[derive(Clone, Copy, Debug)]
pub struct DesignFile<'a> {
    /// The name or path, as given.
    pub name: &'a Path,
    /// The content.
    pub bytes: &'a [u8],
}

impl DesignFile<'_> {
    /// The name for messages.
    pub fn display(&self) -> String {
        self.name.display().to_string()
    }

    /// The content as UTF-8 text (the message `foldcam` prints for a file that is not).
    pub fn text(&self) -> Result<&str, SourceError> {
        std::str::from_utf8(self.bytes).map_err(|e| {
            SourceError::Read(FormatError::Parse {
                path: self.name.to_path_buf(),
                source: ParseError::new(
                    format!("byte {}", e.valid_up_to()),
                    "file is not valid UTF-8 text",
                ),
            })
        })
    }

    /// The content as a mesh, the reader chosen by the ending (`.obj` or `.stl`).
    pub fn mesh(&self) -> Result<PolyMesh, SourceError> {
        let lower = self.name.to_string_lossy().to_ascii_lowercase();
        let mesh = if lower.ends_with(".obj") {
            parse_obj(self.bytes)
        } else if lower.ends_with(".stl") {
            parse_stl(self.bytes)
        } else {
            Err(MeshError::UnknownFormat)
        };
        mesh.map_err(|e| SourceError::input(self.name, e))
    }
}

/// Reads a design file named on the command line, with the message `foldcam` prints when it
/// cannot: text files through [`crate::formats::read_bytes`] (size limit), meshes and height
/// maps as their readers say it.
pub fn read_design_file(path: &Path) -> Result<Vec<u8>, SourceError> {
    let lower = path.to_string_lossy().to_ascii_lowercase();
    if lower.ends_with(".obj") || lower.ends_with(".stl") {
        std::fs::read(path).map_err(|e| SourceError::input(path, MeshError::Io(e.to_string())))
    } else if lower.ends_with(".png") {
        std::fs::read(path).map_err(|e| SourceError::input(path, e))
    } else {
        crate::formats::read_bytes(path).map_err(SourceError::Read)
    }
}

/// Why a design was not built.
#[derive(Debug, thiserror::Error)]
pub enum SourceError {
    /// The file could not be read or is not text.
    #[error(transparent)]
    Read(FormatError),
    /// The file, or a value in it, is refused: `message` names the place and the limit.
    #[error("{file}: {message}")]
    Input {
        /// The file, as named.
        file: String,
        /// What is wrong and where.
        message: String,
    },
    /// An option out of its range (the message names the option and the range).
    #[error("{0}")]
    Option(String),
    /// The build was cancelled through [`Progress::cancelled`].
    #[error("cancelled")]
    Cancelled,
    /// The design was read but its own check refuses it (the card would not pop up, the
    /// solver did not converge): the lines `foldcam` prints on standard output before exiting
    /// with status 1.
    #[error("{}", lines.join("\n"))]
    NotMade {
        /// The report, one line each.
        lines: Vec<String>,
    },
    /// A paper-craft or tessellation design whose mesh is not among the files given with it.
    #[error(
        "{design}: its mesh {mesh} is not among the files given with it: drop {mesh} together \
         with {design} (or name both on the command line)"
    )]
    MissingMesh {
        /// The design file.
        design: String,
        /// The mesh it names.
        mesh: String,
    },
    /// The file is not one this module builds.
    #[error(
        "{0}: not a design file foldcam recognises (a .voxel.txt, height-map .png, .obj or \
         .stl mesh, .popup.toml, .craft.toml, .tess.toml, or a fold script .toml with [sheet] and [[step]])"
    )]
    Unrecognised(String),
}

impl SourceError {
    /// An input error naming `file`.
    pub fn input(file: &Path, message: impl std::fmt::Display) -> SourceError {
        SourceError::Input {
            file: file.display().to_string(),
            message: message.to_string(),
        }
    }

    /// Whether the design's own check refused it (exit status 1 on the command line) rather
    /// than the input being bad (status 2).
    pub fn is_refusal(&self) -> bool {
        matches!(self, SourceError::NotMade { .. })
    }
}

/// Hears what a build has to say while it runs: its notes ([`BuildNote`], printed by
/// `foldcam` on standard error after `foldcam: `), when long work starts and ends, and the
/// tessellation solver's iterations. Every method has a default that ignores it.
pub trait Progress {
    /// A note (see [`BuildNote::is_warning`]).
    fn note(&mut self, _note: BuildNote) {}
    /// Long work begins (`what` says which).
    fn busy(&mut self, _what: &str) {}
    /// The long work announced by [`Progress::busy`] ended.
    fn idle(&mut self) {}
    /// One iteration of the tessellation solver (Tachi 2014).
    fn iteration(&mut self, _it: &crate::design::tessellation::Iteration) {}
    /// A solve of the tessellation's schedule ended without a usable result (whether or not
    /// it made any iteration): the next one of the schedule, if any, begins.
    fn next_solve(&mut self) {}
    /// Whether the caller wants the build stopped: asked after every solver iteration and
    /// between solves (the tessellation then ends with [`SourceError::Cancelled`]); never by
    /// default.
    fn cancelled(&self) -> bool {
        false
    }
}

/// Collects the notes, ignores the rest.
impl Progress for Vec<BuildNote> {
    fn note(&mut self, note: BuildNote) {
        self.push(note);
    }
}

/// Options for every kind of design file (each the command line's defaults).
#[derive(Clone, Debug, Default)]
pub struct DesignOptions {
    /// Voxel cards (text, height maps, meshes made into cards).
    pub voxel: VoxelOptions,
    /// Polygon cards.
    pub poly: PolyOptions,
    /// Tessellations.
    pub tessellation: TessellationOptions,
    /// What a mesh given alone becomes.
    pub mesh_use: MeshUse,
}

/// A built design as one pattern: what the studio opens.
#[derive(Clone, Debug)]
pub struct Design {
    /// What the file was.
    pub kind: DesignKind,
    /// What was made of it (e.g. "origami tessellation (Tachi 2014)").
    pub made: &'static str,
    /// The crease pattern, as the matching command writes it with `-o NAME.fold` (the first
    /// sheet of a paper craft).
    pub pattern: CreasePattern,
    /// The folded state the command writes with it, if any.
    pub folded: Option<FoldedState>,
    /// The lines the command prints on standard output when it succeeds.
    pub summary: Vec<SummaryLine>,
    /// How many sheets the design made (paper craft can make several; the others are left
    /// out of [`Design::pattern`]).
    pub sheets: usize,
}

/// Builds `file` as the matching `foldcam` command builds it with `options`. `companions` are
/// the other files given with it: a paper craft's mesh is looked up among them by file name
/// (and nowhere else).
///
/// # Errors
/// [`SourceError`]: bad input naming the file, a refusal with the command's lines, or
/// [`SourceError::MissingMesh`].
pub fn build_design(
    file: &DesignFile<'_>,
    companions: &[DesignFile<'_>],
    options: &DesignOptions,
    progress: &mut dyn Progress,
) -> Result<Design, SourceError> {
    let kind = DesignKind::recognise(file.name, file.bytes)
        .ok_or_else(|| SourceError::Unrecognised(file.display()))?;
    match kind {
        DesignKind::VoxelText | DesignKind::HeightMap => {
            voxel::build(file, None, &options.voxel, progress).map(|d| d.into_design(kind))
        }
        DesignKind::Mesh => {
            let mesh = file.mesh()?;
            match options.mesh_use.resolve(&mesh) {
                MeshUse::Tessellation => {
                    tessellate::build(file, &mesh, &options.tessellation, progress)
                        .map(|d| d.into_design())
                }
                _ => voxel::build(file, Some(&mesh), &options.voxel, progress)
                    .map(|d| d.into_design(kind)),
            }
        }
        DesignKind::PopupPolygon => {
            poly::build(file, &options.poly, progress).map(|d| d.into_design())
        }
        DesignKind::FoldScript => script::build(file, progress).map(|d| d.into_design()),
        DesignKind::PaperCraft => {
            let parsed = craft::parse(file)?;
            let mesh_name = parsed.mesh_name();
            let mesh_file = companion_mesh(file, companions, &mesh_name)?;
            let mesh = mesh_file.mesh()?;
            craft::build(parsed, mesh_file.name, &mesh, progress)?.into_design(file.name)
        }
        DesignKind::Tessellation => {
            let design = tess_design::parse(file)?;
            let mesh_file = companion_mesh(file, companions, &design.mesh)?;
            let mesh = mesh_file.mesh()?;
            let mut opts = options.tessellation;
            design.settings.apply_to(&mut opts);
            tessellate::build(mesh_file, &mesh, &opts, progress).map(|d| d.into_design())
        }
    }
}

/// The title a design file gives the patterns made of it when they have none of their own:
/// its file name without the design ending (`house.voxel.txt` → `house`, `dome.obj` →
/// `dome`) or, for another name, without its last extension. Machine jobs name their source
/// by it (the G-code header's `source:`).
pub fn design_title(name: &Path) -> Option<String> {
    let name = name.to_string_lossy();
    let stem = bare_stem(&name);
    (!stem.is_empty()).then(|| stem.to_string())
}

/// The stem of the files saved from a document, session or job named `name` (a path, an
/// upload's name): [`design_title`]'s stem with spaces made dashes (`a/my vase.craft.toml`
/// → `my-vase`), or `fallback` when nothing is left. Forward and back slashes both separate
/// folders (a name can come from any browser's system).
pub fn file_stem(name: &str, fallback: &str) -> String {
    let stem = bare_stem(name).replace(' ', "-");
    if stem.is_empty() {
        fallback.to_string()
    } else {
        stem
    }
}

/// The last component of `name` (after `/` or `\`) without a design ending or, for another
/// name, its last extension; the component whole when that would leave nothing (`.fold`).
fn bare_stem(name: &str) -> &str {
    let file = name.rsplit(['/', '\\']).next().unwrap_or_default();
    let lower = file.to_ascii_lowercase();
    let cut = match DesignKind::EXTENSIONS.iter().find(|e| lower.ends_with(*e)) {
        Some(e) => file.len() - e.len(),
        None => file.rfind('.').unwrap_or(file.len()),
    };
    if cut == 0 { file } else { &file[..cut] }
}

/// Gives `pattern` the title of the design file `name` unless it has one.
pub(crate) fn title_from(pattern: &mut CreasePattern, name: &Path) {
    if pattern.meta.title.is_none() {
        pattern.meta.title = design_title(name);
    }
}

/// The companion of `design` that is the mesh file it names (`mesh`, matched by its last
/// component: an upload or a file beside the design).
///
/// # Errors
/// [`SourceError::MissingMesh`] naming the design and the mesh.
fn companion_mesh<'c, 'f>(
    design: &DesignFile<'_>,
    companions: &'c [DesignFile<'f>],
    mesh: &Path,
) -> Result<&'c DesignFile<'f>, SourceError> {
    let wanted = mesh_file_name(mesh);
    companions
        .iter()
        .find(|c| {
            c.name
                .file_name()
                .is_some_and(|n| Some(n) == wanted.as_deref())
        })
        .ok_or_else(|| SourceError::MissingMesh {
            design: design.display(),
            mesh: mesh.display().to_string(),
        })
}

/// The last component of a mesh path a design names (what an upload of it is called).
pub fn mesh_file_name(mesh: &Path) -> Option<std::ffi::OsString> {
    mesh.file_name().map(|n| n.to_os_string())
}

/// The path a paper-craft design at `design` names its mesh by: relative to the design's
/// folder, as `foldcam papercraft` reads it.
pub fn mesh_path_beside(design: &Path, mesh: &Path) -> PathBuf {
    design.parent().unwrap_or(Path::new(".")).join(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn saved_names_lose_the_pattern_and_design_endings() {
        assert_eq!(
            file_stem("examples/papercraft/vase.craft.toml", "x"),
            "vase"
        );
        assert_eq!(file_stem("C:\\work\\bird.CP", "x"), "bird");
        assert_eq!(file_stem("house.voxel.txt", "x"), "house");
        assert_eq!(file_stem("my.design.fold", "x"), "my.design");
        assert_eq!(file_stem("a/my vase.OBJ", "x"), "my-vase");
        assert_eq!(file_stem(".fold", "x"), ".fold");
        assert_eq!(file_stem("", "pattern"), "pattern");
        assert_eq!(file_stem("dir/", "pattern"), "pattern");
        assert_eq!(
            design_title(Path::new("scan.v2.OBJ")).as_deref(),
            Some("scan.v2")
        );
        assert_eq!(design_title(Path::new("")), None);
    }
}
