//! What the mesh targets assert: an accepted mesh is well formed, an error says something.

use foldcam::mesh::{MeshError, PolyMesh};

/// Checks a mesh reader's result.
pub fn check(result: Result<PolyMesh, MeshError>) {
    match result {
        Ok(mesh) => {
            let n = mesh.positions().len();
            assert!(
                mesh.positions().iter().all(|p| p.is_finite()),
                "non-finite position"
            );
            for face in mesh.faces() {
                assert!(face.len() >= 3, "a face of {} corners", face.len());
                assert!(face.iter().all(|&i| (i as usize) < n), "index out of range");
            }
            let _ = mesh.bounds();
            let _ = mesh.area();
            let _ = mesh.to_obj();
        }
        Err(e) => assert!(!e.to_string().trim().is_empty(), "an empty error"),
    }
}
