//! Client images to GL's pixel values (GL 1.1 spec §3.6.3 "Unpacking" and "Conversion to
//! floating-point", table 3.5; Mesa `main/pack.c`): what `glDrawPixels` and `glTexImage` read
//! from client memory, element by element, before the pixel transfer.
//!
//! Every GL 1.1 type is read (`GL_BITMAP` for indices, the signed and unsigned integers of
//! 8, 16 and 32 bits, `GL_FLOAT`), and GL 1.2's packed types ([`super::pixel_packed`]), with
//! `GL_UNPACK_SWAP_BYTES`, the row length, the skipped rows and pixels and the row alignment.
//! Colour and depth components become floats as Mesa 22 converts them (measured: a `GL_BYTE` 1
//! draws as 1/127, not GL 1.1's 3/255, so signed values are `max(c / (2^(b−1) − 1), −1)`,
//! unsigned `c / (2^b − 1)`); colour and stencil indices stay integers.

use super::consts::*;
use super::pixel_packed::{depth_stencil_size, packed, packed_mismatch};
use super::pixels::PixelStore;
use super::types::*;

/// Elements per pixel of a `glDrawPixels`/`glTexImage` format, `None` for one GL 1.1 does not
/// have (`GL_BGR` and `GL_BGRA` of GL 1.2 and `GL_RG` of GL 3.0 included, as Mesa's
/// compatibility contexts take them).
#[must_use]
pub(crate) fn format_components(format: GLenum) -> Option<usize> {
    match format {
        GL_COLOR_INDEX | GL_STENCIL_INDEX | GL_DEPTH_COMPONENT => Some(1),
        GL_RED | GL_GREEN | GL_BLUE | GL_ALPHA | GL_LUMINANCE => Some(1),
        GL_LUMINANCE_ALPHA | GL_RG => Some(2),
        GL_RGB | GL_BGR => Some(3),
        GL_RGBA | GL_BGRA => Some(4),
        GL_DEPTH_STENCIL => Some(2),
        _ => None,
    }
}

/// Bytes per element of a GL 1.1 type other than `GL_BITMAP`, `None` for the others.
#[must_use]
pub(crate) fn element_size(type_: GLenum) -> Option<usize> {
    match type_ {
        GL_BYTE | GL_UNSIGNED_BYTE => Some(1),
        GL_SHORT | GL_UNSIGNED_SHORT => Some(2),
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT => Some(4),
        _ => None,
    }
}

/// The errors Mesa's `_mesa_error_check_format_and_type` gives a client image's `format` and
/// `type_` before a call's own checks: a packed type the format does not go with →
/// `GL_INVALID_OPERATION` ([`packed_mismatch`], checked first: an unknown format with a packed
/// type is `GL_INVALID_OPERATION` too, measured in `pack_types.calls`); an unknown format or
/// type, or `GL_BITMAP` with a format that is not an index → `GL_INVALID_ENUM`.
#[must_use]
pub(crate) fn format_and_type_error(format: GLenum, type_: GLenum) -> Option<GLenum> {
    // GL_DEPTH_STENCIL goes with its packed type alone, any other GL_INVALID_ENUM, a packed
    // colour type too (measured, capi/tests/depth_stencil.c).
    if format == GL_DEPTH_STENCIL && depth_stencil_size(type_).is_none() {
        return Some(GL_INVALID_ENUM);
    }
    if packed_mismatch(format, type_) {
        return Some(GL_INVALID_OPERATION);
    }
    let known_type = type_ == GL_BITMAP
        || element_size(type_).is_some()
        || packed(type_).is_some()
        || depth_stencil_size(type_).is_some();
    let bitmap_mismatch = type_ == GL_BITMAP && !is_index(format);
    (format_components(format).is_none() || !known_type || bitmap_mismatch).then_some(GL_INVALID_ENUM)
}

/// Whether a format's values are indices (integers, not normalised).
fn is_index(format: GLenum) -> bool {
    matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX)
}

/// One element at `bytes` (its type's size, in client byte order unless `swap`) as GL's float:
/// normalised for colour and depth, the integer itself for an index.
fn element(type_: GLenum, bytes: &[u8], swap: bool, index: bool) -> f32 {
    let mut b = [0u8; 4];
    let n = bytes.len();
    b[..n].copy_from_slice(bytes);
    if swap {
        b[..n].reverse();
    }
    let signed = |value: f64, max: f64| if index { value as f32 } else { (value / max).max(-1.0) as f32 };
    let unsigned = |value: f64, max: f64| if index { value as f32 } else { (value / max) as f32 };
    // A 32-bit index keeps its low 24 bits, which an f32 holds exactly: every use of an index
    // reads its low bits only (the power-of-two maps, the 8-bit stencil buffer), except a
    // negative `GL_INDEX_SHIFT`, which would bring higher bits down (left out).
    let index32 = |value: u32| (value & 0xFF_FFFF) as f32;
    match type_ {
        GL_INT if index => index32(i32::from_ne_bytes(b) as u32),
        GL_UNSIGNED_INT if index => index32(u32::from_ne_bytes(b)),
        GL_BYTE => signed(f64::from(b[0] as i8), 127.0),
        GL_UNSIGNED_BYTE => unsigned(f64::from(b[0]), 255.0),
        GL_SHORT => signed(f64::from(i16::from_ne_bytes([b[0], b[1]])), 32767.0),
        GL_UNSIGNED_SHORT => unsigned(f64::from(u16::from_ne_bytes([b[0], b[1]])), 65535.0),
        GL_INT => signed(f64::from(i32::from_ne_bytes(b)), 2_147_483_647.0),
        GL_UNSIGNED_INT => unsigned(f64::from(u32::from_ne_bytes(b)), 4_294_967_295.0),
        _ => f32::from_ne_bytes(b),
    }
}

/// One pixel's elements as GL's RGBA (GL 1.1 §3.6.3 "Conversion to RGB": missing colour
/// components 0, a missing alpha 1, luminance to R, G and B). An index, or a depth, travels in
/// the red slot.
#[must_use]
pub(crate) fn to_rgba(format: GLenum, c: &[f32]) -> [f32; 4] {
    match format {
        GL_RED | GL_COLOR_INDEX | GL_STENCIL_INDEX | GL_DEPTH_COMPONENT => [c[0], 0.0, 0.0, 1.0],
        GL_GREEN => [0.0, c[0], 0.0, 1.0],
        GL_BLUE => [0.0, 0.0, c[0], 1.0],
        GL_ALPHA => [0.0, 0.0, 0.0, c[0]],
        GL_LUMINANCE => [c[0], c[0], c[0], 1.0],
        GL_LUMINANCE_ALPHA => [c[0], c[0], c[0], c[1]],
        GL_RG | GL_DEPTH_STENCIL => [c[0], c[1], 0.0, 1.0],
        GL_RGB => [c[0], c[1], c[2], 1.0],
        GL_BGR => [c[2], c[1], c[0], 1.0],
        GL_BGRA => [c[2], c[1], c[0], c[3]],
        _ => [c[0], c[1], c[2], c[3]],
    }
}

/// Unpacks a `width` × `height` image of `format` and `type_` from `data` as GL reads it with
/// `store`: one RGBA value per pixel ([`to_rgba`]), row by row from the bottom. `GL_BITMAP`
/// (indices only) reads one bit a pixel as a bitmap does. `None` when `data` is shorter than
/// the image; a format or type not read, or a negative size, gives an empty image (the calls
/// report those errors themselves).
#[must_use]
pub(crate) fn unpack_image(
    store: PixelStore,
    size: (GLsizei, GLsizei),
    format: GLenum,
    type_: GLenum,
    data: &[u8],
) -> Option<Vec<[f32; 4]>> {
    let mut out = Vec::new();
    unpack_each(store, size, format, type_, data, |c| out.push(c))?;
    Some(out)
}

/// [`unpack_image`] handing each pixel to `emit` as it is read, for a caller that keeps the
/// pixels in another form (a texture's bytes) and need not hold the floats of a whole image.
/// `None` when `data` is shorter than the image (then nothing is emitted).
pub(crate) fn unpack_each(
    store: PixelStore,
    (width, height): (GLsizei, GLsizei),
    format: GLenum,
    type_: GLenum,
    data: &[u8],
    mut emit: impl FnMut([f32; 4]),
) -> Option<()> {
    let (Ok(w), Ok(h)) = (usize::try_from(width), usize::try_from(height)) else { return Some(()) };
    let Some(n) = format_components(format) else { return Some(()) };
    if w == 0 || h == 0 || format_and_type_error(format, type_).is_some() {
        return Some(());
    }
    if type_ == GL_BITMAP {
        let bits = unpack_bitmap(store, width, height, data)?;
        bits.into_iter().for_each(|set| emit([f32::from(u8::from(set)), 0.0, 0.0, 1.0]));
        return Some(());
    }
    if type_ == GL_FLOAT_32_UNSIGNED_INT_24_8_REV {
        return unpack_float_depth_stencil(store, (w, h), data, emit);
    }
    // One element a pixel for a packed type, `n` of them otherwise.
    let (packed, size, per_pixel) = match packed(type_) {
        Some(p) => (Some(p), p.size, 1),
        None => match element_size(type_) {
            Some(size) => (None, size, n),
            None => return Some(()),
        },
    };
    let stride = store.row_stride(w, per_pixel, size);
    let first = store.first_byte(stride, per_pixel * size);
    if data.len() < first + (h - 1) * stride + w * per_pixel * size {
        return None;
    }
    let swap = store.swap_bytes && size > 1;
    let index = is_index(format);
    let mut c = [0.0f32; 4];
    for row in 0..h {
        let row_bytes = &data[first + row * stride..][..w * per_pixel * size];
        for pixel in row_bytes.chunks_exact(per_pixel * size) {
            match packed {
                Some(p) => {
                    let value = p.read(pixel, swap);
                    p.unpack(value, &mut c);
                    if format == GL_DEPTH_STENCIL {
                        // The stencil index is an integer, not normalised.
                        c[1] = (value & 0xFF) as f32;
                    }
                    emit(to_rgba(format, &c[..p.components()]));
                }
                None => {
                    for (value, bytes) in c.iter_mut().zip(pixel.chunks_exact(size)) {
                        *value = element(type_, bytes, swap, index);
                    }
                    emit(to_rgba(format, &c[..n]));
                }
            }
        }
    }
    Some(())
}

/// [`unpack_each`] of `GL_DEPTH_STENCIL` in `GL_FLOAT_32_UNSIGNED_INT_24_8_REV`: each pixel's
/// float depth (as it is; the caller clamps where its buffer does) and the low 8 bits of the
/// word after it, the stencil index. `GL_UNPACK_SWAP_BYTES` swaps each word.
fn unpack_float_depth_stencil(
    store: PixelStore,
    (w, h): (usize, usize),
    data: &[u8],
    mut emit: impl FnMut([f32; 4]),
) -> Option<()> {
    let stride = store.row_stride(w, 1, 8);
    let first = store.first_byte(stride, 8);
    if data.len() < first + (h - 1) * stride + w * 8 {
        return None;
    }
    let word = |b: &[u8]| {
        let mut b: [u8; 4] = b.try_into().expect("four bytes");
        if store.swap_bytes {
            b.reverse();
        }
        b
    };
    for row in 0..h {
        for pixel in data[first + row * stride..][..w * 8].chunks_exact(8) {
            let depth = f32::from_ne_bytes(word(&pixel[..4]));
            let stencil = u32::from_ne_bytes(word(&pixel[4..])) & 0xFF;
            emit([depth, stencil as f32, 0.0, 1.0]);
        }
    }
    Some(())
}

/// Bytes from one image of a 3D texture to the next in client memory for images of `width` ×
/// `height` pixels of `format` and `type_` (GL 1.2 §3.8.1: rows as a 2D image's, and
/// `GL_UNPACK_IMAGE_HEIGHT` rows an image, or `height` when it is 0); `None` for a format or
/// type GL rejects.
pub(crate) fn image_stride(
    store: PixelStore,
    (width, height): (usize, usize),
    format: GLenum,
    type_: GLenum,
) -> Option<usize> {
    let (size, per_pixel) = match (packed(type_), depth_stencil_size(type_)) {
        (Some(p), _) => (p.size, 1),
        (None, Some(size)) => (size, 1),
        (None, None) => (element_size(type_)?, format_components(format)?),
    };
    Some(store.image_stride(store.row_stride(width, per_pixel, size), height))
}

/// Unpacks a `width` × `height` bitmap from `data` as GL reads it with `store` (rows bottom
/// first, bit order per `GL_UNPACK_LSB_FIRST`, rows and bits skipped, rows aligned): one bool
/// per pixel, row by row. `None` when `data` is shorter than the bitmap; negative sizes give an
/// empty image (the call reports them).
pub(crate) fn unpack_bitmap(store: PixelStore, width: GLsizei, height: GLsizei, data: &[u8]) -> Option<Vec<bool>> {
    let (Ok(w), Ok(h)) = (usize::try_from(width), usize::try_from(height)) else { return Some(Vec::new()) };
    if w == 0 || h == 0 {
        return Some(Vec::new());
    }
    let stride = store.bitmap_row_stride(w);
    let first_row = store.skip_rows * stride;
    let needed = first_row + (h - 1) * stride + (store.skip_pixels + w).div_ceil(8);
    if data.len() < needed {
        return None;
    }
    let bit = |row: usize, i: usize| {
        let b = store.skip_pixels + i;
        let byte = data[first_row + row * stride + b / 8];
        let mask = if store.lsb_first { 1 << (b % 8) } else { 0x80 >> (b % 8) };
        byte & mask != 0
    };
    Some((0..h).flat_map(|j| (0..w).map(move |i| bit(j, i))).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// GL's initial unpack modes: bits from the most significant, rows of 4-byte alignment.
    fn msb() -> PixelStore {
        PixelStore::default()
    }

    fn rows(bits: &[bool], w: usize) -> Vec<String> {
        bits.chunks(w).map(|r| r.iter().map(|&b| if b { '#' } else { '.' }).collect()).collect()
    }

    #[test]
    fn bitmaps_unpack_with_alignment_bit_order_and_skips() {
        // 10 × 2: rows of 2 bytes, padded to 4 by the default alignment.
        let data = [0b1000_0000, 0b0100_0000, 0xEE, 0xEE, 0b0000_0001, 0b1100_0000, 0xEE, 0xEE];
        let bits = unpack_bitmap(msb(), 10, 2, &data).unwrap();
        assert_eq!(rows(&bits, 10), ["#........#", ".......###"]);
        let lsb = PixelStore { lsb_first: true, ..msb() };
        assert_eq!(rows(&unpack_bitmap(lsb, 10, 2, &data).unwrap(), 10), [".......#..", "#........."]);
        let one = PixelStore { alignment: 1, ..msb() };
        assert_eq!(rows(&unpack_bitmap(one, 8, 2, &[0xF0, 0x0F]).unwrap(), 8), ["####....", "....####"]);
        let skipped = PixelStore { skip_rows: 1, skip_pixels: 7, row_length: 16, alignment: 1, ..msb() };
        assert_eq!(rows(&unpack_bitmap(skipped, 3, 1, &[0, 0, 0b0000_0001, 0b1000_0000]).unwrap(), 3), ["##."]);
        assert_eq!(unpack_bitmap(msb(), 10, 2, &data[..5]), None, "the last row needs 2 bytes, not 4");
        assert!(unpack_bitmap(msb(), 10, 2, &data[..6]).is_some());
        assert_eq!(unpack_bitmap(msb(), 0, 5, &[]), Some(Vec::new()));
    }

    #[test]
    fn pixels_unpack_to_rgba() {
        let one = PixelStore { alignment: 1, ..msb() };
        let rgb = unpack_image(one, (2, 1), GL_RGB, GL_UNSIGNED_BYTE, &[255, 0, 0, 0, 51, 255]).unwrap();
        assert_eq!(rgb, [[1.0, 0.0, 0.0, 1.0], [0.0, 0.2, 1.0, 1.0]]);
        // Rows of 3 luminance bytes are padded to 4.
        let lum = unpack_image(msb(), (3, 2), GL_LUMINANCE, GL_UNSIGNED_BYTE, &[0, 0, 0, 9, 255, 255, 255]).unwrap();
        assert_eq!(lum[3], [1.0, 1.0, 1.0, 1.0]);
        assert_eq!(unpack_image(msb(), (3, 2), GL_LUMINANCE, GL_UNSIGNED_BYTE, &[0; 6]), None);
        let floats: Vec<u8> = [0.25f32, 0.5, 0.75, 1.0].iter().flat_map(|f| f.to_ne_bytes()).collect();
        assert_eq!(unpack_image(msb(), (1, 1), GL_RGBA, GL_FLOAT, &floats).unwrap(), [[0.25, 0.5, 0.75, 1.0]]);
    }

    #[test]
    fn integers_normalise_as_mesa_converts_them() {
        // Measured on Mesa 22.3 (glDrawPixels 1×1, read back as bytes): GL_BYTE 1, 64, 127
        // draw 2, 129, 255; GL_SHORT 300 draws 2; GL_UNSIGNED_SHORT 257 draws 1.
        let store = PixelStore { alignment: 1, ..PixelStore::default() };
        let byte = |v: f32| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        let bytes = unpack_image(store, (1, 1), GL_RGBA, GL_BYTE, &[1, 64, 127, 0xff]).unwrap();
        assert_eq!(bytes[0].map(byte), [2, 129, 255, 0]);
        let shorts: Vec<u8> = [1i16, 16384, 32767, 300].iter().flat_map(|s| s.to_ne_bytes()).collect();
        let shorts = unpack_image(store, (1, 1), GL_RGBA, GL_SHORT, &shorts).unwrap();
        assert_eq!(shorts[0].map(byte), [0, 128, 255, 2]);
        let ushorts: Vec<u8> = [257u16, 32768, 65535, 128].iter().flat_map(|s| s.to_ne_bytes()).collect();
        let ushorts = unpack_image(store, (1, 1), GL_RGBA, GL_UNSIGNED_SHORT, &ushorts).unwrap();
        assert_eq!(ushorts[0].map(byte), [1, 128, 255, 0]);
        assert_eq!(unpack_image(store, (1, 1), GL_LUMINANCE, GL_BYTE, &[0x80]).unwrap()[0], [-1.0, -1.0, -1.0, 1.0]);
    }

    #[test]
    fn packed_types_put_the_first_component_high_or_low() {
        let store = PixelStore { alignment: 1, ..PixelStore::default() };
        // 3_3_2: red in the top three bits; 2_3_3_REV: red in the lowest three.
        assert_eq!(
            unpack_image(store, (1, 1), GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &[0b1110_0000]).unwrap()[0],
            [1.0, 0.0, 0.0, 1.0]
        );
        assert_eq!(
            unpack_image(store, (1, 1), GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, &[0b0000_0111]).unwrap()[0],
            [1.0, 0.0, 0.0, 1.0]
        );
        let word = 0x1234_56ffu32.to_ne_bytes();
        let rgba = unpack_image(store, (1, 1), GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, &word).unwrap()[0];
        assert_eq!(rgba.map(|c| (c * 255.0).round() as u8), [0x12, 0x34, 0x56, 0xff]);
        let rev = unpack_image(store, (1, 1), GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, &word).unwrap()[0];
        // REV: B = 0xff, G = 0x56, R = 0x34, A = 0x12 (BGRA's order from the lowest byte).
        assert_eq!(rev.map(|c| (c * 255.0).round() as u8), [0x34, 0x56, 0xff, 0x12]);
        let ones = (1u16 | (31 << 11)).to_ne_bytes();
        assert_eq!(
            unpack_image(store, (1, 1), GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, &ones).unwrap()[0],
            [1.0, 0.0, 0.0, 1.0]
        );
        assert_eq!(format_and_type_error(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5), Some(GL_INVALID_OPERATION));
        assert_eq!(format_and_type_error(GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8), Some(GL_INVALID_OPERATION));
        assert_eq!(format_and_type_error(GL_RGB, GL_BITMAP), Some(GL_INVALID_ENUM));
        assert_eq!(format_and_type_error(GL_COLOR_INDEX, GL_BITMAP), None);
    }

    #[test]
    fn indices_stay_integers_and_bitmaps_read_bits() {
        let store = PixelStore { alignment: 1, ..PixelStore::default() };
        let ints: Vec<u8> = [-3i32, 70000, 0x7654_3210].iter().flat_map(|s| s.to_ne_bytes()).collect();
        let rgba = unpack_image(store, (3, 1), GL_COLOR_INDEX, GL_INT, &ints).unwrap();
        // 32-bit indices keep their low 24 bits exactly (-3 is 0xFFFFFD).
        assert_eq!([rgba[0][0], rgba[1][0], rgba[2][0]], [16_777_213.0, 70000.0, 5_517_840.0]);
        // 0x8f: bits 1000 1111, most significant first.
        let bits = unpack_image(store, (8, 1), GL_COLOR_INDEX, GL_BITMAP, &[0x8f]).unwrap();
        let reds: Vec<f32> = bits.iter().map(|p| p[0]).collect();
        assert_eq!(reds, [1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
        assert!(unpack_image(store, (8, 1), GL_RGBA, GL_BITMAP, &[0x8f]).unwrap().is_empty());
    }

    #[test]
    fn swapped_bytes_rows_and_short_data() {
        let store = PixelStore { alignment: 4, swap_bytes: true, ..PixelStore::default() };
        // Two rows of one GL_UNSIGNED_SHORT luminance in the other byte order, each padded to
        // four bytes.
        let swapped = |v: u16| {
            let mut b = v.to_ne_bytes();
            b.reverse();
            b
        };
        let data: Vec<u8> = [swapped(255).as_slice(), &[0, 0], &swapped(65280)].concat();
        let rgba = unpack_image(store, (1, 2), GL_LUMINANCE, GL_UNSIGNED_SHORT, &data).unwrap();
        assert_eq!([rgba[0][0], rgba[1][0]], [255.0 / 65535.0, 65280.0 / 65535.0]);
        assert_eq!(unpack_image(store, (1, 2), GL_LUMINANCE, GL_UNSIGNED_SHORT, &data[..5]), None);
        let store = PixelStore { alignment: 1, ..PixelStore::default() };
        let bgra = unpack_image(store, (1, 1), GL_BGRA, GL_UNSIGNED_BYTE, &[0, 0, 255, 255]).unwrap();
        assert_eq!(bgra[0], [1.0, 0.0, 0.0, 1.0]);
    }
}
