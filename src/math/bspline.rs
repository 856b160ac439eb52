//! B-spline basis functions and their derivatives, and B-spline curves and tensor-product
//! surfaces evaluated directly (The NURBS Book A2.2 BasisFuns, A2.3 DersBasisFuns, A3.1, A3.5).
//!
//! Textbook convention (seed 004 §9.5): **order** d = degree + 1, `npts` control points and
//! `npts + order` knots, valid range [u_{d−1}, u_{npts}]. Control points are flat, `dim`
//! components each as in [`super::bezier`]; a surface net is packed u-major, point (i, j) at
//! `(i * nv + j) * dim` with `nv` points along v. A 4-component net is homogeneous
//! (w·x, w·y, w·z, w): the `*_rational` methods project it (GL's `*_VERTEX_4`).
//!
//! Direct evaluation is the oracle; drawing goes through Bezier pieces
//! ([`super::insertion::decompose_curve`]) as GLU does. Orders are limited to
//! [`MAX_ORDER`] (30, GL's limit) so that basis values live on the stack.

use super::bezier::{Vec4, MAX_DIM};
use super::knots::{find_span, KnotVector};
use super::patch::{PatchSample, MAX_ORDER};
use super::rational::{project, rational_derivative};
use super::scalar::Scalar;
use super::MathError;

/// Basis values N_{span−p..=span}(u) (or their derivatives) in `[..order]`.
pub type Basis<S> = [S; MAX_ORDER];

/// a / b, with the textbook's convention 0/0 = 0 extended to x/0 = 0 (seed 004 §9.5.1 note):
/// empty knot spans contribute nothing instead of NaN.
fn div0<S: Scalar>(a: S, b: S) -> S {
    if b == S::ZERO {
        S::ZERO
    } else {
        a / b
    }
}

/// Checks `order` and that `span` indexes a span with `order` basis functions.
fn span_fits(len: usize, order: usize, span: usize) -> bool {
    (1..=MAX_ORDER).contains(&order) && span + 1 >= order && span + order < len + 1
}

/// The `order` nonzero basis functions N_{span−p, p}(u) .. N_{span, p}(u), p = order − 1
/// (The NURBS Book A2.2 BasisFuns), in `[..order]`. `span` comes from
/// [`find_span`]; `None` if it leaves the knot vector or `order` is outside 1..=30.
#[must_use]
pub fn basis_funs<S: Scalar>(knots: &[S], order: usize, span: usize, u: S) -> Option<Basis<S>> {
    if !span_fits(knots.len(), order, span) {
        return None;
    }
    Some(raise_basis(knots, order, span, u, |_, _, _| {}))
}

/// The triangle of A2.2 BasisFuns, which A2.3 DersBasisFuns runs again recording it as `ndu`:
/// the basis raised one degree at a time from N_{span,0} = 1, degree j's N_{span−j..=span, j}
/// in `n[..=j]`. After each degree j, `step(j, n, sums)` sees those values and the knot sums
/// `sums[..j]` (u_{span+r+1} − u_{span+r+1−j}) that step divided by. Returns degree p's.
fn raise_basis<S: Scalar>(
    knots: &[S],
    order: usize,
    span: usize,
    u: S,
    mut step: impl FnMut(usize, &Basis<S>, &Basis<S>),
) -> Basis<S> {
    let (mut n, mut left, mut right) = ([S::ZERO; MAX_ORDER], [S::ZERO; MAX_ORDER], [S::ZERO; MAX_ORDER]);
    let mut sums = [S::ZERO; MAX_ORDER];
    n[0] = S::ONE;
    for j in 1..order {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        let mut saved = S::ZERO;
        for r in 0..j {
            sums[r] = right[r + 1] + left[j - r];
            let temp = div0(n[r], sums[r]);
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
        step(j, &n, &sums);
    }
    n
}

/// The basis functions and their first derivatives at `u`, from the basis one order lower:
/// N′_{i,p} = p (N_{i,p−1} / (u_{i+p} − u_i) − N_{i+1,p−1} / (u_{i+p+1} − u_{i+1}))
/// (The NURBS Book eq. 2.7). Allocation-free; `None` as for [`basis_funs`].
#[must_use]
pub fn basis_with_derivative<S: Scalar>(knots: &[S], order: usize, span: usize, u: S) -> Option<(Basis<S>, Basis<S>)> {
    let n = basis_funs(knots, order, span, u)?;
    let mut d = [S::ZERO; MAX_ORDER];
    if order == 1 {
        return Some((n, d));
    }
    let lower = basis_funs(knots, order - 1, span, u)?;
    let p = order - 1;
    let deg = S::from_usize(p);
    for (j, dj) in d.iter_mut().enumerate().take(order) {
        let i = span + j - p; // global index of this basis function
        let a = if j > 0 { div0(lower[j - 1], knots[i + p] - knots[i]) } else { S::ZERO };
        let b = if j < p { div0(lower[j], knots[i + p + 1] - knots[i + 1]) } else { S::ZERO };
        *dj = deg * (a - b);
    }
    Some((n, d))
}

/// The basis functions and their derivatives up to `nders` (The NURBS Book A2.3
/// DersBasisFuns): a flat `(nders + 1) * order` vector, row k holding the k-th derivatives of
/// N_{span−p..=span}. Rows beyond the degree are zero.
pub fn ders_basis_funs<S: Scalar>(
    knots: &[S],
    order: usize,
    span: usize,
    u: S,
    nders: usize,
) -> Result<Vec<S>, MathError> {
    if order == 0 || order > MAX_ORDER {
        return Err(MathError::BadOrder(order));
    }
    if !span_fits(knots.len(), order, span) {
        return Err(MathError::OutOfRange);
    }
    let ndu = ndu_table(knots, order, span, u);
    let mut ders = vec![S::ZERO; (nders + 1) * order];
    for j in 0..order {
        ders[j] = ndu[j * order + order - 1];
    }
    let top = nders.min(order - 1);
    for r in 0..order {
        derivative_column(&ndu, order, r, top, &mut ders);
    }
    let mut factor = S::from_usize(order - 1);
    for k in 1..=top {
        for v in &mut ders[k * order..(k + 1) * order] {
            *v *= factor;
        }
        factor *= S::from_usize(order - 1 - k);
    }
    Ok(ders)
}

/// A2.3's `ndu` triangle, flat `order × order` (row-major `[j][r]`): basis functions of every
/// degree above the diagonal, knot differences below it.
fn ndu_table<S: Scalar>(knots: &[S], order: usize, span: usize, u: S) -> Vec<S> {
    let at = |j: usize, r: usize| j * order + r;
    let mut ndu = vec![S::ZERO; order * order];
    ndu[0] = S::ONE;
    raise_basis(knots, order, span, u, |j, n, sums| {
        for r in 0..j {
            ndu[at(j, r)] = sums[r];
        }
        for r in 0..=j {
            ndu[at(r, j)] = n[r];
        }
    });
    ndu
}

/// A2.3's inner loop for basis function r: its derivatives 1..=top (unscaled by p!/(p−k)!).
fn derivative_column<S: Scalar>(ndu: &[S], order: usize, r: usize, top: usize, ders: &mut [S]) {
    let at = |j: usize, c: usize| j * order + c;
    let p = order as isize - 1;
    let ri = r as isize;
    let mut a = [[S::ZERO; MAX_ORDER]; 2];
    let (mut s1, mut s2) = (0, 1);
    a[0][0] = S::ONE;
    for k in 1..=top as isize {
        let (rk, pk) = (ri - k, (p - k) as usize);
        let mut d = S::ZERO;
        if rk >= 0 {
            a[s2][0] = div0(a[s1][0], ndu[at(pk + 1, rk as usize)]);
            d = a[s2][0] * ndu[at(rk as usize, pk)];
        }
        let j1 = if rk >= -1 { 1 } else { -rk };
        let j2 = if ri - 1 <= pk as isize { k - 1 } else { p - ri };
        for j in j1..=j2 {
            let (ju, col) = (j as usize, (rk + j) as usize);
            a[s2][ju] = div0(a[s1][ju] - a[s1][ju - 1], ndu[at(pk + 1, col)]);
            d += a[s2][ju] * ndu[at(col, pk)];
        }
        if ri <= pk as isize {
            let ku = k as usize;
            a[s2][ku] = div0(-a[s1][ku - 1], ndu[at(pk + 1, r)]);
            d += a[s2][ku] * ndu[at(r, pk)];
        }
        ders[k as usize * order + r] = d;
        core::mem::swap(&mut s1, &mut s2);
    }
}

/// Checks a spline's shape: order 1..=30, at least `order` control points, and `width` values
/// per control point. Returns the number of control points.
pub(crate) fn check_shape(knots: usize, values: usize, width: usize, order: usize) -> Result<usize, MathError> {
    if order == 0 || order > MAX_ORDER {
        return Err(MathError::BadOrder(order));
    }
    let n = knots.checked_sub(order).filter(|&n| n >= order).ok_or(MathError::Knots("too few knots"))?;
    if n.checked_mul(width) != Some(values) {
        return Err(MathError::PointCount { len: values, dim: width });
    }
    Ok(n)
}

fn check_dim(dim: usize) -> Result<(), MathError> {
    if dim == 0 || dim > MAX_DIM {
        return Err(MathError::BadDimension(dim));
    }
    Ok(())
}

/// Σ weights\[j\] · P_{first+j}, the `order` control points from `first` on.
fn combine<S: Scalar>(points: &[S], dim: usize, first: usize, weights: &[S]) -> Vec4<S> {
    let mut out = [S::ZERO; MAX_DIM];
    for (j, &w) in weights.iter().enumerate() {
        let p = &points[(first + j) * dim..(first + j + 1) * dim];
        for c in 0..dim {
            out[c] += w * p[c];
        }
    }
    out
}

/// The curve point and first derivative d/du at `u` (The NURBS Book A3.1 and A3.2 for k = 1).
/// `points` holds `knots.len() − order` points of `dim` components; `u` must lie in the valid
/// range ([`MathError::OutOfRange`] otherwise, also for NaN).
pub fn curve_point_and_derivative<S: Scalar>(
    knots: &[S],
    points: &[S],
    dim: usize,
    order: usize,
    u: S,
) -> Result<(Vec4<S>, Vec4<S>), MathError> {
    check_dim(dim)?;
    check_shape(knots.len(), points.len(), dim, order)?;
    let span = find_span(knots, order, u).ok_or(MathError::OutOfRange)?;
    let (n, d) = basis_with_derivative(knots, order, span, u).ok_or(MathError::OutOfRange)?;
    let first = span + 1 - order;
    Ok((combine(points, dim, first, &n[..order]), combine(points, dim, first, &d[..order])))
}

/// The curve point at `u` (The NURBS Book A3.1 CurvePoint); see [`curve_point_and_derivative`].
pub fn curve_point<S: Scalar>(knots: &[S], points: &[S], dim: usize, order: usize, u: S) -> Result<Vec4<S>, MathError> {
    curve_point_and_derivative(knots, points, dim, order, u).map(|(p, _)| p)
}

/// The first derivative d/du at `u`; see [`curve_point_and_derivative`].
pub fn curve_derivative<S: Scalar>(
    knots: &[S],
    points: &[S],
    dim: usize,
    order: usize,
    u: S,
) -> Result<Vec4<S>, MathError> {
    curve_point_and_derivative(knots, points, dim, order, u).map(|(_, d)| d)
}

/// The projected point and its true derivative from a homogeneous point p and derivative d:
/// (x/w)′ = (x′w − w′x)/w².
fn project_with_derivative<S: Scalar>(p: Vec4<S>, d: Vec4<S>) -> ([S; 3], [S; 3]) {
    let scaled = rational_derivative(p, d);
    let w2 = p[3] * p[3];
    (project(p), scaled.map(|c| c / w2))
}

/// A projected point of a rational surface with its true partial derivatives.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ProjectedSample<S: Scalar> {
    /// (x/w, y/w, z/w).
    pub point: [S; 3],
    /// ∂/∂u of the projected point.
    pub du: [S; 3],
    /// ∂/∂v of the projected point.
    pub dv: [S; 3],
}

/// A B-spline curve: `order`, knots and `knots.len() − order` control points of `dim` components.
///
/// ```
/// use gleval::math::{BSplineCurve, KnotVector};
/// // Seed 004 §9.5.4: uniform quadratic through P0(0,0), P1(0.5,1), P2(1,0), knots {0..5}:
/// // p(u) = (u/2 − 3/4, −u² + 5u − 11/2) on [2, 3].
/// let knots = KnotVector::uniform(3, 3).unwrap();
/// let c = BSplineCurve::try_new(2, 3, knots, vec![0.0f64, 0.0, 0.5, 1.0, 1.0, 0.0]).unwrap();
/// let p = c.eval(2.5).unwrap();
/// assert!((p[0] - 0.5).abs() < 1e-12 && (p[1] - 0.75).abs() < 1e-12);
/// assert!(c.eval(3.5).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineCurve<S: Scalar> {
    /// Components per control point, 1..=4 (4 = homogeneous for the rational methods).
    pub dim: usize,
    /// Degree + 1.
    pub order: usize,
    /// `npts + order` knots.
    pub knots: KnotVector<S>,
    /// `npts * dim` values.
    pub points: Vec<S>,
}

impl<S: Scalar> BSplineCurve<S> {
    /// Checks dimension (1..=4), order (1..=30), GLU's knot rules 2..=5
    /// ([`KnotVector::check_knots`]), finite knots, and `npts * dim` values.
    ///
    /// ```
    /// use gleval::math::{BSplineCurve, KnotVector, MathError};
    /// let bad = BSplineCurve::try_new(2, 2, KnotVector::new(vec![0.0, 1.0, 0.5, 1.0]), vec![0.0; 4]);
    /// assert_eq!(bad, Err(MathError::Knots("valid knot range is empty")));
    /// ```
    pub fn try_new(dim: usize, order: usize, knots: KnotVector<S>, points: Vec<S>) -> Result<Self, MathError> {
        check_dim(dim)?;
        check_knot_vector(&knots, order)?;
        check_shape(knots.len(), points.len(), dim, order)?;
        Ok(Self { dim, order, knots, points })
    }

    /// Number of control points.
    #[must_use]
    pub fn control_count(&self) -> usize {
        self.points.len() / self.dim.max(1)
    }

    /// The valid parameter range [knots\[order−1\], knots\[npts\]].
    #[must_use]
    pub fn valid_range(&self) -> Option<(S, S)> {
        self.knots.valid_range(self.order)
    }

    /// The point at `u` in the valid range.
    pub fn eval(&self, u: S) -> Result<Vec4<S>, MathError> {
        curve_point(&self.knots.knots, &self.points, self.dim, self.order, u)
    }

    /// The first derivative d/du at `u`.
    pub fn derivative(&self, u: S) -> Result<Vec4<S>, MathError> {
        curve_derivative(&self.knots.knots, &self.points, self.dim, self.order, u)
    }

    /// The projected point of a homogeneous (dim 4) curve: a NURBS curve point.
    pub fn eval_rational(&self, u: S) -> Result<[S; 3], MathError> {
        self.rational_with_derivative(u).map(|(p, _)| p)
    }

    /// The projected point of a homogeneous (dim 4) curve and its derivative d/du.
    pub fn rational_with_derivative(&self, u: S) -> Result<([S; 3], [S; 3]), MathError> {
        if self.dim != 4 {
            return Err(MathError::BadDimension(self.dim));
        }
        let (p, d) = curve_point_and_derivative(&self.knots.knots, &self.points, 4, self.order, u)?;
        Ok(project_with_derivative(p, d))
    }
}

/// GLU's rules 2..=5 plus finite knots, as a [`MathError`].
fn check_knot_vector<S: Scalar>(knots: &KnotVector<S>, order: usize) -> Result<(), MathError> {
    if order == 0 || order > MAX_ORDER {
        return Err(MathError::BadOrder(order));
    }
    knots.check_knots(order)?;
    if !knots.knots.iter().all(|k| k.is_finite()) {
        return Err(MathError::Knots("knots must be finite"));
    }
    Ok(())
}

/// A tensor-product B-spline surface (seed 004 §9.5.6): p(u,v) = Σᵢ Σⱼ N_{i,uorder}(u)
/// N_{j,vorder}(v) P_{ij}, the net packed u-major: point (i, j) at `(i * nv + j) * dim` with
/// nu = uknots − uorder and nv = vknots − vorder.
///
/// ```
/// use gleval::math::{BSplineSurface, KnotVector};
/// // A bilinear surface: order 2 both ways, Bezier knots.
/// let k = KnotVector::new(vec![0.0, 0.0, 1.0, 1.0]);
/// let net = vec![0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 1.];
/// let s = BSplineSurface::try_new(3, 2, 2, k.clone(), k, net).unwrap();
/// assert_eq!(s.eval(0.5, 0.5).unwrap(), [0.5, 0.5, 0.25, 0.0]);
/// assert_eq!(s.eval_with_partials(0.5, 0.5).unwrap().du, [1.0, 0.0, 0.5, 0.0]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineSurface<S: Scalar> {
    /// Components per control point, 1..=4 (4 = homogeneous for the rational methods).
    pub dim: usize,
    /// Order along u (degree + 1).
    pub uorder: usize,
    /// Order along v.
    pub vorder: usize,
    /// `nu + uorder` knots.
    pub uknots: KnotVector<S>,
    /// `nv + vorder` knots.
    pub vknots: KnotVector<S>,
    /// `nu * nv * dim` values, u-major.
    pub points: Vec<S>,
}

impl<S: Scalar> BSplineSurface<S> {
    /// Checks as [`BSplineCurve::try_new`] in each direction, and `nu * nv * dim` values.
    pub fn try_new(
        dim: usize,
        uorder: usize,
        vorder: usize,
        uknots: KnotVector<S>,
        vknots: KnotVector<S>,
        points: Vec<S>,
    ) -> Result<Self, MathError> {
        check_dim(dim)?;
        check_knot_vector(&uknots, uorder)?;
        check_knot_vector(&vknots, vorder)?;
        let nv = vknots.len() - vorder;
        check_shape(uknots.len(), points.len(), nv * dim, uorder)?;
        Ok(Self { dim, uorder, vorder, uknots, vknots, points })
    }

    /// Control points along (u, v).
    #[must_use]
    pub fn control_counts(&self) -> (usize, usize) {
        (self.uknots.len().saturating_sub(self.uorder), self.vknots.len().saturating_sub(self.vorder))
    }

    /// The point at (u, v) in the valid ranges.
    pub fn eval(&self, u: S, v: S) -> Result<Vec4<S>, MathError> {
        self.eval_with_partials(u, v).map(|s| s.point)
    }

    /// The point and its partial derivatives ∂/∂u, ∂/∂v (The NURBS Book A3.6 for d = 1).
    pub fn eval_with_partials(&self, u: S, v: S) -> Result<PatchSample<S>, MathError> {
        let (nu, nv) = self.control_counts();
        if nu.checked_mul(nv).and_then(|n| n.checked_mul(self.dim)) != Some(self.points.len()) || self.dim > MAX_DIM {
            return Err(MathError::PointCount { len: self.points.len(), dim: self.dim });
        }
        let (us, bu, dbu) = self.direction(&self.uknots.knots, self.uorder, u)?;
        let (vs, bv, dbv) = self.direction(&self.vknots.knots, self.vorder, v)?;
        let mut out = PatchSample::default();
        for i in 0..self.uorder {
            let row = (us + i) * nv + vs;
            let val = combine(&self.points, self.dim, row, &bv[..self.vorder]);
            let dv = combine(&self.points, self.dim, row, &dbv[..self.vorder]);
            for c in 0..self.dim {
                out.point[c] += bu[i] * val[c];
                out.du[c] += dbu[i] * val[c];
                out.dv[c] += bu[i] * dv[c];
            }
        }
        Ok(out)
    }

    /// First control index, basis values and derivatives along one direction.
    fn direction(&self, knots: &[S], order: usize, t: S) -> Result<(usize, Basis<S>, Basis<S>), MathError> {
        let span = find_span(knots, order, t).ok_or(MathError::OutOfRange)?;
        let (b, d) = basis_with_derivative(knots, order, span, t).ok_or(MathError::BadOrder(order))?;
        Ok((span + 1 - order, b, d))
    }

    /// The projected point of a homogeneous (dim 4) surface: a NURBS surface point.
    pub fn eval_rational(&self, u: S, v: S) -> Result<[S; 3], MathError> {
        self.eval_rational_with_partials(u, v).map(|s| s.point)
    }

    /// The projected point of a homogeneous (dim 4) surface and its true partial derivatives.
    pub fn eval_rational_with_partials(&self, u: S, v: S) -> Result<ProjectedSample<S>, MathError> {
        if self.dim != 4 {
            return Err(MathError::BadDimension(self.dim));
        }
        let s = self.eval_with_partials(u, v)?;
        let (point, du) = project_with_derivative(s.point, s.du);
        let (_, dv) = project_with_derivative(s.point, s.dv);
        Ok(ProjectedSample { point, du, dv })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::bezier::de_casteljau;
    use crate::math::patch::horner_patch;
    use proptest::prelude::*;

    /// The textbook's recursive definition (seed 004 §9.5.1) with 0/0 = 0: the reference.
    fn cox_de_boor(t: &[f64], k: usize, d: usize, u: f64) -> f64 {
        if d == 1 {
            return if t[k] <= u && u < t[k + 1] { 1.0 } else { 0.0 };
        }
        let q = |a: f64, b: f64| if b == 0.0 { 0.0 } else { a / b };
        q(u - t[k], t[k + d - 1] - t[k]) * cox_de_boor(t, k, d - 1, u)
            + q(t[k + d] - u, t[k + d] - t[k + 1]) * cox_de_boor(t, k + 1, d - 1, u)
    }

    const UNI: [f64; 6] = [0., 1., 2., 3., 4., 5.];
    const SEED_PTS: [f64; 6] = [0.0, 0.0, 0.5, 1.0, 1.0, 0.0];

    fn n03(u: f64) -> f64 {
        match u {
            u if u < 1.0 => 0.5 * u * u,
            u if u < 2.0 => 0.5 * u * (2.0 - u) + 0.5 * (u - 1.0) * (3.0 - u),
            u => 0.5 * (3.0 - u).powi(2),
        }
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol * (1.0 + b.abs())
    }

    #[test]
    fn seed_004_basis_closed_forms() {
        // N03 on [0,3) and N13, N23 on their pieces, as printed in §9.5.4 (N13(u) = N03(u−1)).
        for i in 0..60 {
            let u = i as f64 * 0.05;
            assert!(close(cox_de_boor(&UNI, 0, 3, u), n03(u), 1e-14), "N03({u})");
            assert!(close(cox_de_boor(&UNI, 1, 3, u + 1.0), n03(u), 1e-14), "N13");
            assert!(close(cox_de_boor(&UNI, 2, 3, u + 2.0), n03(u), 1e-14), "N23");
        }
        for u in [2.0, 2.25, 2.5, 2.9] {
            let b = basis_funs(&UNI, 3, 2, u).unwrap();
            assert!(close(b[0], 0.5 * (3.0 - u).powi(2), 1e-14));
            assert!(close(b[1], 0.5 * (u - 1.0) * (3.0 - u) + 0.5 * (u - 2.0) * (4.0 - u), 1e-14));
            assert!(close(b[2], 0.5 * (u - 2.0).powi(2), 1e-14));
            let b3 = basis_funs(&UNI, 3, 3, u + 1.0).unwrap();
            assert!(close(b3[0], 0.5 * (4.0 - (u + 1.0)).powi(2), 1e-14), "N13 on [3,4)");
        }
    }

    #[test]
    fn seed_004_quadratic_curve_closed_form() {
        // p(u) = (u/2 − 3/4, −u² + 5u − 11/2), p′(u) = (1/2, −2u + 5) on [2, 3], ends included.
        for i in 0..=20 {
            let u = 2.0 + i as f64 / 20.0;
            let (p, d) = curve_point_and_derivative(&UNI, &SEED_PTS, 2, 3, u).unwrap();
            assert!(close(p[0], u / 2.0 - 0.75, 1e-13) && close(p[1], -u * u + 5.0 * u - 5.5, 1e-13), "{u}");
            assert!(close(d[0], 0.5, 1e-13) && close(d[1], -2.0 * u + 5.0, 1e-13), "{u}");
        }
        assert_eq!(curve_point(&UNI, &SEED_PTS, 2, 3, 1.99), Err(MathError::OutOfRange));
        assert_eq!(curve_point(&UNI, &SEED_PTS, 2, 3, f64::NAN), Err(MathError::OutOfRange));
    }

    #[test]
    fn ders_basis_funs_rows_agree_and_second_derivative_is_finite_difference() {
        let knots = [0.0, 0.0, 0.0, 0.0, 0.7, 1.5, 1.5, 2.2, 3.0, 3.0, 3.0, 3.0];
        let (u, h) = (1.1, 1e-5);
        let span = find_span(&knots, 4, u).unwrap();
        let ders = ders_basis_funs(&knots, 4, span, u, 5).unwrap();
        let (b, db) = basis_with_derivative(&knots, 4, span, u).unwrap();
        let (_, dp) = basis_with_derivative(&knots, 4, span, u + h).unwrap();
        let (_, dm) = basis_with_derivative(&knots, 4, span, u - h).unwrap();
        for j in 0..4 {
            assert!(close(ders[j], b[j], 1e-14) && close(ders[4 + j], db[j], 1e-12));
            assert!(close(ders[8 + j], (dp[j] - dm[j]) / (2.0 * h), 1e-6), "second derivative {j}");
            assert!(ders[16 + j] == 0.0 && ders[20 + j] == 0.0, "beyond the degree");
        }
        assert_eq!(ders_basis_funs(&knots, 31, span, u, 1), Err(MathError::BadOrder(31)));
        assert_eq!(ders_basis_funs(&knots, 4, 11, u, 1), Err(MathError::OutOfRange));
    }

    #[test]
    fn surface_is_curve_of_curves() {
        // 4 x 5 net, orders 3 x 4, non-uniform knots: evaluate rows along v, then the column along u.
        let uk = vec![0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0];
        let vk = vec![-1.0, -1.0, -1.0, -1.0, 0.5, 2.0, 2.0, 2.0, 2.0];
        let net: Vec<f64> = (0..4 * 5 * 3).map(|k| ((k * 29 % 13) as f64) * 0.25 - 1.0).collect();
        let s = BSplineSurface::try_new(3, 3, 4, KnotVector::new(uk.clone()), KnotVector::new(vk.clone()), net.clone())
            .unwrap();
        for (u, v) in [(0.0, -1.0), (0.3, 0.2), (0.4, 0.5), (1.0, 2.0), (0.77, 1.3)] {
            let mut column = Vec::new();
            for i in 0..4 {
                let p = curve_point(&vk, &net[i * 15..(i + 1) * 15], 3, 4, v).unwrap();
                column.extend_from_slice(&p[..3]);
            }
            let want = curve_point(&uk, &column, 3, 3, u).unwrap();
            let got = s.eval(u, v).unwrap();
            for c in 0..3 {
                assert!(close(got[c], want[c], 1e-12), "({u},{v})");
            }
        }
        assert_eq!(s.eval(1.1, 0.0), Err(MathError::OutOfRange));
    }

    #[test]
    fn surface_partials_are_finite_differences() {
        let uk = KnotVector::new(vec![0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0]);
        let vk = KnotVector::<f64>::uniform(5, 3).unwrap();
        let net: Vec<f64> = (0..4 * 5 * 4).map(|k| ((k * 17 % 7) as f64) * 0.3 + 0.5).collect();
        let s = BSplineSurface::try_new(4, 3, 3, uk, vk, net).unwrap();
        let h = 1e-6;
        for (u, v) in [(0.2, 2.5), (0.7, 3.9), (0.41, 4.2)] {
            let d = s.eval_with_partials(u, v).unwrap();
            let r = s.eval_rational_with_partials(u, v).unwrap();
            for c in 0..4 {
                let fu = (s.eval(u + h, v).unwrap()[c] - s.eval(u - h, v).unwrap()[c]) / (2.0 * h);
                let fv = (s.eval(u, v + h).unwrap()[c] - s.eval(u, v - h).unwrap()[c]) / (2.0 * h);
                assert!(close(d.du[c], fu, 1e-6) && close(d.dv[c], fv, 1e-6));
            }
            for c in 0..3 {
                let fu = (s.eval_rational(u + h, v).unwrap()[c] - s.eval_rational(u - h, v).unwrap()[c]) / (2.0 * h);
                let fv = (s.eval_rational(u, v + h).unwrap()[c] - s.eval_rational(u, v - h).unwrap()[c]) / (2.0 * h);
                assert!(close(r.du[c], fu, 1e-6) && close(r.dv[c], fv, 1e-6));
            }
        }
    }

    #[test]
    fn rational_quarter_circle() {
        // The standard NURBS quarter circle: weights 1, √2/2, 1 on (1,0), (1,1), (0,1).
        let w = 0.5f64.sqrt();
        let pts = vec![1.0, 0.0, 0.0, 1.0, w, w, 0.0, w, 0.0, 1.0, 0.0, 1.0];
        let c = BSplineCurve::try_new(4, 3, KnotVector::new(vec![0., 0., 0., 1., 1., 1.]), pts).unwrap();
        let h = 1e-6;
        for i in 0..=10 {
            let u = i as f64 / 10.0;
            let (p, d) = c.rational_with_derivative(u).unwrap();
            assert!(close(p[0].hypot(p[1]), 1.0, 1e-14), "on the circle at {u}");
            assert!((p[0] * d[0] + p[1] * d[1]).abs() < 1e-12, "tangent ⟂ radius");
            if (0.0..1.0).contains(&(u - h)) && u + h <= 1.0 {
                let fd = (c.eval_rational(u + h).unwrap()[1] - c.eval_rational(u - h).unwrap()[1]) / (2.0 * h);
                assert!(close(d[1], fd, 1e-6));
            }
        }
        let flat = BSplineCurve::try_new(2, 2, KnotVector::new(vec![0., 0., 1., 1.]), vec![0.0; 4]).unwrap();
        assert_eq!(flat.eval_rational(0.5), Err(MathError::BadDimension(2)));
    }

    #[test]
    fn try_new_rejects_bad_input() {
        let k = |v: &[f64]| KnotVector::new(v.to_vec());
        let uni = k(&[0., 0., 1., 1.]);
        assert_eq!(BSplineCurve::try_new(0, 2, uni.clone(), vec![]), Err(MathError::BadDimension(0)));
        assert_eq!(BSplineCurve::try_new(2, 31, uni.clone(), vec![0.0; 4]), Err(MathError::BadOrder(31)));
        assert_eq!(BSplineCurve::try_new(2, 0, uni.clone(), vec![0.0; 4]), Err(MathError::BadOrder(0)));
        assert_eq!(
            BSplineCurve::try_new(2, 2, uni.clone(), vec![0.0; 5]),
            Err(MathError::PointCount { len: 5, dim: 2 })
        );
        assert_eq!(BSplineCurve::try_new(1, 2, k(&[0., 0., 1.]), vec![0.0]), Err(MathError::Knots("too few knots")));
        assert_eq!(
            BSplineCurve::try_new(1, 2, k(&[0., 0., 1., f64::INFINITY]), vec![0.0; 2]),
            Err(MathError::Knots("knots must be finite"))
        );
        let s = BSplineSurface::try_new(3, 2, 2, uni.clone(), uni, vec![0.0; 11]);
        assert_eq!(s, Err(MathError::PointCount { len: 11, dim: 6 }));
        assert!(basis_funs(&UNI, 3, 1, 1.5).is_none() && basis_funs(&UNI, 3, 4, 4.5).is_none());
    }

    fn sorted_knots(order: usize, extra: usize) -> impl Strategy<Value = Vec<f64>> {
        prop::collection::vec(0.0f64..4.0, 2 * order + extra).prop_map(|mut k| {
            k.sort_by(f64::total_cmp);
            k
        })
    }

    proptest! {
        #[test]
        fn partition_of_unity_and_basis_matches_recursion(
            (order, knots) in (1usize..6, 0usize..5).prop_flat_map(|(o, e)| (Just(o), sorted_knots(o, e))),
            t in 0.0f64..=1.0,
        ) {
            let n = knots.len() - order;
            let (lo, hi) = (knots[order - 1], knots[n]);
            prop_assume!(hi - lo > 1e-3);
            let u = lo + (hi - lo) * t;
            let span = find_span(&knots, order, u).unwrap();
            let (b, d) = basis_with_derivative(&knots, order, span, u).unwrap();
            prop_assert!((b[..order].iter().sum::<f64>() - 1.0).abs() < 1e-12);
            prop_assert!(d[..order].iter().sum::<f64>().abs() < 1e-7 * (1.0 + d[..order].iter().map(|x| x.abs()).sum::<f64>()));
            if u < hi {
                for (j, &bj) in b[..order].iter().enumerate() {
                    prop_assert!((bj - cox_de_boor(&knots, span + 1 - order + j, order, u)).abs() < 1e-12);
                }
            }
        }

        #[test]
        fn bezier_knots_give_the_bezier_curve(
            order in 1usize..9, dim in 1usize..=4, t in 0.0f64..=1.0,
            pts in prop::collection::vec(-5.0f64..5.0, 32),
        ) {
            let mut knots = vec![0.0; order];
            knots.resize(2 * order, 1.0);
            let p = &pts[..order * dim];
            let got = curve_point(&knots, p, dim, order, t).unwrap();
            let want = de_casteljau(p, dim, order, t);
            for c in 0..dim {
                prop_assert!((got[c] - want[c]).abs() < 1e-12);
            }
            let k = KnotVector::new(knots);
            let s = BSplineSurface::try_new(1, order, 2, k, KnotVector::new(vec![0.0, 0.0, 1.0, 1.0]), pts[..2 * order].to_vec()).unwrap();
            let sp = s.eval(t, 1.0 - t).unwrap()[0];
            prop_assert!((sp - horner_patch(&pts[..2 * order], 1, order, 2, t, 1.0 - t)[0]).abs() < 1e-12);
        }

        #[test]
        fn curve_derivative_is_central_difference(
            (order, knots) in (2usize..6, 0usize..4).prop_flat_map(|(o, e)| (Just(o), sorted_knots(o, e))),
            t in 0.05f64..0.95,
            pts in prop::collection::vec(-5.0f64..5.0, 40),
        ) {
            let n = knots.len() - order;
            let (lo, hi) = (knots[order - 1], knots[n]);
            // Keep clear of knots, where the derivative of a low-order spline may jump.
            let u = lo + (hi - lo) * t;
            prop_assume!(knots.iter().all(|k| (k - u).abs() > 1e-3));
            let pts = &pts[..n * 3];
            let h = 1e-7;
            let d = curve_derivative(&knots, pts, 3, order, u).unwrap();
            let p1 = curve_point(&knots, pts, 3, order, u + h).unwrap();
            let p0 = curve_point(&knots, pts, 3, order, u - h).unwrap();
            for c in 0..3 {
                let fd = (p1[c] - p0[c]) / (2.0 * h);
                prop_assert!((d[c] - fd).abs() < 1e-3 * (1.0 + d[c].abs()), "{} vs {}", d[c], fd);
            }
        }
    }
}
