//! Where a component of the region meets its first and last grid lines (`findUpCorners`,
//! `findDownCorners`, `findNeckF` in `nurbtess/sampleMonoPoly.cc`): each corner is on the
//! left chain (0), the top or bottom vertex (1) or the right chain (2), with its index.

use super::chain::{at, index_below, index_first_above_equal, intersect_chain, skip_equality};
use super::grid::BoundaryChain;
use super::Pt;

/// A corner: GLU's `CornerWhere` (0 left chain, 1 top/bottom vertex, 2 right chain) and index.
pub(crate) type Corner = (i32, i64);

/// The two chains of a component: left `l[ls..=le]`, right `r[rs..=re]`.
#[derive(Clone, Copy)]
pub(crate) struct Sides<'a> {
    pub l: &'a [Pt],
    pub ls: i64,
    pub le: i64,
    pub r: &'a [Pt],
    pub rs: i64,
    pub re: i64,
}

/// GLU `findUpCorners`: the corners on grid line v (grid points `uleft`, `uright`) seen from
/// `top`.
pub(crate) fn up_corners(top: Pt, c: &Sides, v: f32, uleft: f32, uright: f32) -> (Corner, Corner) {
    let (lg, rg) = ([uleft, v], [uright, v]);
    let i1 = index_first_above_equal(c.l, v, c.ls, c.le);
    let mut i2 = index_first_above_equal(c.r, v, c.rs, c.re);
    if i2 >= c.ls {
        // GLU compares with the left chain's start here.
        i2 = skip_equality(c.r, v, i2, c.re);
    }
    if i1 < c.ls && i2 < c.rs {
        return ((1, 0), (1, 0));
    }
    if i1 < c.ls {
        let (mut tmin, mut ti) = (at(c.r, i2)[0], i2);
        for i in (c.rs..i2).rev() {
            if at(c.r, i)[0] < tmin {
                (tmin, ti) = (at(c.r, i)[0], i);
            }
        }
        let left = if intersect_chain(c.r, c.rs, c.re, lg, top) {
            (2, i2)
        } else if top[0] < tmin {
            (1, 0)
        } else {
            (2, ti)
        };
        return (left, (2, i2));
    }
    if i2 < c.rs {
        let (mut tmax, mut ti) = (at(c.l, i1)[0], i1);
        for i in (c.ls..i1).rev() {
            if at(c.l, i)[0] > tmax {
                (tmax, ti) = (at(c.l, i)[0], i);
            }
        }
        let right = if intersect_chain(c.l, c.ls, c.le, rg, top) {
            (0, i1)
        } else if top[0] > tmax {
            (1, 0)
        } else {
            (0, ti)
        };
        return ((0, i1), right);
    }
    let (p1, p2) = (at(c.l, i1), at(c.r, i2));
    if p1[1] <= p2[1] {
        let (mut tmax, mut ti) = (p1[0], i1);
        let mut i = i1 - 1;
        while i >= c.ls && at(c.l, i)[1] <= p2[1] {
            if at(c.l, i)[0] > tmax {
                (tmax, ti) = (at(c.l, i)[0], i);
            }
            i -= 1;
        }
        let right = if intersect_chain(c.l, c.ls, c.le, rg, p2) {
            (0, i1)
        } else if tmax >= p2[0] || tmax >= uright {
            (0, ti)
        } else {
            (2, i2)
        };
        ((0, i1), right)
    } else {
        let (mut tmin, mut ti) = (p2[0], i2);
        let mut i = i2 - 1;
        while i >= c.rs && at(c.r, i)[1] <= p1[1] {
            if at(c.r, i)[0] < tmin {
                (tmin, ti) = (at(c.r, i)[0], i);
            }
            i -= 1;
        }
        let left = if intersect_chain(c.r, c.rs, c.re, lg, p1) {
            (2, i2)
        } else if tmin <= p1[0] || tmin <= uleft {
            (2, ti)
        } else {
            (0, i1)
        };
        (left, (2, i2))
    }
}

/// GLU `findDownCorners`: the same on the component's last grid line, seen from `bot`.
pub(crate) fn down_corners(bot: Pt, c: &Sides, v: f32, uleft: f32, uright: f32) -> (Corner, Corner) {
    let (lg, rg) = ([uleft, v], [uright, v]);
    let i1 = index_below(c.l, v, c.ls, c.le);
    let mut i2 = index_below(c.r, v, c.rs, c.re);
    if i2 <= c.re {
        i2 = skip_equality(c.r, v, i2, c.re);
    }
    if i1 > c.le && i2 > c.re {
        return ((1, 0), (1, 0));
    }
    if i1 > c.le {
        let (mut tmin, mut ti) = (at(c.r, i2)[0], i2);
        for i in i2 + 1..=c.re {
            if at(c.r, i)[0] < tmin {
                (tmin, ti) = (at(c.r, i)[0], i);
            }
        }
        let left = if intersect_chain(c.r, c.rs, c.re, lg, bot) {
            (2, i2)
        } else if bot[0] < tmin {
            (1, 0)
        } else {
            (2, ti)
        };
        return (left, (2, i2));
    }
    if i2 > c.re {
        let mut ti = i1;
        while ti <= c.le && at(c.l, ti)[1] >= v {
            ti += 1;
        }
        if ti > c.le {
            return ((0, i1), (1, 0));
        }
        let (mut tmax, from) = (at(c.l, ti)[0], ti);
        for i in from..=c.le {
            if at(c.l, i)[0] > tmax {
                (tmax, ti) = (at(c.l, i)[0], i);
            }
        }
        let right = if intersect_chain(c.l, c.ls, c.le, rg, bot) {
            (0, i1)
        } else if bot[0] > tmax {
            (1, 0)
        } else {
            (0, ti)
        };
        return ((0, i1), right);
    }
    let (p1, p2) = (at(c.l, i1), at(c.r, i2));
    if p1[1] >= p2[1] {
        let (mut tmax, mut ti) = (p1[0], i1);
        let mut i = i1 + 1;
        while i <= c.le && at(c.l, i)[1] >= p2[1] {
            if at(c.l, i)[0] > tmax {
                (tmax, ti) = (at(c.l, i)[0], i);
            }
            i += 1;
        }
        let right = if intersect_chain(c.l, c.ls, c.le, rg, p2) {
            (0, i1)
        } else if tmax >= p2[0] || tmax >= uright {
            (0, ti)
        } else {
            (2, i2)
        };
        ((0, i1), right)
    } else {
        let (mut tmin, mut ti) = (p2[0], i2);
        let mut i = i2 + 1;
        while i <= c.re && at(c.r, i)[1] >= p1[1] {
            if at(c.r, i)[0] < tmin {
                (tmin, ti) = (at(c.r, i)[0], i);
            }
            i += 1;
        }
        let left = if intersect_chain(c.r, c.rs, c.re, lg, p1) {
            (2, i2)
        } else if tmin <= p1[0] || tmin <= uleft {
            (2, ti)
        } else {
            (0, i1)
        };
        (left, (2, i2))
    }
}

/// GLU `findNeckF`: where the region narrows between this component and the next, as
/// indices on the left and right chains, or `None`.
pub(crate) fn neck(
    l: &[Pt],
    bot_left: i64,
    r: &[Pt],
    bot_right: i64,
    (lg, rg): (&BoundaryChain, &BoundaryChain),
    start: i64,
) -> Option<(i64, i64)> {
    let (nl, nr) = (l.len() as i64, r.len() as i64);
    if bot_left >= nl || bot_right >= nr {
        return None;
    }
    let v = super::grid::min(at(l, bot_left)[1], at(r, bot_right)[1]);
    let mut i = start;
    while i < lg.n() && !(lg.v(i) <= v && lg.uline(i) <= rg.uline(i)) {
        i += 1;
    }
    if i == lg.n() {
        return None;
    }
    let gv = lg.v(i);
    let bl2 = (index_first_above_equal(l, gv, bot_left, nl - 1) - 1).max(bot_left);
    let br2 = (index_first_above_equal(r, gv, bot_right, nr - 1) - 1).max(bot_right);
    let (mut tl, mut best) = (bot_left, at(l, bot_left)[0]);
    for i in bot_left + 1..=bl2 {
        if at(l, i)[0] > best {
            (best, tl) = (at(l, i)[0], i);
        }
    }
    let (mut tr, mut best) = (bot_right, at(r, bot_right)[0]);
    for i in bot_right + 1..=br2 {
        if at(r, i)[0] < best {
            (best, tr) = (at(r, i)[0], i);
        }
    }
    Some((tl, tr))
}
