//! GLU's sampling of a region that is not a rectangle (`sampleMonoPoly`,
//! `nurbtess/sampleMonoPoly.cc`, called by `Slicer::slice_new`): the region, monotone in v,
//! is laid on the grid of its steps; where grid lines cross it with grid points inside,
//! those points form blocks of quads (`rectBlock`, drawn as grid meshes), and the bands
//! between the blocks and the trim chains are triangulated in fans, component by component
//! down the region (`sampleMonoPolyRec`, `sampleConnectedComp`).

mod chain;
mod convex;
mod corners;
mod ends;
mod grid;
mod partition;
mod sides;
mod tri;

pub(crate) use crate::glu::draw::slicer::c_int;
use crate::glu::draw::slicer::Piece;
use crate::glu::draw::subdivider::mono::{chains, comp_v2_in_y, extremes};
use chain::index_strict_below;
use corners::{down_corners, neck, up_corners, Sides};
use ends::{comp_bot, comp_top, End};
use grid::{left_indices, right_indices, BoundaryChain, GridWrap};
use sides::{comp_left, comp_right, Comp};
use std::cmp::Ordering;

pub(crate) type Pt = [f32; 2];

/// `ZERO` of `sampleMonoPoly.cc`.
pub(crate) const ZERO: f64 = 0.00001;

/// A polygon as GLU's `directedLine` loop: lines of points, each starting where the one
/// before it ends.
pub(crate) struct Poly {
    pub lines: Vec<Vec<Pt>>,
}

impl Poly {
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    pub fn next(&self, i: usize) -> usize {
        (i + 1) % self.len()
    }

    pub fn prev(&self, i: usize) -> usize {
        (i + self.len() - 1) % self.len()
    }

    /// `directedLine::head`: the line's first point.
    pub fn head(&self, i: usize) -> Pt {
        self.lines[i][0]
    }

    /// `directedLine::tail`: the line's last point.
    pub fn tail(&self, i: usize) -> Pt {
        *self.lines[i].last().expect("lines have points")
    }

    /// The lines whose heads are the greatest and the least under `cmp` (the first of equal
    /// heads; line 0 for both in a polygon of no lines, as GLU's loop leaves them): see
    /// [`extremes`].
    pub fn extremes(&self, cmp: fn(Pt, Pt) -> Ordering) -> (usize, usize) {
        extremes(0..self.len(), |t| self.head(t), cmp).unwrap_or((0, 0))
    }

    /// The chains from the head of line `top` down to the head of line `bot`: forwards (the
    /// left, or increasing, chain) and backwards, each without its ends (as
    /// `monoTriangulationFun` and `sampleMonoPoly` build them).
    pub fn chains(&self, top: usize, bot: usize) -> (Vec<Pt>, Vec<Pt>) {
        let inner = |l: &Vec<Pt>| l[..l.len() - 1].to_vec();
        let mut inc: Vec<Pt> =
            self.lines[top].iter().skip(1).take(self.lines[top].len().saturating_sub(2)).copied().collect();
        let mut t = self.next(top);
        while t != bot {
            inc.extend(inner(&self.lines[t]));
            t = self.next(t);
        }
        let mut dec = Vec::new();
        let mut t = self.prev(top);
        while t != bot {
            dec.extend(inner(&self.lines[t]).into_iter().rev());
            t = self.prev(t);
        }
        let b = &self.lines[bot];
        dec.extend(b[1..b.len().saturating_sub(1).max(1)].iter().rev());
        (inc, dec)
    }
}

/// GLU's `primStream` (fans) and whether GLU would have read past its arrays on the way.
#[derive(Default)]
pub(crate) struct Stream {
    pub pieces: Vec<Piece>,
    pub bad: bool,
}

impl Stream {
    /// `primStream::begin`/`insert`/`end(PRIMITIVE_STREAM_FAN)` (and `triangle`).
    pub fn fan(&mut self, pts: Vec<Pt>) {
        if !pts.is_empty() {
            self.pieces.push(Piece::Fan(pts));
        }
    }
}

/// A block of the grid's quads (GLU `rectBlock`): from grid line `up` down to `low`, on each
/// line below the first the grid points `left[k]..=right[k]`.
pub(crate) struct Block {
    pub up: i64,
    pub low: i64,
    pub left: Vec<i64>,
    pub right: Vec<i64>,
}

/// What `sampleMonoPoly` leaves: the fans and the blocks of quads of its grid.
pub(crate) struct Sampled {
    pub pieces: Vec<Piece>,
    pub blocks: Vec<Block>,
}

/// GLU `sampleMonoPoly` on `poly` over a grid of `lines` = (n_u, n_v) lines spanning the
/// region's box; `None` where GLU would read past its arrays (loops it mishandles).
pub(crate) fn sample_mono_poly(
    poly: &Poly,
    lines: (usize, usize),
    bbox: [f32; 4],
    linear: (bool, bool),
) -> Option<Sampled> {
    let grid = GridWrap::new(lines.0, lines.1, (bbox[0], bbox[1]), (bbox[2], bbox[3]));
    let mut s = Stream::default();
    if lines.0 == 2 || lines.1 == 2 {
        if linear.0 && lines.0 == 2 {
            tri::mono_fun(poly, comp_v2_in_y, &mut s);
            return finish(s, lines.0, Vec::new());
        }
        if convex::is_convex(poly) && poly.len() >= 4 {
            convex::triangulate_convex(poly, linear, &mut s);
            return finish(s, lines.0, Vec::new());
        }
        if (linear.1 || convex::is_u_direction(poly)) && tri::mono_u(poly, &mut s) {
            return finish(s, lines.0, Vec::new());
        }
    }
    let (top, bot) = poly.extremes(comp_v2_in_y);
    let (vmin, vmax) = (grid.v_min, grid.v_max);
    let scale = (lines.1 - 1) as f32;
    let first = c_int((poly.head(top)[1] - vmin) / (vmax - vmin) * scale);
    let last = c_int((poly.head(bot)[1] - vmin) / (vmax - vmin) * scale) + 1;
    let (li, lin) = left_indices(poly, top, first, last, &grid);
    let (ri, rin) = right_indices(poly, top, first, last, &grid);
    let lg = BoundaryChain::new(&grid, first, li, lin);
    let rg = BoundaryChain::new(&grid, first, ri, rin);
    let (left, right) = poly.chains(top, bot);
    let mut blocks = Vec::new();
    Rec { l: &left, r: &right, lg: &lg, rg: &rg, s: &mut s, blocks: &mut blocks }.run(
        poly.head(top),
        poly.head(bot),
        (0, 0),
        0,
    );
    finish(s, grid.u.len(), blocks)
}

fn finish(s: Stream, n_u: usize, blocks: Vec<Block>) -> Option<Sampled> {
    let nan = |p: &Pt| p[0].is_nan() || p[1].is_nan();
    let bad_piece = |p: &Piece| matches!(p, Piece::Fan(v) if v.iter().any(nan));
    // Only the lines below a block's first are drawn (`Slicer::evalRBArray` reads k + 1).
    let n_u = n_u as i64;
    let bad_row = |(&l, &r): (&i64, &i64)| l <= r && (l < 0 || r >= n_u);
    let bad_block = |b: &Block| b.left.iter().zip(&b.right).skip(1).any(bad_row);
    if s.bad || s.pieces.iter().any(bad_piece) || blocks.iter().any(bad_block) {
        return None;
    }
    Some(Sampled { pieces: s.pieces, blocks })
}

/// `sampleMonoPolyRec`'s state: the chains, the grid chains, the output.
struct Rec<'a, 'g> {
    l: &'a [Pt],
    r: &'a [Pt],
    lg: &'a BoundaryChain<'g>,
    rg: &'a BoundaryChain<'g>,
    s: &'a mut Stream,
    blocks: &'a mut Vec<Block>,
}

impl Rec<'_, '_> {
    /// GLU `sampleMonoPolyRec`: the next component of grid lines with points inside, from
    /// `top` down, then the rest below its neck.
    fn run(&mut self, mut top: Pt, bot: Pt, (mut ls, mut rs): (i64, i64), mut start: i64) {
        let (nl, nr, n) = (self.l.len() as i64, self.r.len() as i64, self.lg.n());
        let mut guard = 0;
        while top[1] > bot[1] && guard <= n + nl + nr + 2 {
            guard += 1;
            let mut i = start;
            while i < n && self.lg.v(i).partial_cmp(&top[1]) != Some(Ordering::Less) {
                i += 1;
            }
            let mut index1 = i;
            let mut skipped = 0;
            while index1 < n && self.lg.uline(index1) > self.rg.uline(index1) {
                skipped += 1;
                index1 += 1;
            }
            if index1 >= n {
                if skipped < 2 {
                    tri::rec_gen_opt(top, bot, self.l, ls, nl - 1, self.r, rs, nr - 1, self.s);
                } else {
                    let (l, r) = (tri::span(self.l, ls, nl - 1), tri::span(self.r, rs, nr - 1));
                    chains(top, bot, (&l, 0), (&r, 0), comp_v2_in_y, &mut self.s.pieces);
                }
                return;
            }
            let mut index2 = index1 + 1;
            while index2 < n && self.lg.inner(index2) <= self.rg.inner(index2) {
                index2 += 1;
            }
            index2 -= 1;
            let mut bl = index_strict_below(self.l, self.lg.v(index2), ls, nl - 1);
            let mut br = index_strict_below(self.r, self.rg.v(index2), rs, nr - 1);
            let (comp_bot, next_top, next_ls, next_rs);
            match neck(self.l, bl, self.r, br, (self.lg, self.rg), index2) {
                None => {
                    (comp_bot, next_top, next_ls, next_rs) = (bot, bot, 0, 0);
                    (bl, br) = (nl - 1, nr - 1);
                }
                Some((nl_i, nr_i)) => {
                    let (a, b) = (chain::at(self.l, nl_i), chain::at(self.r, nr_i));
                    if a[1] <= b[1] {
                        (comp_bot, next_top, next_ls, next_rs) = (a, b, nl_i, nr_i + 1);
                        (bl, br) = (nl_i - 1, nr_i);
                    } else {
                        (comp_bot, next_top, next_ls, next_rs) = (b, a, nl_i + 1, nr_i);
                        (bl, br) = (nl_i, nr_i - 1);
                    }
                }
            }
            let sides = Sides { l: self.l, ls, le: bl, r: self.r, rs, re: br };
            let up = up_corners(top, &sides, self.lg.v(index1), self.lg.u(index1), self.rg.u(index1));
            let down = down_corners(comp_bot, &sides, self.lg.v(index2), self.lg.u(index2), self.rg.u(index2));
            self.component(top, comp_bot, &sides, (index1, index2), (up, down));
            (top, ls, rs, start) = (next_top, next_ls, next_rs, index2 + 1);
        }
    }

    /// GLU `sampleConnectedComp`: the component's left, right, top and bottom bands, then its
    /// block of quads.
    fn component(
        &mut self,
        top: Pt,
        bot: Pt,
        sides: &Sides,
        (g1, g2): (i64, i64),
        (up, down): ((corners::Corner, corners::Corner), (corners::Corner, corners::Corner)),
    ) {
        let left = Comp { top, bot, sides: Sides { ..*sides }, grid: self.lg, g1, g2, up: up.0, down: down.0 };
        comp_left(&left, self.s);
        let right = Comp { grid: self.rg, up: up.1, down: down.1, ..left };
        comp_right(&right, self.s);
        let e = End { lg: self.lg, rg: self.rg, index: g1, l: self.l, r: self.r };
        comp_top(top, &e, (sides.ls, sides.rs), up, self.s);
        let e = End { index: g2, ..e };
        comp_bot(bot, &e, (sides.le, sides.re), down, self.s);
        let up_line = self.lg.vline(g1);
        let low = self.lg.vline(g2);
        let (left, right) =
            ((g1..=g2).map(|i| self.lg.inner(i)).collect(), (g1..=g2).map(|i| self.rg.inner(i)).collect());
        self.blocks.push(Block { up: up_line, low, left, right });
    }
}
