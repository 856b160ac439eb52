//! The depth buffer attribute group (GL 1.1 spec §4.1.5 the depth test, §4.2.2 the write mask,
//! §4.2.3 the clear value; table 6.12–6.13; Mesa `main/depth.c`): `glDepthFunc`, `glDepthMask`,
//! `glClearDepth`, in one struct as `GL_DEPTH_BUFFER_BIT` saves it, with the group's display-list
//! record, its `glGet` rows and its part of `glPushAttrib`. The enable (`GL_DEPTH_TEST`) is a
//! capability; a recorded primitive's [`DrawState`](super::DrawState) carries the test and the
//! mask, and both rasterisers apply them.
//!
//! This file is the pattern for a state call: the state, the call (list gate, then Mesa's
//! checks in Mesa's order, then the state and `touch_state` when a draw sees it), the call's
//! list record and replay, the `glGet` rows and the attribute group, side by side.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put_enum, put_flag, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// `GL_DEPTH_BUFFER_BIT`'s state (its enable aside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Depth {
    /// `glDepthFunc`: `GL_NEVER` .. `GL_ALWAYS`.
    pub func: GLenum,
    /// `glDepthMask`: whether fragments that pass the test write their depth.
    pub write: bool,
    /// `glClearDepth`, clamped to [0, 1].
    pub clear: f32,
}

impl Default for Depth {
    fn default() -> Self {
        Self { func: GL_LESS, write: true, clear: 1.0 }
    }
}

/// A depth call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum DepthCall {
    Func(GLenum),
    Mask(GLboolean),
    Clear(GLdouble),
}

/// The enables GL files under the group (GL 1.1 table 6.12).
pub(crate) const DEPTH_ENABLES: &[GLenum] = &[GL_DEPTH_TEST];

impl Gl {
    /// `glDepthFunc`: the comparison (`GL_NEVER` .. `GL_ALWAYS`, else `GL_INVALID_ENUM`) the
    /// depth test makes while `GL_DEPTH_TEST` is on.
    pub fn depth_func(&mut self, func: GLenum) {
        if self.compiled_state_call(|| ListCommand::Depth(DepthCall::Func(func))) {
            return;
        }
        if !(GL_NEVER..=GL_ALWAYS).contains(&func) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.depth.func = func;
        self.touch_state();
    }

    /// `glDepthMask`: whether fragments that pass the depth test write their depth.
    pub fn depth_mask(&mut self, flag: GLboolean) {
        if self.compiled_state_call(|| ListCommand::Depth(DepthCall::Mask(flag))) {
            return;
        }
        self.server.depth.write = flag != GL_FALSE;
        self.touch_state();
    }

    /// `glClearDepth` (clamped to [0, 1]): what `glClear`'s depth bit writes. No draw reads it,
    /// so the draw state is not touched.
    pub fn clear_depth(&mut self, depth: GLdouble) {
        if self.compiled_state_call(|| ListCommand::Depth(DepthCall::Clear(depth))) {
            return;
        }
        self.server.depth.clear = depth.clamp(0.0, 1.0) as f32;
    }

    /// Replays a listed depth call.
    pub(crate) fn replay_depth_call(&mut self, call: DepthCall) {
        match call {
            DepthCall::Func(func) => self.depth_func(func),
            DepthCall::Mask(flag) => self.depth_mask(flag),
            DepthCall::Clear(depth) => self.clear_depth(depth),
        }
    }
}

/// The group's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_DEPTH_FUNC, 1, Kind::Int, |gl, o| put_enum(o, gl.server.depth.func)),
    row(GL_DEPTH_WRITEMASK, 1, Kind::Bool, |gl, o| put_flag(o, gl.server.depth.write)),
    row(GL_DEPTH_CLEAR_VALUE, 1, Kind::Normalized, |gl, o| o[0] = gl.server.depth.clear.into()),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_as_mesa_keeps_it() {
        let mut gl = Gl::new(4, 4);
        gl.depth_func(0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.begin(GL_POINTS);
        gl.depth_mask(GL_FALSE);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.push_attrib(GL_DEPTH_BUFFER_BIT);
        gl.depth_func(GL_GEQUAL);
        gl.depth_mask(GL_FALSE);
        gl.clear_depth(2.0);
        let (mut func, mut mask, mut clear) = ([0], [1], [0.0]);
        gl.get_integerv(GL_DEPTH_FUNC, &mut func);
        gl.get_booleanv(GL_DEPTH_WRITEMASK, &mut mask);
        gl.get_doublev(GL_DEPTH_CLEAR_VALUE, &mut clear);
        assert_eq!((func[0] as GLenum, mask[0], clear[0]), (GL_GEQUAL, GL_FALSE, 1.0));
        gl.pop_attrib();
        assert_eq!(gl.server.depth, Depth::default());
        // Compiled, not executed, then replayed.
        gl.new_list(1, GL_COMPILE);
        gl.depth_func(GL_ALWAYS);
        gl.end_list();
        assert_eq!(gl.server.depth.func, GL_LESS);
        gl.call_list(1);
        assert_eq!((gl.server.depth.func, gl.get_error()), (GL_ALWAYS, GL_NO_ERROR));
    }
}
