//! The plan settings a user may change in the studio (the overrides `foldcam cut` and
//! `foldcam plan` take as options), and machine and material profiles uploaded as TOML,
//! read by the same parser as the profile files the command line names.

use serde::Deserialize;

use crate::fab::{DEFAULT_TAB_SPACING_MM, Operation, PlanOptions, PlanOverrides, Tabs};
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

/// Every plan override of `foldcam cut` / `foldcam plan`, by the option's name with `_` for
/// `-` (`min_dash` is `--min-dash`); `None` keeps the material's or the planner's default.
/// Lengths are millimetres.
#[derive(Clone, Debug, Default, Deserialize, PartialEq)]
pub struct PlanSettings {
    /// Operation for mountain creases (`mark`, `score`, `perforate`, `cut`, `plot`, `skip`).
    pub mountain: Option<String>,
    /// Operation for valley creases.
    pub valley: Option<String>,
    /// Operation for unassigned creases.
    pub unassigned: Option<String>,
    /// Operation for flat lines.
    pub flat: Option<String>,
    /// Operation for boundary and cut lines.
    pub boundary: Option<String>,
    /// Perforation dash length.
    pub dash: Option<f64>,
    /// Material left between dashes.
    pub bridge: Option<f64>,
    /// Cut share of each dash period, in (0, 1), instead of `bridge`.
    pub duty: Option<f64>,
    /// Shortest dash worth cutting.
    pub min_dash: Option<f64>,
    /// Least uncut material between two cuts.
    pub min_web: Option<f64>,
    /// Uncut clearance around every vertex.
    pub clearance: Option<f64>,
    /// Kerf width.
    pub kerf: Option<f64>,
    /// `true` is `--no-kerf-offset`.
    #[serde(default)]
    pub no_kerf_offset: bool,
    /// Mountains from the front, valleys from the back.
    #[serde(default)]
    pub two_sided: bool,
    /// Holding tab width.
    pub tabs: Option<f64>,
    /// Spacing between tabs ([`DEFAULT_TAB_SPACING_MM`] when absent, as on the command line).
    pub tab_spacing: Option<f64>,
    /// Lead-in length.
    pub lead_in: Option<f64>,
    /// Distance from the bed origin ([`crate::fab::DEFAULT_MARGIN_MM`] when absent, as on the
    /// command line).
    pub margin: Option<f64>,
    /// `true` is `--no-optimize`.
    #[serde(default)]
    pub no_optimize: bool,
    /// `corner` (default) or `centre`.
    pub origin: Option<String>,
}

fn operation(option: &str, name: &str) -> Result<Option<Operation>, String> {
    Operation::choice(name).map_err(|e| format!("{option}: {e}"))
}

impl PlanSettings {
    /// The plan options for `material` on `machine` with these overrides, resolved as
    /// `foldcam cut` resolves its options ([`PlanOptions::for_machine`]).
    ///
    /// # Errors
    /// The option and the range it must lie in, or the planner's cross-check message.
    pub fn options(
        &self,
        machine: &MachineProfile,
        material: &Material,
    ) -> Result<PlanOptions, String> {
        let op = |option: &str, value: &Option<String>| {
            value
                .as_deref()
                .map(|name| operation(option, name))
                .transpose()
        };
        let centre = match self.origin.as_deref() {
            None | Some("" | "corner") => false,
            Some("centre" | "center") => true,
            Some(other) => return Err(format!("origin: {other:?} is not corner or centre")),
        };
        let overrides = PlanOverrides {
            mountain: op("mountain", &self.mountain)?,
            valley: op("valley", &self.valley)?,
            unassigned: op("unassigned", &self.unassigned)?,
            flat: op("flat", &self.flat)?,
            boundary: op("boundary", &self.boundary)?,
            dash_mm: self.dash,
            bridge_mm: self.bridge,
            duty: self.duty,
            min_dash_mm: self.min_dash,
            min_web_mm: self.min_web,
            vertex_clearance_mm: self.clearance,
            kerf_mm: self.kerf,
            kerf_offset: Some(!self.no_kerf_offset),
            two_sided: self.two_sided,
            tabs: self.tabs.map(|width_mm| Tabs {
                width_mm,
                spacing_mm: self.tab_spacing.unwrap_or(DEFAULT_TAB_SPACING_MM),
            }),
            lead_in_mm: self.lead_in,
            margin_mm: self.margin,
            optimize: Some(!self.no_optimize),
            centre,
            offset_mm: None,
        };
        PlanOptions::for_machine(machine, material, &overrides).map_err(|e| e.to_string())
    }
}

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
    pub fn add(&mut self, kind: Kind, name: &str, bytes: &[u8]) -> Result<String, String> {
        let text = std::str::from_utf8(bytes)
            .map_err(|e| format!("{name}: file: not UTF-8 text (byte {})", e.valid_up_to()))?;
        let key = format!("{UPLOAD_PREFIX}{name}");
        match kind {
            Kind::Machine => {
                let m = parse_machine(text, name).map_err(|e| e.to_string())?;
                keep(&mut self.machines, key.clone(), m);
            }
            Kind::Material => {
                let m = parse_material(text, name).map_err(|e| e.to_string())?;
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
    pub fn machine(&self, name: &str) -> Result<MachineProfile, String> {
        if let Some((_, m)) = self.machines.iter().find(|(k, _)| k == name) {
            return Ok(m.clone());
        }
        shipped(name, "machine", &shipped_machines())?;
        load_machine(name).map_err(|e| e.to_string())
    }

    /// A shipped material by name or an uploaded one by key.
    ///
    /// # Errors
    /// As [`UploadedProfiles::machine`].
    pub fn material(&self, name: &str) -> Result<Material, String> {
        if let Some((_, m)) = self.materials.iter().find(|(k, _)| k == name) {
            return Ok(m.clone());
        }
        shipped(name, "material", &shipped_materials())?;
        load_material(name).map_err(|e| e.to_string())
    }
}

/// Refuses a name that is not a shipped profile (a path would make the server read a file a
/// request names).
fn shipped(name: &str, kind: &str, names: &[&str]) -> Result<(), String> {
    if names.contains(&name) {
        Ok(())
    } else {
        Err(format!(
            "{kind} {name:?}: not a shipped profile (one of {}) nor an uploaded one; the studio \
             reads no profile files from disk",
            names.join(", ")
        ))
    }
}
