//! Loops made monotone (`internals/monotonizer.cc`, `Subdivider::findIrregularS` and
//! `findIrregularT` in `subdivider.cc`): each trim polyline is broken where it turns back in
//! u or v, and the lines through the loops' points of non-monotonicity are where GLU cuts the
//! regions before slicing them.

use super::arcs::{ArcId, Bin};
use super::turns::ccw_turn;
use super::{Jump, Subdivider};

/// The sense of a segment in one coordinate.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Dir {
    None,
    Same,
    Down,
    Up,
}

fn dir(d: f32) -> Dir {
    if d == 0.0 {
        Dir::Same
    } else if d < 0.0 {
        Dir::Down
    } else {
        Dir::Up
    }
}

impl Subdivider<'_> {
    /// GLU `Subdivider::monotonize`: arc `j` broken into pieces monotone in u and in v, each
    /// new piece linked after the last and put at the head of `bin`; a last piece of no length
    /// (or an arc of one point) is dropped from its loop and the bin.
    pub(crate) fn monotonize(&mut self, j: ArcId, bin: &mut Bin) {
        let pts = std::mem::take(&mut self.arcs[j].pts);
        let side = self.arcs[j].side;
        let (mut sdir, mut tdir) = (Dir::None, Dir::None);
        let mut degenerate = true;
        let (mut jarc, mut first) = (j, 0usize);
        for k in 0..pts.len().saturating_sub(1) {
            let (s, t) = (dir(pts[k + 1][0] - pts[k][0]), dir(pts[k + 1][1] - pts[k][1]));
            let moving = s != Dir::Same || t != Dir::Same;
            let change = s != sdir || t != tdir;
            (sdir, tdir) = (s, t);
            if change {
                if !degenerate {
                    self.arcs[jarc].pts = pts[first..=k].to_vec();
                    let next = self.arcs.add(Vec::new(), side, false);
                    jarc = self.arcs.append(next, Some(jarc));
                    bin.add(jarc);
                }
                first = k;
                degenerate = !moving;
            }
        }
        self.arcs[jarc].pts = pts[first.min(pts.len().saturating_sub(1))..].to_vec();
        if degenerate {
            let (p, n) = (self.arcs[jarc].prev, self.arcs[jarc].next);
            self.arcs[p].next = n;
            self.arcs[n].prev = p;
            bin.remove_this(jarc);
        }
    }

    /// GLU `Subdivider::findIrregularS`: the u of every point where a loop turns back in v
    /// clockwise, sorted, once each.
    pub(crate) fn irregular_s(&self, bin: &Bin) -> Vec<f32> {
        let mut out = Vec::new();
        for j in bin.arcs() {
            let prev = self.arcs[j].prev;
            let (mut a, b, mut c) = (self.arcs.tail(prev), self.arcs.tail(j), self.arcs.head(j));
            if b[1] == a[1] && b[1] == c[1] {
                continue;
            }
            if (b[1] <= a[1] && b[1] <= c[1]) || (b[1] >= a[1] && b[1] >= c[1]) {
                // A loop of two arcs: look back along the arcs instead.
                if a == c {
                    let (own, before) = (&self.arcs[j].pts, &self.arcs[prev].pts);
                    if own.len() > 2 {
                        c = own[own.len() - 2];
                    } else if before.len() > 2 {
                        a = before[before.len() - 2];
                    }
                }
                if area(a, b, c) < 0.0 {
                    out.push(b[0]);
                }
            }
        }
        filter(out)
    }

    /// GLU `Subdivider::findIrregularT`: the v of every point where a loop turns back in u
    /// along a line of constant v, the wrong way.
    pub(crate) fn irregular_t(&self, bin: &Bin) -> Result<Vec<f32>, Jump> {
        let mut out = Vec::new();
        for j in bin.arcs() {
            let prev = self.arcs[j].prev;
            let (a, b, c) = (self.arcs.tail(prev), self.arcs.tail(j), self.arcs.head(j));
            if b[0] == a[0] && b[0] == c[0] {
                continue;
            }
            let low = b[0] <= a[0] && b[0] <= c[0];
            let high = b[0] >= a[0] && b[0] >= c[0];
            if !low && !high {
                continue;
            }
            if a[1] != b[1] && b[1] != c[1] {
                continue;
            }
            if !ccw_turn(&self.arcs, prev, j, 0, low)? {
                out.push(b[1]);
            }
        }
        Ok(filter(out))
    }
}

/// GLU `area` (`nurbtess/polyUtil.cc`): twice the signed area of a, b, c.
pub(crate) fn area(a: [f32; 2], b: [f32; 2], c: [f32; 2]) -> f32 {
    let (bx, by) = (b[0] - a[0], b[1] - a[1]);
    let (cx, cy) = (c[0] - a[0], c[1] - a[1]);
    bx * cy - cx * by
}

/// GLU `Flist::filter`: sorted, duplicates removed.
fn filter(mut v: Vec<f32>) -> Vec<f32> {
    v.sort_by(f32::total_cmp);
    v.dedup();
    v
}
