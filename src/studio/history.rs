//! The versions an open document or editor session keeps for undo and redo, within a count
//! and a byte budget ([`STUDIO_UNDO_VERSIONS`], [`STUDIO_UNDO_BYTES`]): the oldest earlier
//! versions are forgotten first, the shown one never. With the studio's session limits this
//! bounds what a page left open can make the server hold (see `crate::limits`).

use std::mem::size_of;
use std::sync::Arc;

use glam::{DVec2, DVec3};

use super::api::{ApiError, ApiResult};
use super::document::Document;
use crate::design::papercraft::sketch::Sketch;
use crate::design::popup::polygon::Design;
use crate::design::popup::voxel::VoxelCard;
use crate::limits::{STUDIO_UNDO_BYTES, STUDIO_UNDO_VERSIONS};
use crate::pattern::{CreasePattern, Edge, Face, VertexId};

/// About how many bytes a version holds (its largest arrays; small fields left out).
pub(super) trait Footprint {
    /// Bytes, an estimate from the lengths of the version's arrays.
    fn footprint(&self) -> usize;
}

/// Versions of one thing edited, the first the one opened; `at` is the one shown.
#[derive(Debug)]
pub(super) struct Versions<T> {
    versions: Vec<(T, usize)>,
    at: usize,
    /// Bytes of the versions other than the shown one.
    earlier_bytes: usize,
    /// Most versions kept, the shown one included.
    max_versions: usize,
    /// Most bytes of versions other than the shown one.
    max_bytes: usize,
}

impl<T: Footprint> Versions<T> {
    /// One version, `first`, within the studio's limits.
    pub(super) fn new(first: T) -> Versions<T> {
        Versions::with_limits(first, STUDIO_UNDO_VERSIONS, STUDIO_UNDO_BYTES)
    }

    fn with_limits(first: T, max_versions: usize, max_bytes: usize) -> Versions<T> {
        let bytes = first.footprint();
        Versions {
            versions: vec![(first, bytes)],
            at: 0,
            earlier_bytes: 0,
            max_versions: max_versions.max(1),
            max_bytes,
        }
    }

    /// The version shown.
    pub(super) fn current(&self) -> &T {
        &self.versions[self.at].0
    }

    /// Whether there is a version to undo to.
    pub(super) fn can_undo(&self) -> bool {
        self.at > 0
    }

    /// Whether there is a version to redo.
    pub(super) fn can_redo(&self) -> bool {
        self.at + 1 < self.versions.len()
    }

    /// Shows `next` after the current version; undone versions are dropped, then the oldest
    /// beyond the count or the byte budget.
    pub(super) fn push(&mut self, next: T) {
        for (_, bytes) in self.versions.drain(self.at + 1..) {
            self.earlier_bytes -= bytes;
        }
        let bytes = next.footprint();
        self.earlier_bytes += self.versions[self.at].1;
        self.versions.push((next, bytes));
        self.at = self.versions.len() - 1;
        while self.versions.len() > 1
            && (self.versions.len() > self.max_versions || self.earlier_bytes > self.max_bytes)
        {
            let (_, oldest) = self.versions.remove(0);
            self.earlier_bytes -= oldest;
            self.at -= 1;
        }
    }

    /// Shows the version before the current one.
    ///
    /// # Errors
    /// "nothing to undo" (422) at the first version kept.
    pub(super) fn undo(&mut self) -> ApiResult<&T> {
        if !self.can_undo() {
            return Err(ApiError::input("nothing to undo".into()));
        }
        self.move_to(self.at - 1);
        Ok(self.current())
    }

    /// Shows the version after the current one.
    ///
    /// # Errors
    /// "nothing to redo" (422) at the last version.
    pub(super) fn redo(&mut self) -> ApiResult<&T> {
        if !self.can_redo() {
            return Err(ApiError::input("nothing to redo".into()));
        }
        self.move_to(self.at + 1);
        Ok(self.current())
    }

    fn move_to(&mut self, at: usize) {
        self.earlier_bytes = self.earlier_bytes + self.versions[self.at].1 - self.versions[at].1;
        self.at = at;
    }
}

fn pattern_bytes(cp: &CreasePattern) -> usize {
    let faces: usize = cp
        .faces
        .iter()
        .flatten()
        .map(|f| {
            let corners = f.outer.len() + f.holes.iter().map(Vec::len).sum::<usize>();
            size_of::<Face>() + corners * size_of::<VertexId>()
        })
        .sum();
    cp.vertices.len() * size_of::<DVec2>() + cp.edges.len() * size_of::<Edge>() + faces
}

impl Footprint for Arc<Document> {
    /// The pattern twice: as read, and as cleaned for snapping.
    fn footprint(&self) -> usize {
        2 * pattern_bytes(&self.imported.pattern)
    }
}

impl Footprint for VoxelCard {
    /// A depth (`u16`) and two flags per row of cells.
    fn footprint(&self) -> usize {
        self.nx() * self.nz() * (size_of::<u16>() + 2 * size_of::<bool>())
    }
}

impl Footprint for Design {
    fn footprint(&self) -> usize {
        self.operations.len() * size_of::<crate::design::popup::polygon::Operation>()
    }
}

impl Footprint for Sketch {
    fn footprint(&self) -> usize {
        let points: usize = self.lines.iter().map(Vec::len).sum();
        points * size_of::<DVec3>() + self.placed.len() * 1024
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    impl Footprint for Vec<u8> {
        fn footprint(&self) -> usize {
            self.len()
        }
    }

    fn pushed(sizes: &[usize], max_versions: usize, max_bytes: usize) -> Versions<Vec<u8>> {
        let mut v = Versions::with_limits(vec![0; sizes[0]], max_versions, max_bytes);
        for &n in &sizes[1..] {
            v.push(vec![1; n]);
        }
        v
    }

    fn undo_all(v: &mut Versions<Vec<u8>>) -> Vec<usize> {
        let mut seen = vec![v.current().len()];
        while let Ok(x) = v.undo() {
            seen.push(x.len());
        }
        seen
    }

    #[test]
    fn the_oldest_versions_go_first_beyond_the_count() {
        let mut v = pushed(&[1, 2, 3, 4, 5], 3, usize::MAX);
        assert_eq!(undo_all(&mut v), vec![5, 4, 3]);
        assert_eq!(v.undo().unwrap_err().message(), "nothing to undo");
    }

    #[test]
    fn earlier_versions_stay_within_the_byte_budget_and_the_shown_one_is_kept() {
        // 100 bytes of earlier versions at most: 40 + 50 fit, 30 more do not.
        let mut v = pushed(&[30, 50, 40, 1000], 10, 100);
        assert_eq!(v.current().len(), 1000);
        assert!(v.earlier_bytes <= 100, "{}", v.earlier_bytes);
        assert_eq!(undo_all(&mut v), vec![1000, 40, 50]);
        // A version larger than the budget is still shown.
        let v = pushed(&[10, 500], 10, 100);
        assert_eq!(v.current().len(), 500);
    }

    #[test]
    fn a_new_version_drops_the_undone_ones_and_the_bytes_follow_the_shown_version() {
        let mut v = pushed(&[1, 2, 3], 10, usize::MAX);
        v.undo().unwrap();
        v.undo().unwrap();
        assert_eq!(v.earlier_bytes, 2 + 3);
        assert_eq!(v.redo().unwrap().len(), 2);
        v.push(vec![7; 7]);
        assert!(!v.can_redo());
        assert_eq!(v.earlier_bytes, 1 + 2);
        assert_eq!(undo_all(&mut v), vec![7, 2, 1]);
        assert_eq!(v.redo().unwrap().len(), 2);
    }

    /// What `STUDIO_UNDO_BYTES` and the README state: the undo history of every document and
    /// editor session the studio keeps open at once stays under 2.2 GB.
    #[test]
    fn the_stated_bound_on_all_undo_history_holds() {
        use crate::studio::{MAX_DOCUMENTS, craft_api, popup_api, voxel_api};
        let sessions = MAX_DOCUMENTS
            + voxel_api::MAX_VOXEL_SESSIONS
            + popup_api::MAX_POPUP_SESSIONS
            + craft_api::MAX_CRAFT_SESSIONS;
        assert_eq!(sessions, 32 + 40);
        assert!(sessions * STUDIO_UNDO_BYTES <= 2_200_000_000);
    }
}
