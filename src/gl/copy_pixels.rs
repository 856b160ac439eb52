//! `glCopyPixels` (GL 1.1 spec §4.3.3; Mesa `main/drawpix.c`, `st_cb_drawpixels.c`): a
//! rectangle of the window copied to the raster position, as if read with `glReadPixels` and
//! drawn with `glDrawPixels` (pixel transfer, zoom, and the fragment operations of a draw).
//!
//! The copy reads the framebuffer as drawn so far, so it cannot run when the call is made: it
//! is recorded as one frame command ([`Command::CopyPixels`] naming a [`PixelCopy`]) that each
//! rasteriser executes in program order: it reads its own buffers at that point of the frame
//! into a [`WindowImage`], asks [`PixelCopy::fragments`] for the fragments (all of GL's rules
//! are here), and draws them through its per-fragment stages with the copy's draw state. A new
//! kind of buffer (the stencil buffer) is one more [`WindowImage`] plane and one more arm of
//! [`PixelCopy::fragments`].

use super::consts::*;
use super::frame::Command;
use super::lists::ListCommand;
use super::pixel_transfer::{ColorTransfer, DepthTransfer};
use super::pixel_zoom::zoomed_pixels;
use super::types::*;
use super::window_read::WindowImage;
use super::Gl;
use std::sync::Arc;

/// A `glCopyPixels` as a frame holds it.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelCopy {
    /// The source rectangle: x, y (window, origin bottom-left), width, height.
    pub source: [i32; 4],
    /// Where its first pixel goes: the raster position rounded as Mesa rounds it.
    pub origin: [i32; 2],
    /// `glPixelZoom`'s factors.
    pub zoom: [f32; 2],
    /// `GL_COLOR`, `GL_DEPTH` or `GL_STENCIL`.
    pub buffer: GLenum,
    /// `glDrawPixels` of `GL_STENCIL_INDEX`: the stencil values written, `source`'s width ×
    /// height row by row from the bottom, in place of the window's (GL writes drawn stencil
    /// indices straight into the stencil buffer, as a stencil copy does, §4.3.3).
    pub stencil_values: Option<Arc<Vec<u8>>>,
    /// The raster position's window depth: every fragment's depth in a colour copy.
    pub depth: f32,
    /// The raster colour: every fragment's colour in a depth copy.
    pub color: [f32; 4],
    /// The colour transfer in force at the call, if any.
    pub color_transfer: Option<Arc<ColorTransfer>>,
    /// The depth scale and bias at the call.
    pub depth_transfer: DepthTransfer,
    /// Index in [`super::Frame::states`] of the draw state of its fragments (the depth test,
    /// blending, the alpha test; window coordinates).
    pub state: usize,
    /// Whether Mesa copies this one with a blit (a plain colour copy: zoom 1, no transfer, no
    /// blending, alpha or depth test): then source pixels outside the window copy nothing.
    /// Otherwise Mesa draws the whole rectangle from a texture that holds what it could read,
    /// and transparent black (depth 0) elsewhere (measured with a source half outside).
    pub blit: bool,
}

/// One fragment a copy makes: window pixel (x, y from the bottom), colour, depth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CopyFragment {
    /// Window column and row (row 0 at the bottom).
    pub pixel: [u32; 2],
    /// RGBA, clamped to [0, 1].
    pub color: [f32; 4],
    /// Window depth in [0, 1].
    pub depth: f32,
}

impl PixelCopy {
    /// The fragments the copy draws into `window`, read from `window` (GL reads the whole
    /// source before it writes: overlapping copies see the old pixels). Work is bounded by the
    /// window's size.
    #[must_use]
    pub fn fragments(&self, window: &WindowImage) -> Vec<CopyFragment> {
        let [sx, sy, w, h] = self.source;
        let (Ok(w), Ok(h)) = (usize::try_from(w), usize::try_from(h)) else { return Vec::new() };
        if self.buffer == GL_STENCIL {
            // Written into the stencil buffer by the rasteriser itself (`Framebuffer::copy_stencil`).
            return Vec::new();
        }
        let size = (window.width, window.height);
        let mut out = Vec::new();
        for ((i, j), (x, y)) in zoomed_pixels(self.origin, self.zoom, (w, h), size) {
            let (px, py) = (i64::from(sx) + i as i64, i64::from(sy) + j as i64);
            let color = window.color_at(px, py);
            if color.is_none() && self.blit {
                continue;
            }
            let (color, depth) = match self.buffer {
                GL_DEPTH => (self.color, self.depth_transfer.apply(window.depth_at(px, py).unwrap_or(0.0))),
                _ => {
                    let c = color.unwrap_or([0.0; 4]);
                    (self.color_transfer.as_ref().map_or(c, |t| t.apply(c)), self.depth)
                }
            };
            out.push(CopyFragment { pixel: [x, y], color: color.map(|c| c.clamp(0.0, 1.0)), depth });
        }
        out
    }
}

impl Gl {
    /// `glCopyPixels(x, y, width, height, type)`: copies the window rectangle at (`x`, `y`) to the
    /// raster position, colours (`GL_COLOR`: through the pixel transfer, at the raster depth),
    /// depths (`GL_DEPTH`: through the depth scale and bias, in the raster colour), stencil
    /// indices (`GL_STENCIL`) or depths and stencil indices (`GL_DEPTH_STENCIL`), zoomed by
    /// `glPixelZoom`. Errors, in Mesa's order: inside `begin`/`end` → `GL_INVALID_OPERATION`; a
    /// negative size → `GL_INVALID_VALUE`; a type other than `GL_COLOR`, `GL_DEPTH`,
    /// `GL_STENCIL`, `GL_DEPTH_STENCIL` → `GL_INVALID_ENUM`; a buffer the window lacks (the
    /// stencil buffer) → `GL_INVALID_OPERATION`. Nothing is drawn with an invalid raster
    /// position; in feedback mode a `GL_COPY_PIXEL_TOKEN` is returned instead. Compiled into
    /// display lists.
    pub fn copy_pixels(&mut self, x: GLint, y: GLint, width: GLsizei, height: GLsizei, type_: GLenum) {
        if self.compiled_state_call(|| ListCommand::CopyPixels([x, y, width, height], type_)) {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        if !matches!(type_, GL_COLOR | GL_DEPTH | GL_STENCIL | GL_DEPTH_STENCIL) {
            return self.set_error(GL_INVALID_ENUM);
        }
        if !self.window_has(type_) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if !self.server.raster_pos.valid || width == 0 || height == 0 || self.feedback_raster_token(GL_COPY_PIXEL_TOKEN)
        {
            return;
        }
        // GL_DEPTH_STENCIL (EXT_packed_depth_stencil) copies the depths, then the stencil
        // indices (which a stencil copy writes untested), of the same rectangle. As Mesa 22.3
        // copies them (measured, `tests/it/pixel_properties.rs`), neither the depth test nor
        // the stencil test applies to the depths.
        let source = [x, y, width, height];
        if type_ == GL_DEPTH_STENCIL {
            self.record_pixel_copy(source, GL_DEPTH, true);
            self.record_pixel_copy(source, GL_STENCIL, true);
        } else {
            self.record_pixel_copy(source, type_, false);
        }
    }

    /// Records the copy of `source` from `buffer` (`GL_COLOR`, `GL_DEPTH` or `GL_STENCIL`) to
    /// the raster position, with the state in force now; `packed`: a half of a
    /// `GL_DEPTH_STENCIL` copy.
    fn record_pixel_copy(&mut self, source: [GLint; 4], buffer: GLenum, packed: bool) {
        let [xr, yr, depth, _] = self.server.raster_pos.window;
        let (zoom, color_transfer) = (self.zoom(), self.draw_color_transfer());
        let tests = self.capability(GL_DEPTH_TEST) || self.capability(GL_BLEND) || self.capability(GL_ALPHA_TEST);
        let copy = PixelCopy {
            source,
            origin: [xr.round() as i32, yr.round() as i32],
            zoom,
            buffer,
            depth,
            color: self.server.raster_pos.color.map(|c| c.clamp(0.0, 1.0)),
            blit: buffer == GL_COLOR && zoom == [1.0, 1.0] && color_transfer.is_none() && !tests,
            color_transfer,
            depth_transfer: self.depth_transfer(),
            state: if packed { self.packed_copy_state() } else { self.window_state() },
            stencil_values: None,
        };
        self.recorder.frame.pixel_copies.push(copy);
        self.recorder.frame.commands.push(Command::CopyPixels(self.recorder.frame.pixel_copies.len() - 1));
    }

    /// [`Gl::window_state`] for the halves of a `GL_DEPTH_STENCIL` copy, as Mesa 22.3 draws
    /// them (measured): without the stencil test, and with the depth test `GL_ALWAYS` whatever
    /// the program set, on or off (the depths are written, through the depth mask).
    pub(crate) fn packed_copy_state(&mut self) -> usize {
        let index = self.window_state();
        let mut state = self.recorder.frame.states[index].clone();
        if state.fragment_tests.stencil.is_none() && state.depth_test == Some(GL_ALWAYS) {
            return index;
        }
        state.fragment_tests.stencil = None;
        state.depth_test = Some(GL_ALWAYS);
        self.recorder.frame.states.push(state);
        self.recorder.frame.states.len() - 1
    }

    /// `glDrawPixels` of stencil indices once unpacked: each index truncated to its low 8 bits
    /// into the stencil buffer from the raster position on, zoomed, under the scissor and the
    /// stencil write mask, as a stencil copy is executed (the depth and stencil tests do not
    /// apply, GL 1.1 §4.3.3). As Mesa 22.3 (measured, `tests/it/pixel_properties.rs`), the
    /// index shift and offset and `GL_MAP_STENCIL`, which GL 1.1 §3.6.3 applies, are not.
    pub(crate) fn draw_stencil(&mut self, (width, height): (GLsizei, GLsizei), indices: &[[f32; 4]]) {
        let low_bits = |index: f32| if index.is_finite() { (index.trunc() as i64 & 0xFF) as u8 } else { 0 };
        let values: Vec<u8> = indices.iter().map(|c| low_bits(c[0])).collect();
        let [xr, yr, depth, _] = self.server.raster_pos.window;
        let copy = PixelCopy {
            source: [0, 0, width, height],
            origin: [xr.round() as i32, yr.round() as i32],
            zoom: self.zoom(),
            buffer: GL_STENCIL,
            depth,
            color: self.server.raster_pos.color.map(|c| c.clamp(0.0, 1.0)),
            blit: false,
            color_transfer: None,
            depth_transfer: self.depth_transfer(),
            state: self.window_state(),
            stencil_values: Some(Arc::new(values)),
        };
        self.recorder.frame.pixel_copies.push(copy);
        self.recorder.frame.commands.push(Command::CopyPixels(self.recorder.frame.pixel_copies.len() - 1));
    }

    /// Whether the window has the buffers `glCopyPixels` names: colour and depth always (both
    /// rasterisers keep a depth buffer); stencil indices where the window has a stencil buffer.
    pub(crate) fn window_has(&self, type_: GLenum) -> bool {
        match type_ {
            GL_COLOR | GL_DEPTH => true,
            GL_STENCIL | GL_DEPTH_STENCIL => self.buffer_config().stencil_bits > 0,
            _ => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 4 × 2 window: red, green, blue, white on the bottom row, black above; depths 0.1 .. 0.8.
    fn window() -> WindowImage {
        let top = [0u8, 0, 0, 255].repeat(4);
        let bottom = [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 255, 255]].concat();
        let depth = vec![0.5, 0.6, 0.7, 0.8, 0.1, 0.2, 0.3, 0.4];
        WindowImage { width: 4, height: 2, color: [top, bottom].concat(), depth, samples: Vec::new() }
    }

    fn copy(source: [i32; 4], origin: [i32; 2], buffer: GLenum) -> PixelCopy {
        PixelCopy {
            source,
            origin,
            zoom: [1.0; 2],
            buffer,
            depth: 0.25,
            color: [0.0, 0.0, 1.0, 1.0],
            color_transfer: None,
            depth_transfer: DepthTransfer { scale: 1.0, bias: 0.0 },
            state: 0,
            blit: buffer == GL_COLOR,
            stencil_values: None,
        }
    }

    #[test]
    fn colour_copies_take_the_raster_depth_and_depth_copies_the_raster_colour() {
        let f = copy([0, 0, 2, 1], [2, 1], GL_COLOR).fragments(&window());
        assert_eq!(f.len(), 2);
        assert_eq!((f[0].pixel, f[0].color, f[0].depth), ([2, 1], [1.0, 0.0, 0.0, 1.0], 0.25));
        assert_eq!(f[1].color, [0.0, 1.0, 0.0, 1.0]);
        let mut d = copy([1, 0, 2, 1], [0, 1], GL_DEPTH);
        d.depth_transfer.bias = 0.5;
        let f = d.fragments(&window());
        assert_eq!(f.iter().map(|f| f.depth).collect::<Vec<_>>(), [0.7, 0.8]);
        assert_eq!(f[0].color, [0.0, 0.0, 1.0, 1.0]);
    }

    #[test]
    fn sources_outside_the_window_blit_nothing_or_draw_black() {
        let f = copy([-1, 0, 2, 1], [0, 1], GL_COLOR).fragments(&window());
        assert_eq!(f.iter().map(|f| f.pixel).collect::<Vec<_>>(), [[1, 1]], "the blit skips x = −1");
        let mut zoomed = copy([-1, 0, 2, 1], [0, 1], GL_COLOR);
        (zoomed.zoom, zoomed.blit) = ([2.0, 1.0], false);
        let f = zoomed.fragments(&window());
        assert_eq!(f.len(), 4);
        assert_eq!(f[0].color, [0.0; 4], "Mesa's texture holds zeros where it read nothing");
    }

    #[test]
    fn copies_check_in_mesas_order_and_record_one_command() {
        let mut gl = Gl::new(8, 8);
        gl.copy_pixels(0, 0, -1, 1, 0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.copy_pixels(0, 0, 1, 1, 0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        // A window without a stencil buffer (a context with one copies: pixel_properties.rs).
        gl.set_buffer_config(crate::gl::BufferConfig { stencil_bits: 0, accum_bits: 0, double: false });
        gl.copy_pixels(0, 0, 1, 1, GL_STENCIL);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.begin(GL_POINTS);
        gl.copy_pixels(0, 0, 1, 1, GL_COLOR);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.raster_pos2f(0.0, 0.0);
        gl.pixel_zoom(2.0, -1.0);
        gl.copy_pixels(1, 2, 3, 4, GL_COLOR);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.frame();
        assert_eq!(frame.commands.last(), Some(&Command::CopyPixels(0)));
        let c = &frame.pixel_copies[0];
        assert_eq!((c.source, c.origin, c.zoom), ([1, 2, 3, 4], [4, 4], [2.0, -1.0]));
    }
}
