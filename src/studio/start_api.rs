//! Starting and saving in the studio: the bundled examples (grouped as Origami Simulator's
//! Examples menu groups its own), a blank sheet to draw on, and the edited pattern saved in
//! the formats `foldcam convert` writes, or its folded form.
//!
//! | route | does |
//! | --- | --- |
//! | `GET /api/examples` | the bundled examples: `[{group, examples: [{name, file, title, description}]}]` |
//! | `POST /api/examples/{name}` | opens example `name` as a document: the pattern view |
//! | `POST /api/blank[?side=MM]` | opens a blank square sheet of `MM` millimetres ([`BLANK_SHEET_MM`] when absent; [`STUDIO_BLANK_SIDE`] bounds it) |
//! | `GET /api/docs/{id}/save?format=F` | the document's pattern as a file: `fold`, `svg`, `cp`, `opx`, or `folded` (the folded form as FOLD) |
//!
//! The examples are compiled into the binary from `examples/` (the files `foldcam demo`
//! bundles and the design files beside them) or made by the classic generators with the
//! defaults of `foldcam generate`; nothing is read from disk.

use std::sync::Arc;

use axum::Json;
use axum::extract::rejection::{PathRejection, QueryRejection};
use axum::extract::{Path, Query, State};
use axum::http::StatusCode;
use axum::response::Response;
use serde::{Deserialize, Serialize};

use super::api::{ApiError, ApiResult, Opened, PathId, Studio, blocking, download, opened};
use super::design_open;
use super::document::Document;
use super::error::{Stage, StudioError};
use crate::check::fold3d::{FoldOptions, fold};
use crate::design::classic::{
    BLANK_SHEET_MM, ClassicError, MiuraOri, SquareTwist, Waterbomb, Yoshimura, blank_sheet,
};
use crate::design::source::{MeshUse, file_stem};
use crate::formats::{self, Format};
use crate::limits::STUDIO_BLANK_SIDE;
use crate::pattern::CreasePattern;

/// Where a bundled example comes from.
#[derive(Clone, Copy)]
enum Source {
    /// A classic generator with `foldcam generate`'s defaults.
    Generated(fn() -> Result<CreasePattern, ClassicError>),
    /// A crease-pattern file, read as an upload of the same name.
    Pattern(&'static str),
    /// A design file, built as an upload of the same name, with the mesh it names.
    Design(&'static [u8], Option<(&'static str, &'static [u8])>),
}

/// One bundled example.
#[derive(Clone, Copy)]
struct Example {
    /// The name in the route (`miura-ori`).
    name: &'static str,
    /// The document's file name (its ending chooses the reader).
    file: &'static str,
    /// The menu's group.
    group: &'static str,
    /// What the menu shows.
    title: &'static str,
    /// One sentence on what it shows.
    description: &'static str,
    source: Source,
}

/// The bundled examples, in the menu's order (groups in order of first appearance).
const EXAMPLES: &[Example] = &[
    Example {
        name: "flat-vertex",
        file: "flat-vertex.fold",
        group: "Simple folds",
        title: "Flat vertex",
        description: "One degree-4 vertex that folds flat: Kawasaki's and Maekawa's theorems hold.",
        source: Source::Pattern(include_str!("../../examples/patterns/flat-vertex.fold")),
    },
    Example {
        name: "broken-vertex",
        file: "broken-vertex.fold",
        group: "Simple folds",
        title: "Broken vertex",
        description: "A vertex whose angles break Kawasaki's theorem: the check rings it.",
        source: Source::Pattern(include_str!("../../examples/patterns/broken-vertex.fold")),
    },
    Example {
        name: "preliminary-base",
        file: "preliminary-base.cp",
        group: "Origami bases",
        title: "Preliminary base",
        description: "The square base, an ORIPA file (unitless: give a size to plan it).",
        source: Source::Pattern(include_str!("../../examples/patterns/preliminary-base.cp")),
    },
    Example {
        name: "bird-base",
        file: "bird-base.cp",
        group: "Origami bases",
        title: "Bird base",
        description: "The crane's base, an ORIPA file (unitless: give a size to plan it).",
        source: Source::Pattern(include_str!("../../examples/patterns/bird-base.cp")),
    },
    Example {
        name: "miura-ori",
        file: "miura-ori.fold",
        group: "Tessellations",
        title: "Miura-ori",
        description: "Parallelogram cells that fold flat in one motion (foldcam generate miura).",
        source: Source::Generated(|| MiuraOri::default().build()),
    },
    Example {
        name: "square-twist",
        file: "square-twist.fold",
        group: "Tessellations",
        title: "Square twist",
        description: "A square turned about its centre (foldcam generate square-twist).",
        source: Source::Generated(|| SquareTwist::default().build()),
    },
    Example {
        name: "waterbomb",
        file: "waterbomb.fold",
        group: "Tessellations",
        title: "Waterbomb",
        description: "A grid of waterbomb bases (foldcam generate waterbomb).",
        source: Source::Generated(|| Waterbomb::default().build()),
    },
    Example {
        name: "yoshimura",
        file: "yoshimura.fold",
        group: "Tessellations",
        title: "Yoshimura",
        description: "The diamond pattern of buckled cylinders (foldcam generate yoshimura).",
        source: Source::Generated(|| Yoshimura::default().build()),
    },
    Example {
        name: "house",
        file: "house.voxel.txt",
        group: "Pop-up cards",
        title: "House (voxel card)",
        description: "A voxel pop-up card from a text front view (Mitani, Suzuki & Uno 2003).",
        source: Source::Design(include_bytes!("../../examples/popup/house.voxel.txt"), None),
    },
    Example {
        name: "taj-mahal",
        file: "taj-mahal.popup.toml",
        group: "Pop-up cards",
        title: "Taj Mahal (polygon card)",
        description: "A polygon pop-up card of vertical and horizontal faces (Mitani & Suzuki 2004).",
        source: Source::Design(
            include_bytes!("../../examples/popup/taj-mahal.popup.toml"),
            None,
        ),
    },
    Example {
        name: "vase",
        file: "vase.craft.toml",
        group: "Paper craft",
        title: "Vase",
        description: "Eight gores unrolled from a vase, with glue tabs and edge numbers (Ōgaki 2016).",
        source: Source::Design(
            include_bytes!("../../examples/papercraft/vase.craft.toml"),
            Some((
                "vase.obj",
                include_bytes!("../../examples/papercraft/vase.obj"),
            )),
        ),
    },
    Example {
        name: "paper-airplane",
        file: "paper-airplane.toml",
        group: "Fold sequences",
        title: "Paper airplane",
        description: "A fold script folded step by step (Miyazaki et al. 1992).",
        source: Source::Design(
            include_bytes!("../../examples/folding/paper-airplane.toml"),
            None,
        ),
    },
];

#[derive(Serialize)]
pub(super) struct ExampleEntry {
    name: &'static str,
    file: &'static str,
    title: &'static str,
    description: &'static str,
}

#[derive(Serialize)]
pub(super) struct ExampleGroup {
    group: &'static str,
    examples: Vec<ExampleEntry>,
}

pub(super) async fn examples() -> Json<Vec<ExampleGroup>> {
    let mut groups: Vec<ExampleGroup> = Vec::new();
    for e in EXAMPLES {
        let entry = ExampleEntry {
            name: e.name,
            file: e.file,
            title: e.title,
            description: e.description,
        };
        match groups.iter_mut().find(|g| g.group == e.group) {
            Some(g) => g.examples.push(entry),
            None => groups.push(ExampleGroup {
                group: e.group,
                examples: vec![entry],
            }),
        }
    }
    Json(groups)
}

/// Example `e` as a document, made as `foldcam` makes the same file.
fn open_example(e: &Example) -> Result<Document, StudioError> {
    match e.source {
        Source::Generated(make) => {
            let cp = make().map_err(|err| StudioError::about(Stage::Design, e.file, err))?;
            Document::from_pattern(e.file.to_string(), cp)
        }
        Source::Pattern(text) => Document::from_upload(e.file, text.as_bytes()),
        Source::Design(bytes, mesh) => {
            let companions: Vec<design_open::Named<'_>> = mesh
                .iter()
                .map(|(name, b)| (name.to_string(), *b))
                .collect();
            design_open::open_upload(e.file, bytes, &companions, MeshUse::Auto)
        }
    }
}

pub(super) async fn open(
    State(s): State<Arc<Studio>>,
    name: Result<Path<String>, PathRejection>,
) -> ApiResult<Json<Opened>> {
    let Path(name) = name?;
    let Some(e) = EXAMPLES.iter().find(|e| e.name == name) else {
        let known: Vec<&str> = EXAMPLES.iter().map(|e| e.name).collect();
        return Err(ApiError::new(
            StatusCode::NOT_FOUND,
            format!(
                "example {name:?}: no such bundled example (the examples are {})",
                known.join(", ")
            ),
        ));
    };
    blocking(move || opened(&s, open_example(e)?)).await
}

/// `side`: the sheet's side in millimetres.
#[derive(Deserialize)]
pub(super) struct BlankQuery {
    side: Option<String>,
}

/// The side a blank sheet gets: [`BLANK_SHEET_MM`], or `side` within [`STUDIO_BLANK_SIDE`].
fn blank_side(side: Option<&str>) -> ApiResult<f64> {
    match side.map(str::trim) {
        None | Some("") => Ok(BLANK_SHEET_MM),
        Some(text) => STUDIO_BLANK_SIDE
            .parse(text)
            .map_err(|e| ApiError::input(format!("blank sheet: side: {e}"))),
    }
}

pub(super) async fn blank(
    State(s): State<Arc<Studio>>,
    query: Result<Query<BlankQuery>, QueryRejection>,
) -> ApiResult<Json<Opened>> {
    let Query(q) = query?;
    let side = blank_side(q.side.as_deref())?;
    blocking(move || {
        let cp = blank_sheet(side).map_err(|e| ApiError::input(format!("blank sheet: {e}")))?;
        let doc = Document::from_pattern("blank.fold".to_string(), cp)?;
        opened(&s, doc)
    })
    .await
}

/// What `save` writes: one of the formats the library writes, or the folded form.
#[derive(Clone, Copy, Debug, PartialEq)]
enum SaveAs {
    Pattern(Format),
    Folded,
}

/// The formats `save` takes, for messages.
pub const SAVE_FORMATS: &str = "fold, svg, cp, opx or folded (the folded form as FOLD)";

impl SaveAs {
    fn from_name(name: &str) -> ApiResult<SaveAs> {
        match name.trim().to_ascii_lowercase().as_str() {
            "fold" => Ok(SaveAs::Pattern(Format::Fold)),
            "svg" => Ok(SaveAs::Pattern(Format::Svg)),
            "cp" => Ok(SaveAs::Pattern(Format::Cp)),
            "opx" => Ok(SaveAs::Pattern(Format::Opx)),
            "folded" => Ok(SaveAs::Folded),
            _ => Err(ApiError::input(format!(
                "format {name:?}: the studio saves a pattern as {SAVE_FORMATS} (DXF is read only)"
            ))),
        }
    }

    /// The file's ending (after the stem) and its content type.
    fn file(self) -> (&'static str, &'static str) {
        match self {
            SaveAs::Pattern(Format::Svg) => (".svg", "image/svg+xml"),
            SaveAs::Pattern(Format::Cp) => (".cp", "text/plain; charset=utf-8"),
            SaveAs::Pattern(Format::Opx) => (".opx", "application/xml"),
            SaveAs::Folded => ("-folded.fold", "application/json"),
            SaveAs::Pattern(_) => (".fold", "application/json"),
        }
    }
}

/// `format`: what to save as (see [`SAVE_FORMATS`]).
#[derive(Deserialize)]
pub(super) struct SaveQuery {
    format: Option<String>,
}

/// The bytes of `doc` saved as `what`: the cleaned pattern the page shows (with the folded
/// state the file or design came with, for FOLD), or its folded form: that folded state, else
/// the 3D fold simulation's settled form (as `foldcam fold3d` folds it, within the studio's
/// time limit).
fn save_bytes(doc: &Document, what: SaveAs) -> Result<Vec<u8>, StudioError> {
    match what {
        SaveAs::Pattern(format) => {
            let c = doc.planar()?;
            let folded = (format == Format::Fold)
                .then_some(c.folded.as_ref())
                .flatten();
            Ok(formats::render(format, &c.pattern, folded).into_bytes())
        }
        SaveAs::Folded => {
            let c = doc.cleaned(true)?;
            let folded = match c.folded {
                Some(f) => f,
                None => {
                    let options = FoldOptions {
                        max_time: super::fold3d_api::FOLD_TIME_LIMIT,
                        ..FoldOptions::default()
                    };
                    fold(&c.pattern, &options)
                        .map_err(|e| {
                            StudioError::about(Stage::Fold, &doc.name, format!("folded form: {e}"))
                        })?
                        .folded
                }
            };
            Ok(formats::fold::write_folded_string(&c.pattern, &folded).into_bytes())
        }
    }
}

pub(super) async fn save(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<SaveQuery>, QueryRejection>,
) -> ApiResult<Response> {
    let Query(q) = query?;
    let what = SaveAs::from_name(q.format.as_deref().unwrap_or("fold"))?;
    let doc = s.get(id)?;
    blocking(move || {
        let bytes = save_bytes(&doc, what)?;
        let (ending, mime) = what.file();
        let file = format!("{}{ending}", file_stem(&doc.name, "pattern"));
        Ok(download(mime, &file, bytes))
    })
    .await
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_example_opens_as_the_command_makes_it() {
        for e in EXAMPLES {
            let doc = open_example(e).unwrap_or_else(|err| panic!("{}: {err}", e.name));
            assert!(doc.planar().is_ok(), "{}", e.name);
        }
    }

    #[test]
    fn the_blank_side_is_bounded() {
        assert_eq!(blank_side(None).unwrap(), BLANK_SHEET_MM);
        assert_eq!(blank_side(Some("200")).unwrap(), 200.0);
        for bad in ["0", "-5", "1e9", "NaN", "wide"] {
            let e = blank_side(Some(bad)).unwrap_err();
            assert_eq!(e.status, StatusCode::UNPROCESSABLE_ENTITY);
            assert!(e.message().contains("side"), "{bad}: {}", e.message());
            assert!(e.message().contains("10000 mm"), "{bad}: {}", e.message());
        }
    }

    #[test]
    fn an_unknown_format_names_those_saved() {
        let e = SaveAs::from_name("dxf").unwrap_err();
        assert_eq!(e.status, StatusCode::UNPROCESSABLE_ENTITY);
        assert!(e.message().contains("fold, svg, cp, opx or folded"));
    }
}
