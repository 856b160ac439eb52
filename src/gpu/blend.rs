//! GL's blending as wgpu's blend state (GL 1.4 §4.1.8): the factors and equations go into the
//! pipeline, the constant colour is the render pass's blend constant, set per draw.
//!
//! WebGPU has one constant colour and no constant-alpha factor. `GL_CONSTANT_ALPHA` becomes the
//! constant factor with the constant set to the colour's alpha in every channel, which is exact
//! when the RGB factors do not also ask for `GL_CONSTANT_COLOR` (the alpha factors read the
//! constant's alpha either way). A frame whose RGB factors ask for both is drawn by the CPU
//! rasteriser (`fallback.rs`).

use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::Blend;

/// `b` as a wgpu blend state and the blend constant it reads, or `None` when wgpu cannot
/// express it.
pub(crate) fn wgpu_blend(b: &Blend) -> Option<(wgpu::BlendState, wgpu::Color)> {
    let constant_kinds = |factors: &[GLenum]| {
        let colour = factors.iter().any(|f| matches!(*f, GL_CONSTANT_COLOR | GL_ONE_MINUS_CONSTANT_COLOR));
        let alpha = factors.iter().any(|f| matches!(*f, GL_CONSTANT_ALPHA | GL_ONE_MINUS_CONSTANT_ALPHA));
        (colour, alpha)
    };
    let (rgb_colour, rgb_alpha) = constant_kinds(&b.factors[..2]);
    if rgb_colour && rgb_alpha {
        return None;
    }
    let [r, g, bl, a] = b.color.map(f64::from);
    let constant = if rgb_alpha { wgpu::Color { r: a, g: a, b: a, a } } else { wgpu::Color { r, g, b: bl, a } };
    let component = |[src, dst]: [GLenum; 2], equation: GLenum| {
        let operation = match equation {
            GL_FUNC_SUBTRACT => wgpu::BlendOperation::Subtract,
            GL_FUNC_REVERSE_SUBTRACT => wgpu::BlendOperation::ReverseSubtract,
            GL_MIN => wgpu::BlendOperation::Min,
            GL_MAX => wgpu::BlendOperation::Max,
            _ => wgpu::BlendOperation::Add,
        };
        // WebGPU requires factors of one with min and max, which ignore them as GL does.
        let minmax = matches!(operation, wgpu::BlendOperation::Min | wgpu::BlendOperation::Max);
        let factor = |f| if minmax { wgpu::BlendFactor::One } else { factor(f) };
        wgpu::BlendComponent { src_factor: factor(src), dst_factor: factor(dst), operation }
    };
    let color = component([b.factors[0], b.factors[1]], b.equations[0]);
    let alpha = component([b.factors[2], b.factors[3]], b.equations[1]);
    Some((wgpu::BlendState { color, alpha }, constant))
}

fn factor(factor: GLenum) -> wgpu::BlendFactor {
    use wgpu::BlendFactor as F;
    match factor {
        GL_ZERO => F::Zero,
        GL_SRC_COLOR => F::Src,
        GL_ONE_MINUS_SRC_COLOR => F::OneMinusSrc,
        GL_SRC_ALPHA => F::SrcAlpha,
        GL_ONE_MINUS_SRC_ALPHA => F::OneMinusSrcAlpha,
        GL_DST_ALPHA => F::DstAlpha,
        GL_ONE_MINUS_DST_ALPHA => F::OneMinusDstAlpha,
        GL_DST_COLOR => F::Dst,
        GL_ONE_MINUS_DST_COLOR => F::OneMinusDst,
        GL_SRC_ALPHA_SATURATE => F::SrcAlphaSaturated,
        GL_CONSTANT_COLOR | GL_CONSTANT_ALPHA => F::Constant,
        GL_ONE_MINUS_CONSTANT_COLOR | GL_ONE_MINUS_CONSTANT_ALPHA => F::OneMinusConstant,
        _ => F::One,
    }
}

/// Whether wgpu draws every blend of `states` (see the module's text).
pub(crate) fn expressible<'a>(mut blends: impl Iterator<Item = &'a Option<Blend>>) -> bool {
    blends.all(|b| b.as_ref().is_none_or(|b| wgpu_blend(b).is_some()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_alpha_is_the_constant_with_alpha_everywhere() {
        let mut b = Blend { color: [0.1, 0.3, 0.5, 0.7], ..Blend::default() };
        b.factors = [GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_CONSTANT_COLOR, GL_ONE];
        let (state, constant) = wgpu_blend(&b).unwrap();
        assert_eq!(state.color.src_factor, wgpu::BlendFactor::Constant);
        assert_eq!((constant.r, constant.a), (f64::from(0.7f32), f64::from(0.7f32)));
        b.factors[1] = GL_ONE_MINUS_CONSTANT_COLOR;
        assert!(wgpu_blend(&b).is_none(), "both constants in the RGB factors cannot be one wgpu constant");
        b.factors = [GL_SRC_ALPHA; 4];
        b.equations = [GL_MIN, GL_FUNC_REVERSE_SUBTRACT];
        let (state, _) = wgpu_blend(&b).unwrap();
        assert_eq!(
            (state.color.src_factor, state.color.operation),
            (wgpu::BlendFactor::One, wgpu::BlendOperation::Min)
        );
        assert_eq!(state.alpha.src_factor, wgpu::BlendFactor::SrcAlpha);
    }
}
