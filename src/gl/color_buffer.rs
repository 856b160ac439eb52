//! The colour buffer attribute group (GL 1.1 spec §4.1.3 the alpha test, §4.1.6 blending,
//! §4.1.7 the logic op, §4.2.1 the draw buffer, §4.2.2 the colour mask, §4.2.3 the clear
//! colour; table 6.13; Mesa `main/blend.c`, `main/logicop.c`, `main/clear.c`): `glAlphaFunc`,
//! `glLogicOp`, `glColorMask`, `glClearColor` (blending is `blend.rs`'s), in one struct as
//! `GL_COLOR_BUFFER_BIT` saves it, with the group's display-list record, its `glGet` rows and
//! its enables. `glDrawBuffer` sets the group's draw buffer from `draw_buffer.rs`, which names
//! the buffers; the colour-index mask and clear index are `color_index.rs`'s. A recorded
//! primitive's [`DrawState`](super::DrawState) carries what is enabled, and both rasterisers
//! apply it.

use super::blend::{Blend, BlendCall};
use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put, put_enum, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// `GL_COLOR_BUFFER_BIT`'s state (its enables and the colour-index values aside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ColorBuffer {
    /// `glAlphaFunc`: the comparison and the reference, clamped to [0, 1].
    pub alpha: (GLenum, f32),
    /// Blending's factors, equations and colour.
    pub blend: Blend,
    /// `glLogicOp`: `GL_CLEAR` .. `GL_SET`.
    pub logic_op: GLenum,
    /// `glColorMask`: red, green, blue, alpha.
    pub color_write: [bool; 4],
    /// `glDrawBuffer`: the name given (see `draw_buffer.rs`).
    pub draw_buffer: GLenum,
    /// `glClearColor`, clamped to [0, 1].
    pub clear_color: [f32; 4],
}

impl Default for ColorBuffer {
    fn default() -> Self {
        Self {
            alpha: (GL_ALWAYS, 0.0),
            blend: Blend::default(),
            logic_op: GL_COPY,
            color_write: [true; 4],
            draw_buffer: GL_FRONT,
            clear_color: [0.0; 4],
        }
    }
}

/// A colour buffer call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ColorBufferCall {
    AlphaFunc(GLenum, GLclampf),
    Blend(BlendCall),
    LogicOp(GLenum),
    ColorMask([GLboolean; 4]),
    DrawBuffer(GLenum),
    ClearColor([GLclampf; 4]),
}

impl From<BlendCall> for ColorBufferCall {
    fn from(call: BlendCall) -> Self {
        Self::Blend(call)
    }
}

/// The enables GL files under the group (GL 1.1 table 6.13).
pub(crate) const COLOR_BUFFER_ENABLES: &[GLenum] =
    &[GL_ALPHA_TEST, GL_BLEND, GL_DITHER, GL_COLOR_LOGIC_OP, GL_INDEX_LOGIC_OP];

impl Gl {
    /// Records a colour buffer call in the list being compiled, or refuses it inside
    /// `begin`/`end`; true when it must not run now.
    pub(crate) fn compiled_color_buffer_call(&mut self, call: ColorBufferCall) -> bool {
        self.compiled_state_call(|| ListCommand::ColorBuffer(call))
    }

    /// `glAlphaFunc`: the comparison (`GL_NEVER` .. `GL_ALWAYS`) and reference (clamped to
    /// [0, 1]) of the alpha test. Another function → `GL_INVALID_ENUM`.
    pub fn alpha_func(&mut self, func: GLenum, reference: GLclampf) {
        if self.compiled_color_buffer_call(ColorBufferCall::AlphaFunc(func, reference)) {
            return;
        }
        if !(GL_NEVER..=GL_ALWAYS).contains(&func) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.color_buffer.alpha = (func, reference.clamp(0.0, 1.0));
        self.touch_state();
    }

    /// `glLogicOp`: the operation (`GL_CLEAR` .. `GL_SET`, else `GL_INVALID_ENUM`) between the
    /// fragment's colour and the buffer's while `GL_COLOR_LOGIC_OP` is on.
    pub fn logic_op(&mut self, opcode: GLenum) {
        if self.compiled_color_buffer_call(ColorBufferCall::LogicOp(opcode)) {
            return;
        }
        if !(GL_CLEAR..=GL_SET).contains(&opcode) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.color_buffer.logic_op = opcode;
        self.touch_state();
    }

    /// `glColorMask`: which of red, green, blue and alpha draws and clears write.
    pub fn color_mask(&mut self, red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) {
        if self.compiled_color_buffer_call(ColorBufferCall::ColorMask([red, green, blue, alpha])) {
            return;
        }
        self.server.color_buffer.color_write = [red, green, blue, alpha].map(|c| c != GL_FALSE);
        self.touch_state();
    }

    /// `glClearColor` (clamped to [0, 1], as GL 1.x does): what `glClear`'s colour bit writes.
    pub fn clear_color(&mut self, r: GLclampf, g: GLclampf, b: GLclampf, a: GLclampf) {
        if self.compiled_color_buffer_call(ColorBufferCall::ClearColor([r, g, b, a])) {
            return;
        }
        self.server.color_buffer.clear_color = [r, g, b, a].map(|c| c.clamp(0.0, 1.0));
    }

    /// Replays a listed colour buffer call.
    pub(crate) fn replay_color_buffer_call(&mut self, call: ColorBufferCall) {
        use ColorBufferCall as C;
        match call {
            C::AlphaFunc(func, reference) => self.alpha_func(func, reference),
            C::Blend(call) => self.replay_blend_call(call),
            C::LogicOp(opcode) => self.logic_op(opcode),
            C::ColorMask([r, g, b, a]) => self.color_mask(r, g, b, a),
            C::DrawBuffer(mode) => self.draw_buffer(mode),
            C::ClearColor([r, g, b, a]) => self.clear_color(r, g, b, a),
        }
    }

    /// The alpha test while `GL_ALPHA_TEST` is on.
    pub(crate) fn enabled_alpha_test(&self) -> Option<(GLenum, f32)> {
        self.capability(GL_ALPHA_TEST).then_some(self.server.color_buffer.alpha)
    }
}

/// The group's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_ALPHA_TEST_FUNC, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.alpha.0)),
    row(GL_ALPHA_TEST_REF, 1, Kind::Normalized, |gl, o| o[0] = gl.server.color_buffer.alpha.1.into()),
    row(GL_LOGIC_OP_MODE, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.logic_op)),
    row(GL_DRAW_BUFFER, 1, Kind::Int, |gl, o| put_enum(o, gl.server.color_buffer.draw_buffer)),
    row(GL_COLOR_WRITEMASK, 4, Kind::Bool, |gl, o| put(o, &gl.server.color_buffer.color_write.map(u8::from))),
    row(GL_COLOR_CLEAR_VALUE, 4, Kind::Normalized, |gl, o| put(o, &gl.server.color_buffer.clear_color)),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_as_mesa_keeps_it() {
        let mut gl = Gl::new(4, 4);
        gl.blend_func(GL_SRC_ALPHA, 0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.alpha_func(0x1234, 0.5);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.logic_op(0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.begin(GL_POINTS);
        gl.clear_color(1.0, 1.0, 1.0, 1.0);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.push_attrib(GL_COLOR_BUFFER_BIT);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.enable(GL_BLEND);
        gl.logic_op(GL_XOR);
        gl.color_mask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        gl.clear_color(2.0, 0.5, -1.0, 1.0);
        let factors = gl.enabled_blend().map(|b| b.factors);
        assert_eq!(factors, Some([GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA]));
        let (mut mask, mut clear) = ([0; 4], [0.0; 4]);
        gl.get_integerv(GL_COLOR_WRITEMASK, &mut mask);
        gl.get_floatv(GL_COLOR_CLEAR_VALUE, &mut clear);
        assert_eq!((mask, clear), ([1, 0, 1, 0], [1.0, 0.5, 0.0, 1.0]));
        gl.pop_attrib();
        assert_eq!((gl.server.color_buffer, gl.enabled_blend()), (ColorBuffer::default(), None));
        // Compiled, not executed, then replayed.
        gl.new_list(1, GL_COMPILE);
        gl.alpha_func(GL_GREATER, 0.5);
        gl.end_list();
        assert_eq!(gl.server.color_buffer.alpha, (GL_ALWAYS, 0.0));
        gl.call_list(1);
        assert_eq!((gl.server.color_buffer.alpha, gl.get_error()), ((GL_GREATER, 0.5), GL_NO_ERROR));
    }
}
