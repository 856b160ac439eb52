//! The event queue: the vertices in sweep order (GLU's `libtess/priorityq.c` and
//! `priorityq-heap.c`).
//!
//! The input vertices are sorted once, by the same randomised quicksort with the same seed as
//! libtess, into an array read from its end; vertices created later (intersections) go into a
//! binary heap with deletion by handle. The minimum is whichever of the two is smaller, the
//! heap winning ties. Vertices at exactly the same place come out in the order this gives, and
//! that order decides which of two merged vertices keeps its data, so it is reproduced exactly.
//!
//! Handles: `-(i + 1)` for entry `i` of the sorted array, positive for the heap.

use super::geom::vert_leq;
use super::mesh::Vertex;

/// The heap of vertices added after the sort (`PriorityQHeap`).
#[derive(Default)]
struct Heap {
    /// `nodes[i]`: the handle at heap position `i` (1-based).
    nodes: Vec<usize>,
    /// `handles[h]`: the vertex and its heap position, or the next free handle.
    handles: Vec<(Option<usize>, usize)>,
    size: usize,
    free_list: usize,
}

fn leq(v: &[Vertex], a: usize, b: usize) -> bool {
    vert_leq((v[a].s, v[a].t), (v[b].s, v[b].t))
}

impl Heap {
    fn new() -> Self {
        // Position 1 holds handle 1 with no key, so that the minimum of an empty heap is none.
        Self { nodes: vec![0, 1], handles: vec![(None, 0), (None, 0)], size: 0, free_list: 0 }
    }

    fn key(&self, pos: usize) -> Option<usize> {
        self.handles[self.nodes[pos]].0
    }

    fn key_leq(&self, v: &[Vertex], a: usize, b: usize) -> bool {
        match (self.key(a), self.key(b)) {
            (Some(x), Some(y)) => leq(v, x, y),
            _ => false,
        }
    }

    fn place(&mut self, pos: usize, h: usize) {
        self.nodes[pos] = h;
        self.handles[h].1 = pos;
    }

    fn float_down(&mut self, v: &[Vertex], mut curr: usize) {
        let h_curr = self.nodes[curr];
        loop {
            let mut child = curr << 1;
            if child < self.size && self.key_leq(v, child + 1, child) {
                child += 1;
            }
            let stop = child > self.size || {
                let (a, b) = (self.handles[h_curr].0, self.key(child));
                matches!((a, b), (Some(x), Some(y)) if leq(v, x, y))
            };
            if stop {
                self.place(curr, h_curr);
                break;
            }
            let h_child = self.nodes[child];
            self.place(curr, h_child);
            curr = child;
        }
    }

    fn float_up(&mut self, v: &[Vertex], mut curr: usize) {
        let h_curr = self.nodes[curr];
        loop {
            let parent = curr >> 1;
            let h_parent = self.nodes[parent];
            let stop = parent == 0 || {
                let (a, b) = (self.handles[h_parent].0, self.handles[h_curr].0);
                matches!((a, b), (Some(x), Some(y)) if leq(v, x, y))
            };
            if stop {
                self.place(curr, h_curr);
                break;
            }
            self.place(curr, h_parent);
            curr = parent;
        }
    }

    fn insert(&mut self, v: &[Vertex], key: usize) -> usize {
        self.size += 1;
        let curr = self.size;
        if self.nodes.len() <= 2 * curr + 1 {
            self.nodes.resize(2 * curr + 2, 0);
        }
        let h = if self.free_list == 0 {
            if self.handles.len() <= curr {
                self.handles.resize(curr + 1, (None, 0));
            }
            curr
        } else {
            let h = self.free_list;
            self.free_list = self.handles[h].1;
            h
        };
        self.place(curr, h);
        self.handles[h].0 = Some(key);
        self.float_up(v, curr);
        h
    }

    fn minimum(&self) -> Option<usize> {
        self.key(1)
    }

    fn extract_min(&mut self, v: &[Vertex]) -> Option<usize> {
        let h_min = self.nodes[1];
        let min = self.handles[h_min].0;
        if self.size > 0 {
            let last = self.nodes[self.size];
            self.place(1, last);
            self.handles[h_min] = (None, self.free_list);
            self.free_list = h_min;
            self.size -= 1;
            if self.size > 0 {
                self.float_down(v, 1);
            }
        }
        min
    }

    fn delete(&mut self, v: &[Vertex], h: usize) {
        let Some(&(Some(_), curr)) = self.handles.get(h) else { return };
        let last = self.nodes[self.size];
        self.place(curr, last);
        self.size -= 1;
        if curr <= self.size {
            if curr <= 1 || self.key_leq(v, curr >> 1, curr) {
                self.float_down(v, curr);
            } else {
                self.float_up(v, curr);
            }
        }
        self.handles[h] = (None, self.free_list);
        self.free_list = h;
    }
}

/// The event queue (`PriorityQSort`).
pub(crate) struct EventQueue {
    heap: Heap,
    keys: Vec<Option<usize>>,
    /// Indices into `keys`, sorted so that the minimum is last.
    order: Vec<usize>,
    size: usize,
    initialized: bool,
}

impl EventQueue {
    pub fn new() -> Self {
        Self { heap: Heap::new(), keys: Vec::new(), order: Vec::new(), size: 0, initialized: false }
    }

    /// Adds vertex `key`; its handle for [`delete`](Self::delete).
    pub fn insert(&mut self, v: &[Vertex], key: usize) -> i64 {
        if self.initialized {
            return self.heap.insert(v, key) as i64;
        }
        self.keys.push(Some(key));
        self.size = self.keys.len();
        -(self.keys.len() as i64)
    }

    /// Sorts the vertices inserted so far (`__gl_pqSortInit`).
    pub fn init(&mut self, v: &[Vertex]) {
        self.order = (0..self.size).collect();
        let keys = &self.keys;
        let lt = |a: usize, b: usize| !leq(v, keys[b].unwrap_or(0), keys[a].unwrap_or(0));
        sort_descending(&mut self.order, lt);
        self.initialized = true;
    }

    fn sort_min(&self) -> Option<usize> {
        self.keys[self.order[self.size - 1]]
    }

    /// The smallest vertex without removing it.
    pub fn minimum(&self, v: &[Vertex]) -> Option<usize> {
        if self.size == 0 {
            return self.heap.minimum();
        }
        let sort_min = self.sort_min();
        match (self.heap.minimum(), sort_min) {
            (Some(h), Some(s)) if self.heap.size > 0 && leq(v, h, s) => Some(h),
            _ => sort_min,
        }
    }

    /// Removes and returns the smallest vertex.
    pub fn extract_min(&mut self, v: &[Vertex]) -> Option<usize> {
        if self.size == 0 {
            return self.heap.extract_min(v);
        }
        let sort_min = self.sort_min();
        if self.heap.size > 0 {
            if let (Some(h), Some(s)) = (self.heap.minimum(), sort_min) {
                if leq(v, h, s) {
                    return self.heap.extract_min(v);
                }
            }
        }
        loop {
            self.size -= 1;
            if self.size == 0 || self.sort_min().is_some() {
                break;
            }
        }
        sort_min
    }

    /// Removes the vertex with handle `h`.
    pub fn delete(&mut self, v: &[Vertex], h: i64) {
        if h >= 0 {
            self.heap.delete(v, h as usize);
            return;
        }
        let Some(slot) = self.keys.get_mut((-(h + 1)) as usize) else { return };
        *slot = None;
        while self.size > 0 && self.sort_min().is_none() {
            self.size -= 1;
        }
    }
}

/// Sorts `order` so that `lt(order[i + 1], order[i])` never holds backwards: largest first
/// (libtess's randomised quicksort: the same seed, the same pivots, insertion sort below 11
/// entries, so that equal keys end in the same order).
fn sort_descending(order: &mut [usize], lt: impl Fn(usize, usize) -> bool) {
    let gt = |a: usize, b: usize| lt(b, a);
    let at = |order: &[usize], k: isize| order[k as usize];
    let mut seed: u64 = 2_016_473_283;
    // Bounds as in libtess, inclusive and signed: `r` may end one below `p`.
    let mut stack: Vec<(isize, isize)> = vec![(0, order.len() as isize - 1)];
    while let Some((mut p, mut r)) = stack.pop() {
        while r > p + 10 {
            seed = seed.wrapping_mul(1_539_415_821).wrapping_add(1);
            let i = p + (seed % (r - p + 1) as u64) as isize;
            order.swap(i as usize, p as usize);
            let piv = at(order, p);
            let (mut i, mut j) = (p - 1, r + 1);
            loop {
                loop {
                    i += 1;
                    if !gt(at(order, i), piv) {
                        break;
                    }
                }
                loop {
                    j -= 1;
                    if !lt(at(order, j), piv) {
                        break;
                    }
                }
                order.swap(i as usize, j as usize);
                if i >= j {
                    break;
                }
            }
            order.swap(i as usize, j as usize);
            if i - p < r - j {
                stack.push((j + 1, r));
                r = i - 1;
            } else {
                stack.push((p, i - 1));
                p = j + 1;
            }
        }
        let mut i = p + 1;
        while i <= r {
            let piv = at(order, i);
            let mut j = i;
            while j > p && lt(at(order, j - 1), piv) {
                order[j as usize] = order[j as usize - 1];
                j -= 1;
            }
            order[j as usize] = piv;
            i += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glu::tess::mesh::Mesh;

    #[test]
    fn vertices_come_out_in_sweep_order_from_both_halves() {
        let mut m = Mesh::new();
        let pts = [(3.0, 1.0), (1.0, 5.0), (1.0, 2.0), (7.0, 0.0), (0.5, 9.0)];
        for _ in 0..40 {
            for &(s, t) in &pts {
                let e = m.make_edge_alone();
                let v = m.org(e);
                (m.v[v].s, m.v[v].t) = (s + m.v.len() as f64 * 0.01, t);
            }
        }
        let mut q = EventQueue::new();
        for v in 1..m.v.len() {
            q.insert(&m.v, v);
        }
        q.init(&m.v);
        let late = m.v.len();
        m.v.push(m.v[1].clone());
        (m.v[late].s, m.v[late].t) = (2.0, 0.0);
        q.insert(&m.v, late);
        let mut last = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        let mut n = 0;
        while let Some(v) = q.extract_min(&m.v) {
            let st = (m.v[v].s, m.v[v].t);
            assert!(vert_leq(last, st));
            last = st;
            n += 1;
        }
        assert_eq!(n, m.v.len() - 1);
    }
}
