//! GLU's sampling subdivision of a rectangle (`Subdivider::samplingSplit`,
//! `internals/subdivider.cc`): when a patch's u step is finer than its parameter length over
//! GLU_U_STEP allows, GLU bisects it (alternately in v and u, v first, at most 6 times) and samples each half on its own. Each level first samples the
//! sides it has not sampled yet at its own sidesteps (`Subdivider::tessellation`); the sides
//! already sampled are cut where the bisector crosses them (`Subdivider::split`, `arc_split` in
//! `intersect.cc`: at a sample lying on the line, or at a new point on it), and the bisector
//! becomes a new unsampled side of both halves. The leaves are sliced at their own steps.
//!
//! A cut between two samples leaves GLU drawing a degenerate triangle there (`arc_split` calls
//! `backend.triangle` while "showing degenerate" arcs): the two samples and the new point, as a
//! fan, the moment the side is cut. The sides are cut in the order of GLU's list of arcs (a
//! `Bin`, new arcs put at its head), which after each split is fixed for a rectangle: see
//! [`Region::split`].

use super::border::{side_down, side_up, RectLoop};
use super::Interior;
use crate::glu::evaluation::patch_steps::DirectionSteps;

/// GLU's `renderhints.cc` subdivisions.
pub(crate) const MAX_SUBDIVISIONS: u32 = 6;

/// A rectangle being subdivided: its ranges, its sides (bottom, right, top, left, each in
/// loop order; `None` for a side not sampled yet) and the order of its sides in GLU's bin.
#[derive(Clone, Debug)]
struct Region {
    u: (f32, f32),
    v: (f32, f32),
    sides: [Option<Vec<[f32; 2]>>; 4],
    bin: [usize; 4],
}

const BOTTOM: usize = 0;
const RIGHT: usize = 1;
const TOP: usize = 2;
const LEFT: usize = 3;

/// What the subdivision produces, in GLU's order.
#[derive(Clone, Debug)]
pub(crate) enum Part {
    /// A degenerate triangle where a side was cut between two samples.
    Degenerate([[f32; 2]; 3]),
    /// A rectangle to slice at these interior steps.
    Leaf(RectLoop, Interior),
}

/// The parts of the subdivision of [u0, u1] × [v0, v1], in GLU's order (lower half first),
/// each leaf with the interior steps it is sliced at. `steps` gives the steps of a
/// sub-rectangle; `linear` says whether u and v are linear (order 2); at most `subdivisions`
/// levels (0 for `GLU_OUTLINE_PATCH`, which GLU outlines before subdividing).
pub(crate) fn leaves(
    u: (f32, f32),
    v: (f32, f32),
    linear: (bool, bool),
    steps: &dyn Fn((f32, f32), (f32, f32)) -> [DirectionSteps; 2],
    subdivisions: u32,
) -> Vec<Part> {
    let mut out = Vec::new();
    // `makeBorderTrim` adds bottom, right, top, left, each at the bin's head.
    let region = Region { u, v, sides: [None, None, None, None], bin: [LEFT, TOP, RIGHT, BOTTOM] };
    subdivide(region, subdivisions.min(MAX_SUBDIVISIONS), 0, linear, steps, &mut out);
    out
}

fn subdivide(
    mut region: Region,
    depth: u32,
    param: usize,
    linear: (bool, bool),
    steps: &dyn Fn((f32, f32), (f32, f32)) -> [DirectionSteps; 2],
    out: &mut Vec<Part>,
) {
    let [s, t] = steps(region.u, region.v);
    region.sample_sides(s, t);
    // GLU's `Patchlist::needsSamplingSubdivision` copies the u flag into both directions
    // (`pspec[1].needsSubdivision |= p->pspec[0].needsSubdivision`): only u's need splits, and
    // the halving then alternates v, u, v, ... whatever v needs.
    if s.needs_split && depth > 0 {
        let param = 1 - param;
        let (low, high) = region.split(param, out);
        subdivide(low, depth - 1, param, linear, steps, out);
        subdivide(high, depth - 1, param, linear, steps, out);
        return;
    }
    let interior = Interior { du: s.step, dv: t.step, ulinear: linear.0, vlinear: linear.1 };
    let [bottom, right, top, left] = region.sides.map(Option::unwrap_or_default);
    out.push(Part::Leaf(RectLoop { bottom, right, top, left }, interior));
}

impl Region {
    /// Samples the sides not sampled yet: bottom and top at the u sidesteps, right and left at
    /// the v sidesteps (index 1 where the other parameter is largest).
    fn sample_sides(&mut self, s: DirectionSteps, t: DirectionSteps) {
        let ((u0, u1), (v0, v1)) = (self.u, self.v);
        let [bottom, right, top, left] = &mut self.sides;
        bottom.get_or_insert_with(|| side_up(u0, u1, s.side[0]).into_iter().map(|u| [u, v0]).collect());
        right.get_or_insert_with(|| side_up(v0, v1, t.side[1]).into_iter().map(|v| [u1, v]).collect());
        top.get_or_insert_with(|| side_down(u1, u0, s.side[1]).into_iter().map(|u| [u, v1]).collect());
        left.get_or_insert_with(|| side_down(v1, v0, t.side[0]).into_iter().map(|v| [u0, v]).collect());
    }

    /// The lower and upper halves across `param` (0: u, 1: v) at the middle of its range,
    /// the degenerate triangles of the cuts pushed to `out` in bin order.
    ///
    /// The halves' bins follow from `Subdivider::split`: the side left whole goes in first,
    /// then the bisector (`join_s`/`join_t`), then the cut pieces in the sorter's order
    /// (increasing v for a cut in u, decreasing u for a cut in v), each at the head.
    fn split(self, param: usize, out: &mut Vec<Part>) -> (Region, Region) {
        let crossing = if param == 0 { [BOTTOM, TOP] } else { [RIGHT, LEFT] };
        let (lo, hi) = if param == 0 { self.u } else { self.v };
        let mid = (lo + hi) * 0.5;
        let mut cuts: [(Side, Side); 4] = Default::default();
        let mut sides = self.sides.map(Option::unwrap_or_default);
        for &side in self.bin.iter().filter(|s| crossing.contains(s)) {
            let (first, second, degenerate) = cut(&sides[side], param, mid);
            out.extend(degenerate.map(Part::Degenerate));
            cuts[side] = (first, second);
        }
        let take = |s: &mut Vec<[f32; 2]>| Some(std::mem::take(s));
        if param == 0 {
            let (b_low, b_high) = std::mem::take(&mut cuts[BOTTOM]);
            let (t_high, t_low) = std::mem::take(&mut cuts[TOP]);
            let low_sides = [Some(b_low), None, Some(t_low), take(&mut sides[LEFT])];
            let high_sides = [Some(b_high), take(&mut sides[RIGHT]), Some(t_high), None];
            let low = Region { u: (lo, mid), v: self.v, sides: low_sides, bin: [TOP, BOTTOM, RIGHT, LEFT] };
            let high = Region { u: (mid, hi), v: self.v, sides: high_sides, bin: [TOP, BOTTOM, LEFT, RIGHT] };
            (low, high)
        } else {
            let (r_low, r_high) = std::mem::take(&mut cuts[RIGHT]);
            let (l_high, l_low) = std::mem::take(&mut cuts[LEFT]);
            let low_sides = [take(&mut sides[BOTTOM]), Some(r_low), None, Some(l_low)];
            let high_sides = [None, Some(r_high), take(&mut sides[TOP]), Some(l_high)];
            let low = Region { u: self.u, v: (lo, mid), sides: low_sides, bin: [LEFT, RIGHT, TOP, BOTTOM] };
            let high = Region { u: self.u, v: (mid, hi), sides: high_sides, bin: [LEFT, RIGHT, BOTTOM, TOP] };
            (low, high)
        }
    }
}

/// A sampled side, (u, v) points in loop order.
type Side = Vec<[f32; 2]>;

/// The two parts of a cut side and the degenerate triangle of the cut, if any.
type Cut = (Side, Side, Option<[[f32; 2]; 3]>);

/// A sampled side cut where coordinate `c` crosses `value`: at a sample lying on it, or at a
/// new sample there (the side is straight, so the other coordinate is the side's own), with
/// the triangle of the two samples around it, listed against the side's direction. Both parts
/// keep the side's direction; the first is the one the side starts in.
fn cut(side: &[[f32; 2]], c: usize, value: f32) -> Cut {
    if let Some(k) = side.iter().position(|p| p[c] == value) {
        return (side[..=k].to_vec(), side[k..].to_vec(), None);
    }
    let crosses = |w: &[[f32; 2]]| (w[0][c] - value) * (w[1][c] - value) < 0.0;
    let Some(k) = side.windows(2).position(crosses) else {
        return (side.to_vec(), side.last().map(|&p| vec![p]).unwrap_or_default(), None);
    };
    let mut point = side[k];
    point[c] = value;
    let mut first = side[..=k].to_vec();
    first.push(point);
    let mut second = vec![point];
    second.extend_from_slice(&side[k + 1..]);
    (first, second, Some([side[k + 1], point, side[k]]))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fixed(step: f32, needs_split: bool) -> DirectionSteps {
        DirectionSteps { step, side: [step; 2], needs_split }
    }

    #[test]
    fn a_side_is_cut_at_a_sample_or_at_a_new_one() {
        let side = [[0.0, 0.0], [0.25, 0.0], [0.5, 0.0], [1.0, 0.0]];
        assert_eq!(cut(&side, 0, 0.5), (side[..3].to_vec(), side[2..].to_vec(), None));
        let (a, b, degenerate) = cut(&side, 0, 0.75);
        assert_eq!(a.last(), Some(&[0.75, 0.0]));
        assert_eq!(b, vec![[0.75, 0.0], [1.0, 0.0]]);
        assert_eq!(degenerate, Some([[1.0, 0.0], [0.75, 0.0], [0.5, 0.0]]));
    }

    #[test]
    fn halves_are_sampled_on_their_own_and_share_the_bisector() {
        // Steps too fine at the top level only: one split (in v, GLU's first), two leaves.
        let steps = |_u: (f32, f32), v: (f32, f32)| {
            let whole = v.1 - v.0 > 0.75;
            [fixed(0.3, whole), fixed(0.5, false)]
        };
        let out = leaves((0.0, 1.0), (0.0, 1.0), (false, false), &steps, MAX_SUBDIVISIONS);
        let rects: Vec<&RectLoop> = out
            .iter()
            .filter_map(|p| match p {
                Part::Leaf(r, _) => Some(r),
                Part::Degenerate(_) => None,
            })
            .collect();
        assert_eq!(rects.len(), 2);
        let (low, high) = (rects[0], rects[1]);
        assert_eq!((low.min(), low.max()), ([0.0, 0.0], [1.0, 0.5]));
        assert_eq!((high.min(), high.max()), ([0.0, 0.5], [1.0, 1.0]));
        assert_eq!(low.top.last(), Some(&[0.0, 0.5]));
        assert_eq!(high.bottom.first(), Some(&[0.0, 0.5]));
    }
}
