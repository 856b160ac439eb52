//! GLU's own conversion of a B-spline curve or surface into Bezier pieces (libnurbs
//! `tobezier.cc`, `Quilt::toBezier`, shared by curves, trim curves and surfaces), in `f32` and in GLU's order of operations, so that the pieces carry
//! GLU's rounding: at the joints of a curve's spans GLU's knot insertion leaves values such as
//! −1e-8 where an exact (or `f64`) decomposition gives 0, and GLU prints them as "-0.000".
//!
//! One parameter direction is a [`Knotspec`] (GLU's struct of that name): its breakpoints
//! (`Knotspec::preselect`, `breakpoints`), the conversion factors (`knots`, `factors`) and
//! the insertion itself (`insert`), which GLU runs in place on a buffer holding the input
//! points at its start and the Bezier points, right-aligned, at its end. The algorithm is
//! Boehm's knot insertion arranged as GLU arranges it, written here anew from its description.

/// GLU's `TOLERANCE` for `identical` knots.
const TOLERANCE: f64 = 1.0e-5;

/// GLU's `identical(x, y)`: one-sided, `x − y` in `float`, compared in `double`.
fn identical(x: f32, y: f32) -> bool {
    f64::from(x - y) < TOLERANCE
}

/// One breakpoint (GLU `Breakpt`): its value, multiplicity and deficit (order − multiplicity).
#[derive(Clone, Copy, Debug)]
struct Breakpt {
    value: f32,
    multi: usize,
    def: usize,
}

/// One parameter direction of a spline (GLU `Knotspec`), after `Knotspec::select`.
#[derive(Debug)]
struct Knotspec {
    order: usize,
    breakpoints: Vec<Breakpt>,
    /// The first input point used (GLU `preoffset`, in points).
    first: usize,
    /// The number of input points read (GLU `prewidth`).
    inputs: usize,
    /// Leading points of the output before the first piece (GLU `postoffset`).
    offset: usize,
    /// The blending factors, in the order `Knotspec::insert` consumes them.
    factors: Vec<f32>,
}

impl Knotspec {
    /// GLU `Knotspec::preselect` then `Knotspec::select` on a validated knot vector; `None` if
    /// an index would leave the knots (never for knots GLU accepts).
    fn new(knots: &[f32], order: usize) -> Option<Self> {
        let n = knots.len();
        if order == 0 || n < 2 * order {
            return None;
        }
        // preselect: `klast` after the run of the knot at n − order, `kfirst` after the run of
        // the knot at order − 1, the first breakpoint's multiplicity counted backwards.
        let run_end = |from: usize| {
            let v = knots[from];
            (from..n).find(|&i| !identical(knots[i], v)).unwrap_or(n)
        };
        let (klast, kfirst) = (run_end(n - order), run_end(order - 1));
        let kval = knots[order - 1];
        let start = (0..kfirst).rev().find(|&i| !identical(kval, knots[i])).map_or(0, |i| i + 1);
        let breakpoints =
            Self::breakpoints(knots, order, (kfirst, klast), Breakpt { value: kval, multi: kfirst - start, def: 0 });
        let last = *breakpoints.last()?;
        // knots: the subsequence the factors are computed on (and partly overwritten).
        let outk = knots.get(kfirst.checked_sub(order)?..klast + last.def)?.to_vec();
        let factors = Self::factors(outk, order, &breakpoints)?;
        let first_def = breakpoints[0].def;
        Some(Self {
            order,
            first: kfirst - order,
            inputs: (klast + last.def - (kfirst - order)).checked_sub(order)?,
            offset: first_def.saturating_sub(1),
            factors,
            breakpoints,
        })
    }

    /// GLU `Knotspec::breakpoints`: the distinct knots from `kfirst` to `klast`, with their
    /// multiplicities and deficits.
    fn breakpoints(knots: &[f32], order: usize, (kfirst, klast): (usize, usize), first: Breakpt) -> Vec<Breakpt> {
        let mut out = vec![first];
        for &k in &knots[kfirst..klast] {
            let current = out.last_mut().expect("first breakpoint");
            if identical(k, current.value) {
                current.multi += 1;
            } else {
                current.def = order.saturating_sub(current.multi);
                out.push(Breakpt { value: k, multi: 1, def: 0 });
            }
        }
        let current = out.last_mut().expect("first breakpoint");
        current.def = order.saturating_sub(current.multi);
        out
    }

    /// GLU `Knotspec::factors`: from the last breakpoint back, for each knot to insert
    /// (deficit − 1 of them), the factors `(kv − k[h]) / (k[t] − k[h])` in `float`, writing the
    /// inserted knot into the working knots as GLU does.
    fn factors(mut outk: Vec<f32>, order: usize, breakpoints: &[Breakpt]) -> Option<Vec<f32>> {
        let last = breakpoints.last()?;
        let mut mid = outk.len() as isize - 1 - order as isize + last.multi as isize;
        let mut out = Vec::new();
        for bpt in breakpoints.iter().rev() {
            mid -= bpt.multi as isize;
            let def = bpt.def as isize - 1;
            if def <= 0 {
                continue;
            }
            let kf = mid - def + order as isize - 1;
            for kl in (kf + 1..=kf + def).rev() {
                let (mut kt, mut kh) = (kl, mid);
                while kt != kf {
                    let (t, h) = (*outk.get(usize::try_from(kt).ok()?)?, *outk.get(usize::try_from(kh).ok()?)?);
                    out.push((bpt.value - h) / (t - h));
                    kh -= 1;
                    kt -= 1;
                }
                *outk.get_mut(usize::try_from(kl).ok()?)? = bpt.value;
            }
        }
        Some(out)
    }

    /// Number of pieces (GLU `bend − bbegin`).
    fn width(&self) -> usize {
        self.breakpoints.len() - 1
    }

    /// Points in the output buffer: the pieces after the leading offset.
    fn output_points(&self) -> usize {
        self.width() * self.order + self.offset
    }

    /// GLU `Knotspec::insert` on a buffer of rows of `w` values (the input rows at its start):
    /// the last breakpoint's insertions in place, then, breakpoint by breakpoint backwards,
    /// each piece's points copied to the end of the buffer while the next ones are blended;
    /// `x = a·x + b·y` with `b = 1 − a` rounded from `double`, as `pt_oo_sum` is called.
    fn insert(&self, buf: &mut [f32], w: usize) -> Option<()> {
        let mut factors = self.factors.iter();
        let mut sum = |buf: &mut [f32], p1: isize, p2: isize| -> Option<()> {
            let a = *factors.next()?;
            let b = (1.0 - f64::from(a)) as f32;
            let (p1, p2) = (usize::try_from(p1).ok()? * w, usize::try_from(p2).ok()? * w);
            for c in 0..w {
                let (x, y) = (*buf.get(p1 + c)?, *buf.get(p2 + c)?);
                buf[p1 + c] = a * x + b * y;
            }
            Some(())
        };
        let copy = |buf: &mut [f32], to: isize, from: isize| -> Option<()> {
            let (to, from) = (usize::try_from(to).ok()? * w, usize::try_from(from).ok()? * w);
            buf.get(from..from + w)?;
            buf.get(to..to + w)?;
            buf.copy_within(from..from + w, to);
            Some(())
        };
        let mut src = self.inputs as isize - 1;
        let mut dst = self.output_points() as isize - 1;
        let last = self.breakpoints.last()?;
        let mut pend = src - last.def as isize;
        while src != pend {
            let (mut p1, mut p2) = (src, src - 1);
            while p2 != pend {
                sum(buf, p1, p2)?;
                (p1, p2) = (p2, p2 - 1);
            }
            pend += 1;
        }
        for bpt in self.breakpoints[..self.width()].iter().rev() {
            for _ in 0..bpt.multi {
                copy(buf, dst, src)?;
                dst -= 1;
                src -= 1;
            }
            let mut pend = src - bpt.def as isize;
            while src != pend {
                copy(buf, dst, src)?;
                let (mut p1, mut p2) = (src, src - 1);
                while p2 != pend {
                    sum(buf, p1, p2)?;
                    (p1, p2) = (p2, p2 - 1);
                }
                pend += 1;
                dst -= 1;
            }
        }
        Some(())
    }
}

/// A curve's Bezier pieces as GLU's `Quilt` holds them after `Quilt::toBezier`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct GluCurvePieces {
    /// The breakpoints, one more than the pieces (GLU `Quiltspec::breakpoints`).
    pub breakpoints: Vec<f32>,
    /// Every piece's `order` points of `dim` values, piece after piece.
    pub points: Vec<f32>,
}

/// GLU `Quilt::toBezier` for a curve: `points` holds `knots.len() − order` points of `dim`
/// values; `None` when GLU's indices would leave the knots or points (not for a knot vector
/// GLU accepts).
pub(crate) fn curve_to_bezier(knots: &[f32], points: &[f32], dim: usize, order: usize) -> Option<GluCurvePieces> {
    let spec = Knotspec::new(knots, order)?;
    // Splinespec::layout and Knotspec::copy (pt_io_copy): the used input points at the start.
    let mut buf = vec![0.0f32; spec.output_points().max(spec.inputs) * dim];
    let input = points.get(spec.first * dim..(spec.first + spec.inputs) * dim)?;
    buf[..input.len()].copy_from_slice(input);
    spec.insert(&mut buf, dim)?;
    let start = spec.offset * dim;
    Some(GluCurvePieces {
        breakpoints: spec.breakpoints.iter().map(|b| b.value).collect(),
        points: buf[start..start + spec.width() * spec.order * dim].to_vec(),
    })
}

/// A surface's Bezier patches as GLU's `Quilt` holds them after `Quilt::toBezier`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct GluSurfacePatches {
    /// The breakpoints along u (s) and along v (t).
    pub breakpoints: (Vec<f32>, Vec<f32>),
    /// Patch (a, b)'s `uorder × vorder` points of `dim` values at `(a · vpatches + b)`, point
    /// (i, j) of a patch at `i · vorder + j`.
    pub points: Vec<f32>,
}

/// GLU `Quilt::toBezier` for a surface (`Splinespec::transform`): every column of the net
/// converted along u first, then every row of the result along v; control point (i, j) of the
/// `nu × nv` net at `(i · nv + j) · dim`.
pub(crate) fn surface_to_bezier(
    (uknots, vknots): (&[f32], &[f32]),
    points: &[f32],
    dim: usize,
    (uorder, vorder): (usize, usize),
) -> Option<GluSurfacePatches> {
    let (s, t) = (Knotspec::new(uknots, uorder)?, Knotspec::new(vknots, vorder)?);
    let nv = vknots.len().checked_sub(vorder)?;
    // Splinespec::layout: a row of the buffer holds every output point along v.
    let (srows, tcols) = (s.output_points().max(s.inputs), t.output_points().max(t.inputs));
    let w = tcols * dim;
    let mut buf = vec![0.0f32; srows * w];
    for i in 0..s.inputs {
        let from = ((s.first + i) * nv + t.first) * dim;
        buf[i * w..i * w + t.inputs * dim].copy_from_slice(points.get(from..from + t.inputs * dim)?);
    }
    s.insert(&mut buf, w)?;
    for row in s.offset..s.output_points() {
        t.insert(&mut buf[row * w..(row + 1) * w], dim)?;
    }
    let mut out = Vec::with_capacity(s.width() * uorder * t.width() * vorder * dim);
    for a in 0..s.width() {
        for b in 0..t.width() {
            for i in 0..uorder {
                let at = (s.offset + a * uorder + i) * w + (t.offset + b * vorder) * dim;
                out.extend_from_slice(buf.get(at..at + vorder * dim)?);
            }
        }
    }
    let values = |k: &Knotspec| k.breakpoints.iter().map(|b| b.value).collect();
    Some(GluSurfacePatches { breakpoints: (values(&s), values(&t)), points: out })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::insertion::decompose_curve;

    fn compare(knots: &[f32], points: &[f32], dim: usize, order: usize) {
        let glu = curve_to_bezier(knots, points, dim, order).expect("pieces");
        let k64: Vec<f64> = knots.iter().map(|&k| f64::from(k)).collect();
        let p64: Vec<f64> = points.iter().map(|&k| f64::from(k)).collect();
        let exact = decompose_curve(&k64, &p64, dim, order).expect("decomposition");
        let bps: Vec<f64> = glu.breakpoints.iter().map(|&b| f64::from(b)).collect();
        let mut want: Vec<f64> = exact.intervals.iter().map(|i| i.0).collect();
        want.push(exact.intervals.last().expect("a piece").1);
        assert_eq!(bps, want);
        assert_eq!(glu.points.len(), exact.points.len());
        for (a, b) in glu.points.iter().zip(&exact.points) {
            assert!((f64::from(*a) - b).abs() < 1e-5, "{a} vs {b}");
        }
    }

    #[test]
    fn clamped_cubic_matches_the_exact_decomposition() {
        let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0, 5.0];
        let points: Vec<f32> = (0..8).flat_map(|i| [i as f32, ((i * 7) % 5) as f32 - 2.0, 0.5 * i as f32]).collect();
        compare(&knots, &points, 3, 4);
    }

    #[test]
    fn uniform_and_repeated_knots_match_the_exact_decomposition() {
        let knots: Vec<f32> = (0..14).map(|i| i as f32 * 0.5).collect();
        let points: Vec<f32> = (0..10).flat_map(|i| [i as f32, ((i * 3) % 7) as f32, 1.0 + 0.1 * i as f32]).collect();
        compare(&knots, &points, 3, 4);
        let knots = [0.0, 0.0, 0.0, 1.0, 1.0, 2.5, 3.0, 3.0, 3.0];
        let points: Vec<f32> = (0..6).flat_map(|i| [i as f32, (i * i) as f32, 1.0, 2.0]).collect();
        compare(&knots, &points, 4, 3);
    }

    #[test]
    fn a_surface_matches_the_exact_decomposition() {
        use crate::math::insertion::decompose_surface;
        use crate::math::{BSplineSurface, KnotVector};
        let uk = [0.0f32, 0.0, 0.0, 0.0, 1.0, 2.5, 3.0, 3.0, 3.0, 3.0];
        let vk: Vec<f32> = (0..9).map(|i| i as f32).collect();
        let (nu, nv, dim) = (6, 6, 3);
        let points: Vec<f32> = (0..nu * nv * dim).map(|i| ((i * 7) % 11) as f32 - 5.0).collect();
        let glu = surface_to_bezier((&uk, &vk), &points, dim, (4, 3)).expect("patches");
        let wide = |v: &[f32]| -> Vec<f64> { v.iter().map(|&x| f64::from(x)).collect() };
        let (u, v) = (KnotVector::new(wide(&uk)), KnotVector::new(wide(&vk)));
        let s = BSplineSurface::try_new(dim, 4, 3, u, v, wide(&points)).expect("surface");
        let exact = decompose_surface(&s).expect("decomposition");
        assert_eq!(glu.breakpoints.0, [0.0, 1.0, 2.5, 3.0]);
        assert_eq!(glu.breakpoints.1, [2.0, 3.0, 4.0, 5.0, 6.0]);
        assert_eq!(glu.points.len(), exact.points.len());
        for (a, b) in glu.points.iter().zip(&exact.points) {
            assert!((f64::from(*a) - b).abs() < 1e-4, "{a} vs {b}");
        }
    }

    #[test]
    fn a_bezier_curve_is_copied() {
        let knots = [0.0, 0.0, 1.0, 1.0];
        let glu = curve_to_bezier(&knots, &[1.0, 2.0, 3.0, 4.0], 2, 2).expect("pieces");
        assert_eq!(glu, GluCurvePieces { breakpoints: vec![0.0, 1.0], points: vec![1.0, 2.0, 3.0, 4.0] });
    }
}
