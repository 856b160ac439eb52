//! GLU's `vertexArray` searches (`nurbtess/monoTriangulation.cc`) and the chain tests of
//! `sampleMonoPoly.cc` and `polyDBG.cc`, on chains of (u, v) points with C's signed indices.

use super::Pt;
use crate::glu::draw::subdivider::monotone::area;

/// Point `i` of a chain, NaN outside it (GLU would read out of bounds; the NaN makes the
/// region fall back rather than panic).
pub(crate) fn at(c: &[Pt], i: i64) -> Pt {
    usize::try_from(i).ok().and_then(|i| c.get(i)).copied().unwrap_or([f32::NAN; 2])
}

/// `vertexArray::findIndexBelowGen`: the first index from which every point is at or below v.
pub(crate) fn index_below(c: &[Pt], v: f32, start: i64, end: i64) -> i64 {
    if start > end || at(c, end)[1] > v {
        return end + 1;
    }
    let mut i = end - 1;
    while i >= start && at(c, i)[1] <= v {
        i -= 1;
    }
    i + 1
}

/// `vertexArray::findIndexStrictBelowGen`.
pub(crate) fn index_strict_below(c: &[Pt], v: f32, start: i64, end: i64) -> i64 {
    if start > end || at(c, end)[1] >= v {
        return end + 1;
    }
    let mut i = end - 1;
    while i >= start && at(c, i)[1] < v {
        i -= 1;
    }
    i + 1
}

/// `vertexArray::findIndexFirstAboveEqualGen`.
pub(crate) fn index_first_above_equal(c: &[Pt], v: f32, start: i64, end: i64) -> i64 {
    if start > end || at(c, start)[1] < v {
        return start - 1;
    }
    let mut i = start;
    while i <= end && at(c, i)[1] > v {
        i += 1;
    }
    if i > end {
        end
    } else if at(c, i)[1] == v {
        i
    } else {
        i - 1
    }
}

/// `vertexArray::findIndexAboveGen`.
pub(crate) fn index_above(c: &[Pt], v: f32, start: i64, end: i64) -> i64 {
    if start > end || at(c, start)[1] < v {
        return start - 1;
    }
    let mut i = start + 1;
    while i <= end && at(c, i)[1] >= v {
        i += 1;
    }
    i - 1
}

/// `vertexArray::skipEqualityFromStart`.
pub(crate) fn skip_equality(c: &[Pt], v: f32, start: i64, end: i64) -> i64 {
    if at(c, start)[1] != v {
        return start;
    }
    let mut i = start + 1;
    while i <= end && at(c, i)[1] == v {
        i += 1;
    }
    i - 1
}

/// `checkMiddle` (`sampleMonoPoly.cc`): a point strictly between the two v values.
pub(crate) fn check_middle(c: &[Pt], begin: i64, end: i64, vup: f32, vbelow: f32) -> Option<i64> {
    (begin..=end).find(|&i| at(c, i)[1] < vup && at(c, i)[1] > vbelow)
}

/// `DBG_intersectChain` (`polyDBG.cc`): whether segment a–b properly crosses the chain.
pub(crate) fn intersect_chain(c: &[Pt], start: i64, end: i64, a: Pt, b: Pt) -> bool {
    let crosses = |p: Pt, q: Pt| area(p, q, a) * area(p, q, b) < 0.0 && area(a, b, p) * area(a, b, q) < 0.0;
    (start..=end - 2).any(|i| crosses(at(c, i), at(c, i + 1)))
}
