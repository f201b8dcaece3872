//! Writes the example meshes of `examples/tessellation/`: a dome, a saddle and a bell, each a
//! hexagonal patch of 54 equilateral triangles (edge 20 mm, interior valence 6) lifted onto
//! the surface (`foldcam::design::tessellation::sample_surface`).
//!
//! Run with `cargo run --example tessellation_meshes`.

use std::path::Path;

use foldcam::design::tessellation::{SampleSurface, sample_surface};
use foldcam::formats::write_atomic;

fn main() -> std::io::Result<()> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/tessellation");
    std::fs::create_dir_all(&dir)?;
    for (name, surface) in [
        ("dome", SampleSurface::Dome),
        ("saddle", SampleSurface::Saddle),
        ("bell", SampleSurface::Bell),
    ] {
        let mesh = sample_surface(surface, 3, 20.0);
        let path = dir.join(format!("{name}.obj"));
        write_atomic(&path, mesh.to_obj().as_bytes())?;
        println!("wrote {} ({} faces)", path.display(), mesh.faces().len());
    }
    Ok(())
}
