//! The half-edge mesh the tessellator works on (GLU's `libtess/mesh.c`, after Guibas and
//! Stolfi's quad-edge structure restricted to one orientation).
//!
//! Every edge is two half-edges, `e` and `e.sym`, stored side by side (`sym = e ^ 1`). Each
//! half-edge knows the next edge counter-clockwise around its origin (`onext`) and around its
//! left face (`lnext`); everything else is derived (`dst = sym.org`, `oprev = sym.lnext`, ...).
//! Vertices, faces and edges are also kept on circular lists with a dummy head each, in the
//! order libtess keeps them: that order decides the order of the sweep's ties and of the
//! rendered primitives, so the operations below insert and unlink exactly where GLU does.
//!
//! Items live in arenas addressed by index; a deleted item is unlinked and never reused (a
//! tessellation is short-lived). [`NIL`] is C's `NULL`.

use super::callbacks::TessData;

/// No item (C's `NULL`).
pub(crate) const NIL: usize = usize::MAX;
/// The dummy heads: vertex 0, face 0, half-edges 0 and 1.
pub(crate) const V_HEAD: usize = 0;
pub(crate) const F_HEAD: usize = 0;
pub(crate) const E_HEAD: usize = 0;

/// A vertex: its user data, its coordinates and their projection `(s, t)` on the sweep plane.
#[derive(Clone)]
pub(crate) struct Vertex {
    pub next: usize,
    pub prev: usize,
    pub an_edge: usize,
    pub data: Option<TessData>,
    pub coords: [f64; 3],
    pub s: f64,
    pub t: f64,
    /// The vertex's handle in the event queue.
    pub pq_handle: i64,
}

/// A face (a loop of half-edges), "inside" once the sweep has classified it.
#[derive(Clone, Debug)]
pub(crate) struct Face {
    pub next: usize,
    pub prev: usize,
    pub an_edge: usize,
    pub marked: bool,
    pub inside: bool,
}

/// A half-edge.
#[derive(Clone, Debug)]
pub(crate) struct HalfEdge {
    /// The edge list: `next` of the even half, `sym.next` walks backwards.
    pub next: usize,
    pub onext: usize,
    pub lnext: usize,
    pub org: usize,
    pub lface: usize,
    /// The sweep's region whose upper edge this is.
    pub active_region: usize,
    /// How the winding number changes crossing from the right face to the left.
    pub winding: i32,
}

/// The mesh: three arenas whose first items are the list heads.
pub(crate) struct Mesh {
    pub v: Vec<Vertex>,
    pub f: Vec<Face>,
    pub e: Vec<HalfEdge>,
}

const fn blank_edge(next: usize) -> HalfEdge {
    HalfEdge { next, onext: NIL, lnext: NIL, org: NIL, lface: NIL, active_region: NIL, winding: 0 }
}

fn blank_vertex() -> Vertex {
    Vertex { next: NIL, prev: NIL, an_edge: NIL, data: None, coords: [0.0; 3], s: 0.0, t: 0.0, pq_handle: 0 }
}

const fn blank_face() -> Face {
    Face { next: NIL, prev: NIL, an_edge: NIL, marked: false, inside: false }
}

impl Mesh {
    /// An empty mesh: the heads only (`__gl_meshNewMesh`).
    pub fn new() -> Self {
        let mut v = blank_vertex();
        (v.next, v.prev) = (V_HEAD, V_HEAD);
        let mut f = blank_face();
        (f.next, f.prev) = (F_HEAD, F_HEAD);
        Self { v: vec![v], f: vec![f], e: vec![blank_edge(0), blank_edge(1)] }
    }

    // The derived links of `mesh.h`.
    #[inline]
    pub fn onext(&self, e: usize) -> usize {
        self.e[e].onext
    }
    #[inline]
    pub fn lnext(&self, e: usize) -> usize {
        self.e[e].lnext
    }
    #[inline]
    pub fn org(&self, e: usize) -> usize {
        self.e[e].org
    }
    #[inline]
    pub fn dst(&self, e: usize) -> usize {
        self.e[e ^ 1].org
    }
    #[inline]
    pub fn lface(&self, e: usize) -> usize {
        self.e[e].lface
    }
    #[inline]
    pub fn rface(&self, e: usize) -> usize {
        self.e[e ^ 1].lface
    }
    #[inline]
    pub fn oprev(&self, e: usize) -> usize {
        self.e[e ^ 1].lnext
    }
    #[inline]
    pub fn lprev(&self, e: usize) -> usize {
        self.e[e].onext ^ 1
    }
    #[inline]
    pub fn dprev(&self, e: usize) -> usize {
        self.e[e].lnext ^ 1
    }
    #[inline]
    pub fn rprev(&self, e: usize) -> usize {
        self.e[e ^ 1].onext
    }
    #[inline]
    pub fn dnext(&self, e: usize) -> usize {
        self.rprev(e) ^ 1
    }

    /// A face's "inside" flag; a missing face (`NULL`) is outside.
    pub fn inside(&self, f: usize) -> bool {
        f != NIL && self.f[f].inside
    }

    /// A new pair of half-edges forming their own loop, inserted in the edge list before
    /// `e_next` (`MakeEdge`).
    fn make_edge(&mut self, e_next: usize) -> usize {
        let e_next = e_next & !1;
        let e = self.e.len();
        let e_prev = self.e[e_next ^ 1].next;
        self.e.push(blank_edge(e_next));
        self.e.push(blank_edge(e_prev));
        self.e[e_prev ^ 1].next = e;
        self.e[e_next ^ 1].next = e ^ 1;
        self.e[e].onext = e;
        self.e[e].lnext = e ^ 1;
        self.e[e ^ 1].onext = e ^ 1;
        self.e[e ^ 1].lnext = e;
        e
    }

    /// Exchanges `a.onext` and `b.onext` (and the matching `lnext`s): joins two origin rings
    /// into one or splits one into two (`Splice`).
    fn splice_rings(&mut self, a: usize, b: usize) {
        let a_onext = self.e[a].onext;
        let b_onext = self.e[b].onext;
        self.e[a_onext ^ 1].lnext = b;
        self.e[b_onext ^ 1].lnext = a;
        self.e[a].onext = b_onext;
        self.e[b].onext = a_onext;
    }

    /// Makes `v` (already allocated) the origin of every edge around `e_orig`, inserted in the
    /// vertex list before `v_next` (`MakeVertex`).
    fn make_vertex(&mut self, e_orig: usize, v_next: usize) -> usize {
        let v = self.v.len();
        let v_prev = self.v[v_next].prev;
        let mut vert = blank_vertex();
        (vert.prev, vert.next, vert.an_edge) = (v_prev, v_next, e_orig);
        self.v.push(vert);
        self.v[v_prev].next = v;
        self.v[v_next].prev = v;
        let mut e = e_orig;
        loop {
            self.e[e].org = v;
            e = self.e[e].onext;
            if e == e_orig {
                break;
            }
        }
        v
    }

    /// A new face left of every edge of the loop of `e_orig`, inserted before `f_next`; it
    /// inherits `f_next`'s "inside" flag (`MakeFace`).
    fn make_face(&mut self, e_orig: usize, f_next: usize) -> usize {
        let f = self.f.len();
        let f_prev = self.f[f_next].prev;
        let mut face = blank_face();
        (face.prev, face.next, face.an_edge) = (f_prev, f_next, e_orig);
        face.inside = self.f[f_next].inside;
        self.f.push(face);
        self.f[f_prev].next = f;
        self.f[f_next].prev = f;
        let mut e = e_orig;
        loop {
            self.e[e].lface = f;
            e = self.e[e].lnext;
            if e == e_orig {
                break;
            }
        }
        f
    }

    /// Unlinks the edge pair of `e` from the edge list (`KillEdge`).
    fn kill_edge(&mut self, e: usize) {
        let e = e & !1;
        let e_next = self.e[e].next;
        let e_prev = self.e[e ^ 1].next;
        self.e[e_next ^ 1].next = e_prev;
        self.e[e_prev ^ 1].next = e_next;
    }

    /// Unlinks `v`, giving its edges the origin `new_org` (`KillVertex`).
    fn kill_vertex(&mut self, v: usize, new_org: usize) {
        let start = self.v[v].an_edge;
        let mut e = start;
        loop {
            self.e[e].org = new_org;
            e = self.e[e].onext;
            if e == start {
                break;
            }
        }
        let (prev, next) = (self.v[v].prev, self.v[v].next);
        self.v[next].prev = prev;
        self.v[prev].next = next;
    }

    /// Unlinks `f`, giving its edges the left face `new_lface` (`KillFace`).
    fn kill_face(&mut self, f: usize, new_lface: usize) {
        let start = self.f[f].an_edge;
        let mut e = start;
        loop {
            self.e[e].lface = new_lface;
            e = self.e[e].lnext;
            if e == start {
                break;
            }
        }
        let (prev, next) = (self.f[f].prev, self.f[f].next);
        self.f[next].prev = prev;
        self.f[prev].next = next;
    }

    /// One edge, two vertices and a loop (`__gl_meshMakeEdge`).
    pub fn make_edge_alone(&mut self) -> usize {
        let e = self.make_edge(E_HEAD);
        self.make_vertex(e, V_HEAD);
        self.make_vertex(e ^ 1, V_HEAD);
        self.make_face(e, F_HEAD);
        e
    }

    /// GLU's basic operation (`__gl_meshSplice`): exchanges `e_org.onext` and `e_dst.onext`,
    /// merging or splitting their vertices and faces as the rings join or part.
    pub fn splice(&mut self, e_org: usize, e_dst: usize) {
        if e_org == e_dst {
            return;
        }
        let mut joining_vertices = false;
        let mut joining_loops = false;
        if self.org(e_dst) != self.org(e_org) {
            joining_vertices = true;
            self.kill_vertex(self.org(e_dst), self.org(e_org));
        }
        if self.lface(e_dst) != self.lface(e_org) {
            joining_loops = true;
            self.kill_face(self.lface(e_dst), self.lface(e_org));
        }
        self.splice_rings(e_dst, e_org);
        if !joining_vertices {
            let org = self.org(e_org);
            self.make_vertex(e_dst, org);
            self.v[org].an_edge = e_org;
        }
        if !joining_loops {
            let lface = self.lface(e_org);
            self.make_face(e_dst, lface);
            self.f[lface].an_edge = e_org;
        }
    }

    /// Removes the edge `e_del`, joining faces or splitting them as needed
    /// (`__gl_meshDelete`).
    pub fn delete(&mut self, e_del: usize) {
        let e_sym = e_del ^ 1;
        let mut joining_loops = false;
        if self.lface(e_del) != self.rface(e_del) {
            joining_loops = true;
            self.kill_face(self.lface(e_del), self.rface(e_del));
        }
        if self.onext(e_del) == e_del {
            self.kill_vertex(self.org(e_del), NIL);
        } else {
            let (rface, oprev) = (self.rface(e_del), self.oprev(e_del));
            self.f[rface].an_edge = oprev;
            let org = self.org(e_del);
            self.v[org].an_edge = self.onext(e_del);
            self.splice_rings(e_del, oprev);
            if !joining_loops {
                let lface = self.lface(e_del);
                self.make_face(e_del, lface);
            }
        }
        if self.onext(e_sym) == e_sym {
            self.kill_vertex(self.org(e_sym), NIL);
            self.kill_face(self.lface(e_sym), NIL);
        } else {
            let lface = self.lface(e_del);
            self.f[lface].an_edge = self.oprev(e_sym);
            let org = self.org(e_sym);
            self.v[org].an_edge = self.onext(e_sym);
            let oprev = self.oprev(e_sym);
            self.splice_rings(e_sym, oprev);
        }
        self.kill_edge(e_del);
    }

    /// A new edge from `e_org.dst` to a new vertex, in `e_org`'s left face
    /// (`__gl_meshAddEdgeVertex`).
    pub fn add_edge_vertex(&mut self, e_org: usize) -> usize {
        let e_new = self.make_edge(e_org);
        let lnext = self.lnext(e_org);
        self.splice_rings(e_new, lnext);
        let dst = self.dst(e_org);
        self.e[e_new].org = dst;
        self.make_vertex(e_new ^ 1, dst);
        let lface = self.lface(e_org);
        self.e[e_new].lface = lface;
        self.e[e_new ^ 1].lface = lface;
        e_new
    }

    /// Splits `e_org` in two at a new vertex: `e_org` keeps its origin and the returned edge
    /// goes on to the old destination (`__gl_meshSplitEdge`).
    pub fn split_edge(&mut self, e_org: usize) -> usize {
        let e_new = self.add_edge_vertex(e_org) ^ 1;
        let sym = e_org ^ 1;
        let oprev = self.oprev(sym);
        self.splice_rings(sym, oprev);
        self.splice_rings(sym, e_new);
        self.e[sym].org = self.org(e_new);
        let new_dst = self.dst(e_new);
        self.v[new_dst].an_edge = e_new ^ 1;
        self.e[e_new ^ 1].lface = self.rface(e_org);
        self.e[e_new].winding = self.e[e_org].winding;
        self.e[e_new ^ 1].winding = self.e[sym].winding;
        e_new
    }

    /// A new edge from `e_org.dst` to `e_dst.org`, splitting a face in two or joining two
    /// loops (`__gl_meshConnect`).
    pub fn connect(&mut self, e_org: usize, e_dst: usize) -> usize {
        let e_new = self.make_edge(e_org);
        let e_new_sym = e_new ^ 1;
        let mut joining_loops = false;
        if self.lface(e_dst) != self.lface(e_org) {
            joining_loops = true;
            self.kill_face(self.lface(e_dst), self.lface(e_org));
        }
        let lnext = self.lnext(e_org);
        self.splice_rings(e_new, lnext);
        self.splice_rings(e_new_sym, e_dst);
        self.e[e_new].org = self.dst(e_org);
        self.e[e_new_sym].org = self.org(e_dst);
        let lface = self.lface(e_org);
        self.e[e_new].lface = lface;
        self.e[e_new_sym].lface = lface;
        self.f[lface].an_edge = e_new_sym;
        if !joining_loops {
            self.make_face(e_new, lface);
        }
        e_new
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Walks `lnext` from `e` and counts the loop.
    fn loop_len(m: &Mesh, e: usize) -> usize {
        let mut n = 1;
        let mut x = m.lnext(e);
        while x != e {
            n += 1;
            x = m.lnext(x);
        }
        n
    }

    #[test]
    fn a_contour_built_by_splitting_is_one_loop_with_two_faces() {
        let mut m = Mesh::new();
        let e = m.make_edge_alone();
        m.splice(e, e ^ 1);
        let mut last = e;
        for _ in 0..3 {
            m.split_edge(last);
            last = m.lnext(last);
        }
        assert_eq!(loop_len(&m, e), 4);
        assert_eq!(loop_len(&m, e ^ 1), 4);
        assert_ne!(m.lface(e), m.rface(e));
        // The diagonal from the second vertex to the fourth.
        let c = m.connect(e, m.lnext(m.lnext(m.lnext(e))));
        assert_eq!(loop_len(&m, c), 3);
        assert_eq!(loop_len(&m, c ^ 1), 3);
        m.delete(c);
        assert_eq!(loop_len(&m, e), 4);
    }
}
