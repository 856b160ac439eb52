//! One loop left by the subdivision, sliced (`Slicer::slice_new`, `internals/slicer.cc`): a
//! rectangle goes the way of an untrimmed patch ([`slice_rect`]), a loop with no inner grid
//! line across it by GLU's monotone triangulation ([`mono`]), the rest by GLU's
//! `sampleMonoPoly` ([`super::sample`]); `None` where GLU would read past its arrays.

use super::arcs::{ArcId, Arcs};
use super::mono;
use super::monotone::area;
use super::sample::{sample_mono_poly, Poly};
use crate::glu::draw::slicer::border::RectLoop;
use crate::glu::draw::slicer::Grid;
use crate::glu::draw::slicer::{c_int, slice_rect, Interior, Piece};
use crate::glu::evaluation::sampling::MAX_SEGMENTS;

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
        sampled(arcs, lp, (ulines, vlines), [umin, umax, vmin, vmax], (ulinear, vlinear))
    }
}

/// GLU's `sampleMonoPoly` on the loop, then its stream of fans (`Slicer::evalStream`) and its
/// blocks of quads (`Slicer::evalRBArray`), or `None` where GLU would read past its arrays
/// (or the grid has more lines than gleval's sampling allows).
fn sampled(arcs: &Arcs, lp: &[ArcId], lines: (i64, i64), bbox: [f32; 4], linear: (bool, bool)) -> Option<Vec<Piece>> {
    let n = |x: i64| usize::try_from(x).ok().filter(|&x| (2..=MAX_SEGMENTS).contains(&x));
    let (nu, nv) = (n(lines.0)?, n(lines.1)?);
    let poly = Poly { lines: lp.iter().flat_map(|&a| dlines(&arcs[a].pts)).collect() };
    let out = sample_mono_poly(&poly, (nu, nv), bbox, linear)?;
    let grid = Grid { u: (bbox[0], bbox[1]), nu: nu - 1, v: (bbox[3], bbox[2]), nv: nv - 1 };
    let mut pieces = out.pieces;
    let top = nv as i64 - 1;
    for b in &out.blocks {
        for (k, i) in (b.low + 1..=b.up).rev().enumerate() {
            let (l, r) = (b.left[k + 1], b.right[k + 1]);
            pieces.push(Piece::Block { grid, u: (l, r), v: (top - i, top - i + 1) });
        }
    }
    Some(pieces)
}

/// GLU `arcToMultDLines` (`slicer.cc`): a straight arc as one line, any other as one line
/// per segment.
fn dlines(pts: &[[f32; 2]]) -> Vec<Vec<[f32; 2]>> {
    let straight = pts.len() <= 2 || area(pts[0], pts[1], pts[pts.len() - 1]) == 0.0;
    if straight {
        vec![pts.to_vec()]
    } else {
        pts.windows(2).map(|w| w.to_vec()).collect()
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
