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

/// [`normalize`] of every vector of `vs`, in place: the same operations on each, so the same
/// bits, run eight vectors side by side so that the square roots and divisions (whose latency
/// is most of a lone normalisation's time) are vector instructions.
pub fn normalize_many<S: Scalar>(vs: &mut [[S; 3]]) {
    const W: usize = 8;
    let mut blocks = vs.chunks_exact_mut(W);
    for block in &mut blocks {
        let len2: [S; W] = std::array::from_fn(|k| {
            let v = block[k];
            v[0] * v[0] + v[1] * v[1] + v[2] * v[2]
        });
        // A zero length's lane divides by zero here; that vector is kept as it is below.
        let inv: [S; W] = std::array::from_fn(|k| S::ONE / len2[k].sqrt());
        for ((v, &l), &inv) in block.iter_mut().zip(&len2).zip(&inv) {
            if l != S::ZERO {
                *v = [v[0] * inv, v[1] * inv, v[2] * inv];
            }
        }
    }
    for v in blocks.into_remainder() {
        *v = normalize(*v);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Block by block and one by one give the same bits, zero, tiny, huge and non-finite
    /// vectors included.
    #[test]
    fn normalize_many_is_normalize_of_each() {
        let specials = [0.0f32, -0.0, 1e-30, 3e38, f32::INFINITY, f32::NAN, 1.0, -2.5, 7e-23];
        let vs: Vec<[f32; 3]> = (0..203)
            .map(|i| {
                let pick = |k: usize| specials[(i * 7 + k * 5) % specials.len()];
                if i % 3 == 0 {
                    [pick(0), pick(1), pick(2)]
                } else {
                    [(i as f32 * 0.37).sin(), (i as f32 * 1.3).cos() * 4.0, i as f32 * 1e-3 - 0.1]
                }
            })
            .collect();
        let mut many = vs.clone();
        normalize_many(&mut many);
        for (v, got) in vs.iter().zip(&many) {
            assert_eq!(got.map(f32::to_bits), normalize(*v).map(f32::to_bits), "{v:?}");
        }
        let mut doubles: Vec<[f64; 3]> = vs.iter().map(|v| v.map(f64::from)).collect();
        normalize_many(&mut doubles);
        for (v, got) in vs.iter().zip(&doubles) {
            assert_eq!(got.map(f64::to_bits), normalize(v.map(f64::from)).map(f64::to_bits));
        }
    }

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
