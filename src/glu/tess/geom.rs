//! The sweep's geometric predicates on projected vertices `(s, t)` (GLU's `libtess/geom.c`).
//!
//! Events are ordered lexicographically, `s` first (`vert_leq`); `edge_eval` and `edge_sign`
//! say where a vertex lies against an edge, computed the way libtess computes them so that
//! the same inputs round the same way; `edge_intersect` interpolates from the two middle
//! endpoints, which keeps the result inside both edges' bounding boxes.

/// A projected point.
pub(crate) type St = (f64, f64);

/// `u` ≤ `v` in sweep order: by `s`, then by `t` (`VertLeq`).
#[inline]
pub(crate) fn vert_leq(u: St, v: St) -> bool {
    u.0 < v.0 || (u.0 == v.0 && u.1 <= v.1)
}

/// The same point (`VertEq`).
#[inline]
pub(crate) fn vert_eq(u: St, v: St) -> bool {
    u.0 == v.0 && u.1 == v.1
}

/// Swaps the coordinates, so that the `Trans*` forms are the plain ones on swapped points.
#[inline]
fn tr(u: St) -> St {
    (u.1, u.0)
}

/// For `u` ≤ `v` ≤ `w`: the signed distance of `v` above the edge `uw` at `v.s`, zero for a
/// vertical edge (`EdgeEval`). Interpolates from the nearer end, which keeps the value exact
/// when `v` is close to `u` or `w`.
pub(crate) fn edge_eval(u: St, v: St, w: St) -> f64 {
    let gap_l = v.0 - u.0;
    let gap_r = w.0 - v.0;
    if gap_l + gap_r > 0.0 {
        if gap_l < gap_r {
            (v.1 - u.1) + (u.1 - w.1) * (gap_l / (gap_l + gap_r))
        } else {
            (v.1 - w.1) + (w.1 - u.1) * (gap_r / (gap_l + gap_r))
        }
    } else {
        0.0
    }
}

/// A number with the sign of [`edge_eval`], cheaper (`EdgeSign`).
pub(crate) fn edge_sign(u: St, v: St, w: St) -> f64 {
    let gap_l = v.0 - u.0;
    let gap_r = w.0 - v.0;
    if gap_l + gap_r > 0.0 {
        (v.1 - w.1) * gap_l + (v.1 - u.1) * gap_r
    } else {
        0.0
    }
}

/// `(b·x + a·y) / (a + b)`, or the midpoint when both weights are zero; negative weights
/// count as zero. The result always lies between `x` and `y` (`RealInterpolate`).
fn interpolate(a: f64, x: f64, b: f64, y: f64) -> f64 {
    let a = if a < 0.0 { 0.0 } else { a };
    let b = if b < 0.0 { 0.0 } else { b };
    if a <= b {
        if b == 0.0 {
            (x + y) / 2.0
        } else {
            x + (y - x) * (a / (a + b))
        }
    } else {
        y + (x - y) * (b / (a + b))
    }
}

/// One coordinate (the first of the pairs, under `leq`) of the intersection of the edges
/// `(o1, d1)` and `(o2, d2)`: sort each edge and the pair, then interpolate between the two
/// middle endpoints with the distances `eval`/`sign` give.
fn intersect_coord(mut o1: St, mut d1: St, mut o2: St, mut d2: St) -> f64 {
    if !vert_leq(o1, d1) {
        std::mem::swap(&mut o1, &mut d1);
    }
    if !vert_leq(o2, d2) {
        std::mem::swap(&mut o2, &mut d2);
    }
    if !vert_leq(o1, o2) {
        std::mem::swap(&mut o1, &mut o2);
        std::mem::swap(&mut d1, &mut d2);
    }
    if !vert_leq(o2, d1) {
        // No overlap in this coordinate: the best guess.
        (o2.0 + d1.0) / 2.0
    } else if vert_leq(d1, d2) {
        let (mut z1, mut z2) = (edge_eval(o1, o2, d1), edge_eval(o2, d1, d2));
        if z1 + z2 < 0.0 {
            (z1, z2) = (-z1, -z2);
        }
        interpolate(z1, o2.0, z2, d1.0)
    } else {
        let (mut z1, mut z2) = (edge_sign(o1, o2, d1), -edge_sign(o1, d2, d1));
        if z1 + z2 < 0.0 {
            (z1, z2) = (-z1, -z2);
        }
        interpolate(z1, o2.0, z2, d2.0)
    }
}

/// The intersection of edges `(o1, d1)` and `(o2, d2)`, inside both bounding rectangles
/// (`__gl_edgeIntersect`): `s` from the sweep order, `t` from the transposed order.
pub(crate) fn edge_intersect(o1: St, d1: St, o2: St, d2: St) -> St {
    let s = intersect_coord(o1, d1, o2, d2);
    let t = intersect_coord(tr(o1), tr(d1), tr(o2), tr(d2));
    (s, t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_diagonals_meet_at_the_centre() {
        let p = edge_intersect((0.0, 0.0), (2.0, 2.0), (0.0, 2.0), (2.0, 0.0));
        assert_eq!(p, (1.0, 1.0));
    }

    #[test]
    fn edge_eval_is_the_signed_distance() {
        assert_eq!(edge_eval((0.0, 0.0), (1.0, 3.0), (2.0, 2.0)), 2.0);
        assert!(edge_sign((0.0, 0.0), (1.0, 3.0), (2.0, 2.0)) > 0.0);
        assert!(edge_sign((0.0, 0.0), (1.0, 0.0), (2.0, 2.0)) < 0.0);
        assert_eq!(edge_eval((1.0, 0.0), (1.0, 5.0), (1.0, 9.0)), 0.0);
    }
}
