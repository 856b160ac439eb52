//! `glReadPixels` of `GL_STENCIL_INDEX` (GL 1.1 spec §4.3.2; Mesa `main/readpix.c`): the stencil
//! values of a rectangle, converted to the caller's type and laid out with the pack modes. As
//! for colour (`read_pixels.rs`), the caller that owns a rasteriser hands in a closure that
//! draws the frame recorded so far and returns the window's stencil buffer (one byte a pixel,
//! rows top to bottom). Each index goes through the index shift and offset and
//! `GL_MAP_STENCIL` first, keeping 8 bits, as Mesa's `_mesa_pack_stencil_span` takes it
//! (measured: 0xCC under shift 1 and offset 3 reads 155, `capi/tests/depth_stencil.c`).

use super::consts::*;
use super::frame::Frame;
use super::pixel_unpack::{element_size as type_size, format_and_type_error};
use super::types::*;
use super::Gl;

/// A stencil index as `type_` stores it (native byte order): the integer itself, or as a float
/// (measured on Mesa 22.3: 255 reads back as 255.0 in `GL_FLOAT`).
fn encode(s: u8, type_: GLenum) -> Vec<u8> {
    match type_ {
        GL_UNSIGNED_BYTE | GL_BYTE => vec![s],
        GL_UNSIGNED_SHORT | GL_SHORT => u16::from(s).to_ne_bytes().to_vec(),
        GL_UNSIGNED_INT | GL_INT => u32::from(s).to_ne_bytes().to_vec(),
        _ => f32::from(s).to_ne_bytes().to_vec(),
    }
}

impl Gl {
    /// `glReadPixels(x, y, width, height, GL_STENCIL_INDEX, type, pixels)` into `out`: `window`
    /// draws what was recorded and returns the stencil buffer, rows top to bottom. Errors, in
    /// Mesa's order: inside `begin`/`end` (`GL_INVALID_OPERATION`), a negative size
    /// (`GL_INVALID_VALUE`), a packed type (`GL_INVALID_OPERATION`), an unknown type
    /// (`GL_INVALID_ENUM`), no stencil buffer (`GL_INVALID_OPERATION`), a non-empty `out`
    /// shorter than [`Gl::packed_image_len`] (`GL_INVALID_VALUE`). Pixels outside the window are
    /// left as they were.
    pub fn read_stencil_pixels(
        &mut self,
        (x, y): (GLint, GLint),
        (width, height): (GLsizei, GLsizei),
        type_: GLenum,
        window: impl FnOnce(&Frame) -> Option<Vec<u8>>,
        out: &mut [u8],
    ) {
        if self.reject_inside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        // A packed type is GL_INVALID_OPERATION with any index format (Mesa's
        // `_mesa_error_check_format_and_type`, measured in pack_types.calls).
        if let Some(error) = format_and_type_error(GL_STENCIL_INDEX, type_) {
            return self.set_error(error);
        }
        let Some(size) = type_size(type_) else { return self.set_error(GL_INVALID_ENUM) };
        if self.server.framebuffer.stencil_bits == 0 {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let needed = self.packed_image_len(width, height, GL_STENCIL_INDEX, type_).unwrap_or(usize::MAX);
        if needed == 0 || out.is_empty() {
            return;
        }
        if out.len() < needed {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (ww, wh) = (self.width(), self.height());
        let Some(stencil) = window(self.frame()) else { return self.set_error(GL_OUT_OF_MEMORY) };
        let store = self.client.pixel_stores.pack;
        let (w, h) = (width as usize, height as usize);
        let stride = store.row_stride(w, 1, size);
        let first = store.first_byte(stride, size);
        for j in 0..h {
            for i in 0..w {
                let (wx, wy) = (x.saturating_add(i as i32), y.saturating_add(j as i32));
                if !(0..ww).contains(&wx) || !(0..wh).contains(&wy) {
                    continue;
                }
                let Some(&s) = stencil.get((wh - 1 - wy) as usize * ww as usize + wx as usize) else { continue };
                let mut bytes = encode(self.stencil_index_transfer(s), type_);
                if store.swap_bytes {
                    bytes.reverse();
                }
                let at = first + j * stride + i * size;
                out[at..at + size].copy_from_slice(&bytes);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::BufferConfig;

    #[test]
    fn reads_bottom_up_and_mesa_s_errors() {
        let mut gl = Gl::new(2, 2);
        // Rows top first: the bottom row holds 1, 2.
        let window = || Some(vec![3, 4, 1, 2]);
        let mut out = [9u8; 2];
        gl.read_stencil_pixels((0, 0), (2, 1), GL_UNSIGNED_BYTE, |_| window(), &mut out);
        assert_eq!((out, gl.get_error()), ([1, 2], GL_NO_ERROR));
        let mut f = [0u8; 4];
        gl.read_stencil_pixels((1, 1), (1, 1), GL_FLOAT, |_| window(), &mut f);
        assert_eq!(f32::from_ne_bytes(f), 4.0);
        gl.read_stencil_pixels((0, 0), (1, 1), 0x1234, |_| window(), &mut out);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.set_buffer_config(BufferConfig { stencil_bits: 0, ..BufferConfig::default() });
        gl.read_stencil_pixels((0, 0), (1, 1), GL_UNSIGNED_BYTE, |_| window(), &mut out);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    }
}
