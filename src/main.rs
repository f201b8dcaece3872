//! The `foldcam` command (the CLI lands once the format readers are merged).

fn main() {}
