//! The studio's edit routes: edits of the crease pattern ([`crate::pattern::edit`]), undo and
//! redo through the document's versions, and snapping ([`crate::pattern::snap`]).

use std::sync::Arc;

use axum::Json;
use axum::extract::State;
use axum::http::StatusCode;
use serde::Deserialize;

use super::api::{ApiError, ApiResult, Opened, PathId, Step, Studio, blocking};
use super::document::PatternView;
use super::error::{Stage, StudioError};
use super::guard::JsonBody;
use crate::pattern::edit::{Edit, apply as apply_edit};
use crate::pattern::snap::{SnapOptions, Snapped, snap};

/// A JSON request body: 415 when it was not sent as `application/json` ([`JsonBody`]), 400
/// naming `what` and the place of the error when it is not valid.
pub(super) fn json_body<T: serde::de::DeserializeOwned>(
    body: JsonBody,
    what: &str,
) -> ApiResult<T> {
    let body = body.0?;
    serde_json::from_slice(&body)
        .map_err(|e| ApiError::new(StatusCode::BAD_REQUEST, format!("{what} request: {e}")))
}

/// Applies an edit ([`crate::pattern::edit`]) to the current version: the new version's
/// view. Refused edits leave the document as it was.
pub(super) async fn edit(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<Opened>> {
    let edit: Edit = json_body(body, "edit")?;
    let base = s.get(id)?;
    blocking(move || {
        let mut pattern = base.planar()?.pattern.clone();
        let report = apply_edit(&mut pattern, &edit, None)
            .map_err(|e| StudioError::about(Stage::Request, &base.name, e))?;
        let next = base.edited(pattern);
        let view = PatternView::new(&next.name, next.planar()?);
        let history = s.push(id, &base, next)?;
        Ok(Json(Opened {
            id,
            view,
            history,
            edit: Some(report),
        }))
    })
    .await
}

pub(super) async fn undo(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
) -> ApiResult<Json<Opened>> {
    moved(&s, id, Step::Back)
}

pub(super) async fn redo(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
) -> ApiResult<Json<Opened>> {
    moved(&s, id, Step::Forward)
}

fn moved(s: &Studio, id: u64, step: Step) -> ApiResult<Json<Opened>> {
    let (doc, history) = s.step(id, step)?;
    // Every version was cleaned when it was made: this takes no time.
    let view = PatternView::new(&doc.name, doc.planar()?);
    Ok(Json(Opened {
        id,
        view,
        history,
        edit: None,
    }))
}

/// The request of `snap`: the pointer and what to snap to.
#[derive(Deserialize)]
struct SnapRequest {
    point: [f64; 2],
    #[serde(flatten)]
    options: SnapOptions,
}

/// Snaps a pointer position ([`crate::pattern::snap`]) on the current version.
pub(super) async fn snap_point(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    body: JsonBody,
) -> ApiResult<Json<Snapped>> {
    let q: SnapRequest = json_body(body, "snap")?;
    let doc = s.get(id)?;
    blocking(move || {
        let c = doc.planar()?;
        Ok(Json(snap(
            &c.pattern,
            glam::DVec2::from(q.point),
            &q.options,
        )))
    })
    .await
}
