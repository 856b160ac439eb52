//! The plane sweep that turns the contours into a planar subdivision whose regions are
//! classified by the winding rule and are each monotone (GLU's `libtess/sweep.c`, Eric
//! Veach's algorithm as `alg-outline` describes it).
//!
//! The sweep line moves left to right over the vertices in [`vert_leq`] order. The edges it
//! crosses are kept bottom to top in the [`Dict`], each with the region below it. At each
//! event the regions that end at the vertex are finished (their faces marked inside or
//! outside), the edges that start there are inserted, and neighbouring edges are checked for
//! intersections, which become new vertices (through the combine callback) and new events.
//! A vertex with no edge to the right is joined to the unprocessed part by a temporary edge
//! (`fix_upper_edge`) so that every inside region stays monotone.
//!
//! Every decision follows libtess's, in the same order, so that the mesh, and so the output,
//! is the one GLU produces. The repair of the dictionary's invariants (splices and
//! intersections) is in `sweep_fix.rs`.

use super::callbacks::TessData;
use super::dict::{Dict, Region};
use super::geom::{edge_eval, edge_sign, vert_eq, vert_leq, St};
use super::mesh::{Mesh, E_HEAD, F_HEAD, NIL, V_HEAD};
use super::queue::EventQueue;
use crate::gl::types::GLenum;
use crate::glu::consts::*;

/// What the sweep asks of its caller: data for new vertices, and reporting errors.
pub(crate) trait SweepHooks {
    /// `GLU_TESS_COMBINE`: data for a vertex at `coords` made of the four `data` with the
    /// `weights`; `None` when there is no callback or it gave none.
    fn combine(&mut self, coords: [f64; 3], data: [Option<TessData>; 4], weights: [f32; 4]) -> Option<TessData>;
    /// The error callback.
    fn error(&mut self, code: GLenum);
}

/// Sentinel edges lie beyond anything the input can reach, even merged with the largest
/// tolerance (`SENTINEL_COORD`).
const SENTINEL_COORD: f64 = 4.0 * GLU_TESS_MAX_COORD;

/// The state of one sweep.
pub(crate) struct Sweep<'a> {
    pub m: &'a mut Mesh,
    pub(super) pq: EventQueue,
    pub(super) d: Dict,
    /// The vertex the sweep line is at.
    pub(super) event: usize,
    rule: GLenum,
    /// An intersection needed data the combine callback did not give: nothing is drawn.
    pub fatal_error: bool,
    pub(super) hooks: &'a mut dyn SweepHooks,
}

/// Whether winding number `n` is inside under `rule` (`IsWindingInside`).
pub(crate) fn is_winding_inside(rule: GLenum, n: i32) -> bool {
    match rule {
        GLU_TESS_WINDING_ODD => n & 1 != 0,
        GLU_TESS_WINDING_NONZERO => n != 0,
        GLU_TESS_WINDING_POSITIVE => n > 0,
        GLU_TESS_WINDING_NEGATIVE => n < 0,
        GLU_TESS_WINDING_ABS_GEQ_TWO => !(-1..=1).contains(&n),
        _ => false,
    }
}

impl<'a> Sweep<'a> {
    /// Runs the sweep over `m` (`__gl_computeInterior`): afterwards every face is marked
    /// inside or outside and every inside face is monotone.
    pub fn compute_interior(m: &'a mut Mesh, rule: GLenum, hooks: &'a mut dyn SweepHooks) -> bool {
        let mut sw = Sweep { m, pq: EventQueue::new(), d: Dict::new(), event: NIL, rule, fatal_error: false, hooks };
        sw.remove_degenerate_edges();
        sw.init_priority_queue();
        sw.add_sentinel(-SENTINEL_COORD);
        sw.add_sentinel(SENTINEL_COORD);
        while let Some(v) = sw.pq.extract_min(&sw.m.v) {
            // Vertices at exactly the same place are merged before their event.
            while let Some(next) = sw.pq.minimum(&sw.m.v) {
                if !vert_eq(sw.st(next), sw.st(v)) {
                    break;
                }
                let next = sw.pq.extract_min(&sw.m.v).unwrap_or(next);
                let (a, b) = (sw.m.v[v].an_edge, sw.m.v[next].an_edge);
                sw.splice_merge_vertices(a, b);
            }
            sw.sweep_event(v);
        }
        sw.done_edge_dict();
        sw.remove_degenerate_faces();
        !sw.fatal_error
    }

    /// The projected position of vertex `v`.
    #[inline]
    pub(super) fn st(&self, v: usize) -> St {
        let v = &self.m.v[v];
        (v.s, v.t)
    }

    #[inline]
    pub(super) fn org_st(&self, e: usize) -> St {
        self.st(self.m.org(e))
    }

    #[inline]
    pub(super) fn dst_st(&self, e: usize) -> St {
        self.st(self.m.dst(e))
    }

    #[inline]
    pub(super) fn reg(&mut self, r: usize) -> &mut Region {
        &mut self.d.regions[r]
    }

    #[inline]
    pub(super) fn e_up(&self, r: usize) -> usize {
        self.d.regions[r].e_up
    }

    /// `eDst` takes on `eSrc`'s winding too (`AddWinding`).
    pub(super) fn add_winding(&mut self, dst: usize, src: usize) {
        self.m.e[dst].winding += self.m.e[src].winding;
        self.m.e[dst ^ 1].winding += self.m.e[src ^ 1].winding;
    }

    /// Whether edge `e1` is below or at edge `e2` where the sweep line crosses them; edges
    /// ending at the event are ordered by slope (`EdgeLeq`).
    pub(super) fn edge_leq(&self, e1: usize, e2: usize) -> bool {
        let ev = self.event;
        let (ev_st, d1, o1, d2, o2) = (self.st(ev), self.dst_st(e1), self.org_st(e1), self.dst_st(e2), self.org_st(e2));
        if self.m.dst(e1) == ev {
            if self.m.dst(e2) == ev {
                if vert_leq(o1, o2) {
                    return edge_sign(d2, o1, o2) <= 0.0;
                }
                return edge_sign(d1, o2, o1) >= 0.0;
            }
            return edge_sign(d2, ev_st, o2) <= 0.0;
        }
        if self.m.dst(e2) == ev {
            return edge_sign(d1, ev_st, o1) >= 0.0;
        }
        edge_eval(d1, ev_st, o1) >= edge_eval(d2, ev_st, o2)
    }

    /// Takes region `r` off the sweep line (`DeleteRegion`).
    pub(super) fn delete_region(&mut self, r: usize) {
        let e = self.e_up(r);
        self.m.e[e].active_region = NIL;
        self.d.delete(r);
    }

    /// Replaces a temporary upper edge by `new_edge` (`FixUpperEdge`).
    pub(super) fn fix_upper_edge(&mut self, r: usize, new_edge: usize) {
        let old = self.e_up(r);
        self.m.delete(old);
        let reg = self.reg(r);
        reg.fix_upper_edge = false;
        reg.e_up = new_edge;
        self.m.e[new_edge].active_region = r;
    }

    /// The region above the uppermost edge with `r`'s upper edge's origin, fixing a temporary
    /// edge there (`TopLeftRegion`).
    pub(super) fn top_left_region(&mut self, mut r: usize) -> usize {
        let org = self.m.org(self.e_up(r));
        loop {
            r = self.d.above(r);
            if r == NIL || self.m.org(self.e_up(r)) != org {
                break;
            }
        }
        if r != NIL && self.d.regions[r].fix_upper_edge {
            let below = self.d.below(r);
            let e = self.m.connect(self.e_up(below) ^ 1, self.m.lnext(self.e_up(r)));
            self.fix_upper_edge(r, e);
            r = self.d.above(r);
        }
        r
    }

    /// The region above the uppermost edge with `r`'s upper edge's destination
    /// (`TopRightRegion`).
    pub(super) fn top_right_region(&self, mut r: usize) -> usize {
        let dst = self.m.dst(self.e_up(r));
        loop {
            r = self.d.above(r);
            if r == NIL || self.m.dst(self.e_up(r)) != dst {
                return r;
            }
        }
    }

    /// A new region below `above` wherever `e_new_up` belongs (`AddRegionBelow`).
    pub(super) fn add_region_below(&mut self, above: usize, e_new_up: usize) -> usize {
        let region = Region { e_up: e_new_up, winding_number: 0, inside: false, dirty: false, fix_upper_edge: false };
        let r = self.insert_region(above, region);
        self.m.e[e_new_up].active_region = r;
        r
    }

    /// Inserts `region` below `above` (the top for `NIL`), walking down to the first region
    /// whose edge is below or at the new one (`dictInsertBefore` with `EdgeLeq`).
    fn insert_region(&mut self, above: usize, region: Region) -> usize {
        let mut node = Dict::start_node(above);
        loop {
            node = self.d.prev_node(node);
            if node == 0 || self.edge_leq(self.d.regions[node].e_up, region.e_up) {
                break;
            }
        }
        self.d.insert_after(node, region)
    }

    /// The winding number and inside flag from the region above (`ComputeWinding`).
    fn compute_winding(&mut self, r: usize) {
        let above = self.d.above(r);
        let n = self.d.regions[above].winding_number + self.m.e[self.e_up(r)].winding;
        let inside = is_winding_inside(self.rule, n);
        let reg = self.reg(r);
        reg.winding_number = n;
        reg.inside = inside;
    }

    /// Gives the face left of `r`'s upper edge the region's inside flag and deletes the
    /// region (`FinishRegion`).
    fn finish_region(&mut self, r: usize) {
        let e = self.e_up(r);
        let f = self.m.lface(e);
        if f != NIL {
            self.m.f[f].inside = self.d.regions[r].inside;
            self.m.f[f].an_edge = e;
        }
        self.delete_region(r);
    }

    /// Finishes the regions from `first` down to (not including) `last` whose edges share an
    /// origin, relinking the mesh to the dictionary's order; the last edge walked
    /// (`FinishLeftRegions`).
    pub(super) fn finish_left_regions(&mut self, first: usize, last: usize) -> usize {
        let mut reg_prev = first;
        let mut e_prev = self.e_up(first);
        while reg_prev != last {
            self.reg(reg_prev).fix_upper_edge = false;
            let r = self.d.below(reg_prev);
            if r == NIL {
                break;
            }
            let mut e = self.e_up(r);
            if self.m.org(e) != self.m.org(e_prev) {
                if !self.d.regions[r].fix_upper_edge {
                    self.finish_region(reg_prev);
                    break;
                }
                e = self.m.connect(self.m.lprev(e_prev), e ^ 1);
                self.fix_upper_edge(r, e);
            }
            if self.m.onext(e_prev) != e {
                self.m.splice(self.m.oprev(e), e);
                self.m.splice(e_prev, e);
            }
            self.finish_region(reg_prev);
            e_prev = self.e_up(r);
            reg_prev = r;
        }
        e_prev
    }

    /// Inserts the right-going edges from `e_first` counter-clockwise up to `e_last` below
    /// `reg_up`, computes their regions' windings and relinks the mesh to match; `e_top_left`
    /// is the edge above the vertex's left-going edges, or `NIL` (`AddRightEdges`).
    pub(super) fn add_right_edges(
        &mut self,
        reg_up: usize,
        e_first: usize,
        e_last: usize,
        e_top_left: usize,
        clean_up: bool,
    ) {
        let mut e = e_first;
        loop {
            self.add_region_below(reg_up, e ^ 1);
            e = self.m.onext(e);
            if e == e_last {
                break;
            }
        }
        let e_top_left = if e_top_left == NIL { self.m.rprev(self.e_up(self.d.below(reg_up))) } else { e_top_left };
        let (mut reg_prev, mut e_prev) = (reg_up, e_top_left);
        let mut first_time = true;
        loop {
            let r = self.d.below(reg_prev);
            if r == NIL {
                break;
            }
            let e = self.e_up(r) ^ 1;
            if self.m.org(e) != self.m.org(e_prev) {
                break;
            }
            if self.m.onext(e) != e_prev {
                self.m.splice(self.m.oprev(e), e);
                self.m.splice(self.m.oprev(e_prev), e);
            }
            let n = self.d.regions[reg_prev].winding_number - self.m.e[e].winding;
            let inside = is_winding_inside(self.rule, n);
            (self.reg(r).winding_number, self.reg(r).inside) = (n, inside);
            self.reg(reg_prev).dirty = true;
            if !first_time && self.check_for_right_splice(reg_prev) {
                self.add_winding(e, e_prev);
                self.delete_region(reg_prev);
                self.m.delete(e_prev);
            }
            first_time = false;
            reg_prev = r;
            e_prev = e;
        }
        self.reg(reg_prev).dirty = true;
        if clean_up {
            self.walk_dirty_regions(reg_prev);
        }
    }

    /// Asks the combine callback for the data of vertex `isect`; without an answer, a merge
    /// keeps the first vertex's data and an intersection is a fatal error (`CallCombine`).
    pub(super) fn call_combine(&mut self, isect: usize, data: [Option<TessData>; 4], weights: [f32; 4], needed: bool) {
        let coords = self.m.v[isect].coords;
        let first = data[0].clone();
        let out = self.hooks.combine(coords, data, weights);
        self.m.v[isect].data = match out {
            Some(d) => Some(d),
            None if !needed => first,
            None => {
                if !self.fatal_error {
                    self.hooks.error(GLU_TESS_NEED_COMBINE_CALLBACK);
                    self.fatal_error = true;
                }
                None
            }
        };
    }

    /// Merges two vertices at the same place: `e1.org` stays, `e2.org` goes
    /// (`SpliceMergeVertices`).
    pub(super) fn splice_merge_vertices(&mut self, e1: usize, e2: usize) {
        let (v1, v2) = (self.m.org(e1), self.m.org(e2));
        let data = [self.m.v[v1].data.clone(), self.m.v[v2].data.clone(), None, None];
        self.call_combine(v1, data, [0.5, 0.5, 0.0, 0.0], false);
        self.m.splice(e1, e2);
    }

    /// Connects a vertex with no right-going edge to the unprocessed part of the mesh
    /// (`ConnectRightVertex`).
    fn connect_right_vertex(&mut self, mut reg_up: usize, mut e_bottom_left: usize) {
        let mut e_top_left = self.m.onext(e_bottom_left);
        let reg_lo = self.d.below(reg_up);
        let (e_up, e_lo) = (self.e_up(reg_up), self.e_up(reg_lo));
        let mut degenerate = false;
        if self.m.dst(e_up) != self.m.dst(e_lo) {
            self.check_for_intersect(reg_up);
        }
        let ev = self.st(self.event);
        if vert_eq(self.org_st(e_up), ev) {
            self.m.splice(self.m.oprev(e_top_left), e_up);
            reg_up = self.top_left_region(reg_up);
            if reg_up == NIL {
                return;
            }
            e_top_left = self.e_up(self.d.below(reg_up));
            let below = self.d.below(reg_up);
            self.finish_left_regions(below, reg_lo);
            degenerate = true;
        }
        if vert_eq(self.org_st(e_lo), ev) {
            self.m.splice(e_bottom_left, self.m.oprev(e_lo));
            e_bottom_left = self.finish_left_regions(reg_lo, NIL);
            degenerate = true;
        }
        if degenerate {
            self.add_right_edges(reg_up, self.m.onext(e_bottom_left), e_top_left, e_top_left, true);
            return;
        }
        // Connect to the closer of the two chains' origins, as a temporary edge.
        let target = if vert_leq(self.org_st(e_lo), self.org_st(e_up)) { self.m.oprev(e_lo) } else { e_up };
        let e_new = self.m.connect(self.m.lprev(e_bottom_left), target);
        let e_new_onext = self.m.onext(e_new);
        self.add_right_edges(reg_up, e_new, e_new_onext, e_new_onext, false);
        let r = self.m.e[e_new ^ 1].active_region;
        if r != NIL {
            self.reg(r).fix_upper_edge = true;
        }
        self.walk_dirty_regions(reg_up);
    }

    /// The event lies exactly on an already-processed edge: splice it in and sweep again
    /// (`ConnectLeftDegenerate`; the other cases cannot happen once equal vertices are
    /// merged, as libtess notes).
    fn connect_left_degenerate(&mut self, reg_up: usize, v_event: usize) {
        let e = self.e_up(reg_up);
        let ev = self.st(v_event);
        if vert_eq(self.org_st(e), ev) {
            let an = self.m.v[v_event].an_edge;
            self.splice_merge_vertices(e, an);
            return;
        }
        if !vert_eq(self.dst_st(e), ev) {
            self.m.split_edge(e ^ 1);
            if self.d.regions[reg_up].fix_upper_edge {
                self.m.delete(self.m.onext(e));
                self.reg(reg_up).fix_upper_edge = false;
            }
            self.m.splice(self.m.v[v_event].an_edge, e);
            self.sweep_event(v_event);
            return;
        }
        let reg_up = self.top_right_region(reg_up);
        if reg_up == NIL {
            return;
        }
        let r = self.d.below(reg_up);
        let mut e_top_right = self.e_up(r) ^ 1;
        let e_last = self.m.onext(e_top_right);
        let mut e_top_left = e_last;
        if self.d.regions[r].fix_upper_edge {
            self.delete_region(r);
            self.m.delete(e_top_right);
            e_top_right = self.m.oprev(e_top_left);
        }
        self.m.splice(self.m.v[v_event].an_edge, e_top_right);
        if !vert_leq(self.dst_st(e_top_left), self.org_st(e_top_left)) {
            e_top_left = NIL;
        }
        self.add_right_edges(reg_up, self.m.onext(e_top_right), e_last, e_top_left, true);
    }

    /// A vertex whose edges all go right: split the region containing it by an edge to the
    /// nearer processed chain, unless the region is outside (`ConnectLeftVertex`).
    fn connect_left_vertex(&mut self, v_event: usize) {
        let probe = self.m.v[v_event].an_edge ^ 1;
        let reg_up = self.d.search(|node| self.edge_leq(probe, self.d.regions[node].e_up));
        if reg_up == NIL {
            return;
        }
        let reg_lo = self.d.below(reg_up);
        if reg_lo == NIL {
            return;
        }
        let (e_up, e_lo) = (self.e_up(reg_up), self.e_up(reg_lo));
        if edge_sign(self.dst_st(e_up), self.st(v_event), self.org_st(e_up)) == 0.0 {
            self.connect_left_degenerate(reg_up, v_event);
            return;
        }
        let r = if vert_leq(self.dst_st(e_lo), self.dst_st(e_up)) { reg_up } else { reg_lo };
        let an = self.m.v[v_event].an_edge;
        if self.d.regions[reg_up].inside || self.d.regions[r].fix_upper_edge {
            let e_new = if r == reg_up {
                self.m.connect(an ^ 1, self.m.lnext(e_up))
            } else {
                self.m.connect(self.m.dnext(e_lo), an) ^ 1
            };
            if self.d.regions[r].fix_upper_edge {
                self.fix_upper_edge(r, e_new);
            } else {
                let nr = self.add_region_below(reg_up, e_new);
                self.compute_winding(nr);
            }
            self.sweep_event(v_event);
        } else {
            self.add_right_edges(reg_up, an, an, NIL, true);
        }
    }

    /// Everything the sweep line does at vertex `v_event` (`SweepEvent`).
    pub(super) fn sweep_event(&mut self, v_event: usize) {
        self.event = v_event;
        let first = self.m.v[v_event].an_edge;
        let mut e = first;
        while self.m.e[e].active_region == NIL {
            e = self.m.onext(e);
            if e == first {
                self.connect_left_vertex(v_event);
                return;
            }
        }
        let reg_up = self.top_left_region(self.m.e[e].active_region);
        if reg_up == NIL {
            return;
        }
        let r = self.d.below(reg_up);
        let e_top_left = self.e_up(r);
        let e_bottom_left = self.finish_left_regions(r, NIL);
        if self.m.onext(e_bottom_left) == e_top_left {
            self.connect_right_vertex(reg_up, e_bottom_left);
        } else {
            self.add_right_edges(reg_up, self.m.onext(e_bottom_left), e_top_left, e_top_left, true);
        }
    }

    /// An edge at `t` spanning every input, above or below everything (`AddSentinel`).
    fn add_sentinel(&mut self, t: f64) {
        let e = self.m.make_edge_alone();
        let (o, d) = (self.m.org(e), self.m.dst(e));
        (self.m.v[o].s, self.m.v[o].t) = (SENTINEL_COORD, t);
        (self.m.v[d].s, self.m.v[d].t) = (-SENTINEL_COORD, t);
        self.event = d;
        let region = Region { e_up: e, winding_number: 0, inside: false, dirty: false, fix_upper_edge: false };
        let r = self.insert_region(NIL, region);
        self.m.e[e].active_region = r;
    }

    /// Takes the remaining regions (the sentinels, perhaps one temporary edge) off the line.
    fn done_edge_dict(&mut self) {
        loop {
            let r = self.d.min();
            if r == NIL {
                break;
            }
            self.delete_region(r);
        }
    }

    /// Removes zero-length edges and contours of fewer than three edges
    /// (`RemoveDegenerateEdges`).
    fn remove_degenerate_edges(&mut self) {
        let mut e = self.m.e[E_HEAD].next;
        while e != E_HEAD {
            let mut e_next = self.m.e[e].next;
            let mut e_lnext = self.m.lnext(e);
            if vert_eq(self.org_st(e), self.dst_st(e)) && self.m.lnext(e_lnext) != e {
                self.splice_merge_vertices(e_lnext, e);
                self.m.delete(e);
                e = e_lnext;
                e_lnext = self.m.lnext(e);
            }
            if self.m.lnext(e_lnext) == e {
                if e_lnext != e {
                    if e_lnext == e_next || e_lnext == e_next ^ 1 {
                        e_next = self.m.e[e_next].next;
                    }
                    self.m.delete(e_lnext);
                }
                if e == e_next || e == e_next ^ 1 {
                    e_next = self.m.e[e_next].next;
                }
                self.m.delete(e);
            }
            e = e_next;
        }
    }

    /// Every vertex into the event queue, then sorted (`InitPriorityQ`).
    fn init_priority_queue(&mut self) {
        let mut v = self.m.v[V_HEAD].next;
        while v != V_HEAD {
            self.m.v[v].pq_handle = self.pq.insert(&self.m.v, v);
            v = self.m.v[v].next;
        }
        self.pq.init(&self.m.v);
    }

    /// Deletes faces of two edges that splices left behind (`RemoveDegenerateFaces`).
    fn remove_degenerate_faces(&mut self) {
        let mut f = self.m.f[F_HEAD].next;
        while f != F_HEAD {
            let f_next = self.m.f[f].next;
            let e = self.m.f[f].an_edge;
            if self.m.lnext(self.m.lnext(e)) == e {
                self.add_winding(self.m.onext(e), e);
                self.m.delete(e);
            }
            f = f_next;
        }
    }
}
