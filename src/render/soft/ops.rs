//! Per-fragment arithmetic shared by the CPU rasteriser's stages: the stencil operations (GL
//! 1.1 spec §4.1.4, with GL 1.4's wrapping ones), blending (GL 1.4 §4.1.8), the logic ops
//! (§4.1.7, table 4.2) and the conversion of a colour component into the 8-bit buffer.

use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::Blend;

/// A float colour component in an 8-bit normalised buffer as Mesa converts it (gallium's
/// `float_to_ubyte`, which llvmpipe's clears, fragment outputs and `glAccum(GL_RETURN)` share):
/// c · 255/256 rounded to a float, added to 2¹⁵ so that the float's last 8 mantissa bits hold
/// the result, rounded to nearest, ties to even. So 0.3 gives 76 and 0.9 gives 230 (measured on
/// Mesa 22.3), where c · 255 rounded half up gives 77 and 229.
pub(super) fn to_unorm8(c: f32) -> u8 {
    if c.is_nan() || c <= 0.0 {
        return 0;
    }
    if c >= 1.0 {
        return 255;
    }
    let t = c * (255.0 / 256.0) + 32768.0;
    (t.to_bits() & 0xFF) as u8
}

/// The stencil value after operation `op` on `old` with reference `reference` (8 bits:
/// `GL_INCR` and `GL_DECR` saturate, the wrapping ones wrap).
pub(super) fn stencil_op(op: GLenum, old: u8, reference: u8) -> u8 {
    match op {
        GL_ZERO => 0,
        GL_REPLACE => reference,
        GL_INCR => old.saturating_add(1),
        GL_DECR => old.saturating_sub(1),
        GL_INVERT => !old,
        GL_INCR_WRAP => old.wrapping_add(1),
        GL_DECR_WRAP => old.wrapping_sub(1),
        _ => old,
    }
}

/// Logic op `op` between source `s` and destination `d` bits (GL 1.1 table 4.2).
pub(super) fn logic_op(op: GLenum, s: u8, d: u8) -> u8 {
    match op {
        GL_CLEAR => 0,
        GL_AND => s & d,
        GL_AND_REVERSE => s & !d,
        GL_AND_INVERTED => !s & d,
        GL_NOOP => d,
        GL_XOR => s ^ d,
        GL_OR => s | d,
        GL_NOR => !(s | d),
        GL_EQUIV => !(s ^ d),
        GL_INVERT => !d,
        GL_OR_REVERSE => s | !d,
        GL_COPY_INVERTED => !s,
        GL_OR_INVERTED => !s | d,
        GL_NAND => !(s & d),
        GL_SET => 0xFF,
        _ => s,
    }
}

/// Source colour `s` blended with destination `d` (GL 1.4 §4.1.8): the RGB channels by the
/// first pair of factors and the first equation, alpha by the second pair and equation.
/// `GL_MIN` and `GL_MAX` ignore the factors.
pub(super) fn blend(b: &Blend, s: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    let rgb = (factor(b.factors[0], s, d, b.color), factor(b.factors[1], s, d, b.color));
    let alpha = (factor(b.factors[2], s, d, b.color), factor(b.factors[3], s, d, b.color));
    std::array::from_fn(|k| {
        let ((fs, fd), equation) = if k < 3 { (rgb, b.equations[0]) } else { (alpha, b.equations[1]) };
        let (s, d) = (s[k], d[k]);
        let value = match equation {
            GL_FUNC_SUBTRACT => s * fs[k] - d * fd[k],
            GL_FUNC_REVERSE_SUBTRACT => d * fd[k] - s * fs[k],
            GL_MIN => s.min(d),
            GL_MAX => s.max(d),
            _ => s * fs[k] + d * fd[k],
        };
        value.clamp(0.0, 1.0)
    })
}

/// A blend factor (GL 1.4 tables 4.1 and 4.2) for source colour `s`, destination `d` and the
/// constant colour `c`.
fn factor(f: GLenum, s: [f32; 4], d: [f32; 4], c: [f32; 4]) -> [f32; 4] {
    match f {
        GL_ZERO => [0.0; 4],
        GL_SRC_COLOR => s,
        GL_ONE_MINUS_SRC_COLOR => s.map(|x| 1.0 - x),
        GL_SRC_ALPHA => [s[3]; 4],
        GL_ONE_MINUS_SRC_ALPHA => [1.0 - s[3]; 4],
        GL_DST_ALPHA => [d[3]; 4],
        GL_ONE_MINUS_DST_ALPHA => [1.0 - d[3]; 4],
        GL_DST_COLOR => d,
        GL_ONE_MINUS_DST_COLOR => d.map(|x| 1.0 - x),
        GL_SRC_ALPHA_SATURATE => {
            let f = s[3].min(1.0 - d[3]);
            [f, f, f, 1.0]
        }
        GL_CONSTANT_COLOR => c,
        GL_ONE_MINUS_CONSTANT_COLOR => c.map(|x| 1.0 - x),
        GL_CONSTANT_ALPHA => [c[3]; 4],
        GL_ONE_MINUS_CONSTANT_ALPHA => [1.0 - c[3]; 4],
        _ => [1.0; 4],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Measured on Mesa 22.3 (OSMesa): white XOR (255, 0, 0, 255) is (0, 255, 255, 0);
    /// COPY_INVERTED of (51, 102, 153, 204) is (204, 153, 102, 51).
    #[test]
    fn logic_ops_as_mesa() {
        assert_eq!([255, 0, 0, 255].map(|d| logic_op(GL_XOR, 255, d)), [0, 255, 255, 0]);
        assert_eq!([51, 102, 153, 204].map(|s| logic_op(GL_COPY_INVERTED, s, 0)), [204, 153, 102, 51]);
    }

    /// Measured on Mesa 22.3 (OSMesa, llvmpipe): clear colours and flat colours 0.1, 0.15, 0.3,
    /// 0.9 are stored as 26, 38, 76, 230.
    #[test]
    fn unorm8_as_mesa() {
        assert_eq!([0.1, 0.15, 0.3, 0.9, 0.0, 1.0, -1.0, 2.0].map(to_unorm8), [26, 38, 76, 230, 0, 255, 0, 255]);
    }

    #[test]
    fn stencil_ops_saturate_or_wrap() {
        assert_eq!(stencil_op(GL_INCR, 255, 0), 255);
        assert_eq!(stencil_op(GL_INCR_WRAP, 255, 0), 0);
        assert_eq!(stencil_op(GL_DECR, 0, 0), 0);
        assert_eq!(stencil_op(GL_DECR_WRAP, 0, 0), 255);
        assert_eq!(stencil_op(GL_REPLACE, 3, 9), 9);
        assert_eq!(stencil_op(GL_INVERT, 0x0F, 0), 0xF0);
    }
}
