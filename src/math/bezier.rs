//! Bezier curves of any order in 1..=4 dimensions: Bernstein basis, Horner and de Casteljau
//! evaluation, derivatives (hodograph), subdivision and degree elevation.
//!
//! Control points are stored flat, `dim` components per point, the layout GL uses after `glMap1`
//! has packed them (GL 1.1 spec §5.1). The parameter `t` is the *normalised* one, t ∈ [0, 1];
//! values outside extrapolate the polynomial, as GL does.

use super::scalar::Scalar;
use super::MathError;

/// Largest number of components a control point has (GL's `GL_MAP*_VERTEX_4`, `COLOR_4`).
pub const MAX_DIM: usize = 4;

/// A point or vector of up to four components; unused trailing components are zero.
pub type Vec4<S> = [S; MAX_DIM];

/// Evaluates a Bezier curve by Horner's rule on the Bernstein form, the way Mesa does
/// (`m_eval.c` `_math_horner_bezier_curve`): Σ C(n,i) tⁱ (1−t)ⁿ⁻ⁱ Pᵢ with a running binomial
/// coefficient and a running power of t. `order` = n + 1 points of `dim` components.
///
/// An order of 0 or a slice too short for `order * dim` gives the zero vector.
#[must_use]
#[inline]
pub fn horner<S: Scalar>(points: &[S], dim: usize, order: usize, t: S) -> Vec4<S> {
    if order == 0 || points.len() < order * dim {
        return [S::ZERO; MAX_DIM];
    }
    // One loop per dimension, so that the component loops unroll.
    match dim {
        1 => horner_dim::<S, 1>(points, order, t),
        2 => horner_dim::<S, 2>(points, order, t),
        3 => horner_dim::<S, 3>(points, order, t),
        4 => horner_dim::<S, 4>(points, order, t),
        _ => [S::ZERO; MAX_DIM],
    }
}

/// [`horner`] for `D` components, `points` holding at least `order · D` values. The binomial
/// coefficient advances as Mesa's `_math_horner_bezier_curve` advances it, C(n, i) =
/// C(n, i−1) · (n − i + 1) · (1/i) with 1/i from a table, so that the values agree with Mesa's
/// bit for bit and no division is left in the loop.
///
/// All four lanes are computed (a point's components past `D` read as zero) and the unused
/// ones set to zero at the end: the result is built whole rather than component by component,
/// which the caller would read back through memory at a store-forwarding stall (measured:
/// a quarter of a `glEvalCoord1f`).
#[inline]
fn horner_dim<S: Scalar, const D: usize>(points: &[S], order: usize, t: S) -> Vec4<S> {
    let point = |i: usize| -> Vec4<S> { std::array::from_fn(|c| if c < D { points[i * D + c] } else { S::ZERO }) };
    if order == 1 {
        return point(0);
    }
    let s = S::ONE - t;
    let n = order - 1;
    let mut binom = S::from_usize(n);
    let mut power = t;
    let (p0, p1) = (point(0), point(1));
    let mut out: Vec4<S> = std::array::from_fn(|c| s * p0[c] + binom * power * p1[c]);
    // n − i + 1 as a float counting down from n − 1 (small integers: exact).
    let mut factor = binom;
    for i in 2..order {
        factor -= S::ONE;
        binom = binom * factor * reciprocal::<S>(i);
        power *= t;
        let p = point(i);
        out = std::array::from_fn(|c| s * out[c] + binom * power * p[c]);
    }
    std::array::from_fn(|c| if c < D { out[c] } else { S::ZERO })
}

/// [`horner`] at every parameter of `ts` into `out` (one value per parameter, `out` at least as
/// long as `ts`): the same operations on each point as [`horner`], so the same bits, run over
/// blocks of parameters side by side so that they vectorise. The binomial coefficients,
/// the same for every point, are worked out once. What `glEvalMesh1` evaluates (the GL spec
/// defines it as the `glEvalCoord1` loop, and Mesa runs that loop).
pub fn horner_many<S: Scalar>(points: &[S], dim: usize, order: usize, ts: &[S], out: &mut [Vec4<S>]) {
    let out = &mut out[..ts.len()];
    if order == 0 || points.len() < order * dim || !(1..=MAX_DIM).contains(&dim) {
        out.fill([S::ZERO; MAX_DIM]);
        return;
    }
    match dim {
        1 => horner_many_dim::<S, 1>(points, order, ts, out),
        2 => horner_many_dim::<S, 2>(points, order, ts, out),
        3 => horner_many_dim::<S, 3>(points, order, ts, out),
        _ => horner_many_dim::<S, 4>(points, order, ts, out),
    }
}

/// [`horner_many`] for `D` components.
fn horner_many_dim<S: Scalar, const D: usize>(points: &[S], order: usize, ts: &[S], out: &mut [Vec4<S>]) {
    const W: usize = 8;
    if order == 1 {
        let mut p = [S::ZERO; MAX_DIM];
        p[..D].copy_from_slice(&points[..D]);
        out.fill(p);
        return;
    }
    // The running coefficient of `horner_dim`, step by step: C(n, 1), then C(n, i).
    let n = order - 1;
    let mut binoms = Vec::with_capacity(order);
    let mut binom = S::from_usize(n);
    binoms.extend([S::ZERO, binom]);
    for i in 2..order {
        binom = binom * S::from_usize(n - i + 1) * reciprocal::<S>(i);
        binoms.push(binom);
    }
    let point = |i: usize| -> [S; D] { std::array::from_fn(|c| points[i * D + c]) };
    for (block_ts, block_out) in ts.chunks(W).zip(out.chunks_mut(W)) {
        let m = block_ts.len();
        let mut t = [S::ZERO; W];
        t[..m].copy_from_slice(block_ts);
        let s: [S; W] = std::array::from_fn(|k| S::ONE - t[k]);
        let mut power = t;
        let (p0, p1) = (point(0), point(1));
        let mut acc: [[S; W]; D] =
            std::array::from_fn(|c| std::array::from_fn(|k| s[k] * p0[c] + binoms[1] * power[k] * p1[c]));
        for (i, &b) in binoms.iter().enumerate().skip(2) {
            let p = point(i);
            for k in 0..W {
                power[k] *= t[k];
            }
            for c in 0..D {
                for k in 0..W {
                    acc[c][k] = s[k] * acc[c][k] + b * power[k] * p[c];
                }
            }
        }
        for (k, o) in block_out.iter_mut().enumerate() {
            *o = [S::ZERO; MAX_DIM];
            for c in 0..D {
                o[c] = acc[c][k];
            }
        }
    }
}

/// 1/i rounded to `S` (Mesa's `inv_tab`), from a table for the orders GL allows.
#[inline]
fn reciprocal<S: Scalar>(i: usize) -> S {
    match S::RECIPROCALS.get(i) {
        Some(&r) => r,
        None => S::ONE / S::from_usize(i),
    }
}

/// Evaluates a Bezier curve by de Casteljau's algorithm (repeated linear interpolation):
/// numerically the most stable form, used as the oracle for [`horner`].
#[must_use]
pub fn de_casteljau<S: Scalar>(points: &[S], dim: usize, order: usize, t: S) -> Vec4<S> {
    let mut out = [S::ZERO; MAX_DIM];
    if order == 0 || dim > MAX_DIM || points.len() < order * dim {
        return out;
    }
    let mut work: Vec<S> = points[..order * dim].to_vec();
    for level in 1..order {
        for i in 0..order - level {
            for c in 0..dim {
                let a = work[i * dim + c];
                let b = work[(i + 1) * dim + c];
                work[i * dim + c] = a + (b - a) * t;
            }
        }
    }
    out[..dim].copy_from_slice(&work[..dim]);
    out
}

/// The first derivative d/dt of the curve at the normalised parameter `t`:
/// n · Σ Bᵢⁿ⁻¹(t) (Pᵢ₊₁ − Pᵢ). An order-1 (constant) curve has derivative zero.
#[must_use]
pub fn derivative<S: Scalar>(points: &[S], dim: usize, order: usize, t: S) -> Vec4<S> {
    if order < 2 || dim > MAX_DIM || points.len() < order * dim {
        return [S::ZERO; MAX_DIM];
    }
    let hodo = hodograph(&points[..order * dim], dim, order);
    horner(&hodo, dim, order - 1, t)
}

/// The control points of the hodograph (derivative curve, seed 001 "derivatives"):
/// Qᵢ = n (Pᵢ₊₁ − Pᵢ), i = 0..n−1, one order lower.
#[must_use]
pub fn hodograph<S: Scalar>(points: &[S], dim: usize, order: usize) -> Vec<S> {
    if order < 2 {
        return Vec::new();
    }
    let n = S::from_usize(order - 1);
    (0..(order - 1) * dim).map(|idx| n * (points[idx + dim] - points[idx])).collect()
}

/// The Bernstein basis values Bᵢⁿ(t), i = 0..order−1, written into `out[..order]`,
/// computed by the de Casteljau triangle (stable for all t).
pub fn bernstein<S: Scalar>(order: usize, t: S, out: &mut [S]) {
    if order == 0 {
        return;
    }
    let s = S::ONE - t;
    out[0] = S::ONE;
    for level in 1..order {
        // Raise degree level-1 -> level in place, from the top down.
        let mut saved = S::ZERO;
        for i in 0..level {
            let b = out[i];
            out[i] = saved + s * b;
            saved = t * b;
        }
        out[level] = saved;
    }
}

/// The Bernstein basis values and their derivatives d/dt, each written into `b[..order]`
/// and `db[..order]`: dBᵢⁿ/dt = n (Bᵢ₋₁ⁿ⁻¹ − Bᵢⁿ⁻¹).
pub fn bernstein_with_derivative<S: Scalar>(order: usize, t: S, b: &mut [S], db: &mut [S]) {
    if order == 0 {
        return;
    }
    if order == 1 {
        b[0] = S::ONE;
        db[0] = S::ZERO;
        return;
    }
    // db temporarily holds the degree n-1 basis.
    bernstein(order - 1, t, db);
    let n = S::from_usize(order - 1);
    let mut prev = S::ZERO;
    for i in 0..order {
        let lower = if i < order - 1 { db[i] } else { S::ZERO };
        db[i] = n * (prev - lower);
        prev = lower;
    }
    bernstein(order, t, b);
}

/// Splits a curve at `t` (de Casteljau subdivision): the left piece maps [0, t] and the right
/// piece [t, 1], each with `order` points.
#[must_use]
pub fn split<S: Scalar>(points: &[S], dim: usize, order: usize, t: S) -> (Vec<S>, Vec<S>) {
    let mut work: Vec<S> = points[..order * dim].to_vec();
    let mut left = Vec::with_capacity(order * dim);
    let mut right = vec![S::ZERO; order * dim];
    for level in 0..order {
        left.extend_from_slice(&work[..dim]);
        let last = order - 1 - level;
        right[last * dim..(last + 1) * dim].copy_from_slice(&work[last * dim..(last + 1) * dim]);
        for i in 0..last {
            for c in 0..dim {
                let a = work[i * dim + c];
                let b = work[(i + 1) * dim + c];
                work[i * dim + c] = a + (b - a) * t;
            }
        }
    }
    (left, right)
}

/// Raises the degree by one without changing the curve (seed 000 "degree elevation"):
/// Qᵢ = i/(n+1) Pᵢ₋₁ + (1 − i/(n+1)) Pᵢ, i = 0..=n+1.
#[must_use]
pub fn elevate<S: Scalar>(points: &[S], dim: usize, order: usize) -> Vec<S> {
    let n1 = S::from_usize(order);
    let mut out = Vec::with_capacity((order + 1) * dim);
    for i in 0..=order {
        let a = S::from_usize(i) / n1;
        for c in 0..dim {
            let prev = if i > 0 { points[(i - 1) * dim + c] } else { S::ZERO };
            let cur = if i < order { points[i * dim + c] } else { S::ZERO };
            out.push(a * prev + (S::ONE - a) * cur);
        }
    }
    out
}

/// A Bezier curve: `order` control points of `dim` components, stored flat.
///
/// ```
/// use gleval::math::BezierCurve;
/// // Seed 004, 9.7.1: the cubic through (0,0),(1,1),(2,-1),(3,0).
/// let c = BezierCurve::<f64>::try_new(2, vec![0.0, 0.0, 1.0, 1.0, 2.0, -1.0, 3.0, 0.0]).unwrap();
/// let p = c.eval(1.0 / 3.0);
/// assert!((p[0] - 1.0).abs() < 1e-12 && (p[1] - 2.0 / 9.0).abs() < 1e-12);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierCurve<S: Scalar> {
    /// Components per control point, 1..=4.
    pub dim: usize,
    /// `order * dim` values.
    pub points: Vec<S>,
}

impl<S: Scalar> BezierCurve<S> {
    /// Checks the dimension and that the points fill whole control points.
    ///
    /// ```
    /// use gleval::math::{BezierCurve, MathError};
    /// assert_eq!(BezierCurve::<f64>::try_new(5, vec![0.0; 10]), Err(MathError::BadDimension(5)));
    /// ```
    pub fn try_new(dim: usize, points: Vec<S>) -> Result<Self, MathError> {
        if dim == 0 || dim > MAX_DIM {
            return Err(MathError::BadDimension(dim));
        }
        if points.is_empty() || points.len() % dim != 0 {
            return Err(MathError::PointCount { len: points.len(), dim });
        }
        Ok(Self { dim, points })
    }

    /// Number of control points (degree + 1).
    #[must_use]
    pub fn order(&self) -> usize {
        self.points.len() / self.dim
    }

    /// The point at normalised parameter `t`.
    #[must_use]
    pub fn eval(&self, t: S) -> Vec4<S> {
        de_casteljau(&self.points, self.dim, self.order(), t)
    }

    /// The first derivative at `t`.
    #[must_use]
    pub fn derivative(&self, t: S) -> Vec4<S> {
        derivative(&self.points, self.dim, self.order(), t)
    }

    /// The derivative curve, one order lower (`None` for a constant curve).
    #[must_use]
    pub fn hodograph(&self) -> Option<Self> {
        (self.order() >= 2).then(|| Self { dim: self.dim, points: hodograph(&self.points, self.dim, self.order()) })
    }

    /// The two halves at `t`.
    #[must_use]
    pub fn split(&self, t: S) -> (Self, Self) {
        let (l, r) = split(&self.points, self.dim, self.order(), t);
        (Self { dim: self.dim, points: l }, Self { dim: self.dim, points: r })
    }

    /// The same curve with one more control point.
    #[must_use]
    pub fn elevate(&self) -> Self {
        Self { dim: self.dim, points: elevate(&self.points, self.dim, self.order()) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cubic() -> Vec<f64> {
        vec![0.0, 0.0, 1.0, 1.0, 2.0, -1.0, 3.0, 0.0]
    }

    /// Many parameters at once give `horner`'s bits at each, zero signs included: every
    /// order to 14, every dimension (and invalid ones), short point slices, block tails, and
    /// parameters outside [0, 1].
    #[test]
    fn horner_many_matches_horner_point_by_point() {
        let ts: Vec<f32> = (0..37).map(|k| -0.4 + k as f32 * 0.05).chain([0.0, 1.0, -0.0, 2.5]).collect();
        for dim in 0..=5 {
            for order in 0..=14 {
                let points: Vec<f32> = (0..order * dim.max(1)).map(|k| ((k * 37 % 23) as f32) * 0.3 - 2.5).collect();
                for len in [0, 1, 7, 8, 9, ts.len()] {
                    for cut in [0, 1] {
                        let p = &points[..points.len().saturating_sub(cut)];
                        let mut out = vec![[f32::NAN; 4]; len + 2];
                        horner_many(p, dim, order, &ts[..len], &mut out);
                        for (k, &t) in ts[..len].iter().enumerate() {
                            let want = horner(p, dim, order, t).map(f32::to_bits);
                            assert_eq!(out[k].map(f32::to_bits), want, "dim {dim} order {order} t {t}");
                        }
                        assert!(out[len].iter().all(|x| x.is_nan()), "wrote past the parameters");
                    }
                }
            }
        }
    }

    #[test]
    fn seed_004_worked_example() {
        // 9.7.1: p(0)=(0,0), p(1/3)=(1,2/9), p(2/3)=(2,-2/9), p(1)=(3,0); p(u) = (3u, 3u(1-u)(1-2u)) by hand.
        for (t, x, y) in [(0.0, 0.0, 0.0), (1.0 / 3.0, 1.0, 2.0 / 9.0), (2.0 / 3.0, 2.0, -2.0 / 9.0), (1.0, 3.0, 0.0)] {
            let p = horner(&cubic(), 2, 4, t);
            assert!((p[0] - x).abs() < 1e-12 && (p[1] - y).abs() < 1e-12, "{t}: {p:?}");
        }
    }

    #[test]
    fn derivative_matches_closed_form() {
        // p(u) = (3u, 3u - 9u² + 6u³) -> p'(u) = (3, 3 - 18u + 18u²)
        for t in [0.0, 0.2, 0.5, 0.9, 1.3] {
            let d = derivative(&cubic(), 2, 4, t);
            assert!((d[0] - 3.0).abs() < 1e-12);
            assert!((d[1] - (3.0 - 18.0 * t + 18.0 * t * t)).abs() < 1e-12);
        }
    }

    #[test]
    fn bernstein_partition_of_unity_and_derivative() {
        let mut b = [0.0f64; 30];
        let mut db = [0.0f64; 30];
        for order in 1..=30 {
            for t in [0.0, 0.25, 0.7, 1.0] {
                bernstein_with_derivative(order, t, &mut b, &mut db);
                let sum: f64 = b[..order].iter().sum();
                let dsum: f64 = db[..order].iter().sum();
                assert!((sum - 1.0).abs() < 1e-12 && dsum.abs() < 1e-9, "order {order}");
            }
        }
        // B_1^3(t) = 3t(1-t)^2, d/dt = 3(1-t)^2 - 6t(1-t)
        bernstein_with_derivative(4, 0.3, &mut b, &mut db);
        assert!((b[1] - 3.0 * 0.3 * 0.49).abs() < 1e-12);
        assert!((db[1] - (3.0 * 0.49 - 6.0 * 0.3 * 0.7)).abs() < 1e-12);
    }

    #[test]
    fn split_halves_reproduce_curve() {
        let (l, r) = split(&cubic(), 2, 4, 0.4);
        for s in [0.0, 0.3, 1.0] {
            let pl = de_casteljau(&l, 2, 4, s);
            let want = de_casteljau(&cubic(), 2, 4, 0.4 * s);
            let pr = de_casteljau(&r, 2, 4, s);
            let want_r = de_casteljau(&cubic(), 2, 4, 0.4 + 0.6 * s);
            for c in 0..2 {
                assert!((pl[c] - want[c]).abs() < 1e-12 && (pr[c] - want_r[c]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn elevation_keeps_curve() {
        let e = elevate(&cubic(), 2, 4);
        for t in [0.0, 0.33, 0.8, 1.0] {
            let a = de_casteljau(&cubic(), 2, 4, t);
            let b = de_casteljau(&e, 2, 5, t);
            assert!((a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
        }
    }

    #[test]
    fn short_input_gives_zero_not_panic() {
        assert_eq!(horner(&[1.0f32, 2.0], 3, 4, 0.5), [0.0; 4]);
        assert_eq!(de_casteljau(&[1.0f32], 1, 0, 0.5), [0.0; 4]);
    }
}
