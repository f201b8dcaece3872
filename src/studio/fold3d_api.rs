//! The studio's 3D fold: the bar-and-hinge simulation ([`crate::check::fold3d`]) sent to the
//! page as frames of positions on the model's triangles.
//!
//! | route | does |
//! | --- | --- |
//! | `GET /api/docs/{id}/fold3d?flat=true` | at once, the flat sheet the fold starts from (no report) |
//! | `GET /api/docs/{id}/fold3d` | the fold from flat to 100 %: its frames and report (JSON [`FoldView`]) |
//! | `GET /api/docs/{id}/fold3d?stream=true` | the same, as it runs: newline-delimited JSON, one [`FoldLine`] per line, each frame as soon as it is made, then the whole view |
//!
//! The fold is the static solve ([`FoldOptions::implicit`]) in [`FOLD_FRAMES`] load steps,
//! each frame a settled state the page can blend between; where it does not settle on the
//! assignment the explicit run takes over, its frames taken while the target rises.

use std::sync::Arc;
use std::time::Duration;

use axum::Json;
use axum::Router;
use axum::body::{Body, Bytes};
use axum::extract::rejection::QueryRejection;
use axum::extract::{Query, State};
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use futures_util::StreamExt;
use serde::{Deserialize, Serialize};

use super::api::{ApiError, ApiResult, PathId, Studio, blocking};
use super::document::Document;
use super::error::{Stage, StudioError};
use crate::check::fold3d::{BarHingeModel, FoldOptions, FoldReport, Frame, fold_streamed};

/// Load steps of the page's fold, each a frame (plus the flat sheet and the end): enough for
/// the page to blend between them smoothly, few enough to keep the static solve fast (on a
/// 71 × 71 Miura-ori, 10,082 triangles, to 100 %: 1 load step per frame 10 → 3.3 s, 40 → 7.9 s).
pub const FOLD_FRAMES: usize = 10;

/// Longest fold simulation the server runs for one request.
pub const FOLD_TIME_LIMIT: Duration = Duration::from_secs(30);

/// Frames waiting to be sent while the page reads slower than the fold makes them.
const STREAM_BACKLOG: usize = 4;

pub(super) fn router() -> Router<Arc<Studio>> {
    Router::new().route("/api/docs/{id}/fold3d", get(fold3d))
}

/// The fold sent to the page: triangles on model vertices and frames of positions.
#[derive(Serialize)]
pub(super) struct FoldView {
    /// Model vertex indices, three per triangle.
    triangles: Vec<u32>,
    /// Pattern face of each triangle.
    triangle_face: Vec<usize>,
    /// Frames from flat to the end (only the flat sheet for `flat=true`).
    frames: Vec<FoldFrame>,
    /// The simulation's report (strain, fold-angle error, crossings, how it stopped); `None`
    /// for the flat sheet alone (`flat=true`: nothing was simulated).
    report: Option<FoldReport>,
}

/// One state of the fold.
#[derive(Serialize)]
pub(super) struct FoldFrame {
    /// Target at this frame, percent of every crease's fold angle.
    percent: f64,
    /// True for a settled state: the flat sheet, and each [`Frame::settled`] (the static
    /// solve's load steps, a settled end); false for the explicit run's frames, taken while
    /// the target rises.
    settled: bool,
    /// x, y, z of every model vertex, in the pattern's unit.
    positions: Vec<f32>,
}

/// One line of a streamed fold.
#[derive(Serialize)]
#[serde(rename_all = "snake_case")]
pub(super) enum FoldLine<'a> {
    /// A frame, as soon as it is made.
    Frame(&'a FoldFrame),
    /// The whole fold, as `GET …/fold3d` sends it; the last line.
    Done(&'a FoldView),
    /// Why the fold failed, as an API error's body; the last line.
    Error(serde_json::Value),
}

#[derive(Deserialize)]
struct FoldQuery {
    /// Only the flat sheet: the model's triangles and its rest positions (z = 0), the
    /// first frame of the fold, without simulating.
    #[serde(default)]
    flat: bool,
    /// Send frames as they are made (newline-delimited JSON, see the module docs).
    #[serde(default)]
    stream: bool,
}

/// x, y, z of every position, as the page's frames hold them.
fn frame_positions(p: &[glam::DVec3]) -> Vec<f32> {
    p.iter()
        .flat_map(|v| [v.x as f32, v.y as f32, v.z as f32])
        .collect()
}

/// The model's triangles and the face of each, as the page takes them.
fn model_triangles(model: &BarHingeModel) -> (Vec<u32>, Vec<usize>) {
    (
        model.triangles.iter().flatten().copied().collect(),
        model.triangle_face.iter().map(|x| x.index()).collect(),
    )
}

/// The flat sheet the simulation starts from ([`fold_streamed`] builds the same model).
fn flat_view(doc: &Document) -> ApiResult<FoldView> {
    let c = doc.cleaned(true)?;
    let model = BarHingeModel::build(&c.pattern)
        .map_err(|e| StudioError::about(Stage::Fold, &doc.name, e))?;
    let (triangles, triangle_face) = model_triangles(&model);
    Ok(FoldView {
        triangles,
        triangle_face,
        frames: vec![FoldFrame {
            percent: 0.0,
            settled: true,
            positions: frame_positions(&model.rest),
        }],
        report: None,
    })
}

/// The page's fold of `doc`, handing each frame to `on_frame` as it is made.
fn fold_view(doc: &Document, on_frame: &mut dyn FnMut(&FoldFrame)) -> ApiResult<FoldView> {
    let c = doc.cleaned(true)?;
    let opts = FoldOptions {
        frames: FOLD_FRAMES,
        max_time: FOLD_TIME_LIMIT,
        implicit: true,
        ..FoldOptions::default()
    };
    let page_frame = |frame: &Frame| FoldFrame {
        percent: frame.percent,
        settled: frame.settled,
        positions: frame_positions(&frame.positions),
    };
    let f = fold_streamed(&c.pattern, &opts, |frame| on_frame(&page_frame(frame)))
        .map_err(|e| StudioError::about(Stage::Fold, &doc.name, e))?;
    let flat = FoldFrame {
        percent: 0.0,
        settled: true,
        positions: frame_positions(&f.model.rest),
    };
    let frames = std::iter::once(flat)
        .chain(f.frames.iter().map(page_frame))
        .collect();
    let (triangles, triangle_face) = model_triangles(&f.model);
    Ok(FoldView {
        triangles,
        triangle_face,
        frames,
        report: Some(f.report),
    })
}

/// The fold's task ended without a word (it panicked).
fn stopped() -> ApiError {
    ApiError::new(
        StatusCode::INTERNAL_SERVER_ERROR,
        "the computation stopped before its first frame",
    )
}

/// One streamed line: the JSON and a newline.
fn line(value: &FoldLine<'_>) -> Bytes {
    let mut bytes = serde_json::to_vec(value).unwrap_or_default();
    bytes.push(b'\n');
    Bytes::from(bytes)
}

async fn fold3d(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<FoldQuery>, QueryRejection>,
) -> ApiResult<Response> {
    let Query(q) = query?;
    let doc = s.get(id)?;
    if q.flat {
        return blocking(move || flat_view(&doc))
            .await
            .map(|v| Json(v).into_response());
    }
    if !q.stream {
        return blocking(move || fold_view(&doc, &mut |_| {}))
            .await
            .map(|v| Json(v).into_response());
    }
    // The fold runs on the blocking pool and sends its lines through a channel. A failure
    // before the first line (the pattern cannot be cleaned or has no model) is the reply's
    // status, as without `stream`; one after it would be the stream's last line.
    let (tx, mut rx) = tokio::sync::mpsc::channel::<ApiResult<Bytes>>(STREAM_BACKLOG);
    tokio::task::spawn_blocking(move || {
        // A page that has gone away stops receiving; the fold ends at its own caps.
        let send = |line: ApiResult<Bytes>| {
            let _ = tx.blocking_send(line);
        };
        let mut sent = false;
        let result = fold_view(&doc, &mut |frame| {
            sent = true;
            send(Ok(line(&FoldLine::Frame(frame))));
        });
        send(match result {
            Ok(view) => Ok(line(&FoldLine::Done(&view))),
            Err(e) if sent => Ok(line(&FoldLine::Error(e.body()))),
            Err(e) => Err(e),
        });
    });
    let first = match rx.recv().await {
        Some(first) => first?,
        None => return Err(stopped()),
    };
    let rest = futures_util::stream::unfold(rx, |mut rx| async move {
        let bytes = rx
            .recv()
            .await?
            .unwrap_or_else(|e| line(&FoldLine::Error(e.body())));
        Some((Ok::<_, std::convert::Infallible>(bytes), rx))
    });
    let lines = futures_util::stream::once(async move { Ok(first) }).chain(rest);
    Ok((
        [(header::CONTENT_TYPE, "application/x-ndjson")],
        Body::from_stream(lines),
    )
        .into_response())
}
