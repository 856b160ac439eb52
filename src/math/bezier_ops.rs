//! The operations the course notes teach on one Bezier curve, beyond evaluation: de
//! Casteljau's construction with every intermediate polygon (seed 001), degree reduction (the
//! inverse of elevation, The NURBS Book §5.6, eqs. 5.41–5.45), and the differential geometry
//! of the curve: curvature and the Frenet frame.

use super::bezier::{BezierCurve, Vec4};
use super::rational::{cross, normalize};
use super::Scalar;

/// The Frenet frame of a space curve at one parameter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frenet<S: Scalar> {
    /// The unit tangent r'/|r'|.
    pub tangent: [S; 3],
    /// The unit principal normal B × T (towards the centre of curvature).
    pub normal: [S; 3],
    /// The unit binormal (r' × r'')/|r' × r''|.
    pub binormal: [S; 3],
    /// κ = |r' × r''| / |r'|³.
    pub curvature: S,
}

fn xyz<S: Scalar>(v: Vec4<S>, dim: usize) -> [S; 3] {
    [v[0], if dim > 1 { v[1] } else { S::ZERO }, if dim > 2 { v[2] } else { S::ZERO }]
}

fn length<S: Scalar>(v: [S; 3]) -> S {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

impl<S: Scalar> BezierCurve<S> {
    /// De Casteljau's construction at `t`: the control polygon, then each polygon of
    /// interpolated points, down to the single point on the curve (`order` levels).
    ///
    /// ```
    /// use gleval::math::BezierCurve;
    /// let c = BezierCurve::try_new(2, vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0]).unwrap();
    /// let levels = c.de_casteljau_levels(0.5);
    /// assert_eq!(levels[1], [0.5, 1.0, 1.5, 1.0]); // the midpoints of the two legs
    /// assert_eq!(levels[2], [1.0, 1.0]); // the point p(1/2)
    /// ```
    #[must_use]
    pub fn de_casteljau_levels(&self, t: S) -> Vec<Vec<S>> {
        let dim = self.dim;
        let mut levels = vec![self.points.clone()];
        while levels.last().is_some_and(|l| l.len() > dim) {
            let prev = levels.last().map(Vec::as_slice).unwrap_or_default();
            let next: Vec<S> = (0..prev.len() - dim).map(|k| (S::ONE - t) * prev[k] + t * prev[k + dim]).collect();
            levels.push(next);
        }
        levels
    }

    /// The curve of one degree less closest to this one: exact when this curve is an elevated
    /// one. Control points are solved from both ends of the elevation relation
    /// Pᵢ = (i/p) Qᵢ₋₁ + (1 − i/p) Qᵢ and joined in the middle (The NURBS Book eqs. 5.41–5.45).
    /// `None` for a curve of order 1.
    ///
    /// ```
    /// use gleval::math::BezierCurve;
    /// let c = BezierCurve::<f64>::try_new(2, vec![0.0, 0.0, 1.0, 2.0, 3.0, 1.0]).unwrap();
    /// let back = c.elevate().reduce().unwrap();
    /// assert!(back.points.iter().zip(&c.points).all(|(a, b)| (a - b).abs() < 1e-12));
    /// ```
    #[must_use]
    pub fn reduce(&self) -> Option<Self> {
        let (dim, n) = (self.dim, self.order());
        if n < 2 {
            return None;
        }
        let p = n - 1; // this curve's degree; the result has p points
        let point = |k: usize| &self.points[k * dim..(k + 1) * dim];
        let alpha = |i: usize| S::from_usize(i) / S::from_usize(p);
        let mut left = vec![S::ZERO; p * dim];
        let mut right = vec![S::ZERO; p * dim];
        left[..dim].copy_from_slice(point(0));
        for i in 1..p {
            for c in 0..dim {
                left[i * dim + c] = (point(i)[c] - alpha(i) * left[(i - 1) * dim + c]) / (S::ONE - alpha(i));
            }
        }
        right[(p - 1) * dim..].copy_from_slice(point(p));
        for i in (1..p).rev() {
            for c in 0..dim {
                right[(i - 1) * dim + c] = (point(i)[c] - (S::ONE - alpha(i)) * right[i * dim + c]) / alpha(i);
            }
        }
        // Left values up to the middle, right values after it; an odd degree averages the middle.
        let r = (p - 1) / 2;
        let mut points = vec![S::ZERO; p * dim];
        for i in 0..p {
            for c in 0..dim {
                let k = i * dim + c;
                points[k] = if p % 2 == 1 && i == r {
                    (left[k] + right[k]) / S::from_f64(2.0)
                } else if i <= r {
                    left[k]
                } else {
                    right[k]
                };
            }
        }
        Some(Self { dim, points })
    }

    /// The second derivative at `t` (zero below order 3).
    #[must_use]
    pub fn second_derivative(&self, t: S) -> Vec4<S> {
        match self.hodograph() {
            Some(h) if h.order() >= 2 => h.derivative(t),
            _ => [S::ZERO; 4],
        }
    }

    /// Curvature and Frenet frame at `t` of a curve in 2 or 3 coordinates (a planar curve lies
    /// in z = 0). `None` for homogeneous (4-component) curves and where r' or r' × r'' vanishes.
    ///
    /// ```
    /// use gleval::math::BezierCurve;
    /// // (−1, 1), (0, −1), (1, 1) draw the parabola y = x² (x = 2t − 1): curvature 2 at its
    /// // vertex, whatever the parameterisation.
    /// let c = BezierCurve::<f64>::try_new(2, vec![-1.0, 1.0, 0.0, -1.0, 1.0, 1.0]).unwrap();
    /// assert!((c.frenet(0.5).unwrap().curvature - 2.0).abs() < 1e-12);
    /// ```
    #[must_use]
    pub fn frenet(&self, t: S) -> Option<Frenet<S>> {
        if self.dim > 3 {
            return None;
        }
        let d1 = xyz(self.derivative(t), self.dim);
        let d2 = xyz(self.second_derivative(t), self.dim);
        let speed = length(d1);
        let b = cross(d1, d2);
        let b_len = length(b);
        if speed == S::ZERO || b_len == S::ZERO || !(speed.is_finite() && b_len.is_finite()) {
            return None;
        }
        let tangent = normalize(d1);
        let binormal = normalize(b);
        Some(Frenet { tangent, normal: cross(binormal, tangent), binormal, curvature: b_len / (speed * speed * speed) })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cubic3() -> BezierCurve<f64> {
        BezierCurve::try_new(3, vec![0.0, 0.0, 0.0, 1.0, 2.0, 0.5, 3.0, -1.0, 1.0, 4.0, 1.0, -0.5]).unwrap()
    }

    #[test]
    fn last_level_is_the_point_and_first_levels_split_the_curve() {
        let c = cubic3();
        for t in [0.0, 0.3, 0.5, 1.0] {
            let levels = c.de_casteljau_levels(t);
            assert_eq!(levels.len(), 4);
            let p = c.eval(t);
            for k in 0..3 {
                assert!((levels[3][k] - p[k]).abs() < 1e-12);
            }
            // The first points of each level are the left half's control points (subdivision).
            let (left, _) = c.split(t);
            for (i, level) in levels.iter().enumerate() {
                for k in 0..3 {
                    assert!((level[k] - left.points[i * 3 + k]).abs() < 1e-12);
                }
            }
        }
    }

    #[test]
    fn reduction_inverts_repeated_elevation_for_every_degree() {
        for n in 2..=8 {
            let pts: Vec<f64> = (0..n * 2).map(|k| ((k * 37 % 11) as f64) * 0.5 - 2.0).collect();
            let c = BezierCurve::try_new(2, pts).unwrap();
            let mut e = c.clone();
            for _ in 0..3 {
                e = e.elevate();
            }
            for _ in 0..3 {
                e = e.reduce().unwrap();
            }
            assert!(e.points.iter().zip(&c.points).all(|(a, b)| (a - b).abs() < 1e-9), "order {n}");
        }
        assert!(BezierCurve::try_new(2, vec![1.0, 2.0]).unwrap().reduce().is_none());
    }

    #[test]
    fn reduction_of_a_true_cubic_stays_close_at_the_ends() {
        // Not an elevated curve: the reduced quadratic keeps both end points.
        let c = BezierCurve::try_new(2, vec![0.0, 0.0, 1.0, 2.0, 2.0, -2.0, 3.0, 0.0]).unwrap();
        let r = c.reduce().unwrap();
        assert_eq!(r.order(), 3);
        assert_eq!(&r.points[..2], &[0.0, 0.0]);
        assert_eq!(&r.points[4..], &[3.0, 0.0]);
    }

    #[test]
    fn frenet_frame_is_orthonormal_and_curvature_matches_finite_differences() {
        let c = cubic3();
        for t in [0.1, 0.4, 0.8] {
            let f = c.frenet(t).unwrap();
            let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
            for (a, b) in [(f.tangent, f.normal), (f.normal, f.binormal), (f.tangent, f.binormal)] {
                assert!(dot(a, b).abs() < 1e-12);
            }
            // κ = |dT/ds|: turning of the tangent per unit arc length, by central differences.
            let h = 1e-5;
            let tan = |s: f64| normalize(xyz(c.derivative(s), 3));
            let (a, b) = (tan(t + h), tan(t - h));
            let dt = [(a[0] - b[0]) / (2.0 * h), (a[1] - b[1]) / (2.0 * h), (a[2] - b[2]) / (2.0 * h)];
            let speed = length(xyz(c.derivative(t), 3));
            assert!((length(dt) / speed - f.curvature).abs() < 1e-6, "{t}");
            // The normal points the way the tangent turns.
            assert!(dot(dt, f.normal) > 0.0);
        }
    }

    #[test]
    fn straight_lines_have_no_frenet_frame() {
        let line = BezierCurve::try_new(3, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0]).unwrap();
        assert!(line.frenet(0.5).is_none());
    }
}
