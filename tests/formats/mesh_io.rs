//! Mesh readers: OBJ polygons kept, STL (ASCII and binary) merged, bad input refused.

use foldcam::mesh::{MeshError, PolyMesh, parse_obj, parse_stl, read_mesh};
use glam::DVec3;

const CUBE_OBJ: &str = "\
o cube
v 0 0 0
v 2 0 0
v 2 2 0
v 0 2 0
v 0 0 2
v 2 0 2
v 2 2 2
v 0 2 2
vn 0 0 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
";

#[test]
fn obj_keeps_quads_and_reads_geometry() {
    let cube = parse_obj(CUBE_OBJ.as_bytes()).unwrap();
    assert_eq!(cube.positions().len(), 8);
    assert!(cube.faces().iter().all(|f| f.len() == 4));
    assert!((cube.area() - 24.0).abs() < 1e-12);
    assert_eq!(cube.bounds(), (DVec3::ZERO, DVec3::splat(2.0)));
}

#[test]
fn obj_objects_are_concatenated() {
    let text = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\no b\nv 5 0 0\nv 6 0 0\nv 5 1 0\nf 4 5 6\n";
    let mesh = parse_obj(text.as_bytes()).unwrap();
    assert_eq!(mesh.faces().len(), 2);
    let far = &mesh.faces()[1];
    assert!(far.iter().all(|&v| mesh.positions()[v as usize].x >= 5.0));
}

#[test]
fn obj_round_trips_through_the_writer() {
    let cube = parse_obj(CUBE_OBJ.as_bytes()).unwrap();
    let back = parse_obj(cube.to_obj().as_bytes()).unwrap();
    assert_eq!(back, cube);
}

fn stl_triangles(mesh: &PolyMesh) -> Vec<stl_io::Triangle> {
    mesh.triangles()
        .map(|t| stl_io::Triangle {
            normal: stl_io::Normal::new([0.0, 0.0, 0.0]),
            vertices: t.map(|p| stl_io::Vertex::new([p.x as f32, p.y as f32, p.z as f32])),
        })
        .collect()
}

#[test]
fn binary_stl_merges_corners() {
    let cube = parse_obj(CUBE_OBJ.as_bytes()).unwrap();
    let mut bytes = Vec::new();
    stl_io::write_stl(&mut bytes, stl_triangles(&cube).iter()).unwrap();
    let back = parse_stl(&bytes).unwrap();
    assert_eq!(back.faces().len(), 12);
    assert_eq!(back.positions().len(), 8, "shared corners are merged");
    assert!((back.area() - 24.0).abs() < 1e-9);
}

#[test]
fn ascii_stl_reads() {
    let text = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 3 0 0\nvertex 0 4 0\nendloop\nendfacet\nendsolid t\n";
    let mesh = parse_stl(text.as_bytes()).unwrap();
    assert_eq!(mesh.faces().len(), 1);
    assert!((mesh.area() - 6.0).abs() < 1e-12);
}

#[test]
fn bad_meshes_are_refused_with_a_reason() {
    assert_eq!(parse_obj(b"v 0 0 0\n"), Err(MeshError::Empty));
    assert_eq!(
        parse_obj(b"v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"),
        Err(MeshError::NonFinite { vertex: 2 })
    );
    assert!(matches!(
        PolyMesh::new(vec![DVec3::ZERO; 3], vec![vec![0, 1, 7]]),
        Err(MeshError::BadIndex {
            face: 0,
            vertex: 7,
            count: 3
        })
    ));
    assert!(matches!(
        PolyMesh::new(vec![DVec3::ZERO; 3], vec![vec![0, 1]]),
        Err(MeshError::ShortFace {
            face: 0,
            corners: 2
        })
    ));
    assert!(
        parse_obj(b"v 0 0 0\nf 1 2 3\n").is_err(),
        "index past the end"
    );
    assert!(parse_stl(b"solid x\nfacet normal\n").is_err());
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("shape.ply");
    std::fs::write(&path, "ply\n").unwrap();
    assert_eq!(read_mesh(&path), Err(MeshError::UnknownFormat));
    assert!(matches!(
        read_mesh(&dir.path().join("missing.obj")),
        Err(MeshError::Io(_))
    ));
}
