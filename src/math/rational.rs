//! Rational (homogeneous) points: GL's `*_VERTEX_4` maps hold (w·x, w·y, w·z, w).

use super::bezier::Vec4;
use super::scalar::Scalar;

/// The projected point (x/w, y/w, z/w). A zero w gives infinities or NaN, as IEEE division does
/// (a point at infinity), never a panic.
#[must_use]
pub fn project<S: Scalar>(p: Vec4<S>) -> [S; 3] {
    [p[0] / p[3], p[1] / p[3], p[2] / p[3]]
}

/// The derivative of the projected point scaled by w²: `d[c]·w − d[3]·p[c]` for c = x, y, z.
/// This is Mesa's correction for `GL_MAP2_VERTEX_4` auto normals (`vbo_exec_eval.c`); after
/// normalisation the positive factor w² does not matter.
#[must_use]
pub fn rational_derivative<S: Scalar>(p: Vec4<S>, d: Vec4<S>) -> [S; 3] {
    [d[0] * p[3] - d[3] * p[0], d[1] * p[3] - d[3] * p[1], d[2] * p[3] - d[3] * p[2]]
}

/// a × b, written as Mesa's `CROSS3`.
#[must_use]
pub fn cross<S: Scalar>(a: [S; 3], b: [S; 3]) -> [S; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The unit vector along `v`; a zero vector stays zero (Mesa's `NORMALIZE_3FV`), so collapsed
/// patch edges give a defined normal instead of NaN.
#[must_use]
pub fn normalize<S: Scalar>(v: [S; 3]) -> [S; 3] {
    let len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if len2 == S::ZERO {
        return v;
    }
    let inv = S::ONE / len2.sqrt();
    [v[0] * inv, v[1] * inv, v[2] * inv]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rational_derivative_is_w_squared_times_quotient_rule() {
        // P(t) = (t, 1, 0, 1 + t): x/w = t/(1+t), derivative 1/(1+t)^2; times w^2 = 1.
        let t = 0.7f64;
        let p = [t, 1.0, 0.0, 1.0 + t];
        let d = [1.0, 0.0, 0.0, 1.0];
        let r = rational_derivative(p, d);
        assert!((r[0] - 1.0).abs() < 1e-12);
        assert!((r[1] + 1.0).abs() < 1e-12); // (1/w)' = -1/w^2 -> times w^2 = -1
    }

    #[test]
    fn zero_vector_normalizes_to_zero() {
        assert_eq!(normalize([0.0f32; 3]), [0.0; 3]);
        let n = normalize([3.0f64, 0.0, 4.0]);
        assert!((n[0] - 0.6).abs() < 1e-15 && (n[2] - 0.8).abs() < 1e-15);
    }
}
