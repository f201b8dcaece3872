//! Variables and constraints of the layer-order problem, as Flat-Folder states them (Ku,
//! Flat-Folder; Akitaya, Demaine & Ku 2023):
//!
//! - a **variable** for every pair of faces that cover a common cell: which of the two is
//!   above;
//! - **taco-taco**: two folded creases along one segment, all four faces on the same side: the
//!   two folds must not interleave (16 of the 64 assignments of the six face pairs are valid);
//! - **taco-tortilla**: a folded crease along a segment that crosses the interior of a third
//!   face (or lies along an unfolded F line whose face on the crease's side is the third face):
//!   the third face is not between the crease's two faces (4 of 8);
//! - **tortilla-tortilla**: two unfolded F lines along one segment, `f1`, `f2` on one side and
//!   `g1`, `g2` on the other: `f1` is above `f2` exactly when `g1` is above `g2` (2 of 4); the
//!   same holds for an F line and a face across it (`f2 = g2`): the face cannot pass between
//!   the two sides of the line;
//! - **transitivity**: three faces covering a common cell are not stacked in a cycle (6 of 8).
//!
//! A mountain or valley crease also fixes its own pair: with the face `f` on one side placed
//! front up, a valley puts the other face above `f` (the front sides meet), a mountain below.

use std::collections::HashSet;

use super::LayerError;
use super::cells::Arrangement;
use super::folded::FoldedFaces;
use crate::clock::Deadline;
use crate::pattern::{Assignment, CreasePattern};

/// The four kinds of constraint, in report order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Two folded creases on the same side of a segment.
    TacoTaco = 0,
    /// A folded crease and a face across it.
    TacoTortilla = 1,
    /// Two unfolded lines along one segment.
    TortillaTortilla = 2,
    /// Three faces covering one cell.
    Transitivity = 3,
}

/// Where a constraint comes from, in the arrangement.
#[derive(Clone, Copy, Debug)]
pub enum Place {
    /// A cell that all the constraint's faces cover (transitivity; found when needed).
    Common,
    /// A segment (the others).
    Segment(u32),
}

/// One constraint: literals `var << 1 | negated`, where a variable is true when its
/// lower-numbered face is above, and the faces it concerns.
#[derive(Clone, Debug)]
pub struct Constraint {
    /// The kind (selects the table of valid tuples).
    pub kind: Kind,
    /// Literals, `len` of them used.
    pub lits: [u32; 6],
    /// How many literals.
    pub len: u8,
    /// The faces concerned (unused slots repeat the last).
    pub faces: [u32; 4],
    /// Where it comes from.
    pub place: Place,
}

/// Most transitivity triples generated before the problem is refused as too large: about
/// 48 bytes each with the solver's rows (3.8 GB at the limit). Imai's Shrimp v2 has 67.5
/// million (Flat-Folder's count).
pub const MAX_TRIPLES: usize = crate::limits::MAX_LAYER_TRIPLES;

/// The constraint system of one folded form.
#[derive(Clone, Debug, Default)]
pub struct System {
    /// Face pairs `(lo, hi)` packed as `lo << 32 | hi`, sorted: the variables.
    pub pairs: Vec<u64>,
    /// Constraints other than the transitivity ones of [`System::triples`] (numbered first).
    pub constraints: Vec<Constraint>,
    /// Transitivity constraints, numbered after [`System::constraints`]: the variables of "a
    /// above b", "a above c" and "b above c" for three faces `a < b < c` (so no literal is
    /// negated). Kept apart, at 12 bytes each: real designs have tens of millions.
    pub triples: Vec<[u32; 3]>,
    /// Forced literals from mountain and valley creases: `(literal, edge)`.
    pub forced: Vec<(u32, u32)>,
    /// Constraint counts by [`Kind`].
    pub counts: [usize; 4],
}

impl System {
    /// The variable of faces `a`, `b` (any order), if they overlap.
    pub fn var(&self, a: u32, b: u32) -> Option<u32> {
        let key = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
        self.pairs.binary_search(&key).ok().map(|i| i as u32)
    }

    /// The literal "`a` is above `b`", if they overlap.
    pub fn above(&self, a: u32, b: u32) -> Option<u32> {
        self.var(a, b).map(|v| (v << 1) | u32::from(a > b))
    }

    /// The two faces of a variable, lower first.
    pub fn faces_of(&self, var: u32) -> (u32, u32) {
        let k = self.pairs[var as usize];
        ((k >> 32) as u32, k as u32)
    }

    /// Number of constraints, the transitivity triples included.
    pub fn constraint_count(&self) -> usize {
        self.constraints.len() + self.triples.len()
    }

    /// The kind and literals of constraint `c` (see [`System::triples`] for the numbering).
    #[inline]
    pub fn lits(&self, c: u32) -> (Kind, [u32; 6], usize) {
        let n = self.constraints.len();
        if (c as usize) < n {
            let con = &self.constraints[c as usize];
            (con.kind, con.lits, con.len as usize)
        } else {
            let [x, y, z] = self.triples[c as usize - n];
            (Kind::Transitivity, [x << 1, y << 1, z << 1, 0, 0, 0], 3)
        }
    }

    /// Constraint `c` written out (see [`System::triples`] for the numbering).
    pub fn constraint(&self, c: u32) -> Constraint {
        let n = self.constraints.len();
        if (c as usize) < n {
            return self.constraints[c as usize].clone();
        }
        let (kind, lits, len) = self.lits(c);
        let (a, b) = self.faces_of(lits[0] >> 1);
        let (_, d) = self.faces_of(lits[2] >> 1);
        Constraint {
            kind,
            lits,
            len: len as u8,
            faces: [a, b, d, d],
            place: Place::Common,
        }
    }

    fn push(&mut self, kind: Kind, faces: &[u32], pairs: &[(u32, u32)], place: Place) {
        let mut lits = [0; 6];
        for (slot, &(a, b)) in lits.iter_mut().zip(pairs) {
            match self.above(a, b) {
                Some(l) => *slot = l,
                None => return,
            }
        }
        let mut fs = [0; 4];
        for (i, slot) in fs.iter_mut().enumerate() {
            *slot = faces[i.min(faces.len() - 1)];
        }
        self.counts[kind as usize] += 1;
        self.constraints.push(Constraint {
            kind,
            lits,
            len: pairs.len() as u8,
            faces: fs,
            place,
        });
    }
}

/// Builds the variables and constraints of a folded form.
pub fn build(
    cp: &CreasePattern,
    folded: &FoldedFaces,
    arr: &Arrangement,
    deadline: &Deadline,
) -> Result<System, LayerError> {
    let maximal = maximal_cells(arr);
    let mut sys = System {
        pairs: pairs(arr, &maximal),
        ..Default::default()
    };
    edge_constraints(cp, folded, arr, &mut sys);
    if deadline.passed() {
        return Err(LayerError::out_of_time(
            deadline,
            "building the constraints",
        ));
    }
    transitivity(arr, &maximal, &mut sys, deadline)?;
    for (e, edge) in cp.edges.iter().enumerate() {
        let [Some(f), Some(g)] = folded.edge_faces[e] else {
            continue;
        };
        if f == g || !edge.assignment.is_fold() {
            continue;
        }
        let valley = edge.assignment == Assignment::Valley;
        if let Some(lit) = sys.above(g, f) {
            let value = valley != folded.faces[f as usize].flipped;
            sys.forced.push((lit ^ u32::from(!value), e as u32));
        }
    }
    Ok(sys)
}

/// Cells whose faces are not a strict subset of a neighbouring cell's. Every pair or triple of
/// faces of a cell is one of a maximal cell's: along a chain of strict supersets the sizes
/// grow, so it ends at a maximal cell.
fn maximal_cells(arr: &Arrangement) -> Vec<bool> {
    let mut maximal = vec![true; arr.cell_faces.len()];
    for &[l, r] in &arr.segment_cells {
        if let (Some(l), Some(r)) = (l, r) {
            let (a, b) = (&arr.cell_faces[l as usize], &arr.cell_faces[r as usize]);
            if a.len() < b.len() && is_subset(a, b) {
                maximal[l as usize] = false;
            } else if b.len() < a.len() && is_subset(b, a) {
                maximal[r as usize] = false;
            }
        }
    }
    maximal
}

/// Every pair of faces that cover a common cell, packed as `lo << 32 | hi`, ascending: for each
/// face, the higher faces of the maximal cells that hold it (marks, not a sort of every pair
/// met).
fn pairs(arr: &Arrangement, maximal: &[bool]) -> Vec<u64> {
    let mut seen: HashSet<&[u32]> = HashSet::new();
    let cells: Vec<&[u32]> = arr
        .cell_faces
        .iter()
        .enumerate()
        .filter(|(c, faces)| faces.len() >= 2 && maximal[*c])
        .map(|(_, faces)| faces.as_slice())
        .filter(|faces| seen.insert(faces))
        .collect();
    let (face_cells, n_faces) = face_cells(&cells);
    let mut mark = vec![u32::MAX; n_faces];
    let mut keys = Vec::new();
    let mut higher: Vec<u32> = Vec::new();
    for (a, holding) in face_cells.iter().enumerate() {
        higher.clear();
        for &c in holding {
            for &b in cells[c as usize] {
                if b as usize > a && mark[b as usize] != a as u32 {
                    mark[b as usize] = a as u32;
                    higher.push(b);
                }
            }
        }
        higher.sort_unstable();
        keys.extend(higher.iter().map(|&b| ((a as u64) << 32) | u64::from(b)));
    }
    keys
}

/// For each face, the indices of the `cells` that hold it (ascending), and the number of
/// faces (one more than the highest face met).
fn face_cells(cells: &[&[u32]]) -> (Vec<Vec<u32>>, usize) {
    let n_faces = cells
        .iter()
        .flat_map(|f| f.iter())
        .map(|&f| f as usize + 1)
        .max()
        .unwrap_or(0);
    let mut face_cells: Vec<Vec<u32>> = vec![Vec::new(); n_faces];
    for (c, faces) in cells.iter().enumerate() {
        for &f in *faces {
            face_cells[f as usize].push(c as u32);
        }
    }
    (face_cells, n_faces)
}

/// One transitivity constraint for every three faces that cover a common cell, found pair by
/// pair: for each overlapping pair `a < b`, the faces `c > b` of the maximal cells that hold
/// both (marks instead of a sort of every triple met, which repeats each triple once per cell
/// that holds it). Listed in ascending order of `(a, b, c)`.
fn transitivity(
    arr: &Arrangement,
    maximal: &[bool],
    sys: &mut System,
    deadline: &Deadline,
) -> Result<(), LayerError> {
    let mut seen: HashSet<&[u32]> = HashSet::new();
    let cells: Vec<&[u32]> = arr
        .cell_faces
        .iter()
        .enumerate()
        .filter(|(c, faces)| faces.len() >= 3 && maximal[*c])
        .map(|(_, faces)| faces.as_slice())
        .filter(|faces| seen.insert(faces))
        .collect();
    check_stack(cells.iter().map(|c| c.len()).max().unwrap_or(0))?;
    let (face_cells, n_faces) = face_cells(&cells);
    // The variables of each face's pairs with higher faces are one run of `pairs`: where each
    // run starts, and the variable of `(a, c)` for every `c` of the current face `a`.
    let n_rows = sys
        .pairs
        .last()
        .map_or(0, |&k| (k >> 32) as usize + 1)
        .max(n_faces);
    let mut row_start = vec![sys.pairs.len() as u32; n_rows + 1];
    for (i, &key) in sys.pairs.iter().enumerate().rev() {
        row_start[(key >> 32) as usize] = i as u32;
    }
    for a in (0..n_rows).rev() {
        row_start[a] = row_start[a].min(row_start[a + 1]);
    }
    let var_in_row = |x: usize, y: u32| -> Option<u32> {
        let (lo, hi) = (row_start[x] as usize, row_start[x + 1] as usize);
        sys.pairs[lo..hi]
            .binary_search_by_key(&y, |&k| k as u32)
            .ok()
            .map(|j| (lo + j) as u32)
    };
    let mut var_of_a = vec![u32::MAX; n_faces];
    let mut current_a = usize::MAX;
    let mut mark = vec![u32::MAX; n_faces];
    let mut thirds: Vec<u32> = Vec::new();
    let mut found: Vec<[u32; 3]> = Vec::new();
    for (i, &key) in sys.pairs.iter().enumerate() {
        let (a, b) = ((key >> 32) as usize, (key & 0xffff_ffff) as usize);
        if b >= n_faces {
            continue;
        }
        if a != current_a {
            current_a = a;
            for j in row_start[a]..row_start[a + 1] {
                // Faces beyond `n_faces` are in no cell of three: never a third face.
                if let Some(slot) = var_of_a.get_mut(sys.pairs[j as usize] as u32 as usize) {
                    *slot = j;
                }
            }
        }
        thirds.clear();
        let (ca, cb) = (&face_cells[a], &face_cells[b]);
        let (mut x, mut y) = (0, 0);
        while x < ca.len() && y < cb.len() {
            match ca[x].cmp(&cb[y]) {
                std::cmp::Ordering::Less => x += 1,
                std::cmp::Ordering::Greater => y += 1,
                std::cmp::Ordering::Equal => {
                    for &c in cells[ca[x] as usize] {
                        if c as usize > b && mark[c as usize] != i as u32 {
                            mark[c as usize] = i as u32;
                            thirds.push(c);
                        }
                    }
                    x += 1;
                    y += 1;
                }
            }
        }
        thirds.sort_unstable();
        // a < b < c: every literal "x above y" has x < y, so none is negated.
        for &c in &thirds {
            let ac = var_of_a[c as usize];
            let Some(bc) = var_in_row(b, c) else {
                continue;
            };
            if ac == u32::MAX || row_start[a] > ac || ac >= row_start[a + 1] {
                continue;
            }
            found.push([i as u32, ac, bc]);
        }
        if deadline.passed() {
            return Err(LayerError::out_of_time(
                deadline,
                "building the transitivity constraints",
            ));
        }
        if found.len() > MAX_TRIPLES {
            return Err(LayerError::TooLarge {
                what: "transitivity constraints",
                count: found.len(),
                limit: MAX_TRIPLES,
            });
        }
    }
    sys.counts[Kind::Transitivity as usize] = found.len();
    sys.triples = found;
    Ok(())
}

/// Refuses a stack of `layers` faces over one place whose transitivity constraints alone
/// (every three of its faces) pass [`MAX_TRIPLES`]: the limit would be passed, and this is
/// known before any constraint is written out (or, from the folded form, before the overlay).
pub fn check_stack(layers: usize) -> Result<(), LayerError> {
    let k = layers as u128;
    let least = k * k.saturating_sub(1) * k.saturating_sub(2) / 6;
    if least > MAX_TRIPLES as u128 {
        return Err(LayerError::TooLarge {
            what: "transitivity constraints at least (from its deepest stack of layers alone)",
            count: usize::try_from(least).unwrap_or(usize::MAX),
            limit: MAX_TRIPLES,
        });
    }
    Ok(())
}

/// True when every element of sorted `a` is in sorted `b`.
fn is_subset(a: &[u32], b: &[u32]) -> bool {
    let mut j = 0;
    for &x in a {
        while j < b.len() && b[j] < x {
            j += 1;
        }
        if j == b.len() || b[j] != x {
            return false;
        }
        j += 1;
    }
    true
}

/// Which side of segment `s` face `f` lies on (0 left, 1 right), if it borders it.
fn side(arr: &Arrangement, s: usize, f: u32) -> Option<usize> {
    (0..2).find(|&k| {
        arr.segment_cells[s][k]
            .is_some_and(|c| arr.cell_faces[c as usize].binary_search(&f).is_ok())
    })
}

fn edge_constraints(cp: &CreasePattern, folded: &FoldedFaces, arr: &Arrangement, sys: &mut System) {
    let mut done: HashSet<(u8, u32, u32)> = HashSet::new();
    for s in 0..arr.segment_edges.len() {
        let place = Place::Segment(s as u32);
        // (faces, side) of the folded creases, and (left face, right face) of the F lines.
        let mut tacos: Vec<(u32, u32, usize, u32)> = Vec::new();
        let mut flats: Vec<([u32; 2], u32)> = Vec::new();
        for &e in &arr.segment_edges[s] {
            let [Some(f), Some(g)] = folded.edge_faces[e as usize] else {
                continue;
            };
            let (Some(sf), Some(sg)) = (side(arr, s, f), side(arr, s, g)) else {
                continue;
            };
            match cp.edges[e as usize].assignment {
                a if a.may_fold() && sf == sg => tacos.push((f, g, sf, e)),
                Assignment::Flat | Assignment::Join if sf != sg => {
                    let mut pair = [f, g];
                    if sf == 1 {
                        pair.swap(0, 1);
                    }
                    flats.push((pair, e));
                }
                _ => {}
            }
        }
        let through: Vec<u32> = match arr.segment_cells[s] {
            [Some(l), Some(r)] => {
                intersection(&arr.cell_faces[l as usize], &arr.cell_faces[r as usize])
            }
            _ => Vec::new(),
        };
        for (i, &(a, b, sa, ea)) in tacos.iter().enumerate() {
            for &(c, d, sc, ec) in &tacos[i + 1..] {
                if sa == sc && done.insert((0, ea.min(ec), ea.max(ec))) {
                    sys.push(
                        Kind::TacoTaco,
                        &[a, b, c, d],
                        &[(a, b), (a, c), (a, d), (b, c), (b, d), (c, d)],
                        place,
                    );
                }
            }
            let thirds = through
                .iter()
                .copied()
                .chain(flats.iter().map(|(pair, _)| pair[sa]));
            for c in thirds {
                if c != a && c != b && done.insert((1, ea, c)) {
                    sys.push(
                        Kind::TacoTortilla,
                        &[a, b, c],
                        &[(a, b), (a, c), (b, c)],
                        place,
                    );
                }
            }
        }
        for &([f, g], e) in &flats {
            for &c in &through {
                if done.insert((3, e, c)) {
                    sys.push(
                        Kind::TortillaTortilla,
                        &[f, c, g, c],
                        &[(f, c), (g, c)],
                        place,
                    );
                }
            }
        }
        for (i, &([f1, g1], e1)) in flats.iter().enumerate() {
            for &([f2, g2], e2) in &flats[i + 1..] {
                if done.insert((2, e1.min(e2), e1.max(e2))) {
                    sys.push(
                        Kind::TortillaTortilla,
                        &[f1, f2, g1, g2],
                        &[(f1, f2), (g1, g2)],
                        place,
                    );
                }
            }
        }
    }
}

fn intersection(a: &[u32], b: &[u32]) -> Vec<u32> {
    let (mut i, mut j, mut out) = (0, 0, Vec::new());
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => i += 1,
            std::cmp::Ordering::Greater => j += 1,
            std::cmp::Ordering::Equal => {
                out.push(a[i]);
                i += 1;
                j += 1;
            }
        }
    }
    out
}

/// The valid tuples of each kind (bit `i` is literal `i`'s value).
pub fn tables() -> [Vec<u8>; 4] {
    let taco_taco = by_ranks(4, &[(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)], |r| {
        let between = |x: usize| (r[x] > r[0]) != (r[x] > r[1]);
        between(2) == between(3)
    });
    let taco_tortilla = by_ranks(3, &[(0, 1), (0, 2), (1, 2)], |r| {
        (r[2] > r[0]) == (r[2] > r[1])
    });
    let transitivity = by_ranks(3, &[(0, 1), (0, 2), (1, 2)], |_| true);
    [taco_taco, taco_tortilla, vec![0b00, 0b11], transitivity]
}

/// Tuples of "x above y" literals over `pairs` for every stacking of `n` faces (ranks, higher
/// above) that `valid` accepts.
fn by_ranks(n: usize, pairs: &[(usize, usize)], valid: impl Fn(&[usize]) -> bool) -> Vec<u8> {
    let mut out = Vec::new();
    let mut ranks: Vec<usize> = (0..n).collect();
    permutations(&mut ranks, 0, &mut |r| {
        if valid(r) {
            let t = pairs
                .iter()
                .enumerate()
                .fold(0u8, |t, (i, &(x, y))| t | (u8::from(r[x] > r[y]) << i));
            out.push(t);
        }
    });
    out.sort_unstable();
    out.dedup();
    out
}

fn permutations(r: &mut Vec<usize>, k: usize, visit: &mut impl FnMut(&[usize])) {
    if k == r.len() {
        visit(r);
        return;
    }
    for i in k..r.len() {
        r.swap(k, i);
        permutations(r, k + 1, visit);
        r.swap(k, i);
    }
}
