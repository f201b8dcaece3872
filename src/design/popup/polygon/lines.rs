//! Line types of the pattern (Mitani & Suzuki 2004, §3.4, Fig. 10).
//!
//! Every face piece (one shape of a face's polygon) is walked along its contours; the piece lies
//! on the left of each contour segment. A segment not parallel to x is a cut, since the card
//! opens about x and such a line can never fold. Segments parallel to x are gathered per
//! pattern line v; every segment on a line is split at the end points of all others on that
//! line (Fig. 10 b), so the pieces above and below each elementary interval are known exactly
//! (the grid is integer). The interval's type then follows from the 3D relation of the two
//! faces along it (eq. 2, 3 at that v):
//! - they do not meet in 3D: cut;
//! - a VFace above an HFace meeting on the same card line: valley (concave, 90°);
//! - an HFace above a VFace meeting on the same card line: mountain (convex, 270°);
//! - both on the same plane: no line (flat paper).
//!
//! Addition to the paper: a non-x-parallel segment shared exactly by two pieces on the same
//! plane (two coplanar faces drawn side by side) is flat paper, not a cut.

use std::collections::{BTreeMap, HashMap};

use super::model::{FaceKind, Plane, Point, PolygonCard};

/// One piece of a face: shape `shape` of face `face`'s polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PieceId {
    /// Face index in [`PolygonCard::faces`].
    pub face: usize,
    /// Shape index in that face's polygon.
    pub shape: usize,
}

/// The type of a pattern line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LineKind {
    /// Fold with the upper piece vertical and the lower horizontal (+90° at 90°).
    Valley,
    /// Fold with the upper piece horizontal and the lower vertical (−90° at 90°).
    Mountain,
    /// The pieces separate.
    Cut,
    /// Both pieces on one plane: no line.
    Flat,
}

/// A line of the pattern between grid points `a` and `b` (grid units).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PatternLine {
    /// One end.
    pub a: Point,
    /// The other end.
    pub b: Point,
    /// Its type (never [`LineKind::Flat`] in [`Lines::lines`]).
    pub kind: LineKind,
}

/// Two pieces sharing part of a line: `upper` on the +v side for x-parallel lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Link {
    /// The piece above (for a slanted flat join: either one).
    pub upper: PieceId,
    /// The piece below.
    pub lower: PieceId,
    /// The type of the shared line.
    pub kind: LineKind,
}

/// The classified lines of a card.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Lines {
    /// Cuts and folds inside the sheet (the outline is left out), x-parallel runs merged.
    pub lines: Vec<PatternLine>,
    /// Every pair of pieces sharing a line, once per elementary interval.
    pub links: Vec<Link>,
}

/// An x-parallel segment on one pattern line: `[x0, x1]`, the piece and whether it lies above.
struct Run {
    x0: i32,
    x1: i32,
    piece: PieceId,
    above: bool,
}

/// Classifies every contour segment of `card` (see the module docs).
pub fn classify(card: &PolygonCard) -> Lines {
    let mut rows: BTreeMap<i32, Vec<Run>> = BTreeMap::new();
    let mut slanted: HashMap<(Point, Point), Vec<PieceId>> = HashMap::new();
    for (face, f) in card.faces().iter().enumerate() {
        for (shape, contours) in f.polygon.iter().enumerate() {
            let piece = PieceId { face, shape };
            for c in contours {
                for i in 0..c.len() {
                    let (a, b) = (c[i], c[(i + 1) % c.len()]);
                    if a.y == b.y && a.x != b.x {
                        let above = b.x > a.x;
                        let (x0, x1) = (a.x.min(b.x), a.x.max(b.x));
                        let run = Run {
                            x0,
                            x1,
                            piece,
                            above,
                        };
                        rows.entry(a.y).or_default().push(run);
                    } else if a != b {
                        let key = if (a.x, a.y) < (b.x, b.y) {
                            (a, b)
                        } else {
                            (b, a)
                        };
                        slanted.entry(key).or_default().push(piece);
                    }
                }
            }
        }
    }
    let plane = |p: PieceId| card.faces()[p.face].plane;
    let [lo, _, hi, _] = card.sheet();
    let mut out = Lines::default();
    for (&v, runs) in &rows {
        let on_outline = v == lo.y || v == hi.y;
        row_lines(v, runs, on_outline, &plane, &mut out);
    }
    let mut keys: Vec<_> = slanted.into_iter().collect();
    keys.sort_by_key(|((a, b), _)| (a.x, a.y, b.x, b.y));
    for ((a, b), pieces) in keys {
        let flat = pieces.len() == 2 && plane(pieces[0]) == plane(pieces[1]);
        if flat {
            out.links.push(Link {
                upper: pieces[0],
                lower: pieces[1],
                kind: LineKind::Flat,
            });
        } else if !(a.x == b.x && (a.x == lo.x || a.x == hi.x)) {
            let kind = LineKind::Cut;
            out.lines.push(PatternLine { a, b, kind });
        }
    }
    out
}

/// Splits the runs of line v at each other's end points (Fig. 10) and classifies every
/// elementary interval; consecutive intervals of one type are merged into one line.
fn row_lines(
    v: i32,
    runs: &[Run],
    on_outline: bool,
    plane: &impl Fn(PieceId) -> Plane,
    out: &mut Lines,
) {
    let mut cuts: Vec<i32> = runs.iter().flat_map(|r| [r.x0, r.x1]).collect();
    cuts.sort_unstable();
    cuts.dedup();
    // sides[k] = (piece above, piece below) of interval [cuts[k], cuts[k + 1]].
    let mut sides: Vec<[Option<PieceId>; 2]> = vec![[None, None]; cuts.len().saturating_sub(1)];
    for r in runs {
        let start = cuts.partition_point(|&x| x < r.x0);
        let end = cuts.partition_point(|&x| x < r.x1);
        for side in &mut sides[start..end] {
            side[usize::from(!r.above)] = Some(r.piece);
        }
    }
    let mut current: Option<(LineKind, i32)> = None;
    for (k, side) in sides.iter().enumerate() {
        let kind = match *side {
            [Some(up), Some(down)] => {
                let kind = relation(plane(up), plane(down), v);
                out.links.push(Link {
                    upper: up,
                    lower: down,
                    kind,
                });
                Some(kind).filter(|&k| k != LineKind::Flat)
            }
            [None, None] => None,
            _ if on_outline => None,
            _ => Some(LineKind::Cut),
        };
        let same = matches!((current, kind), (Some((c, _)), Some(n)) if c == n);
        if !same {
            if let Some((c, x0)) = current {
                push_row(out, v, x0, cuts[k], c);
            }
            current = kind.map(|n| (n, cuts[k]));
        }
    }
    if let Some((c, x0)) = current {
        push_row(out, v, x0, cuts[cuts.len() - 1], c);
    }
}

fn push_row(out: &mut Lines, v: i32, x0: i32, x1: i32, kind: LineKind) {
    out.lines.push(PatternLine {
        a: Point::new(x0, v),
        b: Point::new(x1, v),
        kind,
    });
}

/// The line between `upper` (above pattern line v) and `lower` (below it): §3.4.
pub fn relation(upper: Plane, lower: Plane, v: i32) -> LineKind {
    if upper == lower {
        return LineKind::Flat;
    }
    if upper.line_at(v) != lower.line_at(v) {
        return LineKind::Cut;
    }
    match (upper.kind, lower.kind) {
        (FaceKind::Vertical, FaceKind::Horizontal) => LineKind::Valley,
        (FaceKind::Horizontal, FaceKind::Vertical) => LineKind::Mountain,
        // Same kind on the same card line means the same plane, handled above.
        _ => LineKind::Flat,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MM: i32 = 10_000;

    fn v(t: i32) -> Plane {
        Plane {
            kind: FaceKind::Vertical,
            t: t * MM,
        }
    }

    fn h(t: i32) -> Plane {
        Plane {
            kind: FaceKind::Horizontal,
            t: t * MM,
        }
    }

    #[test]
    fn relations_follow_eq_2_and_3() {
        // Back sheet over the base on the central fold: valley.
        assert_eq!(relation(Plane::BACK, Plane::BASE, 0), LineKind::Valley);
        // The back sheet over a roof at z = 30 meets it on the card line (y 0, z 30) at v = 30.
        assert_eq!(relation(Plane::BACK, h(30), 30 * MM), LineKind::Valley);
        assert_eq!(relation(Plane::BACK, h(30), 20 * MM), LineKind::Cut);
        // A roof at z = 30 over a wall at y = 30 meets it on (30, 30) at v = 0: mountain.
        assert_eq!(relation(h(30), v(30), 0), LineKind::Mountain);
        assert_eq!(relation(h(30), v(20), 0), LineKind::Cut);
        // Two walls never fold; the same plane is flat paper.
        assert_eq!(relation(v(30), v(20), 0), LineKind::Cut);
        assert_eq!(relation(v(30), v(30), 5 * MM), LineKind::Flat);
    }
}
