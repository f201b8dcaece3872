//! The studio's routes to the machine: the plan drawn, the job files `foldcam cut` writes, the
//! G-code run on the simulated machine, and the machine and material profiles (shipped and
//! uploaded). The routes are listed in [`super::api`].

use std::sync::{Arc, PoisonError};

use axum::Json;
use axum::body::Bytes;
use axum::extract::rejection::{BytesRejection, PathRejection, QueryRejection};
use axum::extract::{Path, Query, State};
use axum::http::StatusCode;
use axum::response::Response;
use serde::Deserialize;
use serde_json::{Value, json};

use super::api::{
    ApiError, ApiResult, PathId, Studio, blocking, download, upload_body, upload_name,
};
use super::error::{Stage, StudioError};
use super::settings::{Kind, MAX_PROFILE_BYTES};
use super::toolpath::{PlanChoice, PlanView, plan_document};
use crate::fab::PlanSettings;
use crate::job::{JOB_EXTENSIONS, JobFormat, check_gcode, job_file, job_file_name};
use crate::machine::{ProfileKind, load_machine, profile_catalogue};

pub(super) async fn plan(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<JobQuery>, QueryRejection>,
    settings: Result<Query<PlanSettings>, QueryRejection>,
) -> ApiResult<Json<PlanView>> {
    let Query(q) = query?;
    let choice = q.choice(&s, settings?.0)?;
    let doc = s.get(id)?;
    blocking(move || {
        let p = plan_document(&doc, &choice)?;
        Ok(Json(PlanView::new(&p)))
    })
    .await
}

/// The query of `plan`, `cut` and `simulate` (no `#[serde(flatten)]`: URL-encoded numbers
/// do not pass through it).
#[derive(Deserialize)]
pub(super) struct JobQuery {
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
    /// The profiles chosen (shipped or uploaded), the size and `settings`.
    fn choice(&self, s: &Studio, settings: PlanSettings) -> ApiResult<PlanChoice> {
        let profiles = s.profiles.lock().unwrap_or_else(PoisonError::into_inner);
        Ok(PlanChoice {
            machine: profiles.machine(&self.machine)?,
            material: profiles.material(&self.material)?,
            size: self.size,
            settings,
        })
    }
}

fn pick_job<'a>(
    plan: &'a crate::fab::FabPlan,
    job: Option<&str>,
) -> ApiResult<&'a crate::fab::Setup> {
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

pub(super) async fn cut(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<JobQuery>, QueryRejection>,
    settings: Result<Query<PlanSettings>, QueryRejection>,
) -> ApiResult<Response> {
    let Query(q) = query?;
    let choice = q.choice(&s, settings?.0)?;
    let doc = s.get(id)?;
    blocking(move || {
        let format = q.format.clone().unwrap_or_default();
        let kind = JobFormat::from_extension(&format).ok_or_else(|| {
            ApiError::input(format!(
                "format {format:?}: unknown job type (expected {JOB_EXTENSIONS})"
            ))
        })?;
        let p = plan_document(&doc, &choice)?;
        let job = pick_job(&p.plan, q.job.as_deref())?;
        let bytes = job_file(kind, &p.plan, job, &p.machine)
            .map_err(|e| StudioError::about(Stage::Plan, &doc.name, e))?;
        let stem = crate::design::source::file_stem(&doc.name, "job");
        let several = (p.plan.jobs.len() > 1).then_some(job.name.as_str());
        let file = job_file_name(&stem, &p.machine, &choice.material, several, kind);
        Ok(download("application/octet-stream", &file, bytes))
    })
    .await
}

pub(super) async fn simulate(
    State(s): State<Arc<Studio>>,
    PathId(id): PathId,
    query: Result<Query<JobQuery>, QueryRejection>,
    settings: Result<Query<PlanSettings>, QueryRejection>,
) -> ApiResult<Json<Value>> {
    let Query(q) = query?;
    let choice = q.choice(&s, settings?.0)?;
    let doc = s.get(id)?;
    blocking(move || {
        let p = plan_document(&doc, &choice)?;
        let job = pick_job(&p.plan, q.job.as_deref())?;
        let failed = |e: &dyn std::fmt::Display| StudioError::about(Stage::Plan, &doc.name, e);
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

pub(super) async fn machines(State(s): State<Arc<Studio>>) -> ApiResult<Json<Value>> {
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
    let profiles = s.profiles.lock().unwrap_or_else(PoisonError::into_inner);
    for (key, m) in profiles.machines() {
        out.push(json!({
            "name": key,
            "description": "uploaded",
            "bed": [m.bed.width_mm, m.bed.height_mm],
            "gcode": m.emits_gcode(),
        }));
    }
    Ok(Json(json!(out)))
}

#[derive(Deserialize)]
pub(super) struct ProfileQuery {
    name: String,
}

/// Reads an uploaded machine or material profile (TOML) with the command line's parser and
/// keeps it for this run: its key (`upload:NAME`) chooses it in `plan`, `cut`, `simulate`.
pub(super) async fn upload_profile(
    State(s): State<Arc<Studio>>,
    kind: Result<Path<String>, PathRejection>,
    query: Result<Query<ProfileQuery>, QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> ApiResult<Json<Value>> {
    let Path(kind) = kind?;
    let Query(q) = query?;
    let kind = match kind.as_str() {
        "machine" => Kind::Machine,
        "material" => Kind::Material,
        other => {
            return Err(ApiError::new(
                StatusCode::NOT_FOUND,
                format!("{other}: profiles are of kind machine or material"),
            ));
        }
    };
    let name = upload_name(&q.name);
    let body = upload_body(&name, body)?;
    if body.len() > MAX_PROFILE_BYTES {
        return Err(ApiError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            format!("{name}: the profile is larger than the limit of {MAX_PROFILE_BYTES} bytes"),
        ));
    }
    let key = s
        .profiles
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .add(kind, &name, &body)?;
    Ok(Json(json!({ "name": key })))
}

pub(super) async fn materials(State(s): State<Arc<Studio>>) -> ApiResult<Json<Value>> {
    let entries = profile_catalogue(ProfileKind::Material)
        .map_err(|e| ApiError::new(StatusCode::INTERNAL_SERVER_ERROR, e.to_string()))?;
    let mut out: Vec<Value> = entries
        .iter()
        .map(|e| json!({ "name": e.name, "description": e.description }))
        .collect();
    let profiles = s.profiles.lock().unwrap_or_else(PoisonError::into_inner);
    out.extend(
        profiles
            .materials()
            .iter()
            .map(|(key, _)| json!({ "name": key, "description": "uploaded" })),
    );
    Ok(Json(json!(out)))
}
