use foldcam::design::tessellation::rigid::*;
use foldcam::pattern::{Assignment, CreasePattern, Face, VertexId};
use glam::DVec2;

fn vertex4(deg: [f64; 4]) -> CreasePattern {
    let mut cp = CreasePattern::new();
    let c = cp.add_vertex(DVec2::ZERO);
    let tips: Vec<VertexId> = deg
        .iter()
        .map(|d| cp.add_vertex(DVec2::from_angle(d.to_radians()) * 10.0))
        .collect();
    for &t in &tips {
        cp.add_edge(c, t, Assignment::Valley);
    }
    for k in 0..4 {
        cp.add_edge(tips[k], tips[(k + 1) % 4], Assignment::Boundary);
    }
    cp.faces = Some(
        (0..4)
            .map(|k| Face::simple(vec![c, tips[k], tips[(k + 1) % 4]]))
            .collect(),
    );
    cp
}

#[test]
fn scratch() {
    let cp = vertex4([0.0, 70.0, 130.0, 240.0]);
    let m = RigidModel::new(&cp).unwrap();
    println!("creases {:?}", m.crease_edges());
    let (a, b) = (70f64.to_radians(), 60f64.to_radians());
    let ks = [
        ("cos", ((a + b) / 2.0).cos() / ((a - b) / 2.0).cos()),
        ("sin", ((a + b) / 2.0).sin() / ((a - b) / 2.0).sin()),
        ("icos", ((a - b) / 2.0).cos() / ((a + b) / 2.0).cos()),
        ("isin", ((a - b) / 2.0).sin() / ((a + b) / 2.0).sin()),
    ];
    let ra = 1.0f64;
    for (name, k) in ks {
        let rb = 2.0 * (k * (ra / 2.0).tan()).atan();
        for pair in 0..2 {
            for s in [1.0, -1.0] {
                let mut rho = vec![0.0; 4];
                rho[pair] = ra;
                rho[pair + 2] = ra;
                rho[1 - pair] = s * rb;
                rho[3 - pair] = -s * rb;
                println!("{name} pair {pair} s {s}: {:.3e}", m.closure_error(&rho));
            }
        }
    }
}
#[test]
fn scratch2() {
    let cp = vertex4([0.0, 70.0, 130.0, 240.0]);
    let m = RigidModel::new(&cp).unwrap();
    for t in [
        [1.0, 0.5, 1.0, -0.5],
        [0.5, 1.0, -0.5, 1.0],
        [1.0, -0.5, 1.0, 0.5],
        [-0.5, 1.0, 0.5, 1.0],
    ] {
        let r = simulate(&m, &t, &RigidOptions::default(), |_, _| {}).unwrap();
        println!("{:?} -> {:?} {}", t, r.angles, r.summary());
    }
}
