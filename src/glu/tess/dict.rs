//! The sweep line's dictionary: the active regions between consecutive edges crossing the
//! sweep line, bottom to top (GLU's `libtess/dict.c`, the sorted-list dictionary, and the
//! `ActiveRegion` of `sweep.h`).
//!
//! libtess keeps a doubly-linked list with a dummy head and inserts by walking down from a
//! given node; searches walk up from the bottom. The list is kept here the same way, so that
//! regions that compare equal end in the same order. Each region owns one node; both share an
//! index. Index 0 is the head (no region): "the region above the topmost" is [`NIL`].

use super::mesh::NIL;

/// The region below an edge crossing the sweep line (`ActiveRegion`).
#[derive(Clone, Debug)]
pub(crate) struct Region {
    /// The edge above the region, directed right to left.
    pub e_up: usize,
    pub winding_number: i32,
    pub inside: bool,
    /// The upper or lower edge changed: check the region's invariants again.
    pub dirty: bool,
    /// `e_up` is a temporary edge (added by `ConnectRightVertex`) to be replaced.
    pub fix_upper_edge: bool,
}

/// The dictionary: a circular list of region indices; slot 0 is the head.
pub(crate) struct Dict {
    next: Vec<usize>,
    prev: Vec<usize>,
    pub regions: Vec<Region>,
}

const HEAD: usize = 0;

impl Dict {
    pub fn new() -> Self {
        let head = Region { e_up: NIL, winding_number: 0, inside: false, dirty: false, fix_upper_edge: false };
        Self { next: vec![HEAD], prev: vec![HEAD], regions: vec![head] }
    }

    /// The region, or `NIL` for the head.
    fn key(n: usize) -> usize {
        if n == HEAD {
            NIL
        } else {
            n
        }
    }

    /// The region below `r`, `NIL` past the bottom.
    pub fn below(&self, r: usize) -> usize {
        Self::key(self.prev[r])
    }

    /// The region above `r`, `NIL` past the top.
    pub fn above(&self, r: usize) -> usize {
        Self::key(self.next[r])
    }

    /// The lowest region, `NIL` when empty.
    pub fn min(&self) -> usize {
        Self::key(self.next[HEAD])
    }

    /// The node below `n` (the head is 0): the walk of `dictInsertBefore`.
    pub fn prev_node(&self, n: usize) -> usize {
        self.prev[n]
    }

    /// The node to start a downward walk from: `above`, or the head for `NIL`.
    pub fn start_node(above: usize) -> usize {
        if above == NIL {
            HEAD
        } else {
            above
        }
    }

    /// Adds `region` just above `node` (`dictInsertBefore` once its walk has stopped).
    pub fn insert_after(&mut self, node: usize, region: Region) -> usize {
        let r = self.regions.len();
        self.regions.push(region);
        let after = self.next[node];
        self.next.push(after);
        self.prev.push(node);
        self.prev[after] = r;
        self.next[node] = r;
        r
    }

    /// Unlinks region `r` (`dictDelete`).
    pub fn delete(&mut self, r: usize) {
        let (p, n) = (self.prev[r], self.next[r]);
        self.prev[n] = p;
        self.next[p] = n;
    }

    /// The lowest region `x` with `leq(key, x)`, `NIL` if none (`dictSearch`).
    pub fn search(&self, leq: impl Fn(usize) -> bool) -> usize {
        let mut node = HEAD;
        loop {
            node = self.next[node];
            if node == HEAD || leq(node) {
                return Self::key(node);
            }
        }
    }
}
