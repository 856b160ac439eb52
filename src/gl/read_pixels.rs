//! `glReadPixels` (GL 1.1 spec §4.3.2; Mesa `main/readpix.c`): a rectangle of the window's
//! colours, converted to the caller's format and type and laid out with the pack modes.
//!
//! The `gl` layer has no framebuffer: the caller that owns a renderer hands in a closure that
//! draws the frame recorded so far and returns the window's buffers ([`WindowImage`]: RGBA8
//! colour and depth, rows top to bottom, as `soft::render_window` and
//! `Renderer::render_window` give them). It runs only when the call is valid. GL's rules
//! live here: the errors in Mesa's order, the rectangle (pixels outside the window are left
//! as they were, as Mesa leaves them), the pixel transfer (colour scale, bias and maps; depth
//! scale and bias, §4.3.2), the conversion of each component (GL 1.1 table 2.9 inverted:
//! unsigned types scale by 2ᵇ − 1, signed ones map [−1, 1] onto the range), luminance as
//! R + G + B clamped (§4.3.2), the pack modes.
//!
//! An RGBA window has no colour-index buffer and gleval's none a stencil buffer yet: reading
//! `GL_COLOR_INDEX` or `GL_STENCIL_INDEX` is `GL_INVALID_OPERATION`, as in Mesa without one.

use super::consts::*;
use super::frame::Frame;
use super::pixel_pack::{components, format_size};
use super::pixel_packed::Source;
use super::pixel_unpack::format_and_type_error;
use super::types::*;
use super::window_read::WindowImage;
use super::Gl;

impl Gl {
    /// `glReadPixels(x, y, width, height, format, type, pixels)` into `out`: `window` draws what
    /// was recorded and returns the window's buffers. Colours go through the pixel transfer,
    /// depths (`GL_DEPTH_COMPONENT`) through the depth scale and bias. Errors, in
    /// Mesa's order: inside `begin`/`end` (`GL_INVALID_OPERATION`), a negative size
    /// (`GL_INVALID_VALUE`), an unknown format (`GL_INVALID_OPERATION`, Mesa's answer), a
    /// packed type the format does not go with (`GL_INVALID_OPERATION`), an unknown type or
    /// `GL_BITMAP` with a colour (`GL_INVALID_ENUM`), a buffer gleval cannot read (stencil,
    /// colour index: `GL_INVALID_OPERATION`), a non-empty `out` shorter than
    /// [`Gl::packed_image_len`] (`GL_INVALID_VALUE`); an empty `out` (C's NULL) writes nothing
    /// and is no error, as in Mesa. Not compiled into lists.
    pub fn read_pixels(
        &mut self,
        (x, y): (GLint, GLint),
        (width, height): (GLsizei, GLsizei),
        format: GLenum,
        type_: GLenum,
        window: impl FnOnce(&Frame) -> Option<WindowImage>,
        out: &mut [u8],
    ) {
        if self.reject_inside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        // Measured on Mesa 22 (capi/tests/readpixels.c): an unknown format is
        // GL_INVALID_OPERATION (an invalid combination) whatever the type, then an unknown
        // type GL_INVALID_ENUM.
        if format_size(format).is_none() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        // Then Mesa's `_mesa_error_check_format_and_type`: a packed type with a format it does
        // not go with GL_INVALID_OPERATION, an unknown type or GL_BITMAP with a colour
        // GL_INVALID_ENUM (measured, pack_types.calls).
        if let Some(error) = format_and_type_error(format, type_) {
            return self.set_error(error);
        }
        if components(format, [0.0; 4]).is_none() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let needed = self.packed_image_len(width, height, format, type_).unwrap_or(usize::MAX);
        if needed == 0 || out.is_empty() {
            // C's NULL destination: Mesa writes nothing and reports nothing.
            return;
        }
        if out.len() < needed {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(image) = window(self.frame()) else { return self.set_error(GL_OUT_OF_MEMORY) };
        let (colors, depths) = (self.color_transfer(), self.depth_transfer());
        // Mesa packs the window's bytes as integers unless the transfer made them floats, or
        // the luminance sum did (measured: a red of 43 reads as GL_RED GL_INT 0x15959595, as
        // GL_LUMINANCE 0x159595A0).
        let luminance = matches!(format, GL_LUMINANCE | GL_LUMINANCE_ALPHA);
        let source = if colors.is_some() || luminance { Source::Float } else { Source::Unorm8 };
        let at = |wx: i32, wy: i32| -> Option<[f32; 4]> {
            let (wx, wy) = (i64::from(wx), i64::from(wy));
            if format == GL_DEPTH_COMPONENT {
                return image.depth_at(wx, wy).map(|d| [depths.apply(d), 0.0, 0.0, 0.0]);
            }
            let c = image.color_at(wx, wy)?;
            Some(colors.as_ref().map_or(c, |t| t.apply(c).map(|v| v.clamp(0.0, 1.0))))
        };
        self.pack_rectangle((x, y), (width as usize, height as usize), (format, type_, source), at, out);
    }

    /// `glReadPixels` as a ported program calls it: [`Gl::read_pixels`] reading the window
    /// through the context's reader ([`Gl::set_window_reader`]; `App` installs its
    /// rasteriser's), drawn as far as the program has drawn.
    pub fn read_window_pixels(
        &mut self,
        (x, y): (GLint, GLint),
        (width, height): (GLsizei, GLsizei),
        format: GLenum,
        type_: GLenum,
        out: &mut [u8],
    ) {
        if self.inside_begin_end() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let image = self.read_window();
        self.read_pixels((x, y), (width, height), format, type_, |_| image, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2 × 2 window: bottom row red, green; top row blue, white (rows top first); depths
    /// 0.25, 0.5 at the bottom, 0.75, 1 above.
    fn window() -> WindowImage {
        let color = [[0, 0, 255, 255], [255, 255, 255, 255], [255, 0, 0, 255], [0, 255, 0, 255]].concat();
        WindowImage { width: 2, height: 2, color, depth: vec![0.75, 1.0, 0.25, 0.5], samples: Vec::new() }
    }

    #[test]
    fn depths_and_transfer() {
        let mut gl = Gl::new(2, 2);
        let mut out = [0u8; 8];
        gl.read_pixels((0, 0), (2, 1), GL_DEPTH_COMPONENT, GL_FLOAT, |_| Some(window()), &mut out[..]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(out[..4], 0.25f32.to_ne_bytes());
        gl.pixel_transferf(GL_DEPTH_BIAS, 0.25);
        gl.pixel_transferf(GL_RED_SCALE, 0.5);
        gl.read_pixels((1, 0), (1, 1), GL_DEPTH_COMPONENT, GL_FLOAT, |_| Some(window()), &mut out[..]);
        assert_eq!(out[..4], 0.75f32.to_ne_bytes());
        let mut rgba = [0u8; 4];
        gl.read_pixels((0, 0), (1, 1), GL_RGBA, GL_UNSIGNED_BYTE, |_| Some(window()), &mut rgba[..]);
        assert_eq!(rgba, [128, 0, 0, 255]);
    }

    #[test]
    fn reads_bottom_up_with_the_pack_modes() {
        let mut gl = Gl::new(2, 2);
        let mut out = [7u8; 8];
        gl.read_pixels((0, 0), (2, 2), GL_RGB, GL_UNSIGNED_BYTE, |_| Some(window()), &mut out[..]);
        // Rows padded to 4 bytes: red, green, pad; blue, white would need 14 bytes.
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
        let mut out = [7u8; 12];
        gl.read_pixels((0, 0), (2, 2), GL_RGB, GL_UNSIGNED_BYTE, |_| Some(window()), &mut out[..]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(out, [255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255]);
        let mut lum = [0u8; 1];
        gl.read_pixels((1, 1), (1, 1), GL_LUMINANCE, GL_UNSIGNED_BYTE, |_| Some(window()), &mut lum[..]);
        assert_eq!(lum, [255]);
    }

    #[test]
    fn bgra_and_packed_types() {
        let mut gl = Gl::new(2, 2);
        gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
        let mut out = [0u8; 8];
        // The bottom row: red, green.
        gl.read_pixels((0, 0), (2, 1), GL_BGRA, GL_UNSIGNED_BYTE, |_| Some(window()), &mut out[..]);
        assert_eq!(out, [0, 0, 255, 255, 0, 255, 0, 255]);
        let mut out = [0u8; 4];
        // 5_6_5: red in bits 15–11, green in 10–5 (GL 1.2 table 3.10).
        gl.read_pixels((0, 0), (2, 1), GL_RGB, GL_UNSIGNED_SHORT_5_6_5, |_| Some(window()), &mut out[..]);
        assert_eq!(out[..], [0xF800u16.to_ne_bytes(), 0x07E0u16.to_ne_bytes()].concat());
        gl.pixel_storei(GL_PACK_SWAP_BYTES, 1);
        gl.read_pixels((0, 0), (1, 1), GL_RGB, GL_UNSIGNED_SHORT_5_6_5, |_| Some(window()), &mut out[..]);
        assert_eq!(out[..2], 0x00F8u16.to_ne_bytes());
        gl.pixel_storei(GL_PACK_SWAP_BYTES, 0);
        // 2_10_10_10_REV with BGRA: blue in bits 9–0, red in 29–20, alpha in 31–30.
        gl.read_pixels((0, 0), (1, 1), GL_BGRA, GL_UNSIGNED_INT_2_10_10_10_REV, |_| Some(window()), &mut out[..]);
        assert_eq!(out, (3u32 << 30 | 0x3FF << 20).to_ne_bytes());
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        for (format, type_) in [
            (GL_BGR, GL_UNSIGNED_BYTE_3_3_2),
            (GL_RGB, GL_UNSIGNED_INT_8_8_8_8),
            (GL_LUMINANCE, GL_UNSIGNED_SHORT_5_6_5),
        ] {
            gl.read_pixels((0, 0), (1, 1), format, type_, |_| Some(window()), &mut out[..]);
            assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        }
        assert_eq!(gl.packed_image_len(3, 2, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4), Some(12));
        assert_eq!(gl.packed_image_len(3, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5), None);
    }

    #[test]
    fn errors_and_the_outside_of_the_window() {
        let mut gl = Gl::new(2, 2);
        let mut out = [9u8; 64];
        gl.read_pixels((0, 0), (-1, 1), GL_RGBA, GL_UNSIGNED_BYTE, |_| None, &mut out[..]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.read_pixels((0, 0), (1, 1), GL_RGBA, 0x1234, |_| None, &mut out[..]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.read_pixels((0, 0), (1, 1), 0x1234, 0x1234, |_| None, &mut out[..]);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.read_pixels((0, 0), (1, 1), GL_RGBA, GL_FLOAT, |_| None, &mut []);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.read_pixels((0, 0), (1, 1), GL_STENCIL_INDEX, GL_FLOAT, |_| None, &mut out[..]);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.read_pixels((1, 1), (2, 1), GL_RGBA, GL_UNSIGNED_BYTE, |_| Some(window()), &mut out[..]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(out[..8], [255, 255, 255, 255, 9, 9, 9, 9], "outside the window: untouched");
    }
}
