//! NURBS constructions of seed 002: the exact circle as a rational quadratic B-spline, and
//! surfaces made from a curve by revolution about the z axis and by extrusion (The NURBS Book
//! §7.5 and §8.4–8.5). Everything is homogeneous: control points (w·x, w·y, w·z, w).

use super::bspline::{BSplineCurve, BSplineSurface};
use super::knots::KnotVector;
use super::{MathError, Scalar};

/// The unit circle's 9 homogeneous control points in the xy plane, starting at (1, 0) and
/// turning counter-clockwise: corners of the circumscribed square with weight √2/2.
fn unit_circle<S: Scalar>() -> [[S; 3]; 9] {
    let h = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    let (o, z) = (S::ONE, S::ZERO);
    let corners = [[o, z], [o, o], [z, o], [-o, o], [-o, z], [-o, -o], [z, -o], [o, -o], [o, z]];
    std::array::from_fn(|k| {
        let w = if k % 2 == 1 { h } else { o };
        [corners[k][0], corners[k][1], w]
    })
}

/// Knots of the 9-point circle: quarter arcs joined with double knots.
fn circle_knots<S: Scalar>() -> KnotVector<S> {
    KnotVector::new([0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0].map(S::from_f64).to_vec())
}

/// The full circle of `radius` about `center` in the plane z = center.z: a rational quadratic
/// B-spline (order 3, 9 control points, homogeneous), exact for u ∈ [0, 1].
///
/// ```
/// use gleval::math::nurbs_circle;
/// let c = nurbs_circle([1.0f64, 2.0, 0.0], 3.0).unwrap();
/// let p = c.eval_rational(0.3).unwrap();
/// let r = ((p[0] - 1.0).powi(2) + (p[1] - 2.0).powi(2)).sqrt();
/// assert!((r - 3.0).abs() < 1e-12);
/// ```
pub fn nurbs_circle<S: Scalar>(center: [S; 3], radius: S) -> Result<BSplineCurve<S>, MathError> {
    let points = unit_circle()
        .iter()
        .flat_map(|&[x, y, w]| [w * (center[0] + radius * x), w * (center[1] + radius * y), w * center[2], w])
        .collect();
    BSplineCurve::try_new(4, 3, circle_knots(), points)
}

/// Homogeneous (w·x, w·y, w·z, w) of control point `k` of a 3- or 4-component curve.
fn homogeneous<S: Scalar>(curve: &BSplineCurve<S>, k: usize) -> [S; 4] {
    let p = &curve.points[k * curve.dim..(k + 1) * curve.dim];
    let get = |c: usize| if c < curve.dim { p[c] } else { S::ZERO };
    if curve.dim == 4 {
        [p[0], p[1], p[2], p[3]]
    } else {
        [get(0), get(1), get(2), S::ONE]
    }
}

/// The surface swept by `profile` (a curve in the xz plane: its x is the distance from the z
/// axis, its y is ignored) turning a full circle about the z axis. u runs around the axis
/// ([0, 1], order 3), v along the profile (its knots and order).
///
/// ```
/// use gleval::math::{nurbs_circle, revolve};
/// use gleval::math::{BSplineCurve, KnotVector};
/// // A segment from (1, 0, 0) to (1, 0, 2) sweeps a cylinder of radius 1.
/// let line = BSplineCurve::try_new(3, 2, KnotVector::new(vec![0.0f64, 0.0, 1.0, 1.0]), vec![1.0, 0.0, 0.0, 1.0, 0.0, 2.0]).unwrap();
/// let s = revolve(&line).unwrap();
/// let p = s.eval_rational(0.37, 0.5).unwrap();
/// assert!(((p[0] * p[0] + p[1] * p[1]).sqrt() - 1.0).abs() < 1e-12 && (p[2] - 1.0).abs() < 1e-12);
/// ```
pub fn revolve<S: Scalar>(profile: &BSplineCurve<S>) -> Result<BSplineSurface<S>, MathError> {
    if profile.dim < 3 {
        return Err(MathError::BadDimension(profile.dim));
    }
    let n = profile.control_count();
    let mut points = Vec::with_capacity(9 * n * 4);
    for [cx, cy, cw] in unit_circle::<S>() {
        for k in 0..n {
            // (w·r, ·, w·z, w) of the profile, turned to the circle's direction and weighted.
            let [wr, _, wz, w] = homogeneous(profile, k);
            points.extend([cw * wr * cx, cw * wr * cy, cw * wz, cw * w]);
        }
    }
    BSplineSurface::try_new(4, 3, profile.order, circle_knots(), profile.knots.clone(), points)
}

/// The surface swept by `curve` moving along `direction`: u along the curve, v ∈ [0, 1] from
/// the curve (v = 0) to its copy moved by `direction` (v = 1).
///
/// ```
/// use gleval::math::{extrude, nurbs_circle};
/// let tube = extrude(&nurbs_circle([0.0f64, 0.0, 0.0], 1.0).unwrap(), [0.0, 0.0, 3.0]).unwrap();
/// let p = tube.eval_rational(0.6, 0.5).unwrap();
/// assert!(((p[0] * p[0] + p[1] * p[1]).sqrt() - 1.0).abs() < 1e-12 && (p[2] - 1.5).abs() < 1e-12);
/// ```
pub fn extrude<S: Scalar>(curve: &BSplineCurve<S>, direction: [S; 3]) -> Result<BSplineSurface<S>, MathError> {
    let n = curve.control_count();
    let mut points = Vec::with_capacity(n * 2 * 4);
    for k in 0..n {
        let [x, y, z, w] = homogeneous(curve, k);
        points.extend([x, y, z, w]);
        points.extend([x + w * direction[0], y + w * direction[1], z + w * direction[2], w]);
    }
    let line = KnotVector::new([0.0, 0.0, 1.0, 1.0].map(S::from_f64).to_vec());
    BSplineSurface::try_new(4, curve.order, 2, curve.knots.clone(), line, points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_circle_is_exact_everywhere() {
        let c = nurbs_circle([0.5, -1.0, 2.0], 2.5).unwrap();
        for k in 0..=100 {
            let p = c.eval_rational(f64::from(k) / 100.0).unwrap();
            let r = ((p[0] - 0.5).powi(2) + (p[1] + 1.0).powi(2)).sqrt();
            assert!((r - 2.5).abs() < 1e-12 && (p[2] - 2.0).abs() < 1e-12, "{k}");
        }
        // Quarter parameters land on the axes: (3, −1), (0.5, 1.5), (−2, −1), (0.5, −3.5).
        for (u, want) in [(0.25, [0.5, 1.5]), (0.5, [-2.0, -1.0]), (0.75, [0.5, -3.5])] {
            let p = c.eval_rational(u).unwrap();
            assert!((p[0] - want[0]).abs() < 1e-12 && (p[1] - want[1]).abs() < 1e-12);
        }
    }

    #[test]
    fn a_revolved_profile_keeps_its_radius_and_height() {
        // A rational profile: a quarter circle of radius 1 centred at (2, 0, 0) in the xz plane
        // (a quarter torus), weights 1, √2/2, 1.
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let pts = vec![3.0, 0.0, 0.0, 1.0, 3.0 * h, 0.0, h, h, 2.0, 0.0, 1.0, 1.0];
        let profile = BSplineCurve::try_new(4, 3, KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]), pts).unwrap();
        let s = revolve(&profile).unwrap();
        for (u, v) in [(0.0, 0.0), (0.1, 0.3), (0.45, 0.9), (0.8, 0.5), (1.0, 1.0)] {
            let p = s.eval_rational(u, v).unwrap();
            let q = profile.eval_rational(v).unwrap();
            assert!(((p[0] * p[0] + p[1] * p[1]).sqrt() - q[0]).abs() < 1e-12);
            assert!((p[2] - q[2]).abs() < 1e-12);
            // And the profile's own circle: distance 1 from the tube's centre line.
            let tube = (((p[0] * p[0] + p[1] * p[1]).sqrt() - 2.0).powi(2) + p[2] * p[2]).sqrt();
            assert!((tube - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn extrusion_runs_from_the_curve_to_its_moved_copy() {
        let c = nurbs_circle([0.0, 0.0, 0.0], 1.0).unwrap();
        let s = extrude(&c, [1.0, 2.0, 3.0]).unwrap();
        for u in [0.0, 0.2, 0.7] {
            let base = c.eval_rational(u).unwrap();
            for v in [0.0, 0.5, 1.0] {
                let p = s.eval_rational(u, v).unwrap();
                for (k, d) in [1.0, 2.0, 3.0].iter().enumerate() {
                    assert!((p[k] - (base[k] + v * d)).abs() < 1e-12);
                }
            }
        }
    }

    #[test]
    fn planar_profiles_are_refused() {
        let flat =
            BSplineCurve::try_new(2, 2, KnotVector::new(vec![0.0, 0.0, 1.0, 1.0]), vec![1.0, 0.0, 1.0, 1.0]).unwrap();
        assert_eq!(revolve(&flat), Err(MathError::BadDimension(2)));
    }
}
