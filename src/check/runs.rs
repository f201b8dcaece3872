//! The "which checks ran, and why" part of a report ([`super::applies::CheckRun`]).

use super::CheckOptions;
use super::applies::CheckRun;
use super::developability::{DEVELOPABLE_RELATIVE_TOLERANCE, Developability};
use super::vertex::Tally;
use crate::pattern::CreasePattern;

/// One [`CheckRun`] per family, in report order.
pub(super) fn describe(
    cp: &CreasePattern,
    opts: &CheckOptions,
    vertices: &Tally,
    develop: Option<&Developability>,
) -> Vec<CheckRun> {
    let creases = cp.edges.iter().filter(|e| e.assignment.may_fold()).count();
    vec![
        flat_foldability(opts, vertices),
        developability(vertices, develop),
        match opts.min_vertex_angle_deg {
            Some(l) => CheckRun::ran(
                "vertex_angle",
                cp.vertices.len(),
                format!(
                    "neighbouring creases at least {l}° apart at every vertex (a fabrication limit)"
                ),
            ),
            None => CheckRun::skipped(
                "vertex_angle",
                "no limit given; the smallest angle is reported",
            ),
        },
        match opts.max_fold_angle_deg {
            Some(l) => CheckRun::ran(
                "fold_angle",
                creases,
                format!(
                    "every crease folds by at most {l}° (a fabrication limit; creases without a \
                     stored angle count as 180°)"
                ),
            ),
            None => CheckRun::skipped(
                "fold_angle",
                "no limit given; the largest angle is reported",
            ),
        },
        match opts.min_edge_length {
            Some(l) => CheckRun::ran(
                "edge_length",
                cp.edges.len(),
                format!("every edge at least {l} long"),
            ),
            None => CheckRun::skipped(
                "edge_length",
                "no limit given; the shortest edge is reported",
            ),
        },
    ]
}

fn flat_foldability(opts: &CheckOptions, v: &Tally) -> CheckRun {
    const NAME: &str = "flat_foldability";
    if !opts.flat_foldability {
        return CheckRun::skipped(NAME, "turned off");
    }
    let skipped_3d = if v.vertices_3d > 0 {
        format!(
            "; not applied at {} vertices where a crease folds to less than 180° (a 3D target: \
             Kawasaki and Maekawa describe folding flat){}",
            v.vertices_3d,
            flat_anyway(v)
        )
    } else {
        String::new()
    };
    if v.checked == 0 && v.vertices_3d > 0 {
        return CheckRun::skipped(
            NAME,
            format!(
                "all {} interior vertices have a crease folding to less than 180°: a 3D target, \
                 which Kawasaki and Maekawa (folding flat) do not describe{}",
                v.vertices_3d,
                flat_anyway(v)
            ),
        );
    }
    CheckRun::ran(
        NAME,
        v.checked,
        format!(
            "Kawasaki and Maekawa at {} interior vertices whose creases all fold flat (±180° or \
             no stored angle); Maekawa skipped at {} with unassigned creases{skipped_3d}",
            v.checked, v.maekawa_skipped
        ),
    )
}

/// `; at N of them the creases satisfy both all the same (…)`, or nothing.
fn flat_anyway(v: &Tally) -> String {
    match v.vertices_3d_flat {
        0 => String::new(),
        n => format!(
            "; at {n} of them the creases satisfy both all the same (they would fold flat; \
             whether they reach the 3D form is not checked without a 3D frame)"
        ),
    }
}

fn developability(v: &Tally, develop: Option<&Developability>) -> CheckRun {
    const NAME: &str = "developability";
    match develop {
        Some(d) => CheckRun::ran(
            NAME,
            d.faces,
            format!(
                "the 3D frame's {} faces keep their flat shape within {:.0e} of their size \
                 (largest change {:.1e})",
                d.faces, DEVELOPABLE_RELATIVE_TOLERANCE, d.largest_error
            ),
        ),
        None if v.vertices_3d > 0 => CheckRun::skipped(
            NAME,
            "the pattern folds to a 3D target but comes without a 3D frame to compare (SVG and \
             .cp carry none; a FOLD file may)",
        ),
        None => CheckRun::skipped(NAME, "no 3D frame"),
    }
}
