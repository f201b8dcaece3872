//! Machine and material profiles, loaded from TOML and validated once, where they enter.
//!
//! A [`MachineProfile`] (`machines/NAME.toml`) says what a machine is and how it wants its
//! G-code: kind, dialect, bed and origin, feeds (mm/min), acceleration (mm/s²), junction
//! deviation (mm), the `S` range of its laser, `M3`/`M4`, the unit of `G4 P`, coordinate
//! resolution, pen commands, preamble and postamble. A [`Material`]
//! (`machines/materials/NAME.toml`) says how a sheet is worked: thickness and kerf (mm), speed,
//! power fraction and passes per operation, the perforation layout, the default operation per
//! crease assignment, and the design limits it imposes (minimum vertex angle, maximum fold
//! angle).
//!
//! [`load_machine`] and [`load_material`] take a shipped name (the profiles in `machines/` are
//! embedded in the binary) or a path to a `.toml` file. Every key is checked: unknown keys,
//! wrong types, numbers that are not finite or out of range, and inconsistent settings are
//! refused with a [`ProfileError`] naming the file, the dotted key, the value found and the
//! line. The accepted ranges are listed in `machines/README.md`.

pub(crate) mod commands;
pub(crate) mod control;
mod fields;
mod load;
mod locate;
mod material;
pub(crate) mod motion;
mod operation;
mod profile;
mod read_machine;
mod read_material;
mod shipped;
pub(crate) mod sync_links;

pub use control::{AirAssist, LaserOutput, MachineControl, SwitchCost};
pub use load::{
    CatalogueEntry, ProfileKind, load_machine, load_material, parse_machine, parse_material,
    profile_catalogue, shipped_machines, shipped_materials,
};
pub use material::{
    DesignLimits, Material, OperationMapping, OperationSettings, Perforation, SettingsByOperation,
};
pub use motion::{
    BLEND_ACC_RATIO_NORMAL, Kinematics, Move, job_time, junction_speed, move_times, trapezoid_time,
};
pub use operation::Operation;
pub use profile::{
    Bed, Corner, Dialect, DwellUnit, LaserMode, MachineKind, MachineProfile, PowerRange,
};

/// An error loading a profile: always names the file (or shipped profile), the key and the
/// problem, including the value found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{source_name}: {key}: {message}")]
pub struct ProfileError {
    /// The file path as given, or `shipped:machines/NAME.toml`
    /// (`shipped:machines/materials/NAME.toml`) for a built-in profile, or the unknown name.
    pub source_name: String,
    /// The TOML key (dotted, with `[i]` for array items), `file` for a file that cannot be
    /// read or is not TOML, or `name` for an unknown shipped name.
    pub key: String,
    /// What is wrong, the value found and what was expected, ending in `(line N)` when the
    /// key is written in the text.
    pub message: String,
}
