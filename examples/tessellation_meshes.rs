//! Writes the example meshes of `examples/tessellation/`: a dome, a saddle and a bell, each a
//! hexagonal patch of 54 equilateral triangles (edge 20 mm, interior valence 6) lifted onto
//! the surface (`foldcam::design::tessellation::sample_surface`).
//!
//! Run with `cargo run --example tessellation_meshes`; `-- RINGS DIR` writes patches of
//! `6·RINGS²` faces into DIR instead (larger meshes for timing).

use std::path::Path;

use foldcam::design::tessellation::{SampleSurface, sample_surface};
use foldcam::formats::write_atomic;

fn main() -> std::io::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let rings: usize = match args.first() {
        Some(r) => r
            .parse()
            .map_err(|_| std::io::Error::other(format!("{r:?} is not a ring count")))?,
        None => 3,
    };
    let dir = match args.get(1) {
        Some(d) => Path::new(d).to_path_buf(),
        None => Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/tessellation"),
    };
    std::fs::create_dir_all(&dir)?;
    for (name, surface) in [
        ("dome", SampleSurface::Dome),
        ("saddle", SampleSurface::Saddle),
        ("bell", SampleSurface::Bell),
    ] {
        let mesh = sample_surface(surface, rings, 20.0);
        let path = if rings == 3 {
            dir.join(format!("{name}.obj"))
        } else {
            dir.join(format!("{name}-{rings}.obj"))
        };
        write_atomic(&path, mesh.to_obj().as_bytes())?;
        println!("wrote {} ({} faces)", path.display(), mesh.faces().len());
    }
    Ok(())
}
