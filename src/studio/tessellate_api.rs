//! The studio's tessellation mode: a mesh made into a freeform origami tessellation (Tachi
//! 2014, "Freeform 3D Origami Tessellations for Fabrication") with the options of `foldcam
//! tessellate`, the solve watched while it converges and stopped on request, the folded form
//! with its creases and vertices measured against the material's limits, and the design saved
//! as the `.tess.toml` file `foldcam tessellate` rebuilds it from
//! ([`crate::design::source::tess_design`]).
//!
//! | route | does |
//! | --- | --- |
//! | `GET /api/tess/setup` | the bundled example meshes, the shipped materials with their limits, the defaults |
//! | `POST /api/tess/mesh?name=N` | reads the body as a mesh (OBJ or STL): its id and faces |
//! | `POST /api/tess/example/{name}` | a bundled example mesh, as `mesh` |
//! | `POST /api/tess/mesh/{id}/solve` | starts a solve (JSON [`SolveRequest`]) on the blocking pool: the job's id |
//! | `GET /api/tess/jobs/{job}[?since=K]` | the job's state and its progress events from the K-th on |
//! | `POST /api/tess/jobs/{job}/cancel` | asks the solve to stop (after its running iteration) |
//! | `GET /api/tess/jobs/{job}/result` | the folded form measured against the limits, the crease pattern, the report |
//! | `GET /api/tess/jobs/{job}/design` | the design file (`NAME.tess.toml`) |
//! | `GET /api/tess/jobs/{job}/mesh` | the mesh it names, as loaded |
//! | `GET /api/tess/jobs/{job}/fold` | the FOLD file `foldcam tessellate -o NAME.fold` writes |
//! | `POST /api/tess/jobs/{job}/pattern` | the crease pattern opened as a studio document |
//!
//! Progress is polled: the page asks for the events after the last one it has (about five
//! times a second while the solve runs).

use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Instant;

use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, QueryRejection};
use axum::extract::{Query, State};
use axum::http::StatusCode;
use axum::response::Response;
use axum::routing::{get, post};
use axum::{Json, Router};
use serde::{Deserialize, Serialize};
use serde_json::{Value, json};

use super::api::{ApiError, ApiResult, Opened, PathId, Studio, blocking, download, opened};
use super::budget;
use super::design_open::message;
use super::document::Document;
use super::edit_api::json_body;
use super::error::{Stage, StudioError};
use super::guard::JsonBody;
use crate::design::source::BuildNote;
use crate::design::source::summary::text_lines;
use crate::design::source::tess_design::{
    TessSettings, layout_by_name, remesh_by_name, tuck_by_name, tuck_name, write_design,
};
use crate::design::source::tess_limits::limit_map;
use crate::design::source::tessellate::{
    SolvePlan, SolveTracker, TessellationOptions, TessellationOutcome, iteration_line, solve_plan,
    tessellate_outcome,
};
use crate::design::source::{DesignFile, Progress, SourceError};
use crate::design::tessellation::Iteration;
use crate::design::tessellation::estimate::solve_bytes;
use crate::machine::{load_material, shipped_materials};
use crate::mesh::PolyMesh;

/// Most meshes and most jobs kept at once each; the oldest is dropped first (a dropped job
/// that still runs is cancelled).
pub const MAX_TESS_ITEMS: usize = 8;

/// Most progress events kept per job (the solver's iteration cap times the attempts stays far
/// below it); later ones are dropped and counted.
pub const MAX_EVENTS: usize = 50_000;

/// The example meshes bundled with the binary (`examples/tessellation/`).
const EXAMPLES: &[(&str, &[u8])] = &[
    (
        "dome.obj",
        include_bytes!("../../examples/tessellation/dome.obj"),
    ),
    (
        "saddle.obj",
        include_bytes!("../../examples/tessellation/saddle.obj"),
    ),
    (
        "bell.obj",
        include_bytes!("../../examples/tessellation/bell.obj"),
    ),
    (
        "mask.obj",
        include_bytes!("../../examples/tessellation/mask.obj"),
    ),
];

/// A loaded mesh.
struct MeshEntry {
    name: String,
    bytes: Vec<u8>,
    mesh: PolyMesh,
}

/// Where a job is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
enum Status {
    /// Solving.
    Running,
    /// Converged, unfolded and checked: a design.
    Done,
    /// Solved, but refused (limits unmet, folded form crossing itself, overlapping pattern).
    Refused,
    /// Stopped on request.
    Cancelled,
    /// Bad options or a mesh the tucks cannot be built on.
    Failed,
}

/// What a job has said and made so far.
struct JobState {
    status: Status,
    events: Vec<Value>,
    dropped: usize,
    error: Option<String>,
    outcome: Option<Arc<TessellationOutcome>>,
}

/// One solve, run in the background (the studio calls it a job: `/api/tess/jobs/{id}`).
struct Solve {
    mesh: Arc<MeshEntry>,
    options: TessellationOptions,
    material: Option<String>,
    cancel: AtomicBool,
    /// When the page last asked for the job's progress.
    last_poll: Mutex<Instant>,
    /// Cancelled when the page has not asked for this long.
    abandon_after: std::time::Duration,
    state: Mutex<JobState>,
}

impl Solve {
    fn state(&self) -> std::sync::MutexGuard<'_, JobState> {
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }

    fn push(&self, event: Value) {
        let mut s = self.state();
        if s.events.len() < MAX_EVENTS {
            s.events.push(event);
        } else {
            s.dropped += 1;
        }
    }

    fn stem(&self) -> String {
        crate::design::source::file_stem(&self.mesh.name, "tessellation")
    }

    /// The outcome, or a 409 naming what the job is doing instead.
    fn outcome(&self) -> ApiResult<Arc<TessellationOutcome>> {
        let s = self.state();
        s.outcome.clone().ok_or_else(|| {
            ApiError::new(
                StatusCode::CONFLICT,
                match s.status {
                    Status::Running => "the solve is still running".to_string(),
                    Status::Cancelled => "the solve was cancelled".to_string(),
                    _ => s.error.clone().unwrap_or_else(|| "no result".into()),
                },
            )
        })
    }

    /// The design, or a 409 with why the result was refused.
    fn design(&self) -> ApiResult<Arc<TessellationOutcome>> {
        let outcome = self.outcome()?;
        match &outcome.design {
            Ok(_) => Ok(Arc::clone(&outcome)),
            Err(lines) => Err(ApiError::new(
                StatusCode::CONFLICT,
                lines.last().map(ToString::to_string).unwrap_or_default(),
            )),
        }
    }
}

/// Reports a solve's progress into its job, with where the schedule stands and the time
/// left as `foldcam tessellate`'s bar says it ([`SolveTracker`]).
struct JobProgress {
    job: Arc<Solve>,
    tracker: SolveTracker,
    started: Instant,
}

impl JobProgress {
    fn new(job: Arc<Solve>, plan: SolvePlan) -> JobProgress {
        JobProgress {
            job,
            tracker: SolveTracker::new(plan),
            started: Instant::now(),
        }
    }

    /// The event of iteration `it`, heard `seconds` after the start.
    fn iteration_event(&mut self, it: &Iteration, seconds: f64) -> Value {
        self.tracker.iteration(it, seconds);
        let (solve, solves) = self.tracker.solve();
        let r = &it.residuals;
        json!({
            "kind": "iteration",
            "attempt": solve + 1,
            "attempts": solves,
            "index": it.index,
            "max_iterations": self.tracker.max_iterations(),
            "developability": r.developability,
            "max_fold": r.max_fold.to_degrees(),
            "min_angle": r.min_vertex_angle.to_degrees(),
            "step": it.step,
            "seconds_left": self.tracker.seconds_left(),
            "progress": self.tracker.line(),
            "text": iteration_line(it),
        })
    }
}

impl Progress for JobProgress {
    fn note(&mut self, note: BuildNote) {
        for line in note.to_string().lines() {
            self.job.push(json!({ "kind": "note", "text": line }));
        }
    }

    fn busy(&mut self, _what: &str) {
        self.started = Instant::now();
    }

    fn next_solve(&mut self) {
        self.tracker
            .next_solve(self.started.elapsed().as_secs_f64());
    }

    fn iteration(&mut self, it: &Iteration) {
        let event = self.iteration_event(it, self.started.elapsed().as_secs_f64());
        self.job.push(event);
    }

    fn cancelled(&self) -> bool {
        if self.job.cancel.load(Ordering::Relaxed) {
            return true;
        }
        let quiet = self
            .job
            .last_poll
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .elapsed();
        if quiet <= self.job.abandon_after {
            return false;
        }
        self.job.cancel.store(true, Ordering::Relaxed);
        self.job.state().error = Some(format!(
            "cancelled: its page stopped asking for progress for {:.0} s (closed?)",
            quiet.as_secs_f64()
        ));
        true
    }
}

/// The mode's state.
pub(super) struct Tessellations {
    studio: Arc<Studio>,
    items: Mutex<Items>,
}

#[derive(Default)]
struct Items {
    next: u64,
    meshes: VecDeque<(u64, Arc<MeshEntry>)>,
    jobs: VecDeque<(u64, Arc<Solve>)>,
}

impl Tessellations {
    fn items(&self) -> std::sync::MutexGuard<'_, Items> {
        self.items.lock().unwrap_or_else(PoisonError::into_inner)
    }

    fn add_mesh(&self, mesh: MeshEntry) -> (u64, Arc<MeshEntry>) {
        let mut items = self.items();
        let id = items.next;
        items.next += 1;
        let mesh = Arc::new(mesh);
        items.meshes.push_back((id, Arc::clone(&mesh)));
        while items.meshes.len() > MAX_TESS_ITEMS {
            items.meshes.pop_front();
        }
        (id, mesh)
    }

    fn mesh(&self, id: u64) -> ApiResult<Arc<MeshEntry>> {
        let items = self.items();
        find(&items.meshes, id).ok_or_else(|| {
            ApiError::new(
                StatusCode::NOT_FOUND,
                format!("mesh {id} is not loaded (load it again)"),
            )
        })
    }

    fn add_job(&self, job: Arc<Solve>) -> u64 {
        let mut items = self.items();
        let id = items.next;
        items.next += 1;
        items.jobs.push_back((id, job));
        while items.jobs.len() > MAX_TESS_ITEMS {
            if let Some((_, old)) = items.jobs.pop_front() {
                old.cancel.store(true, Ordering::Relaxed);
            }
        }
        id
    }

    fn job(&self, id: u64) -> ApiResult<Arc<Solve>> {
        let items = self.items();
        find(&items.jobs, id).ok_or_else(|| {
            ApiError::new(
                StatusCode::NOT_FOUND,
                format!("tessellation job {id} is not kept (solve again)"),
            )
        })
    }
}

fn find<T>(list: &VecDeque<(u64, Arc<T>)>, id: u64) -> Option<Arc<T>> {
    list.iter()
        .find(|(i, _)| *i == id)
        .map(|(_, x)| Arc::clone(x))
}

/// The tessellation mode's routes (merged into the studio's router).
pub(super) fn router(studio: Arc<Studio>) -> Router<Arc<Studio>> {
    let tess = Arc::new(Tessellations {
        studio,
        items: Mutex::new(Items::default()),
    });
    Router::new()
        .route("/api/tess/setup", get(setup))
        .route("/api/tess/mesh", post(upload_mesh))
        .route("/api/tess/example/{name}", post(example_mesh))
        .route("/api/tess/mesh/{id}/solve", post(solve))
        .route("/api/tess/jobs/{id}", get(progress))
        .route("/api/tess/jobs/{id}/cancel", post(cancel))
        .route("/api/tess/jobs/{id}/result", get(result))
        .route("/api/tess/jobs/{id}/design", get(design_file))
        .route("/api/tess/jobs/{id}/mesh", get(mesh_file))
        .route("/api/tess/jobs/{id}/fold", get(fold_file))
        .route("/api/tess/jobs/{id}/pattern", post(to_pattern))
        .with_state(tess)
}

async fn setup() -> ApiResult<Json<Value>> {
    let materials: Vec<Value> = shipped_materials()
        .into_iter()
        .filter_map(|name| {
            let m = load_material(name).ok()?;
            Some(json!({
                "name": name,
                "description": m.description,
                "max_fold_angle": m.limits.max_fold_angle_deg,
                "min_vertex_angle": m.limits.min_vertex_angle_deg,
            }))
        })
        .collect();
    let d = TessellationOptions::default();
    Ok(Json(json!({
        "examples": EXAMPLES.iter().map(|(n, _)| n).collect::<Vec<_>>(),
        "materials": materials,
        "defaults": {
            "tuck": tuck_name(d.tuck),
            "layout": d.layout.to_string(),
            "truncation": d.truncation,
            "twist": d.twist_deg,
            "max_fold_angle": d.max_fold_angle_deg,
            "min_vertex_angle": d.min_vertex_angle_deg,
            "max_iterations": d.max_iterations,
        },
    })))
}

#[derive(Deserialize)]
struct NameQuery {
    name: String,
}

/// A loaded mesh as the page shows it before solving.
#[derive(Serialize)]
struct MeshView {
    id: u64,
    name: String,
    positions: Vec<[f64; 3]>,
    faces: Vec<Vec<u32>>,
}

fn load_mesh(tess: &Tessellations, name: String, bytes: Vec<u8>) -> ApiResult<Json<MeshView>> {
    let path = PathBuf::from(&name);
    let lower = name.to_ascii_lowercase();
    if !(lower.ends_with(".obj") || lower.ends_with(".stl")) {
        return Err(ApiError::input(format!(
            "{name}: a tessellation starts from a mesh (.obj or .stl)"
        )));
    }
    let mesh = DesignFile {
        name: &path,
        bytes: &bytes,
    }
    .mesh()
    .map_err(|e| ApiError::input(message(&e)))?;
    let view = |id: u64, m: &MeshEntry| MeshView {
        id,
        name: m.name.clone(),
        positions: m.mesh.positions().iter().map(|p| p.to_array()).collect(),
        faces: m.mesh.faces().iter().map(|f| f.to_vec()).collect(),
    };
    let (id, entry) = tess.add_mesh(MeshEntry { name, bytes, mesh });
    Ok(Json(view(id, &entry)))
}

async fn upload_mesh(
    State(tess): State<Arc<Tessellations>>,
    query: Result<Query<NameQuery>, QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<MeshView>> {
    let Query(q) = query?;
    let body = body.map_err(|e| ApiError::new(e.status(), e.body_text()))?;
    let name = super::api::upload_name(&q.name);
    blocking(move || load_mesh(&tess, name, body.to_vec())).await
}

async fn example_mesh(
    State(tess): State<Arc<Tessellations>>,
    axum::extract::Path(name): axum::extract::Path<String>,
) -> ApiResult<Json<MeshView>> {
    let Some((n, bytes)) = EXAMPLES.iter().find(|(n, _)| *n == name) else {
        return Err(ApiError::new(
            StatusCode::NOT_FOUND,
            format!("{name}: no such example mesh"),
        ));
    };
    let (n, bytes) = (n.to_string(), bytes.to_vec());
    blocking(move || load_mesh(&tess, n, bytes)).await
}

/// The options of a solve, named as `foldcam tessellate`'s; each left out keeps the
/// command's default. `material` sets the two limits first, the angles given override it.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SolveRequest {
    /// `star`, `truncated`, `twisted` or `twist`.
    pub tuck: Option<String>,
    /// `auto`, `checkerboard` or `digon`.
    pub layout: Option<String>,
    /// One face shrink in (0, 1] (left out: the shrinks 0.8 … 0.4 in turn).
    pub shrink: Option<f64>,
    /// Initial n-gon size, fraction in (0, 1).
    pub truncation: Option<f64>,
    /// Initial twist, degrees.
    pub twist: Option<f64>,
    /// A shipped material whose limits to use.
    pub material: Option<String>,
    /// Fold-angle limit, degrees.
    pub max_fold_angle: Option<f64>,
    /// Vertex-angle limit, degrees.
    pub min_vertex_angle: Option<f64>,
    /// Ground contact.
    pub ground: Option<bool>,
    /// Surface-fit weight in [0, 1].
    pub fit: Option<f64>,
    /// `auto`, `never` or `only`.
    pub remesh: Option<String>,
    /// Faces of the re-triangulation.
    pub remesh_faces: Option<usize>,
    /// Newton iteration cap.
    pub max_iterations: Option<usize>,
}

impl SolveRequest {
    /// The options, as `foldcam tessellate` with the matching flags makes them.
    fn options(&self) -> Result<TessellationOptions, StudioError> {
        let mut o = TessellationOptions::default();
        if let Some(name) = &self.material {
            load_material(name)
                .map_err(|e| StudioError::named(Stage::Profile, e))?
                .limits
                .apply_to_tessellation(&mut o);
        }
        let tuck = by_name(
            &self.tuck,
            "tuck",
            "star, truncated, twisted or twist",
            tuck_by_name,
        )?;
        let layout = by_name(
            &self.layout,
            "layout",
            "auto, checkerboard or digon",
            layout_by_name,
        )?;
        let remesh = by_name(
            &self.remesh,
            "remesh",
            "auto, never or only",
            remesh_by_name,
        )?;
        TessSettings {
            tuck,
            layout,
            shrink: self.shrink,
            truncation: self.truncation,
            twist_deg: self.twist,
            max_fold_angle_deg: self.max_fold_angle,
            min_vertex_angle_deg: self.min_vertex_angle,
            ground: self.ground,
            fit: self.fit,
            remesh,
            remesh_faces: self.remesh_faces,
            max_iterations: self.max_iterations,
        }
        .apply_to(&mut o);
        o.to_solver().map_err(StudioError::request)?;
        Ok(o)
    }
}

/// The value `value` names, found by `find`; an error naming `what` and the `expected` names.
fn by_name<T>(
    value: &Option<String>,
    what: &str,
    expected: &str,
    find: impl Fn(&str) -> Option<T>,
) -> Result<Option<T>, StudioError> {
    match value {
        None => Ok(None),
        Some(v) => find(v)
            .map(Some)
            .ok_or_else(|| StudioError::request(format!("{what} {v:?}: expected {expected}"))),
    }
}

async fn solve(
    State(tess): State<Arc<Tessellations>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<Value>> {
    let mesh = tess.mesh(id)?;
    let request: SolveRequest = json_body(body, "solve")?;
    let options = request.options()?;
    // The solve's memory, by the solver's estimate for its largest triangulation, held until
    // the job ends.
    let faces = options
        .remesh_faces
        .unwrap_or(0)
        .max(mesh.mesh.faces().len());
    let memory = budget::reserve(
        &format!("{}: the solve", mesh.name),
        solve_bytes(faces) as u64,
    )?;
    let job = Arc::new(Solve {
        mesh,
        options,
        material: request.material,
        cancel: AtomicBool::new(false),
        last_poll: Mutex::new(Instant::now()),
        abandon_after: tess.studio.abandon_after(),
        state: Mutex::new(JobState {
            status: Status::Running,
            events: Vec::new(),
            dropped: 0,
            error: None,
            outcome: None,
        }),
    });
    let job_id = tess.add_job(Arc::clone(&job));
    // Not awaited: the page polls the job.
    tokio::task::spawn_blocking(move || {
        run_job(&job);
        drop(memory);
    });
    Ok(Json(json!({ "job": job_id })))
}

/// Solves, recording progress and the end in the job.
fn run_job(job: &Arc<Solve>) {
    let name = PathBuf::from(&job.mesh.name);
    let result = solve_plan(&job.mesh.mesh, &job.options).and_then(|plan| {
        let mut progress = JobProgress::new(Arc::clone(job), plan);
        tessellate_outcome(&name, &job.mesh.mesh, &job.options, &mut progress)
    });
    let mut s = job.state();
    match result {
        Ok(outcome) => {
            s.status = if outcome.design.is_ok() {
                Status::Done
            } else {
                Status::Refused
            };
            s.outcome = Some(Arc::new(outcome));
        }
        Err(SourceError::Cancelled) => s.status = Status::Cancelled,
        Err(e) => {
            s.status = Status::Failed;
            s.error = Some(message(&e));
        }
    }
}

#[derive(Deserialize)]
struct SinceQuery {
    since: Option<usize>,
}

async fn progress(
    State(tess): State<Arc<Tessellations>>,
    PathId(id): PathId,
    query: Result<Query<SinceQuery>, QueryRejection>,
) -> ApiResult<Json<Value>> {
    let Query(q) = query?;
    let job = tess.job(id)?;
    *job.last_poll.lock().unwrap_or_else(PoisonError::into_inner) = Instant::now();
    let s = job.state();
    let since = q.since.unwrap_or(0).min(s.events.len());
    Ok(Json(json!({
        "status": s.status,
        "events": &s.events[since..],
        "next": s.events.len(),
        "dropped": s.dropped,
        "error": s.error,
    })))
}

async fn cancel(
    State(tess): State<Arc<Tessellations>>,
    PathId(id): PathId,
) -> ApiResult<Json<Value>> {
    let job = tess.job(id)?;
    job.cancel.store(true, Ordering::Relaxed);
    Ok(Json(json!({ "status": job.state().status })))
}

async fn result(
    State(tess): State<Arc<Tessellations>>,
    PathId(id): PathId,
) -> ApiResult<Json<Value>> {
    let job = tess.job(id)?;
    let outcome = job.outcome()?;
    blocking(move || Ok(Json(result_view(&job, &outcome)))).await
}

/// The folded form measured against the limits (see [`limit_map`]), the crease pattern when
/// there is one, and the report.
fn result_view(job: &Solve, outcome: &TessellationOutcome) -> Value {
    let surface = &outcome.surface;
    let map = limit_map(
        surface,
        &surface.positions,
        &outcome.limits,
        outcome.tolerance,
    );
    let creases: Vec<Value> = map
        .creases
        .iter()
        .map(|c| {
            json!({
                "v": c.vertices,
                "a": c.assignment.letter().to_string(),
                "fold": c.fold.to_degrees(),
                "over": c.beyond_limit,
                "wrong": c.wrong_sign,
            })
        })
        .collect();
    let vertices: Vec<Value> = map
        .vertices
        .iter()
        .map(|v| {
            json!({
                "min_angle": v.min_angle.to_degrees(),
                "defect": v.defect,
                "under": v.under_limit,
                "undevelopable": v.not_developable,
            })
        })
        .collect();
    // Why the command would call the form partial (and exit 1 without --allow-partial).
    let partial = match &outcome.design {
        Ok(d) => d.fit.as_ref().and_then(|f| f.partial()),
        Err(_) => None,
    };
    let (made, lines, pattern) = match &outcome.design {
        Ok(d) => {
            let p = &d.unfolded.pattern;
            let pattern = json!({
                "vertices": p.vertices.iter().map(|v| v.to_array()).collect::<Vec<_>>(),
                "edges": p.edges.iter().map(|e| json!([
                    e.vertices[0].index(), e.vertices[1].index(),
                    e.assignment.letter().to_string(),
                ])).collect::<Vec<_>>(),
            });
            (true, text_lines(&d.summary), pattern)
        }
        Err(lines) => (false, text_lines(lines), Value::Null),
    };
    json!({
        "name": job.mesh.name,
        "made": made,
        "partial": partial,
        "lines": lines,
        "limits": {
            "max_fold_angle": outcome.limits.max_fold.to_degrees(),
            "min_vertex_angle": outcome.limits.min_vertex_angle.to_degrees(),
        },
        "folded": {
            "positions": surface.positions.iter().map(|p| p.to_array()).collect::<Vec<_>>(),
            "triangles": surface.triangles,
            "creases": creases,
            "vertices": vertices,
        },
        "violations": {
            "creases": map.creases_violating(),
            "vertices": map.vertices_violating(),
        },
        "pattern": pattern,
    })
}

async fn design_file(
    State(tess): State<Arc<Tessellations>>,
    PathId(id): PathId,
) -> ApiResult<Response> {
    let job = tess.job(id)?;
    let note = job.material.as_ref().map(|m| {
        format!("material chosen in the studio: {m} (the limits below are those solved for)")
    });
    let text = write_design(&job.mesh.name, &job.options, note.as_deref());
    Ok(download(
        "application/toml",
        &format!("{}.tess.toml", job.stem()),
        text.into_bytes(),
    ))
}

async fn mesh_file(
    State(tess): State<Arc<Tessellations>>,
    PathId(id): PathId,
) -> ApiResult<Response> {
    let job = tess.job(id)?;
    Ok(download(
        "application/octet-stream",
        &job.mesh.name,
        job.mesh.bytes.clone(),
    ))
}

async fn fold_file(
    State(tess): State<Arc<Tessellations>>,
    PathId(id): PathId,
) -> ApiResult<Response> {
    let job = tess.job(id)?;
    let outcome = job.design()?;
    let name = format!("{}.fold", job.stem());
    let bytes = blocking(move || {
        let Ok(d) = &outcome.design else {
            return Err(ApiError::input("no design".into()));
        };
        crate::formats::encode(
            Path::new("out.fold"),
            &d.unfolded.pattern,
            Some(&d.unfolded.folded),
        )
        .map_err(|e| ApiError::input(e.to_string()))
    })
    .await?;
    Ok(download("application/json", &name, bytes))
}

async fn to_pattern(
    State(tess): State<Arc<Tessellations>>,
    PathId(id): PathId,
) -> ApiResult<Json<Opened>> {
    let job = tess.job(id)?;
    let outcome = job.design()?;
    let studio = Arc::clone(&tess.studio);
    let name = format!("{}.fold", job.stem());
    blocking(move || {
        let Ok(d) = &outcome.design else {
            return Err(ApiError::input("no design".into()));
        };
        let doc = Document::from_design(name, d.clone().into_design(), Vec::new())?;
        opened(&studio, doc)
    })
    .await
}
