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

/// Which chain of a component a corner search is on: the left (GLU's `CornerWhere` 0) or
/// the right (2). `findUpCorners` and `findDownCorners` (`sampleMonoPoly.cc`) treat the two
/// chains as mirror images, the left looking for its largest u and the right for its
/// smallest, so each search is written once here for either chain.
#[derive(Clone, Copy)]
enum Hand {
    Left,
    Right,
}

impl Hand {
    fn code(self) -> i32 {
        match self {
            Hand::Left => 0,
            Hand::Right => 2,
        }
    }

    /// Whether u `a` lies strictly further in (towards the other chain) than `b`: GLU's
    /// `>` on the left chain, `<` on the right.
    fn inward(self, a: f32, b: f32) -> bool {
        match self {
            Hand::Left => a > b,
            Hand::Right => a < b,
        }
    }

    /// `inward` or equal: GLU's `>=` on the left chain, `<=` on the right.
    fn inward_or_at(self, a: f32, b: f32) -> bool {
        match self {
            Hand::Left => a >= b,
            Hand::Right => a <= b,
        }
    }

    /// The innermost u of `c` at `first` and then the indices of `rest`, with its index: the
    /// `tempMax`/`tempMin` loops of `sampleMonoPoly.cc`, whose strict comparisons keep the
    /// first point met on a tie.
    fn innermost(self, c: &[Pt], first: i64, rest: impl IntoIterator<Item = i64>) -> (f32, i64) {
        let mut best = (at(c, first)[0], first);
        for i in rest {
            if self.inward(at(c, i)[0], best.0) {
                best = (at(c, i)[0], i);
            }
        }
        best
    }
}

/// Which way a corner search walks a chain from the grid line: up towards the component's
/// top vertex (`findUpCorners`, indices falling) or down towards its bottom vertex
/// (`findDownCorners`, indices rising).
#[derive(Clone, Copy)]
enum Walk {
    Up,
    Down,
}

impl Walk {
    /// The indices after `i` on a chain spanning `start..=end`, walking this way to its end.
    fn after(self, i: i64, start: i64, end: i64) -> impl Iterator<Item = i64> {
        let (step, n) = match self {
            Walk::Up => (-1, i - start),
            Walk::Down => (1, end - i),
        };
        (1..=n).map(move |k| i + step * k)
    }

    /// Whether v `a` is not yet past v `b` walking this way: `<=` up, `>=` down.
    fn within(self, a: f32, b: f32) -> bool {
        match self {
            Walk::Up => a <= b,
            Walk::Down => a >= b,
        }
    }
}

/// One chain of a component in a corner search: its points `c[start..=end]`, and `far`,
/// the grid point at the other chain's end of the grid line.
struct Side<'a> {
    hand: Hand,
    c: &'a [Pt],
    start: i64,
    end: i64,
    far: Pt,
}

impl<'a> Side<'a> {
    /// The left and right chains of `c` on grid line v between grid points `uleft`, `uright`.
    fn both(c: &Sides<'a>, v: f32, uleft: f32, uright: f32) -> (Side<'a>, Side<'a>) {
        (
            Side { hand: Hand::Left, c: c.l, start: c.ls, end: c.le, far: [uright, v] },
            Side { hand: Hand::Right, c: c.r, start: c.rs, end: c.re, far: [uleft, v] },
        )
    }

    fn corner(&self, i: i64) -> Corner {
        (self.hand.code(), i)
    }

    /// The innermost point from `first` on, walking `walk` to the chain's end.
    fn innermost(&self, walk: Walk, first: i64) -> (f32, i64) {
        self.hand.innermost(self.c, first, walk.after(first, self.start, self.end))
    }

    /// The same, stopping at the first point past v `until`.
    fn innermost_within(&self, walk: Walk, first: i64, until: f32) -> (f32, i64) {
        let stretch = walk.after(first, self.start, self.end).take_while(|&i| walk.within(at(self.c, i)[1], until));
        self.hand.innermost(self.c, first, stretch)
    }

    /// The corner of this chain's far side when the other chain does not reach the grid line
    /// and this one meets it at `i`: the chain's own point there if the chain crosses the
    /// segment from the far grid point to the vertex `vertex`, else the vertex if it is further
    /// in than the chain's innermost point `(u, ti)`, else that point.
    fn corner_alone(&self, i: i64, (u, ti): (f32, i64), vertex: Pt) -> Corner {
        if intersect_chain(self.c, self.start, self.end, self.far, vertex) {
            self.corner(i)
        } else if self.hand.inward(vertex[0], u) {
            (1, 0)
        } else {
            self.corner(ti)
        }
    }

    /// The corner of this chain's far side when both chains meet the grid line, this one at
    /// `i` and the other at `other` (point `p`): this chain's point if it crosses the segment
    /// from the far grid point to `p`, its innermost point `(u, ti)` if that reaches `p` or
    /// the far grid point, else the other chain's corner.
    fn corner_facing(&self, i: i64, (u, ti): (f32, i64), other: Corner, p: Pt) -> Corner {
        if intersect_chain(self.c, self.start, self.end, self.far, p) {
            self.corner(i)
        } else if self.hand.inward_or_at(u, p[0]) || self.hand.inward_or_at(u, self.far[0]) {
            self.corner(ti)
        } else {
            other
        }
    }
}

/// The last case of `findUpCorners` and `findDownCorners`: both chains meet the grid line, the
/// left at `i1` and the right at `i2`. The chain whose point there is nearer the vertex in v
/// gives one corner itself; its innermost point over the stretch not past the other's point
/// decides the other corner.
fn both_chains(walk: Walk, (left, right): (&Side, &Side), (i1, i2): (i64, i64)) -> (Corner, Corner) {
    let (p1, p2) = (at(left.c, i1), at(right.c, i2));
    if walk.within(p1[1], p2[1]) {
        let best = left.innermost_within(walk, i1, p2[1]);
        (left.corner(i1), left.corner_facing(i1, best, right.corner(i2), p2))
    } else {
        let best = right.innermost_within(walk, i2, p1[1]);
        (right.corner_facing(i2, best, left.corner(i1), p1), right.corner(i2))
    }
}

/// GLU `findUpCorners`: the corners on grid line v (grid points `uleft`, `uright`) seen from
/// `top`.
pub(crate) fn up_corners(top: Pt, c: &Sides, v: f32, uleft: f32, uright: f32) -> (Corner, Corner) {
    let i1 = index_first_above_equal(c.l, v, c.ls, c.le);
    let mut i2 = index_first_above_equal(c.r, v, c.rs, c.re);
    if i2 >= c.ls {
        // GLU compares with the left chain's start here.
        i2 = skip_equality(c.r, v, i2, c.re);
    }
    if i1 < c.ls && i2 < c.rs {
        return ((1, 0), (1, 0));
    }
    let (left, right) = Side::both(c, v, uleft, uright);
    if i1 < c.ls {
        return (right.corner_alone(i2, right.innermost(Walk::Up, i2), top), right.corner(i2));
    }
    if i2 < c.rs {
        return (left.corner(i1), left.corner_alone(i1, left.innermost(Walk::Up, i1), top));
    }
    both_chains(Walk::Up, (&left, &right), (i1, i2))
}

/// GLU `findDownCorners`: the same on the component's last grid line, seen from `bot`.
pub(crate) fn down_corners(bot: Pt, c: &Sides, v: f32, uleft: f32, uright: f32) -> (Corner, Corner) {
    let i1 = index_below(c.l, v, c.ls, c.le);
    let mut i2 = index_below(c.r, v, c.rs, c.re);
    if i2 <= c.re {
        i2 = skip_equality(c.r, v, i2, c.re);
    }
    if i1 > c.le && i2 > c.re {
        return ((1, 0), (1, 0));
    }
    let (left, right) = Side::both(c, v, uleft, uright);
    if i1 > c.le {
        return (right.corner_alone(i2, right.innermost(Walk::Down, i2), bot), right.corner(i2));
    }
    if i2 > c.re {
        // GLU skips the left chain's points still on or above the line before its search.
        let mut ti = i1;
        while ti <= c.le && at(c.l, ti)[1] >= v {
            ti += 1;
        }
        if ti > c.le {
            return (left.corner(i1), (1, 0));
        }
        return (left.corner(i1), left.corner_alone(i1, left.innermost(Walk::Down, ti), bot));
    }
    both_chains(Walk::Down, (&left, &right), (i1, i2))
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
    let (_, tl) = Hand::Left.innermost(l, bot_left, bot_left + 1..=bl2);
    let (_, tr) = Hand::Right.innermost(r, bot_right, bot_right + 1..=br2);
    Some((tl, tr))
}
