//! The interpolating cubic spline y = s(x) with natural end conditions s'' = 0 (seed 004, 9.7.2
//! exercise 5: the bird's back), solved for the second derivatives at the knots by the
//! tridiagonal system of the moment method (Burden & Faires, Algorithm 3.4).

use super::MathError;

/// A natural cubic spline through points (xᵢ, yᵢ) with increasing xᵢ.
#[derive(Clone, Debug, PartialEq)]
pub struct CubicSpline {
    xs: Vec<f64>,
    ys: Vec<f64>,
    /// s''(xᵢ) (the "moments"); zero at both ends.
    moments: Vec<f64>,
}

impl CubicSpline {
    /// The natural spline through `xs`, `ys` (at least two points, finite, xs strictly
    /// increasing).
    ///
    /// ```
    /// use gleval::math::CubicSpline;
    /// // Points on a line: the natural spline is that line.
    /// let s = CubicSpline::natural(&[0.0, 1.0, 3.0], &[1.0, 3.0, 7.0]).unwrap();
    /// assert!((s.eval(2.0) - 5.0).abs() < 1e-12);
    /// ```
    pub fn natural(xs: &[f64], ys: &[f64]) -> Result<Self, MathError> {
        if xs.len() != ys.len() || xs.len() < 2 {
            return Err(MathError::BadData("a spline needs as many y as x values, and at least two"));
        }
        if xs.iter().chain(ys).any(|v| !v.is_finite()) {
            return Err(MathError::BadData("spline data must be finite"));
        }
        if xs.windows(2).any(|w| w[1] <= w[0]) {
            return Err(MathError::BadData("spline x values must increase strictly"));
        }
        let n = xs.len() - 1;
        let h: Vec<f64> = xs.windows(2).map(|w| w[1] - w[0]).collect();
        let slope = |i: usize| (ys[i + 1] - ys[i]) / h[i];
        // Rows i = 1..n−1: h[i−1] M[i−1] + 2 (h[i−1] + h[i]) M[i] + h[i] M[i+1] = 6 (slope_i − slope_{i−1}),
        // with M[0] = M[n] = 0; forward elimination then back substitution (Thomas).
        let mut moments = vec![0.0; n + 1];
        let (mut diag, mut rhs) = (vec![0.0; n + 1], vec![0.0; n + 1]);
        for i in 1..n {
            diag[i] = 2.0 * (h[i - 1] + h[i]);
            rhs[i] = 6.0 * (slope(i) - slope(i - 1));
            if i > 1 {
                let f = h[i - 1] / diag[i - 1];
                diag[i] -= f * h[i - 1];
                rhs[i] -= f * rhs[i - 1];
            }
        }
        for i in (1..n).rev() {
            moments[i] = (rhs[i] - h[i] * moments[i + 1]) / diag[i];
        }
        Ok(Self { xs: xs.to_vec(), ys: ys.to_vec(), moments })
    }

    /// The piece holding x (the end pieces extend beyond the data).
    fn piece(&self, x: f64) -> usize {
        let last = self.xs.len() - 2;
        self.xs[1..].iter().position(|&b| x <= b).unwrap_or(last).min(last)
    }

    /// s(x).
    #[must_use]
    pub fn eval(&self, x: f64) -> f64 {
        let i = self.piece(x);
        let (a, b) = (self.xs[i], self.xs[i + 1]);
        let h = b - a;
        let (m0, m1) = (self.moments[i], self.moments[i + 1]);
        m0 * (b - x).powi(3) / (6.0 * h)
            + m1 * (x - a).powi(3) / (6.0 * h)
            + (self.ys[i] / h - m0 * h / 6.0) * (b - x)
            + (self.ys[i + 1] / h - m1 * h / 6.0) * (x - a)
    }

    /// s'(x).
    #[must_use]
    pub fn derivative(&self, x: f64) -> f64 {
        self.piece_derivative(self.piece(x), x)
    }

    /// s''(x).
    #[must_use]
    pub fn second_derivative(&self, x: f64) -> f64 {
        let i = self.piece(x);
        let (a, b) = (self.xs[i], self.xs[i + 1]);
        (self.moments[i] * (b - x) + self.moments[i + 1] * (x - a)) / (b - a)
    }

    /// Each piece as a planar cubic Bezier curve (x, y): x runs linearly over the piece, so
    /// the inner points sit a third of the way along, at heights y ± h·s'/3. Drawing these
    /// with `glMap1f` draws the spline exactly.
    #[must_use]
    pub fn bezier_pieces(&self) -> Vec<[[f64; 2]; 4]> {
        self.xs
            .windows(2)
            .zip(self.ys.windows(2))
            .map(|(x, y)| {
                let h = x[1] - x[0];
                // One-sided at the shared knots: each piece's own derivative.
                let i = self.piece(0.5 * (x[0] + x[1]));
                let (d0, d1) = (self.piece_derivative(i, x[0]), self.piece_derivative(i, x[1]));
                [
                    [x[0], y[0]],
                    [x[0] + h / 3.0, y[0] + h * d0 / 3.0],
                    [x[1] - h / 3.0, y[1] - h * d1 / 3.0],
                    [x[1], y[1]],
                ]
            })
            .collect()
    }

    /// s' of piece i at x.
    fn piece_derivative(&self, i: usize, x: f64) -> f64 {
        let (a, b) = (self.xs[i], self.xs[i + 1]);
        let h = b - a;
        let (m0, m1) = (self.moments[i], self.moments[i + 1]);
        -m0 * (b - x).powi(2) / (2.0 * h) + m1 * (x - a).powi(2) / (2.0 * h) + (self.ys[i + 1] - self.ys[i]) / h
            - (m1 - m0) * h / 6.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::bezier::horner;

    /// The bird data of seed 004, 9.7.2 exercise 5.
    const X: [f64; 21] = [
        0.9, 1.3, 1.9, 2.1, 2.6, 3.0, 3.9, 4.4, 4.7, 5.0, 6.0, 7.0, 8.0, 9.2, 10.5, 11.3, 11.6, 12.0, 12.6, 13.0, 13.3,
    ];
    const Y: [f64; 21] = [
        1.3, 1.5, 1.85, 2.1, 2.6, 2.7, 2.4, 2.15, 2.05, 2.1, 2.25, 2.3, 2.25, 1.95, 1.4, 0.9, 0.7, 0.6, 0.5, 0.4, 0.25,
    ];

    #[test]
    fn bird_spline_interpolates_is_natural_and_c2() {
        let s = CubicSpline::natural(&X, &Y).unwrap();
        for (x, y) in X.iter().zip(Y) {
            assert!((s.eval(*x) - y).abs() < 1e-12);
        }
        assert!(s.second_derivative(0.9).abs() < 1e-12 && s.second_derivative(13.3).abs() < 1e-12);
        // C¹ and C² at every interior knot, by one-sided finite differences.
        let e = 1e-7;
        for &x in &X[1..20] {
            let (l, r) = ((s.eval(x) - s.eval(x - e)) / e, (s.eval(x + e) - s.eval(x)) / e);
            assert!((l - r).abs() < 1e-5, "s' jumps at {x}");
            let (l2, r2) = (s.second_derivative(x - 1e-9), s.second_derivative(x + 1e-9));
            assert!((l2 - r2).abs() < 1e-6, "s'' jumps at {x}");
        }
    }

    #[test]
    fn three_points_give_the_hand_solved_moment() {
        // Three points leave one equation, solved by hand: (0,0), (1,1), (3,0) give
        // 2 (1 + 2) M₁ = 6 (−1/2 − 1), so M₁ = −1.5.
        let s = CubicSpline::natural(&[0.0, 1.0, 3.0], &[0.0, 1.0, 0.0]).unwrap();
        assert!((s.second_derivative(1.0) + 1.5).abs() < 1e-12);
    }

    #[test]
    fn bezier_pieces_draw_the_spline() {
        let s = CubicSpline::natural(&X, &Y).unwrap();
        for (k, piece) in s.bezier_pieces().iter().enumerate() {
            let pts: Vec<f64> = piece.iter().flatten().copied().collect();
            for t in [0.0, 0.3, 0.5, 0.9, 1.0] {
                let p = horner(&pts, 2, 4, t);
                assert!((p[0] - (X[k] + t * (X[k + 1] - X[k]))).abs() < 1e-12, "x is linear");
                assert!((p[1] - s.eval(p[0])).abs() < 1e-12, "piece {k} at {t}");
            }
        }
    }

    #[test]
    fn bad_data_is_refused() {
        assert!(CubicSpline::natural(&[0.0], &[1.0]).is_err());
        assert!(CubicSpline::natural(&[0.0, 1.0], &[1.0]).is_err());
        assert!(CubicSpline::natural(&[0.0, 0.0], &[1.0, 2.0]).is_err());
        assert!(CubicSpline::natural(&[0.0, f64::NAN], &[1.0, 2.0]).is_err());
        assert!(CubicSpline::natural(&[1.0, 0.0], &[1.0, 2.0]).unwrap_err().to_string().contains("increase"));
    }
}
