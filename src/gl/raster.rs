//! Rasterisation state and framebuffer calls: viewport, point size, line width, polygon mode,
//! face culling, depth function and `glClear`.

use super::consts::*;
use super::frame::Command;
use super::lists::ListCommand;
use super::types::*;
use super::Gl;

/// The largest viewport side (`GL_MAX_VIEWPORT_DIMS`): llvmpipe's, as Mesa 22.3 reports it.
/// `glViewport` clamps larger sizes to it, as Mesa's `_mesa_set_viewport` does.
pub(crate) const MAX_VIEWPORT_DIMS: i32 = 16384;

/// GL's rasterisation state with its initial values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RasterState {
    pub viewport: [i32; 4],
    pub depth_range: [f32; 2],
    pub shade_model: GLenum,
    /// `glClipPlane`: the planes in eye coordinates, as transformed at the call.
    pub clip_planes: [[f32; 4]; super::clip::MAX_CLIP_PLANES],
    /// `glPolygonStipple`: row y, bit x for window pixel (x, y) modulo 32.
    pub polygon_stipple: [u32; 32],
}

impl RasterState {
    pub fn new(width: i32, height: i32) -> Self {
        Self {
            viewport: [0, 0, width, height],
            depth_range: [0.0, 1.0],
            shade_model: GL_SMOOTH,
            clip_planes: [[0.0; 4]; super::clip::MAX_CLIP_PLANES],
            polygon_stipple: [u32::MAX; 32],
        }
    }
}

impl Gl {
    /// `glViewport`: a negative width or height → `GL_INVALID_VALUE`.
    pub fn viewport(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
        if self.compiled(|| ListCommand::Viewport([x, y, width, height])) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (width, height) = (width.min(MAX_VIEWPORT_DIMS), height.min(MAX_VIEWPORT_DIMS));
        self.server.raster.viewport = [x, y, width, height];
        self.touch_state();
    }

    /// `glDepthRange` (clamped to [0, 1] as GL does).
    pub fn depth_range(&mut self, near: GLdouble, far: GLdouble) {
        if self.compiled(|| ListCommand::DepthRange(near, far)) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        self.server.raster.depth_range = [near.clamp(0.0, 1.0) as f32, far.clamp(0.0, 1.0) as f32];
        self.touch_state();
    }

    /// `glGetIntegerv(GL_VIEWPORT)` for GLU, which loads its sampling matrices so
    /// (`glrenderer.cc`). Unlike `glGet`, it records no error inside `begin`/`end`.
    pub(crate) fn viewport_box(&self) -> [GLint; 4] {
        self.server.raster.viewport
    }

    /// `glClear`: bits other than colour, depth, stencil and accum → `GL_INVALID_VALUE`.
    /// Records a clear of the whole drawable (no scissor), as GL does.
    pub fn clear(&mut self, mask: GLbitfield) {
        if self.compiled(|| ListCommand::Clear(mask)) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
        if mask & !known != 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (color, depth) = (self.server.color_buffer.clear_color, self.server.depth.clear);
        let (stencil, accum, tests) = (self.server.stencil.clear, self.server.clear_accum, self.fragment_tests());
        self.recorder.frame.commands.push(Command::Clear { mask, color, depth, stencil, accum, tests });
    }

    /// `glFlush`: the recording is already complete; nothing to do.
    pub fn flush(&mut self) {
        self.reject_inside_begin_end();
    }

    /// `glFinish`: as [`Gl::flush`].
    pub fn finish(&mut self) {
        self.reject_inside_begin_end();
    }
}
