//! OBJ (tobj) and STL (stl_io, ASCII or binary) readers.

use std::io::Cursor;
use std::path::Path;

use glam::DVec3;

use super::{MeshError, PolyMesh};

/// Reads a mesh, choosing the reader from the extension (`.obj` or `.stl`, any case).
pub fn read_mesh(path: &Path) -> Result<PolyMesh, MeshError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let parse = match ext.as_deref() {
        Some("obj") => parse_obj,
        Some("stl") => parse_stl,
        _ => return Err(MeshError::UnknownFormat),
    };
    let bytes = std::fs::read(path).map_err(|e| MeshError::Io(e.to_string()))?;
    parse(&bytes)
}

/// Parses Wavefront OBJ: every object and group becomes part of one mesh; faces keep their
/// polygons (no triangulation); points, lines, normals, texture coordinates and materials
/// are ignored.
pub fn parse_obj(bytes: &[u8]) -> Result<PolyMesh, MeshError> {
    check_obj_face_indices(bytes)?;
    let options = tobj::LoadOptions {
        triangulate: false,
        single_index: false,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, _) = tobj::load_obj_buf(&mut Cursor::new(bytes), &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .map_err(|e| MeshError::Syntax {
        format: "OBJ",
        message: e.to_string(),
    })?;
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for model in models {
        let mesh = model.mesh;
        let base = positions.len() as u32;
        positions.extend(
            mesh.positions
                .chunks_exact(3)
                .map(|p| DVec3::new(p[0].into(), p[1].into(), p[2].into())),
        );
        let mut start = 0usize;
        let arities: Box<dyn Iterator<Item = usize>> = if mesh.face_arities.is_empty() {
            Box::new(std::iter::repeat_n(3, mesh.indices.len() / 3))
        } else {
            Box::new(mesh.face_arities.iter().map(|&a| a as usize))
        };
        for arity in arities {
            let Some(corners) = mesh.indices.get(start..start + arity) else {
                return Err(MeshError::Syntax {
                    format: "OBJ",
                    message: "face list is truncated".into(),
                });
            };
            faces.push(corners.iter().map(|&i| base + i).collect());
            start += arity;
        }
    }
    PolyMesh::new(positions, faces)
}

/// Parses STL, ASCII or binary; identical corner positions are merged into one vertex.
pub fn parse_stl(bytes: &[u8]) -> Result<PolyMesh, MeshError> {
    check_binary_stl_length(bytes)?;
    let mesh = stl_io::read_stl(&mut Cursor::new(bytes)).map_err(|e| MeshError::Syntax {
        format: "STL",
        message: e.to_string(),
    })?;
    let positions = mesh
        .vertices
        .iter()
        .map(|v| DVec3::new(v[0].into(), v[1].into(), v[2].into()))
        .collect();
    let faces = mesh
        .faces
        .iter()
        .map(|t| t.vertices.iter().map(|&i| i as u32).collect())
        .collect();
    PolyMesh::new(positions, faces)
}

/// Bytes of a binary STL before the triangles: an 80-byte header and a `u32` triangle count.
const STL_HEADER_BYTES: usize = 84;

/// Bytes per binary STL triangle: normal and three corners (12 `f32`) and a `u16`.
const STL_TRIANGLE_BYTES: u64 = 50;

/// For a binary STL (one that does not start with `solid`), refuses a file shorter than its
/// header or than the triangles its count announces, with both sizes in the message.
fn check_binary_stl_length(bytes: &[u8]) -> Result<(), MeshError> {
    if bytes.trim_ascii_start().starts_with(b"solid") {
        return Ok(());
    }
    let error = |message: String| MeshError::Syntax {
        format: "STL",
        message,
    };
    let Some(count) = bytes.get(80..STL_HEADER_BYTES) else {
        return Err(error(format!(
            "a binary STL starts with an 80-byte header and a 4-byte triangle count, but the \
             file has {} bytes (and is not ASCII STL, which starts with `solid`)",
            bytes.len()
        )));
    };
    let count = u32::from_le_bytes(count.try_into().expect("4 bytes"));
    let needed = STL_HEADER_BYTES as u64 + STL_TRIANGLE_BYTES * u64::from(count);
    if (bytes.len() as u64) < needed {
        return Err(error(format!(
            "the binary STL header announces {count} triangles ({needed} bytes), but the file \
             has {} bytes: it is truncated",
            bytes.len()
        )));
    }
    Ok(())
}

/// Largest face index (in magnitude) an OBJ file may use: a mesh holds at most `u32::MAX`
/// vertices.
const MAX_OBJ_INDEX: i64 = u32::MAX as i64;

/// Refuses `f` lines whose indices tobj would turn into overflowing arithmetic (it multiplies
/// indices by 3 unchecked: a panic in debug builds, a wrong normal in release builds): an
/// index beyond [`MAX_OBJ_INDEX`], or a relative (negative) index reaching before the first
/// position, texture coordinate or normal defined so far. Names the line.
fn check_obj_face_indices(bytes: &[u8]) -> Result<(), MeshError> {
    const KINDS: [(&str, &str); 3] = [
        ("v", "position"),
        ("vt", "texture coordinate"),
        ("vn", "normal"),
    ];
    let mut defined = [0i64; 3];
    let error = |n: usize, message: String| MeshError::Syntax {
        format: "OBJ",
        message: format!("line {}: {message}", n + 1),
    };
    for (n, line) in bytes.split(|&b| b == b'\n').enumerate() {
        let Ok(line) = std::str::from_utf8(line) else {
            continue; // tobj refuses the file itself
        };
        let mut words = line.split_whitespace();
        let first = words.next();
        if let Some(k) = KINDS.iter().position(|(key, _)| Some(*key) == first) {
            defined[k] += 1;
            continue;
        }
        if first != Some("f") {
            continue;
        }
        for word in words {
            for (k, part) in word.split('/').enumerate().take(3) {
                let Ok(i) = part.parse::<i64>() else {
                    continue; // empty, or tobj refuses it
                };
                if i.unsigned_abs() > MAX_OBJ_INDEX as u64 {
                    return Err(error(
                        n,
                        format!(
                            "face index {i} is beyond ±{MAX_OBJ_INDEX}, the most vertices a mesh may have"
                        ),
                    ));
                }
                if i < 0 && -i > defined[k] {
                    return Err(error(
                        n,
                        format!(
                            "relative face index {i} reaches before the first {} ({} defined so far)",
                            KINDS[k].1, defined[k]
                        ),
                    ));
                }
            }
        }
    }
    Ok(())
}
