//! The studio's paper-craft mode: cut lines drawn on a reference mesh, the interaction of
//! Ōgaki (2016) over the library's [`crate::design::papercraft::sketch`]. Each session holds the
//! mesh, the drawing and its earlier states (for undo); after every change the regions are
//! traced, given patches, unrolled and packed, and the design file written — the same file
//! `foldcam papercraft` reads, with the mesh beside it.
//!
//! | route | does |
//! | --- | --- |
//! | `GET /api/craft/examples` | the bundled examples' names |
//! | `POST /api/craft/example/{name}` | a session on a bundled example (its mesh, cut lines, placed patches) |
//! | `POST /api/craft/mesh?name=N` | a session on the OBJ/STL mesh in the body, no cut lines |
//! | `POST /api/craft/design?name=N&with=W` | a session on a `.craft.toml` and its mesh sent after it (`W` = JSON `[{name, size}]`) |
//! | `GET /api/craft/{id}` | the session's view with the mesh's triangles |
//! | `POST /api/craft/{id}/line` | adds a cut line through the points (JSON `{"points": [[x, y, z], …]}`) |
//! | `POST /api/craft/{id}/remove` | removes cut line `{"line": i}` |
//! | `POST /api/craft/{id}/undo` | back to the drawing before the last change |
//! | `GET /api/craft/{id}/design` | the design file (`.craft.toml`) |
//! | `GET /api/craft/{id}/mesh` | the mesh file it names |
//! | `POST /api/craft/{id}/pattern` | the first sheet opened as a studio document |
//!
//! Errors are JSON `{"error": …}`. A drawing whose parts cannot be made is still a view: the
//! regions carry their own errors and `error` says why the whole did not build.

use std::sync::{Arc, PoisonError};

use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, QueryRejection};
use axum::extract::{Path, Query, State};
use axum::http::StatusCode;
use axum::response::Response;
use axum::routing::{get, post};
use axum::{Json, Router};
use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::api::{
    ApiError, ApiResult, Opened, PathId, Studio, blocking, download, opened, upload_body,
    upload_name,
};
use super::design_open;
use super::edit_api::json_body;
use super::error::{Stage, StudioError};
use super::guard::JsonBody;
use super::history::Versions;
use super::sessions::Sessions;
use crate::design::papercraft::design::parse_design;
use crate::design::papercraft::paint::{Paint, paint_regions};
use crate::design::papercraft::sketch::{Evaluation, Sketch, SketchParams, regions, snap_line};
use crate::design::source::MeshUse;
use crate::mesh::ReferenceMesh;
use crate::mesh::{PolyMesh, parse_obj, parse_stl};

/// Most paper-craft sessions kept at once; the oldest is dropped first.
pub const MAX_CRAFT_SESSIONS: usize = 8;

/// Snapping reach of a cut line's ends, as a share of the mesh's bounding-box diagonal.
pub const SNAP_FRACTION: f64 = 0.03;

/// Samples per cut-line segment drawn on the mesh.
const CURVE_SAMPLES: usize = 12;

/// The bundled examples: name, design text, mesh name, mesh bytes.
const EXAMPLES: &[(&str, &str, &str, &[u8])] = &[
    (
        "vase",
        include_str!("../../examples/papercraft/vase.craft.toml"),
        "vase.obj",
        include_bytes!("../../examples/papercraft/vase.obj"),
    ),
    (
        "vase_auto",
        include_str!("../../examples/papercraft/vase_auto.craft.toml"),
        "vase.obj",
        include_bytes!("../../examples/papercraft/vase.obj"),
    ),
    (
        "fish",
        include_str!("../../examples/papercraft/fish.craft.toml"),
        "fish.obj",
        include_bytes!("../../examples/papercraft/fish.obj"),
    ),
];

/// One drawing being made.
struct Session {
    /// File stem of the downloads.
    name: String,
    mesh_bytes: Arc<Vec<u8>>,
    mesh: Arc<ReferenceMesh>,
    diagonal: f64,
    /// The drawing and its earlier states.
    sketches: Versions<Sketch>,
    eval: Evaluation,
    paint: Paint,
}

impl Session {
    fn new(
        name: String,
        mesh_name: &str,
        mesh_bytes: Vec<u8>,
        design: Option<&str>,
    ) -> Result<Session, StudioError> {
        let poly = read_mesh(mesh_name, &mesh_bytes)?;
        let (lo, hi) = poly.bounds();
        let diagonal = (hi - lo).length();
        let mesh = ReferenceMesh::new(&poly)
            .map_err(|e| StudioError::about(Stage::Design, mesh_name, e))?;
        let sketch = match design {
            Some(text) => {
                let d = parse_design(text).map_err(|e| {
                    StudioError::about(Stage::Design, format!("{name}.craft.toml"), e)
                })?;
                let mut s = Sketch::from_design(&d);
                s.mesh_name = mesh_name.to_string();
                s
            }
            None => Sketch {
                mesh_name: mesh_name.to_string(),
                params: SketchParams::for_diagonal(diagonal),
                lines: Vec::new(),
                placed: Vec::new(),
            },
        };
        let (eval, paint) = evaluate(&mesh, &sketch)?;
        Ok(Session {
            name,
            mesh_bytes: Arc::new(mesh_bytes),
            mesh: Arc::new(mesh),
            diagonal,
            sketches: Versions::new(sketch),
            eval,
            paint,
        })
    }

    /// Replaces the drawing by `next`, keeping the current one for undo.
    fn change(&mut self, next: Sketch) -> Result<(), StudioError> {
        let (eval, paint) = evaluate(&self.mesh, &next)?;
        self.sketches.push(next);
        self.eval = eval;
        self.paint = paint;
        Ok(())
    }
}

fn evaluate(mesh: &ReferenceMesh, sketch: &Sketch) -> Result<(Evaluation, Paint), StudioError> {
    let eval = sketch
        .evaluate(mesh)
        .map_err(|e| StudioError::named(Stage::Design, e))?;
    let lines = sketch
        .cut_lines()
        .map_err(|e| StudioError::named(Stage::Design, e))?;
    let paint = paint_regions(mesh, &lines, &regions(mesh, &lines));
    Ok((eval, paint))
}

fn read_mesh(name: &str, bytes: &[u8]) -> Result<PolyMesh, StudioError> {
    let lower = name.to_ascii_lowercase();
    let mesh = if lower.ends_with(".obj") {
        parse_obj(bytes)
    } else if lower.ends_with(".stl") {
        parse_stl(bytes)
    } else {
        return Err(StudioError::about(
            Stage::Read,
            name,
            "expected an OBJ or STL mesh (.obj, .stl)",
        ));
    };
    mesh.map_err(|e| StudioError::about(Stage::Read, name, e))
}

/// The paper-craft mode's state.
pub(super) struct Crafts {
    studio: Arc<Studio>,
    sessions: Sessions<Session>,
}

/// The paper-craft mode's routes (merged into the studio's router).
pub(super) fn router(studio: Arc<Studio>) -> Router<Arc<Studio>> {
    let crafts = Arc::new(Crafts {
        studio,
        sessions: Sessions::new("paper craft", MAX_CRAFT_SESSIONS),
    });
    Router::new()
        .route("/api/craft/examples", get(examples))
        .route("/api/craft/example/{name}", post(from_example))
        .route("/api/craft/mesh", post(from_mesh))
        .route("/api/craft/design", post(from_design))
        .route("/api/craft/{id}", get(show))
        .route("/api/craft/{id}/line", post(add_line))
        .route("/api/craft/{id}/remove", post(remove_line))
        .route("/api/craft/{id}/undo", post(undo))
        .route("/api/craft/{id}/design", get(design_file))
        .route("/api/craft/{id}/mesh", get(mesh_file))
        .route("/api/craft/{id}/pattern", post(to_pattern))
        .with_state(crafts)
}

/// The mesh's fan triangles, corner by corner (x, y, z), mesh units.
#[derive(Serialize)]
struct MeshView {
    triangles: Vec<f32>,
}

#[derive(Serialize)]
struct LineView {
    /// The points the cut line passes through.
    points: Vec<[f64; 3]>,
    /// The Catmull–Rom curve sampled and projected onto the mesh.
    curve: Vec<[f64; 3]>,
    /// A loose end: the line bounds no region yet.
    open: bool,
}

#[derive(Serialize)]
struct RegionView {
    lines: Vec<usize>,
    patch: Option<usize>,
    residual: Option<f64>,
    error: Option<String>,
}

#[derive(Serialize)]
struct PartView {
    /// The region it comes from.
    region: Option<usize>,
    sheet: usize,
    /// Outline on its sheet, millimetres.
    outline: Vec<[f64; 2]>,
    /// Tab polygons on its sheet, millimetres.
    tabs: Vec<Vec<[f64; 2]>>,
    /// The unrolled outline crosses itself.
    overlapping: bool,
}

/// The pieces of [`Paint`]: the triangle each is part of, nine coordinates each, the region
/// of each (−1: none).
#[derive(Serialize)]
struct PiecesView {
    triangles: Vec<usize>,
    corners: Vec<f64>,
    regions: Vec<i64>,
}

/// A region as the page numbers it, −1 for none.
fn region_number(r: Option<usize>) -> i64 {
    r.map_or(-1, |r| r as i64)
}

#[derive(Serialize)]
struct SessionView {
    id: u64,
    name: String,
    mesh_name: String,
    /// Snapping reach of cut-line ends, mesh units.
    reach: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    mesh: Option<MeshView>,
    /// Region of each mesh triangle (−1: none); a triangle in `pieces` is drawn as them.
    paint: Vec<i64>,
    /// Triangles a cut line divides, drawn as pieces so that the colours meet along it.
    pieces: PiecesView,
    lines: Vec<LineView>,
    regions: Vec<RegionView>,
    holes: Vec<Vec<usize>>,
    parts: Vec<PartView>,
    sheet: [f64; 2],
    sheets: usize,
    /// Why the parts could not be made.
    error: Option<String>,
    /// Glued cut lines whose two sides differ in length beyond the tolerance.
    unglued: Vec<crate::design::papercraft::Seam>,
    can_undo: bool,
}

fn session_view(id: u64, s: &Session, with_mesh: bool) -> SessionView {
    let mesh = with_mesh.then(|| MeshView {
        triangles: (0..s.mesh.triangle_count())
            .flat_map(|t| s.mesh.triangle(t))
            .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32])
            .collect(),
    });
    let arr = |p: DVec3| p.to_array();
    let open = &s.eval.open;
    let lines = s
        .sketches
        .current()
        .cut_lines()
        .unwrap_or_default()
        .iter()
        .enumerate()
        .map(|(i, l)| LineView {
            points: l.points().iter().map(|&p| arr(p)).collect(),
            curve: l
                .sample(&s.mesh, CURVE_SAMPLES)
                .into_iter()
                .map(arr)
                .collect(),
            open: open.contains(&i),
        })
        .collect();
    let regions = (s.eval.regions.iter())
        .map(|r| RegionView {
            lines: r.lines.clone(),
            patch: r.patch,
            residual: r.residual,
            error: r.error.clone(),
        })
        .collect();
    let unglued = match &s.eval.made {
        Ok(made) => (made.seams.iter())
            .filter(|seam| !seam.glues())
            .cloned()
            .collect(),
        Err(_) => Vec::new(),
    };
    let (parts, sheets, error) = match &s.eval.made {
        Ok(made) => {
            let parts = (made.placements.iter())
                .map(|pl| {
                    let part = &made.parts[pl.part];
                    let on_sheet = |ps: &[glam::DVec2]| -> Vec<[f64; 2]> {
                        ps.iter().map(|&p| pl.apply(p).to_array()).collect()
                    };
                    PartView {
                        region: (s.eval.regions.iter()).position(|r| r.patch == Some(part.patch)),
                        sheet: pl.sheet,
                        outline: on_sheet(&part.outline),
                        tabs: (part.tabs.iter())
                            .map(|t| on_sheet(&part.tab_polygon(t)))
                            .collect(),
                        overlapping: s.eval.self_overlapping.contains(&pl.part),
                    }
                })
                .collect();
            (parts, made.sheets.len(), None)
        }
        Err(e) => (Vec::new(), 0, Some(e.to_string())),
    };
    SessionView {
        id,
        name: s.name.clone(),
        mesh_name: s.sketches.current().mesh_name.clone(),
        reach: SNAP_FRACTION * s.diagonal,
        mesh,
        paint: (s.paint.triangles.iter())
            .map(|&r| region_number(r))
            .collect(),
        pieces: PiecesView {
            triangles: (s.paint.pieces.iter()).map(|p| p.triangle).collect(),
            corners: (s.paint.pieces.iter())
                .flat_map(|p| p.corners.iter().flat_map(|c| c.to_array()))
                .collect(),
            regions: (s.paint.pieces.iter())
                .map(|p| region_number(p.region))
                .collect(),
        },
        lines,
        regions,
        holes: s.eval.holes.clone(),
        parts,
        sheet: [
            s.sketches.current().params.sheet.width,
            s.sketches.current().params.sheet.height,
        ],
        sheets,
        error,
        unglued,
        can_undo: s.sketches.can_undo(),
    }
}

/// Runs `work` on session `id` off the async threads and answers its view.
async fn on_session(
    crafts: Arc<Crafts>,
    id: u64,
    with_mesh: bool,
    work: impl FnOnce(&mut Session) -> ApiResult<()> + Send + 'static,
) -> ApiResult<Json<SessionView>> {
    let session = crafts.sessions.get(id)?;
    blocking(move || {
        let mut s = session.lock().unwrap_or_else(PoisonError::into_inner);
        work(&mut s)?;
        Ok(Json(session_view(id, &s, with_mesh)))
    })
    .await
}

async fn start(
    crafts: Arc<Crafts>,
    make: impl FnOnce() -> Result<Session, StudioError> + Send + 'static,
) -> ApiResult<Json<SessionView>> {
    blocking(move || {
        let session = make()?;
        let (id, s) = crafts.sessions.add(session);
        let s = s.lock().unwrap_or_else(PoisonError::into_inner);
        Ok(Json(session_view(id, &s, true)))
    })
    .await
}

#[derive(Serialize)]
struct ExampleEntry {
    name: &'static str,
    mesh: &'static str,
}

async fn examples() -> Json<Vec<ExampleEntry>> {
    Json(
        EXAMPLES
            .iter()
            .map(|&(name, _, mesh, _)| ExampleEntry { name, mesh })
            .collect(),
    )
}

async fn from_example(
    State(crafts): State<Arc<Crafts>>,
    Path(name): Path<String>,
) -> ApiResult<Json<SessionView>> {
    let Some(&(name, text, mesh_name, mesh)) = EXAMPLES.iter().find(|e| e.0 == name) else {
        let known: Vec<&str> = EXAMPLES.iter().map(|e| e.0).collect();
        return Err(ApiError::new(
            StatusCode::NOT_FOUND,
            format!("no bundled paper-craft example {name:?} (known: {known:?})"),
        ));
    };
    start(crafts, move || {
        Session::new(name.to_string(), mesh_name, mesh.to_vec(), Some(text))
    })
    .await
}

#[derive(Deserialize)]
struct NameQuery {
    name: String,
    with: Option<String>,
}

async fn from_mesh(
    State(crafts): State<Arc<Crafts>>,
    query: Result<Query<NameQuery>, QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<SessionView>> {
    let Query(q) = query?;
    let name = upload_name(&q.name);
    let body = upload_body(&name, body)?;
    start(crafts, move || {
        Session::new(
            crate::design::source::file_stem(&name, "paper-craft"),
            &name,
            body.to_vec(),
            None,
        )
    })
    .await
}

async fn from_design(
    State(crafts): State<Arc<Crafts>>,
    query: Result<Query<NameQuery>, QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<SessionView>> {
    let Query(q) = query?;
    let name = upload_name(&q.name);
    let parts: Vec<design_open::Part> = match &q.with {
        None => Vec::new(),
        Some(w) => serde_json::from_str(w)
            .map_err(|e| ApiError::new(StatusCode::BAD_REQUEST, format!("with={w}: {e}")))?,
    };
    let body = upload_body(&name, body)?;
    start(crafts, move || {
        let (main, companions) = design_open::split_body(&name, &body, &parts)?;
        let text = std::str::from_utf8(main).map_err(|e| {
            let at = format!("byte {}: not UTF-8 text", e.valid_up_to());
            StudioError::about(Stage::Read, &name, at)
        })?;
        let design = parse_design(text).map_err(|e| StudioError::about(Stage::Design, &name, e))?;
        let wanted = upload_name(&design.mesh);
        let Some((mesh_name, mesh)) = companions.iter().find(|(n, _)| *n == wanted) else {
            return Err(StudioError::about(
                Stage::Design,
                &name,
                format!("names the mesh {:?}; send it with the design", design.mesh),
            ));
        };
        Session::new(
            crate::design::source::file_stem(&name, "paper-craft"),
            mesh_name,
            mesh.to_vec(),
            Some(text),
        )
    })
    .await
}

async fn show(
    State(crafts): State<Arc<Crafts>>,
    PathId(id): PathId,
) -> ApiResult<Json<SessionView>> {
    on_session(crafts, id, true, |_| Ok(())).await
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LineRequest {
    points: Vec<[f64; 3]>,
}

async fn add_line(
    State(crafts): State<Arc<Crafts>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<SessionView>> {
    let q: LineRequest = json_body(body, "cut line")?;
    on_session(crafts, id, false, move |s| {
        let clicked: Vec<DVec3> = q.points.iter().map(|&p| DVec3::from_array(p)).collect();
        let reach = SNAP_FRACTION * s.diagonal;
        let line = snap_line(&s.mesh, &s.sketches.current().lines, &clicked, reach)
            .map_err(|e| ApiError::input(e.to_string()))?;
        let mut next = s.sketches.current().clone();
        next.lines.push(line);
        s.change(next).map_err(ApiError::from)
    })
    .await
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RemoveRequest {
    line: usize,
}

async fn remove_line(
    State(crafts): State<Arc<Crafts>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<SessionView>> {
    let q: RemoveRequest = json_body(body, "remove")?;
    on_session(crafts, id, false, move |s| {
        let mut next = s.sketches.current().clone();
        next.remove_line(q.line)
            .map_err(|e| ApiError::input(e.to_string()))?;
        s.change(next).map_err(ApiError::from)
    })
    .await
}

async fn undo(
    State(crafts): State<Arc<Crafts>>,
    PathId(id): PathId,
) -> ApiResult<Json<SessionView>> {
    on_session(crafts, id, false, |s| {
        let (eval, paint) = evaluate(&s.mesh, s.sketches.undo()?)?;
        s.eval = eval;
        s.paint = paint;
        Ok(())
    })
    .await
}

async fn design_file(State(crafts): State<Arc<Crafts>>, PathId(id): PathId) -> ApiResult<Response> {
    let session = crafts.sessions.get(id)?;
    let s = session.lock().unwrap_or_else(PoisonError::into_inner);
    Ok(download(
        "application/toml; charset=utf-8",
        &format!("{}.craft.toml", s.name),
        s.eval.text.clone().into_bytes(),
    ))
}

async fn mesh_file(State(crafts): State<Arc<Crafts>>, PathId(id): PathId) -> ApiResult<Response> {
    let session = crafts.sessions.get(id)?;
    let s = session.lock().unwrap_or_else(PoisonError::into_inner);
    Ok(download(
        "application/octet-stream",
        &s.sketches.current().mesh_name,
        s.mesh_bytes.as_ref().clone(),
    ))
}

async fn to_pattern(
    State(crafts): State<Arc<Crafts>>,
    PathId(id): PathId,
) -> ApiResult<Json<Opened>> {
    let studio = Arc::clone(&crafts.studio);
    let session = crafts.sessions.get(id)?;
    let (name, text, mesh_name, mesh) = {
        let s = session.lock().unwrap_or_else(PoisonError::into_inner);
        (
            format!("{}.craft.toml", s.name),
            s.eval.text.clone(),
            s.sketches.current().mesh_name.clone(),
            Arc::clone(&s.mesh_bytes),
        )
    };
    blocking(move || {
        let companions = [(mesh_name, mesh.as_slice())];
        let doc = design_open::open_upload(&name, text.as_bytes(), &companions, MeshUse::Auto)?;
        opened(&studio, doc)
    })
    .await
}
