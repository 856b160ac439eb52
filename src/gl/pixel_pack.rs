//! Packing GL's pixel values into client memory (GL 1.1 spec §4.3.2 "Conversion of RGBA
//! values", "Final conversion", "Placement in client memory"; Mesa `main/pack.c`): what
//! `glReadPixels` and `glGetTexImage` write, under the pack modes. Each component converts as
//! GL 1.1 table 2.9 inverted (unsigned types scale by 2ᵇ − 1, signed ones map [−1, 1] onto the
//! range), luminance as R + G + B clamped. GL 1.2's `GL_BGR` and `GL_BGRA` write the components
//! in the other order, and its packed types one element a pixel ([`super::pixel_packed`]),
//! converted as Mesa 22.3 converts them ([`Source`]).

use super::consts::*;
use super::pixel_packed::{byte_of, from_unorm8, packed, packed_mismatch, Packed, Source};
use super::pixel_unpack::element_size;
use super::types::*;
use super::Gl;

/// The components of one window pixel (floats in [0, 1]) that `format` returns; `None` for a
/// format that is not a colour format.
pub(crate) fn components(format: GLenum, [r, g, b, a]: [f32; 4]) -> Option<Vec<f32>> {
    Some(match format {
        GL_RED => vec![r],
        GL_GREEN => vec![g],
        GL_BLUE => vec![b],
        GL_ALPHA => vec![a],
        GL_RGB => vec![r, g, b],
        GL_RGBA => vec![r, g, b, a],
        GL_BGR => vec![b, g, r],
        GL_BGRA => vec![b, g, r, a],
        GL_LUMINANCE => vec![(r + g + b).min(1.0)],
        GL_LUMINANCE_ALPHA => vec![(r + g + b).min(1.0), a],
        // A depth travels in the red slot (see `Gl::read_pixels`).
        GL_DEPTH_COMPONENT => vec![r],
        _ => return None,
    })
}

/// Components per pixel of a format glReadPixels takes, the colour ones and those gleval
/// cannot read.
pub(crate) fn format_size(format: GLenum) -> Option<usize> {
    match format {
        GL_LUMINANCE_ALPHA => Some(2),
        GL_RGB | GL_BGR => Some(3),
        GL_RGBA | GL_BGRA => Some(4),
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

/// One 8-bit component `c` (a byte over 255) as `type_` stores it, native byte order, converted
/// from the byte as integers as Mesa converts a window's or texture's bytes that no pixel
/// transfer made floats ([`from_unorm8`]; measured: 0 reads as `GL_SHORT` 0 and 1 as 128, 200
/// as `GL_INT` 0x64646464, where the float conversion gives −1, 128 and 0x6464647F).
fn encode_unorm8(c: f32, type_: GLenum) -> Vec<u8> {
    let byte = byte_of(c);
    match type_ {
        GL_UNSIGNED_BYTE => vec![byte as u8],
        GL_BYTE => vec![from_unorm8(byte, 7) as u8],
        GL_UNSIGNED_SHORT => (from_unorm8(byte, 16) as u16).to_ne_bytes().to_vec(),
        GL_SHORT => (from_unorm8(byte, 15) as u16).to_ne_bytes().to_vec(),
        GL_UNSIGNED_INT => from_unorm8(byte, 32).to_ne_bytes().to_vec(),
        GL_INT => from_unorm8(byte, 31).to_ne_bytes().to_vec(),
        _ => c.to_ne_bytes().to_vec(),
    }
}

/// Bytes per element of a type `glReadPixels` takes: a GL 1.1 type's, or a packed type's one
/// element a pixel; `None` for `GL_BITMAP` and unknown types.
fn type_size(type_: GLenum) -> Option<usize> {
    element_size(type_).or(packed(type_).map(|p| p.size))
}

/// The elements per pixel and bytes per element `format` and `type_` are packed in: one
/// element a pixel for a packed type (GL 1.2 §4.3.2), the format's components otherwise.
fn pixel_shape(format: GLenum, type_: GLenum) -> Option<(usize, usize)> {
    if type_ == GL_FLOAT_32_UNSIGNED_INT_24_8_REV {
        return (format == GL_DEPTH_STENCIL).then_some((1, 8));
    }
    match packed(type_) {
        Some(p) => (!packed_mismatch(format, type_)).then_some((1, p.size)),
        None => Some((format_size(format)?, element_size(type_)?)),
    }
}

/// The error `glGetTexImage` of `format` and `type_` gets from a level that holds depths
/// (`depth_level`) or colours (Mesa's `_mesa_error_check_format_and_type` order, then
/// `getteximage_error_check`): a packed type the format does not go with
/// `GL_INVALID_OPERATION` (an unknown format too, measured), an unknown format or type
/// `GL_INVALID_ENUM`; a stencil or colour-index format, a depth format from a colour level, or
/// any but `GL_DEPTH_COMPONENT` from a depth level (GL 1.4 §6.1.4), `GL_INVALID_OPERATION`.
pub(crate) fn texture_read_error(format: GLenum, type_: GLenum, depth_level: bool) -> Option<GLenum> {
    if packed_mismatch(format, type_) {
        return Some(GL_INVALID_OPERATION);
    }
    if format_size(format).is_none() || type_size(type_).is_none() {
        return Some(GL_INVALID_ENUM);
    }
    let colour = format != GL_DEPTH_COMPONENT && components(format, [0.0; 4]).is_some();
    let agrees = if depth_level { format == GL_DEPTH_COMPONENT } else { colour };
    (!agrees).then_some(GL_INVALID_OPERATION)
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

/// One depth of a depth texture as `type_` stores it (see [`Source::TextureDepth`]):
/// `GL_UNSIGNED_SHORT` to the nearest integer (Mesa's `CLAMPED_FLOAT_TO_USHORT`), the others
/// as [`encode_depth`] does (measured: a 16-bit 0.25 reads as `GL_UNSIGNED_INT` 0x40003FFF,
/// truncated).
fn encode_texture_depth(d: f32, type_: GLenum) -> Vec<u8> {
    match type_ {
        GL_UNSIGNED_SHORT => ((f64::from(d.clamp(0.0, 1.0)) * 65535.0).round() as u16).to_ne_bytes().to_vec(),
        _ => encode_depth(d, type_),
    }
}

impl Gl {
    /// Bytes `glReadPixels` writes for a `width` × `height` rectangle of `format` and `type_`
    /// under the current pack modes (skips, padded rows, the last row up to its last pixel);
    /// `None` when GL writes nothing because it rejects the format, type or a negative size.
    #[must_use]
    pub fn packed_image_len(&self, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum) -> Option<usize> {
        let (w, h) = (usize::try_from(width).ok()?, usize::try_from(height).ok()?);
        let (n, size) = pixel_shape(format, type_)?;
        if w == 0 || h == 0 {
            return Some(0);
        }
        let store = self.client.pixel_stores.pack;
        let stride = store.row_stride(w, n, size);
        let first = store.first_byte(stride, n * size);
        first.checked_add((h - 1).checked_mul(stride)?)?.checked_add(w * n * size)
    }

    /// Bytes from one image of a 3D texture to the next under the pack modes, and the images
    /// skipped before the first (GL 1.2 §6.1.4: each image packed as `glReadPixels` packs one,
    /// `GL_PACK_IMAGE_HEIGHT` rows apart, after `GL_PACK_SKIP_IMAGES` images).
    pub(crate) fn packed_image_stride(
        &self,
        (width, height): (usize, usize),
        format: GLenum,
        type_: GLenum,
    ) -> Option<(usize, usize)> {
        let store = self.client.pixel_stores.pack;
        let (n, size) = pixel_shape(format, type_)?;
        let row = store.row_stride(width, n, size);
        Some((store.image_stride(row, height), store.skip_images))
    }

    /// Packs a `w` × `h` image of RGBA floats from `source` (rows bottom first) as
    /// `glReadPixels` would (`glGetTexImage`); `out` holds at least [`Gl::packed_image_len`]
    /// bytes.
    pub(crate) fn pack_rgba(
        &self,
        rgba: &[[f32; 4]],
        (w, h): (usize, usize),
        (format, type_, source): (GLenum, GLenum, Source),
        out: &mut [u8],
    ) {
        let at = |x: i32, y: i32| rgba.get(y as usize * w + x as usize).copied();
        self.pack_rectangle((0, 0), (w, h), (format, type_, source), at, out);
    }

    /// Writes the rectangle's pixels that lie in the window where the pack modes put them.
    /// Nothing is written for a format and type [`Gl::packed_image_len`] rejects.
    pub(crate) fn pack_rectangle(
        &self,
        (x, y): (GLint, GLint),
        (w, h): (usize, usize),
        (format, type_, source): (GLenum, GLenum, Source),
        at: impl Fn(i32, i32) -> Option<[f32; 4]>,
        out: &mut [u8],
    ) {
        let store = self.client.pixel_stores.pack;
        let Some((n, size)) = pixel_shape(format, type_) else { return };
        let stride = store.row_stride(w, n, size);
        let first = store.first_byte(stride, n * size);
        for j in 0..h {
            for i in 0..w {
                let (wx, wy) = (x.saturating_add(i as i32), y.saturating_add(j as i32));
                let Some(rgba) = at(wx, wy) else { continue };
                let pixel = &mut out[first + j * stride + i * n * size..][..n * size];
                let values = components(format, rgba).unwrap_or_default();
                match packed(type_) {
                    Some(p) => pack_element(p, &values, (source, store.swap_bytes), pixel),
                    None => pack_components(&values, (format, type_, source), store.swap_bytes, pixel),
                }
            }
        }
    }
}

/// One pixel of a packed type: its components in one element, its bytes swapped as one
/// (GL 1.2 §4.3.2: `GL_PACK_SWAP_BYTES` swaps the element's bytes).
fn pack_element(p: Packed, values: &[f32], (source, swap): (Source, bool), pixel: &mut [u8]) {
    p.write(p.pack(values, source), swap, pixel);
}

/// One pixel of a GL 1.1 type: each component its own element, each swapped on its own.
fn pack_components(values: &[f32], (format, type_, source): (GLenum, GLenum, Source), swap: bool, pixel: &mut [u8]) {
    let mut offset = 0;
    for &c in values {
        let mut bytes = match (format, source) {
            (GL_DEPTH_COMPONENT, Source::TextureDepth) => encode_texture_depth(c, type_),
            (GL_DEPTH_COMPONENT, _) => encode_depth(c, type_),
            (_, Source::Unorm8) => encode_unorm8(c, type_),
            (_, Source::Float | Source::TextureDepth) => encode(c, type_),
        };
        if swap {
            bytes.reverse();
        }
        pixel[offset..offset + bytes.len()].copy_from_slice(&bytes);
        offset += bytes.len();
    }
}
