//! Writes the example meshes of `examples/tessellation/`: a dome, a saddle and a bell, each a
//! hexagonal patch of 54 equilateral triangles (edge 20 mm, interior valence 6) lifted onto
//! the surface (`foldcam::design::tessellation::samples::sample_surface`).
//!
//! It also writes `cap.obj`, a 60° spherical cap of radius 100 mm as modelling programs
//! export one: a 12-valent pole and rings of 12, 24, …, 72 vertices (432 faces,
//! `foldcam::design::tessellation::samples::spherical_cap`).
//!
//! Run with `cargo run --example tessellation_meshes`; `-- RINGS DIR` writes patches of
//! `6·RINGS²` faces into DIR instead (larger meshes for timing);
//! `-- cap N RINGS DEGREES RADIUS DIR` writes one cap of `N·RINGS²` faces into DIR;
//! `-- mask RINGS PATH` writes the face mask (`face_mask`, `6·RINGS²` faces) to PATH
//! (`mask 8 examples/tessellation/mask.obj` is the bundled one).

use std::path::Path;

use foldcam::design::tessellation::samples::{
    SampleSurface, face_mask, sample_surface, spherical_cap,
};
use foldcam::formats::write_atomic;

fn main() -> std::io::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("cap") {
        return cap(&args[1..]);
    }
    if args.first().map(String::as_str) == Some("mask") {
        return mask(&args[1..]);
    }
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
    if rings == 3 {
        let mesh = spherical_cap(12, 6, 60.0, 100.0);
        let path = dir.join("cap.obj");
        write_atomic(&path, mesh.to_obj().as_bytes())?;
        println!("wrote {} ({} faces)", path.display(), mesh.faces().len());
    }
    Ok(())
}

/// `cap N RINGS DEGREES RADIUS DIR`: one spherical cap, `DIR/cap-N-RINGS-DEGREES.obj`.
fn cap(args: &[String]) -> std::io::Result<()> {
    let [n, rings, degrees, radius, dir] = args else {
        return Err(std::io::Error::other(
            "usage: cap N RINGS DEGREES RADIUS DIR (e.g. cap 12 6 60 100 /tmp)",
        ));
    };
    let number = |s: &String| -> std::io::Result<f64> {
        s.parse()
            .map_err(|_| std::io::Error::other(format!("{s:?} is not a number")))
    };
    let (n, rings) = (number(n)? as usize, number(rings)? as usize);
    let mesh = spherical_cap(n, rings, number(degrees)?, number(radius)?);
    std::fs::create_dir_all(dir)?;
    let path = Path::new(dir).join(format!("cap-{n}-{rings}-{degrees}.obj"));
    write_atomic(&path, mesh.to_obj().as_bytes())?;
    println!("wrote {} ({} faces)", path.display(), mesh.faces().len());
    Ok(())
}

/// `mask RINGS PATH`: the face mask of `6·RINGS²` faces, written to PATH with a comment line
/// saying whose work it is.
fn mask(args: &[String]) -> std::io::Result<()> {
    let [rings, path] = args else {
        return Err(std::io::Error::other("usage: mask RINGS PATH"));
    };
    let rings: usize = rings
        .parse()
        .map_err(|_| std::io::Error::other(format!("{rings:?} is not a ring count")))?;
    let mesh = face_mask(rings);
    let text = format!("{MASK_HEADER}{}", mesh.to_obj());
    write_atomic(Path::new(path), text.as_bytes())?;
    println!("wrote {path} ({} faces)", mesh.faces().len());
    Ok(())
}

/// The first lines of `mask.obj`.
const MASK_HEADER: &str = "# face mask: foldcam's own procedural model (face_mask in \
src/design/tessellation/samples.rs), MIT like the rest of foldcam\n";
