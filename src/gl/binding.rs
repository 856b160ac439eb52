//! What a binding from another language needs of the context (the C ABI, crate `gleval-c`).
//!
//! How many bytes of client memory a call reads (GL 1.1 spec §3.6.3 "Unpacking", §3.6.4
//! bitmaps, §5.4 `glCallLists`): what a C caller promises to have at the pointer it passes.
//! The Rust façade takes slices and checks their length; a C binding has only a pointer and
//! must know how far it may read before it makes the slice. The answer depends on the unpack
//! modes (`glPixelStore`), which are GL state, so it lives here. And `GL_OUT_OF_MEMORY`, GL's
//! answer when the implementation could not carry out a call.

use super::consts::*;
use super::pixel_packed::packed;
use super::pixel_unpack::{element_size as type_size, format_components};
use super::types::*;
use super::Gl;

/// Bytes per name of a `glCallLists` type (`GL_2_BYTES` .. `GL_4_BYTES` included).
fn list_name_size(type_: GLenum) -> Option<usize> {
    match type_ {
        GL_2_BYTES => Some(2),
        GL_3_BYTES => Some(3),
        GL_4_BYTES => Some(4),
        _ => type_size(type_),
    }
}

impl Gl {
    /// Bytes GL reads for a `width` × `height` image of `format` and `type_` (`glTexImage2D`,
    /// `glTexSubImage2D`, `glDrawPixels`, `gluBuild2DMipmaps`) with the current unpack modes:
    /// the skipped rows and pixels, the padded rows, and the last row up to its last pixel.
    /// `None` when GL reads nothing because it rejects the call (a negative size, an unknown
    /// format or type); `Some(0)` for an empty image.
    #[must_use]
    pub fn unpacked_image_len(&self, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum) -> Option<usize> {
        let (w, h) = (usize::try_from(width).ok()?, usize::try_from(height).ok()?);
        // GL 3.0's packed depth and stencil, which a depth texture takes (4 bytes a pixel).
        let (format, type_) = super::texture::depth_of_depth_stencil(format, type_);
        if type_ == GL_BITMAP {
            // Indices one bit a pixel, laid out as a bitmap (GL 1.1 §3.6.3).
            format_components(format)?;
            return self.unpacked_bitmap_len(width, height);
        }
        // A packed type is one element a pixel, whatever the format's component count.
        let (components, size) = match (packed(type_), type_ == GL_FLOAT_32_UNSIGNED_INT_24_8_REV) {
            (Some(p), _) => (format_components(format).map(|_| 1)?, p.size),
            (None, true) => (format_components(format).map(|_| 1)?, 8),
            (None, false) => (format_components(format)?, type_size(type_)?),
        };
        if w == 0 || h == 0 {
            return Some(0);
        }
        let store = self.unpack_store();
        let stride = store.row_stride(w, components, size);
        let first = store.first_byte(stride, components * size);
        first.checked_add((h - 1).checked_mul(stride)?)?.checked_add(w * components * size)
    }

    /// Bytes GL reads for a `glTexImage3D` or `glTexSubImage3D` image of `width` × `height` ×
    /// `depth` with the current unpack modes (GL 1.2 §3.8.1: the images after the skipped ones,
    /// [`Gl::unpacked_image_len`] each, an image height apart); `None` for a negative size or
    /// a format or type GL rejects.
    #[must_use]
    pub fn unpacked_image_3d_len(
        &self,
        (width, height, depth): (GLsizei, GLsizei, GLsizei),
        format: GLenum,
        type_: GLenum,
    ) -> Option<usize> {
        let image = self.unpacked_image_len(width, height, format, type_)?;
        let (w, h, d) = (usize::try_from(width).ok()?, usize::try_from(height).ok()?, usize::try_from(depth).ok()?);
        if image == 0 || d == 0 {
            return Some(0);
        }
        let store = self.unpack_store();
        let stride = super::pixel_unpack::image_stride(store, (w, h), format, type_)?;
        (store.skip_images + d - 1).checked_mul(stride)?.checked_add(image)
    }

    /// Bytes GL reads for a `glBitmap` of `width` × `height` bits with the current unpack modes;
    /// `None` for a negative size.
    #[must_use]
    pub fn unpacked_bitmap_len(&self, width: GLsizei, height: GLsizei) -> Option<usize> {
        let (w, h) = (usize::try_from(width).ok()?, usize::try_from(height).ok()?);
        if w == 0 || h == 0 {
            return Some(0);
        }
        let store = self.unpack_store();
        let stride = store.bitmap_row_stride(w);
        let first = store.skip_rows.checked_mul(stride)?;
        first.checked_add((h - 1).checked_mul(stride)?)?.checked_add((store.skip_pixels + w).div_ceil(8))
    }

    /// Records `GL_OUT_OF_MEMORY` (unless an earlier error is pending): a binding's answer when
    /// a call could not be carried out, e.g. the C ABI after catching a panic.
    pub fn set_out_of_memory(&mut self) {
        self.set_error(GL_OUT_OF_MEMORY);
    }

    /// Bytes `glCallLists(n, type_, lists)` reads; `None` for a negative `n` or an unknown type.
    #[must_use]
    pub fn call_lists_len(n: GLsizei, type_: GLenum) -> Option<usize> {
        usize::try_from(n).ok()?.checked_mul(list_name_size(type_)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn images_count_padding_and_skips() {
        let mut gl = Gl::new(4, 4);
        // 3 RGB bytes a pixel, rows padded to 4: 12 + 12 + 9.
        assert_eq!(gl.unpacked_image_len(3, 3, GL_RGB, GL_UNSIGNED_BYTE), Some(33));
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        assert_eq!(gl.unpacked_image_len(3, 3, GL_RGB, GL_UNSIGNED_BYTE), Some(27));
        assert_eq!(gl.unpacked_image_len(2, 2, GL_RGBA, GL_FLOAT), Some(64)); // 2 × 2 pixels of 4 floats
        assert_eq!(gl.unpacked_image_len(-1, 2, GL_RGBA, GL_FLOAT), None);
        assert_eq!(gl.unpacked_image_len(2, 2, 0x1234, GL_FLOAT), None);
        assert_eq!(gl.unpacked_image_len(0, 2, GL_RGB, GL_FLOAT), Some(0));
    }

    #[test]
    fn bitmaps_and_lists() {
        let gl = Gl::new(4, 4);
        assert_eq!(gl.unpacked_bitmap_len(9, 2), Some(4 + 2));
        assert_eq!(Gl::call_lists_len(3, GL_3_BYTES), Some(9));
        assert_eq!(Gl::call_lists_len(-1, GL_BYTE), None);
    }

    #[test]
    fn the_acceptance_answers_are_the_calls_own() {
        // What a binding asks before it keeps a buffer is the error the call then raises.
        let mut gl = Gl::new(4, 4);
        let check = |gl: &mut Gl| {
            for size in [-1, 0, 8] {
                let asked = gl.select_buffer_error(size);
                gl.select_buffer(size);
                assert_eq!(asked.unwrap_or(GL_NO_ERROR), gl.get_error(), "select {size}");
                for kind in [GL_2D, GL_4D_COLOR_TEXTURE, 0x1234] {
                    let asked = gl.feedback_buffer_error(size, kind);
                    gl.feedback_buffer(size, kind);
                    assert_eq!(asked.unwrap_or(GL_NO_ERROR), gl.get_error(), "feedback {size} {kind:#x}");
                }
            }
            for pname in [GL_VERTEX_ARRAY_POINTER, GL_SELECTION_BUFFER_POINTER, 0x1234] {
                let asked = gl.get_pointerv_error(pname);
                gl.get_pointerv(pname);
                assert_eq!(asked.unwrap_or(GL_NO_ERROR), gl.get_error(), "pointer {pname:#x}");
            }
        };
        check(&mut gl);
        gl.feedback_buffer(8, GL_2D);
        gl.render_mode(GL_FEEDBACK);
        check(&mut gl);
        gl.render_mode(GL_RENDER);
        // Inside begin/end every call is refused (and glGetError answers only after glEnd).
        gl.begin(GL_POINTS);
        assert_eq!(gl.select_buffer_error(8), Some(GL_INVALID_OPERATION));
        assert_eq!(gl.feedback_buffer_error(8, GL_2D), Some(GL_INVALID_OPERATION));
        assert_eq!(gl.get_pointerv_error(GL_VERTEX_ARRAY_POINTER), Some(GL_INVALID_OPERATION));
        gl.end();
        assert_eq!(Gl::draw_elements_len(3, GL_UNSIGNED_SHORT), Some(6));
        assert_eq!(Gl::draw_elements_len(3, GL_FLOAT), None);
        assert_eq!(Gl::draw_elements_len(-3, GL_UNSIGNED_INT), None);
    }
}
