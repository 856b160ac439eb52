//! Cutting a bin of trim loops along a line u = value or v = value (`Subdivider::split` in
//! `internals/splitarcs.cc`, `Subdivider::partition` and `arc_split` in `intersect.cc`, the
//! sorters of `arcsorter.cc`): arcs crossing the line are cut there (at a sample on it, or at
//! a new point, leaving GLU's degenerate triangle), the arcs ending on the line are sorted
//! along it and joined pairwise by two new arcs running along the line in opposite senses,
//! one for each side.

use super::arcs::{ArcId, Arcs, Bin, Side};
use super::turns::ccw_turn;
use super::{Jump, Subdivider};
use crate::glu::draw::slicer::border::{side_down, side_up};
use crate::glu::draw::slicer::Piece;

/// The bins of arcs ending on the line, by which end and side (GLU `partition`'s locals).
#[derive(Default)]
struct OnLine {
    head_left: Bin,
    tail_left: Bin,
    head_right: Bin,
    tail_right: Bin,
}

impl Subdivider<'_> {
    /// GLU `Subdivider::split`: `bin` cut along coordinate `param` = `value` into the part
    /// below (`left`) and above (`right`).
    pub(crate) fn split(&mut self, bin: &mut Bin, param: usize, value: f32) -> Result<(Bin, Bin), Jump> {
        let (mut left, mut right) = (Bin::default(), Bin::default());
        let (mut list, unknown) = self.partition(bin, &mut left, &mut right, param, value)?;
        if list.len() % 2 == 1 {
            return Err(Jump(29));
        }
        self.sort_along(&mut list, param)?;
        for pair in list.chunks_exact(2) {
            self.check(pair[0], pair[1], param)?;
        }
        for pair in list.chunks_exact(2) {
            self.join(&mut left, &mut right, pair[0], pair[1], param);
        }
        for &j in &list {
            let below = |p: [f32; 2]| p[param] <= value;
            if below(self.arcs.head(j)) && below(self.arcs.tail(j)) {
                left.add(j);
            } else {
                right.add(j);
            }
        }
        adopt(&mut self.arcs, unknown, [&mut left, &mut right]);
        Ok((left, right))
    }

    /// GLU `Subdivider::partition`: every arc of `bin` to the left or right bin, cut where it
    /// crosses the line; the arcs ending on the line classified into the returned list of
    /// intersections (in GLU's bin order) or a side; arcs lying on the line returned apart.
    fn partition(
        &mut self,
        bin: &mut Bin,
        left: &mut Bin,
        right: &mut Bin,
        param: usize,
        value: f32,
    ) -> Result<(Vec<ArcId>, Bin), Jump> {
        let mut on = OnLine::default();
        let mut unknown = Bin::default();
        while let Some(j) = bin.remove() {
            let t = self.arcs.tail(j)[param] - value;
            let h = self.arcs.head(j)[param] - value;
            if t > 0.0 {
                if h > 0.0 {
                    right.add(j);
                } else if h == 0.0 {
                    on.tail_right.add(j);
                } else {
                    self.arc_split(j, param, value, false);
                    on.tail_right.add(j);
                    on.head_left.add(self.arcs[j].next);
                }
            } else if t == 0.0 {
                if h > 0.0 {
                    on.head_right.add(j);
                } else if h == 0.0 {
                    unknown.add(j);
                } else {
                    on.head_left.add(j);
                }
            } else if h > 0.0 {
                self.arc_split(j, param, value, true);
                on.tail_left.add(j);
                on.head_right.add(self.arcs[j].next);
            } else if h == 0.0 {
                on.tail_left.add(j);
            } else {
                left.add(j);
            }
        }
        let mut inter = Bin::default();
        self.classify(&mut on.head_left, &mut inter, left, param, value, End::HeadOnLeft)?;
        self.classify(&mut on.tail_left, &mut inter, left, param, value, End::TailOnLeft)?;
        self.classify(&mut on.head_right, &mut inter, right, param, value, End::HeadOnRight)?;
        self.classify(&mut on.tail_right, &mut inter, right, param, value, End::TailOnRight)?;
        let mut list = Vec::with_capacity(inter.len());
        while let Some(j) = inter.remove() {
            list.push(j);
        }
        Ok((list, unknown))
    }

    /// GLU `arc_split`: arc `j` (increasing in `param` or not) cut where it crosses the line,
    /// found by bisection (`pwlarc_intersect`); the second part becomes a new arc after `j`.
    fn arc_split(&mut self, j: ArcId, param: usize, value: f32, increasing: bool) {
        let pts = self.arcs[j].pts.clone();
        let (mut lo, mut hi) = if increasing { (0, pts.len() - 1) } else { (pts.len() - 1, 0) };
        // `lo` below the value, `hi` above it.
        while lo.abs_diff(hi) > 1 {
            let mid = (lo + hi) / 2;
            let x = pts[mid][param];
            if x > value {
                hi = mid;
            } else if x < value {
                lo = mid;
            } else {
                let second = pts[mid..].to_vec();
                self.arcs[j].pts.truncate(mid + 1);
                return self.insert_after(j, second);
            }
        }
        let (i, k) = (lo.max(hi), lo.min(hi)); // the cut lies between k and i = k + 1
        let new = interpolate(pts[lo], pts[hi], param, value);
        if self.degenerate {
            self.pieces.push(Piece::Fan(vec![pts[i], new, pts[k]]));
        }
        let mut second = vec![new];
        second.extend_from_slice(&pts[i..]);
        let first = &mut self.arcs[j].pts;
        first.truncate(k + 1);
        first.push(new);
        self.insert_after(j, second);
    }

    /// A copy of arc `j` (GLU's `Arc(Arc*, PwlArc*)` keeps its type bits) with `pts`, linked
    /// after it.
    fn insert_after(&mut self, j: ArcId, pts: Vec<[f32; 2]>) {
        let copy = self.arcs[j].clone();
        let id = self.arcs.add(pts, copy.side, copy.bezier);
        self.arcs[id].itail = copy.itail;
        self.arcs[id].mark = copy.mark;
        self.arcs.append(id, Some(j));
    }

    /// GLU's `classify_*_s` and `classify_*_t`: arcs with one end on the line go to the list of
    /// intersections (`inter`) or stay on their side (`out`), by how the loop turns there.
    fn classify(
        &mut self,
        bin: &mut Bin,
        inter: &mut Bin,
        out: &mut Bin,
        p: usize,
        value: f32,
        end: End,
    ) -> Result<(), Jump> {
        let q = 1 - p;
        while let Some(j) = bin.remove() {
            let tail_on_line = matches!(end, End::HeadOnLeft | End::HeadOnRight);
            self.arcs[j].itail = tail_on_line;
            // The neighbour beyond the end on the line, and the pair in loop order.
            let (other, pair) = if tail_on_line {
                let prev = self.arcs[j].prev;
                (self.arcs.tail(prev), (prev, j))
            } else {
                let next = self.arcs[j].next;
                (self.arcs.head(next), (j, next))
            };
            let neighbour = if tail_on_line { pair.0 } else { pair.1 };
            let diff = other[p] - value;
            let (nt, nh) = (self.arcs.tail(neighbour), self.arcs.head(neighbour));
            // GLU's tie rule, when the neighbour lies along the line.
            let along = if p == 0 { nt[q] > nh[q] } else { nt[q] <= nh[q] };
            let to_inter = match end {
                End::TailOnLeft if diff > 0.0 => true,
                End::TailOnLeft if diff < 0.0 => !ccw_turn(&self.arcs, pair.0, pair.1, p, false)?,
                End::TailOnLeft => along,
                End::HeadOnLeft if diff > 0.0 => false,
                End::HeadOnLeft if diff < 0.0 => !ccw_turn(&self.arcs, pair.0, pair.1, p, false)?,
                End::HeadOnLeft => along,
                End::TailOnRight if diff > 0.0 => !ccw_turn(&self.arcs, pair.0, pair.1, p, true)?,
                End::TailOnRight if diff < 0.0 => true,
                End::TailOnRight => !along,
                End::HeadOnRight if diff > 0.0 => !ccw_turn(&self.arcs, pair.0, pair.1, p, true)?,
                End::HeadOnRight if diff < 0.0 => false,
                End::HeadOnRight => !along,
            };
            if to_inter {
                inter.add(j);
            } else {
                out.add(j);
            }
        }
        Ok(())
    }

    /// GLU's `ArcSdirSorter` (increasing t along a line of constant s) and `ArcTdirSorter`
    /// (decreasing s along a line of constant t), through GLU's own quicksort.
    fn sort_along(&self, list: &mut [ArcId], param: usize) -> Result<(), Jump> {
        let mut error = None;
        let mut cmp = |a: ArcId, b: ArcId| match self.compare_on_line(a, b, param) {
            Ok(c) => c,
            Err(e) => {
                error = Some(e);
                0
            }
        };
        super::sorter::qsort(list, &mut cmp);
        error.map_or(Ok(()), Err)
    }

    /// One comparison of GLU's arc sorters.
    fn compare_on_line(&self, j1: ArcId, j2: ArcId, p: usize) -> Result<i32, Jump> {
        let q = 1 - p;
        let on_line = |j: ArcId| if self.arcs[j].itail { self.arcs.tail(j) } else { self.arcs.rhead(j) };
        let diff = on_line(j1)[q] - on_line(j2)[q];
        let sign = if p == 0 { 1 } else { -1 };
        if diff < 0.0 {
            return Ok(-sign);
        } else if diff > 0.0 {
            return Ok(sign);
        }
        let a = &self.arcs;
        let turn = |x, y, inc| ccw_turn(a, x, y, p, inc);
        // GLU's tie-breaks, written out per sorter as `arcsorter.cc` has them.
        Ok(if self.arcs[j1].itail {
            if a.tail(j2)[p] < a.tail(j1)[p] {
                if turn(j2, j1, false)? {
                    1
                } else {
                    -1
                }
            } else if turn(j2, j1, true)? {
                -1
            } else {
                1
            }
        } else if a.head(j2)[p] < a.head(j1)[p] {
            if turn(j1, j2, false)? {
                -1
            } else {
                1
            }
        } else if turn(j1, j2, true)? {
            1
        } else {
            -1
        })
    }

    /// GLU `check_s` / `check_t`: the first of a pair must leave the line increasing, the
    /// second arrive decreasing, else error 28.
    fn check(&self, j1: ArcId, j2: ArcId, p: usize) -> Result<(), Jump> {
        let a = &self.arcs;
        let ok1 = a.tail(j1)[p] < a.head(j1)[p];
        let ok2 = a.tail(j2)[p] > a.head(j2)[p];
        if ok1 && ok2 {
            Ok(())
        } else {
            Err(Jump(28))
        }
    }

    /// GLU `join_s` / `join_t`: the pair linked across the line by two new arcs along it (or
    /// directly when they meet at one point), sampled now at the boundary steps in pwl mode,
    /// or left as two-point "bezier" arcs for the next sampling.
    fn join(&mut self, left: &mut Bin, right: &mut Bin, j1: ArcId, j2: ArcId, p: usize) {
        let j1 = if self.arcs[j1].itail { j1 } else { self.arcs[j1].next };
        let j2 = if self.arcs[j2].itail { j2 } else { self.arcs[j2].next };
        let (a, b) = (self.arcs.tail(j1), self.arcs.tail(j2));
        let q = 1 - p;
        if a[q] == b[q] {
            return self.simple_link(j1, j2);
        }
        let (up, down) = if p == 0 {
            // join_s: newright from t1 up to t2 (to the left bin), newleft back down.
            let (s, t1, t2) = (a[0], a[1], b[1]);
            let right_pts = self.line(Side::Right, [s, t1], [s, t2], self.stepsizes[0], |t| [s, t]);
            let left_pts = self.line(Side::Left, [s, t2], [s, t1], self.stepsizes[2], |t| [s, t]);
            (self.arcs.add(right_pts, Side::Right, self.bezier), self.arcs.add(left_pts, Side::Left, self.bezier))
        } else {
            // join_t: newtop from s1 down to s2 (to the bottom bin), newbot back.
            let (t, s1, s2) = (a[1], a[0], b[0]);
            let top_pts = self.line(Side::Top, [s1, t], [s2, t], self.stepsizes[1], |s| [s, t]);
            let bot_pts = self.line(Side::Bottom, [s2, t], [s1, t], self.stepsizes[3], |s| [s, t]);
            (self.arcs.add(top_pts, Side::Top, self.bezier), self.arcs.add(bot_pts, Side::Bottom, self.bezier))
        };
        self.link(j1, j2, up, down);
        left.add(up);
        right.add(down);
    }

    /// The points of a new arc along a line from `from` to `to`: its two ends in "bezier"
    /// mode (`ArcTessellator::bezier`), else sampled at `rate` (`pwl_right`, `pwl_left`,
    /// `pwl_top`, `pwl_bottom`).
    fn line(&self, side: Side, from: [f32; 2], to: [f32; 2], rate: f32, at: impl Fn(f32) -> [f32; 2]) -> Vec<[f32; 2]> {
        if self.bezier {
            return vec![from, to];
        }
        sample_side(side, from, to, rate).into_iter().map(at).collect()
    }

    /// GLU `Subdivider::link`.
    fn link(&mut self, j1: ArcId, j2: ArcId, up: ArcId, down: ArcId) {
        let a = &mut self.arcs;
        a[up].next = j2;
        a[down].next = j1;
        a[up].prev = a[j1].prev;
        a[down].prev = a[j2].prev;
        let (dn, un, dp, up_p) = (a[down].next, a[up].next, a[down].prev, a[up].prev);
        a[dn].prev = down;
        a[un].prev = up;
        a[dp].next = down;
        a[up_p].next = up;
    }

    /// GLU `Subdivider::simple_link`.
    fn simple_link(&mut self, j1: ArcId, j2: ArcId) {
        let a = &mut self.arcs;
        let tmp = a[j2].prev;
        a[j2].prev = a[j1].prev;
        a[j1].prev = tmp;
        let (p2, p1) = (a[j2].prev, a[j1].prev);
        a[p2].next = j2;
        a[p1].next = j1;
    }
}

/// Which end of an arc lies on the line, and on which side the arc is.
#[derive(Clone, Copy)]
enum End {
    HeadOnLeft,
    TailOnLeft,
    HeadOnRight,
    TailOnRight,
}

/// The coordinate that varies along a border side sampled at `rate`: right and bottom
/// increase (`pwl_right`, `pwl_bottom`), left and top decrease (`pwl_left`, `pwl_top`).
pub(crate) fn sample_side(side: Side, from: [f32; 2], to: [f32; 2], rate: f32) -> Vec<f32> {
    match side {
        Side::Right => side_up(from[1], to[1], rate),
        Side::Left => side_down(from[1], to[1], rate),
        Side::Bottom => side_up(from[0], to[0], rate),
        Side::Top | Side::None => side_down(from[0], to[0], rate),
    }
}

/// GLU `vert_interp`: the point of segment l–r where coordinate `p` is `value`.
fn interpolate(l: [f32; 2], r: [f32; 2], p: usize, value: f32) -> [f32; 2] {
    let q = 1 - p;
    let mut n = [0.0; 2];
    n[p] = value;
    n[q] = if l[q] != r[q] {
        let ratio = (value - l[p]) / (r[p] - l[p]);
        l[q] + ratio * (r[q] - l[q])
    } else {
        l[q]
    };
    n
}

/// GLU `Bin::adopt` for the arcs lying on the line: each goes into the bin of the first arc
/// after it in its loop that does not lie on the line, right after that arc.
fn adopt(arcs: &mut Arcs, mut orphans: Bin, bins: [&mut Bin; 2]) {
    for j in orphans.arcs() {
        arcs[j].mark = true;
    }
    let [a, b] = bins;
    while let Some(orphan) = orphans.remove() {
        let mut parent = arcs[orphan].next;
        while parent != orphan && arcs[parent].mark {
            parent = arcs[parent].next;
        }
        if parent == orphan {
            continue;
        }
        arcs[orphan].mark = false;
        let _ = a.insert_after(parent, orphan) || b.insert_after(parent, orphan);
    }
}
