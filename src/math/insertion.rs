//! Knot insertion (The NURBS Book A5.1 CurveKnotIns), knot refinement, and Bezier decomposition
//! (A5.6 DecomposeCurve, A5.7 DecomposeSurface): how GLU turns a NURBS into the Bezier pieces it
//! draws with `glMap1`/`glMap2` (`tobezier.cc`, `Quilt::toBezier`), and what the GPU path consumes.
//!
//! Every routine works on "rows": a control point of a curve, or a whole row of a surface net
//! (all `nv` points of one u index, `nv * dim` values), so one implementation serves curves and
//! both directions of surfaces (the v direction by transposing the net).
//!
//! Decomposition follows GLU: breakpoints closer than 1e−5 ([`GLU_TOLERANCE`]) are one
//! breakpoint (knots are snapped to the first knot of their cluster), every breakpoint of the
//! valid range gets multiplicity `order − 1`, and each non-empty span becomes one piece of
//! `order` points; rational (homogeneous, dim 4) nets are decomposed as they are.

use super::bezier::{de_casteljau, Vec4};
use super::bspline::{check_shape, BSplineCurve, BSplineSurface};
use super::knots::{KnotVector, GLU_TOLERANCE};
use super::patch::{patch_with_partials, PatchSample};
use super::scalar::Scalar;
use super::MathError;

/// New knots and control points (rows), as the insertion routines return them.
pub type KnotsAndPoints<S> = (Vec<S>, Vec<S>);

/// Piece intervals and the pieces' rows, piece after piece.
type Decomposed<S> = (Vec<(S, S)>, Vec<S>);

/// A parametric direction of a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// The first parameter (GLU's s, GL's u; the net's slow index).
    U,
    /// The second parameter (GLU's t, GL's v).
    V,
}

/// Bezier pieces of a curve, ready for `glMap1(target, u0, u1, dim, order, piece)`.
///
/// Piece `k` covers `intervals[k]` = (u0, u1) and has `order` points of `dim` values at
/// `points[k * order * dim..(k + 1) * order * dim]`; on it the spline equals the Bezier curve of
/// those points at t = (u − u0)/(u1 − u0).
///
/// ```
/// use gleval::math::{BSplineCurve, KnotVector};
/// // Seed 004 §9.5.4: the uniform quadratic is one Bezier piece on [2, 3].
/// let c = BSplineCurve::try_new(2, 3, KnotVector::uniform(3, 3).unwrap(), vec![0., 0., 0.5, 1., 1., 0.]).unwrap();
/// let bez = c.to_bezier().unwrap();
/// assert_eq!((bez.len(), bez.order, bez.intervals[0]), (1, 3, (2.0, 3.0)));
/// assert_eq!(bez.piece(0).unwrap(), [0.25, 0.5, 0.5, 1.0, 0.75, 0.5]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPieces<S: Scalar> {
    /// Values per control point.
    pub dim: usize,
    /// Points per piece (degree + 1).
    pub order: usize,
    /// Parameter interval of each piece, ascending.
    pub intervals: Vec<(S, S)>,
    /// All pieces' points, piece after piece.
    pub points: Vec<S>,
}

impl<S: Scalar> BezierPieces<S> {
    /// Number of pieces.
    #[must_use]
    pub fn len(&self) -> usize {
        self.intervals.len()
    }

    /// No pieces.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.intervals.is_empty()
    }

    /// The points of piece `k`.
    #[must_use]
    pub fn piece(&self, k: usize) -> Option<&[S]> {
        let size = self.order.checked_mul(self.dim)?;
        self.points.get(k.checked_mul(size)?..(k + 1).checked_mul(size)?)
    }

    /// The curve at `u` through the piece containing it (de Casteljau); `None` outside.
    #[must_use]
    pub fn eval(&self, u: S) -> Option<Vec4<S>> {
        let (k, t) = locate(&self.intervals, u)?;
        Some(de_casteljau(self.piece(k)?, self.dim, self.order, t))
    }
}

/// Bezier patches of a surface, ready for `glMap2(target, u0, u1, vorder * dim, uorder, v0, v1,
/// dim, vorder, patch)`.
///
/// Patch (a, b) covers `uintervals[a] × vintervals[b]`; its `uorder * vorder` points start at
/// `(a * vintervals.len() + b) * uorder * vorder * dim`, packed u-major as in
/// [`crate::math::BezierPatch`]: point (i, j) at `(i * vorder + j) * dim` within the patch.
///
/// ```
/// use gleval::math::{BSplineSurface, KnotVector};
/// // Biquadratic open uniform surface, 4 x 3 points: 2 x 1 patches.
/// let (uk, vk) = (KnotVector::open_uniform(4, 3).unwrap(), KnotVector::open_uniform(3, 3).unwrap());
/// let net: Vec<f64> = (0..12).map(|k| (k * k % 5) as f64).collect();
/// let s = BSplineSurface::try_new(1, 3, 3, uk, vk, net).unwrap();
/// let bez = s.to_bezier().unwrap();
/// assert_eq!((bez.uintervals.len(), bez.vintervals.len()), (2, 1));
/// let p = bez.eval(1.3, 0.6).unwrap();
/// assert!((p.point[0] - s.eval(1.3, 0.6).unwrap()[0]).abs() < 1e-12);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatches<S: Scalar> {
    /// Values per control point.
    pub dim: usize,
    /// Points per patch along u.
    pub uorder: usize,
    /// Points per patch along v.
    pub vorder: usize,
    /// Parameter interval of each patch column along u.
    pub uintervals: Vec<(S, S)>,
    /// Parameter interval of each patch row along v.
    pub vintervals: Vec<(S, S)>,
    /// All patches' points, patch (a, b) at index a * vintervals.len() + b.
    pub points: Vec<S>,
}

impl<S: Scalar> BezierPatches<S> {
    /// Number of patches.
    #[must_use]
    pub fn len(&self) -> usize {
        self.uintervals.len() * self.vintervals.len()
    }

    /// No patches.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The points of patch (a, b), u-major.
    #[must_use]
    pub fn patch(&self, a: usize, b: usize) -> Option<&[S]> {
        if a >= self.uintervals.len() || b >= self.vintervals.len() {
            return None;
        }
        let size = self.uorder.checked_mul(self.vorder)?.checked_mul(self.dim)?;
        let k = a * self.vintervals.len() + b;
        self.points.get(k.checked_mul(size)?..(k + 1).checked_mul(size)?)
    }

    /// Point and partials (with respect to u and v, not the patch's normalised parameters)
    /// through the patch containing (u, v); `None` outside.
    #[must_use]
    pub fn eval(&self, u: S, v: S) -> Option<PatchSample<S>> {
        let (a, s) = locate(&self.uintervals, u)?;
        let (b, t) = locate(&self.vintervals, v)?;
        let mut out = patch_with_partials(self.patch(a, b)?, self.dim, self.uorder, self.vorder, s, t);
        let (du, dv) = (self.uintervals[a].1 - self.uintervals[a].0, self.vintervals[b].1 - self.vintervals[b].0);
        out.du = out.du.map(|c| c / du);
        out.dv = out.dv.map(|c| c / dv);
        Some(out)
    }
}

/// The interval holding `x` (the last one whose start is ≤ x) and x's normalised parameter.
fn locate<S: Scalar>(intervals: &[(S, S)], x: S) -> Option<(usize, S)> {
    let (first, last) = (intervals.first()?, intervals.last()?);
    if !(x >= first.0 && x <= last.1) {
        return None;
    }
    let k = intervals.partition_point(|iv| iv.0 <= x).max(1) - 1;
    let (a, b) = intervals[k];
    Some((k, (x - a) / (b - a)))
}

/// Validates a spline of rows: shape, finite knots, GLU's knot rules 2..=5 (as `MathError::Knots`).
fn check_rows<S: Scalar>(knots: &[S], values: usize, width: usize, order: usize) -> Result<usize, MathError> {
    if width == 0 {
        return Err(MathError::BadDimension(0));
    }
    let n = check_shape(knots.len(), values, width, order)?;
    if !knots.iter().all(|k| k.is_finite()) {
        return Err(MathError::Knots("knots must be finite"));
    }
    let kv = KnotVector { knots: knots.to_vec() };
    kv.check_knots(order)?;
    Ok(n)
}

/// dst = α·a + (1 − α)·b, row-wise.
fn blend<S: Scalar>(a: &[S], b: &[S], alpha: S, dst: &mut [S]) {
    for ((d, &x), &y) in dst.iter_mut().zip(a).zip(b) {
        *d = alpha * x + (S::ONE - alpha) * y;
    }
}

/// A5.1 CurveKnotIns on rows of `width` values: `u` inserted `times` times. Returns the new
/// knots and rows. Errors: shape or knots invalid, `u` outside the valid range or NaN, or the
/// resulting multiplicity of `u` above the degree.
fn insert_rows<S: Scalar>(
    knots: &[S],
    rows: &[S],
    width: usize,
    order: usize,
    u: S,
    times: usize,
) -> Result<KnotsAndPoints<S>, MathError> {
    let n = check_rows(knots, rows.len(), width, order)?;
    let p = order - 1;
    if !(u >= knots[p] && u <= knots[n]) {
        return Err(MathError::OutOfRange);
    }
    let k = knots.partition_point(|&x| x <= u) - 1; // u ∈ [U_k, U_k+1)
    let s = knots.iter().filter(|&&x| x == u).count();
    if times == 0 {
        return Ok((knots.to_vec(), rows.to_vec()));
    }
    if times + s > p || k + 1 >= knots.len() {
        return Err(MathError::Knots("knot multiplicity would exceed the degree"));
    }
    let w = width;
    let mut q = vec![S::ZERO; (n + times) * w];
    q[..(k - p + 1) * w].copy_from_slice(&rows[..(k - p + 1) * w]);
    q[(k - s + times) * w..].copy_from_slice(&rows[(k - s) * w..]);
    let mut r = rows[(k - p) * w..(k - s + 1) * w].to_vec();
    let mut l = 0;
    for j in 1..=times {
        l = k - p + j;
        for i in 0..=p - j - s {
            let alpha = (u - knots[l + i]) / (knots[i + k + 1] - knots[l + i]);
            let (lo, hi) = r.split_at_mut((i + 1) * w);
            let cur = lo[i * w..].to_vec();
            blend(&hi[..w], &cur, alpha, &mut lo[i * w..]);
        }
        q[l * w..(l + 1) * w].copy_from_slice(&r[..w]);
        let last = p - j - s;
        let at = k + times - j - s;
        q[at * w..(at + 1) * w].copy_from_slice(&r[last * w..(last + 1) * w]);
    }
    for i in l + 1..k - s {
        q[i * w..(i + 1) * w].copy_from_slice(&r[(i - l) * w..(i - l + 1) * w]);
    }
    let mut new_knots = Vec::with_capacity(knots.len() + times);
    new_knots.extend_from_slice(&knots[..=k]);
    new_knots.extend(core::iter::repeat_n(u, times));
    new_knots.extend_from_slice(&knots[k + 1..]);
    Ok((new_knots, q))
}

/// Inserts `u` into a curve `times` times (The NURBS Book A5.1 CurveKnotIns) without changing
/// its shape: returns the new knots and control points. `u` must lie in the valid range and its
/// multiplicity stay ≤ order − 1.
pub fn insert_knot<S: Scalar>(
    knots: &[S],
    points: &[S],
    dim: usize,
    order: usize,
    u: S,
    times: usize,
) -> Result<KnotsAndPoints<S>, MathError> {
    check_dim(dim)?;
    insert_rows(knots, points, dim, order, u, times)
}

/// Knot refinement: inserts every value of `new_knots` once, in order (the result of The NURBS
/// Book A5.4 RefineKnotVectCurve, computed by repeated A5.1).
pub fn refine_knots<S: Scalar>(
    knots: &[S],
    points: &[S],
    dim: usize,
    order: usize,
    new_knots: &[S],
) -> Result<KnotsAndPoints<S>, MathError> {
    check_dim(dim)?;
    let (mut k, mut p) = (knots.to_vec(), points.to_vec());
    for &x in new_knots {
        (k, p) = insert_rows(&k, &p, dim, order, x, 1)?;
    }
    Ok((k, p))
}

fn check_dim(dim: usize) -> Result<(), MathError> {
    if dim == 0 || dim > super::bezier::MAX_DIM {
        return Err(MathError::BadDimension(dim));
    }
    Ok(())
}

/// Replaces each knot closer than 1e−5 to the first knot of its cluster by that knot (GLU's
/// `identical`), so that multiplicities can be counted exactly.
fn snap<S: Scalar>(knots: &[S]) -> Vec<S> {
    let tol = S::from_f64(GLU_TOLERANCE);
    let mut rep = knots[0];
    knots
        .iter()
        .map(|&k| {
            if k - rep >= tol {
                rep = k;
            }
            rep
        })
        .collect()
}

fn multiplicity<S: Scalar>(knots: &[S], u: S) -> usize {
    knots.iter().filter(|&&x| x == u).count()
}

/// Raises the multiplicity of both ends of the valid range to ≥ order − 1 (A5.1) and drops the
/// knots and rows outside, leaving a clamped vector (order equal knots at each end), as A5.6 needs.
fn clamp_rows<S: Scalar>(knots: Vec<S>, rows: Vec<S>, w: usize, order: usize) -> Result<KnotsAndPoints<S>, MathError> {
    let p = order - 1;
    let a = knots[p];
    let (knots, rows) = raise(knots, rows, w, order, a)?;
    let last_a = knots.iter().rposition(|&x| x == a).unwrap_or(p);
    let mut k = vec![a];
    k.extend_from_slice(&knots[last_a + 1 - p..]);
    let rows = rows[(last_a - p) * w..].to_vec();
    let b = k[k.len() - order];
    let (k, rows) = raise(k, rows, w, order, b)?;
    let first_b = k.iter().position(|&x| x == b).unwrap_or(k.len() - order);
    let mut out = k[..first_b + p].to_vec();
    out.push(b);
    Ok((out, rows[..first_b * w].to_vec()))
}

/// Inserts `u` until its multiplicity is at least order − 1.
fn raise<S: Scalar>(knots: Vec<S>, rows: Vec<S>, w: usize, order: usize, u: S) -> Result<KnotsAndPoints<S>, MathError> {
    let s = multiplicity(&knots, u);
    if s + 1 >= order {
        return Ok((knots, rows));
    }
    insert_rows(&knots, &rows, w, order, u, order - 1 - s)
}

/// A5.6 DecomposeCurve on rows: Bezier intervals and pieces (`order` rows each).
fn decompose_rows<S: Scalar>(knots: &[S], rows: &[S], w: usize, order: usize) -> Result<Decomposed<S>, MathError> {
    check_rows(knots, rows.len(), w, order)?;
    let (u, p_rows) = clamp_rows(snap(knots), rows.to_vec(), w, order)?;
    if order == 1 {
        let intervals: Vec<_> = u.windows(2).map(|x| (x[0], x[1])).collect();
        return Ok((intervals, p_rows));
    }
    let (p, m) = (order - 1, u.len() - 1);
    let size = order * w;
    let (mut intervals, mut out) = (Vec::new(), Vec::new());
    let mut q = p_rows[..size].to_vec();
    let mut next = vec![S::ZERO; size];
    let (mut a, mut b) = (p, p + 1);
    while b < m {
        let i = b;
        while b < m && u[b + 1] == u[b] {
            b += 1;
        }
        let mult = b - i + 1;
        if mult < p {
            split_piece(&u, &mut q, &mut next, w, p, (a, b, mult), b < m);
        }
        intervals.push((u[a], u[b]));
        out.extend_from_slice(&q);
        if b < m {
            let from = p.saturating_sub(mult);
            next[from * w..].copy_from_slice(&p_rows[(b - p + from) * w..(b + 1) * w]);
            core::mem::swap(&mut q, &mut next);
            a = b;
            b += 1;
        }
    }
    Ok((intervals, out))
}

/// A5.6's inner loop: inserts U\[b\] until it has multiplicity p, updating the current piece `q`
/// and seeding the leading rows of the `next` piece.
fn split_piece<S: Scalar>(
    u: &[S],
    q: &mut [S],
    next: &mut [S],
    w: usize,
    p: usize,
    (a, b, mult): (usize, usize, usize),
    more: bool,
) {
    let numer = u[b] - u[a];
    let alphas: Vec<S> = (mult + 1..=p).map(|j| numer / (u[a + j] - u[a])).collect();
    let r = p - mult;
    for j in 1..=r {
        let (save, s) = (r - j, mult + j);
        for k in (s..=p).rev() {
            let alpha = alphas[k - s];
            let (lo, hi) = q.split_at_mut(k * w);
            let cur = hi[..w].to_vec();
            blend(&cur, &lo[(k - 1) * w..], alpha, &mut hi[..w]);
        }
        if more {
            next[save * w..(save + 1) * w].copy_from_slice(&q[p * w..(p + 1) * w]);
        }
    }
}

/// The Bezier pieces of a B-spline curve (The NURBS Book A5.6 DecomposeCurve, after clamping
/// both ends with A5.1); see [`BezierPieces`]. Any `dim` ≥ 1 is accepted here (4 for a
/// homogeneous NURBS); [`BezierPieces::eval`] needs dim ≤ 4.
pub fn decompose_curve<S: Scalar>(
    knots: &[S],
    points: &[S],
    dim: usize,
    order: usize,
) -> Result<BezierPieces<S>, MathError> {
    let (intervals, points) = decompose_rows(knots, points, dim, order)?;
    Ok(BezierPieces { dim, order, intervals, points })
}

/// Point (r, c) of a `rows × cols` net at (r·cols + c)·dim → at (c·rows + r)·dim.
fn transpose<S: Scalar>(points: &[S], rows: usize, cols: usize, dim: usize) -> Vec<S> {
    let mut out = Vec::with_capacity(points.len());
    for c in 0..cols {
        for r in 0..rows {
            out.extend_from_slice(&points[(r * cols + c) * dim..(r * cols + c + 1) * dim]);
        }
    }
    out
}

/// The Bezier patches of a B-spline surface (The NURBS Book A5.7 DecomposeSurface): the curve
/// decomposition along u on whole rows, then along v on the transposed result.
pub fn decompose_surface<S: Scalar>(s: &BSplineSurface<S>) -> Result<BezierPatches<S>, MathError> {
    let (nu, nv) = s.control_counts();
    check_rows(&s.vknots.knots, nu * nv * s.dim, nu * s.dim, s.vorder)?;
    let (uintervals, by_u) = decompose_rows(&s.uknots.knots, &s.points, nv * s.dim, s.uorder)?;
    let urows = uintervals.len() * s.uorder;
    let vmajor = transpose(&by_u, urows, nv, s.dim);
    let (vintervals, both) = decompose_rows(&s.vknots.knots, &vmajor, urows * s.dim, s.vorder)?;
    let vrows = vintervals.len() * s.vorder;
    let (uo, vo, dim) = (s.uorder, s.vorder, s.dim);
    let mut points = Vec::with_capacity(both.len());
    for a in 0..uintervals.len() {
        for b in 0..vintervals.len() {
            for i in 0..uo {
                for j in 0..vo {
                    let at = ((b * vo + j) * urows + a * uo + i) * dim;
                    points.extend_from_slice(&both[at..at + dim]);
                }
            }
        }
    }
    debug_assert_eq!(points.len(), urows * vrows * dim);
    Ok(BezierPatches { dim, uorder: uo, vorder: vo, uintervals, vintervals, points })
}

impl<S: Scalar> BSplineCurve<S> {
    /// The same curve with `u` inserted `times` times (A5.1); see [`insert_knot`].
    pub fn insert_knot(&self, u: S, times: usize) -> Result<Self, MathError> {
        let (k, p) = insert_knot(&self.knots.knots, &self.points, self.dim, self.order, u, times)?;
        Ok(Self { dim: self.dim, order: self.order, knots: KnotVector::new(k), points: p })
    }

    /// The Bezier pieces (A5.6); see [`decompose_curve`].
    pub fn to_bezier(&self) -> Result<BezierPieces<S>, MathError> {
        decompose_curve(&self.knots.knots, &self.points, self.dim, self.order)
    }
}

impl<S: Scalar> BSplineSurface<S> {
    /// The same surface with `t` inserted `times` times along `dir` (A5.3 SurfaceKnotIns, done
    /// as A5.1 on whole rows of the net).
    pub fn insert_knot(&self, dir: Direction, t: S, times: usize) -> Result<Self, MathError> {
        let (nu, nv) = self.control_counts();
        let mut out = self.clone();
        match dir {
            Direction::U => {
                let (k, p) = insert_rows(&self.uknots.knots, &self.points, nv * self.dim, self.uorder, t, times)?;
                (out.uknots.knots, out.points) = (k, p);
            }
            Direction::V => {
                check_rows(&self.vknots.knots, self.points.len(), nu * self.dim, self.vorder)?;
                let vmajor = transpose(&self.points, nu, nv, self.dim);
                let (k, p) = insert_rows(&self.vknots.knots, &vmajor, nu * self.dim, self.vorder, t, times)?;
                out.points = transpose(&p, nv + times, nu, self.dim);
                out.vknots.knots = k;
            }
        }
        Ok(out)
    }

    /// The Bezier patches (A5.7); see [`decompose_surface`].
    pub fn to_bezier(&self) -> Result<BezierPatches<S>, MathError> {
        decompose_surface(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::bspline::curve_point;
    use proptest::prelude::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + b.abs())
    }

    fn same_curve(k0: &[f64], p0: &[f64], k1: &[f64], p1: &[f64], dim: usize, order: usize) {
        let (lo, hi) = (k0[order - 1], k0[k0.len() - order]);
        for i in 0..=40 {
            let u = lo + (hi - lo) * i as f64 / 40.0;
            let a = curve_point(k0, p0, dim, order, u).unwrap();
            let b = curve_point(k1, p1, dim, order, u).unwrap();
            for c in 0..dim {
                assert!(close(a[c], b[c], 1e-10), "u = {u}: {a:?} vs {b:?}");
            }
        }
    }

    #[test]
    fn inserting_into_a_bezier_is_de_casteljau() {
        // Boehm at t = 1/2 on a quadratic Bezier: P0, (P0+P1)/2, (P1+P2)/2, P2.
        let pts = [0.0, 0.0, 2.0, 4.0, 4.0, 0.0];
        let (k, q) = insert_knot(&[0., 0., 0., 1., 1., 1.], &pts, 2, 3, 0.5, 1).unwrap();
        assert_eq!(k, [0., 0., 0., 0.5, 1., 1., 1.]);
        assert_eq!(q, [0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0]);
        // A second insertion gives the split point (the curve at 1/2: (2, 2)) twice as the join.
        let (_, q2) = insert_knot(&[0., 0., 0., 1., 1., 1.], &pts, 2, 3, 0.5, 2).unwrap();
        assert_eq!(&q2[4..6], [2.0, 2.0]);
    }

    #[test]
    fn seed_004_quadratic_becomes_midpoint_bezier() {
        // A uniform quadratic span's Bezier points are (P0+P1)/2, P1, (P1+P2)/2; they agree
        // with the closed form p(2) = (1/4, 1/2), p(3) = (3/4, 1/2).
        let pts = [0.0, 0.0, 0.5, 1.0, 1.0, 0.0];
        let b = decompose_curve(&[0., 1., 2., 3., 4., 5.], &pts, 2, 3).unwrap();
        assert_eq!(b.intervals, [(2.0, 3.0)]);
        assert_eq!(b.points, [0.25, 0.5, 0.5, 1.0, 0.75, 0.5]);
        for u in [2.0, 2.3, 2.5, 3.0] {
            let p = b.eval(u).unwrap();
            assert!(close(p[0], u / 2.0 - 0.75, 1e-14) && close(p[1], -u * u + 5.0 * u - 5.5, 1e-14));
        }
        assert!(b.eval(3.01).is_none() && b.eval(f64::NAN).is_none());
    }

    #[test]
    fn open_uniform_cubic_has_one_piece_per_span_and_interpolates_ends() {
        let kv = KnotVector::<f64>::open_uniform(6, 4).unwrap();
        let pts: Vec<f64> = (0..18).map(|k| ((k * 7 % 5) as f64) - 1.5).collect();
        let b = decompose_curve(&kv.knots, &pts, 3, 4).unwrap();
        assert_eq!(b.intervals, [(0.0, 1.0), (1.0, 2.0), (2.0, 3.0)]);
        assert_eq!(&b.points[..3], &pts[..3]);
        assert_eq!(&b.points[b.points.len() - 3..], &pts[15..]);
        // C² joins: consecutive pieces share their end point.
        assert_eq!(b.piece(0).unwrap()[9..12], b.piece(1).unwrap()[..3]);
    }

    #[test]
    fn breakpoints_within_tolerance_are_one() {
        // Knots 1 and 1 + 4e-6 are one breakpoint for GLU: three pieces, not four.
        let knots = [0., 0., 0., 1., 1. + 4e-6, 2., 3., 3., 3.];
        let pts: Vec<f64> = (0..6).map(|k| (k * k) as f64).collect();
        let b = decompose_curve(&knots, &pts, 1, 3).unwrap();
        assert_eq!(b.intervals, [(0.0, 1.0), (1.0, 2.0), (2.0, 3.0)]);
        for u in [0.3, 0.99, 1.5, 2.7] {
            let want = curve_point(&knots, &pts, 1, 3, u).unwrap()[0];
            assert!(close(b.eval(u).unwrap()[0], want, 1e-4));
        }
    }

    #[test]
    fn discontinuous_and_constant_splines() {
        // Interior multiplicity = order (a jump), and order 1 (piecewise constant).
        let knots = [0., 0., 1., 1., 2., 2.];
        let pts = [0.0, 1.0, 5.0, 6.0];
        let b = decompose_curve(&knots, &pts, 1, 2).unwrap();
        assert_eq!((b.intervals.clone(), b.points.clone()), (vec![(0.0, 1.0), (1.0, 2.0)], pts.to_vec()));
        let c = decompose_curve(&[0., 1., 3.], &[8.0, 9.0], 1, 1).unwrap();
        assert_eq!((c.intervals, c.points), (vec![(0.0, 1.0), (1.0, 3.0)], vec![8.0, 9.0]));
    }

    #[test]
    fn errors_instead_of_panics() {
        let k = [0., 0., 0., 1., 1., 1.];
        let p = [0.0; 6];
        assert_eq!(insert_knot(&k, &p, 2, 3, 1.5, 1), Err(MathError::OutOfRange));
        assert_eq!(insert_knot(&k, &p, 2, 3, f64::NAN, 1), Err(MathError::OutOfRange));
        assert!(matches!(insert_knot(&k, &p, 2, 3, 0.5, 3), Err(MathError::Knots(_))));
        assert!(matches!(insert_knot(&k, &p, 2, 3, 1.0, 1), Err(MathError::Knots(_))));
        assert_eq!(insert_knot(&k, &p, 5, 3, 0.5, 1), Err(MathError::BadDimension(5)));
        assert_eq!(insert_knot(&k, &p[..5], 2, 3, 0.5, 1), Err(MathError::PointCount { len: 5, dim: 2 }));
        assert_eq!(
            decompose_curve(&[0., 0.5, 1., 0.7, 2., 2.], &[0.0; 4], 1, 2),
            Err(MathError::Knots("decreasing knot sequence knot"))
        );
        assert_eq!(
            decompose_curve(&[0., 0., 0., 1., 1.], &[0.0; 3], 1, 2),
            Err(MathError::Knots("knot multiplicity greater than order of spline"))
        );
        assert_eq!(
            decompose_curve(&[0., 0., 1., f64::NAN], &[0.0; 2], 1, 2),
            Err(MathError::Knots("knots must be finite"))
        );
        assert_eq!(refine_knots(&k, &p, 2, 3, &[0.5, 2.0]), Err(MathError::OutOfRange));
    }

    fn test_surface(rational: bool) -> BSplineSurface<f64> {
        let uk = KnotVector::new(vec![0.0, 0.0, 0.0, 0.4, 0.4 + 3e-6, 1.0, 1.0, 1.0]);
        let vk = KnotVector::<f64>::uniform(5, 4).unwrap();
        let dim = if rational { 4 } else { 3 };
        let net: Vec<f64> =
            (0..5 * 5 * dim)
                .map(|k| {
                    if rational && k % 4 == 3 {
                        0.5 + (k % 7) as f64 * 0.2
                    } else {
                        ((k * 29 % 13) as f64) * 0.25 - 1.0
                    }
                })
                .collect();
        BSplineSurface::try_new(dim, 3, 4, uk, vk, net).unwrap()
    }

    #[test]
    fn surface_pieces_reproduce_surface() {
        for rational in [false, true] {
            let s = test_surface(rational);
            let b = s.to_bezier().unwrap();
            assert_eq!((b.uintervals.len(), b.vintervals.len(), b.len()), (2, 2, 4));
            for i in 0..=12 {
                for j in 0..=12 {
                    let (u, v) = (i as f64 / 12.0, 3.0 + 2.0 * j as f64 / 12.0);
                    let want = s.eval_with_partials(u, v).unwrap();
                    let got = b.eval(u, v).unwrap();
                    for c in 0..s.dim {
                        assert!(close(got.point[c], want.point[c], 1e-4), "({u},{v})");
                        assert!(close(got.dv[c], want.dv[c], 1e-4), "dv at ({u},{v})");
                    }
                }
            }
        }
    }

    #[test]
    fn surface_insertion_keeps_surface_in_both_directions() {
        let s = test_surface(true);
        let su = s.insert_knot(Direction::U, 0.7, 2).unwrap();
        let sv = s.insert_knot(Direction::V, 3.5, 1).unwrap();
        assert_eq!((su.control_counts(), sv.control_counts()), ((7, 5), (5, 6)));
        for (u, v) in [(0.0, 3.0), (0.2, 3.3), (0.69, 3.5), (0.9, 4.7), (1.0, 5.0)] {
            let (a, bu, bv) = (s.eval(u, v).unwrap(), su.eval(u, v).unwrap(), sv.eval(u, v).unwrap());
            for c in 0..4 {
                assert!(close(bu[c], a[c], 1e-12) && close(bv[c], a[c], 1e-12));
            }
        }
        assert_eq!(s.insert_knot(Direction::V, 2.0, 1), Err(MathError::OutOfRange));
    }

    /// Random GLU-valid splines of 2-D points with small integer knots (many repeats).
    fn spline() -> impl Strategy<Value = (usize, Vec<f64>, Vec<f64>)> {
        spline_of_order(1)
    }

    /// [`spline`] of order at least `min_order` (generated so, not filtered: long property runs
    /// would otherwise hit proptest's limit on rejected cases).
    fn spline_of_order(min_order: usize) -> impl Strategy<Value = (usize, Vec<f64>, Vec<f64>)> {
        (min_order..6, 0usize..6)
            .prop_flat_map(|(order, extra)| {
                let nk = 2 * order + extra;
                let knots = prop::collection::vec(0u8..6, nk).prop_map(|mut k| {
                    k.sort_unstable();
                    k.into_iter().map(f64::from).collect::<Vec<_>>()
                });
                (Just(order), knots, prop::collection::vec(-5.0f64..5.0, (nk - order) * 2))
            })
            .prop_filter("GLU-valid knots", |(order, knots, _)| {
                KnotVector::new(knots.clone()).check_knots(*order).is_ok()
            })
    }

    proptest! {
        #[test]
        fn insertion_keeps_the_curve((order, knots, pts) in spline(), t in 0.0f64..=1.0, times in 1usize..4) {
            let n = knots.len() - order;
            let u = knots[order - 1] + (knots[n] - knots[order - 1]) * t;
            let s = knots.iter().filter(|&&k| k == u).count();
            let times = times.min((order - 1).saturating_sub(s));
            let (k1, p1) = insert_knot(&knots, &pts, 2, order, u, times).unwrap();
            prop_assert_eq!(k1.len(), knots.len() + times);
            same_curve(&knots, &pts, &k1, &p1, 2, order);
        }

        #[test]
        fn refinement_keeps_the_curve((order, knots, pts) in spline_of_order(2), ts in prop::collection::vec(0.0f64..=1.0, 0..4)) {
            let n = knots.len() - order;
            let (lo, hi) = (knots[order - 1], knots[n]);
            let mut new: Vec<f64> = ts.iter().map(|t| lo + (hi - lo) * (0.05 + 0.9 * t)).collect();
            new.sort_by(f64::total_cmp);
            let (k1, p1) = refine_knots(&knots, &pts, 2, order, &new).unwrap();
            same_curve(&knots, &pts, &k1, &p1, 2, order);
        }

        #[test]
        fn decomposition_reproduces_the_curve((order, knots, pts) in spline()) {
            let kv = KnotVector::new(knots.clone());
            let b = decompose_curve(&knots, &pts, 2, order).unwrap();
            prop_assert_eq!(b.len() + 1, kv.breakpoints(order).len());
            prop_assert_eq!(b.points.len(), b.len() * order * 2);
            for (k, &(u0, u1)) in b.intervals.iter().enumerate() {
                for i in 0..=8 {
                    // Inside each piece, away from its ends (a jump at a full-multiplicity knot).
                    let t = 0.01 + 0.98 * i as f64 / 8.0;
                    let want = curve_point(&knots, &pts, 2, order, u0 + (u1 - u0) * t).unwrap();
                    let got = de_casteljau(b.piece(k).unwrap(), 2, order, t);
                    prop_assert!(close(got[0], want[0], 1e-9) && close(got[1], want[1], 1e-9));
                }
            }
        }
    }
}
