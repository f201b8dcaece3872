//! The studio's fold mode: a fold sequence designed by dragging the folded sheet, the
//! interaction of Miyazaki, Yasuda, Yokoi & Toriwaki (1992) over the library's simulator
//! ([`crate::design::folding`]). Each session holds the simulator's states (one per step, so
//! stepping back and forward is exact) and the script steps that made them; the script is
//! the format `foldcam fold` reads, and replays to the same crease pattern.
//!
//! | route | does |
//! | --- | --- |
//! | `POST /api/fold/new` | a session on a sheet (JSON `{"sheet": {"square": 150}, "title": …}`) |
//! | `POST /api/fold/script?name=N` | a session replaying the fold script in the body |
//! | `GET /api/fold/{id}` | the session's view: faces from above, steps, crease pattern |
//! | `POST /api/fold/{id}/preview` | a drag (JSON [`GestureRequest`]) planned, not kept: fold line, snapping, the faces it would give |
//! | `POST /api/fold/{id}/drag` | the drag made a step |
//! | `POST /api/fold/{id}/back`, `…/forward` | steps back or forward through the steps |
//! | `GET /api/fold/{id}/script` | the steps up to the shown one as a fold script (TOML) |
//! | `GET /api/fold/{id}/fold` | the crease pattern with one frame per step, as `foldcam fold -o` writes it |
//! | `POST /api/fold/{id}/pattern` | the crease pattern opened as a studio document |
//!
//! Errors are JSON `{"error": …}` with the library's message (a refused fold names its step
//! as `foldcam fold` does). A preview whose fold is refused answers 200 with the plan and the
//! reason in `refused`, so that the page can show the line and why it does not fold.

use std::sync::{Arc, PoisonError};

use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, QueryRejection};
use axum::extract::{Query, State};
use axum::response::Response;
use axum::routing::{get, post};
use axum::{Json, Router};
use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::api::{
    ApiError, ApiResult, Opened, PathId, Studio, blocking, download, opened, upload_body,
    upload_name, upload_text,
};
use super::document::Document;
use super::edit_api::json_body;
use super::error::{Stage, StudioError};
use super::guard::JsonBody;
use super::sessions::Sessions;
use crate::design::folding::Folding;
use crate::design::folding::crease::{crease_pattern, step_states};
use crate::design::folding::display::{TopFace, faces_from_above, sheet_size};
use crate::design::folding::drag::{Snap, Snapped};
use crate::design::folding::gesture::{Gesture, GesturePlan, Operation};
use crate::design::folding::layers::layer_problems;
use crate::design::folding::script::{
    Script, ScriptError, SheetSpec, SnapSpec, apply_step, parse_script, run_script, sheet_outline,
    write_script,
};
use crate::formats::fold::write_string_frames;

/// Most fold sessions kept at once; the oldest is dropped first.
pub const MAX_FOLD_SESSIONS: usize = 16;

/// Snapping reach of a new sheet's drags, as a fraction of the sheet's size (3 mm on a 150 mm
/// square: a pointer lands within a few pixels, not within the library's default 1 mm). A
/// script keeps its own `[snap]` table.
pub const SNAP_FRACTION: f64 = 0.02;

/// Layers drawn apart by this fraction of the sheet's size per place in their stack (as
/// `foldcam fold --png` spreads them).
pub const LAYER_GAP_FRACTION: f64 = 0.004;

/// One fold sequence being designed.
struct Session {
    /// What the page calls it (the script's file name, or "fold sequence").
    name: String,
    /// Title, sheet and snapping; `steps` holds every step made, shown or undone.
    script: Script,
    /// The simulator after every step of `script` (undone ones included, for forward).
    folding: Folding,
    /// The step shown (0 = the flat sheet).
    at: usize,
}

impl Session {
    fn new(name: String, script: Script) -> Result<Session, StudioError> {
        let folding = run_script(&script).map_err(|e| StudioError::about(Stage::Fold, &name, e))?;
        let at = folding.steps().len() - 1;
        Ok(Session {
            name,
            script,
            folding,
            at,
        })
    }

    fn snap(&self) -> Snap {
        self.script.snap.to_snap()
    }

    /// The simulator at the shown step (undone steps forgotten).
    fn shown(&self) -> Folding {
        let mut f = self.folding.clone();
        // `at` is always a step of `folding`.
        let _ = f.undo_to(self.at);
        f
    }

    /// The script of the steps up to the shown one.
    fn shown_script(&self) -> Script {
        let mut script = self.script.clone();
        script.steps.truncate(self.at);
        script
    }

    /// The FOLD text of the shown state, as `foldcam fold -o` writes it.
    fn fold_text(&self) -> String {
        let f = self.shown();
        let mut sheet = crease_pattern(&f);
        sheet.pattern.meta.title = self.script.title.clone();
        let states = step_states(&f, &sheet);
        write_string_frames(&sheet.pattern, &states)
    }
}

/// The fold mode's state: the sessions, and the studio (to open a result as a document).
pub(super) struct Folds {
    studio: Arc<Studio>,
    sessions: Sessions<Session>,
}

/// The fold mode's routes (merged into the studio's router).
pub(super) fn router(studio: Arc<Studio>) -> Router<Arc<Studio>> {
    let folds = Arc::new(Folds {
        studio,
        sessions: Sessions::new("fold sequence", MAX_FOLD_SESSIONS),
    });
    Router::new()
        .route("/api/fold/new", post(new_sheet))
        .route("/api/fold/script", post(from_script))
        .route("/api/fold/{id}", get(show))
        .route("/api/fold/{id}/preview", post(preview))
        .route("/api/fold/{id}/drag", post(drag))
        .route("/api/fold/{id}/back", post(back))
        .route("/api/fold/{id}/forward", post(forward))
        .route("/api/fold/{id}/script", get(script))
        .route("/api/fold/{id}/fold", get(fold_file))
        .route("/api/fold/{id}/pattern", post(to_pattern))
        .with_state(folds)
}

/// The request of `new`: the sheet (as a script's `[sheet]` table) and an optional title.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct NewSheet {
    sheet: SheetSpec,
    title: Option<String>,
}

/// A drag on the view from above (see [`crate::design::folding::gesture`]).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct GestureRequest {
    /// Where the pointer went down, millimetres.
    from: [f64; 2],
    /// Where it is now (preview) or was let go (drag).
    to: [f64; 2],
    /// Pick radius, millimetres.
    pick: f64,
    /// `"bend"`, `"fold"` (fold up by `angle`) or `"tuck"`.
    operation: String,
    /// Fold-up angle, degrees.
    angle: Option<f64>,
    /// Fold away from the eye (mountain as seen from above).
    #[serde(default)]
    behind: bool,
    /// A name for the step.
    name: Option<String>,
}

impl GestureRequest {
    fn gesture(&self) -> ApiResult<Gesture> {
        let operation = match (self.operation.as_str(), self.angle) {
            ("bend", _) => Operation::Bend,
            ("tuck", _) => Operation::TuckIn,
            ("fold", Some(angle_deg)) => Operation::FoldUp { angle_deg },
            ("fold", None) => {
                return Err(ApiError::input("fold up needs an angle in degrees".into()));
            }
            (other, _) => {
                return Err(ApiError::input(format!(
                    "operation {other:?}: expected \"bend\", \"fold\" or \"tuck\""
                )));
            }
        };
        Ok(Gesture {
            from: self.from.into(),
            to: self.to.into(),
            pick_radius: self.pick,
            operation,
            behind: self.behind,
        })
    }
}

/// One face as the page draws it.
#[derive(Serialize)]
struct FaceView {
    /// Corners in space, millimetres.
    corners: Vec<[f64; 3]>,
    /// Place in its stack from the middle, in layers, positive towards the eye.
    layer: f64,
    /// The sheet's front faces the eye.
    front: bool,
}

fn face_views(faces: Vec<TopFace>) -> Vec<FaceView> {
    faces
        .into_iter()
        .map(|f| FaceView {
            corners: f.corners.iter().map(|c| c.to_array()).collect(),
            layer: f.layer,
            front: f.front_up,
        })
        .collect()
}

/// One step in the page's list.
#[derive(Serialize)]
struct StepView {
    number: usize,
    name: Option<String>,
    /// What the simulator did, in words.
    summary: String,
    /// Made but stepped back from.
    undone: bool,
}

/// The crease pattern of the shown step, for the page's small pattern view.
#[derive(Serialize)]
struct CreaseView {
    vertices: Vec<[f64; 2]>,
    /// End vertices and FOLD assignment letter.
    edges: Vec<([usize; 2], char)>,
}

/// The session as the page shows it.
#[derive(Serialize)]
struct SessionView {
    id: u64,
    name: String,
    title: Option<String>,
    /// The shown step (0 = the flat sheet) and the last one made.
    step: usize,
    last: usize,
    steps: Vec<StepView>,
    /// Faces of the shown step from above, painted in this order.
    faces: Vec<FaceView>,
    /// Millimetres between drawn layers.
    gap: f64,
    /// The sheet's outline, millimetres.
    sheet: Vec<[f64; 2]>,
    pattern: CreaseView,
    /// Drag snapping tolerances: millimetres, and degrees for the angle.
    snap: [f64; 4],
    /// Layers passing through each other in the shown state.
    warnings: Vec<String>,
}

fn session_view(id: u64, s: &Session) -> SessionView {
    let f = s.shown();
    let gap = sheet_size(&f) * LAYER_GAP_FRACTION;
    let cp = crease_pattern(&f).pattern;
    let sn = &s.script.snap;
    SessionView {
        id,
        name: s.name.clone(),
        title: s.script.title.clone(),
        step: s.at,
        last: s.folding.steps().len() - 1,
        steps: s
            .folding
            .steps()
            .iter()
            .enumerate()
            .skip(1)
            .map(|(number, step)| StepView {
                number,
                name: step.name.clone(),
                summary: step.summary.clone(),
                undone: number > s.at,
            })
            .collect(),
        faces: face_views(faces_from_above(&f, s.at, gap)),
        gap,
        sheet: f.sheet().iter().map(|p| p.to_array()).collect(),
        pattern: CreaseView {
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
        },
        snap: [sn.vertex, sn.edge, sn.line, sn.angle],
        warnings: layer_problems(&f, f.current())
            .iter()
            .map(ToString::to_string)
            .collect(),
    }
}

/// Runs `work` on session `id` off the async threads.
async fn on_session<T: Send + 'static>(
    folds: Arc<Folds>,
    id: u64,
    work: impl FnOnce(&mut Session) -> ApiResult<T> + Send + 'static,
) -> ApiResult<T> {
    let session = folds.sessions.get(id)?;
    blocking(move || {
        let mut s = session.lock().unwrap_or_else(PoisonError::into_inner);
        work(&mut s)
    })
    .await
}

async fn new_sheet(
    State(folds): State<Arc<Folds>>,
    body: JsonBody,
) -> ApiResult<Json<SessionView>> {
    let q: NewSheet = json_body(body, "new sheet")?;
    blocking(move || {
        let size = sheet_outline(&q.sheet)
            .map(|outline| {
                let (lo, hi) = outline.iter().fold(
                    (glam::DVec2::INFINITY, glam::DVec2::NEG_INFINITY),
                    |(lo, hi), p| (lo.min(*p), hi.max(*p)),
                );
                (hi - lo).max_element()
            })
            .map_err(|e| ApiError::input(e.to_string()))?;
        let reach = size * SNAP_FRACTION;
        let snap = Snap {
            vertex: reach,
            edge: reach,
            line: reach,
            ..Snap::default()
        };
        let script = Script {
            title: q.title,
            sheet: q.sheet,
            snap: SnapSpec::from(snap),
            steps: Vec::new(),
        };
        let session = Session::new("fold sequence".into(), script)?;
        let (id, s) = folds.sessions.add(session);
        let s = s.lock().unwrap_or_else(PoisonError::into_inner);
        Ok(Json(session_view(id, &s)))
    })
    .await
}

#[derive(Deserialize)]
struct ScriptQuery {
    name: String,
}

async fn from_script(
    State(folds): State<Arc<Folds>>,
    query: Result<Query<ScriptQuery>, QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<SessionView>> {
    let Query(q) = query?;
    let name = upload_name(&q.name);
    let body = upload_body(&name, body)?;
    blocking(move || {
        let text = upload_text(&name, &body)?;
        let script = parse_script(text).map_err(|e| ApiError::input(format!("{name}: {e}")))?;
        let session = Session::new(name, script)?;
        let (id, s) = folds.sessions.add(session);
        let s = s.lock().unwrap_or_else(PoisonError::into_inner);
        Ok(Json(session_view(id, &s)))
    })
    .await
}

async fn show(State(folds): State<Arc<Folds>>, PathId(id): PathId) -> ApiResult<Json<SessionView>> {
    on_session(folds, id, move |s| Ok(Json(session_view(id, s)))).await
}

/// The planned drag as the page draws it.
#[derive(Serialize)]
struct PreviewView {
    /// Two points of the fold line, millimetres.
    line: [[f64; 3]; 2],
    /// The picked vertex and where it lands.
    vertex: [[f64; 3]; 2],
    /// Fold angle, degrees, positive towards the picked layer's normal.
    angle: f64,
    /// The snapping rules that fired, in words.
    snapped: Vec<String>,
    /// The faces after the fold (absent when it is refused).
    faces: Option<Vec<FaceView>>,
    /// Why the fold cannot be made.
    refused: Option<String>,
}

fn snapped_words(s: &Snapped) -> String {
    match s {
        Snapped::Vertex => "onto a vertex".into(),
        Snapped::EdgeOntoEdge => "edge onto edge".into(),
        Snapped::LineThroughVertices => "fold line through two vertices".into(),
        Snapped::Angle(a) => format!("angle to {a}°"),
    }
}

/// The gesture planned on the shown step, and the simulator after it (or why not).
fn plan(s: &Session, q: &GestureRequest) -> ApiResult<(GesturePlan, Result<Folding, String>)> {
    let gesture = q.gesture()?;
    let mut f = s.shown();
    let mut plan = f
        .plan_gesture(&gesture, s.snap())
        .map_err(|e| ApiError::input(e.to_string()))?;
    plan.step.name = q.name.clone().filter(|n| !n.trim().is_empty());
    let made = apply_step(&mut f, &plan.step, s.snap()).map(|()| f);
    Ok((plan, made))
}

async fn preview(
    State(folds): State<Arc<Folds>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<PreviewView>> {
    let q: GestureRequest = json_body(body, "preview")?;
    on_session(folds, id, move |s| {
        let (plan, made) = plan(s, &q)?;
        let (faces, refused) = match made {
            Ok(f) => {
                let last = f.steps().len() - 1;
                let gap = sheet_size(&f) * LAYER_GAP_FRACTION;
                (Some(face_views(faces_from_above(&f, last, gap))), None)
            }
            Err(e) => (None, Some(e)),
        };
        let point = |p: DVec3| p.to_array();
        Ok(Json(PreviewView {
            line: [point(plan.line[0]), point(plan.line[1])],
            vertex: [point(plan.vertex.0), point(plan.vertex.1)],
            angle: plan.angle_deg,
            snapped: plan.snapped.iter().map(snapped_words).collect(),
            faces,
            refused,
        }))
    })
    .await
}

async fn drag(
    State(folds): State<Arc<Folds>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<SessionView>> {
    let q: GestureRequest = json_body(body, "drag")?;
    on_session(folds, id, move |s| {
        let (plan, made) = plan(s, &q)?;
        let folding = made.map_err(|message| {
            ApiError::input(
                ScriptError::Step {
                    number: s.at + 1,
                    name: plan.step.name.clone(),
                    message,
                }
                .to_string(),
            )
        })?;
        s.script.steps.truncate(s.at);
        s.script.steps.push(plan.step);
        s.folding = folding;
        s.at += 1;
        Ok(Json(session_view(id, s)))
    })
    .await
}

async fn back(State(folds): State<Arc<Folds>>, PathId(id): PathId) -> ApiResult<Json<SessionView>> {
    on_session(folds, id, move |s| {
        if s.at == 0 {
            return Err(ApiError::input(
                "nothing to step back from: the sheet is flat".into(),
            ));
        }
        s.at -= 1;
        Ok(Json(session_view(id, s)))
    })
    .await
}

async fn forward(
    State(folds): State<Arc<Folds>>,
    PathId(id): PathId,
) -> ApiResult<Json<SessionView>> {
    on_session(folds, id, move |s| {
        if s.at + 1 >= s.folding.steps().len() {
            return Err(ApiError::input(
                "nothing to step forward to: this is the last step".into(),
            ));
        }
        s.at += 1;
        Ok(Json(session_view(id, s)))
    })
    .await
}

/// The file stem a session's downloads take.
fn stem(s: &Session) -> String {
    crate::design::source::file_stem(&s.name, "fold-sequence")
}

async fn script(State(folds): State<Arc<Folds>>, PathId(id): PathId) -> ApiResult<Response> {
    on_session(folds, id, move |s| {
        let text = write_script(&s.shown_script());
        Ok(download(
            "application/toml; charset=utf-8",
            &format!("{}.toml", stem(s)),
            text.into_bytes(),
        ))
    })
    .await
}

async fn fold_file(State(folds): State<Arc<Folds>>, PathId(id): PathId) -> ApiResult<Response> {
    on_session(folds, id, move |s| {
        Ok(download(
            "application/json",
            &format!("{}.fold", stem(s)),
            s.fold_text().into_bytes(),
        ))
    })
    .await
}

async fn to_pattern(
    State(folds): State<Arc<Folds>>,
    PathId(id): PathId,
) -> ApiResult<Json<Opened>> {
    let studio = Arc::clone(&folds.studio);
    let (name, text) = on_session(folds, id, move |s| {
        Ok((format!("{}.fold", stem(s)), s.fold_text()))
    })
    .await?;
    blocking(move || {
        let doc = Document::from_upload(&name, text.as_bytes())?;
        opened(&studio, doc)
    })
    .await
}
