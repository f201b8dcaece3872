//! PLACEHOLDER (machine work): machine and material profiles, loaded from TOML and validated.

mod material;
pub mod motion;
mod profile;

pub use material::{
    DesignLimits, Material, OperationMapping, OperationSettings, Perforation, SettingsByOperation,
};
pub use profile::{
    Bed, Corner, Dialect, DwellUnit, LaserMode, MachineKind, MachineProfile, PowerRange,
};

/// An error loading a profile: always names the file (or shipped profile), the key and the
/// problem.
#[derive(Debug, thiserror::Error)]
#[error("{source_name}: {key}: {message}")]
pub struct ProfileError {
    /// The file path, or `shipped:NAME` for a built-in profile.
    pub source_name: String,
    /// The TOML key (dotted), or `file`.
    pub key: String,
    /// What is wrong and what was expected.
    pub message: String,
}
