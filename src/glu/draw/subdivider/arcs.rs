//! GLU's trim arcs and bins (`internals/arc.h`, `arc.cc`, `bin.h`, `bin.cc`): each arc is a
//! polyline in (u, v) (`PwlArc`), linked to the arcs before and after it in its loop; a bin is
//! GLU's singly linked list of arcs, a stack whose head is where arcs are added and removed.
//! The order of a bin decides the order in which GLU cuts and draws, so it is kept exactly.

/// Which side of a region an arc created by the subdivision lies on (GLU `arc_side`); the
/// user's trim arcs have none.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Side {
    None,
    Right,
    Top,
    Left,
    Bottom,
}

/// Index of an arc in [`Arcs`].
pub(crate) type ArcId = usize;

/// One arc (GLU `Arc` with its `PwlArc`).
#[derive(Clone, Debug)]
pub(crate) struct Arc {
    pub pts: Vec<[f32; 2]>,
    pub prev: ArcId,
    pub next: ArcId,
    pub side: Side,
    /// A border or cut line not sampled yet: two points, sampled by the next
    /// `Subdivider::tessellation` (GLU's `bezier_tag`).
    pub bezier: bool,
    /// GLU's `tail_tag`: the arc's tail lies on the line being cut along.
    pub itail: bool,
    pub mark: bool,
}

/// Every arc of a surface's trimming, linked in loops.
#[derive(Clone, Debug, Default)]
pub(crate) struct Arcs {
    arcs: Vec<Arc>,
}

impl std::ops::Index<ArcId> for Arcs {
    type Output = Arc;
    fn index(&self, id: ArcId) -> &Arc {
        &self.arcs[id]
    }
}

impl std::ops::IndexMut<ArcId> for Arcs {
    fn index_mut(&mut self, id: ArcId) -> &mut Arc {
        &mut self.arcs[id]
    }
}

impl Arcs {
    /// A new arc linked to itself.
    pub fn add(&mut self, pts: Vec<[f32; 2]>, side: Side, bezier: bool) -> ArcId {
        let id = self.arcs.len();
        self.arcs.push(Arc { pts, prev: id, next: id, side, bezier, itail: false, mark: false });
        id
    }

    /// GLU `Arc::append`: links `id` after `after` in its loop (alone when `after` is none).
    pub fn append(&mut self, id: ArcId, after: Option<ArcId>) -> ArcId {
        if let Some(p) = after {
            let n = self[p].next;
            self[id].next = n;
            self[id].prev = p;
            self[n].prev = id;
            self[p].next = id;
        }
        id
    }

    /// The arc's first point (GLU `Arc::tail`).
    pub fn tail(&self, id: ArcId) -> [f32; 2] {
        self[id].pts[0]
    }

    /// The next arc's first point (GLU `Arc::head`).
    pub fn head(&self, id: ArcId) -> [f32; 2] {
        self.tail(self[id].next)
    }

    /// The arc's own last point (GLU `Arc::rhead`).
    pub fn rhead(&self, id: ArcId) -> [f32; 2] {
        *self[id].pts.last().expect("arcs have points")
    }

    /// The arcs of the loop through `id`, from `id` on.
    pub fn loop_of(&self, id: ArcId) -> Vec<ArcId> {
        let mut out = vec![id];
        let mut a = self[id].next;
        while a != id && out.len() <= self.arcs.len() {
            out.push(a);
            a = self[a].next;
        }
        out
    }
}

/// GLU's `Bin`: arcs added at the head and taken from it; walked from the head.
#[derive(Clone, Debug, Default)]
pub(crate) struct Bin {
    /// The head is the last element.
    stack: Vec<ArcId>,
}

impl Bin {
    /// `Bin::addarc`.
    pub fn add(&mut self, id: ArcId) {
        self.stack.push(id);
    }

    /// `Bin::removearc`.
    pub fn remove(&mut self) -> Option<ArcId> {
        self.stack.pop()
    }

    /// `Bin::isnonempty`.
    pub fn is_empty(&self) -> bool {
        self.stack.is_empty()
    }

    /// The arcs from the head (`firstarc`, `nextarc`).
    pub fn arcs(&self) -> Vec<ArcId> {
        self.stack.iter().rev().copied().collect()
    }

    /// `Bin::remove_this_arc`.
    pub fn remove_this(&mut self, id: ArcId) {
        if let Some(k) = self.stack.iter().rposition(|&a| a == id) {
            self.stack.remove(k);
        }
    }

    /// `Bin::numarcs`.
    pub fn len(&self) -> usize {
        self.stack.len()
    }
}

impl Bin {
    /// Puts `orphan` right after `parent` (towards the tail) if `parent` is in this bin, as
    /// GLU's `Bin::adopt` relinks it.
    pub fn insert_after(&mut self, parent: ArcId, orphan: ArcId) -> bool {
        match self.stack.iter().position(|&a| a == parent) {
            Some(k) => {
                self.stack.insert(k, orphan);
                true
            }
            None => false,
        }
    }
}
