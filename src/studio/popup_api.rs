//! The studio's polygon pop-up editor: the interactive editor of Mitani & Suzuki (2004) over
//! the library's card ([`crate::design::popup::polygon`]). A session holds every version of
//! the design (one per edit, so undo and redo are exact); each edit is the paper's operation
//! replayed on the pattern ([`apply_edit`]), and after each the card is checked exactly as
//! `foldcam popup poly` checks the saved file ([`crate::design::source::poly::build`]), with
//! the faces that fail the pop-up check named and outlined ([`findings`]).
//!
//! | route | does |
//! | --- | --- |
//! | `POST /api/popup/new` | a session on a blank card (JSON `{"width": …, "depth": …, "height": …}`, mm) |
//! | `POST /api/popup/design?name=N` | a session on the `.popup.toml` in the body |
//! | `GET /api/popup/{id}` | the session's view: operations, check, crease pattern |
//! | `POST /api/popup/{id}/edit` | an edit (JSON `{"add": operation}`, `{"move": {"operation": n, "by": [dx, dy, dz]}}`, `{"resize": {"operation": n, "lo": [x, w], "hi": [x, w]}}`, `{"remove": {"operation": n}}`) |
//! | `POST /api/popup/{id}/undo`, `…/redo` | steps through the versions |
//! | `GET /api/popup/{id}/design` | the design as the `.popup.toml` the CLI reads |
//! | `GET /api/popup/{id}/card?angle=A` | the card's faces in space at opening angle A° (eq. 7) |
//! | `POST /api/popup/{id}/pattern` | the saved design opened as a studio document |
//!
//! Errors are JSON `{"error": …}` with the library's message; a refused edit names its
//! operation and leaves the session as it was.

use std::path::Path;
use std::sync::{Arc, PoisonError};

use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, QueryRejection};
use axum::extract::{Query, State};
use axum::response::Response;
use axum::routing::{get, post};
use axum::{Json, Router};
use serde::{Deserialize, Serialize};

use super::api::{
    ApiError, ApiResult, Opened, PathId, Studio, blocking, download, opened, upload_body,
    upload_name, upload_text,
};
use super::design_open::{design_error, open_upload};
use super::edit_api::json_body;
use super::error::{Stage, StudioError};
use super::guard::JsonBody;
use super::history::Versions;
use super::sessions::Sessions;
use crate::design::popup::polygon::{
    Add, CardSize, Design, Edit, Operation, PlaneName, apply_edit, crease_pattern, findings,
    fold_card, outline_box, parse_design, write_design,
};
use crate::design::source::poly::{PolyOptions, build};
use crate::design::source::summary::text_lines;
use crate::design::source::{DesignFile, MeshUse};
use crate::pattern::CreasePattern;

/// Most pop-up sessions kept at once; the oldest is dropped first.
pub const MAX_POPUP_SESSIONS: usize = 16;

/// The name a new card's downloads take.
const NEW_NAME: &str = "card.popup.toml";

/// One design being edited.
struct Session {
    /// The design's file name (always ending `.popup.toml`).
    name: String,
    /// Every version kept, the first the design opened.
    versions: Versions<Design>,
}

impl Session {
    fn design(&self) -> &Design {
        self.versions.current()
    }
}

pub(super) struct Popups {
    studio: Arc<Studio>,
    sessions: Sessions<Session>,
}

/// The pop-up editor's routes (merged into the studio's router).
pub(super) fn router(studio: Arc<Studio>) -> Router<Arc<Studio>> {
    let popups = Arc::new(Popups {
        studio,
        sessions: Sessions::new("pop-up card", MAX_POPUP_SESSIONS),
    });
    Router::new()
        .route("/api/popup/new", post(new_card))
        .route("/api/popup/design", post(from_design))
        .route("/api/popup/{id}", get(show))
        .route("/api/popup/{id}/edit", post(edit))
        .route("/api/popup/{id}/undo", post(undo))
        .route("/api/popup/{id}/redo", post(redo))
        .route("/api/popup/{id}/design", get(design_file))
        .route("/api/popup/{id}/card", get(card))
        .route("/api/popup/{id}/pattern", post(to_pattern))
        .with_state(popups)
}

/// An edit as the page sends it.
#[derive(Deserialize)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
enum EditRequest {
    Add(Operation),
    Move {
        operation: usize,
        by: [f64; 3],
    },
    Resize {
        operation: usize,
        lo: [f64; 2],
        hi: [f64; 2],
    },
    Remove {
        operation: usize,
    },
}

impl From<EditRequest> for Edit {
    fn from(r: EditRequest) -> Edit {
        match r {
            EditRequest::Add(op) => Edit::Add(op),
            EditRequest::Move { operation, by } => Edit::Move { operation, by },
            EditRequest::Resize { operation, lo, hi } => Edit::Resize { operation, lo, hi },
            EditRequest::Remove { operation } => Edit::Remove { operation },
        }
    }
}

/// One operation as the page draws it (millimetres, whatever the file's units).
#[derive(Serialize)]
struct OperationView {
    /// 1-based, as messages number it.
    number: usize,
    /// "vertical" (y = at) or "horizontal" (z = at).
    plane: &'static str,
    at: f64,
    /// (x, z) on a vertical plane, (x, y) on a horizontal one.
    polygon: Vec<[f64; 2]>,
    opening: bool,
    /// The outline's box on its plane: lower and upper corner.
    lo: [f64; 2],
    hi: [f64; 2],
}

/// A face that does not stand up.
#[derive(Serialize)]
struct FindingView {
    /// The operation that made it (absent for the back sheet).
    operation: Option<usize>,
    words: String,
    /// Its outline on the pattern (outer ring, then holes), millimetres.
    outline: Vec<Vec<[f64; 2]>>,
}

/// The crease pattern for the page's pattern view.
#[derive(Serialize)]
struct CreaseView {
    vertices: Vec<[f64; 2]>,
    /// End vertices and FOLD assignment letter.
    edges: Vec<([usize; 2], char)>,
}

impl CreaseView {
    fn new(cp: &CreasePattern) -> CreaseView {
        CreaseView {
            vertices: cp.vertices.iter().map(|p| p.to_array()).collect(),
            edges: cp
                .edges
                .iter()
                .map(|e| {
                    (
                        [e.vertices[0].index(), e.vertices[1].index()],
                        e.assignment.letter(),
                    )
                })
                .collect(),
        }
    }
}

/// Whether there are versions to undo to and redo.
#[derive(Serialize)]
struct History {
    undo: bool,
    redo: bool,
}

/// The session as the page shows it.
#[derive(Serialize)]
struct SessionView {
    id: u64,
    name: String,
    /// Width along the fold, depth of the base and height of the back sheet, mm.
    card: [f64; 3],
    operations: Vec<OperationView>,
    history: History,
    /// Whether `foldcam popup poly` makes the saved design.
    valid: bool,
    /// The command's summary when valid, its refusal line by line when not.
    lines: Vec<String>,
    findings: Vec<FindingView>,
    /// The crease pattern (absent when the card has none).
    pattern: Option<CreaseView>,
}

/// The card as the CLI builds the saved text: the design made, or the refusal's lines.
fn cli_build(
    name: &str,
    text: &str,
) -> Result<crate::design::source::poly::PolyDesign, StudioError> {
    let path = Path::new(name);
    let file = DesignFile {
        name: path,
        bytes: text.as_bytes(),
    };
    let mut notes = Vec::new();
    build(&file, &PolyOptions::default(), &mut notes).map_err(|e| design_error(&e))
}

fn session_view(id: u64, s: &Session) -> ApiResult<SessionView> {
    let design = s.design();
    let replay = design
        .replay()
        .map_err(|e| ApiError::input(e.to_string()))?;
    let found = findings(&replay.card, &replay.report);
    let built = cli_build(&s.name, &write_design(design));
    let (valid, lines, pattern) = match built {
        Ok(made) => (true, text_lines(&made.summary), Some(made.pattern)),
        Err(refusal) => (
            false,
            refusal.to_string().lines().map(str::to_string).collect(),
            crease_pattern(&replay.card).ok(),
        ),
    };
    let grid = design.card.grid.unwrap_or(1.0);
    let operations = design
        .operations
        .iter()
        .enumerate()
        .map(|(i, op)| {
            let scale = match op.units {
                crate::design::popup::polygon::Units::Mm => 1.0,
                crate::design::popup::polygon::Units::Grid => grid,
            };
            let polygon: Vec<[f64; 2]> = op
                .polygon
                .iter()
                .map(|p| [p[0] * scale, p[1] * scale])
                .collect();
            let (lo, hi) = outline_box(op);
            OperationView {
                number: i + 1,
                plane: match op.plane {
                    PlaneName::Vertical => "vertical",
                    PlaneName::Horizontal => "horizontal",
                },
                at: op.at * scale,
                polygon,
                opening: op.add == Add::Opening,
                lo: lo.map(|v| v * scale),
                hi: hi.map(|v| v * scale),
            }
        })
        .collect();
    let c = &design.card;
    Ok(SessionView {
        id,
        name: s.name.clone(),
        card: [c.width, c.depth, c.height],
        operations,
        history: History {
            undo: s.versions.can_undo(),
            redo: s.versions.can_redo(),
        },
        valid,
        lines,
        findings: found
            .into_iter()
            .map(|f| FindingView {
                operation: f.operation,
                words: f.words,
                outline: f
                    .outline
                    .iter()
                    .map(|r| r.iter().map(|p| p.to_array()).collect())
                    .collect(),
            })
            .collect(),
        pattern: pattern.as_ref().map(CreaseView::new),
    })
}

/// Runs `work` on session `id` off the async threads.
async fn on_session<T: Send + 'static>(
    popups: Arc<Popups>,
    id: u64,
    work: impl FnOnce(&mut Session) -> ApiResult<T> + Send + 'static,
) -> ApiResult<T> {
    let session = popups.sessions.get(id)?;
    blocking(move || {
        let mut s = session.lock().unwrap_or_else(PoisonError::into_inner);
        work(&mut s)
    })
    .await
}

/// Opens a session on `design` (refused when the model refuses an operation).
fn start(popups: &Popups, name: String, design: Design) -> ApiResult<Json<SessionView>> {
    design
        .build()
        .map_err(|e| ApiError::input(format!("{name}: {e}")))?;
    let (id, s) = popups.sessions.add(Session {
        name,
        versions: Versions::new(design),
    });
    let s = s.lock().unwrap_or_else(PoisonError::into_inner);
    Ok(Json(session_view(id, &s)?))
}

async fn new_card(
    State(popups): State<Arc<Popups>>,
    body: JsonBody,
) -> ApiResult<Json<SessionView>> {
    let card: CardSize = json_body(body, "new card")?;
    blocking(move || {
        let design = Design {
            card,
            operations: Vec::new(),
        };
        start(&popups, NEW_NAME.into(), design)
    })
    .await
}

#[derive(Deserialize)]
struct NameQuery {
    name: String,
}

async fn from_design(
    State(popups): State<Arc<Popups>>,
    query: Result<Query<NameQuery>, QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<SessionView>> {
    let Query(q) = query?;
    let name = upload_name(&q.name);
    let body = upload_body(&name, body)?;
    blocking(move || {
        let text = upload_text(&name, &body)?;
        let design = parse_design(text).map_err(|e| ApiError::input(format!("{name}: {e}")))?;
        let name = if name.ends_with(".popup.toml") {
            name
        } else {
            NEW_NAME.into()
        };
        start(&popups, name, design)
    })
    .await
}

async fn show(
    State(popups): State<Arc<Popups>>,
    PathId(id): PathId,
) -> ApiResult<Json<SessionView>> {
    on_session(popups, id, move |s| Ok(Json(session_view(id, s)?))).await
}

async fn edit(
    State(popups): State<Arc<Popups>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<SessionView>> {
    let request: EditRequest = json_body(body, "edit")?;
    on_session(popups, id, move |s| {
        let next = apply_edit(s.design(), &request.into())
            .map_err(|e| StudioError::about(Stage::Design, &s.name, e))?;
        s.versions.push(next);
        Ok(Json(session_view(id, s)?))
    })
    .await
}

async fn undo(
    State(popups): State<Arc<Popups>>,
    PathId(id): PathId,
) -> ApiResult<Json<SessionView>> {
    on_session(popups, id, move |s| {
        s.versions.undo()?;
        Ok(Json(session_view(id, s)?))
    })
    .await
}

async fn redo(
    State(popups): State<Arc<Popups>>,
    PathId(id): PathId,
) -> ApiResult<Json<SessionView>> {
    on_session(popups, id, move |s| {
        s.versions.redo()?;
        Ok(Json(session_view(id, s)?))
    })
    .await
}

async fn design_file(State(popups): State<Arc<Popups>>, PathId(id): PathId) -> ApiResult<Response> {
    on_session(popups, id, move |s| {
        Ok(download(
            "application/toml; charset=utf-8",
            &s.name,
            write_design(s.design()).into_bytes(),
        ))
    })
    .await
}

#[derive(Deserialize)]
struct AngleQuery {
    angle: f64,
}

/// One face of the card in space: its rings on the pattern (for triangulating) and the same
/// rings' points in space, millimetres.
#[derive(Serialize)]
struct SpaceFace {
    flat: Vec<Vec<[f64; 2]>>,
    space: Vec<Vec<[f64; 3]>>,
}

#[derive(Serialize)]
struct CardView {
    /// The opening angle shown, degrees (0 shut, 90 standing, 180 flat).
    angle: f64,
    faces: Vec<SpaceFace>,
}

async fn card(
    State(popups): State<Arc<Popups>>,
    PathId(id): PathId,
    query: Result<Query<AngleQuery>, QueryRejection>,
) -> ApiResult<Json<CardView>> {
    let Query(q) = query?;
    if !(q.angle.is_finite() && (0.0..=180.0).contains(&q.angle)) {
        return Err(ApiError::input(format!(
            "opening angle {}° must be from 0 to 180",
            q.angle
        )));
    }
    on_session(popups, id, move |s| {
        let card = s
            .design()
            .build()
            .map_err(|e| ApiError::input(e.to_string()))?;
        let cp =
            crease_pattern(&card).map_err(|e| StudioError::about(Stage::Design, &s.name, e))?;
        let folded = fold_card(&card, &cp, q.angle);
        let faces = folded.state.faces.as_deref().unwrap_or_default();
        let faces = faces
            .iter()
            .map(|f| {
                let rings: Vec<&Vec<crate::pattern::VertexId>> =
                    std::iter::once(&f.outer).chain(&f.holes).collect();
                SpaceFace {
                    flat: rings
                        .iter()
                        .map(|r| {
                            r.iter()
                                .map(|&v| cp.position(folded.source[v.index()]).to_array())
                                .collect()
                        })
                        .collect(),
                    space: rings
                        .iter()
                        .map(|r| {
                            r.iter()
                                .map(|&v| folded.state.positions[v.index()].to_array())
                                .collect()
                        })
                        .collect(),
                }
            })
            .collect();
        Ok(Json(CardView {
            angle: q.angle,
            faces,
        }))
    })
    .await
}

async fn to_pattern(
    State(popups): State<Arc<Popups>>,
    PathId(id): PathId,
) -> ApiResult<Json<Opened>> {
    let studio = Arc::clone(&popups.studio);
    let (name, text) = on_session(popups, id, move |s| {
        Ok((s.name.clone(), write_design(s.design())))
    })
    .await?;
    blocking(move || {
        let doc = open_upload(&name, text.as_bytes(), &[], MeshUse::default())?;
        opened(&studio, doc)
    })
    .await
}
