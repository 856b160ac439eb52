//! `GL_EXT_packed_depth_stencil`'s pixel paths (GL 3.0 spec §4.3.1, §3.7.4; Mesa
//! `main/readpix.c`, `main/pack.c`, `state_tracker/st_cb_drawpixels.c`): `glReadPixels` and
//! `glDrawPixels` of `GL_DEPTH_STENCIL` in `GL_UNSIGNED_INT_24_8`, one 32-bit element a pixel,
//! the depth in its high 24 bits and the stencil index in its low 8.
//!
//! As Mesa 22.3 on llvmpipe does (measured: `capi/tests/depth_stencil.c` against Mesa):
//! - a read packs the depth buffer's 24-bit value as it is, or, under a depth scale or bias,
//!   that value as a float through the transfer, truncated back to 24 bits; the stencil index
//!   goes through the index shift and offset and `GL_MAP_STENCIL`, keeping its low 8 bits;
//! - a draw writes the image's depths and indices as they are (no transfer), through the depth
//!   mask, the stencil write mask, the scissor and the zoom, whatever the depth and stencil
//!   tests say, and leaves the colour buffers alone.

use super::consts::*;
use super::frame::Frame;
use super::pixel_packed::depth_stencil_size;
use super::pixel_zoom::zoomed_pixels;
use super::types::*;
use super::window_read::WindowImage;
use super::Gl;

/// The largest 24-bit depth.
const DEPTH_24_MAX: f32 = 16_777_215.0;

/// A depth of the window (in [0, 1], of 24 bits) as the 24-bit integer the buffer holds.
fn depth_24(d: f32) -> u32 {
    (f64::from(d.clamp(0.0, 1.0)) * f64::from(DEPTH_24_MAX)).round() as u32
}

impl Gl {
    /// `glReadPixels(x, y, width, height, GL_DEPTH_STENCIL, type, pixels)` into `out`: `window`
    /// draws what was recorded and returns the window's buffers and its stencil buffer (rows
    /// top to bottom). Errors, in Mesa's order: inside `begin`/`end` (`GL_INVALID_OPERATION`),
    /// a negative size (`GL_INVALID_VALUE`), a type other than `GL_UNSIGNED_INT_24_8` and
    /// `GL_ARB_depth_buffer_float`'s `GL_FLOAT_32_UNSIGNED_INT_24_8_REV` (`GL_INVALID_ENUM`), no stencil buffer (`GL_INVALID_OPERATION`), a non-empty `out`
    /// shorter than [`Gl::packed_image_len`] (`GL_INVALID_VALUE`). Pixels outside the window
    /// are left as they were.
    pub fn read_depth_stencil_pixels(
        &mut self,
        (x, y): (GLint, GLint),
        (width, height): (GLsizei, GLsizei),
        type_: GLenum,
        window: impl FnOnce(&Frame) -> Option<(WindowImage, Vec<u8>)>,
        out: &mut [u8],
    ) {
        if self.reject_inside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(size) = depth_stencil_size(type_) else { return self.set_error(GL_INVALID_ENUM) };
        if !self.window_has(GL_DEPTH_STENCIL) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let needed = self.packed_image_len(width, height, GL_DEPTH_STENCIL, type_).unwrap_or(usize::MAX);
        if needed == 0 || out.is_empty() {
            return;
        }
        if out.len() < needed {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some((image, stencil)) = window(self.frame()) else { return self.set_error(GL_OUT_OF_MEMORY) };
        let depths = self.depth_transfer();
        let identity = depths.scale == 1.0 && depths.bias == 0.0;
        let store = self.client.pixel_stores.pack;
        let (w, h) = (width as usize, height as usize);
        let stride = store.row_stride(w, 1, size);
        let first = store.first_byte(stride, size);
        let (ww, wh) = (i64::from(image.width), i64::from(image.height));
        for j in 0..h {
            for i in 0..w {
                let (wx, wy) = (i64::from(x) + i as i64, i64::from(y) + j as i64);
                let Some(d) = image.depth_at(wx, wy) else { continue };
                let Some(&s) = stencil.get(((wh - 1 - wy) * ww + wx) as usize) else { continue };
                let z = depth_24(d);
                let stencil = u32::from(self.stencil_index_transfer(s));
                // Words of the element in order, each swapped on its own.
                let words = if size == 8 {
                    // The buffer's 24-bit value as a float (measured: 0x3FFFFF reads as
                    // 0.24999996), through the transfer.
                    let depth = z as f32 / DEPTH_24_MAX;
                    let depth = if identity { depth } else { depths.apply(depth) };
                    [depth.to_bits(), stencil]
                } else if identity {
                    [z << 8 | stencil, 0]
                } else {
                    // Mesa unpacks the 24-bit value to a float, scales and biases it, and
                    // packs it back truncated (measured: 0x400000 at scale 0.5, bias 0.25,
                    // reads 0x5FFFFF).
                    [((depths.apply(z as f32 / DEPTH_24_MAX) * DEPTH_24_MAX) as u32) << 8 | stencil, 0]
                };
                let at = first + j * stride + i * size;
                for (k, word) in words.iter().take(size / 4).enumerate() {
                    let mut bytes = word.to_ne_bytes();
                    if store.swap_bytes {
                        bytes.reverse();
                    }
                    out[at + 4 * k..at + 4 * k + 4].copy_from_slice(&bytes);
                }
            }
        }
    }

    /// `glDrawPixels` of unpacked `GL_DEPTH_STENCIL` pixels (each the depth, then the stencil
    /// index), from the raster position on: the stencil indices as a `GL_STENCIL_INDEX` image
    /// writes them, the depths written untested, both through their masks, the scissor and the
    /// zoom, no transfer applied and no colour written (Mesa draws them with the depth
    /// function `GL_ALWAYS` and the colour writes off, `st_cb_drawpixels.c`; measured).
    pub(crate) fn draw_depth_stencil(&mut self, (width, height): (GLsizei, GLsizei), pixels: &[[f32; 4]]) {
        let [xr, yr, _, _] = self.server.raster_pos.window;
        let origin = [xr.round() as i32, yr.round() as i32];
        let window = (self.width().max(0) as u32, self.height().max(0) as u32);
        let (w, h) = (width as usize, height as usize);
        let color = self.server.raster_pos.color;
        let fragments: Vec<_> = zoomed_pixels(origin, self.zoom(), (w, h), window)
            .map(|((i, j), (x, y))| ([x as i32, y as i32], color, pixels[j * w + i][0].clamp(0.0, 1.0)))
            .collect();
        let state = self.depth_only_state();
        self.record_fragments_in(&fragments, state);
        let indices: Vec<[f32; 4]> = pixels.iter().map(|p| [p[1], 0.0, 0.0, 1.0]).collect();
        self.draw_stencil((width, height), &indices);
    }

    /// The packed copy's state ([`Gl::packed_copy_state`]: depth `GL_ALWAYS`, no stencil test)
    /// with no colour written.
    fn depth_only_state(&mut self) -> usize {
        let index = self.packed_copy_state();
        let mut state = self.recorder.frame.states[index].clone();
        state.fragment_tests.color_write = [false; 4];
        state.blend = None;
        state.alpha_test = None;
        self.recorder.frame.states.push(state);
        self.recorder.frame.states.len() - 1
    }

    /// A stencil index read back through the index shift and offset and, with
    /// `GL_MAP_STENCIL`, the `S_TO_S` map, its low 8 bits kept (GL 1.1 §3.6.3; Mesa
    /// `_mesa_apply_stencil_transfer_ops`; measured: 0x33 under shift 1 and offset 3 reads
    /// 0x69, 0x99 reads 0x35).
    pub(crate) fn stencil_index_transfer(&self, s: u8) -> u8 {
        let (shift, offset, map) = self.stencil_transfer_params();
        let mut v = i64::from(s);
        if shift >= 0 {
            v = (v << shift.min(32)) + i64::from(offset);
        } else {
            v = (v >> (-shift).min(32)) + i64::from(offset);
        }
        if let Some(map) = map {
            let mask = map.len() as i64 - 1;
            v = map.get((v & mask) as usize).map_or(0, |&m| m as i64);
        }
        (v & 0xFF) as u8
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2 × 1 window with a stencil buffer: depths 0.25 and 0.75, stencil 0x33 and 0x99.
    fn window() -> Option<(WindowImage, Vec<u8>)> {
        let image =
            WindowImage { width: 2, height: 1, color: vec![0; 8], depth: vec![0.25, 0.75], samples: Vec::new() };
        Some((image, vec![0x33, 0x99]))
    }

    fn gl_with_stencil(stencil_bits: u8) -> Gl {
        let mut gl = Gl::new(2, 1);
        gl.set_buffer_config(crate::gl::BufferConfig { stencil_bits, ..gl.buffer_config() });
        gl
    }

    #[test]
    fn reads_pack_depth_over_stencil() {
        let mut gl = gl_with_stencil(8);
        let mut out = [0u8; 8];
        gl.read_depth_stencil_pixels((0, 0), (2, 1), GL_UNSIGNED_INT_24_8, |_| window(), &mut out);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(out[..4], 0x4000_0033u32.to_ne_bytes());
        assert_eq!(out[4..], 0xBFFF_FF99u32.to_ne_bytes());
        // Mesa's numbers (capi/tests/depth_stencil.c): scale 0.5, bias 0.25, shift 1, offset 3.
        gl.pixel_transferf(GL_DEPTH_SCALE, 0.5);
        gl.pixel_transferf(GL_DEPTH_BIAS, 0.25);
        gl.pixel_transferi(GL_INDEX_SHIFT, 1);
        gl.pixel_transferi(GL_INDEX_OFFSET, 3);
        gl.read_depth_stencil_pixels((0, 0), (2, 1), GL_UNSIGNED_INT_24_8, |_| window(), &mut out);
        assert_eq!(out[..4], 0x5FFF_FF69u32.to_ne_bytes());
        assert_eq!(out[4..], 0x9FFF_FF35u32.to_ne_bytes());
    }

    #[test]
    fn read_errors_in_mesas_order() {
        let mut gl = gl_with_stencil(8);
        let mut out = [0u8; 8];
        gl.read_depth_stencil_pixels((0, 0), (-1, 1), GL_FLOAT, |_| window(), &mut out);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.read_depth_stencil_pixels((0, 0), (1, 1), GL_FLOAT, |_| window(), &mut out);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.read_depth_stencil_pixels((0, 0), (2, 1), GL_UNSIGNED_INT_24_8, |_| window(), &mut out[..7]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        let mut plain = gl_with_stencil(0);
        plain.read_depth_stencil_pixels((0, 0), (1, 1), GL_UNSIGNED_INT_24_8, |_| window(), &mut out);
        assert_eq!(plain.get_error(), GL_INVALID_OPERATION);
    }
}
