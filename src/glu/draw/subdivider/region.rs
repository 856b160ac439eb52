//! One loop left by the subdivision, sliced (`Slicer::slice_new`, `internals/slicer.cc`): a
//! rectangle goes the way of an untrimmed patch ([`slice_rect`]), a loop with no inner grid
//! line across it by GLU's monotone triangulation ([`mono`]); the rest are not written yet
//! (GLU's `sampleMonoPoly`), and give `None`.

use super::arcs::{ArcId, Arcs};
use super::mono;
use crate::glu::draw::slicer::border::RectLoop;
use crate::glu::draw::slicer::{c_int, slice_rect, Interior, Piece};

/// GLU's `ZERO` (`slicer.cc`): how far a rectangle's sides may be from straight.
const ZERO: f64 = 0.00001;

/// The pieces covering the loop `lp` (its arcs from the first GLU slices from), or `None` for
/// a loop this port cannot slice as GLU does.
pub(super) fn slice(arcs: &Arcs, lp: &[ArcId], interior: Interior) -> Option<Vec<Piece>> {
    let tails: Vec<[f32; 2]> = lp.iter().map(|&a| arcs.tail(a)).collect();
    let fold = |c: usize, f: fn(f32, f32) -> f32| tails.iter().map(|p| p[c]).fold(tails[0][c], f);
    let (umin, umax, vmin, vmax) = (fold(0, f32::min), fold(0, f32::max), fold(1, f32::min), fold(1, f32::max));
    if umax == umin {
        return Some(Vec::new()); // GLU returns here to avoid a division by zero.
    }
    let (du, dv) = (interior.du.abs(), interior.dv.abs());
    let ulines = if du > umax - umin { 2 } else { 3 + c_int((umax - umin) / du) };
    let vlines = if dv >= vmax - vmin { 2 } else { 2 + c_int((vmax - vmin) / dv) };
    let thin = ulines <= 2 || vlines <= 2;
    let (ulinear, vlinear) = (interior.ulinear, interior.vlinear);
    if is_rect(arcs, lp) {
        Some(slice_rect(&rect_sides(arcs, lp[0], thin), interior))
    } else if (thin && ulinear) || (!ulinear && !vlinear && ulines == 2 && vlines > 2) {
        Some(mono::triangulate_loop(arcs, lp))
    } else {
        None // GLU's sampleMonoPoly
    }
}

/// GLU `is_rect`: four arcs, alternately along u and along v (to within [`ZERO`]).
fn is_rect(arcs: &Arcs, lp: &[ArcId]) -> bool {
    if lp.len() != 4 {
        return false;
    }
    let flat = |a: ArcId, c: usize| f64::from((arcs.tail(a)[c] - arcs.head(a)[c]).abs()) <= ZERO;
    let (l, next, prev) = (lp[0], lp[1], lp[3]);
    let pp = lp[2];
    (flat(l, 0) && flat(next, 1) && flat(prev, 1) && flat(pp, 0))
        || (flat(l, 1) && flat(next, 0) && flat(prev, 0) && flat(pp, 1))
}

/// The four sides of a rectangular loop from its top (GLU `triangulateRect`, which compares
/// exactly, and `triangulateRectGen`, which compares to within [`ZERO`]).
fn rect_sides(arcs: &Arcs, l: ArcId, exact: bool) -> RectLoop {
    let (t, h) = (arcs.tail(l), arcs.head(l));
    let along_u = if exact { t[1] == h[1] } else { f64::from((t[1] - h[1]).abs()) <= ZERO };
    let opposite = arcs[arcs[l].prev].prev;
    let top = if along_u {
        if t[1] > arcs.tail(opposite)[1] {
            l
        } else {
            opposite
        }
    } else if t[0] > arcs.tail(opposite)[0] {
        arcs[l].next
    } else {
        arcs[l].prev
    };
    let left = arcs[top].next;
    let bottom = arcs[left].next;
    let right = arcs[bottom].next;
    let pts = |a: ArcId| arcs[a].pts.clone();
    RectLoop { bottom: pts(bottom), right: pts(right), top: pts(top), left: pts(left) }
}
