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
use super::pixel_unpack::element_size as type_size;
use super::types::*;
use super::window_read::WindowImage;
use super::Gl;

/// The components of one window pixel (floats in [0, 1]) that `format` returns; `None` for a
/// format that is not a colour format.
fn components(format: GLenum, [r, g, b, a]: [f32; 4]) -> Option<Vec<f32>> {
    Some(match format {
        GL_RED => vec![r],
        GL_GREEN => vec![g],
        GL_BLUE => vec![b],
        GL_ALPHA => vec![a],
        GL_RGB => vec![r, g, b],
        GL_RGBA => vec![r, g, b, a],
        GL_LUMINANCE => vec![(r + g + b).min(1.0)],
        GL_LUMINANCE_ALPHA => vec![(r + g + b).min(1.0), a],
        // A depth travels in the red slot (see `Gl::read_pixels`).
        GL_DEPTH_COMPONENT => vec![r],
        _ => return None,
    })
}

/// Components per pixel of a format glReadPixels takes, the colour ones and those gleval
/// cannot read.
fn format_size(format: GLenum) -> Option<usize> {
    match format {
        GL_LUMINANCE_ALPHA => Some(2),
        GL_RGB => Some(3),
        GL_RGBA => Some(4),
        GL_RED | GL_GREEN | GL_BLUE | GL_ALPHA | GL_LUMINANCE | GL_COLOR_INDEX | GL_STENCIL_INDEX
        | GL_DEPTH_COMPONENT => Some(1),
        _ => None,
    }
}

/// One component `c` ∈ [0, 1] as `type_` stores it, native byte order.
fn encode(c: f32, type_: GLenum) -> Vec<u8> {
    let c = f64::from(c.clamp(0.0, 1.0));
    let unsigned = |max: f64| (c * max).round();
    let signed = |max: f64| ((c * (2.0 * max + 1.0) - 1.0) / 2.0).round();
    // Mesa's `_mesa_float_to_unorm`: the product in floats, rounded half to even (a colour
    // biased to 131.5 reads as 132).
    let unorm = |max: f32| (c as f32 * max).round_ties_even();
    match type_ {
        GL_UNSIGNED_BYTE => vec![unorm(255.0) as u8],
        GL_BYTE => (signed(127.0) as i8).to_ne_bytes().to_vec(),
        GL_UNSIGNED_SHORT => (unorm(65535.0) as u16).to_ne_bytes().to_vec(),
        GL_SHORT => (signed(32767.0) as i16).to_ne_bytes().to_vec(),
        GL_UNSIGNED_INT => (unsigned(4294967295.0) as u32).to_ne_bytes().to_vec(),
        GL_INT => (signed(2147483647.0) as i32).to_ne_bytes().to_vec(),
        _ => (c as f32).to_ne_bytes().to_vec(),
    }
}

/// The error a colour read of `format` and `type_` gets (`glGetTexImage`'s checks, Mesa's
/// `_mesa_error_check_format_and_type` order): an unknown format or type `GL_INVALID_ENUM`, a
/// depth, stencil or colour-index format `GL_INVALID_OPERATION`.
pub(crate) fn read_format_error(format: GLenum, type_: GLenum) -> Option<GLenum> {
    if format_size(format).is_none() || type_size(type_).is_none() {
        return Some(GL_INVALID_ENUM);
    }
    let colour = format != GL_DEPTH_COMPONENT && components(format, [0.0; 4]).is_some();
    (!colour).then_some(GL_INVALID_OPERATION)
}

/// One depth `d` ∈ [0, 1] as `type_` stores it: Mesa packs depths with truncating conversions
/// (`FLOAT_TO_UBYTE` and its kin in `_mesa_pack_depth_span`; measured: 0.25 reads as 63).
fn encode_depth(d: f32, type_: GLenum) -> Vec<u8> {
    let d = f64::from(d.clamp(0.0, 1.0));
    let signed = |max: f64| ((d * (2.0 * max + 1.0) - 1.0) / 2.0).trunc();
    match type_ {
        GL_UNSIGNED_BYTE => vec![(d * 255.0) as u8],
        GL_BYTE => (signed(127.0) as i8).to_ne_bytes().to_vec(),
        GL_UNSIGNED_SHORT => ((d * 65535.0) as u16).to_ne_bytes().to_vec(),
        GL_SHORT => (signed(32767.0) as i16).to_ne_bytes().to_vec(),
        GL_UNSIGNED_INT => ((d * 4294967295.0) as u32).to_ne_bytes().to_vec(),
        GL_INT => (signed(2147483647.0) as i32).to_ne_bytes().to_vec(),
        _ => (d as f32).to_ne_bytes().to_vec(),
    }
}

impl Gl {
    /// Bytes `glReadPixels` writes for a `width` × `height` rectangle of `format` and `type_`
    /// under the current pack modes (skips, padded rows, the last row up to its last pixel);
    /// `None` when GL writes nothing because it rejects the format, type or a negative size.
    #[must_use]
    pub fn packed_image_len(&self, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum) -> Option<usize> {
        let (w, h) = (usize::try_from(width).ok()?, usize::try_from(height).ok()?);
        let (n, size) = (format_size(format)?, type_size(type_)?);
        if w == 0 || h == 0 {
            return Some(0);
        }
        let store = self.client.pixel_stores.pack;
        let stride = store.row_stride(w, n, size);
        let first = store.first_byte(stride, n * size);
        first.checked_add((h - 1).checked_mul(stride)?)?.checked_add(w * n * size)
    }

    /// `glReadPixels(x, y, width, height, format, type, pixels)` into `out`: `window` draws what
    /// was recorded and returns the window's buffers. Colours go through the pixel transfer,
    /// depths (`GL_DEPTH_COMPONENT`) through the depth scale and bias. Errors, in
    /// Mesa's order: inside `begin`/`end` (`GL_INVALID_OPERATION`), a negative size
    /// (`GL_INVALID_VALUE`), an unknown type or `GL_BITMAP` (`GL_INVALID_ENUM`), an unknown
    /// format (`GL_INVALID_OPERATION`, Mesa's answer), a buffer gleval cannot read (stencil,
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
        let Some(size) = type_size(type_) else { return self.set_error(GL_INVALID_ENUM) };
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
        let at = |wx: i32, wy: i32| -> Option<[f32; 4]> {
            let (wx, wy) = (i64::from(wx), i64::from(wy));
            if format == GL_DEPTH_COMPONENT {
                return image.depth_at(wx, wy).map(|d| [depths.apply(d), 0.0, 0.0, 0.0]);
            }
            let c = image.color_at(wx, wy)?;
            Some(colors.as_ref().map_or(c, |t| t.apply(c).map(|v| v.clamp(0.0, 1.0))))
        };
        self.pack_rectangle((x, y), (width as usize, height as usize), (format, type_, size), at, out);
    }

    /// Packs a `w` × `h` image of RGBA floats (rows bottom first) as `glReadPixels` would
    /// (`glGetTexImage`); `out` holds at least [`Gl::packed_image_len`] bytes.
    pub(crate) fn pack_rgba(
        &self,
        rgba: &[[f32; 4]],
        (w, h): (usize, usize),
        (format, type_): (GLenum, GLenum),
        out: &mut [u8],
    ) {
        let size = type_size(type_).unwrap_or(1);
        let at = |x: i32, y: i32| rgba.get(y as usize * w + x as usize).copied();
        self.pack_rectangle((0, 0), (w, h), (format, type_, size), at, out);
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

    /// Writes the rectangle's pixels that lie in the window where the pack modes put them.
    fn pack_rectangle(
        &self,
        (x, y): (GLint, GLint),
        (w, h): (usize, usize),
        (format, type_, size): (GLenum, GLenum, usize),
        at: impl Fn(i32, i32) -> Option<[f32; 4]>,
        out: &mut [u8],
    ) {
        let store = self.client.pixel_stores.pack;
        let n = format_size(format).unwrap_or(1);
        let stride = store.row_stride(w, n, size);
        let first = store.first_byte(stride, n * size);
        for j in 0..h {
            for i in 0..w {
                let (wx, wy) = (x.saturating_add(i as i32), y.saturating_add(j as i32));
                let Some(rgba) = at(wx, wy) else { continue };
                let mut offset = first + j * stride + i * n * size;
                for c in components(format, rgba).unwrap_or_default() {
                    let mut bytes =
                        if format == GL_DEPTH_COMPONENT { encode_depth(c, type_) } else { encode(c, type_) };
                    if store.swap_bytes {
                        bytes.reverse();
                    }
                    out[offset..offset + size].copy_from_slice(&bytes);
                    offset += size;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2 × 2 window: bottom row red, green; top row blue, white (rows top first); depths
    /// 0.25, 0.5 at the bottom, 0.75, 1 above.
    fn window() -> WindowImage {
        let color = [[0, 0, 255, 255], [255, 255, 255, 255], [255, 0, 0, 255], [0, 255, 0, 255]].concat();
        WindowImage { width: 2, height: 2, color, depth: vec![0.75, 1.0, 0.25, 0.5] }
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
