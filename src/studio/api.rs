//! The studio's HTTP routes: the embedded front end and a JSON API over the library.
//!
//! | route | does |
//! | --- | --- |
//! | `GET /api/files` | the files named on the command line (index and name) |
//! | `POST /api/files/{index}[?make=M]` | opens one of them: the pattern view |
//! | `POST /api/upload?name=N[&make=M][&with=W]` | reads the body as a file named `N` (a pattern or a design file, see [`design_open`]; `M` what a mesh becomes; `W` the files sent after it, JSON `[{name, size}]`): the pattern view |
//! | `POST /api/docs/{id}/edit` | applies one edit (JSON `Edit`): the new version's view |
//! | `POST /api/docs/{id}/undo`, `…/redo` | steps back or forward through the edits |
//! | `POST /api/docs/{id}/snap` | snaps a pointer position (JSON `point` and `SnapOptions`) |
//! | `GET /api/docs/{id}/check` | `foldcam check --json`'s report |
//! | `GET /api/docs/{id}/layers` | the layer-order check (`foldcam check --layers`) |
//! | `GET /api/docs/{id}/flat[?state=K]` | the flat-folded state K seen from above (`foldcam fold-flat --png`) |
//! | `GET /api/docs/{id}/fold3d[?flat=true\|stream=true]` | the 3D fold ([`super::fold3d_api`]) |
//! | `GET /api/docs/{id}/plan?machine&material[&size][&options]` | the plan drawn: toolpaths, travel, totals |
//! | `GET /api/docs/{id}/cut?machine&material&format[&job][&size]` | the job file `foldcam cut` writes |
//! | `GET /api/docs/{id}/simulate?machine&material[&job][&size]` | the G-code run on the simulated machine |
//! | `GET /api/machines`, `GET /api/materials` | the shipped profiles and the uploaded ones |
//! | `POST /api/profiles/{machine,material}?name=N` | reads a TOML profile as `cut -m N.toml` would |
//! | `GET /api/legend` | line colours and dashes of each assignment (as in our previews) |
//! | `GET /api/examples`, `POST /api/examples/{name}`, `POST /api/blank[?side=MM]` | the bundled examples and a blank sheet, opened as documents ([`super::start_api`]) |
//! | `GET /api/docs/{id}/save?format=F` | the pattern saved as FOLD, SVG, `.cp`, `.opx` or its folded form ([`super::start_api`]) |
//! | `/api/fold/…` | the fold-sequence designer ([`super::folding_api`]) |
//! | `/api/tess/…` | the tessellation designer ([`super::tessellate_api`]) |
//! | `/api/voxel/…` | the voxel pop-up editor ([`super::voxel_api`]) |
//!
//! Work that takes time (checks, folding, planning) runs on tokio's blocking pool.

use std::collections::VecDeque;
use std::sync::{Arc, Mutex, PoisonError};

use axum::Json;
use axum::Router;
use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, PathRejection, QueryRejection};
use axum::extract::{DefaultBodyLimit, FromRequestParts, Path, Query, State};
use axum::http::{HeaderMap, StatusCode, Uri, header};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use serde::{Deserialize, Serialize};
use serde_json::{Value, json};

use super::StudioConfig;
use super::assets;
use super::design_open;
use super::document::{Document, PatternView};
use super::edit_api;
use super::error::StudioError;
use super::flat::{FlatView, flat_view};
use super::guard::{self, Guard};
use super::history::Versions;
use super::machine_api;
use super::settings::UploadedProfiles;
use crate::check::layers::{KawasakiTolerance, LayerOptions, check_layers};
use crate::check::{CheckOptions, check_with_frame};
use crate::design::source::MeshUse;
use crate::pattern::Assignment;
use crate::pattern::edit::EditReport;

/// The server's state: its configuration and the open documents.
pub struct Studio {
    config: StudioConfig,
    /// What keeps other web pages out ([`super::guard`]).
    guard: Arc<Guard>,
    docs: Mutex<Documents>,
    pub(super) profiles: Mutex<UploadedProfiles>,
}

#[derive(Default)]
struct Documents {
    next: u64,
    open: VecDeque<(u64, History)>,
}

/// The versions of one document: the file as opened, then one per edit.
type History = Versions<Arc<Document>>;

impl History {
    fn state(&self) -> Undo {
        Undo {
            undo: self.can_undo(),
            redo: self.can_redo(),
        }
    }
}

/// Whether the document has edits to undo and redo.
#[derive(Clone, Copy, Debug, Serialize)]
pub(super) struct Undo {
    undo: bool,
    redo: bool,
}

/// Where to move in a document's history.
#[derive(Clone, Copy)]
pub(super) enum Step {
    Back,
    Forward,
}

impl Studio {
    /// How long a tessellation solve runs without its page asking for progress.
    pub(super) fn abandon_after(&self) -> std::time::Duration {
        self.config.abandon_after
    }

    /// A studio with no document open, answering to the address of `config` (give the
    /// port actually bound).
    pub fn new(config: StudioConfig) -> Studio {
        Studio {
            guard: Arc::new(Guard::new(std::net::SocketAddr::new(
                config.host,
                config.port,
            ))),
            config,
            docs: Mutex::new(Documents::default()),
            profiles: Mutex::new(UploadedProfiles::default()),
        }
    }

    fn add(&self, doc: Document) -> (u64, Arc<Document>) {
        let mut docs = self.docs.lock().unwrap_or_else(PoisonError::into_inner);
        let id = docs.next;
        docs.next += 1;
        let doc = Arc::new(doc);
        docs.open.push_back((id, Versions::new(Arc::clone(&doc))));
        while docs.open.len() > super::MAX_DOCUMENTS {
            docs.open.pop_front();
        }
        (id, doc)
    }

    /// Runs `f` on document `id`'s history.
    fn with<T>(&self, id: u64, f: impl FnOnce(&mut History) -> T) -> Result<T, ApiError> {
        let mut docs = self.docs.lock().unwrap_or_else(PoisonError::into_inner);
        docs.open
            .iter_mut()
            .find(|(i, _)| *i == id)
            .map(|(_, h)| f(h))
            .ok_or_else(|| {
                ApiError::new(
                    StatusCode::NOT_FOUND,
                    format!("document {id} is not open (open the file again)"),
                )
            })
    }

    pub(super) fn get(&self, id: u64) -> Result<Arc<Document>, ApiError> {
        self.with(id, |h| Arc::clone(h.current()))
    }

    /// Makes `next` the current version of `id`, made from `base`; refused when another
    /// edit came first. Versions after the current one (undone edits) are dropped.
    pub(super) fn push(&self, id: u64, base: &Arc<Document>, next: Document) -> ApiResult<Undo> {
        self.with(id, |h| {
            if !Arc::ptr_eq(h.current(), base) {
                return Err(ApiError::new(
                    StatusCode::CONFLICT,
                    "the document changed while the edit was made: try again",
                ));
            }
            h.push(Arc::new(next));
            Ok(h.state())
        })?
    }

    /// Moves in `id`'s history; refused when there is nothing to undo or redo.
    pub(super) fn step(&self, id: u64, step: Step) -> ApiResult<(Arc<Document>, Undo)> {
        self.with(id, |h| {
            let doc = match step {
                Step::Back => h.undo()?,
                Step::Forward => h.redo()?,
            };
            Ok((Arc::clone(doc), h.state()))
        })?
    }
}

/// An API error: an HTTP status and the message `foldcam` would print, with the stage and
/// file of a [`StudioError`] as data.
#[derive(Debug)]
pub struct ApiError {
    pub(super) status: StatusCode,
    message: String,
    detail: Option<StudioError>,
}

impl From<StudioError> for ApiError {
    /// Unprocessable input (422), whatever the stage: the request was understood, the file
    /// or value it carries cannot be used.
    fn from(e: StudioError) -> ApiError {
        ApiError {
            status: StatusCode::UNPROCESSABLE_ENTITY,
            message: e.to_string(),
            detail: Some(e),
        }
    }
}

impl ApiError {
    pub(super) fn new(status: StatusCode, message: impl Into<String>) -> ApiError {
        ApiError {
            status,
            message: message.into(),
            detail: None,
        }
    }

    /// The message.
    #[cfg(test)]
    pub(super) fn message(&self) -> &str {
        &self.message
    }

    /// Bad input: 422 with the message.
    pub(super) fn input(message: String) -> ApiError {
        ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, message)
    }
}

impl ApiError {
    /// The reply's JSON: `{"error"}`, with `"stage"` and `"file"` for a [`StudioError`].
    pub(super) fn body(&self) -> Value {
        match &self.detail {
            Some(d) => json!({ "error": self.message, "stage": d.stage, "file": d.file }),
            None => json!({ "error": self.message }),
        }
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        (self.status, Json(self.body())).into_response()
    }
}

impl From<QueryRejection> for ApiError {
    fn from(r: QueryRejection) -> ApiError {
        ApiError::new(StatusCode::BAD_REQUEST, r.body_text())
    }
}

impl From<PathRejection> for ApiError {
    fn from(r: PathRejection) -> ApiError {
        ApiError::new(StatusCode::NOT_FOUND, r.body_text())
    }
}

pub(super) type ApiResult<T> = Result<T, ApiError>;

/// A document id from the path (a JSON error when it is not a number).
pub(super) struct PathId(pub(super) u64);

impl<S: Send + Sync> FromRequestParts<S> for PathId {
    type Rejection = ApiError;

    async fn from_request_parts(
        parts: &mut axum::http::request::Parts,
        state: &S,
    ) -> Result<Self, Self::Rejection> {
        let Path(id) = Path::<u64>::from_request_parts(parts, state).await?;
        Ok(PathId(id))
    }
}

/// Runs CPU work off the async threads.
pub(super) async fn blocking<T: Send + 'static>(
    work: impl FnOnce() -> ApiResult<T> + Send + 'static,
) -> ApiResult<T> {
    tokio::task::spawn_blocking(work).await.map_err(|e| {
        ApiError::new(
            StatusCode::INTERNAL_SERVER_ERROR,
            format!("the computation stopped: {e}"),
        )
    })?
}

/// The name an upload is known by: only the last component of what the page sent, so that a
/// name is never a path on this machine.
pub(super) fn upload_name(sent: &str) -> String {
    sent.rsplit(['/', '\\'])
        .next()
        .unwrap_or_default()
        .to_string()
}

/// An upload's body, or why it could not be read, naming the upload.
pub(super) fn upload_body(name: &str, body: Result<Bytes, BytesRejection>) -> ApiResult<Bytes> {
    body.map_err(|r| ApiError::new(r.status(), format!("{name}: {}", r.body_text())))
}

/// An upload read as UTF-8 text; the error names the upload and the first byte that is not.
pub(super) fn upload_text<'a>(name: &str, body: &'a [u8]) -> ApiResult<&'a str> {
    std::str::from_utf8(body).map_err(|e| {
        ApiError::input(format!(
            "{name}: byte {}: file is not valid UTF-8 text",
            e.valid_up_to()
        ))
    })
}

/// The routes, with the upload limit of `state`'s configuration, behind the checks of
/// [`super::guard`] and with its security headers on every response.
pub fn router(state: Arc<Studio>) -> Router {
    let limit = state.config.max_upload_bytes;
    let guard = Arc::clone(&state.guard);
    Router::new()
        .route("/api/files", get(files))
        .route("/api/files/{index}", post(open_file))
        .route("/api/upload", post(upload))
        .route("/api/docs/{id}/edit", post(edit_api::edit))
        .route("/api/docs/{id}/undo", post(edit_api::undo))
        .route("/api/docs/{id}/redo", post(edit_api::redo))
        .route("/api/docs/{id}/snap", post(edit_api::snap_point))
        .route("/api/docs/{id}/check", get(check))
        .route("/api/docs/{id}/layers", get(layers))
        .route("/api/docs/{id}/flat", get(flat))
        .route("/api/docs/{id}/plan", get(machine_api::plan))
        .route("/api/docs/{id}/cut", get(machine_api::cut))
        .route("/api/docs/{id}/simulate", get(machine_api::simulate))
        .route("/api/machines", get(machine_api::machines))
        .route("/api/profiles/{kind}", post(machine_api::upload_profile))
        .route("/api/materials", get(machine_api::materials))
        .route("/api/legend", get(legend))
        .route("/api/examples", get(super::start_api::examples))
        .route("/api/examples/{name}", post(super::start_api::open))
        .route("/api/blank", post(super::start_api::blank))
        .route("/api/docs/{id}/save", get(super::start_api::save))
        .merge(super::fold3d_api::router())
        .merge(super::folding_api::router(Arc::clone(&state)))
        .merge(super::tessellate_api::router(Arc::clone(&state)))
        .merge(super::voxel_api::router(Arc::clone(&state)))
        .merge(super::popup_api::router(Arc::clone(&state)))
        .merge(super::craft_api::router(Arc::clone(&state)))
        .layer(axum::middleware::map_response(no_store))
        .fallback(static_file)
        .layer(DefaultBodyLimit::max(limit))
        .layer(axum::middleware::from_fn_with_state(guard, guard::check))
        .layer(axum::middleware::map_response(guard::security_headers))
        .with_state(state)
}

/// API replies describe the document as it is now (edits change it under the same URL):
/// never cached.
async fn no_store(mut response: Response) -> Response {
    response.headers_mut().insert(
        header::CACHE_CONTROL,
        axum::http::HeaderValue::from_static("no-store"),
    );
    response
}

/// An embedded front-end file by exact name; anything else is 404. The page gets this
/// launch's token ([`Guard::page`]); large files are sent gzipped when the request accepts it.
async fn static_file(State(s): State<Arc<Studio>>, headers: HeaderMap, uri: Uri) -> Response {
    let path = uri.path();
    let name = if path == "/" {
        "index.html"
    } else {
        path.trim_start_matches('/')
    };
    let Some((bytes, mime)) = assets::get(name) else {
        return ApiError::new(StatusCode::NOT_FOUND, format!("{path}: no such page"))
            .into_response();
    };
    if name == "index.html" {
        let page = s.guard.page(&String::from_utf8_lossy(bytes));
        return ([(header::CONTENT_TYPE, mime)], page).into_response();
    }
    let vary = (header::VARY, "accept-encoding");
    match assets::gzipped(name).filter(|_| assets::accepts_gzip(&headers)) {
        Some(gz) => (
            [
                (header::CONTENT_TYPE, mime),
                (header::CONTENT_ENCODING, "gzip"),
                vary,
            ],
            gz,
        )
            .into_response(),
        None => ([(header::CONTENT_TYPE, mime), vary], bytes).into_response(),
    }
}

#[derive(Serialize)]
struct FileEntry {
    index: usize,
    name: String,
}

async fn files(State(s): State<Arc<Studio>>) -> Json<Vec<FileEntry>> {
    Json(
        s.config
            .files
            .iter()
            .enumerate()
            .map(|(index, p)| FileEntry {
                index,
                name: p.display().to_string(),
            })
            .collect(),
    )
}

#[derive(Serialize)]
pub(super) struct Opened {
    pub(super) id: u64,
    #[serde(flatten)]
    pub(super) view: PatternView,
    /// What can be undone and redone.
    pub(super) history: Undo,
    /// What the edit did, after an edit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) edit: Option<EditReport>,
}

pub(super) fn opened(s: &Studio, doc: Document) -> ApiResult<Json<Opened>> {
    let view = PatternView::new(&doc.name, doc.planar()?);
    let (id, _) = s.add(doc);
    Ok(Json(Opened {
        id,
        view,
        history: Undo {
            undo: false,
            redo: false,
        },
        edit: None,
    }))
}

/// How to open a file: what a mesh becomes (`auto`, `tessellation`, `popup`).
#[derive(Deserialize)]
struct OpenQuery {
    make: Option<String>,
}

fn mesh_use(make: Option<&str>) -> ApiResult<MeshUse> {
    match make {
        None => Ok(MeshUse::Auto),
        Some(m) => MeshUse::from_name(m).ok_or_else(|| {
            ApiError::new(
                StatusCode::BAD_REQUEST,
                format!("make={m}: expected auto, tessellation or popup"),
            )
        }),
    }
}

async fn open_file(
    State(s): State<Arc<Studio>>,
    index: Result<Path<usize>, PathRejection>,
    query: Result<Query<OpenQuery>, QueryRejection>,
) -> ApiResult<Json<Opened>> {
    let Path(index) = index?;
    let Query(q) = query?;
    let make = mesh_use(q.make.as_deref())?;
    let path = s.config.files.get(index).cloned().ok_or_else(|| {
        ApiError::new(
            StatusCode::NOT_FOUND,
            format!("file {index}: not one of the files given on the command line"),
        )
    })?;
    blocking(move || {
        let doc = if design_open::is_design(&path) {
            design_open::open_path(&path, &s.config.files, make)
        } else {
            Document::open(&path)
        };
        opened(&s, doc?)
    })
    .await
}

/// `name`: the file's name; `make`: what a mesh becomes; `with`: the files sent after it in
/// the same body (a JSON list of `{name, size}`), e.g. a paper craft's mesh.
#[derive(Deserialize)]
struct UploadQuery {
    name: String,
    make: Option<String>,
    with: Option<String>,
}

async fn upload(
    State(s): State<Arc<Studio>>,
    query: Result<Query<UploadQuery>, QueryRejection>,
    headers: HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<Opened>> {
    let Query(q) = query?;
    let name = upload_name(&q.name);
    let make = mesh_use(q.make.as_deref())?;
    let parts: Vec<design_open::Part> = match &q.with {
        None => Vec::new(),
        Some(w) => serde_json::from_str(w)
            .map_err(|e| ApiError::new(StatusCode::BAD_REQUEST, format!("with={w}: {e}")))?,
    };
    let limit = s.config.max_upload_bytes;
    let too_large = || {
        ApiError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            format!("{name}: the upload is larger than the limit of {limit} bytes"),
        )
    };
    // Refused on its declared length before any of the body is read (a client that sent
    // `Expect: 100-continue` never sends it); bodies without a length stop at the limit.
    let declared = headers
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse::<u64>().ok());
    if declared.is_some_and(|n| n > limit as u64) {
        return Err(too_large());
    }
    let body = body.map_err(|r| {
        if r.status() == StatusCode::PAYLOAD_TOO_LARGE {
            too_large()
        } else {
            ApiError::new(r.status(), format!("{name}: {}", r.body_text()))
        }
    })?;
    blocking(move || {
        let (main, companions) = design_open::split_body(&name, &body, &parts)?;
        let doc = if design_open::is_design(std::path::Path::new(&name)) {
            design_open::open_upload(&name, main, &companions, make)
        } else {
            Document::from_upload(&name, main)
        };
        opened(&s, doc?)
    })
    .await
}

async fn check(State(s): State<Arc<Studio>>, PathId(id): PathId) -> ApiResult<Json<Value>> {
    let doc = s.get(id)?;
    blocking(move || {
        let c = doc.cleaned(false)?;
        let report = check_with_frame(&c.pattern, c.folded.as_ref(), &CheckOptions::default());
        Ok(Json(json!(report)))
    })
    .await
}

/// The Kawasaki tolerance of the layer-order check and the flat-folded view: absent or
/// empty for the tolerance fitted to the drawing, else degrees (as `--kawasaki-tolerance`).
#[derive(Deserialize)]
struct ToleranceQuery {
    kawasaki_tolerance: Option<String>,
}

impl ToleranceQuery {
    fn tolerance(&self) -> Result<KawasakiTolerance, ApiError> {
        let text = self.kawasaki_tolerance.as_deref().map(str::trim);
        match text {
            None | Some("") => Ok(KawasakiTolerance::Fitted),
            Some(t) => crate::limits::KAWASAKI_TOLERANCE
                .parse(t)
                .map(KawasakiTolerance::Degrees)
                .map_err(|e| {
                    ApiError::input(format!(
                        "Kawasaki tolerance: {e} (or leave the field empty to fit it to the \
                         drawing)"
                    ))
                }),
        }
    }
}

async fn layers(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<ToleranceQuery>, QueryRejection>,
) -> ApiResult<Json<Value>> {
    let Query(q) = query?;
    let kawasaki = q.tolerance()?;
    let doc = s.get(id)?;
    blocking(move || {
        let c = doc.cleaned(false)?;
        let check_options = CheckOptions {
            kawasaki_tolerance_deg: match kawasaki {
                KawasakiTolerance::Degrees(d) => d,
                KawasakiTolerance::Fitted => CheckOptions::default().kawasaki_tolerance_deg,
            },
            ..CheckOptions::default()
        };
        let mut report = check_with_frame(&c.pattern, c.folded.as_ref(), &check_options);
        let options = LayerOptions {
            max_states: Some(crate::check::layers::DEFAULT_MAX_STATES),
            kawasaki,
            time_limit: Some(std::time::Duration::from_secs(
                crate::limits::STUDIO_LAYER_SECONDS,
            )),
            ..LayerOptions::default()
        };
        let outcome = check_layers(&c.pattern, &mut report, &options)
            .map_err(|e| ApiError::input(format!("{}: layer order: {e}", doc.name)))?;
        Ok(Json(
            json!({ "text": outcome.to_text(), "layers": outcome, "check": report }),
        ))
    })
    .await
}

#[derive(Deserialize)]
struct FlatQuery {
    state: Option<u64>,
    kawasaki_tolerance: Option<String>,
}

async fn flat(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<FlatQuery>, QueryRejection>,
) -> ApiResult<Json<FlatView>> {
    let Query(q) = query?;
    let kawasaki = ToleranceQuery {
        kawasaki_tolerance: q.kawasaki_tolerance.clone(),
    }
    .tolerance()?;
    let doc = s.get(id)?;
    blocking(move || {
        flat_view(&doc, q.state.unwrap_or(0), kawasaki)
            .map(Json)
            .map_err(ApiError::from)
    })
    .await
}

/// Line styles of the previews ([`crate::render::style::line_style`]) with a base width of 1:
/// widths and dashes in multiples of the base width.
async fn legend() -> Json<Value> {
    let entries: Vec<Value> = Assignment::ALL
        .iter()
        .map(|&a| {
            let s = crate::render::style::line_style(a, 1.0);
            json!({
                "letter": a.letter().to_string(),
                "name": a.name(),
                "colour": format!("#{:02x}{:02x}{:02x}", s.color[0], s.color[1], s.color[2]),
                "width": s.width,
                "dash": s.dash,
            })
        })
        .collect();
    let c = crate::render::style::FAULT_COLOR;
    let fault = format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]);
    Json(json!({ "assignments": entries, "fault": fault }))
}

/// A download: the bytes with a content type and a file name made safe for the header.
pub(super) fn download(mime: &'static str, file: &str, bytes: Vec<u8>) -> Response {
    let safe: String = file
        .chars()
        .map(|c| {
            if c.is_ascii_graphic() && c != '"' && c != '\\' {
                c
            } else {
                '_'
            }
        })
        .collect();
    (
        [
            (header::CONTENT_TYPE, mime.to_string()),
            (
                header::CONTENT_DISPOSITION,
                format!("attachment; filename=\"{safe}\""),
            ),
        ],
        bytes,
    )
        .into_response()
}
