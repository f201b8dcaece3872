//! Axis-aligned rectangles: the bounding boxes every stage needs (pattern extent, toolpath
//! extent, preview framing, packing).

use glam::DVec2;

/// An axis-aligned rectangle `[min.x, max.x] × [min.y, max.y]`, in the caller's units.
/// [`Rect::EMPTY`] (min +∞, max −∞) holds nothing and is the identity of [`Rect::union`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Lower-left corner.
    pub min: DVec2,
    /// Upper-right corner.
    pub max: DVec2,
}

impl Rect {
    /// The empty rectangle: [`Rect::include`] of any point gives that point.
    pub const EMPTY: Rect = Rect {
        min: DVec2::splat(f64::INFINITY),
        max: DVec2::splat(f64::NEG_INFINITY),
    };

    /// The smallest rectangle holding every point; `None` when there is none.
    ///
    /// ```
    /// use foldcam::geom::{DVec2, Rect};
    /// let r = Rect::of([DVec2::new(1.0, 5.0), DVec2::new(-2.0, 3.0)]).unwrap();
    /// assert_eq!((r.min, r.max), (DVec2::new(-2.0, 3.0), DVec2::new(1.0, 5.0)));
    /// assert_eq!(r.size(), DVec2::new(3.0, 2.0));
    /// assert!(Rect::of(std::iter::empty()).is_none());
    /// ```
    pub fn of(points: impl IntoIterator<Item = DVec2>) -> Option<Rect> {
        let r = Rect::covering(points);
        (!r.is_empty()).then_some(r)
    }

    /// The smallest rectangle holding every point, [`Rect::EMPTY`] when there is none.
    pub fn covering(points: impl IntoIterator<Item = DVec2>) -> Rect {
        points.into_iter().fold(Rect::EMPTY, Rect::include)
    }

    /// This rectangle grown to hold `p`.
    pub fn include(self, p: DVec2) -> Rect {
        Rect {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// The smallest rectangle holding both.
    pub fn union(self, other: Rect) -> Rect {
        Rect {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// Holds no point (some min above its max).
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y
    }

    /// Width and height.
    pub fn size(&self) -> DVec2 {
        self.max - self.min
    }

    /// `(min, max)`, the form older code passes around.
    pub fn corners(self) -> (DVec2, DVec2) {
        (self.min, self.max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn union_with_the_empty_rectangle_changes_nothing() {
        let r = Rect::of([DVec2::new(0.5, -1.0), DVec2::new(2.0, 4.0)]).unwrap();
        assert_eq!(r.union(Rect::EMPTY), r);
        assert_eq!(Rect::EMPTY.union(r), r);
        assert!(Rect::EMPTY.is_empty() && !r.is_empty());
    }
}
