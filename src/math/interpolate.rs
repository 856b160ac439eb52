//! Global B-spline interpolation through given points (The NURBS Book §9.2.1, A9.1): the
//! parameters of the points by one of three rules, knots by averaging (eq. 9.8), and the
//! control points from the linear system N·P = Q.

use super::bspline::{basis_funs, BSplineCurve};
use super::knots::{find_span, KnotVector};
use super::{MathError, Scalar};

/// How the points' parameters ū₀ = 0 < ū₁ < … < ūₙ = 1 are chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parameterization {
    /// Equally spaced, k/n.
    Uniform,
    /// Proportional to the chord lengths |Qₖ − Qₖ₋₁| (eq. 9.5).
    ChordLength,
    /// Proportional to the square roots of the chord lengths (eq. 9.6; Lee's centripetal).
    Centripetal,
}

/// The parameters of `points` (`dim` values each) under `method`.
pub fn parameters<S: Scalar>(points: &[S], dim: usize, method: Parameterization) -> Result<Vec<S>, MathError> {
    if dim == 0 || points.len() % dim != 0 || points.len() < 2 * dim {
        return Err(MathError::BadData("interpolation needs at least two whole points"));
    }
    let n = points.len() / dim - 1;
    let gaps: Vec<S> = points
        .chunks_exact(dim)
        .zip(points.chunks_exact(dim).skip(1))
        .map(|(a, b)| {
            let d = a.iter().zip(b).fold(S::ZERO, |s, (&x, &y)| s + (y - x) * (y - x)).sqrt();
            match method {
                Parameterization::Uniform => S::ONE,
                Parameterization::ChordLength => d,
                Parameterization::Centripetal => d.sqrt(),
            }
        })
        .collect();
    let total = gaps.iter().fold(S::ZERO, |s, &g| s + g);
    if !(total > S::ZERO && total.is_finite()) || gaps.contains(&S::ZERO) {
        return Err(MathError::BadData("interpolation points must be finite and distinct in sequence"));
    }
    let mut params = Vec::with_capacity(n + 1);
    let mut acc = S::ZERO;
    params.push(S::ZERO);
    for &g in &gaps[..n - 1] {
        acc += g;
        params.push(acc / total);
    }
    params.push(S::ONE);
    Ok(params)
}

/// The curve of `degree` through `points` (`dim` values each; at least degree + 1 points), and
/// the parameter at which it passes through each point.
///
/// ```
/// use gleval::math::{interpolate, Parameterization};
/// let pts = [0.0, 0.0, 1.0, 2.0, 3.0, 2.0, 4.0, 0.0, 6.0, 1.0];
/// let (curve, params) = interpolate(&pts, 2, 3, Parameterization::Centripetal).unwrap();
/// let p = curve.eval(params[2]).unwrap();
/// assert!((p[0] - 3.0f64).abs() < 1e-12 && (p[1] - 2.0f64).abs() < 1e-12);
/// ```
pub fn interpolate<S: Scalar>(
    points: &[S],
    dim: usize,
    degree: usize,
    method: Parameterization,
) -> Result<(BSplineCurve<S>, Vec<S>), MathError> {
    let params = parameters(points, dim, method)?;
    let count = params.len();
    if degree == 0 || degree >= count {
        return Err(MathError::BadOrder(degree + 1));
    }
    let order = degree + 1;
    // Knots by averaging (eq. 9.8): clamped ends, interior knots the mean of `degree` parameters.
    let mut knots = vec![S::ZERO; order];
    for j in 1..count - degree {
        let sum = params[j..j + degree].iter().fold(S::ZERO, |s, &u| s + u);
        knots.push(sum / S::from_usize(degree));
    }
    knots.extend(std::iter::repeat_n(S::ONE, order));
    // N·P = Q, row k: the basis functions at ū_k.
    let mut matrix = vec![S::ZERO; count * count];
    for (k, &u) in params.iter().enumerate() {
        let span = find_span(&knots, order, u).ok_or(MathError::OutOfRange)?;
        let basis = basis_funs(&knots, order, span, u).ok_or(MathError::OutOfRange)?;
        for (i, &b) in basis[..order].iter().enumerate() {
            matrix[k * count + span - degree + i] = b;
        }
    }
    let control = solve(&mut matrix, points, count, dim)?;
    let curve = BSplineCurve::try_new(dim, order, KnotVector::new(knots), control)?;
    Ok((curve, params))
}

/// Solves A·X = B for X (`n` × `n` matrix, `dim` right-hand columns) by Gaussian elimination
/// with partial pivoting.
fn solve<S: Scalar>(a: &mut [S], b: &[S], n: usize, dim: usize) -> Result<Vec<S>, MathError> {
    let mut x = b.to_vec();
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&r, &s| a[r * n + col].abs().to_f64().total_cmp(&a[s * n + col].abs().to_f64()))
            .unwrap_or(col);
        if a[pivot * n + col] == S::ZERO {
            return Err(MathError::BadData("the interpolation system is singular"));
        }
        for c in 0..n {
            a.swap(col * n + c, pivot * n + c);
        }
        for c in 0..dim {
            x.swap(col * dim + c, pivot * dim + c);
        }
        for r in col + 1..n {
            let f = a[r * n + col] / a[col * n + col];
            if f == S::ZERO {
                continue;
            }
            for c in col..n {
                let d = f * a[col * n + c];
                a[r * n + c] -= d;
            }
            for c in 0..dim {
                let d = f * x[col * dim + c];
                x[r * dim + c] -= d;
            }
        }
    }
    for row in (0..n).rev() {
        for c in 0..dim {
            let mut v = x[row * dim + c];
            for k in row + 1..n {
                v -= a[row * n + k] * x[k * dim + c];
            }
            x[row * dim + c] = v / a[row * n + row];
        }
    }
    Ok(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    const POINTS: [f64; 14] = [0.0, 0.0, 1.0, 3.0, 2.0, 3.5, 5.0, 1.0, 6.0, -2.0, 8.0, 0.0, 8.5, 2.0];

    #[test]
    fn the_curve_passes_through_every_point_for_every_rule_and_degree() {
        for method in [Parameterization::Uniform, Parameterization::ChordLength, Parameterization::Centripetal] {
            for degree in 1..=5 {
                let (curve, params) = interpolate(&POINTS, 2, degree, method).unwrap();
                for (k, &u) in params.iter().enumerate() {
                    let p = curve.eval(u).unwrap();
                    assert!(
                        (p[0] - POINTS[2 * k]).abs() < 1e-10 && (p[1] - POINTS[2 * k + 1]).abs() < 1e-10,
                        "{method:?} {degree} {k}"
                    );
                }
            }
        }
    }

    #[test]
    fn parameters_follow_their_rules() {
        // Chords 5, 5 and 10 (3-4-5 triangles): chord length gives 0, 1/4, 1/2, 1; centripetal
        // √5, √5, √10 over their sum; uniform thirds.
        let pts = [0.0, 0.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0];
        let close = |a: &[f64], b: &[f64]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12);
        assert!(close(&parameters(&pts, 2, Parameterization::ChordLength).unwrap(), &[0.0, 0.25, 0.5, 1.0]));
        assert!(close(&parameters(&pts, 2, Parameterization::Uniform).unwrap(), &[0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]));
        let t = 2.0 * 5f64.sqrt() + 10f64.sqrt();
        let want = [0.0, 5f64.sqrt() / t, 2.0 * 5f64.sqrt() / t, 1.0];
        assert!(close(&parameters(&pts, 2, Parameterization::Centripetal).unwrap(), &want));
    }

    #[test]
    fn degree_one_interpolation_is_the_polyline() {
        let (curve, params) = interpolate(&POINTS, 2, 1, Parameterization::ChordLength).unwrap();
        assert!(curve.points.iter().zip(POINTS).all(|(a, b)| (a - b).abs() < 1e-12));
        let mid = 0.5 * (params[1] + params[2]);
        let p = curve.eval(mid).unwrap();
        assert!((p[0] - 1.5).abs() < 1e-12 && (p[1] - 3.25).abs() < 1e-12);
    }

    #[test]
    fn bad_input_is_refused() {
        assert!(interpolate(&[0.0, 0.0], 2, 1, Parameterization::Uniform).is_err());
        assert!(interpolate(&POINTS, 2, 7, Parameterization::Uniform).is_err());
        assert!(interpolate(&POINTS, 2, 0, Parameterization::Uniform).is_err());
        assert!(interpolate(&[0.0, 0.0, 0.0, 0.0, 1.0, 1.0], 2, 1, Parameterization::ChordLength).is_err());
        assert!(interpolate(&[0.0, 0.0, f64::NAN, 0.0], 2, 1, Parameterization::ChordLength).is_err());
    }
}
