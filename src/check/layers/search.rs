//! Unit propagation, independent components and counting search over the layer variables.
//!
//! Propagation: whenever a variable is set, every constraint on it filters its table of valid
//! tuples by the values known so far; no tuple left is a contradiction, and a literal that has
//! one value in every tuple left is forced. After the creases' forced orders have propagated,
//! the unset variables split into components joined by constraints that still restrict two or
//! more of them; components are independent, so the number of states is the product of their
//! counts. Each component is counted by depth-first search (choosing variables in
//! breadth-first order through the constraints, so each choice propagates near the last),
//! stopping at a cap.

use super::constraints::{System, tables};

/// Outcome of counting one component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Count {
    /// States found (all of them when `exact`).
    pub states: u128,
    /// False when the cap stopped the count.
    pub exact: bool,
}

/// The propagation engine over one [`System`].
pub struct Engine<'a> {
    sys: &'a System,
    tables: [Vec<u8>; 4],
    /// Constraints of each variable (compressed rows).
    offsets: Vec<u32>,
    incident: Vec<u32>,
    /// −1 unset, 0 or 1.
    pub value: Vec<i8>,
    trail: Vec<u32>,
    head: usize,
    /// The constraint of the last contradiction met.
    pub last_conflict: Option<u32>,
}

/// What a constraint allows given the values known: `(tuples left, and of them, or of them,
/// unknown-literal mask)`.
struct Filtered {
    left: u32,
    all: u8,
    any: u8,
    unknown: u8,
}

impl<'a> Engine<'a> {
    /// An engine with nothing set.
    pub fn new(sys: &'a System) -> Engine<'a> {
        let n = sys.pairs.len();
        let mut degree = vec![0u32; n + 1];
        for c in &sys.constraints {
            for &l in &c.lits[..c.len as usize] {
                degree[(l >> 1) as usize] += 1;
            }
        }
        let mut offsets = vec![0u32; n + 1];
        for v in 0..n {
            offsets[v + 1] = offsets[v] + degree[v];
        }
        let mut fill = offsets.clone();
        let mut incident = vec![0u32; offsets[n] as usize];
        for (i, c) in sys.constraints.iter().enumerate() {
            for &l in &c.lits[..c.len as usize] {
                let v = (l >> 1) as usize;
                incident[fill[v] as usize] = i as u32;
                fill[v] += 1;
            }
        }
        Engine {
            sys,
            tables: tables(),
            offsets,
            incident,
            value: vec![-1; n],
            trail: Vec::new(),
            head: 0,
            last_conflict: None,
        }
    }

    fn constraints_of(&self, v: u32) -> &[u32] {
        &self.incident[self.offsets[v as usize] as usize..self.offsets[v as usize + 1] as usize]
    }

    /// The variables sharing a binding constraint with `v` (`v` itself included), the edges
    /// of the graph whose connected parts are the independent components.
    fn bound_neighbours<'s>(
        &'s self,
        v: u32,
        binding: &'s [bool],
    ) -> impl Iterator<Item = u32> + 's {
        self.constraints_of(v)
            .iter()
            .filter(move |&&c| binding[c as usize])
            .flat_map(move |&c| {
                let con = &self.sys.constraints[c as usize];
                con.lits[..con.len as usize].iter().map(|&l| l >> 1)
            })
    }

    fn filter(&self, c: u32) -> Filtered {
        let con = &self.sys.constraints[c as usize];
        let (mut known, mut bits, mut unknown) = (0u8, 0u8, 0u8);
        for (i, &l) in con.lits[..con.len as usize].iter().enumerate() {
            match self.value[(l >> 1) as usize] {
                -1 => unknown |= 1 << i,
                v => {
                    known |= 1 << i;
                    bits |= (((v as u8) ^ (l & 1) as u8) & 1) << i;
                }
            }
        }
        let (mut left, mut all, mut any) = (0, 0xff, 0);
        for &t in &self.tables[con.kind as usize] {
            if t & known == bits {
                left += 1;
                all &= t;
                any |= t;
            }
        }
        Filtered {
            left,
            all,
            any,
            unknown,
        }
    }

    /// Sets a literal true; false if it is already false.
    pub fn set_literal(&mut self, lit: u32) -> bool {
        let v = (lit >> 1) as usize;
        let want = 1 - (lit & 1) as i8;
        match self.value[v] {
            -1 => {
                self.value[v] = want;
                self.trail.push(v as u32);
                true
            }
            x => x == want,
        }
    }

    /// Propagates everything set since the last call; on a contradiction returns the
    /// constraint that has no valid tuple left.
    pub fn propagate(&mut self) -> Result<(), u32> {
        while self.head < self.trail.len() {
            let v = self.trail[self.head];
            self.head += 1;
            let (lo, hi) = (
                self.offsets[v as usize] as usize,
                self.offsets[v as usize + 1] as usize,
            );
            for k in lo..hi {
                let c = self.incident[k];
                self.revise(c)?;
            }
        }
        Ok(())
    }

    /// Filters one constraint and sets what it forces.
    pub fn revise(&mut self, c: u32) -> Result<(), u32> {
        let f = self.filter(c);
        if f.left == 0 {
            self.last_conflict = Some(c);
            return Err(c);
        }
        let forced = f.unknown & (f.all | !f.any);
        if forced == 0 {
            return Ok(());
        }
        let con = &self.sys.constraints[c as usize];
        for i in 0..con.len as usize {
            if forced & (1 << i) != 0 {
                let l = con.lits[i];
                let lit = if f.all & (1 << i) != 0 { l } else { l ^ 1 };
                self.set_literal(lit);
            }
        }
        Ok(())
    }

    /// Revises every constraint once, then propagates (the start of a solve).
    pub fn propagate_all(&mut self) -> Result<(), u32> {
        for c in 0..self.sys.constraints.len() as u32 {
            self.revise(c)?;
            self.propagate()?;
        }
        Ok(())
    }

    fn undo_to(&mut self, mark: usize) {
        while self.trail.len() > mark {
            if let Some(v) = self.trail.pop() {
                self.value[v as usize] = -1;
            }
        }
        self.head = mark;
    }

    /// True when constraint `c` restricts its unset variables (some completion is invalid).
    fn binds(&self, c: u32) -> bool {
        let f = self.filter(c);
        f.unknown.count_ones() >= 2 && f.left < (1u32 << f.unknown.count_ones())
    }

    /// The unset variables grouped into independent components, each in breadth-first order
    /// from its most constrained variable; components are listed by their lowest variable.
    pub fn components(&self) -> Vec<Vec<u32>> {
        let n = self.value.len();
        let mut comp = vec![u32::MAX; n];
        let mut out: Vec<Vec<u32>> = Vec::new();
        let binding: Vec<bool> = (0..self.sys.constraints.len() as u32)
            .map(|c| self.binds(c))
            .collect();
        for start in 0..n as u32 {
            if self.value[start as usize] != -1 || comp[start as usize] != u32::MAX {
                continue;
            }
            let id = out.len() as u32;
            let mut members = vec![start];
            comp[start as usize] = id;
            let mut k = 0;
            while k < members.len() {
                let v = members[k];
                k += 1;
                for w in self.bound_neighbours(v, &binding) {
                    if self.value[w as usize] == -1 && comp[w as usize] == u32::MAX {
                        comp[w as usize] = id;
                        members.push(w);
                    }
                }
            }
            out.push(self.bfs_order(&members, &comp, id, &binding));
        }
        out
    }

    /// Breadth-first order of a component from its variable with the most constraints.
    fn bfs_order(&self, members: &[u32], comp: &[u32], id: u32, binding: &[bool]) -> Vec<u32> {
        let Some(&root) = members
            .iter()
            .max_by_key(|&&v| (self.constraints_of(v).len(), std::cmp::Reverse(v)))
        else {
            return Vec::new();
        };
        let mut seen = std::collections::HashSet::from([root]);
        let mut order = vec![root];
        let mut k = 0;
        while k < order.len() {
            let v = order[k];
            k += 1;
            for w in self.bound_neighbours(v, binding) {
                if comp[w as usize] == id && seen.insert(w) {
                    order.push(w);
                }
            }
        }
        order
    }

    /// Counts the states of one component (`order` from [`Engine::components`]), stopping at
    /// `cap` states. With `keep` = Some(k), stops at the state numbered k (from 0) and leaves
    /// it set; otherwise every value set by the search is undone.
    pub fn count(&mut self, order: &[u32], cap: Option<u128>, keep: Option<u128>) -> Count {
        let base = self.trail.len();
        let mut total: u128 = 0;
        let next_unset = |value: &[i8], from: usize| {
            (from..order.len()).find(|&p| value[order[p] as usize] == -1)
        };
        let Some(first) = next_unset(&self.value, 0) else {
            return Count {
                states: 1,
                exact: true,
            };
        };
        // (position in `order`, next value to try, trail length before trying it)
        let mut frames: Vec<(usize, i8, usize)> = vec![(first, 0, base)];
        while let Some(&(pos, next, mark)) = frames.last() {
            self.undo_to(mark);
            if next == 2 {
                frames.pop();
                continue;
            }
            if let Some(top) = frames.last_mut() {
                top.1 += 1;
            }
            self.set_literal((order[pos] << 1) | (1 - next as u32));
            if self.propagate().is_err() {
                continue;
            }
            match next_unset(&self.value, pos + 1) {
                Some(p) => frames.push((p, 0, self.trail.len())),
                None => {
                    if keep == Some(total) {
                        return Count {
                            states: total + 1,
                            exact: false,
                        };
                    }
                    total += 1;
                    if cap.is_some_and(|c| total >= c) {
                        self.undo_to(base);
                        return Count {
                            states: total,
                            exact: false,
                        };
                    }
                }
            }
        }
        self.undo_to(base);
        Count {
            states: total,
            exact: true,
        }
    }
}
