//! Joining consecutive toolpaths that continue each other.
//!
//! When a toolpath ends where the next one starts, with the same operation, both plain lines
//! (role `None` or `Slit`, no container), the second is appended to the first and its first
//! stroke merged with the first's last stroke: one pierce less and no stop at the joint.
//! O(total points).

use super::visit::SAME_POINT_MM;
use crate::fab::{ContourRole, Toolpath};

/// Whether `b` may be appended to `a`.
fn continues(a: &Toolpath, b: &Toolpath) -> bool {
    let plain = |p: &Toolpath| {
        matches!(p.role, ContourRole::None | ContourRole::Slit) && p.container.is_none()
    };
    let end = a.strokes.last().and_then(|s| s.last());
    let start = b.strokes.first().and_then(|s| s.first());
    a.op == b.op
        && a.role == b.role
        && plain(a)
        && plain(b)
        && matches!((end, start), (Some(e), Some(s)) if e.distance(*s) <= SAME_POINT_MM)
}

/// Appends `b` to `a` (which [`continues`] allows).
fn append(a: &mut Toolpath, b: Toolpath) {
    let mut strokes = b.strokes.into_iter();
    if let (Some(last), Some(first)) = (a.strokes.last_mut(), strokes.next()) {
        last.extend(first.into_iter().skip(1));
    }
    a.strokes.extend(strokes);
    a.edges.extend(b.edges);
}

/// Joins continuing neighbours of `paths`. Returns the joined list and, for every input
/// position, the position of the toolpath that now holds it.
pub(super) fn join(paths: Vec<Toolpath>) -> (Vec<Toolpath>, Vec<usize>) {
    let mut out: Vec<Toolpath> = Vec::with_capacity(paths.len());
    let mut holder = Vec::with_capacity(paths.len());
    for p in paths {
        match out.last_mut() {
            Some(last) if continues(last, &p) => append(last, p),
            _ => out.push(p),
        }
        holder.push(out.len() - 1);
    }
    (out, holder)
}
