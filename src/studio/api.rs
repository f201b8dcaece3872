//! The studio's HTTP routes: the embedded front end and a JSON API over the library.
//!
//! | route | does |
//! | --- | --- |
//! | `GET /api/files` | the files named on the command line (index and name) |
//! | `POST /api/files/{index}` | opens one of them: the pattern view |
//! | `POST /api/upload?name=N` | reads the body as a file named `N`: the pattern view |
//! | `GET /api/docs/{id}/check` | `foldcam check --json`'s report |
//! | `GET /api/docs/{id}/layers` | the layer-order check (`foldcam check --layers`) |
//! | `GET /api/docs/{id}/fold3d` | the 3D fold (bar-and-hinge model) as frames from flat to 100% |
//! | `GET /api/docs/{id}/plan?machine&material[&size]` | the plan drawn: toolpaths, travel, totals |
//! | `GET /api/docs/{id}/cut?machine&material&format[&job][&size]` | the job file `foldcam cut` writes |
//! | `GET /api/docs/{id}/simulate?machine&material[&job][&size]` | the G-code run on the simulated machine |
//! | `GET /api/machines`, `GET /api/materials` | the shipped profiles |
//! | `GET /api/legend` | line colours and dashes of each assignment (as in our previews) |
//!
//! Work that takes time (checks, folding, planning) runs on tokio's blocking pool.

use std::collections::VecDeque;
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Duration;

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
use super::document::{Document, PatternView};
use super::toolpath::{PlanChoice, PlanView, plan_document};
use crate::check::fold3d::{FoldOptions, fold};
use crate::check::layers::{LayerOptions, check_layers};
use crate::check::{CheckOptions, check_with_frame};
use crate::job::{JOB_EXTENSIONS, JobFormat, check_gcode, job_file};
use crate::machine::{ProfileKind, load_machine, profile_catalogue};
use crate::pattern::Assignment;

/// Frames of the fold sent to the page while folding (plus the flat sheet and the settled end).
pub const FOLD_FRAMES: usize = 40;

/// Longest fold simulation the server runs for one request.
pub const FOLD_TIME_LIMIT: Duration = Duration::from_secs(30);

/// The layer solver's state cap, as `foldcam check --layers`'s default `--max-states`.
pub const LAYER_MAX_STATES: u64 = 1_000_000;

/// The server's state: its configuration and the open documents.
pub struct Studio {
    config: StudioConfig,
    docs: Mutex<Documents>,
}

#[derive(Default)]
struct Documents {
    next: u64,
    open: VecDeque<(u64, Arc<Document>)>,
}

impl Studio {
    /// A studio with no document open.
    pub fn new(config: StudioConfig) -> Studio {
        Studio {
            config,
            docs: Mutex::new(Documents::default()),
        }
    }

    fn add(&self, doc: Document) -> (u64, Arc<Document>) {
        let mut docs = self.docs.lock().unwrap_or_else(PoisonError::into_inner);
        let id = docs.next;
        docs.next += 1;
        let doc = Arc::new(doc);
        docs.open.push_back((id, Arc::clone(&doc)));
        while docs.open.len() > super::MAX_DOCUMENTS {
            docs.open.pop_front();
        }
        (id, doc)
    }

    fn get(&self, id: u64) -> Result<Arc<Document>, ApiError> {
        let docs = self.docs.lock().unwrap_or_else(PoisonError::into_inner);
        docs.open
            .iter()
            .find(|(i, _)| *i == id)
            .map(|(_, d)| Arc::clone(d))
            .ok_or_else(|| {
                ApiError::new(
                    StatusCode::NOT_FOUND,
                    format!("document {id} is not open (open the file again)"),
                )
            })
    }
}

/// An API error: an HTTP status and the message `foldcam` would print.
#[derive(Debug)]
pub struct ApiError {
    status: StatusCode,
    message: String,
}

impl ApiError {
    fn new(status: StatusCode, message: impl Into<String>) -> ApiError {
        ApiError {
            status,
            message: message.into(),
        }
    }

    /// Bad input: 422 with the message.
    fn input(message: String) -> ApiError {
        ApiError::new(StatusCode::UNPROCESSABLE_ENTITY, message)
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        (self.status, Json(json!({ "error": self.message }))).into_response()
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

type ApiResult<T> = Result<T, ApiError>;

/// A document id from the path (a JSON error when it is not a number).
struct PathId(u64);

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
async fn blocking<T: Send + 'static>(
    work: impl FnOnce() -> ApiResult<T> + Send + 'static,
) -> ApiResult<T> {
    tokio::task::spawn_blocking(work).await.map_err(|e| {
        ApiError::new(
            StatusCode::INTERNAL_SERVER_ERROR,
            format!("the computation stopped: {e}"),
        )
    })?
}

/// The routes, with the upload limit of `state`'s configuration.
pub fn router(state: Arc<Studio>) -> Router {
    let limit = state.config.max_upload_bytes;
    Router::new()
        .route("/api/files", get(files))
        .route("/api/files/{index}", post(open_file))
        .route("/api/upload", post(upload))
        .route("/api/docs/{id}/check", get(check))
        .route("/api/docs/{id}/layers", get(layers))
        .route("/api/docs/{id}/fold3d", get(fold3d))
        .route("/api/docs/{id}/plan", get(plan))
        .route("/api/docs/{id}/cut", get(cut))
        .route("/api/docs/{id}/simulate", get(simulate))
        .route("/api/machines", get(machines))
        .route("/api/materials", get(materials))
        .route("/api/legend", get(legend))
        .fallback(static_file)
        .layer(DefaultBodyLimit::max(limit))
        .with_state(state)
}

/// An embedded front-end file by exact name; anything else is 404.
async fn static_file(uri: Uri) -> Response {
    let path = uri.path();
    let name = if path == "/" {
        "index.html"
    } else {
        path.trim_start_matches('/')
    };
    match assets::get(name) {
        Some((bytes, mime)) => ([(header::CONTENT_TYPE, mime)], bytes).into_response(),
        None => {
            ApiError::new(StatusCode::NOT_FOUND, format!("{path}: no such page")).into_response()
        }
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
struct Opened {
    id: u64,
    #[serde(flatten)]
    view: PatternView,
}

fn opened(s: &Studio, doc: Document) -> ApiResult<Json<Opened>> {
    let cleaned = doc.cleaned(false).map_err(ApiError::input)?;
    let view = PatternView::new(&doc.name, &cleaned);
    let (id, _) = s.add(doc);
    Ok(Json(Opened { id, view }))
}

async fn open_file(
    State(s): State<Arc<Studio>>,
    index: Result<Path<usize>, PathRejection>,
) -> ApiResult<Json<Opened>> {
    let Path(index) = index?;
    let path = s.config.files.get(index).cloned().ok_or_else(|| {
        ApiError::new(
            StatusCode::NOT_FOUND,
            format!("file {index}: not one of the files given on the command line"),
        )
    })?;
    blocking(move || {
        let doc = Document::open(&path).map_err(ApiError::input)?;
        opened(&s, doc)
    })
    .await
}

#[derive(Deserialize)]
struct UploadQuery {
    name: String,
}

async fn upload(
    State(s): State<Arc<Studio>>,
    query: Result<Query<UploadQuery>, QueryRejection>,
    headers: HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<Opened>> {
    let Query(q) = query?;
    // Only the last component names the upload: a name is never a path on this machine.
    let name = q
        .name
        .rsplit(['/', '\\'])
        .next()
        .unwrap_or_default()
        .to_string();
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
        let doc = Document::from_upload(&name, &body).map_err(ApiError::input)?;
        opened(&s, doc)
    })
    .await
}

async fn check(State(s): State<Arc<Studio>>, PathId(id): PathId) -> ApiResult<Json<Value>> {
    let doc = s.get(id)?;
    blocking(move || {
        let c = doc.cleaned(false).map_err(ApiError::input)?;
        let report = check_with_frame(&c.pattern, c.folded.as_ref(), &CheckOptions::default());
        Ok(Json(json!(report)))
    })
    .await
}

async fn layers(State(s): State<Arc<Studio>>, PathId(id): PathId) -> ApiResult<Json<Value>> {
    let doc = s.get(id)?;
    blocking(move || {
        let c = doc.cleaned(false).map_err(ApiError::input)?;
        let mut report = check_with_frame(&c.pattern, c.folded.as_ref(), &CheckOptions::default());
        let options = LayerOptions {
            max_states: Some(LAYER_MAX_STATES),
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

/// The fold sent to the page: triangles on model vertices and frames of positions.
#[derive(Serialize)]
struct FoldView {
    /// Model vertex indices, three per triangle.
    triangles: Vec<u32>,
    /// Pattern face of each triangle.
    triangle_face: Vec<usize>,
    /// Frames from flat to the settled end.
    frames: Vec<FoldFrame>,
    /// The simulation's report (strain, fold-angle error, crossings, how it stopped).
    report: crate::check::fold3d::FoldReport,
}

#[derive(Serialize)]
struct FoldFrame {
    /// Target at this frame, percent of every crease's fold angle.
    percent: f64,
    /// True for the settled end (other frames are taken while the target rises).
    settled: bool,
    /// x, y, z of every model vertex.
    positions: Vec<f32>,
}

async fn fold3d(State(s): State<Arc<Studio>>, PathId(id): PathId) -> ApiResult<Json<FoldView>> {
    let doc = s.get(id)?;
    blocking(move || {
        let c = doc.cleaned(true).map_err(ApiError::input)?;
        let opts = FoldOptions {
            frames: FOLD_FRAMES,
            max_time: FOLD_TIME_LIMIT,
            ..FoldOptions::default()
        };
        let f =
            fold(&c.pattern, &opts).map_err(|e| ApiError::input(format!("{}: {e}", doc.name)))?;
        let flat = |p: &[glam::DVec3]| -> Vec<f32> {
            p.iter()
                .flat_map(|v| [v.x as f32, v.y as f32, v.z as f32])
                .collect()
        };
        // Frame k of the ramp is taken at step k·every, when the target is k·every/ramp of
        // the full fold (see `fold3d::fold_with`).
        let ramp = opts.ramp_steps.min(opts.max_steps);
        let every = (ramp / FOLD_FRAMES).max(1);
        let ramp_frames = f.frames.len().saturating_sub(1);
        let mut frames = vec![FoldFrame {
            percent: 0.0,
            settled: true,
            positions: flat(&f.model.rest),
        }];
        for (k, p) in f.frames.iter().enumerate() {
            let last = k == ramp_frames;
            let percent = if last {
                opts.percent
            } else {
                opts.percent * (((k + 1) * every) as f64 / ramp.max(1) as f64).min(1.0)
            };
            frames.push(FoldFrame {
                percent,
                settled: last,
                positions: flat(p),
            });
        }
        Ok(Json(FoldView {
            triangles: f.model.triangles.iter().flatten().copied().collect(),
            triangle_face: f.model.triangle_face.iter().map(|x| x.index()).collect(),
            frames,
            report: f.report,
        }))
    })
    .await
}

async fn plan(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<JobQuery>, QueryRejection>,
) -> ApiResult<Json<PlanView>> {
    let Query(q) = query?;
    let doc = s.get(id)?;
    blocking(move || {
        let p = plan_document(&doc, &q.choice()).map_err(ApiError::input)?;
        Ok(Json(PlanView::new(&p)))
    })
    .await
}

/// The query of `plan`, `cut` and `simulate` (no `#[serde(flatten)]`: URL-encoded numbers
/// do not pass through it).
#[derive(Deserialize)]
struct JobQuery {
    /// A shipped machine profile name.
    machine: String,
    /// A shipped material profile name.
    material: String,
    /// Longer side of the pattern, mm (as `--size`).
    size: Option<f64>,
    /// `cut`: file kind by extension (gcode, nc, ngc, dxf, svg, lbrn2).
    format: Option<String>,
    /// Which job (`front` or `back`); the first when absent.
    job: Option<String>,
}

impl JobQuery {
    fn choice(&self) -> PlanChoice {
        PlanChoice {
            machine: self.machine.clone(),
            material: self.material.clone(),
            size: self.size,
        }
    }
}

fn pick_job<'a>(
    plan: &'a crate::fab::FabPlan,
    job: Option<&str>,
) -> ApiResult<&'a crate::fab::Job> {
    match job {
        None => plan.jobs.first(),
        Some(name) => plan.jobs.iter().find(|j| j.name == name),
    }
    .ok_or_else(|| {
        ApiError::input(format!(
            "job {:?}: the plan has the jobs {}",
            job.unwrap_or_default(),
            plan.jobs
                .iter()
                .map(|j| j.name.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        ))
    })
}

async fn cut(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<JobQuery>, QueryRejection>,
) -> ApiResult<Response> {
    let Query(q) = query?;
    let doc = s.get(id)?;
    blocking(move || {
        let format = q.format.clone().unwrap_or_default();
        let kind = JobFormat::from_extension(&format).ok_or_else(|| {
            ApiError::input(format!(
                "format {format:?}: unknown job type (expected {JOB_EXTENSIONS})"
            ))
        })?;
        let p = plan_document(&doc, &q.choice()).map_err(ApiError::input)?;
        let job = pick_job(&p.plan, q.job.as_deref())?;
        let bytes = job_file(kind, &p.plan, job, &p.machine)
            .map_err(|e| ApiError::input(format!("{}: {e}", doc.name)))?;
        let stem = std::path::Path::new(&doc.name)
            .file_stem()
            .map_or_else(|| "job".to_string(), |s| s.to_string_lossy().into_owned());
        let file = if p.plan.jobs.len() > 1 {
            format!("{stem}.{}.{}", job.name, kind.extension())
        } else {
            format!("{stem}.{}", kind.extension())
        };
        // The file name is ours (a stem of letters the user chose, quoted safely).
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
        Ok((
            [
                (header::CONTENT_TYPE, "application/octet-stream".to_string()),
                (
                    header::CONTENT_DISPOSITION,
                    format!("attachment; filename=\"{safe}\""),
                ),
            ],
            bytes,
        )
            .into_response())
    })
    .await
}

async fn simulate(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<JobQuery>, QueryRejection>,
) -> ApiResult<Json<Value>> {
    let Query(q) = query?;
    let doc = s.get(id)?;
    blocking(move || {
        let p = plan_document(&doc, &q.choice()).map_err(ApiError::input)?;
        let job = pick_job(&p.plan, q.job.as_deref())?;
        let failed = |e: &dyn std::fmt::Display| ApiError::input(format!("{}: {e}", doc.name));
        let text = crate::post::gcode(&p.plan, job, &p.machine).map_err(|e| failed(&e))?;
        let r = check_gcode(&text, &p.machine).map_err(|e| failed(&e))?;
        Ok(Json(json!({
            "machine": r.machine,
            "lines": r.lines,
            "burn_length_mm": r.burn_length_mm,
            "travel_length_mm": r.travel_length_mm,
            "pierces": r.pierces,
            "time_s": r.time_s,
            "violation_count": r.violation_count,
            "violations": r.violations,
        })))
    })
    .await
}

async fn machines() -> ApiResult<Json<Value>> {
    let entries = profile_catalogue(ProfileKind::Machine)
        .map_err(|e| ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?;
    let mut out = Vec::new();
    for e in entries {
        let m = load_machine(&e.name)
            .map_err(|e| ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?;
        out.push(json!({
            "name": e.name,
            "description": e.description,
            "bed": [m.bed.width_mm, m.bed.height_mm],
            "gcode": m.emits_gcode(),
        }));
    }
    Ok(Json(json!(out)))
}

async fn materials() -> ApiResult<Json<Value>> {
    let entries = profile_catalogue(ProfileKind::Material)
        .map_err(|e| ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?;
    Ok(Json(json!(
        entries
            .iter()
            .map(|e| json!({ "name": e.name, "description": e.description }))
            .collect::<Vec<_>>()
    )))
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
