//! Design files in the studio: voxel and polygon pop-up cards, fold scripts, paper craft and
//! meshes (tessellation or pop-up card) built by [`crate::design::source`] exactly as the
//! matching `foldcam` command builds them, then opened as a pattern document.
//!
//! A paper-craft or tessellation design names its mesh by a relative path. The studio reads no
//! file for it: an upload's mesh must come in the same request (the files dropped together), a
//! command-line design's mesh must itself be named on the command line.

use std::path::{Path, PathBuf};

use serde::Deserialize;

use super::document::Document;
use super::error::{Stage, StudioError};
use crate::design::source::{
    DesignFile, DesignKind, DesignOptions, MeshUse, SourceError, build_design, craft,
    mesh_path_beside, read_design_file, tess_design,
};
use crate::formats::Format;

/// Whether `name` is opened as a design file rather than a pattern.
pub fn is_design(name: &Path) -> bool {
    Format::from_path(name).is_none() && DesignKind::has_design_ending(name)
}

/// The message `foldcam` prints for a build error: the error and its causes joined with
/// ": ", leaving out a cause the message already holds; a refusal's report line by line.
pub fn message(e: &SourceError) -> String {
    let mut text = e.to_string();
    let mut cause = std::error::Error::source(e);
    while let Some(c) = cause {
        let part = c.to_string();
        if !text.contains(&part) {
            text.push_str(": ");
            text.push_str(&part);
        }
        cause = c.source();
    }
    text
}

/// A design's failure as a studio error: [`message`] at [`Stage::Design`].
pub fn design_error(e: &SourceError) -> StudioError {
    StudioError::named(Stage::Design, message(e))
}

/// Builds an upload: `name` and `bytes` the design file, `companions` the files sent with it
/// (a paper craft's mesh is found among them by name).
///
/// # Errors
/// The message `foldcam` prints for the same files.
pub fn open_upload(
    name: &str,
    bytes: &[u8],
    companions: &[Named<'_>],
    mesh_use: MeshUse,
) -> Result<Document, StudioError> {
    let path = PathBuf::from(name);
    let file = DesignFile { name: &path, bytes };
    let named: Vec<PathBuf> = companions.iter().map(|(n, _)| PathBuf::from(n)).collect();
    let others: Vec<DesignFile<'_>> = named
        .iter()
        .zip(companions)
        .map(|(n, (_, b))| DesignFile { name: n, bytes: b })
        .collect();
    build(name, &file, &others, mesh_use)
}

/// Builds a design file named on the command line. A paper craft's mesh is read only when
/// it is itself one of `given` (the files on the command line).
///
/// # Errors
/// The message `foldcam` prints for the same file.
pub fn open_path(
    path: &Path,
    given: &[PathBuf],
    mesh_use: MeshUse,
) -> Result<Document, StudioError> {
    let bytes = read_design_file(path).map_err(|e| design_error(&e))?;
    let file = DesignFile {
        name: path,
        bytes: &bytes,
    };
    let mut companion = None;
    let mesh_named = match DesignKind::recognise(path, &bytes) {
        Some(DesignKind::PaperCraft) => Some(craft::parse(&file).map(|p| p.mesh_name())),
        Some(DesignKind::Tessellation) => Some(tess_design::parse(&file).map(|d| d.mesh)),
        _ => None,
    };
    if let Some(named) = mesh_named {
        let wanted = mesh_path_beside(path, &named.map_err(|e| design_error(&e))?);
        let same = |a: &Path, b: &Path| {
            a == b || matches!((a.canonicalize(), b.canonicalize()), (Ok(a), Ok(b)) if a == b)
        };
        if given.iter().any(|g| same(g, &wanted)) {
            let mesh = read_design_file(&wanted).map_err(|e| design_error(&e))?;
            companion = Some((wanted, mesh));
        }
    }
    let others: Vec<DesignFile<'_>> = companion
        .iter()
        .map(|(n, b)| DesignFile { name: n, bytes: b })
        .collect();
    build(&path.display().to_string(), &file, &others, mesh_use)
}

fn build(
    name: &str,
    file: &DesignFile<'_>,
    companions: &[DesignFile<'_>],
    mesh_use: MeshUse,
) -> Result<Document, StudioError> {
    let options = DesignOptions {
        mesh_use,
        ..DesignOptions::default()
    };
    let mut notes = Vec::new();
    let design =
        build_design(file, companions, &options, &mut notes).map_err(|e| design_error(&e))?;
    Document::from_design(name.to_string(), design, notes)
}

/// A file sent with another: its name and bytes.
pub type Named<'a> = (String, &'a [u8]);

/// One file of an upload sent with companions: its name and length in bytes.
#[derive(Clone, Debug, Deserialize)]
pub struct Part {
    /// The file's name.
    pub name: String,
    /// Its length, bytes.
    pub size: usize,
}

/// Splits a body holding the main file followed by `parts` (in order) into the main file's
/// bytes and the parts'.
///
/// # Errors
/// When the parts are longer than the body.
pub fn split_body<'a>(
    name: &str,
    body: &'a [u8],
    parts: &[Part],
) -> Result<(&'a [u8], Vec<Named<'a>>), StudioError> {
    let total = parts
        .iter()
        .fold(0usize, |sum, p| sum.saturating_add(p.size));
    let Some(main_len) = body.len().checked_sub(total) else {
        return Err(StudioError::about(
            Stage::Read,
            name,
            format!(
                "the files sent with it announce {total} bytes, more than the {} received",
                body.len()
            ),
        ));
    };
    let (main, mut rest) = body.split_at(main_len);
    let mut out = Vec::with_capacity(parts.len());
    for p in parts {
        let (this, next) = rest.split_at(p.size);
        out.push((super::api::upload_name(&p.name), this));
        rest = next;
    }
    Ok((main, out))
}
