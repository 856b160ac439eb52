//! After the sweep: triangulating each inside region, which the sweep left monotone, or
//! keeping only the edges between inside and outside (GLU's `libtess/tessmono.c`).

use super::geom::{edge_sign, vert_leq};
use super::mesh::{Mesh, E_HEAD, F_HEAD};

impl Mesh {
    fn st(&self, v: usize) -> (f64, f64) {
        (self.v[v].s, self.v[v].t)
    }

    fn goes_left(&self, e: usize) -> bool {
        vert_leq(self.st(self.dst(e)), self.st(self.org(e)))
    }

    fn goes_right(&self, e: usize) -> bool {
        vert_leq(self.st(self.org(e)), self.st(self.dst(e)))
    }

    /// Splits the monotone face into triangles (`__gl_meshTessellateMonoRegion`): walk the
    /// upper and lower chains from the right, fanning triangles from whichever chain's end is
    /// rightmost while they turn the right way, then fan what is left from the leftmost vertex.
    fn tessellate_mono_region(&mut self, face: usize) {
        let mut up = self.f[face].an_edge;
        if self.lnext(up) == up || self.lnext(self.lnext(up)) == up {
            return;
        }
        // The edge whose origin is rightmost (the sweep left `an_edge` near it).
        let first = up;
        while self.goes_left(up) {
            up = self.lprev(up);
            if up == first {
                break;
            }
        }
        let first = up;
        while self.goes_right(up) {
            up = self.lnext(up);
            if up == first {
                break;
            }
        }
        let mut lo = self.lprev(up);
        while self.lnext(up) != lo {
            if vert_leq(self.st(self.dst(up)), self.st(self.org(lo))) {
                // up.dst is on the left: form triangles from lo.org.
                while self.lnext(lo) != up
                    && (self.goes_left(self.lnext(lo))
                        || edge_sign(self.st(self.org(lo)), self.st(self.dst(lo)), self.st(self.dst(self.lnext(lo))))
                            <= 0.0)
                {
                    lo = self.connect(self.lnext(lo), lo) ^ 1;
                }
                lo = self.lprev(lo);
            } else {
                // lo.org is on the left: form triangles from up.dst.
                while self.lnext(lo) != up
                    && (self.goes_right(self.lprev(up))
                        || edge_sign(self.st(self.dst(up)), self.st(self.org(up)), self.st(self.org(self.lprev(up))))
                            >= 0.0)
                {
                    up = self.connect(up, self.lprev(up)) ^ 1;
                }
                up = self.lnext(up);
            }
        }
        // lo.org == up.dst is the leftmost vertex: fan the rest from it.
        if self.lnext(lo) == up {
            return;
        }
        while self.lnext(self.lnext(lo)) != up {
            lo = self.connect(self.lnext(lo), lo) ^ 1;
        }
    }

    /// Triangulates every inside face (`__gl_meshTessellateInterior`).
    pub(crate) fn tessellate_interior(&mut self) {
        let mut f = self.f[F_HEAD].next;
        while f != F_HEAD {
            // New triangles go before `next` in the list: they are not visited again.
            let next = self.f[f].next;
            if self.f[f].inside {
                self.tessellate_mono_region(f);
            }
            f = next;
        }
    }

    /// Gives boundary edges the winding `value` (its sign after which side is inside) and
    /// deletes every other edge when `keep_only_boundary`, otherwise zeroes its winding
    /// (`__gl_meshSetWindingNumber`).
    pub(crate) fn set_winding_number(&mut self, value: i32, keep_only_boundary: bool) {
        let mut e = self.e[E_HEAD].next;
        while e != E_HEAD {
            let next = self.e[e].next;
            let (l, r) = (self.inside(self.lface(e)), self.inside(self.rface(e)));
            if l != r {
                self.e[e].winding = if l { value } else { -value };
            } else if !keep_only_boundary {
                self.e[e].winding = 0;
            } else {
                self.delete(e);
            }
            e = next;
        }
    }
}
