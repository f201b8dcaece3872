//! Sample surfaces for examples, tests and benchmarks: a hexagonal patch of equilateral
//! triangles (edge `l`, `6·rings²` faces) laid onto a dome, a saddle or a bell (the doubly
//! curved shapes of Tachi (2014) Fig. 13), saddles of other curvatures, a sinusoidal height
//! field, a cylinder and a torus; spherical caps triangulated two ways (rings of growing
//! length, [`spherical_cap`]; a UV sphere's latitude rings, [`uv_cap`]); a face mask.

use glam::DVec3;

use crate::mesh::PolyMesh;

/// Smallest cap angle, degrees, [`spherical_cap`] accepts: it keeps the cap open (at 0° every
/// ring would sit on the pole).
const MIN_CAP_DEG: f64 = 1e-3;

/// The shape a sample patch is lifted onto.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SampleSurface {
    /// A spherical cap (positive Gaussian curvature), sphere radius 1.5 × patch radius.
    Dome,
    /// A hyperbolic paraboloid `z = (x² − y²) / (3 ρ)` (negative curvature), ρ the patch radius.
    Saddle,
    /// A Gaussian bell `z = 0.4 ρ exp(−r² / (2 (ρ/2.5)²))` (positive top, negative rim).
    Bell,
    /// A shallower saddle `z = (x² − y²) / (6 ρ)` (a quarter of [`Self::Saddle`]'s Gaussian
    /// curvature).
    ShallowSaddle,
    /// A steeper saddle `z = (x² − y²) / (1.5 ρ)` (four times [`Self::Saddle`]'s).
    SteepSaddle,
    /// A sinusoidal height field `z = 0.06 ρ sin(k x) sin(k y)`, wavelength `2π/k = 1.5 ρ`:
    /// bumps and dips side by side, saddles between them.
    Waves,
    /// A cylinder of radius `1.5 ρ` about the y axis, the patch wrapped round it without
    /// stretching (Gaussian curvature zero).
    Cylinder,
    /// The top of a torus lying flat (tube radius `ρ`, centre circle radius `2 ρ`), the patch
    /// centred on the tube's top circle: positive curvature on the outer side (x > 0),
    /// negative on the inner.
    Torus,
}

/// A hexagonal patch of `6·rings²` triangles of edge `edge` (mesh units) lifted onto
/// `surface`; every interior vertex has valence 6. Faces are counter-clockwise seen from +z.
/// `rings` is clamped to 1..=64.
pub fn sample_surface(surface: SampleSurface, rings: usize, edge: f64) -> PolyMesh {
    let r = rings.clamp(1, 64) as i64;
    let radius = r as f64 * edge;
    let place = |x: f64, y: f64| -> DVec3 {
        let rr = x * x + y * y;
        let height = |z: f64| DVec3::new(x, y, z);
        match surface {
            SampleSurface::Dome => {
                let s = 1.5 * radius;
                height((s * s - rr).max(0.0).sqrt() - s)
            }
            SampleSurface::Saddle => height((x * x - y * y) / (3.0 * radius)),
            SampleSurface::ShallowSaddle => height((x * x - y * y) / (6.0 * radius)),
            SampleSurface::SteepSaddle => height((x * x - y * y) / (1.5 * radius)),
            SampleSurface::Bell => {
                let sigma = radius / 2.5;
                height(0.4 * radius * (-rr / (2.0 * sigma * sigma)).exp())
            }
            SampleSurface::Waves => {
                let k = std::f64::consts::TAU / (1.5 * radius);
                height(0.06 * radius * (k * x).sin() * (k * y).sin())
            }
            SampleSurface::Cylinder => {
                let r = 1.5 * radius;
                let a = x / r;
                DVec3::new(r * a.sin(), y, r * (a.cos() - 1.0))
            }
            SampleSurface::Torus => {
                // x across the tube (arc length from its top), y along the centre circle.
                let (tube, centre) = (radius, 2.0 * radius);
                let (phi, theta) = (x / tube, y / centre);
                let reach = centre + tube * phi.sin();
                DVec3::new(
                    reach * theta.cos() - centre,
                    reach * theta.sin(),
                    tube * (phi.cos() - 1.0),
                )
            }
        }
    };
    let inside = |i: i64, j: i64| i.abs().max(j.abs()).max((i + j).abs()) <= r;
    let mut index = std::collections::HashMap::new();
    let mut positions = Vec::new();
    for j in -r..=r {
        for i in -r..=r {
            if inside(i, j) {
                let x = edge * (i as f64 + 0.5 * j as f64);
                let y = edge * 0.75f64.sqrt() * j as f64;
                index.insert((i, j), positions.len() as u32);
                positions.push(place(x, y));
            }
        }
    }
    let mut faces = Vec::new();
    for j in -r..=r {
        for i in -r..=r {
            let corners = [
                [(i, j), (i + 1, j), (i, j + 1)],
                [(i + 1, j), (i + 1, j + 1), (i, j + 1)],
            ];
            for tri in corners {
                if tri.iter().all(|&(a, b)| inside(a, b)) {
                    faces.push(tri.iter().map(|k| index[k]).collect());
                }
            }
        }
    }
    PolyMesh::new(positions, faces).expect("a sample patch is a valid mesh")
}

/// A spherical cap triangulated the way modelling programs export a geodesic/UV-style
/// sphere: a pole vertex joined to a first ring of `n` vertices, ring `k` (1..=`rings`)
/// with `n·k` vertices at polar angle `k·cap/rings`, so `n·rings²` triangles; every vertex
/// but the pole has valence 6 (interior) and the pole has valence `n`. `radius` is the
/// sphere radius (mesh units), `cap_deg` the polar angle of the rim in degrees (a 60° cap
/// spans 120° of arc). The pole sits at the origin, the cap opens towards −z; faces are
/// counter-clockwise seen from outside. Clamps: `n` to 3..=64, `rings` to 1..=128,
/// `cap_deg` to (0, 180).
pub fn spherical_cap(n: usize, rings: usize, cap_deg: f64, radius: f64) -> PolyMesh {
    let cap = cap_deg.clamp(MIN_CAP_DEG, 179.0).to_radians();
    let (polar, faces) = polar_disk(n, rings);
    let positions = polar
        .iter()
        .map(|&(k, a)| {
            // `cap · k / rings` in this order: the caps' published figures were solved on
            // exactly these positions, and the solves are sensitive to the last bit.
            let phi = cap * k / rings.clamp(1, 128) as f64;
            DVec3::new(
                radius * phi.sin() * a.cos(),
                radius * phi.sin() * a.sin(),
                radius * (phi.cos() - 1.0),
            )
        })
        .collect();
    PolyMesh::new(positions, faces).expect("a spherical cap is a valid mesh")
}

/// A spherical cap as a UV sphere is triangulated (the way most modelling programs make a
/// sphere, and unlike [`spherical_cap`]): a pole joined to the first of `rings` latitude rings
/// of `segments` vertices each, at polar angles `k·cap/rings`, the quads between rings split
/// along one diagonal, so `segments·(2·rings − 1)` triangles, long and thin near the pole and
/// square-ish at the rim. The pole sits at the origin, the cap opens towards −z; faces are
/// counter-clockwise seen from outside. Clamps: `segments` to 3..=256, `rings` to 1..=256,
/// `cap_deg` to (0, 179].
pub fn uv_cap(segments: usize, rings: usize, cap_deg: f64, radius: f64) -> PolyMesh {
    let (n, rings) = (segments.clamp(3, 256), rings.clamp(1, 256));
    let cap = cap_deg.clamp(MIN_CAP_DEG, 179.0).to_radians();
    let mut positions = vec![DVec3::ZERO];
    for k in 1..=rings {
        let phi = cap * k as f64 / rings as f64;
        for i in 0..n {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            positions.push(DVec3::new(
                radius * phi.sin() * a.cos(),
                radius * phi.sin() * a.sin(),
                radius * (phi.cos() - 1.0),
            ));
        }
    }
    // Vertex i of ring k (1-based rings; ring 0 is the pole).
    let at = |k: usize, i: usize| -> u32 {
        if k == 0 {
            0
        } else {
            (1 + (k - 1) * n + i % n) as u32
        }
    };
    let mut faces = Vec::with_capacity(n * (2 * rings - 1));
    for i in 0..n {
        faces.push(vec![at(0, 0), at(1, i), at(1, i + 1)]);
    }
    for k in 1..rings {
        for i in 0..n {
            faces.push(vec![at(k, i), at(k + 1, i), at(k + 1, i + 1)]);
            faces.push(vec![at(k, i), at(k + 1, i + 1), at(k, i + 1)]);
        }
    }
    PolyMesh::new(positions, faces).expect("a UV cap is a valid mesh")
}

/// The connectivity of [`spherical_cap`] on the disk: per vertex its ring number `k` (0 at the
/// pole, `rings` on the rim; the radius is `k / rings`) and its azimuth, radians; and the faces,
/// counter-clockwise seen from +z. Clamps `n` to 3..=64 and `rings` to 1..=128.
fn polar_disk(n: usize, rings: usize) -> (Vec<(f64, f64)>, Vec<Vec<u32>>) {
    let n = n.clamp(3, 64);
    let rings = rings.clamp(1, 128);
    let mut polar = vec![(0.0, 0.0)];
    // First index of ring k (ring 0 is the pole).
    let mut start = vec![0usize];
    for k in 1..=rings {
        start.push(polar.len());
        let count = n * k;
        for i in 0..count {
            let a = 2.0 * std::f64::consts::PI * i as f64 / count as f64;
            polar.push((k as f64, a));
        }
    }
    let at = |k: usize, i: usize| -> u32 {
        if k == 0 {
            0
        } else {
            (start[k] + i % (n * k)) as u32
        }
    };
    let mut faces: Vec<Vec<u32>> = Vec::with_capacity(n * rings * rings);
    for k in 1..=rings {
        for j in 0..n {
            // Sector j: ring k−1 from j(k−1) over k−1 segments, ring k from jk over k.
            let (a0, b0) = (j * (k - 1), j * k);
            for m in 0..k {
                faces.push(vec![at(k, b0 + m), at(k, b0 + m + 1), at(k - 1, a0 + m)]);
                if m + 1 < k {
                    faces.push(vec![
                        at(k - 1, a0 + m),
                        at(k, b0 + m + 1),
                        at(k - 1, a0 + m + 1),
                    ]);
                }
            }
        }
    }
    (polar, faces)
}

/// Half width, half height and depth of [`face_mask`]'s shell, mm: an adult face's front
/// (about 150 × 190 mm; with the features 53 mm from the rim's plane to the nose tip).
pub const MASK_SIZE_MM: [f64; 3] = [75.0, 95.0, 40.0];

/// One raised (or sunken, negative height) feature of [`face_mask`]: a Gaussian bump at
/// `(u, v)` in units of the half width and half height, with standard deviations `(su, sv)`
/// in the same units and `height` in mm; mirrored about the vertical axis when `pair`.
struct Feature {
    u: f64,
    v: f64,
    su: f64,
    sv: f64,
    height: f64,
    pair: bool,
}

/// A [`Feature`] in one line: `(u, v, su, sv, height, pair)`.
const fn feature(u: f64, v: f64, su: f64, sv: f64, height: f64, pair: bool) -> Feature {
    Feature {
        u,
        v,
        su,
        sv,
        height,
        pair,
    }
}

/// The features of [`face_mask`]: nose ridge and tip, brows, eye sockets, cheeks, chin.
const MASK_FEATURES: [Feature; 7] = [
    // Nose bridge: a narrow ridge from between the eyes down to the tip.
    feature(0.0, -0.08, 0.08, 0.2, 8.0, false),
    // Nose tip.
    feature(0.0, -0.3, 0.11, 0.09, 11.0, false),
    // Brows.
    feature(0.34, 0.3, 0.2, 0.07, 5.0, true),
    // Eye sockets.
    feature(0.34, 0.12, 0.12, 0.09, -8.0, true),
    // Cheekbones.
    feature(0.46, -0.22, 0.17, 0.15, 6.0, true),
    // Lips.
    feature(0.0, -0.56, 0.2, 0.07, 3.0, false),
    // Chin.
    feature(0.0, -0.82, 0.18, 0.1, 6.0, false),
];

/// A face-mask-like open surface (Tachi 2014 shows a mask among its examples), our own
/// procedural model: an elliptic shell of half width, half height and depth [`MASK_SIZE_MM`]
/// seen from +z (the face looks up the z axis, the top of the head towards +y), with a nose
/// ridge and tip, brows, eye sockets, cheekbones, mouth area and chin as Gaussian bumps; no
/// eye holes (a disk with one boundary). Triangulated as a modelling program fills a disk:
/// the connectivity of [`spherical_cap`] with `n = 6` (every vertex valence 6), `6·rings²`
/// faces, ring `k` on the ellipse of `k / rings` of the outline. The shell is the elliptic
/// paraboloid `depth · (1 − r²)`, `r` the outline's normalized radius. `rings` is clamped to
/// 1..=128.
pub fn face_mask(rings: usize) -> PolyMesh {
    let [a, b, depth] = MASK_SIZE_MM;
    let (polar, faces) = polar_disk(6, rings);
    let bump = |u: f64, v: f64, f: &Feature| {
        let g = |u: f64| {
            let (du, dv) = ((u - f.u) / f.su, (v - f.v) / f.sv);
            f.height * (-0.5 * (du * du + dv * dv)).exp()
        };
        if f.pair { g(u) + g(-u) } else { g(u) }
    };
    let positions = polar
        .iter()
        .map(|&(k, angle)| {
            let r = k / rings.clamp(1, 128) as f64;
            let (u, v) = (r * angle.cos(), r * angle.sin());
            let shell = depth * (1.0 - r * r);
            // The features fade out towards the rim so the outline stays a plane curve.
            let fade = 1.0 - r.powi(4);
            let z = shell + fade * MASK_FEATURES.iter().map(|f| bump(u, v, f)).sum::<f64>();
            DVec3::new(a * u, b * v, z)
        })
        .collect();
    PolyMesh::new(positions, faces).expect("a face mask is a valid mesh")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::HalfEdgeMesh;

    #[test]
    fn spherical_cap_is_a_disk_with_the_published_counts() {
        for (n, rings) in [(6, 3), (12, 6), (7, 4)] {
            let mesh = spherical_cap(n, rings, 60.0, 100.0);
            // Faces n·K², vertices 1 + n·K(K+1)/2, all on the sphere of radius 100 about
            // (0, 0, −100).
            assert_eq!(mesh.faces().len(), n * rings * rings);
            assert_eq!(mesh.positions().len(), 1 + n * rings * (rings + 1) / 2);
            for p in mesh.positions() {
                assert!((p.distance(DVec3::new(0.0, 0.0, -100.0)) - 100.0).abs() < 1e-9);
            }
            let he = HalfEdgeMesh::new(&mesh, 1e-9).expect("manifold");
            assert_eq!(he.fan(0).len(), n, "pole valence");
            for v in 1..mesh.positions().len() {
                if !he.is_boundary(v) {
                    assert_eq!(he.fan(v).len(), 6, "vertex {v}");
                }
            }
            // Outward normals: every face's normal points away from the sphere's centre.
            for f in 0..mesh.faces().len() {
                let c = he.face_centroid(f);
                let [a, b, d] = [0, 1, 2].map(|k| mesh.positions()[mesh.faces()[f][k] as usize]);
                let normal = (b - a).cross(d - a);
                assert!(
                    normal.dot(c - DVec3::new(0.0, 0.0, -100.0)) > 0.0,
                    "face {f}"
                );
            }
        }
    }
}
