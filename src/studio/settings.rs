//! Machine and material profiles uploaded to the studio as TOML, read by the same parser as
//! the profile files the command line names. (The plan settings a user may change are the
//! library's [`crate::fab::PlanSettings`].)

use super::error::{Stage, StudioError};
use crate::machine::{
    MachineProfile, Material, load_machine, load_material, parse_machine, parse_material,
    shipped_machines, shipped_materials,
};

/// Largest profile upload, bytes (the shipped profiles are under 4 KiB).
pub const MAX_PROFILE_BYTES: usize = 64 * 1024;

/// Most uploaded profiles of each kind kept; the oldest goes first.
pub const MAX_UPLOADED_PROFILES: usize = 16;

/// The prefix that names an uploaded profile among the shipped ones (`upload:NAME.toml`).
pub const UPLOAD_PREFIX: &str = "upload:";

/// Profiles uploaded during this run of the studio, by `upload:FILE NAME`.
#[derive(Default)]
pub struct UploadedProfiles {
    machines: Vec<(String, MachineProfile)>,
    materials: Vec<(String, Material)>,
}

/// The kind of a profile upload.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A machine profile.
    Machine,
    /// A material profile.
    Material,
}

fn keep<T>(list: &mut Vec<(String, T)>, key: String, item: T) {
    list.retain(|(k, _)| *k != key);
    list.push((key, item));
    if list.len() > MAX_UPLOADED_PROFILES {
        list.remove(0);
    }
}

impl UploadedProfiles {
    /// Reads an uploaded profile named `name` (its file name: the profile's name is its stem,
    /// as for a file on the command line) and keeps it; returns the key that chooses it.
    ///
    /// # Errors
    /// The message `foldcam cut -m NAME` prints for a file of that name and content.
    pub fn add(&mut self, kind: Kind, name: &str, bytes: &[u8]) -> Result<String, StudioError> {
        let text = std::str::from_utf8(bytes).map_err(|e| {
            let at = format!("file: not UTF-8 text (byte {})", e.valid_up_to());
            StudioError::about(Stage::Profile, name, at)
        })?;
        let key = format!("{UPLOAD_PREFIX}{name}");
        match kind {
            Kind::Machine => {
                let m =
                    parse_machine(text, name).map_err(|e| StudioError::named(Stage::Profile, e))?;
                keep(&mut self.machines, key.clone(), m);
            }
            Kind::Material => {
                let m = parse_material(text, name)
                    .map_err(|e| StudioError::named(Stage::Profile, e))?;
                keep(&mut self.materials, key.clone(), m);
            }
        }
        Ok(key)
    }

    /// Keys and profiles of the uploaded machines.
    pub fn machines(&self) -> &[(String, MachineProfile)] {
        &self.machines
    }

    /// Keys and profiles of the uploaded materials.
    pub fn materials(&self) -> &[(String, Material)] {
        &self.materials
    }

    /// A shipped machine by name or an uploaded one by key (never a file on disk).
    ///
    /// # Errors
    /// A name that is neither, listing the shipped names.
    pub fn machine(&self, name: &str) -> Result<MachineProfile, StudioError> {
        if let Some((_, m)) = self.machines.iter().find(|(k, _)| k == name) {
            return Ok(m.clone());
        }
        shipped(name, "machine", &shipped_machines())?;
        load_machine(name).map_err(|e| StudioError::named(Stage::Profile, e))
    }

    /// A shipped material by name or an uploaded one by key.
    ///
    /// # Errors
    /// As [`UploadedProfiles::machine`].
    pub fn material(&self, name: &str) -> Result<Material, StudioError> {
        if let Some((_, m)) = self.materials.iter().find(|(k, _)| k == name) {
            return Ok(m.clone());
        }
        shipped(name, "material", &shipped_materials())?;
        load_material(name).map_err(|e| StudioError::named(Stage::Profile, e))
    }
}

/// Refuses a name that is not a shipped profile (a path would make the server read a file a
/// request names).
fn shipped(name: &str, kind: &str, names: &[&str]) -> Result<(), StudioError> {
    if names.contains(&name) {
        Ok(())
    } else {
        Err(StudioError::named(
            Stage::Profile,
            format!(
                "{kind} {name:?}: not a shipped profile (one of {}) nor an uploaded one; the studio \
             reads no profile files from disk",
                names.join(", ")
            ),
        ))
    }
}
