//! The studio's voxel pop-up editor: the editor of Mitani, Suzuki & Uno (2003), §2.7, over
//! the library's voxel card ([`crate::design::popup::voxel`]). Each session holds a card and
//! its earlier versions (undo, redo); every reply carries the card's faults at their places
//! ([`card_verdict`]), so the page can mark them; the card opens from 0° to 180° by the
//! paper's eq. 6 ([`fold_card`]).
//!
//! | route | does |
//! | --- | --- |
//! | `POST /api/voxel/new` | a session on an empty card (JSON `{"nx", "ny", "nz", "cell_mm", "margin_mm"}`) |
//! | `POST /api/voxel/load?name=N` | a session on the body: a `.voxel.txt`, or a height-map `.png` or an OBJ/STL mesh made a card as `foldcam popup voxel` makes it (its options `resolution`, `depth`, `card_width`, `card_margin`, `morphology`, `windows`, `thin_top` in the query) |
//! | `GET /api/voxel/{id}` | the session's view: depths, windows, left-out tops, faults |
//! | `POST /api/voxel/{id}/edit` | one edit (JSON [`VoxelEdit`]) |
//! | `POST /api/voxel/{id}/undo`, `…/redo` | steps back or forward through the edits |
//! | `GET /api/voxel/{id}/open?angle=A` | the card opened A degrees (0 shut, 90 standing, 180 flat): triangles, and the faulty cells as quads |
//! | `GET /api/voxel/{id}/save` | the card as the `.voxel.txt` `foldcam popup voxel` reads |
//! | `POST /api/voxel/{id}/pattern` | the saved card built as `foldcam popup voxel` builds it, opened as a studio document |

use std::sync::{Arc, PoisonError};

use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, QueryRejection};
use axum::extract::{Query, State};
use axum::response::Response;
use axum::routing::{get, post};
use axum::{Json, Router};
use glam::{DVec2, DVec3};
use serde::{Deserialize, Serialize};

use super::api::{
    ApiError, ApiResult, Opened, PathId, Studio, blocking, download, opened, upload_body,
    upload_name,
};
use super::edit_api::json_body;
use super::error::{Stage, StudioError};
use super::guard::JsonBody;
use super::history::Versions;
use super::sessions::Sessions;
use super::{budget, design_open};
use crate::design::popup::voxel::estimate as conversion_estimate;
use crate::design::popup::voxel::surface::Surface;
use crate::design::popup::voxel::{
    CardVerdict, EditChange, PatternCell, VoxelCard, VoxelEdit, VoxelFace, apply_edit,
    card_verdict, crease_pattern, fold_card, format_voxel_card, open_transform,
};
use crate::design::source::voxel::{VoxelOptions, load_card};
use crate::design::source::{BuildNote, DesignFile, DesignKind, MeshUse, SourceError};
use crate::geom::triangulate::triangulate_polygon;
use crate::limits::{STUDIO_BYTES_PER_PATTERN_CELL, STUDIO_VOXEL_PATTERN_CELLS};

/// Most voxel sessions kept at once; the oldest is dropped first.
pub const MAX_VOXEL_SESSIONS: usize = 16;

/// Most faulty cells sent for one fault (the page marks them; the list says how many more).
pub const CELLS_SHOWN: usize = 2_000;

/// One card being edited.
struct Session {
    /// The file it came from, or "card.voxel.txt".
    name: String,
    /// Every version kept, the first the card opened.
    versions: Versions<VoxelCard>,
}

impl Session {
    fn card(&self) -> &VoxelCard {
        self.versions.current()
    }

    /// The name of the saved file: the session's, ending in `.voxel.txt`.
    fn file_name(&self) -> String {
        format!(
            "{}.voxel.txt",
            crate::design::source::file_stem(&self.name, "card")
        )
    }
}

/// The editor's state: the sessions, and the studio (to open a pattern as a document).
pub(super) struct Voxels {
    studio: Arc<Studio>,
    sessions: Sessions<Session>,
}

/// The editor's routes (merged into the studio's router).
pub(super) fn router(studio: Arc<Studio>) -> Router<Arc<Studio>> {
    let voxels = Arc::new(Voxels {
        studio,
        sessions: Sessions::new("voxel card", MAX_VOXEL_SESSIONS),
    });
    Router::new()
        .route("/api/voxel/new", post(new_card))
        .route("/api/voxel/load", post(load))
        .route("/api/voxel/{id}", get(show))
        .route("/api/voxel/{id}/edit", post(edit))
        .route("/api/voxel/{id}/undo", post(undo))
        .route("/api/voxel/{id}/redo", post(redo))
        .route("/api/voxel/{id}/open", get(open_card))
        .route("/api/voxel/{id}/save", get(save))
        .route("/api/voxel/{id}/pattern", post(to_pattern))
        .with_state(voxels)
}

/// The request of `new`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct NewCard {
    nx: usize,
    ny: usize,
    nz: usize,
    cell_mm: f64,
    #[serde(default)]
    margin_mm: f64,
}

/// A face as the page marks it: `kind` is `front` or `top` (of voxel `cell`), `back` (the
/// back sheet at x = `cell[0]`, z = `cell[2]`) or `base` (the base at x = `cell[0]`, y = `cell[1]`).
#[derive(Serialize)]
struct FaceView {
    kind: &'static str,
    cell: [usize; 3],
    /// Pattern column and row.
    pattern: [usize; 2],
}

fn face_view(c: &PatternCell) -> FaceView {
    let (kind, cell) = match c.face {
        VoxelFace::Front { x, y, z } => ("front", [x, y, z]),
        VoxelFace::Top { x, y, z } => ("top", [x, y, z]),
        VoxelFace::BackSheet { x, z } => ("back", [x, 0, z]),
        VoxelFace::Base { x, y } => ("base", [x, y, 0]),
    };
    FaceView {
        kind,
        cell,
        pattern: [c.x, c.row],
    }
}

/// One fault of the card, at its place.
#[derive(Serialize)]
struct FaultView {
    /// `popup` (refused), `loose` (refused) or `beyond` (a warning).
    kind: &'static str,
    message: String,
    faces: Vec<FaceView>,
    /// Faces at fault left out of `faces` (beyond [`CELLS_SHOWN`]).
    more: usize,
}

fn faults(card: &VoxelCard, v: &CardVerdict) -> Vec<FaultView> {
    let s = Surface::new(card);
    let mut out: Vec<FaultView> = v
        .popup
        .iter()
        .map(|p| {
            let row = p.z + card.ny() - p.depth;
            FaultView {
                kind: "popup",
                message: format!(
                    "the card would not pop up: {}",
                    p.describe_at(card.cell_mm())
                ),
                faces: vec![face_view(&PatternCell {
                    x: p.x,
                    row,
                    face: crate::design::popup::voxel::face_of(&s, p.x, row),
                })],
                more: 0,
            }
        })
        .collect();
    for piece in &v.loose {
        out.push(FaultView {
            kind: "loose",
            message: format!(
                "a piece of {} cell(s), {:.1} mm², is cut on every side and falls out (it starts \
                 at {})",
                piece.cells.len(),
                piece.area_mm2,
                piece.cells[0].face
            ),
            faces: piece
                .cells
                .iter()
                .take(CELLS_SHOWN)
                .map(face_view)
                .collect(),
            more: piece.cells.len().saturating_sub(CELLS_SHOWN),
        });
    }
    if let Some(far) = v.beyond.first() {
        out.push(FaultView {
            kind: "beyond",
            message: format!(
                "folded shut, {} face cell(s) reach beyond the closed card, up to {:.1} mm at {}: \
                 a larger margin or a lower model holds them",
                v.beyond.len(),
                far.beyond_mm,
                far.cell.face
            ),
            faces: v
                .beyond
                .iter()
                .take(CELLS_SHOWN)
                .map(|b| face_view(&b.cell))
                .collect(),
            more: v.beyond.len().saturating_sub(CELLS_SHOWN),
        });
    }
    out
}

/// The session as the page shows it.
#[derive(Serialize)]
struct CardView {
    id: u64,
    name: String,
    nx: usize,
    ny: usize,
    nz: usize,
    cell_mm: f64,
    margin_mm: f64,
    /// Sheet width and height, mm.
    sheet_mm: [f64; 2],
    /// `depth[x][z]`: the row's filled cells are y < depth.
    depth: Vec<Vec<usize>>,
    /// `window[x][z]` (eq. 5).
    window: Vec<Vec<bool>>,
    /// `omitted[x][z]`: the row's top face is left out (§3.3).
    omitted: Vec<Vec<bool>>,
    /// Pops up and holds together (faces beyond the closed card only warn).
    makes_a_card: bool,
    faults: Vec<FaultView>,
    undo: bool,
    redo: bool,
    /// What the last edit changed.
    #[serde(skip_serializing_if = "Option::is_none")]
    change: Option<[usize; 2]>,
}

fn card_view(id: u64, s: &Session, change: Option<EditChange>) -> ApiResult<CardView> {
    let card = s.card();
    let _memory = card_memory(&s.name, card)?;
    let verdict = card_verdict(card)
        .map_err(|e| ApiError::input(format!("{}: the crease pattern: {e}", s.name)))?;
    let per_row = |f: &dyn Fn(usize, usize) -> bool| -> Vec<Vec<bool>> {
        (0..card.nx())
            .map(|x| (0..card.nz()).map(|z| f(x, z)).collect())
            .collect()
    };
    let (w, h) = card.sheet_mm();
    Ok(CardView {
        id,
        name: s.name.clone(),
        nx: card.nx(),
        ny: card.ny(),
        nz: card.nz(),
        cell_mm: card.cell_mm(),
        margin_mm: card.margin_mm(),
        sheet_mm: [w, h],
        depth: (0..card.nx())
            .map(|x| (0..card.nz()).map(|z| card.depth(x, z)).collect())
            .collect(),
        window: per_row(&|x, z| card.is_hole(x, z)),
        omitted: per_row(&|x, z| card.is_top_omitted(x, z)),
        makes_a_card: verdict.makes_a_card(),
        faults: faults(card, &verdict),
        undo: s.versions.can_undo(),
        redo: s.versions.can_redo(),
        change: change.map(|c| [c.added, c.removed]),
    })
}

/// Runs `work` on session `id` off the async threads.
async fn on_session<T: Send + 'static>(
    voxels: Arc<Voxels>,
    id: u64,
    work: impl FnOnce(&mut Session) -> ApiResult<T> + Send + 'static,
) -> ApiResult<T> {
    let session = voxels.sessions.get(id)?;
    blocking(move || {
        let mut s = session.lock().unwrap_or_else(PoisonError::into_inner);
        work(&mut s)
    })
    .await
}

fn start(voxels: &Voxels, name: String, card: VoxelCard) -> ApiResult<Json<CardView>> {
    let (id, s) = voxels.sessions.add(Session {
        name,
        versions: Versions::new(card),
    });
    let s = s.lock().unwrap_or_else(PoisonError::into_inner);
    Ok(Json(card_view(id, &s, None)?))
}

/// Refuses a card of `nx × ny × nz` cells beyond [`STUDIO_VOXEL_PATTERN_CELLS`] pattern
/// cells; otherwise its pattern cells.
fn card_cells(what: &str, [nx, ny, nz]: [usize; 3]) -> ApiResult<u64> {
    let cells = nx.saturating_mul(ny.saturating_add(nz));
    if cells > STUDIO_VOXEL_PATTERN_CELLS {
        return Err(ApiError::input(format!(
            "{what}: a card of {nx} × {ny} × {nz} cells has a crease pattern of {cells} cells, \
             more than the {STUDIO_VOXEL_PATTERN_CELLS} the studio edits: make it smaller, or \
             build it with `foldcam popup voxel`"
        )));
    }
    Ok(cells as u64)
}

/// Reserves the memory of a reply on `card` (its verdict and view, [`budget`]).
fn card_memory(what: &str, card: &VoxelCard) -> ApiResult<budget::Reservation> {
    let cells = card_cells(what, [card.nx(), card.ny(), card.nz()])?;
    budget::reserve(what, cells * STUDIO_BYTES_PER_PATTERN_CELL)
}

async fn new_card(State(voxels): State<Arc<Voxels>>, body: JsonBody) -> ApiResult<Json<CardView>> {
    let q: NewCard = json_body(body, "new card")?;
    card_cells("new card", [q.nx, q.ny, q.nz])?;
    blocking(move || {
        let mut card = VoxelCard::new(q.nx, q.ny, q.nz, q.cell_mm)
            .map_err(|e| ApiError::input(format!("new card: {e}")))?;
        card.set_margin_mm(q.margin_mm)
            .map_err(|e| ApiError::input(format!("new card: {e}")))?;
        start(&voxels, "card.voxel.txt".into(), card)
    })
    .await
}

/// `name`: the file's name; the rest are `foldcam popup voxel`'s options of the same names
/// (its defaults when left out) for a height map or mesh.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LoadQuery {
    name: String,
    resolution: Option<usize>,
    depth: Option<usize>,
    card_width: Option<f64>,
    card_margin: Option<f64>,
    morphology: Option<usize>,
    windows: Option<bool>,
    thin_top: Option<usize>,
}

impl LoadQuery {
    fn options(&self) -> ApiResult<VoxelOptions> {
        let d = VoxelOptions::default();
        let options = VoxelOptions {
            resolution: self.resolution.unwrap_or(d.resolution),
            depth: self.depth.unwrap_or(d.depth),
            card_width: self.card_width.unwrap_or(d.card_width),
            card_margin: self.card_margin.unwrap_or(d.card_margin),
            morphology: self.morphology.unwrap_or(d.morphology),
            windows: self.windows.unwrap_or(d.windows),
            thin_top: self.thin_top.unwrap_or(d.thin_top),
            max_pattern_cells: STUDIO_VOXEL_PATTERN_CELLS,
            ..d
        };
        options
            .validate()
            .map_err(|e| ApiError::input(design_open::message(&e)))?;
        Ok(options)
    }
}

async fn load(
    State(voxels): State<Arc<Voxels>>,
    query: Result<Query<LoadQuery>, QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<CardView>> {
    let Query(q) = query?;
    let name = upload_name(&q.name);
    let options = q.options()?;
    let body = upload_body(&name, body)?;
    // The conversion of a mesh or height map into a card of at most the largest size the
    // studio edits (`max_pattern_cells`), by the conversion's own estimate of its memory.
    let converting = budget::reserve(
        &name,
        (conversion_estimate::BASE_BYTES
            + conversion_estimate::BYTES_PER_PATTERN_CELL * STUDIO_VOXEL_PATTERN_CELLS as f64)
            as u64,
    )?;
    blocking(move || {
        let converting = converting;
        let path = std::path::PathBuf::from(&name);
        let file = DesignFile {
            name: &path,
            bytes: &body,
        };
        let fail = |e: SourceError| ApiError::from(design_open::design_error(&e));
        let mesh = match DesignKind::recognise(&path, &body) {
            Some(DesignKind::Mesh) => Some(file.mesh().map_err(fail)?),
            _ => None,
        };
        let mut notes: Vec<BuildNote> = Vec::new();
        let card = load_card(&file, mesh.as_ref(), &options, &mut notes).map_err(fail)?;
        drop(converting);
        start(&voxels, name, card)
    })
    .await
}

async fn show(State(voxels): State<Arc<Voxels>>, PathId(id): PathId) -> ApiResult<Json<CardView>> {
    on_session(voxels, id, move |s| Ok(Json(card_view(id, s, None)?))).await
}

async fn edit(
    State(voxels): State<Arc<Voxels>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<CardView>> {
    let e: VoxelEdit = json_body(body, "voxel edit")?;
    on_session(voxels, id, move |s| {
        let mut card = s.card().clone();
        let change = apply_edit(&mut card, &e)
            .map_err(|err| ApiError::input(format!("{}: {err}", s.name)))?;
        s.versions.push(card);
        Ok(Json(card_view(id, s, Some(change))?))
    })
    .await
}

async fn undo(State(voxels): State<Arc<Voxels>>, PathId(id): PathId) -> ApiResult<Json<CardView>> {
    on_session(voxels, id, move |s| {
        s.versions.undo()?;
        Ok(Json(card_view(id, s, None)?))
    })
    .await
}

async fn redo(State(voxels): State<Arc<Voxels>>, PathId(id): PathId) -> ApiResult<Json<CardView>> {
    on_session(voxels, id, move |s| {
        s.versions.redo()?;
        Ok(Json(card_view(id, s, None)?))
    })
    .await
}

#[derive(Deserialize)]
struct OpenQuery {
    angle: f64,
}

/// The card opened: every pattern face triangulated on its pattern polygon, the triangles
/// on the folded vertices; each faulty cell as a quad at its place.
#[derive(Serialize)]
struct OpenView {
    /// The opening angle, degrees (0 shut, 90 standing, 180 flat).
    angle: f64,
    /// Folded vertices, mm (x along the fold, y towards the viewer, z up).
    positions: Vec<[f64; 3]>,
    /// Three vertex indices each.
    triangles: Vec<[usize; 3]>,
    /// For each fault of the view (same order), the corners of its faulty cells, mm.
    faults: Vec<Vec<[[f64; 3]; 4]>>,
}

/// The card `name` opened to `angle` degrees.
fn open_view(name: &str, card: &VoxelCard, angle: f64) -> Result<OpenView, StudioError> {
    if !angle.is_finite() {
        let reason = format!("angle {angle}: expected degrees from 0 to 180");
        return Err(StudioError::about(Stage::Request, name, reason));
    }
    let pattern_error = |e: &dyn std::fmt::Display| {
        StudioError::about(Stage::Design, name, format!("the crease pattern: {e}"))
    };
    let cp = crease_pattern(card).map_err(|e| pattern_error(&e))?;
    let folded = fold_card(card, &cp, angle).state;
    let mut triangles = Vec::new();
    for (pattern_face, face) in cp.faces.iter().flatten().zip(folded.faces.iter().flatten()) {
        let ring = |r: &[crate::pattern::VertexId]| -> Vec<DVec2> {
            r.iter().map(|&v| cp.position(v)).collect()
        };
        let holes: Vec<Vec<DVec2>> = pattern_face
            .holes
            .iter()
            .map(|h| ring(h.as_slice()))
            .collect();
        let tris =
            triangulate_polygon(&ring(pattern_face.outer.as_slice()), &holes).map_err(|e| {
                StudioError::about(Stage::Design, name, format!("a face of the card: {e}"))
            })?;
        let ids: Vec<usize> = face
            .outer
            .iter()
            .chain(face.holes.iter().flatten())
            .map(|v| v.index())
            .collect();
        triangles.extend(tris.iter().map(|t| t.map(|k| ids[k])));
    }
    let verdict = card_verdict(card).map_err(|e| pattern_error(&e))?;
    let surface = Surface::new(card);
    let (s, ny) = (card.cell_mm(), card.ny() as f64);
    let quad = |f: &FaceView| -> [[f64; 3]; 4] {
        let [x, r] = f.pattern;
        let plane = surface.plane(x as i64, r as i64);
        let v0 = r as f64 - ny;
        [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(|(du, dv)| {
            let p = DVec3::from(plane.to_card(x as f64 + du, v0 + dv));
            (open_transform(p, angle) * s).to_array()
        })
    };
    Ok(OpenView {
        angle,
        positions: folded.positions.iter().map(|p| p.to_array()).collect(),
        triangles,
        faults: faults(card, &verdict)
            .iter()
            .map(|f| f.faces.iter().map(quad).collect())
            .collect(),
    })
}

async fn open_card(
    State(voxels): State<Arc<Voxels>>,
    PathId(id): PathId,
    query: Result<Query<OpenQuery>, QueryRejection>,
) -> ApiResult<Json<OpenView>> {
    let Query(q) = query?;
    on_session(voxels, id, move |s| {
        open_view(&s.name, s.card(), q.angle)
            .map(Json)
            .map_err(ApiError::from)
    })
    .await
}

async fn save(State(voxels): State<Arc<Voxels>>, PathId(id): PathId) -> ApiResult<Response> {
    on_session(voxels, id, move |s| {
        Ok(download(
            "text/plain; charset=utf-8",
            &s.file_name(),
            format_voxel_card(s.card()).into_bytes(),
        ))
    })
    .await
}

async fn to_pattern(
    State(voxels): State<Arc<Voxels>>,
    PathId(id): PathId,
) -> ApiResult<Json<Opened>> {
    let studio = Arc::clone(&voxels.studio);
    let (name, text) = on_session(voxels, id, move |s| {
        Ok((s.file_name(), format_voxel_card(s.card())))
    })
    .await?;
    blocking(move || {
        // The saved file, built as an upload of it is (and as `foldcam popup voxel` builds it).
        let doc = design_open::open_upload(&name, text.as_bytes(), &[], MeshUse::Auto)?;
        opened(&studio, doc)
    })
    .await
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_open_card_covers_the_sheet_at_every_angle() {
        let mut card = VoxelCard::new(4, 3, 3, 5.0).unwrap();
        card.add(1, 1, 1).unwrap();
        // Every triangle is one of the card's faces moved rigidly (eq. 6 is an isometry of
        // each face), so the triangles' area is the sheet's at any opening.
        let (w, h) = card.sheet_mm();
        for angle in [0.0, 30.0, 90.0, 150.0, 180.0] {
            let v = open_view("card", &card, angle).unwrap();
            let area: f64 = v
                .triangles
                .iter()
                .map(|t| {
                    let p = t.map(|k| DVec3::from(v.positions[k]));
                    0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length()
                })
                .sum();
            assert!((area - w * h).abs() < 1e-6, "{angle}°: {area} vs {}", w * h);
        }
        assert!(open_view("card", &card, f64::NAN).is_err());
    }
}
