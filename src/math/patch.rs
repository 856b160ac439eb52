//! Tensor-product Bezier patches (GL 1.1 spec §5.1, `glMap2`): p(u,v) = Σᵢ Σⱼ Bᵢⁿ(u) Bⱼᵐ(v) Rᵢⱼ,
//! with i indexing u. Control points are packed u-major, `dim` components each:
//! Rᵢⱼ starts at `(i * vorder + j) * dim`, exactly the layout Mesa keeps after `glMap2`.

use super::bezier::{bernstein, horner, Vec4, MAX_DIM};
use super::scalar::Scalar;
use super::MathError;

/// Largest order any evaluator accepts (Mesa's `MAX_EVAL_ORDER`).
pub const MAX_ORDER: usize = 30;

/// A point of a patch with its partial derivatives with respect to the normalised parameters.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PatchSample<S: Scalar> {
    /// p(u, v).
    pub point: Vec4<S>,
    /// ∂p/∂u (zero when uorder is 1).
    pub du: Vec4<S>,
    /// ∂p/∂v (zero when vorder is 1).
    pub dv: Vec4<S>,
}

fn fits(len: usize, dim: usize, uorder: usize, vorder: usize) -> bool {
    uorder >= 1 && vorder >= 1 && dim <= MAX_DIM && len >= uorder * vorder * dim
}

/// Evaluates a patch by nested Horner, as Mesa's `_math_horner_bezier_surf` does: the rows
/// along the longer direction are reduced first. Too-short input gives the zero vector.
#[must_use]
pub fn horner_patch<S: Scalar>(points: &[S], dim: usize, uorder: usize, vorder: usize, u: S, v: S) -> Vec4<S> {
    if !fits(points.len(), dim, uorder, vorder) {
        return [S::ZERO; MAX_DIM];
    }
    let mut curve = [S::ZERO; MAX_ORDER * MAX_DIM];
    if vorder > uorder.min(MAX_ORDER) {
        // Each v column j: reduce along u, then evaluate the column curve at v.
        let mut column = [S::ZERO; MAX_ORDER * MAX_DIM];
        for j in 0..vorder.min(MAX_ORDER) {
            for i in 0..uorder {
                let src = (i * vorder + j) * dim;
                column[i * dim..(i + 1) * dim].copy_from_slice(&points[src..src + dim]);
            }
            let p = horner(&column, dim, uorder, u);
            curve[j * dim..(j + 1) * dim].copy_from_slice(&p[..dim]);
        }
        horner(&curve, dim, vorder.min(MAX_ORDER), v)
    } else {
        for i in 0..uorder.min(MAX_ORDER) {
            let row = &points[i * vorder * dim..(i + 1) * vorder * dim];
            let p = horner(row, dim, vorder, v);
            curve[i * dim..(i + 1) * dim].copy_from_slice(&p[..dim]);
        }
        horner(&curve, dim, uorder.min(MAX_ORDER), u)
    }
}

/// The point and both partial derivatives (with respect to the normalised u and v). This is the
/// quantity Mesa's `_math_de_casteljau_surf` computes for `GL_AUTO_NORMAL`, up to the positive
/// factors (uorder−1) and (vorder−1). Derivatives are taken on differences of control points
/// (the hodograph), so an edge whose control points coincide has an exactly zero derivative,
/// as in Mesa, instead of rounding noise that would normalise to a random direction.
#[must_use]
pub fn patch_with_partials<S: Scalar>(
    points: &[S],
    dim: usize,
    uorder: usize,
    vorder: usize,
    u: S,
    v: S,
) -> PatchSample<S> {
    let mut out = PatchSample::default();
    if !fits(points.len(), dim, uorder, vorder) || uorder > MAX_ORDER || vorder > MAX_ORDER {
        return out;
    }
    let (mut bu, mut bu1) = ([S::ZERO; MAX_ORDER], [S::ZERO; MAX_ORDER]);
    let (mut bv, mut bv1) = ([S::ZERO; MAX_ORDER], [S::ZERO; MAX_ORDER]);
    bernstein(uorder, u, &mut bu);
    bernstein(uorder - 1, u, &mut bu1);
    bernstein(vorder, v, &mut bv);
    bernstein(vorder - 1, v, &mut bv1);
    let (nu, nv) = (S::from_usize(uorder - 1), S::from_usize(vorder - 1));
    let mut rows = [[S::ZERO; MAX_DIM]; MAX_ORDER];
    for (i, row) in rows.iter_mut().enumerate().take(uorder) {
        let net = &points[i * vorder * dim..(i + 1) * vorder * dim];
        let mut row_dv = [S::ZERO; MAX_DIM];
        for j in 0..vorder {
            for c in 0..dim {
                row[c] += bv[j] * net[j * dim + c];
                if j + 1 < vorder {
                    row_dv[c] += bv1[j] * (net[(j + 1) * dim + c] - net[j * dim + c]);
                }
            }
        }
        for c in 0..dim {
            out.point[c] += bu[i] * row[c];
            out.dv[c] += bu[i] * nv * row_dv[c];
        }
    }
    for i in 0..uorder - 1 {
        for c in 0..dim {
            out.du[c] += bu1[i] * nu * (rows[i + 1][c] - rows[i][c]);
        }
    }
    out
}

/// A tensor-product Bezier patch, packed u-major as after `glMap2`.
///
/// ```
/// use gleval::math::BezierPatch;
/// // A bilinear patch is the bilinear blend of its corners.
/// let p = BezierPatch::try_new(3, 2, 2, vec![0.,0.,0., 0.,1.,0., 1.,0.,0., 1.,1.,1.]).unwrap();
/// assert_eq!(p.eval(0.5, 0.5), [0.5, 0.5, 0.25, 0.0]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatch<S: Scalar> {
    /// Components per control point, 1..=4.
    pub dim: usize,
    /// Control points along u.
    pub uorder: usize,
    /// Control points along v.
    pub vorder: usize,
    /// `uorder * vorder * dim` values, point (i, j) at `(i * vorder + j) * dim`.
    pub points: Vec<S>,
}

impl<S: Scalar> BezierPatch<S> {
    /// Checks dimension, orders (1..=30) and the number of values.
    pub fn try_new(dim: usize, uorder: usize, vorder: usize, points: Vec<S>) -> Result<Self, MathError> {
        if dim == 0 || dim > MAX_DIM {
            return Err(MathError::BadDimension(dim));
        }
        for order in [uorder, vorder] {
            if order == 0 || order > MAX_ORDER {
                return Err(MathError::BadOrder(order));
            }
        }
        if points.len() != uorder * vorder * dim {
            return Err(MathError::PointCount { len: points.len(), dim });
        }
        Ok(Self { dim, uorder, vorder, points })
    }

    /// The point at normalised (u, v).
    #[must_use]
    pub fn eval(&self, u: S, v: S) -> Vec4<S> {
        horner_patch(&self.points, self.dim, self.uorder, self.vorder, u, v)
    }

    /// Point and partial derivatives at normalised (u, v).
    #[must_use]
    pub fn eval_with_partials(&self, u: S, v: S) -> PatchSample<S> {
        patch_with_partials(&self.points, self.dim, self.uorder, self.vorder, u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::bezier::de_casteljau;

    /// An irregular 3x5 net in 4D.
    fn net() -> Vec<f64> {
        (0..3 * 5 * 4).map(|k| ((k * 37 % 11) as f64) * 0.3 - 1.0).collect()
    }

    /// Oracle: de Casteljau along v for each row, then along u.
    fn oracle(points: &[f64], dim: usize, uo: usize, vo: usize, u: f64, v: f64) -> Vec4<f64> {
        let mut curve = Vec::new();
        for i in 0..uo {
            let p = de_casteljau(&points[i * vo * dim..], dim, vo, v);
            curve.extend_from_slice(&p[..dim]);
        }
        de_casteljau(&curve, dim, uo, u)
    }

    #[test]
    fn horner_patch_equals_de_casteljau_both_branches() {
        let pts = net();
        for (uo, vo) in [(3, 5), (5, 3)] {
            for (u, v) in [(0.0, 0.0), (0.3, 0.8), (1.0, 1.0), (1.4, -0.2)] {
                let a = horner_patch(&pts, 4, uo, vo, u, v);
                let b = oracle(&pts, 4, uo, vo, u, v);
                for c in 0..4 {
                    assert!((a[c] - b[c]).abs() < 1e-12, "{uo}x{vo} at ({u},{v})");
                }
            }
        }
    }

    #[test]
    fn partials_match_finite_differences() {
        let pts = net();
        let h = 1e-6;
        for (u, v) in [(0.2, 0.7), (0.5, 0.5), (0.9, 0.1)] {
            let s = patch_with_partials(&pts, 4, 3, 5, u, v);
            let fu = |du: f64| oracle(&pts, 4, 3, 5, u + du, v);
            let fv = |dv: f64| oracle(&pts, 4, 3, 5, u, v + dv);
            for c in 0..4 {
                let du = (fu(h)[c] - fu(-h)[c]) / (2.0 * h);
                let dv = (fv(h)[c] - fv(-h)[c]) / (2.0 * h);
                assert!((s.du[c] - du).abs() < 1e-6 && (s.dv[c] - dv).abs() < 1e-6);
                assert!((s.point[c] - fu(0.0)[c]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn collapsed_edge_has_exactly_zero_derivative() {
        // Row i = 0 collapsed to one point: dv at u = 0 must be exactly 0 (Mesa's differences).
        let mut pts = net();
        for j in 1..5 {
            for c in 0..4 {
                pts[j * 4 + c] = pts[c];
            }
        }
        let s = patch_with_partials(&pts, 4, 3, 5, 0.0, 0.37);
        assert_eq!(s.dv, [0.0; 4]);
    }

    #[test]
    fn order_one_direction_has_zero_derivative() {
        let pts = [1.0f64, 2.0, 3.0, 4.0, 5.0, 6.0];
        let s = patch_with_partials(&pts, 3, 1, 2, 0.3, 0.6);
        assert_eq!(s.du, [0.0; 4]);
        assert_eq!(s.dv, [3.0, 3.0, 3.0, 0.0]);
    }
}
