//! The viewport attribute group (GL 1.1 spec §2.10.1; table 6.5; Mesa `main/viewport.c`):
//! `glViewport` and `glDepthRange`, in one struct as `GL_VIEWPORT_BIT` saves it, with the
//! group's display-list record and its `glGet` rows. A recorded primitive's
//! [`DrawState`](super::DrawState) carries both; the rasterisers map clip coordinates to the
//! window with them.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{int_limit, put, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// The largest viewport side (`GL_MAX_VIEWPORT_DIMS`): llvmpipe's, as Mesa 22.3 reports it.
/// `glViewport` clamps larger sizes to it, as Mesa's `_mesa_set_viewport` does.
pub(crate) const MAX_VIEWPORT_DIMS: i32 = 16384;

/// `GL_VIEWPORT_BIT`'s state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Viewport {
    /// `glViewport`: x, y, width, height (the sizes clamped to [`MAX_VIEWPORT_DIMS`]).
    pub rect: [i32; 4],
    /// `glDepthRange`: near, far, clamped to [0, 1].
    pub depth_range: [f32; 2],
}

impl Viewport {
    /// GL's initial viewport: the whole `width` × `height` drawable, depths over [0, 1].
    pub fn new(width: i32, height: i32) -> Self {
        Self { rect: [0, 0, width, height], depth_range: [0.0, 1.0] }
    }
}

/// A viewport call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ViewportCall {
    Viewport([GLint; 4]),
    DepthRange(GLdouble, GLdouble),
}

impl Gl {
    /// `glViewport`: a negative width or height → `GL_INVALID_VALUE`.
    pub fn viewport(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
        if self.compiled(|| ListCommand::Viewport(ViewportCall::Viewport([x, y, width, height]))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (width, height) = (width.min(MAX_VIEWPORT_DIMS), height.min(MAX_VIEWPORT_DIMS));
        self.server.viewport.rect = [x, y, width, height];
        self.touch_state();
    }

    /// `glDepthRange` (clamped to [0, 1] as GL does).
    pub fn depth_range(&mut self, near: GLdouble, far: GLdouble) {
        if self.compiled(|| ListCommand::Viewport(ViewportCall::DepthRange(near, far))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        self.server.viewport.depth_range = [near.clamp(0.0, 1.0) as f32, far.clamp(0.0, 1.0) as f32];
        self.touch_state();
    }

    /// `glGetIntegerv(GL_VIEWPORT)` for GLU, which loads its sampling matrices so
    /// (`glrenderer.cc`). Unlike `glGet`, it records no error inside `begin`/`end`.
    pub(crate) fn viewport_box(&self) -> [GLint; 4] {
        self.server.viewport.rect
    }

    /// Replays a listed viewport call.
    pub(crate) fn replay_viewport_call(&mut self, call: ViewportCall) {
        match call {
            ViewportCall::Viewport([x, y, w, h]) => self.viewport(x, y, w, h),
            ViewportCall::DepthRange(near, far) => self.depth_range(near, far),
        }
    }
}

/// The group's `glGet` rows, and the limit.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_VIEWPORT, 4, Kind::Int, |gl, o| put(o, &gl.server.viewport.rect)),
    row(GL_DEPTH_RANGE, 2, Kind::Normalized, |gl, o| put(o, &gl.server.viewport.depth_range)),
    int_limit!(GL_MAX_VIEWPORT_DIMS, MAX_VIEWPORT_DIMS, MAX_VIEWPORT_DIMS),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_as_mesa_keeps_it() {
        let mut gl = Gl::new(10, 20);
        gl.viewport(0, 0, -1, 1);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.push_attrib(GL_VIEWPORT_BIT);
        gl.viewport(1, 2, 100_000, 4);
        gl.depth_range(-1.0, 0.5);
        let (mut rect, mut range) = ([0; 4], [0.0; 2]);
        gl.get_integerv(GL_VIEWPORT, &mut rect);
        gl.get_doublev(GL_DEPTH_RANGE, &mut range);
        assert_eq!((rect, range), ([1, 2, MAX_VIEWPORT_DIMS, 4], [0.0, 0.5]));
        gl.pop_attrib();
        assert_eq!(gl.server.viewport, Viewport::new(10, 20));
        gl.new_list(1, GL_COMPILE);
        gl.depth_range(0.25, 0.75);
        gl.end_list();
        assert_eq!(gl.server.viewport.depth_range, [0.0, 1.0]);
        gl.call_list(1);
        assert_eq!((gl.server.viewport.depth_range, gl.get_error()), ([0.25, 0.75], GL_NO_ERROR));
    }
}
