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
use super::progress::LayerProgress;
use crate::clock::Deadline;

/// Outcome of counting one component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Count {
    /// States found (all of them when `exact`).
    pub states: u128,
    /// False when the cap stopped the count.
    pub exact: bool,
}

/// The filter of a table of valid tuples for every pattern of known literals (see
/// [`Engine::filter`]).
fn filtered_table(table: &[u8]) -> Vec<(u8, u8, u8)> {
    (0..1usize << 12)
        .map(|i| {
            let (known, bits) = ((i >> 6) as u8, (i & 63) as u8);
            table
                .iter()
                .filter(|&&t| t & known == bits)
                .fold((0u8, 0xffu8, 0u8), |(n, all, any), &t| {
                    (n + 1, all & t, any | t)
                })
        })
        .collect()
}

/// Compressed rows: for each of `n` variables, the entries that `items` lists for it, as
/// `(variable, entry)`, called twice (once to count, once to fill).
fn rows<T: Copy + Default, I: Iterator<Item = (u32, T)>>(
    n: usize,
    items: impl Fn() -> I,
) -> (Vec<u32>, Vec<T>) {
    let mut offsets = vec![0u32; n + 1];
    for (v, _) in items() {
        offsets[v as usize + 1] += 1;
    }
    for v in 0..n {
        offsets[v + 1] += offsets[v];
    }
    let mut fill = offsets[..n].to_vec();
    let mut out = vec![T::default(); offsets[n] as usize];
    for (v, t) in items() {
        out[fill[v as usize] as usize] = t;
        fill[v as usize] += 1;
    }
    (offsets, out)
}

/// The compressed rows of [`Engine::transit`]: for each variable, its transitivity
/// constraints seen from it (written out loop by loop: real designs have tens of millions).
fn transit_rows(n: usize, sys: &System) -> (Vec<u32>, Vec<Transit>) {
    let mut offsets = vec![0u32; n + 1];
    for t in &sys.triples {
        for &v in t {
            offsets[v as usize + 1] += 1;
        }
    }
    for v in 0..n {
        offsets[v + 1] += offsets[v];
    }
    let mut fill = offsets[..n].to_vec();
    let mut out = vec![Transit::default(); offsets[n] as usize];
    let first = sys.constraints.len() as u32;
    for (t, &[x, y, z]) in sys.triples.iter().enumerate() {
        // Not all equal: "a above b", "c above a" (the second negated), "b above c".
        let nae = [x << 1, (y << 1) | 1, z << 1];
        for k in 0..3 {
            let own = nae[k] & 1;
            let v = (nae[k] >> 1) as usize;
            out[fill[v] as usize] = Transit {
                others: [nae[(k + 1) % 3] ^ own, nae[(k + 2) % 3] ^ own],
                constraint: first + t as u32,
            };
            fill[v] += 1;
        }
    }
    (offsets, out)
}

/// The propagation engine over one [`System`].
pub struct Engine<'a> {
    sys: &'a System,
    /// For each kind, indexed by `known << 6 | bits` (which literals are known, and their
    /// values): how many valid tuples agree, and the AND and OR of those tuples.
    filtered: [Vec<(u8, u8, u8)>; 4],
    /// The constraints of [`System::constraints`] on each variable (compressed rows), revised
    /// through the tables.
    offsets: Vec<u32>,
    incident: Vec<u32>,
    /// The transitivity constraints of each variable (compressed rows), written out for
    /// propagation without the tables (see [`Transit`]).
    transit_offsets: Vec<u32>,
    transit: Vec<Transit>,
    /// −1 unset, 0 or 1.
    pub value: Vec<i8>,
    trail: Vec<u32>,
    head: usize,
    /// The constraint of the last contradiction met.
    pub last_conflict: Option<u32>,
    /// Scratch marks for splitting into components, valid when equal to `epoch`.
    stamp: Vec<u32>,
    epoch: u32,
    /// Exact counts of components already met, by [`Engine::cache_key`].
    cache: std::collections::HashMap<(u64, u64), u128>,
    /// When to give up counting (see [`Engine::with_deadline`]).
    deadline: Option<&'a Deadline>,
    /// Where the states found are counted for a front end (see [`Engine::with_progress`]).
    progress: Option<&'a LayerProgress>,
    /// The deadline passed: the counts since are not to be used.
    pub timed_out: bool,
}

/// SplitMix64's finaliser (Steele, Lea & Flood 2014): spreads the bits of `x`.
fn mix(mut x: u64) -> u64 {
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}

/// One transitivity constraint as seen from one of its variables `v`.
///
/// Three faces `a < b < c` are stacked in a cycle exactly when the literals "a above b",
/// "c above a" and "b above c" are all true or all false, so the constraint says that these
/// three literals are *not all equal*. `others` are the two literals other than `v`'s, each
/// negated once more when `v`'s own literal is negated: the constraint is then violated when
/// both are true exactly as `v`'s value is (1 or 0), and forces the second once the first is.
#[derive(Clone, Copy, Debug, Default)]
struct Transit {
    others: [u32; 2],
    constraint: u32,
}

/// Choices the first, depth-first enumeration of a component may make before the component
/// is counted by splitting instead (see [`Engine::count`]).
const ENUMERATION_DECISIONS: u64 = 50_000;

/// States the first enumeration lists one by one before the component is counted by
/// splitting instead.
const ENUMERATION_STATES: u128 = 4096;

/// Components of at most this many variables are split again after every choice.
const SPLIT_ALWAYS: usize = 256;

/// Larger components are split again after a choice that settled at least one in this many
/// of their variables (see [`Engine::branch`]).
const SPLIT_SHARE: usize = 32;

/// Most component counts remembered before the memory is cleared.
const CACHE_ENTRIES: usize = 1 << 20;

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
        let (offsets, incident) = rows(n, || {
            sys.constraints.iter().enumerate().flat_map(|(i, c)| {
                c.lits[..c.len as usize]
                    .iter()
                    .map(move |&l| (l >> 1, i as u32))
            })
        });
        let (transit_offsets, transit) = transit_rows(n, sys);
        Engine {
            sys,
            filtered: tables().map(|t| filtered_table(&t)),
            offsets,
            incident,
            transit_offsets,
            transit,
            value: vec![-1; n],
            trail: Vec::new(),
            head: 0,
            last_conflict: None,
            stamp: vec![0; n],
            epoch: 0,
            cache: std::collections::HashMap::new(),
            deadline: None,
            progress: None,
            timed_out: false,
        }
    }

    /// This engine, stopping its counts when `deadline` passes: [`Engine::timed_out`] is then
    /// set and the counts returned are not to be used.
    pub fn with_deadline(mut self, deadline: &'a Deadline) -> Engine<'a> {
        self.deadline = Some(deadline);
        self
    }

    /// This engine, counting every state its enumeration finds in `progress` (when given).
    pub fn with_progress(mut self, progress: Option<&'a LayerProgress>) -> Engine<'a> {
        self.progress = progress;
        self
    }

    /// Whether the deadline has passed (remembered in [`Engine::timed_out`]).
    fn out_of_time(&mut self) -> bool {
        if !self.timed_out && self.deadline.is_some_and(Deadline::passed) {
            self.timed_out = true;
        }
        self.timed_out
    }

    /// The constraints of [`System::constraints`] on variable `v` (no transitivity).
    fn general_of(&self, v: u32) -> &[u32] {
        let v = v as usize;
        &self.incident[self.offsets[v] as usize..self.offsets[v + 1] as usize]
    }

    /// The transitivity constraints on variable `v`, seen from it: their other two variables
    /// are read here, without the triple (tens of millions of them, read out of order).
    fn transit_of(&self, v: u32) -> &[Transit] {
        let v = v as usize;
        &self.transit[self.transit_offsets[v] as usize..self.transit_offsets[v + 1] as usize]
    }

    /// How many constraints are on variable `v`.
    fn degree(&self, v: u32) -> u32 {
        let v = v as usize;
        self.offsets[v + 1] - self.offsets[v] + self.transit_offsets[v + 1]
            - self.transit_offsets[v]
    }

    /// The variables sharing a binding constraint with `v` (`v` itself included), the edges
    /// of the graph whose connected parts are the independent components.
    fn bound_neighbours<'s>(
        &'s self,
        v: u32,
        binding: &'s [bool],
    ) -> impl Iterator<Item = u32> + 's {
        let general = (self.general_of(v).iter())
            .filter(move |&&c| binding[c as usize])
            .flat_map(move |&c| {
                let (_, lits, len) = self.sys.lits(c);
                (0..len).map(move |i| lits[i] >> 1)
            });
        // A transitivity constraint's variables from `v`'s own rows (see `transit_of`).
        let transit = (self.transit_of(v).iter())
            .filter(move |t| binding[t.constraint as usize])
            .flat_map(move |t| [v, t.others[0] >> 1, t.others[1] >> 1]);
        general.chain(transit)
    }

    fn filter(&self, c: u32) -> Filtered {
        let (kind, lits, len) = self.sys.lits(c);
        let (mut known, mut bits, mut unknown) = (0u8, 0u8, 0u8);
        for (i, &l) in lits[..len].iter().enumerate() {
            match self.value[(l >> 1) as usize] {
                -1 => unknown |= 1 << i,
                v => {
                    known |= 1 << i;
                    bits |= (((v as u8) ^ (l & 1) as u8) & 1) << i;
                }
            }
        }
        let (left, all, any) =
            self.filtered[kind as usize][(usize::from(known) << 6) | usize::from(bits)];
        Filtered {
            left: u32::from(left),
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
            let v = self.trail[self.head] as usize;
            self.head += 1;
            let (lo, hi) = (self.offsets[v] as usize, self.offsets[v + 1] as usize);
            for k in lo..hi {
                let c = self.incident[k];
                self.revise(c)?;
            }
            let own = self.value[v];
            let (lo, hi) = (
                self.transit_offsets[v] as usize,
                self.transit_offsets[v + 1] as usize,
            );
            for k in lo..hi {
                let t = self.transit[k];
                let truth = |l: u32| {
                    let x = self.value[(l >> 1) as usize];
                    if x < 0 { -1 } else { x ^ (l & 1) as i8 }
                };
                let (p, q) = (truth(t.others[0]), truth(t.others[1]));
                // Both others equal to `own` would close a cycle; one equal forces the other
                // to differ.
                if p == own {
                    if q == own {
                        self.last_conflict = Some(t.constraint);
                        return Err(t.constraint);
                    }
                    if q < 0 {
                        self.set_literal(t.others[1] ^ own as u32);
                    }
                } else if q == own && p < 0 {
                    self.set_literal(t.others[0] ^ own as u32);
                }
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
        let (_, lits, len) = self.sys.lits(c);
        for (i, &l) in lits[..len].iter().enumerate() {
            if forced & (1 << i) != 0 {
                let lit = if f.all & (1 << i) != 0 { l } else { l ^ 1 };
                self.set_literal(lit);
            }
        }
        Ok(())
    }

    /// Revises every constraint once, then propagates (the start of a solve).
    ///
    /// A transitivity constraint of [`System::triples`] forces nothing before one of its
    /// variables is set, and [`Engine::propagate`] looks at it whenever one is: those are
    /// left out here.
    pub fn propagate_all(&mut self) -> Result<(), u32> {
        self.propagate()?;
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
        let (_, lits, len) = self.sys.lits(c);
        let unset = lits[..len]
            .iter()
            .filter(|&&l| self.value[(l >> 1) as usize] == -1)
            .count();
        if unset < 2 {
            return false;
        }
        let f = self.filter(c);
        f.unknown.count_ones() >= 2 && f.left < (1u32 << f.unknown.count_ones())
    }

    /// The unset variables grouped into independent components, each in breadth-first order
    /// from its most constrained variable; components are listed by their lowest variable.
    pub fn components(&self) -> Vec<Vec<u32>> {
        let n = self.value.len();
        let mut comp = vec![u32::MAX; n];
        let mut out: Vec<Vec<u32>> = Vec::new();
        let binding: Vec<bool> = (0..self.sys.constraint_count() as u32)
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
            .max_by_key(|&&v| (self.degree(v), std::cmp::Reverse(v)))
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
    /// `cap` states (the count is then `cap`, `exact` false). With `keep` = Some(k), stops at
    /// the state numbered k (from 0, in depth-first order along `order`) and leaves it set;
    /// otherwise every value set by the search is undone.
    pub fn count(&mut self, order: &[u32], cap: Option<u128>, keep: Option<u128>) -> Count {
        if keep.is_some() {
            return self.enumerate(order, cap, keep, None).unwrap_or(Count {
                states: 0,
                exact: false,
            });
        }
        // Depth-first along the breadth-first order first, as Flat-Folder does: each choice
        // propagates next to the last, so dead ends show at once; components with few states
        // (however many variables) are done this way. Many states, or a long search, go to
        // counting by splitting.
        let budget = Some(ENUMERATION_DECISIONS);
        let first_cap = cap.map_or(ENUMERATION_STATES, |c| c.min(ENUMERATION_STATES));
        if let Some(count) = self.enumerate(order, Some(first_cap), None, budget)
            && (count.exact || cap.is_some_and(|c| count.states >= c) || self.timed_out)
        {
            return count;
        }
        {
            let mut vars: Vec<u32> = order
                .iter()
                .copied()
                .filter(|&v| self.value[v as usize] == -1)
                .collect();
            vars.sort_unstable();
            if let Some(p) = self.progress {
                p.splitting();
            }
            let base = self.trail.len();
            let mut count = self.count_split(&vars, cap);
            self.undo_to(base);
            if let Some(c) = cap
                && count.states >= c
                && !count.exact
            {
                count.states = c;
            }
            count
        }
    }

    /// Depth-first enumeration of every state of `order` (see [`Engine::count`]); `None`
    /// when more than `budget` choices were needed (everything undone).
    fn enumerate(
        &mut self,
        order: &[u32],
        cap: Option<u128>,
        keep: Option<u128>,
        budget: Option<u64>,
    ) -> Option<Count> {
        let base = self.trail.len();
        let mut total: u128 = 0;
        let mut choices: u64 = 0;
        let next_unset = |value: &[i8], from: usize| {
            (from..order.len()).find(|&p| value[order[p] as usize] == -1)
        };
        let Some(first) = next_unset(&self.value, 0) else {
            return Some(Count {
                states: 1,
                exact: true,
            });
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
            choices += 1;
            if budget.is_some_and(|b| choices > b) {
                self.undo_to(base);
                return None;
            }
            if self.out_of_time() {
                self.undo_to(base);
                return Some(Count {
                    states: total,
                    exact: false,
                });
            }
            self.set_literal((order[pos] << 1) | (1 - next as u32));
            if self.propagate().is_err() {
                continue;
            }
            match next_unset(&self.value, pos + 1) {
                Some(p) => frames.push((p, 0, self.trail.len())),
                None => {
                    if keep == Some(total) {
                        return Some(Count {
                            states: total + 1,
                            exact: false,
                        });
                    }
                    total += 1;
                    if let Some(p) = self.progress {
                        p.add_state();
                    }
                    if cap.is_some_and(|c| total >= c) {
                        self.undo_to(base);
                        return Some(Count {
                            states: total,
                            exact: false,
                        });
                    }
                }
            }
        }
        self.undo_to(base);
        Some(Count {
            states: total,
            exact: true,
        })
    }

    /// The unset variables of `vars` split into the components that the binding constraints
    /// join.
    fn split(&mut self, vars: &[u32]) -> Vec<Vec<u32>> {
        if self.epoch >= u32::MAX - 2 {
            self.stamp.iter_mut().for_each(|s| *s = 0);
            self.epoch = 0;
        }
        let (inside, done) = (self.epoch + 1, self.epoch + 2);
        self.epoch += 2;
        for &v in vars {
            if self.value[v as usize] == -1 {
                self.stamp[v as usize] = inside;
            }
        }
        let mut out = Vec::new();
        for &start in vars {
            if self.stamp[start as usize] != inside {
                continue;
            }
            self.stamp[start as usize] = done;
            let mut members = vec![start];
            let mut k = 0;
            while k < members.len() {
                let v = members[k];
                k += 1;
                // A transitivity constraint ("not all equal") on the unset `v` binds exactly
                // when another of its variables is unset too: 3 of the 4 values of two unset
                // ones are left, 6 of 8 of three. So its unset neighbours join, unread.
                let (lo, hi) = (
                    self.transit_offsets[v as usize] as usize,
                    self.transit_offsets[v as usize + 1] as usize,
                );
                for i in lo..hi {
                    for l in self.transit[i].others {
                        let w = (l >> 1) as usize;
                        if self.stamp[w] == inside {
                            self.stamp[w] = done;
                            members.push(w as u32);
                        }
                    }
                }
                let (lo, hi) = (
                    self.offsets[v as usize] as usize,
                    self.offsets[v as usize + 1] as usize,
                );
                for j in lo..hi {
                    let c = self.incident[j];
                    let (_, lits, len) = self.sys.lits(c);
                    if !lits[..len]
                        .iter()
                        .any(|&l| self.stamp[(l >> 1) as usize] == inside)
                        || !self.binds(c)
                    {
                        continue;
                    }
                    for &l in &lits[..len] {
                        let w = (l >> 1) as usize;
                        if self.stamp[w] == inside {
                            self.stamp[w] = done;
                            members.push(w as u32);
                        }
                    }
                }
            }
            out.push(members);
        }
        out
    }

    /// Counts the states of `vars` (unset variables closed under the binding constraints) by
    /// splitting into independent components, counting each and multiplying, the way model
    /// counters do (Birnbaum & Lozinskii 1999; Bayardo & Pehoushek 2000): choose the variable
    /// with the most constraints, try both values, propagate, split what is left again.
    /// Leaves values set; the caller undoes them.
    fn count_split(&mut self, vars: &[u32], cap: Option<u128>) -> Count {
        let mut product = Count {
            states: 1,
            exact: true,
        };
        for comp in self.split(vars) {
            let c = self.count_component(&comp, cap);
            if self.timed_out {
                return Count {
                    states: 0,
                    exact: false,
                };
            }
            if c.states == 0 {
                return Count {
                    states: 0,
                    exact: c.exact,
                };
            }
            product.exact &= c.exact;
            product.states = match product.states.checked_mul(c.states) {
                Some(p) => p,
                None => {
                    product.exact = false;
                    u128::MAX
                }
            };
        }
        product
    }

    /// Counts one component (see [`Engine::count_split`]).
    fn count_component(&mut self, comp: &[u32], cap: Option<u128>) -> Count {
        if comp.len() == 1 {
            // A lone variable bound by no constraint with another unset one: both values
            // that propagate without contradiction count.
            let mut states = 0;
            for value in 0..2u32 {
                let mark = self.trail.len();
                self.set_literal((comp[0] << 1) | value);
                if self.propagate().is_ok() {
                    states += 1;
                }
                self.undo_to(mark);
            }
            return Count {
                states,
                exact: true,
            };
        }
        let key = self.cache_key(comp);
        if let Some(&states) = self.cache.get(&key) {
            return Count {
                states,
                exact: true,
            };
        }
        let count = self.branch(comp, cap);
        if count.exact {
            if self.cache.len() >= CACHE_ENTRIES {
                self.cache.clear();
            }
            self.cache.insert(key, count.states);
        }
        count
    }

    /// A 128-bit fingerprint of what a component's count depends on: its variables and the
    /// values set on every variable sharing a constraint with them. Sums of mixed values, so
    /// the order in which the component was listed does not matter.
    fn cache_key(&self, comp: &[u32]) -> (u64, u64) {
        let (mut h1, mut h2) = (0u64, 0u64);
        let mut add = |x: u64| {
            h1 = h1.wrapping_add(mix(x));
            h2 = h2.wrapping_add(mix(x ^ 0x9e37_79b9_7f4a_7c15));
        };
        for &v in comp {
            add(u64::from(v));
            for &c in self.general_of(v) {
                let (_, lits, len) = self.sys.lits(c);
                for &l in &lits[..len] {
                    let x = self.value[(l >> 1) as usize];
                    if x != -1 {
                        add((1 << 40) | u64::from((l & !1) | x as u32));
                    }
                }
            }
            // A transitivity triple's literals are its variables unnegated, `v` unset: the
            // same entries from its other two variables, without reading the triple.
            for t in self.transit_of(v) {
                for l in t.others {
                    let x = self.value[(l >> 1) as usize];
                    if x != -1 {
                        add((1 << 40) | u64::from((l & !1) | x as u32));
                    }
                }
            }
        }
        (h1, h2)
    }

    /// Branches on the variable of `comp` with the most constraints (see
    /// [`Engine::count_split`]).
    fn branch(&mut self, comp: &[u32], cap: Option<u128>) -> Count {
        if self.out_of_time() {
            return Count {
                states: 0,
                exact: false,
            };
        }
        let Some(&pick) = comp.iter().max_by_key(|&&v| (self.degree(v), v)) else {
            return Count {
                states: 1,
                exact: true,
            };
        };
        let mut total = Count {
            states: 0,
            exact: true,
        };
        for value in 0..2u32 {
            let mark = self.trail.len();
            self.set_literal((pick << 1) | value);
            if self.propagate().is_ok() {
                // Splitting walks every constraint of the component: worth it only when the
                // choice settled a good share of it. Otherwise branch on in the same (still
                // correct, if perhaps not independent) set of variables.
                let settled = self.trail.len() - mark;
                let c = if comp.len() <= SPLIT_ALWAYS || settled * SPLIT_SHARE >= comp.len() {
                    self.count_split(comp, cap)
                } else {
                    let rest: Vec<u32> = comp
                        .iter()
                        .copied()
                        .filter(|&v| self.value[v as usize] == -1)
                        .collect();
                    self.branch(&rest, cap)
                };
                total.exact &= c.exact;
                total.states = total.states.saturating_add(c.states);
                total.exact &= total.states != u128::MAX;
            }
            self.undo_to(mark);
            if cap.is_some_and(|c| total.states >= c) {
                total.exact = false;
                break;
            }
        }
        total
    }
}

#[cfg(test)]
mod tests {
    use super::super::constraints::{Constraint, Kind, Place, System, tables};
    use super::Engine;

    /// A small system with constraints of every kind over `n` variables, drawn from a fixed
    /// linear congruential sequence.
    fn system(n: u32, m: usize, seed: u64) -> System {
        let mut state = seed;
        let mut next = |k: u32| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 33) % u64::from(k)) as u32
        };
        let mut sys = System {
            pairs: (0..u64::from(n)).collect(),
            ..Default::default()
        };
        for _ in 0..m {
            let kind = [
                Kind::TacoTaco,
                Kind::TacoTortilla,
                Kind::TortillaTortilla,
                Kind::Transitivity,
            ][next(4) as usize];
            sys.counts[kind as usize] += 1;
            if kind == Kind::Transitivity && next(2) == 0 {
                // The written-out form that the solver builds for three faces.
                sys.triples.push([next(n), next(n), next(n)]);
                continue;
            }
            let len = [6, 3, 2, 3][kind as usize];
            let mut lits = [0; 6];
            for slot in lits.iter_mut().take(len) {
                *slot = (next(n) << 1) | next(2);
            }
            sys.constraints.push(Constraint {
                kind,
                lits,
                len: len as u8,
                faces: [0; 4],
                place: Place::Common,
            });
        }
        sys
    }

    /// Every assignment tried against every constraint's table: no propagation, no search.
    fn brute_force(sys: &System) -> u128 {
        let tables = tables();
        let n = sys.pairs.len();
        (0u32..1 << n)
            .filter(|&a| {
                (0..sys.constraint_count() as u32).all(|c| {
                    let (kind, lits, len) = sys.lits(c);
                    let t = (0..len).fold(0u8, |t, i| {
                        let l = lits[i];
                        let v = ((a >> (l >> 1)) & 1) ^ (l & 1);
                        t | ((v as u8) << i)
                    });
                    tables[kind as usize].contains(&t)
                })
            })
            .count() as u128
    }

    #[test]
    fn split_counting_agrees_with_trying_every_assignment() {
        let mut nonzero = 0;
        for seed in 0..200 {
            let (n, m) = (4 + (seed % 9) as u32, 2 + (seed % 7) as usize);
            let sys = system(n, m, seed);
            let expected = brute_force(&sys);
            let mut engine = Engine::new(&sys);
            let counted = match engine.propagate_all() {
                Err(_) => 0,
                Ok(()) => engine
                    .components()
                    .iter()
                    .map(|comp| {
                        let c = engine.count(comp, None, None);
                        assert!(c.exact);
                        c.states
                    })
                    .product(),
            };
            assert_eq!(
                counted, expected,
                "seed {seed}, {n} variables, {m} constraints"
            );
            nonzero += usize::from(expected > 0);
        }
        assert!(nonzero > 50, "only {nonzero} systems with a state");
    }

    #[test]
    fn enumeration_and_split_counting_agree() {
        for seed in 0..60 {
            let sys = system(9, 5, 1000 + seed);
            let mut engine = Engine::new(&sys);
            if engine.propagate_all().is_err() {
                continue;
            }
            for comp in engine.components() {
                let split = engine.count(&comp, None, None);
                let listed = engine
                    .enumerate(&comp, None, None, None)
                    .expect("no budget");
                assert_eq!(split, listed, "seed {seed}");
            }
        }
    }
}
