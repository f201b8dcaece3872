//! `foldcam serve [FILE…]`: the local web studio ([`foldcam::studio`]).

use std::net::IpAddr;
use std::path::PathBuf;

use anyhow::{Result, bail};
use foldcam::studio::{self, StudioConfig};

use super::Outcome;

/// Open patterns in the browser: look, check, fold, plan and download job files.
#[derive(clap::Args)]
#[command(
    long_about = "Serves the foldcam studio, a web page on this machine: open a pattern (the \
                  files given here, or any FOLD, SVG, .cp, .opx or DXF file dropped on the \
                  page) or a design file the design commands read (a .voxel.txt, height-map \
                  .png, .popup.toml, fold-script .toml, .craft.toml with its mesh, or an OBJ/STL \
                  mesh made into a tessellation or a pop-up card), see it with its check findings ringed, fold it in 3D with a slider \
                  (the bar-and-hinge simulation of Ghassaei, Demaine & Gershenfeld 2018), choose \
                  a machine and material, see the toolpath and its time, and download the job \
                  files exactly as `foldcam cut` writes them. The server reads only the files \
                  named here and uploads; it listens on 127.0.0.1 unless --host says otherwise. \
                  Stop it with Ctrl-C.",
    after_help = "Examples:\n  foldcam serve\n  foldcam serve miura.fold bird.cp --open\n  \
                  foldcam serve --port 0"
)]
pub struct Args {
    /// Pattern or design files to offer in the studio (the only files it reads from disk; a
    /// .craft.toml's mesh is read only when it is named here too).
    pub files: Vec<PathBuf>,
    /// Port to listen on (0 picks a free one).
    #[arg(long, default_value_t = studio::DEFAULT_PORT)]
    pub port: u16,
    /// Address to listen on. Anything but a loopback address lets other machines on the
    /// network open the studio (it has no login).
    #[arg(long, default_value_t = studio::DEFAULT_HOST)]
    pub host: IpAddr,
    /// Open the studio in the default web browser.
    #[arg(long)]
    pub open: bool,
    /// Largest upload accepted, MiB.
    #[arg(long, value_name = "MIB", default_value_t = studio::DEFAULT_MAX_UPLOAD_BYTES / (1024 * 1024))]
    pub max_upload: usize,
    /// Cancel a tessellation solve when its page has not asked for its progress for this
    /// long, seconds (a closed tab).
    #[arg(long, value_name = "SECONDS", default_value_t = foldcam::limits::STUDIO_ABANDONED_SECONDS, value_parser = clap::value_parser!(u64).range(1..=86_400))]
    pub abandon_after: u64,
}

/// Starts the server and serves until interrupted.
pub fn run(args: Args) -> Result<Outcome> {
    for f in &args.files {
        if !f.is_file() {
            bail!("{}: no such file", f.display());
        }
    }
    if !args.host.is_loopback() {
        errln!(
            "foldcam: warning: serving on {}: other machines on the network can open the \
             studio and upload files to it (it has no login)",
            args.host
        );
    }
    let Some(max_upload_bytes) = args.max_upload.checked_mul(1024 * 1024) else {
        bail!("--max-upload {}: too large", args.max_upload);
    };
    let config = StudioConfig {
        host: args.host,
        port: args.port,
        files: args.files,
        max_upload_bytes,
        abandon_after: std::time::Duration::from_secs(args.abandon_after),
    };
    let open = args.open;
    studio::serve(config, |addr| {
        let url = format!("http://{addr}/");
        // The first line on stdout is the address (scripts and tests read it).
        outln!("foldcam studio: {url}");
        errln!("foldcam: serving the studio at {url} (Ctrl-C stops it)");
        if open {
            open_browser(&url);
        }
    })?;
    Ok(Outcome::Done)
}

/// Asks the desktop to open `url`; says so when it cannot.
fn open_browser(url: &str) {
    let opener = if cfg!(target_os = "macos") {
        "open"
    } else if cfg!(windows) {
        "explorer"
    } else {
        "xdg-open"
    };
    // The opener's own complaints (xdg-open tries several programs, and says so for each)
    // are replaced by one line when it fails.
    let spawned = std::process::Command::new(opener)
        .arg(url)
        .stdin(std::process::Stdio::null())
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn();
    let url = url.to_string();
    match spawned {
        Ok(mut child) => {
            std::thread::spawn(move || match child.wait() {
                Ok(status) if !status.success() => errln!(
                    "foldcam: warning: could not open a browser ({opener} {status}): open {url}"
                ),
                Err(e) => {
                    errln!("foldcam: warning: could not open a browser ({opener}: {e}): open {url}")
                }
                Ok(_) => {}
            });
        }
        Err(e) => {
            errln!("foldcam: warning: could not open a browser ({opener}: {e}): open {url}")
        }
    }
}
