//! `plan()` end to end on the Miura-ori with the shipped machine and material profiles.

use super::*;
use foldcam::design::classic::MiuraOri;
use foldcam::fab::{plan, toolpaths};
use foldcam::machine::{load_machine, load_material, shipped_machines, shipped_materials};

/// The edges of `paths`, sorted (a multiset).
fn edge_multiset<'a>(paths: impl Iterator<Item = &'a Toolpath>) -> Vec<EdgeId> {
    let mut e: Vec<EdgeId> = paths.flat_map(|p| p.edges.iter().copied()).collect();
    e.sort_unstable();
    e
}

#[test]
fn miura_plans_with_every_shipped_profile() {
    let cp = MiuraOri::default().build().unwrap();
    for machine_name in shipped_machines() {
        let mut m = load_machine(machine_name).unwrap();
        for material_name in shipped_materials() {
            let mat = load_material(material_name).unwrap();
            for two_sided in [false, true] {
                for origin in CORNERS {
                    m.bed.origin = origin;
                    m.bed.y_flipped = matches!(origin, Corner::TopLeft | Corner::TopRight);
                    let mut opts = PlanOptions::from_material(&mat);
                    opts.two_sided = two_sided;
                    let case = format!("{machine_name} {material_name} {two_sided} {origin:?}");
                    let p = plan(&cp, &m, &mat, &opts).unwrap_or_else(|e| panic!("{case}: {e}"));
                    // Nothing lost or duplicated between the geometry and the jobs.
                    let given = toolpaths(&cp, &opts).unwrap();
                    let planned = p.jobs.iter().flat_map(|j| &j.paths);
                    assert_eq!(
                        edge_multiset(given.iter()),
                        edge_multiset(planned),
                        "{case}"
                    );
                    for job in &p.jobs {
                        let pts = all_points(&job.paths);
                        assert!(pts.iter().all(|&q| inside_bed(q, &m.bed)), "{case}");
                    }
                    // Outer contours are the last thing the last job does.
                    let last = &p.jobs.last().unwrap().paths;
                    let outer = last.iter().position(|q| q.role == ContourRole::Outer);
                    if let Some(first_outer) = outer {
                        assert!(
                            last[first_outer..]
                                .iter()
                                .all(|q| q.role == ContourRole::Outer)
                        );
                    }
                    assert!(p.stats.travel_mm <= p.stats.naive_travel_mm, "{case}");
                    assert!(p.stats.time_s > 0.0 && p.stats.pierces > 0, "{case}");
                }
            }
        }
    }
}

#[test]
fn miura_outline_is_one_closed_contour_started_near_the_previous_work() {
    let cp = MiuraOri::default().build().unwrap();
    let m = load_machine("grbl-diode").unwrap();
    let mat = load_material("card-300gsm").unwrap();
    let p = plan(&cp, &m, &mat, &PlanOptions::from_material(&mat)).unwrap();
    let job = &p.jobs[0];
    let outer: Vec<&Toolpath> = job
        .paths
        .iter()
        .filter(|q| q.role == ContourRole::Outer)
        .collect();
    assert_eq!(outer.len(), 1);
    let ring = &outer[0].strokes[0];
    assert!(
        ring[0].distance(ring[ring.len() - 1]) < 1e-9,
        "a closed ring"
    );
    // Entered at the ring vertex nearest to where the previous toolpath ended.
    let before = &job.paths[job.paths.len() - 2];
    let from = *before.strokes.last().unwrap().last().unwrap();
    let nearest = ring
        .iter()
        .map(|v| v.distance(from))
        .fold(f64::INFINITY, f64::min);
    assert!((ring[0].distance(from) - nearest).abs() < 1e-9);
}
