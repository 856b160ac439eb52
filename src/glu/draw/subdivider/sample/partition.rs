//! GLU's cuts of a polygon into polygons monotone in u: one diagonal from a single interior cusp
//! (`findDiagonal_singleCuspX`, `partitionX.cc`) and the linear-time partition of a polygon
//! monotone in v (`monoPolyPart`, `nurbtess/monoPolyPart.cc`, after Zicheng Liu's
//! "Quality-Oriented Linear Time Tessellation"). Both work on GLU's `directedLine` loops of
//! one-segment lines (`polygonConvert`, `sampleMonoPoly.cc`) joined by diagonals
//! (`directedLine::connectDiagonal_2slines`): here an arena of segments linked both ways.

use super::tri::comp_v2_in_x;
use super::{Poly, Pt};
use crate::glu::draw::subdivider::mono::{comp_v2_in_y, extremes};
use std::cmp::Ordering;

/// A segment of a loop: from `head` to `tail`, with its neighbours in the arena.
#[derive(Clone, Copy)]
struct Seg {
    head: Pt,
    tail: Pt,
    next: usize,
    prev: usize,
}

/// Loops of segments that diagonals cut apart.
struct Loops {
    segs: Vec<Seg>,
}

impl Loops {
    /// GLU `polygonConvert`: the loop of `poly` from the head of its line `start`, one segment
    /// per pair of consecutive points.
    fn convert(poly: &Poly, start: usize) -> Self {
        let mut pts = Vec::new();
        for k in 0..poly.len() {
            let line = &poly.lines[(start + k) % poly.len()];
            pts.extend(line.windows(2).map(|w| (w[0], w[1])));
        }
        let n = pts.len();
        let segs = pts
            .into_iter()
            .enumerate()
            .map(|(i, (head, tail))| Seg { head, tail, next: (i + 1) % n, prev: (i + n - 1) % n })
            .collect();
        Self { segs }
    }

    fn head(&self, s: usize) -> Pt {
        self.segs[s].head
    }

    fn next(&self, s: usize) -> usize {
        self.segs[s].next
    }

    fn prev(&self, s: usize) -> usize {
        self.segs[s].prev
    }

    /// GLU `connectDiagonal_2slines(v1, v2)`: the diagonal from v1's head to v2's head, twice;
    /// returns (the segment v2 → v1 opening the loop on through v1, the segment v1 → v2
    /// opening the loop on through v2).
    fn connect(&mut self, v1: usize, v2: usize) -> (usize, usize) {
        let (a, b) = (self.head(v1), self.head(v2));
        let (v1_prev, v2_prev) = (self.prev(v1), self.prev(v2));
        let dec = self.segs.len();
        let inc = dec + 1;
        self.segs.push(Seg { head: b, tail: a, next: v1, prev: v2_prev });
        self.segs.push(Seg { head: a, tail: b, next: v2, prev: v1_prev });
        self.segs[v1].prev = dec;
        self.segs[v2_prev].next = dec;
        self.segs[v2].prev = inc;
        self.segs[v1_prev].next = inc;
        (dec, inc)
    }

    /// The loop from segment `s`, as a polygon of one-segment lines.
    fn poly(&self, s: usize) -> Poly {
        let mut lines = vec![vec![self.head(s), self.segs[s].tail]];
        let mut t = self.next(s);
        while t != s && lines.len() <= self.segs.len() {
            lines.push(vec![self.head(t), self.segs[t].tail]);
            t = self.next(t);
        }
        Poly { lines }
    }

    /// `directedLine::numEdges` of the loop from `s` is below 4 (`monoPolyPart`'s small cases).
    fn fewer_than_four(&self, s: usize) -> bool {
        let p = self.prev(s);
        p == s || p == self.next(s) || self.prev(p) == self.next(s)
    }
}

/// GLU's single-cusp cut (`monoTriangulationOpt`, `sampleMonoPoly`): the polygon from the
/// cusp's line, one segment a line, cut by the diagonal from the cusp to the first vertex past
/// it in u (`findDiagonal_singleCuspX`); the two halves, or `None` when no vertex lies past it
/// (self-intersecting loops).
pub(crate) fn split_at_cusp(poly: &Poly, cusp: usize) -> Option<[Poly; 2]> {
    let mut loops = Loops::convert(poly, cusp);
    let c = 0;
    let head = loops.head(c);
    let minimal = comp_v2_in_x(head, loops.segs[c].tail) == Ordering::Less;
    let want = if minimal { Ordering::Greater } else { Ordering::Less };
    let mut other = loops.next(c);
    while other != c && comp_v2_in_x(head, loops.head(other)) != want {
        other = loops.next(other);
    }
    if other == c {
        return None;
    }
    let (p1, p2) = loops.connect(c, other);
    Some([loops.poly(p1), loops.poly(p2)])
}

/// `is_u_maximal`: both neighbours strictly before the vertex in u.
fn u_maximal(l: &Loops, v: usize) -> bool {
    comp_v2_in_x(l.head(l.prev(v)), l.head(v)) == Ordering::Less
        && comp_v2_in_x(l.head(l.next(v)), l.head(v)) == Ordering::Less
}

/// `is_u_minimal`: both neighbours strictly after the vertex in u.
fn u_minimal(l: &Loops, v: usize) -> bool {
    comp_v2_in_x(l.head(l.prev(v)), l.head(v)) == Ordering::Greater
        && comp_v2_in_x(l.head(l.next(v)), l.head(v)) == Ordering::Greater
}

/// Which way a walk goes round a loop.
#[derive(Clone, Copy)]
enum Dir {
    Next,
    Prev,
}

impl Loops {
    fn step(&self, s: usize, dir: Dir) -> usize {
        match dir {
            Dir::Next => self.next(s),
            Dir::Prev => self.prev(s),
        }
    }

    /// The first segment from `from` (itself included) going `dir` where `stop` holds; `None`
    /// past every segment (a loop GLU would walk forever).
    fn find(&self, from: usize, dir: Dir, stop: impl Fn(usize) -> bool) -> Option<usize> {
        let mut t = from;
        for _ in 0..=self.segs.len() {
            if stop(t) {
                return Some(t);
            }
            t = self.step(t, dir);
        }
        None
    }

    /// The `monoPolyPart` scan from `from` (excluded) towards `bot`: the first vertex where
    /// `extreme` holds (or `bot`), and the vertex furthest along `better` on the way, starting
    /// from `best`.
    fn scan(
        &self,
        from: usize,
        bot: usize,
        dir: Dir,
        mut best: usize,
        better: impl Fn(f32, f32) -> bool,
        extreme: impl Fn(&Loops, usize) -> bool,
    ) -> Option<(usize, usize)> {
        let u = |v: usize| self.head(v)[0];
        let mut t = self.step(from, dir);
        for _ in 0..=self.segs.len() {
            if t == bot {
                if better(u(bot), u(best)) {
                    best = bot;
                }
                return Some((bot, best));
            }
            if better(u(t), u(best)) {
                best = t;
            }
            if extreme(self, t) {
                return Some((t, best));
            }
            t = self.step(t, dir);
        }
        None
    }
}

/// GLU `monoPolyPart(polygonConvert(poly))`: the polygon, monotone in v, cut into polygons
/// monotone in u, in GLU's list order (the rest first, then the pieces cut off, the last cut
/// first); `None` where GLU would never finish (loops that cross themselves).
pub(crate) fn mono_poly_part(poly: &Poly) -> Option<Vec<Poly>> {
    let mut l = Loops::convert(poly, 0);
    let polygon = 0;
    if l.fewer_than_four(polygon) {
        return Some(vec![l.poly(polygon)]);
    }
    let around = std::iter::successors(Some(polygon), |&t| Some(l.next(t)).filter(|&t| t != polygon));
    let (top, bot) = extremes(around, |t| l.head(t), comp_v2_in_y).expect("the loop has a vertex");
    let u = |l: &Loops, v: usize| l.head(v)[0];
    let left = |a: f32, b: f32| a < b;
    let right = |a: f32, b: f32| a > b;
    // A: the first u-maximal vertex down the left chain, C: the leftmost vertex above it;
    // B: the first u-minimal vertex down the right chain, D: the rightmost above it.
    let (mut a, mut c) = l.scan(top, bot, Dir::Next, top, left, u_maximal)?;
    let (mut b, mut d) = l.scan(top, bot, Dir::Prev, top, right, u_minimal)?;
    if u(&l, c) >= u(&l, d) {
        return Some(vec![l.poly(polygon)]);
    }
    let above = |l: &Loops, v: usize, w: usize| comp_v2_in_y(l.head(v), l.head(w)) == Ordering::Greater;
    // G: the left chain's vertex right above B; H: the right chain's right above A.
    let mut g = l.prev(l.find(top, Dir::Next, |t| !above(&l, t, b))?);
    let mut h = l.next(l.find(top, Dir::Prev, |t| !above(&l, t, a))?);
    let (mut out, mut current) = (Vec::new(), polygon);
    // Each round cuts one polygon off; the bound only stops loops that GLU would not leave.
    for _ in 0..=l.segs.len() * 2 {
        if a == bot && b == bot {
            out.push(current);
            out.reverse();
            return Some(out.into_iter().map(|s| l.poly(s)).collect());
        }
        if above(&l, a, b) {
            // Cut A to E, the first vertex from C back to D as far right as A (at most H).
            let mut e = l.find(c, Dir::Prev, |t| t == d || u(&l, t) >= u(&l, a))?;
            if u(&l, e) > u(&l, h) {
                e = h;
            }
            let (p1, p2) = l.connect(a, e);
            out.push(p2);
            current = p1;
            if e == d {
                d = p1;
            }
            if e == h {
                h = p1;
            }
            if l.head(g)[1] >= l.head(a)[1] {
                g = a;
            }
            (a, c) = l.scan(a, bot, Dir::Next, a, left, u_maximal)?;
            h = if a == bot { bot } else { l.next(l.find(h, Dir::Prev, |t| !above(&l, t, a))?) };
        } else {
            // Cut F to B, F the first vertex from D on to C as far left as B (at least G).
            let mut f = l.find(d, Dir::Next, |t| t == c || u(&l, t) <= u(&l, b))?;
            if u(&l, f) < u(&l, g) {
                f = g;
            }
            let (p1, p2) = l.connect(f, b);
            out.push(p2);
            current = p1;
            b = p1;
            if l.head(h)[1] >= l.head(b)[1] {
                h = p1;
            }
            (b, d) = l.scan(b, bot, Dir::Prev, b, right, u_minimal)?;
            g = if b == bot { bot } else { l.prev(l.find(g, Dir::Next, |t| !above(&l, t, b))?) };
        }
    }
    None
}
