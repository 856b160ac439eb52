//! GLU's subdivision of a trimmed domain (`internals/subdivider.cc`, `Subdivider::drawSurfaces`
//! and what it calls): the trim loops, as arcs in a bin, are cut along every knot line of the
//! surface into patches (`splitInS`, `splitInT`), each patch bisected while its sampling asks
//! for it (`samplingSplit`), its region cut again through every point where a loop turns back
//! (`findIrregularS`, `monosplitInS`, `findIrregularT`, `monosplitInT`), and every loop left
//! sliced (`render`, `Slicer::slice`). The cuts' new arcs along the lines are sampled at the
//! patch's border steps (`tessellation`, `join_s`, `join_t`), and cuts between two samples
//! leave GLU's degenerate triangles.
//!
//! Loops that end up rectangles are sliced as untrimmed patches are ([`crate::glu::draw::slicer`]),
//! other loops by GLU's `sampleMonoPoly` in all its ways. Where GLU itself would read past its
//! arrays (loops it mishandles), the subdivision reports [`Failure::Unsupported`] and the
//! caller falls back to gleval's own triangulation.

mod arcs;
pub(crate) mod arctess;
mod mono;
mod monotone;
mod region;
mod sample;
mod sorter;
mod split;
mod turns;

use crate::glu::draw::slicer::{Interior, Piece};
use crate::glu::evaluation::patch_steps::DirectionSteps;
use arcs::{ArcId, Arcs, Bin, Side};

/// GLU's `mylongjmp(jumpbuffer, n)`: the subdivision stops with NURBS error `n`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Jump(pub u32);

/// Why the subdivision gave no pieces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Failure {
    /// GLU's error for these loops (28, 29: misoriented or intersecting).
    Error(u32),
    /// A region this port does not slice as GLU does yet.
    Unsupported,
}

impl From<Jump> for Failure {
    fn from(j: Jump) -> Self {
        Failure::Error(j.0)
    }
}

/// One curve of a trim loop: a `gluPwlCurve` polyline or a Bezier arc of a NURBS trim curve.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum TrimArc {
    Pwl(Vec<[f32; 2]>),
    Bezier(arctess::BezierArc),
}

/// What the subdivision needs of the surface.
pub(crate) struct Setup<'a> {
    /// The rate NURBS trim curves are sampled at (GLU's `Quilt::findRates`, the smaller).
    pub geo_step: f32,
    /// The distinct knots in u and v, increasing (GLU `Quilt::getRange`'s breakpoint lists).
    pub ubreaks: Vec<f32>,
    pub vbreaks: Vec<f32>,
    /// The steps of a sub-rectangle of a patch (GLU `Patchlist::getstepsize`).
    pub steps: &'a dyn Fn((f32, f32), (f32, f32)) -> [DirectionSteps; 2],
    /// Whether u and v are of order 2.
    pub linear: (bool, bool),
    /// `GLU_OUTLINE_PATCH`: each patch's loops outlined instead of sliced.
    pub outline: bool,
}

/// One Bezier patch's range and the pieces GLU draws on it, in its order.
pub(crate) struct PatchPieces {
    pub u: (f32, f32),
    pub v: (f32, f32),
    pub pieces: Vec<Piece>,
}

/// The state GLU's `Subdivider` keeps while it cuts.
pub(crate) struct Subdivider<'a> {
    arcs: Arcs,
    setup: &'a Setup<'a>,
    /// Rates of the lines made by cuts in pwl mode (`Subdivider::stepsizes`).
    stepsizes: [f32; 4],
    interior: Interior,
    /// `showDegenerate`: cuts between samples draw their triangle.
    degenerate: bool,
    /// `isArcTypeBezier`: cut lines are left unsampled.
    bezier: bool,
    pieces: Vec<Piece>,
    patches: Vec<PatchPieces>,
    unsupported: bool,
}

/// GLU's tessellation of the domain trimmed by `loops` (each a list of curves in (u, v),
/// joined end to end), patch by patch.
pub(crate) fn subdivide(loops: &[Vec<TrimArc>], setup: &Setup) -> Result<Vec<PatchPieces>, Failure> {
    let interior = Interior { du: 0.0, dv: 0.0, ulinear: setup.linear.0, vlinear: setup.linear.1 };
    let mut s = Subdivider {
        arcs: Arcs::default(),
        setup,
        stepsizes: [0.0; 4],
        interior,
        degenerate: false,
        bezier: true,
        pieces: Vec::new(),
        patches: Vec::new(),
        unsupported: false,
    };
    let mut bin = if loops.is_empty() { s.border_bin() } else { s.initial_bin(loops)? };
    s.split_in_s(&mut bin, 0, setup.ubreaks.len())?;
    if s.unsupported {
        return Err(Failure::Unsupported);
    }
    Ok(s.patches)
}

impl Subdivider<'_> {
    /// The user's loops as arcs (GLU `addArc` per pwl curve and per Bezier arc of a NURBS
    /// curve, each at the bin's head and after the last in its loop), the Bezier arcs sampled
    /// and joined to their neighbours, then all made monotone (`Subdivider::decompose`).
    fn initial_bin(&mut self, loops: &[Vec<TrimArc>]) -> Result<Bin, Jump> {
        let mut bin = Bin::default();
        let mut curves = Vec::new();
        for lp in loops {
            let mut last = None;
            for arc in lp {
                let pts = match arc {
                    TrimArc::Pwl(p) if p.is_empty() => continue,
                    TrimArc::Pwl(p) => p.clone(),
                    TrimArc::Bezier(_) => Vec::new(),
                };
                let id = self.arcs.add(pts, Side::None, false);
                if let TrimArc::Bezier(b) = arc {
                    curves.push((id, b));
                }
                bin.add(id);
                last = Some(self.arcs.append(id, last));
            }
        }
        for j in bin.arcs() {
            if let Some((_, b)) = curves.iter().find(|(id, _)| *id == j) {
                self.arcs[j].pts = arctess::tessellate(b, self.setup.geo_step);
                let next = self.arcs[j].next;
                if self.disconnected(j) || self.disconnected(next) {
                    return Err(Jump(31));
                }
            }
        }
        for j in bin.arcs() {
            self.monotonize(j, &mut bin);
        }
        Ok(bin)
    }

    /// GLU `Subdivider::makeBorderTrim`: an untrimmed surface's domain as one loop, bottom,
    /// right, top, left (counter-clockwise), each side an unsampled line sampled later at its
    /// patch's steps like a cut (`tessellation`).
    fn border_bin(&mut self) -> Bin {
        let (ub, vb) = (&self.setup.ubreaks, &self.setup.vbreaks);
        let (s0, s1, t0, t1) = (ub[0], ub[ub.len() - 1], vb[0], vb[vb.len() - 1]);
        let sides = [
            (Side::Bottom, [[s0, t0], [s1, t0]]),
            (Side::Right, [[s1, t0], [s1, t1]]),
            (Side::Top, [[s1, t1], [s0, t1]]),
            (Side::Left, [[s0, t1], [s0, t0]]),
        ];
        let mut bin = Bin::default();
        let mut last = None;
        for (side, pts) in sides {
            let id = self.arcs.add(pts.to_vec(), side, true);
            bin.add(id);
            last = Some(self.arcs.append(id, last));
        }
        bin
    }

    /// GLU `Subdivider::outline` with `Slicer::outline`: each loop of the bin from its first
    /// arc in the bin, walked back through `prev`, every arc a line strip of its points from
    /// the last.
    fn outline(&mut self, bin: &Bin) {
        let arcs = bin.arcs();
        for &j in &arcs {
            self.arcs[j].mark = true;
        }
        for &j in &arcs {
            let mut a = j;
            while self.arcs[a].mark {
                self.arcs[a].mark = false;
                if self.arcs[a].pts.len() >= 2 {
                    self.pieces.push(Piece::Line(self.arcs[a].pts.iter().rev().copied().collect()));
                }
                a = self.arcs[a].prev;
            }
        }
    }

    /// GLU `Arc::isDisconnected`: the arc's start more than 1e-5 from the previous arc's end
    /// (both sampled); otherwise both are moved to their average.
    fn disconnected(&mut self, j: ArcId) -> bool {
        let prev = self.arcs[j].prev;
        if self.arcs[j].pts.is_empty() || self.arcs[prev].pts.is_empty() {
            return false;
        }
        let (p0, p1) = (self.arcs.tail(j), self.arcs.rhead(prev));
        let far = |a: f32, b: f32| f64::from(a - b) > 0.00001 || f64::from(b - a) > 0.00001;
        if far(p0[0], p1[0]) || far(p0[1], p1[1]) {
            return true;
        }
        let mid = [(p1[0] + p0[0]) * 0.5, (p1[1] + p0[1]) * 0.5];
        self.arcs[j].pts[0] = mid;
        *self.arcs[prev].pts.last_mut().expect("points") = mid;
        false
    }

    /// GLU `Subdivider::splitInS`: the bin cut along the u knots `breaks[start..end]`, the
    /// parts beyond the first and last dropped.
    fn split_in_s(&mut self, bin: &mut Bin, start: usize, end: usize) -> Result<(), Failure> {
        if bin.is_empty() {
            return Ok(());
        }
        if start != end {
            let i = start + (end - start) / 2;
            let (mut left, mut right) = self.split(bin, 0, self.setup.ubreaks[i])?;
            self.split_in_s(&mut left, start, i)?;
            return self.split_in_s(&mut right, i + 1, end);
        }
        if start == 0 || start == self.setup.ubreaks.len() {
            return Ok(());
        }
        self.bezier = true;
        self.degenerate = false;
        let u = (self.setup.ubreaks[start - 1], self.setup.ubreaks[start]);
        self.split_in_t(bin, u, 0, self.setup.vbreaks.len())
    }

    /// GLU `Subdivider::splitInT`: the same along the v knots, each patch then subdivided
    /// for sampling.
    fn split_in_t(&mut self, bin: &mut Bin, u: (f32, f32), start: usize, end: usize) -> Result<(), Failure> {
        if bin.is_empty() {
            return Ok(());
        }
        if start != end {
            let i = start + (end - start) / 2;
            let (mut left, mut right) = self.split(bin, 1, self.setup.vbreaks[i])?;
            self.split_in_t(&mut left, u, start, i)?;
            return self.split_in_t(&mut right, u, i + 1, end);
        }
        if start == 0 || start == self.setup.vbreaks.len() {
            return Ok(());
        }
        let v = (self.setup.vbreaks[start - 1], self.setup.vbreaks[start]);
        self.bezier = true;
        self.degenerate = true;
        self.sampling_split(bin, (u, v), crate::glu::draw::slicer::split::MAX_SUBDIVISIONS, 0)?;
        let pieces = std::mem::take(&mut self.pieces);
        self.patches.push(PatchPieces { u, v, pieces });
        self.degenerate = false;
        self.bezier = true;
        Ok(())
    }

    /// GLU `Subdivider::samplingSplit`: the region sampled at its patch's steps, bisected (v
    /// first, then alternately) while u's step asks for it.
    fn sampling_split(
        &mut self,
        bin: &mut Bin,
        range: ((f32, f32), (f32, f32)),
        subdivisions: u32,
        param: usize,
    ) -> Result<(), Failure> {
        if bin.is_empty() {
            return Ok(());
        }
        let [s, t] = (self.setup.steps)(range.0, range.1);
        self.tessellation(bin, s, t);
        if self.setup.outline {
            // GLU outlines a patch before any sampling subdivision.
            self.outline(bin);
            return Ok(());
        }
        if s.needs_split && subdivisions > 0 {
            let param = 1 - param;
            let r = if param == 0 { range.0 } else { range.1 };
            let mid = (r.0 + r.1) * 0.5;
            let (mut left, mut right) = self.split(bin, param, mid)?;
            let (low, high) = if param == 0 {
                (((r.0, mid), range.1), ((mid, r.1), range.1))
            } else {
                ((range.0, (r.0, mid)), (range.0, (mid, r.1)))
            };
            self.sampling_split(&mut left, low, subdivisions - 1, param)?;
            return self.sampling_split(&mut right, high, subdivisions - 1, param);
        }
        self.bezier = false;
        self.degenerate = true;
        // `nonSamplingSplit` with no bounding-box subdivision: straight to the monotone cuts.
        let breaks = self.irregular_s(bin);
        self.monosplit_in_s(bin, &breaks, 0, breaks.len())?;
        self.degenerate = true;
        self.bezier = true;
        Ok(())
    }

    /// GLU `Subdivider::tessellation`: the unsampled border and cut lines sampled at the
    /// patch's sidesteps, and the interior and cut-line steps set.
    fn tessellation(&mut self, bin: &Bin, s: DirectionSteps, t: DirectionSteps) {
        for j in bin.arcs() {
            if !self.arcs[j].bezier || self.arcs[j].pts.len() != 2 {
                continue;
            }
            let arc = &self.arcs[j];
            let (from, to) = (arc.pts[0], arc.pts[1]);
            let (rate, vertical) = match arc.side {
                Side::Right => (t.side[1], true),
                Side::Left => (t.side[0], true),
                Side::Top => (s.side[1], false),
                Side::Bottom | Side::None => (s.side[0], false),
            };
            let values = split::sample_side(arc.side, from, to, rate);
            let pts = values.into_iter().map(|x| if vertical { [from[0], x] } else { [x, from[1]] }).collect();
            self.arcs[j].pts = pts;
            self.arcs[j].bezier = false;
        }
        self.interior.du = s.step;
        self.interior.dv = t.step;
        self.stepsizes = [t.step, s.step, t.step, s.step];
    }

    /// GLU `Subdivider::monosplitInS`: the bin cut along the u values `breaks[start..end]`.
    fn monosplit_in_s(&mut self, bin: &mut Bin, breaks: &[f32], start: usize, end: usize) -> Result<(), Failure> {
        if bin.is_empty() {
            return Ok(());
        }
        if start != end {
            let i = start + (end - start) / 2;
            let (mut left, mut right) = self.split(bin, 0, breaks[i])?;
            self.monosplit_in_s(&mut left, breaks, start, i)?;
            return self.monosplit_in_s(&mut right, breaks, i + 1, end);
        }
        self.bezier = false;
        self.degenerate = true;
        let tbreaks = self.irregular_t(bin)?;
        self.monosplit_in_t(bin, &tbreaks, 0, tbreaks.len())
    }

    /// GLU `Subdivider::monosplitInT`: the same along v, then every loop left sliced.
    fn monosplit_in_t(&mut self, bin: &mut Bin, breaks: &[f32], start: usize, end: usize) -> Result<(), Failure> {
        if bin.is_empty() {
            return Ok(());
        }
        if start != end {
            let i = start + (end - start) / 2;
            let (mut left, mut right) = self.split(bin, 1, breaks[i])?;
            self.monosplit_in_t(&mut left, breaks, start, i)?;
            return self.monosplit_in_t(&mut right, breaks, i + 1, end);
        }
        self.render(bin);
        Ok(())
    }

    /// GLU `Subdivider::render`: each loop of the bin sliced once, from its first arc in the
    /// bin.
    fn render(&mut self, bin: &Bin) {
        let arcs = bin.arcs();
        for &j in &arcs {
            self.arcs[j].mark = true;
        }
        for &j in &arcs {
            if !self.arcs[j].mark {
                continue;
            }
            let lp = self.arcs.loop_of(j);
            for &a in &lp {
                self.arcs[a].mark = false;
            }
            match region::slice(&self.arcs, &lp, self.interior) {
                Some(pieces) => self.pieces.extend(pieces),
                None => self.unsupported = true,
            }
        }
    }
}
