//! `foldcam serve`: the local web studio. A small HTTP server (axum on tokio) serves a front
//! end embedded in the binary ([`assets`]) and a JSON API over the library ([`api`]): open a
//! pattern or a design file ([`design_open`]), check it, fold it in 3D, plan it for a machine and download the job files exactly
//! as `foldcam cut` writes them.
//!
//! # What the server reads
//! Only the files named on the command line (by their index in [`StudioConfig::files`]) and
//! uploads (request bodies of at most [`StudioConfig::max_upload_bytes`]). A paper-craft
//! design's mesh is read only when it is itself among those files or uploaded with the design
//! ([`design_open`]). No request names a
//! path on disk: machine and material profiles are chosen among the shipped ones by name, and
//! static files come from the embedded table, so `..` in a URL reaches nothing.
//!
//! # Other web pages
//! Requests naming another `Host`, and state-changing requests from another origin or without
//! the page's token, are refused; JSON bodies must be sent as `application/json`; every
//! response carries a content security policy and framing, sniffing and referrer headers
//! ([`guard`]).
//!
//! # Errors
//! Every API error is a JSON object `{"error": "..."}` whose text is the message `foldcam`
//! would print for the same input (without the leading `foldcam: `), with the upload's file
//! name where the command line names the file. A failure to read, build, clean, fold or plan
//! (an [`error::StudioError`]) adds what failed (`"stage"`: `read`, `design`, `clean`, `fold`,
//! `profile`, `plan`, `request`) and the file it concerns when its text does not name it
//! (`"file"`, else `null`).

pub(crate) mod api;
pub(crate) mod assets;
mod budget;
mod craft_api;
pub(crate) mod design_open;
pub(crate) mod document;
mod edit_api;
pub(crate) mod error;
pub(crate) mod flat;
mod fold3d_api;
mod folding_api;
pub(crate) mod guard;
mod history;
mod machine_api;
mod popup_api;
mod sessions;
pub(crate) mod settings;
mod start_api;
mod tessellate_api;
pub(crate) mod toolpath;
mod voxel_api;

use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::PathBuf;
use std::sync::Arc;

/// Largest upload accepted by default, bytes (32 MiB: the largest bundled pattern is far
/// smaller; the command line reads up to [`crate::formats::MAX_INPUT_BYTES`]).
pub const DEFAULT_MAX_UPLOAD_BYTES: usize = 32 * 1024 * 1024;

/// The address served when none is given: this machine only.
pub const DEFAULT_HOST: IpAddr = IpAddr::V4(Ipv4Addr::LOCALHOST);

/// The port served when none is given.
pub const DEFAULT_PORT: u16 = 8470;

/// Most documents (opened files and uploads) kept at once; the oldest is dropped first.
pub const MAX_DOCUMENTS: usize = 32;

/// How to run the studio.
#[derive(Clone, Debug)]
pub struct StudioConfig {
    /// Address to bind (loopback unless the user asks otherwise).
    pub host: IpAddr,
    /// Port to bind; 0 picks a free one.
    pub port: u16,
    /// Files the user named on the command line: the only paths the server reads.
    pub files: Vec<PathBuf>,
    /// Largest request body accepted, bytes.
    pub max_upload_bytes: usize,
    /// A tessellation solve whose page has not asked for its progress for this long is
    /// cancelled.
    pub abandon_after: std::time::Duration,
}

impl Default for StudioConfig {
    fn default() -> Self {
        StudioConfig {
            host: DEFAULT_HOST,
            port: DEFAULT_PORT,
            files: Vec::new(),
            max_upload_bytes: DEFAULT_MAX_UPLOAD_BYTES,
            abandon_after: std::time::Duration::from_secs(crate::limits::STUDIO_ABANDONED_SECONDS),
        }
    }
}

/// Why the studio could not start.
#[derive(Debug, thiserror::Error)]
pub enum StudioError {
    /// The address could not be bound.
    #[error("cannot listen on {addr}: {source}")]
    Bind {
        /// The address.
        addr: SocketAddr,
        /// What the system said.
        source: std::io::Error,
    },
    /// The async runtime could not start or the server stopped with an error.
    #[error("the web server stopped: {0}")]
    Runtime(std::io::Error),
}

/// Binds the address and serves until the process ends. `on_ready` is called once with the
/// address actually bound (useful with port 0) before the first request is taken.
///
/// # Errors
/// [`StudioError::Bind`] when the address is taken or not allowed, [`StudioError::Runtime`]
/// when the runtime cannot start.
pub fn serve(config: StudioConfig, on_ready: impl FnOnce(SocketAddr)) -> Result<(), StudioError> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_io()
        .build()
        .map_err(StudioError::Runtime)?;
    runtime.block_on(async move {
        let addr = SocketAddr::new(config.host, config.port);
        let listener = tokio::net::TcpListener::bind(addr)
            .await
            .map_err(|source| StudioError::Bind { addr, source })?;
        let bound = listener
            .local_addr()
            .map_err(|source| StudioError::Bind { addr, source })?;
        // The guard answers to the port actually bound (port 0 picks one).
        let config = StudioConfig {
            port: bound.port(),
            ..config
        };
        let state = Arc::new(api::Studio::new(config));
        on_ready(bound);
        axum::serve(listener, api::router(state))
            .await
            .map_err(StudioError::Runtime)
    })
}
