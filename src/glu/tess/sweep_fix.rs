//! Keeping the sweep's dictionary ordered: neighbouring edges that touch are spliced together,
//! edges that cross are split at their intersection (a new vertex, whose data comes from the
//! combine callback), and the dirty regions are walked until no more changes are needed
//! (GLU's `libtess/sweep.c`: `CheckForRightSplice`, `CheckForLeftSplice`,
//! `CheckForIntersect`, `WalkDirtyRegions`).
//!
//! The splices are libtess's "combinatorial solution to a numerical problem": whenever
//! rounding puts a vertex on the wrong side of an edge, the vertex is spliced into the edge,
//! which keeps the sweep consistent however degenerate the input.

use super::callbacks::TessData;
use super::geom::{edge_intersect, edge_sign, vert_eq, vert_leq, St};
use super::mesh::NIL;
use super::sweep::Sweep;

impl Sweep<'_> {
    fn mark_dirty(&mut self, r: usize) {
        if r != NIL {
            self.reg(r).dirty = true;
        }
    }

    /// Makes sure `reg_up`'s upper edge's origin is above its lower edge, or the lower edge's
    /// origin below the upper edge, whichever origin is leftmost, by splicing the offending
    /// vertex into the other edge; true if anything changed (`CheckForRightSplice`).
    pub(super) fn check_for_right_splice(&mut self, reg_up: usize) -> bool {
        let reg_lo = self.d.below(reg_up);
        let (e_up, e_lo) = (self.e_up(reg_up), self.e_up(reg_lo));
        let (org_up, org_lo) = (self.org_st(e_up), self.org_st(e_lo));
        if vert_leq(org_up, org_lo) {
            if edge_sign(self.dst_st(e_lo), org_up, org_lo) > 0.0 {
                return false;
            }
            if !vert_eq(org_up, org_lo) {
                self.m.split_edge(e_lo ^ 1);
                self.m.splice(e_up, self.m.oprev(e_lo));
                self.mark_dirty(reg_up);
                self.mark_dirty(reg_lo);
            } else if self.m.org(e_up) != self.m.org(e_lo) {
                let h = self.m.v[self.m.org(e_up)].pq_handle;
                self.pq.delete(&self.m.v, h);
                self.splice_merge_vertices(self.m.oprev(e_lo), e_up);
            }
        } else {
            if edge_sign(self.dst_st(e_up), org_lo, org_up) < 0.0 {
                return false;
            }
            self.mark_dirty(reg_up);
            self.mark_dirty(self.d.above(reg_up));
            self.m.split_edge(e_up ^ 1);
            self.m.splice(self.m.oprev(e_lo), e_up);
        }
        true
    }

    /// The same for the destinations, whichever is rightmost (`CheckForLeftSplice`).
    pub(super) fn check_for_left_splice(&mut self, reg_up: usize) -> bool {
        let reg_lo = self.d.below(reg_up);
        let (e_up, e_lo) = (self.e_up(reg_up), self.e_up(reg_lo));
        let (dst_up, dst_lo) = (self.dst_st(e_up), self.dst_st(e_lo));
        let inside = self.d.regions[reg_up].inside;
        if vert_leq(dst_up, dst_lo) {
            if edge_sign(dst_up, dst_lo, self.org_st(e_up)) < 0.0 {
                return false;
            }
            self.mark_dirty(reg_up);
            self.mark_dirty(self.d.above(reg_up));
            let e = self.m.split_edge(e_up);
            self.m.splice(e_lo ^ 1, e);
            let f = self.m.lface(e);
            if f != NIL {
                self.m.f[f].inside = inside;
            }
        } else {
            if edge_sign(dst_lo, dst_up, self.org_st(e_lo)) > 0.0 {
                return false;
            }
            self.mark_dirty(reg_up);
            self.mark_dirty(reg_lo);
            let e = self.m.split_edge(e_lo);
            self.m.splice(self.m.lnext(e_up), e_lo ^ 1);
            let f = self.m.rface(e);
            if f != NIL {
                self.m.f[f].inside = inside;
            }
        }
        true
    }

    /// Weights that make `isect` a combination of `org` and `dst` (half the total, split by
    /// the L1 distances), adding that combination to its coordinates (`VertexWeights`).
    fn vertex_weights(&mut self, isect: usize, org: usize, dst: usize) -> [f32; 2] {
        let (i, o, d) = (self.st(isect), self.st(org), self.st(dst));
        let t1 = (o.0 - i.0).abs() + (o.1 - i.1).abs();
        let t2 = (d.0 - i.0).abs() + (d.1 - i.1).abs();
        let w0 = (0.5 * t2 / (t1 + t2)) as f32;
        let w1 = (0.5 * t1 / (t1 + t2)) as f32;
        let (oc, dc) = (self.m.v[org].coords, self.m.v[dst].coords);
        let c = &mut self.m.v[isect].coords;
        for k in 0..3 {
            c[k] += f64::from(w0) * oc[k] + f64::from(w1) * dc[k];
        }
        [w0, w1]
    }

    /// Coordinates and user data for an intersection vertex (`GetIntersectData`).
    fn get_intersect_data(&mut self, isect: usize, ends: [usize; 4]) {
        let data: [Option<TessData>; 4] = ends.map(|v| self.m.v[v].data.clone());
        self.m.v[isect].coords = [0.0; 3];
        let [a, b] = self.vertex_weights(isect, ends[0], ends[1]);
        let [c, d] = self.vertex_weights(isect, ends[2], ends[3]);
        self.call_combine(isect, data, [a, b, c, d], true);
    }

    /// Checks `reg_up`'s two edges for an intersection and, if they cross, splits both there
    /// (a new event). True when it recursed into `add_right_edges`, which has then walked
    /// every dirty region (`CheckForIntersect`).
    pub(super) fn check_for_intersect(&mut self, mut reg_up: usize) -> bool {
        let mut reg_lo = self.d.below(reg_up);
        let (e_up, mut e_lo) = (self.e_up(reg_up), self.e_up(reg_lo));
        let (org_up, org_lo) = (self.m.org(e_up), self.m.org(e_lo));
        let (dst_up, dst_lo) = (self.m.dst(e_up), self.m.dst(e_lo));
        if org_up == org_lo {
            return false;
        }
        let (ou, ol, du, dl) = (self.st(org_up), self.st(org_lo), self.st(dst_up), self.st(dst_lo));
        let t_min_up = if ou.1 <= du.1 { ou.1 } else { du.1 };
        let t_max_lo = if ol.1 >= dl.1 { ol.1 } else { dl.1 };
        if t_min_up > t_max_lo {
            return false;
        }
        if vert_leq(ou, ol) {
            if edge_sign(dl, ou, ol) > 0.0 {
                return false;
            }
        } else if edge_sign(du, ol, ou) < 0.0 {
            return false;
        }
        let ev = self.st(self.event);
        let mut isect: St = edge_intersect(du, ou, dl, ol);
        if vert_leq(isect, ev) {
            // Rounding put it left of the sweep line: use the event itself.
            isect = ev;
        }
        let org_min = if vert_leq(ou, ol) { ou } else { ol };
        if vert_leq(org_min, isect) {
            isect = org_min;
        }
        if vert_eq(isect, ou) || vert_eq(isect, ol) {
            self.check_for_right_splice(reg_up);
            return false;
        }
        let event = self.event;
        let up_wrong = !vert_eq(du, ev) && edge_sign(du, ev, isect) >= 0.0;
        let lo_wrong = !vert_eq(dl, ev) && edge_sign(dl, ev, isect) <= 0.0;
        if up_wrong || lo_wrong {
            // The new edges would pass on the wrong side of the event.
            if dst_lo == event {
                self.m.split_edge(e_up ^ 1);
                self.m.splice(e_lo ^ 1, e_up);
                reg_up = self.top_left_region(reg_up);
                if reg_up == NIL {
                    return true;
                }
                let below = self.d.below(reg_up);
                let e_up = self.e_up(below);
                self.finish_left_regions(below, reg_lo);
                self.add_right_edges(reg_up, self.m.oprev(e_up), e_up, e_up, true);
                return true;
            }
            if dst_up == event {
                self.m.split_edge(e_lo ^ 1);
                self.m.splice(self.m.lnext(e_up), self.m.oprev(e_lo));
                reg_lo = reg_up;
                reg_up = self.top_right_region(reg_up);
                if reg_up == NIL {
                    return true;
                }
                let e = self.m.rprev(self.e_up(self.d.below(reg_up)));
                self.reg(reg_lo).e_up = self.m.oprev(e_lo);
                e_lo = self.finish_left_regions(reg_lo, NIL);
                self.add_right_edges(reg_up, self.m.onext(e_lo), self.m.rprev(e_up), e, true);
                return true;
            }
            // Called from `connect_right_vertex`: split the edge passing on the wrong side at
            // the event, and leave the rest to it.
            if edge_sign(du, ev, isect) >= 0.0 {
                self.mark_dirty(self.d.above(reg_up));
                self.mark_dirty(reg_up);
                self.m.split_edge(e_up ^ 1);
                let o = self.m.org(e_up);
                (self.m.v[o].s, self.m.v[o].t) = ev;
            }
            if edge_sign(dl, ev, isect) <= 0.0 {
                self.mark_dirty(reg_up);
                self.mark_dirty(reg_lo);
                self.m.split_edge(e_lo ^ 1);
                let o = self.m.org(e_lo);
                (self.m.v[o].s, self.m.v[o].t) = ev;
            }
            return false;
        }
        // The general case: split both edges and splice them at the new vertex.
        self.m.split_edge(e_up ^ 1);
        self.m.split_edge(e_lo ^ 1);
        self.m.splice(self.m.oprev(e_lo), e_up);
        let v = self.m.org(e_up);
        (self.m.v[v].s, self.m.v[v].t) = isect;
        self.m.v[v].pq_handle = self.pq.insert(&self.m.v, v);
        self.get_intersect_data(v, [org_up, dst_up, org_lo, dst_lo]);
        self.mark_dirty(self.d.above(reg_up));
        self.mark_dirty(reg_up);
        self.mark_dirty(reg_lo);
        false
    }

    /// Restores the dictionary's invariants over every dirty region, from the bottom up
    /// (`WalkDirtyRegions`).
    pub(super) fn walk_dirty_regions(&mut self, mut reg_up: usize) {
        let mut reg_lo = self.d.below(reg_up);
        loop {
            while reg_lo != NIL && self.d.regions[reg_lo].dirty {
                reg_up = reg_lo;
                reg_lo = self.d.below(reg_lo);
            }
            if !self.d.regions[reg_up].dirty {
                reg_lo = reg_up;
                reg_up = self.d.above(reg_up);
                if reg_up == NIL || !self.d.regions[reg_up].dirty {
                    return;
                }
            }
            if reg_lo == NIL {
                return;
            }
            self.reg(reg_up).dirty = false;
            let (mut e_up, mut e_lo) = (self.e_up(reg_up), self.e_up(reg_lo));
            if self.m.dst(e_up) != self.m.dst(e_lo) && self.check_for_left_splice(reg_up) {
                // A temporary edge is no longer needed once the vertex has a real one.
                if self.d.regions[reg_lo].fix_upper_edge {
                    self.delete_region(reg_lo);
                    self.m.delete(e_lo);
                    reg_lo = self.d.below(reg_up);
                    e_lo = self.e_up(reg_lo);
                } else if self.d.regions[reg_up].fix_upper_edge {
                    self.delete_region(reg_up);
                    self.m.delete(e_up);
                    reg_up = self.d.above(reg_lo);
                    if reg_up == NIL {
                        return;
                    }
                    e_up = self.e_up(reg_up);
                }
            }
            if self.m.org(e_up) != self.m.org(e_lo) {
                let event = self.event;
                if self.m.dst(e_up) != self.m.dst(e_lo)
                    && !self.d.regions[reg_up].fix_upper_edge
                    && !self.d.regions[reg_lo].fix_upper_edge
                    && (self.m.dst(e_up) == event || self.m.dst(e_lo) == event)
                {
                    if self.check_for_intersect(reg_up) {
                        return;
                    }
                } else {
                    self.check_for_right_splice(reg_up);
                }
            }
            if self.m.org(e_up) == self.m.org(e_lo) && self.m.dst(e_up) == self.m.dst(e_lo) {
                // Two edges forming a loop of their own: merge them.
                self.add_winding(e_lo, e_up);
                self.delete_region(reg_up);
                self.m.delete(e_up);
                reg_up = self.d.above(reg_lo);
                if reg_up == NIL {
                    return;
                }
            }
        }
    }
}
