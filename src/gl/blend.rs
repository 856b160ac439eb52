//! Blending, part of the colour buffer attribute group (GL 1.1 spec §4.1.6; GL 1.2's imaging
//! subset `glBlendColor` and `glBlendEquation`, GL 1.4 §4.1.8 `glBlendFuncSeparate`, GL 2.0's
//! `glBlendEquationSeparate` as `GL_EXT_blend_equation_separate` gives it to 1.x contexts; Mesa
//! `main/blend.c`). Both rasterisers read the [`Blend`] a recorded primitive carries while
//! `GL_BLEND` is on.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put, put_enum, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// How a fragment's colour is combined with the buffer's (GL 1.4 §4.1.8): per channel,
/// `equation(source × source factor, destination × destination factor)`, the RGB channels and
/// alpha each with their own factors and equation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Blend {
    /// Source RGB, destination RGB, source alpha, destination alpha factors.
    pub factors: [GLenum; 4],
    /// The RGB and the alpha equation: `GL_FUNC_ADD`, `GL_FUNC_SUBTRACT`,
    /// `GL_FUNC_REVERSE_SUBTRACT`, `GL_MIN` or `GL_MAX` (the last two ignore the factors).
    pub equations: [GLenum; 2],
    /// `glBlendColor`, clamped to [0, 1] as Mesa blends with it (and answers it) for a
    /// fixed-point colour buffer, the only kind gleval has.
    pub color: [f32; 4],
}

impl Default for Blend {
    fn default() -> Self {
        Self { factors: [GL_ONE, GL_ZERO, GL_ONE, GL_ZERO], equations: [GL_FUNC_ADD; 2], color: [0.0; 4] }
    }
}

/// A blending call as a display list holds it (inside the colour buffer group's record).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum BlendCall {
    Func([GLenum; 4]),
    Equation([GLenum; 2]),
    Color([GLclampf; 4]),
}

/// Whether `factor` is a blend factor GL 1.5 takes, as source or destination alike (GL 1.4
/// table 4.1 and 4.2: GL 1.4 added the colour factors to both sides, as `GL_NV_blend_square` did, and Mesa's desktop GL takes
/// `GL_SRC_ALPHA_SATURATE` as a destination too). Mesa 22.3 also takes the dual-source factors
/// of `GL_ARB_blend_func_extended` (GL 3.3), which gleval does not claim: `GL_INVALID_ENUM` here,
/// as GL 1.5 says.
fn is_factor(factor: GLenum) -> bool {
    matches!(factor, GL_ZERO | GL_ONE)
        || (GL_SRC_COLOR..=GL_SRC_ALPHA_SATURATE).contains(&factor)
        || (GL_CONSTANT_COLOR..=GL_ONE_MINUS_CONSTANT_ALPHA).contains(&factor)
}

/// Whether `mode` is a blend equation of GL 1.5 (`GL_EXT_blend_minmax` and
/// `GL_EXT_blend_subtract`). Mesa's `glBlendEquation` also takes `GL_KHR_blend_equation_advanced`'s
/// modes, which gleval does not claim.
fn is_equation(mode: GLenum) -> bool {
    matches!(mode, GL_FUNC_ADD | GL_FUNC_SUBTRACT | GL_FUNC_REVERSE_SUBTRACT | GL_MIN | GL_MAX)
}

impl Gl {
    /// Records a blending call in the list being compiled, or refuses it inside
    /// `begin`/`end`; true when it must not run now.
    fn compiled_blend_call(&mut self, call: BlendCall) -> bool {
        self.compiled_state_call(|| ListCommand::ColorBuffer(call.into()))
    }

    /// Replays a listed blending call.
    pub(crate) fn replay_blend_call(&mut self, call: BlendCall) {
        match call {
            BlendCall::Func([src_rgb, dst_rgb, src_alpha, dst_alpha]) => {
                self.blend_func_separate(src_rgb, dst_rgb, src_alpha, dst_alpha)
            }
            BlendCall::Equation([rgb, alpha]) => self.blend_equation_separate(rgb, alpha),
            BlendCall::Color([r, g, b, a]) => self.blend_color(r, g, b, a),
        }
    }

    /// `glBlendFunc`: one source and one destination factor for RGB and alpha alike. A factor
    /// GL does not know → `GL_INVALID_ENUM`.
    pub fn blend_func(&mut self, sfactor: GLenum, dfactor: GLenum) {
        self.blend_func_separate(sfactor, dfactor, sfactor, dfactor);
    }

    /// `glBlendFuncSeparate` (GL 1.4): the RGB and the alpha factors. A factor GL does not
    /// know → `GL_INVALID_ENUM`, and nothing changes.
    pub fn blend_func_separate(&mut self, src_rgb: GLenum, dst_rgb: GLenum, src_alpha: GLenum, dst_alpha: GLenum) {
        let factors = [src_rgb, dst_rgb, src_alpha, dst_alpha];
        if self.compiled_blend_call(BlendCall::Func(factors)) {
            return;
        }
        if !factors.into_iter().all(is_factor) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.color_buffer.blend.factors = factors;
        self.touch_state();
    }

    /// `glBlendEquation` (GL 1.2's imaging subset, in every 1.4 context): the RGB and alpha
    /// equation. Another mode → `GL_INVALID_ENUM`.
    pub fn blend_equation(&mut self, mode: GLenum) {
        self.blend_equation_separate(mode, mode);
    }

    /// `glBlendEquationSeparate` (`GL_EXT_blend_equation_separate`): the RGB and the alpha
    /// equation. Another mode → `GL_INVALID_ENUM`.
    pub fn blend_equation_separate(&mut self, mode_rgb: GLenum, mode_alpha: GLenum) {
        let equations = [mode_rgb, mode_alpha];
        if self.compiled_blend_call(BlendCall::Equation(equations)) {
            return;
        }
        if !equations.into_iter().all(is_equation) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.color_buffer.blend.equations = equations;
        self.touch_state();
    }

    /// `glBlendColor` (GL 1.2's imaging subset): the colour of the `GL_CONSTANT_*` factors,
    /// clamped to [0, 1].
    pub fn blend_color(&mut self, red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) {
        let color = [red, green, blue, alpha];
        if self.compiled_blend_call(BlendCall::Color(color)) {
            return;
        }
        self.server.color_buffer.blend.color = color.map(|c| c.clamp(0.0, 1.0));
        self.touch_state();
    }

    /// Blending while `GL_BLEND` is on.
    pub(crate) fn enabled_blend(&self) -> Option<Blend> {
        self.capability(GL_BLEND).then_some(self.server.color_buffer.blend)
    }
}

/// Blending's `glGet` rows (GL 1.4 table 6.21; `GL_BLEND_SRC` and `GL_BLEND_DST` are the RGB
/// factors, `GL_BLEND_EQUATION` the RGB equation).
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_BLEND_SRC, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.blend.factors[0])),
    row(GL_BLEND_DST, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.blend.factors[1])),
    row(GL_BLEND_SRC_RGB, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.blend.factors[0])),
    row(GL_BLEND_DST_RGB, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.blend.factors[1])),
    row(GL_BLEND_SRC_ALPHA, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.blend.factors[2])),
    row(GL_BLEND_DST_ALPHA, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.blend.factors[3])),
    row(GL_BLEND_EQUATION, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.blend.equations[0])),
    row(GL_BLEND_EQUATION_ALPHA, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.blend.equations[1])),
    row(GL_BLEND_COLOR, 4, Kind::Normalized, |gl, o| put(o, &gl.server.color_buffer.blend.color)),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn separate_factors_equations_and_colour_as_mesa_keeps_them() {
        let mut gl = Gl::new(4, 4);
        gl.blend_func_separate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, 0x1234);
        gl.blend_equation_separate(GL_FUNC_ADD, 0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        assert_eq!(gl.server.color_buffer.blend, Blend::default());
        gl.blend_func_separate(GL_CONSTANT_COLOR, GL_SRC_ALPHA_SATURATE, GL_ONE, GL_ZERO);
        gl.blend_equation_separate(GL_FUNC_SUBTRACT, GL_MAX);
        gl.blend_color(-0.5, 2.0, 0.25, 1.5);
        let (mut ints, mut color) = ([0; 4], [0.0; 4]);
        for (k, name) in [GL_BLEND_SRC, GL_BLEND_DST_RGB, GL_BLEND_EQUATION, GL_BLEND_EQUATION_ALPHA].iter().enumerate()
        {
            gl.get_integerv(*name, &mut ints[k..=k]);
        }
        gl.get_floatv(GL_BLEND_COLOR, &mut color);
        let expected = [GL_CONSTANT_COLOR, GL_SRC_ALPHA_SATURATE, GL_FUNC_SUBTRACT, GL_MAX].map(|e| e as i32);
        assert_eq!((ints, color), (expected, [0.0, 1.0, 0.25, 1.0]));
        assert_eq!(gl.enabled_blend(), None);
        gl.enable(GL_BLEND);
        assert_eq!(gl.enabled_blend().map(|b| b.equations), Some([GL_FUNC_SUBTRACT, GL_MAX]));
    }
}
