//! GLU's triangulation of a loop monotone in v with no inner grid line across it
//! (`monoTriangulationFunBackend` and `monoTriangulationRecFunBackend` in
//! `internals/monoTriangulationBackend.cc`, with `reflexChain` of `nurbtess/monoTriangulation.cc`):
//! the loop's two chains from its top to its bottom are walked down together, and every
//! vertex that makes the chain of pending vertices convex there closes a triangle fan.

use super::arcs::{ArcId, Arcs};
use super::monotone::area;
use crate::glu::draw::slicer::Piece;
use std::cmp::Ordering;

type Pt = [f32; 2];

/// GLU `compV2InY` (`nurbtess/directedLine.cc`): by v, then by u.
pub(crate) fn comp_v2_in_y(a: Pt, b: Pt) -> Ordering {
    if a[1] < b[1] || (a[1] == b[1] && a[0] < b[0]) {
        Ordering::Less
    } else if a == b {
        Ordering::Equal
    } else {
        Ordering::Greater
    }
}

/// The first of `items` whose point is greatest under `cmp`, and the first whose point is
/// least: the top and bottom vertices GLU's monotone triangulations start from. Each of
/// `monoTriangulationFun`, `monoTriangulationFunBackend`, `triangulateConvexPoly`,
/// `sampleMonoPoly` and `monoPolyPart` (`nurbtess`, `internals`) runs this same loop, keeping
/// the first of equal points as its strict comparisons do.
pub(crate) fn extremes<T: Copy>(
    mut items: impl Iterator<Item = T>,
    point: impl Fn(T) -> Pt,
    cmp: fn(Pt, Pt) -> Ordering,
) -> Option<(T, T)> {
    let first = items.next()?;
    let (mut top, mut bot) = (first, first);
    for t in items {
        if cmp(point(top), point(t)) == Ordering::Less {
            top = t;
        }
        if cmp(point(bot), point(t)) == Ordering::Greater {
            bot = t;
        }
    }
    Some((top, bot))
}

/// GLU `reflexChain`: the pending vertices of one side, each new vertex closing a fan over
/// those it sees convexly.
pub(crate) struct ReflexChain {
    queue: Vec<Pt>,
    increasing: bool,
}

impl ReflexChain {
    pub fn new(increasing: bool) -> Self {
        Self { queue: Vec::new(), increasing }
    }

    /// `reflexChain::processNewVertex`.
    pub fn process(&mut self, v: Pt, out: &mut Vec<Piece>) {
        let q = &self.queue;
        if q.len() <= 1 {
            self.queue.push(v);
            return;
        }
        let j = q.len() - 1;
        let mut i = j;
        while i >= 1 {
            let reflex = if self.increasing { area(q[i - 1], q[i], v) <= 0.0 } else { area(v, q[i], q[i - 1]) <= 0.0 };
            if reflex {
                break;
            }
            i -= 1;
        }
        if i < j {
            let mut fan = vec![v];
            if self.increasing {
                fan.extend_from_slice(&q[i..=j]);
            } else {
                fan.extend(q[i..=j].iter().rev());
            }
            out.push(Piece::Fan(fan));
        }
        self.queue.truncate(i + 1);
        self.queue.push(v);
    }

    /// `reflexChain::outputFan`: a fan from `v` over every pending vertex.
    pub fn output_fan(&self, v: Pt, out: &mut Vec<Piece>) {
        let mut fan = vec![v];
        if self.increasing {
            fan.extend_from_slice(&self.queue);
        } else {
            fan.extend(self.queue.iter().rev());
        }
        out.push(Piece::Fan(fan));
    }
}

/// GLU `monoTriangulationFunBackend(loop, compV2InY)`: the fans covering the loop `lp`.
pub(super) fn triangulate_loop(arcs: &Arcs, lp: &[ArcId]) -> Vec<Piece> {
    let (top, bot) = extremes(lp.iter().copied(), |a| arcs.tail(a), comp_v2_in_y).expect("a loop has arcs");
    let inner = |a: ArcId| &arcs[a].pts[..arcs[a].pts.len().saturating_sub(1)];
    let mut inc: Vec<Pt> = inner(top).iter().skip(1).copied().collect();
    let mut a = arcs[top].next;
    while a != bot {
        inc.extend_from_slice(inner(a));
        a = arcs[a].next;
    }
    let mut dec: Vec<Pt> = Vec::new();
    let mut a = arcs[top].prev;
    while a != bot {
        dec.extend(inner(a).iter().rev());
        a = arcs[a].prev;
    }
    dec.extend(inner(bot).iter().skip(1).rev());
    let mut out = Vec::new();
    chains(arcs.tail(top), arcs.tail(bot), (&inc, 0), (&dec, 0), comp_v2_in_y, &mut out);
    out
}

/// GLU `monoTriangulationRecFunBackend` (and `monoTriangulationRec`, the same with
/// `compV2InY`): the region between the increasing and decreasing chains, from `top` down
/// to `bot`, starting at the given indices.
pub(crate) fn chains(
    mut top: Pt,
    bot: Pt,
    (inc, mut i_inc): (&[Pt], usize),
    (dec, mut i_dec): (&[Pt], usize),
    cmp: fn(Pt, Pt) -> Ordering,
    out: &mut Vec<Piece>,
) {
    loop {
        if i_inc >= inc.len() || i_dec >= dec.len() {
            let (rest, increasing) =
                if i_inc >= inc.len() { (&dec[i_dec.min(dec.len())..], false) } else { (&inc[i_inc..], true) };
            let mut chain = ReflexChain::new(increasing);
            chain.process(top, out);
            for &v in rest {
                chain.process(v, out);
            }
            chain.process(bot, out);
            return;
        }
        if cmp(inc[i_inc], dec[i_dec]) != Ordering::Greater {
            let mut chain = ReflexChain::new(false);
            chain.process(top, out);
            let mut i = i_dec;
            while i < dec.len() && cmp(inc[i_inc], dec[i]) != Ordering::Greater {
                chain.process(dec[i], out);
                i += 1;
            }
            chain.output_fan(inc[i_inc], out);
            top = dec[i - 1];
            i_dec = i;
        } else {
            let mut chain = ReflexChain::new(true);
            chain.process(top, out);
            let mut i = i_inc;
            while i < inc.len() && cmp(inc[i], dec[i_dec]) == Ordering::Greater {
                chain.process(inc[i], out);
                i += 1;
            }
            chain.output_fan(dec[i_dec], out);
            top = inc[i - 1];
            i_inc = i;
        }
    }
}
