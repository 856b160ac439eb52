//! GLU's ways for a region on a grid of two lines (`sampleMonoPoly.cc`: `triangulateConvexPoly`
//! with `triangulateConvexPolyHoriz` and `triangulateConvexPolyVertical`; `polyDBG.cc`:
//! `DBG_isConvex`, `DBG_is_U_direction`; `monoTriangulation.cc`: `triangulateXYMonoTB`).

use super::tri::xy_mono;
use super::{Poly, Pt, Stream};
use crate::glu::draw::subdivider::mono::comp_v2_in_y;
use crate::glu::draw::subdivider::monotone::area;

/// GLU `DBG_isConvex`: no line turns right into the next (each line by its ends only).
pub(crate) fn is_convex(poly: &Poly) -> bool {
    (0..poly.len()).all(|i| area(poly.head(i), poly.tail(i), poly.tail(poly.next(i))) >= 0.0)
}

/// GLU `DBG_is_U_direction`: more points on lines that run more along u than along v.
pub(crate) fn is_u_direction(poly: &Poly) -> bool {
    let (mut u, mut v) = (0, 0);
    for (i, line) in poly.lines.iter().enumerate() {
        let (h, t) = (poly.head(i), poly.tail(i));
        if (h[0] - t[0]).abs() <= (h[1] - t[1]).abs() {
            v += line.len();
        } else {
            u += line.len();
        }
    }
    u > v
}

/// GLU `triangulateConvexPoly`: strips across the polygon between its lower and upper chains
/// (from its leftmost to its rightmost line) where v is linear or the polygon runs along u,
/// otherwise between its left and right chains (from its top to its bottom).
pub(crate) fn triangulate_convex(poly: &Poly, (ulinear, vlinear): (bool, bool), s: &mut Stream) {
    let (top, bot) = poly.extremes(comp_v2_in_y);
    let mut left = top;
    while left != bot && poly.tail(left)[0] < poly.head(left)[0] {
        left = poly.next(left);
    }
    let mut right = bot;
    while right != top && poly.tail(right)[0] > poly.head(right)[0] {
        right = poly.next(right);
    }
    if vlinear || (!ulinear && is_u_direction(poly)) {
        horizontal(poly, left, right, s);
    } else {
        vertical(poly, top, bot, s);
    }
}

/// GLU `triangulateConvexPolyHoriz`: every point of the lines from `left` on to `right`
/// (the lower chain) and, backwards, from before `left` to `right` (the upper chain; both
/// with the shared ends of consecutive lines twice), as `triangulateXYMono` strips.
fn horizontal(poly: &Poly, left: usize, right: usize, s: &mut Stream) {
    let mut lower = Vec::new();
    let mut t = left;
    while t != right {
        lower.extend_from_slice(&poly.lines[t]);
        t = poly.next(t);
    }
    let mut upper = Vec::new();
    let mut t = poly.prev(left);
    while t != poly.prev(right) {
        upper.extend(poly.lines[t].iter().rev());
        t = poly.prev(t);
    }
    if upper.is_empty() || lower.is_empty() {
        s.bad = true; // GLU reads past the arrays
        return;
    }
    xy_mono(&upper, &lower, s);
}

/// GLU `triangulateConvexPolyVertical`: the points after the top down the forward chain, and
/// from the top down the backward chain (without the bottom), as `triangulateXYMonoTB` fans.
fn vertical(poly: &Poly, top: usize, bot: usize, s: &mut Stream) {
    let mut left = Vec::new();
    let mut t = top;
    while t != bot {
        left.extend_from_slice(&poly.lines[t][1..]);
        t = poly.next(t);
    }
    let mut right = Vec::new();
    let mut t = poly.prev(top);
    while t != poly.prev(bot) {
        right.extend(poly.lines[t][1..].iter().rev());
        t = poly.prev(t);
    }
    xy_mono_tb(&left, &right, s);
}

/// GLU `triangulateXYMonoTB`: fans between a left and a right chain, both going down in v.
/// Where the right chain outlasts the left, GLU's fan repeats the right chain's first
/// remaining point (it inserts `rightVerts[j]` for every `k`); that is kept.
pub(crate) fn xy_mono_tb(left: &[Pt], right: &[Pt], s: &mut Stream) {
    if left.is_empty() || right.is_empty() {
        s.bad = true; // GLU reads past the arrays
        return;
    }
    let (mut i, mut j, mut top) = if left[0][1] >= right[0][1] { (1, 0, left[0]) } else { (0, 1, right[0]) };
    loop {
        if i >= left.len() {
            if j + 1 < right.len() {
                let mut fan = vec![top];
                fan.extend(std::iter::repeat_n(right[j], right.len() - j));
                s.fan(fan);
            }
            return;
        }
        if j >= right.len() {
            if i + 1 < left.len() {
                let mut fan = vec![top];
                fan.extend_from_slice(&left[i..]);
                s.fan(fan);
            }
            return;
        }
        if left[i][1] >= right[j][1] {
            let mut k = i;
            while k < left.len() && left[k][1] >= right[j][1] {
                k += 1;
            }
            let k = k - 1;
            let mut fan = vec![right[j], top];
            fan.extend_from_slice(&left[i..=k]);
            s.fan(fan);
            i = k + 1;
            top = left[k];
        } else {
            let mut k = j;
            while k < right.len() && right[k][1] > left[i][1] {
                k += 1;
            }
            let k = k - 1;
            let mut fan = vec![left[i]];
            fan.extend(right[j..=k].iter().rev());
            fan.push(top);
            s.fan(fan);
            j = k + 1;
            top = right[j - 1];
        }
    }
}
