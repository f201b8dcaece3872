//! The profiles shipped with foldcam, embedded in the binary so `foldcam` finds them from any
//! folder. The files live in `machines/` and `machines/materials/`; adding one means adding a
//! line here.

/// Shipped machines: (name, TOML text), sorted by name.
pub(crate) const MACHINES: [(&str, &str); 5] = [
    ("grbl-diode", include_str!("../../machines/grbl-diode.toml")),
    (
        "grbl-pen-plotter",
        include_str!("../../machines/grbl-pen-plotter.toml"),
    ),
    ("lightburn", include_str!("../../machines/lightburn.toml")),
    (
        "linuxcnc-fiber",
        include_str!("../../machines/linuxcnc-fiber.toml"),
    ),
    (
        "marlin-laser",
        include_str!("../../machines/marlin-laser.toml"),
    ),
];

/// Shipped materials: (name, TOML text), sorted by name.
pub(crate) const MATERIALS: [(&str, &str); 5] = [
    (
        "card-300gsm",
        include_str!("../../machines/materials/card-300gsm.toml"),
    ),
    (
        "paper-160gsm",
        include_str!("../../machines/materials/paper-160gsm.toml"),
    ),
    (
        "polypropylene-0.5",
        include_str!("../../machines/materials/polypropylene-0.5.toml"),
    ),
    (
        "stainless-0.3",
        include_str!("../../machines/materials/stainless-0.3.toml"),
    ),
    (
        "stainless-0.5",
        include_str!("../../machines/materials/stainless-0.5.toml"),
    ),
];
