//! Cubic Hermite curves: a segment fixed by its end points and end tangents (seed 004, 9.3; The
//! NURBS Book §1.4). As a cubic it is also a Bezier curve, with inner control points one third
//! of a tangent away from each end, which is how it is drawn through `glMap1f`.

use super::Scalar;

/// A cubic Hermite segment over u ∈ [0, 1]: p(0) = `p0`, p(1) = `p1`, p'(0) = `t0`,
/// p'(1) = `t1`, in `D` components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HermiteCurve<S: Scalar, const D: usize> {
    /// p(0).
    pub p0: [S; D],
    /// p(1).
    pub p1: [S; D],
    /// p'(0).
    pub t0: [S; D],
    /// p'(1).
    pub t1: [S; D],
}

/// The four Hermite basis functions at u: H₀ = 2u³ − 3u² + 1, H₁ = −2u³ + 3u²,
/// H₂ = u³ − 2u² + u, H₃ = u³ − u² (weights of p0, p1, t0, t1).
#[must_use]
pub fn hermite_basis<S: Scalar>(u: S) -> [S; 4] {
    let (u2, u3) = (u * u, u * u * u);
    let (two, three) = (S::from_f64(2.0), S::from_f64(3.0));
    [two * u3 - three * u2 + S::ONE, three * u2 - two * u3, u3 - two * u2 + u, u3 - u2]
}

impl<S: Scalar, const D: usize> HermiteCurve<S, D> {
    /// The point at u.
    ///
    /// Exercise 5 of seed 004 (9.7.1): from (0, 0) to (5, 6) with tangents (3, 8) and (5, 1),
    /// p(0.5) = (0, 0)/2 + (5, 6)/2 + (3, 8)/8 − (5, 1)/8 = (2.25, 3.875).
    ///
    /// ```
    /// use gleval::math::HermiteCurve;
    /// let c = HermiteCurve { p0: [0.0, 0.0], p1: [5.0, 6.0], t0: [3.0, 8.0], t1: [5.0, 1.0] };
    /// assert_eq!(c.eval(0.5), [2.25, 3.875]);
    /// ```
    #[must_use]
    pub fn eval(&self, u: S) -> [S; D] {
        let h = hermite_basis(u);
        std::array::from_fn(|c| h[0] * self.p0[c] + h[1] * self.p1[c] + h[2] * self.t0[c] + h[3] * self.t1[c])
    }

    /// p'(u).
    #[must_use]
    pub fn derivative(&self, u: S) -> [S; D] {
        let (two, three, six) = (S::from_f64(2.0), S::from_f64(3.0), S::from_f64(6.0));
        let dh = [
            six * u * u - six * u,
            six * u - six * u * u,
            three * u * u - S::from_f64(4.0) * u + S::ONE,
            three * u * u - two * u,
        ];
        std::array::from_fn(|c| dh[0] * self.p0[c] + dh[1] * self.p1[c] + dh[2] * self.t0[c] + dh[3] * self.t1[c])
    }

    /// The same cubic as Bezier control points: p0, p0 + t0/3, p1 − t1/3, p1.
    #[must_use]
    pub fn to_bezier(&self) -> [[S; D]; 4] {
        let third = S::ONE / S::from_f64(3.0);
        [
            self.p0,
            std::array::from_fn(|c| self.p0[c] + self.t0[c] * third),
            std::array::from_fn(|c| self.p1[c] - self.t1[c] * third),
            self.p1,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::bezier::{derivative, horner};

    fn curve() -> HermiteCurve<f64, 3> {
        HermiteCurve { p0: [0.0, 1.0, -1.0], p1: [2.0, -3.0, 0.5], t0: [4.0, 0.0, 1.0], t1: [-1.0, 2.0, 3.0] }
    }

    #[test]
    fn end_conditions_hold() {
        let c = curve();
        assert_eq!(c.eval(0.0), c.p0);
        assert_eq!(c.eval(1.0), c.p1);
        assert_eq!(c.derivative(0.0), c.t0);
        assert_eq!(c.derivative(1.0), c.t1);
    }

    #[test]
    fn bezier_form_is_the_same_cubic() {
        let c = curve();
        let pts: Vec<f64> = c.to_bezier().iter().flatten().copied().collect();
        for k in 0..=10 {
            let u = f64::from(k) / 10.0;
            let (p, d) = (horner(&pts, 3, 4, u), derivative(&pts, 3, 4, u));
            for i in 0..3 {
                assert!((p[i] - c.eval(u)[i]).abs() < 1e-12);
                assert!((d[i] - c.derivative(u)[i]).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn derivative_matches_finite_differences() {
        let c = curve();
        let h = 1e-6;
        for u in [0.1, 0.5, 0.77] {
            let (a, b) = (c.eval(u + h), c.eval(u - h));
            for i in 0..3 {
                assert!(((a[i] - b[i]) / (2.0 * h) - c.derivative(u)[i]).abs() < 1e-6);
            }
        }
    }
}
