//! GL 1.2's packed pixel types (GL 1.2 spec §3.6.4 "Packed Pixels", table 3.8, and the
//! bitfield layouts of tables 3.9–3.11; §4.3.2 packs with the same layouts): one element of 1,
//! 2 or 4 bytes holds a whole pixel, its components in bitfields from the highest bits down,
//! or, for the `_REV` types, from the lowest up. The one table of the 12 types, read by
//! [`super::pixel_unpack`] (`glDrawPixels`, `glTexImage`) and written by
//! [`super::pixel_pack`] (`glReadPixels`, `glGetTexImage`).

use super::consts::*;
use super::types::*;

/// A packed type: the bytes of its one element a pixel, the bits of each component from the
/// first (the format's first component, red for `GL_RGBA`, blue for `GL_BGRA`), and whether
/// the first sits in the lowest bits (`_REV`) rather than the highest.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Packed {
    pub(crate) size: usize,
    bits: &'static [u32],
    reversed: bool,
}

/// The layout of a packed type, `None` for any other type.
pub(crate) fn packed(type_: GLenum) -> Option<Packed> {
    let (size, bits, reversed): (usize, &'static [u32], bool) = match type_ {
        GL_UNSIGNED_BYTE_3_3_2 => (1, &[3, 3, 2], false),
        GL_UNSIGNED_BYTE_2_3_3_REV => (1, &[3, 3, 2], true),
        GL_UNSIGNED_SHORT_5_6_5 => (2, &[5, 6, 5], false),
        GL_UNSIGNED_SHORT_5_6_5_REV => (2, &[5, 6, 5], true),
        GL_UNSIGNED_SHORT_4_4_4_4 => (2, &[4, 4, 4, 4], false),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => (2, &[4, 4, 4, 4], true),
        GL_UNSIGNED_SHORT_5_5_5_1 => (2, &[5, 5, 5, 1], false),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => (2, &[5, 5, 5, 1], true),
        GL_UNSIGNED_INT_8_8_8_8 => (4, &[8, 8, 8, 8], false),
        GL_UNSIGNED_INT_8_8_8_8_REV => (4, &[8, 8, 8, 8], true),
        GL_UNSIGNED_INT_10_10_10_2 => (4, &[10, 10, 10, 2], false),
        GL_UNSIGNED_INT_2_10_10_10_REV => (4, &[10, 10, 10, 2], true),
        // GL_EXT_packed_depth_stencil: a 24-bit depth over an 8-bit stencil index.
        GL_UNSIGNED_INT_24_8 => (4, &[24, 8], false),
        _ => return None,
    };
    Some(Packed { size, bits, reversed })
}

/// Bytes a pixel of `GL_DEPTH_STENCIL` takes in `type_`: 4 in `GL_UNSIGNED_INT_24_8`, 8 in
/// `GL_ARB_depth_buffer_float`'s `GL_FLOAT_32_UNSIGNED_INT_24_8_REV` (a float depth, then a
/// word whose low 8 bits are the stencil index); `None` for another type.
pub(crate) fn depth_stencil_size(type_: GLenum) -> Option<usize> {
    match type_ {
        GL_UNSIGNED_INT_24_8 => Some(4),
        GL_FLOAT_32_UNSIGNED_INT_24_8_REV => Some(8),
        _ => None,
    }
}

/// Whether `format` cannot go with the packed `type_`: Mesa 22.3 takes a 3-component type
/// with `GL_RGB` alone (not `GL_BGR`) and a 4-component one with `GL_RGBA` or `GL_BGRA`, and
/// gives any other format `GL_INVALID_OPERATION`, an unknown one included (measured with
/// `glDrawPixels`, `glTexImage2D`, `glReadPixels` and `glGetTexImage`,
/// `tests/reference/calls/cases/pack_types.calls`).
pub(crate) fn packed_mismatch(format: GLenum, type_: GLenum) -> bool {
    if type_ == GL_FLOAT_32_UNSIGNED_INT_24_8_REV {
        return format != GL_DEPTH_STENCIL;
    }
    packed(type_).is_some_and(|p| match p.bits.len() {
        2 => format != GL_DEPTH_STENCIL,
        3 => format != GL_RGB,
        _ => !matches!(format, GL_RGBA | GL_BGRA),
    })
}

/// Where the colours being packed come from, which decides how Mesa converts them to a
/// bitfield (measured on Mesa 22.3, `pack_types.calls`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Source {
    /// 8-bit values, a window's or a texture's, not through the pixel transfer: converted from
    /// the byte as integers ([`from_unorm8`]: 43 into 10 bits is 172, where 43/255·1023 =
    /// 172.51 would round to 173).
    Unorm8,
    /// Floats after the pixel transfer: the product by the field's largest value in f32,
    /// plus 0.5 in f32, truncated (a product of 2.5 gives 3, not the even 2; one of
    /// 0.49999997 gives 1, as the sum rounds to 1.0).
    Float,
    /// A depth texture's depths (GL 1.4): `glGetTexImage` packs them as `glReadPixels` packs
    /// depths, but `GL_UNSIGNED_SHORT` to the nearest integer (measured: a 24-bit 0.24999995
    /// reads as 0x4000); no packed type takes depths.
    TextureDepth,
}

impl Packed {
    /// Components per pixel: 3 or 4.
    pub(crate) fn components(&self) -> usize {
        self.bits.len()
    }

    /// Each component's (shift, bits), from the first component to the last.
    fn fields(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        let total = 8 * self.size as u32;
        let mut used = 0;
        self.bits.iter().map(move |&b| {
            let shift = if self.reversed { used } else { total - used - b };
            used += b;
            (shift, b)
        })
    }

    /// The components of one element, each normalised by its field's largest value
    /// (GL 1.2 §3.6.4, "Conversion to floating-point"), a field of fewer than 8 bits as the
    /// byte its bits repeated make, over 255: Mesa widens such a field to 8 bits so
    /// (`_mesa_unorm_to_unorm` in `format_utils.h`, through `_mesa_unpack_ubyte_rgba_row`;
    /// measured: 5 bits' 3 is 24 where 3/31 of 255 rounds to 25, 6 bits' 11 is 44, not 45;
    /// `unpack_widening.calls`), and glTexImage and glDrawPixels store or draw it unchanged.
    pub(crate) fn unpack(&self, value: u32, out: &mut [f32; 4]) {
        for (k, (shift, b)) in self.fields().enumerate() {
            let max = field_max(b);
            let field = (value >> shift) & max;
            out[k] = if b < 8 {
                (f64::from(widen_to_byte(field, b)) / 255.0) as f32
            } else {
                (f64::from(field) / f64::from(max)) as f32
            };
        }
    }

    /// One element holding `components` ∈ [0, 1], in the format's order.
    pub(crate) fn pack(&self, components: &[f32], source: Source) -> u32 {
        self.fields().zip(components).fold(0, |value, ((shift, b), &c)| value | to_field(c, b, source) << shift)
    }

    /// The element at `bytes` (its size, in client byte order unless `swap`).
    pub(crate) fn read(&self, bytes: &[u8], swap: bool) -> u32 {
        let mut b = [0u8; 4];
        b[..self.size].copy_from_slice(&bytes[..self.size]);
        if swap {
            b[..self.size].reverse();
        }
        match self.size {
            1 => u32::from(b[0]),
            2 => u32::from(u16::from_ne_bytes([b[0], b[1]])),
            _ => u32::from_ne_bytes(b),
        }
    }

    /// Writes `value` into `out` (its size), in client byte order unless `swap`: swapping
    /// reverses the element's bytes, as `GL_PACK_SWAP_BYTES` does (GL 1.2 §4.3.2).
    pub(crate) fn write(&self, value: u32, swap: bool, out: &mut [u8]) {
        let mut bytes = [0u8; 4];
        match self.size {
            1 => bytes[0] = value as u8,
            2 => bytes[..2].copy_from_slice(&(value as u16).to_ne_bytes()),
            _ => bytes = value.to_ne_bytes(),
        }
        let bytes = &mut bytes[..self.size];
        if swap {
            bytes.reverse();
        }
        out[..self.size].copy_from_slice(bytes);
    }
}

/// A field of `bits` (1 to 7) bits as 8: its bits repeated from the top (5 bits abcde make
/// abcdeabc), which is the rounded product by 255/(2ᵇ − 1) for 1, 2, 3 and 4 bits but not for
/// 5 or 6.
fn widen_to_byte(field: u32, bits: u32) -> u32 {
    let (mut repeated, mut filled) = (0, 0);
    while filled < 8 {
        repeated = repeated << bits | field;
        filled += bits;
    }
    repeated >> (filled - 8)
}

/// A field's largest value, 2ᵇ − 1 (`bits` below 32).
fn field_max(bits: u32) -> u32 {
    (1 << bits) - 1
}

/// One component `c` ∈ [0, 1] as a field of `bits` bits (see [`Source`]).
fn to_field(c: f32, bits: u32, source: Source) -> u32 {
    match source {
        Source::Unorm8 => from_unorm8(byte_of(c), bits),
        Source::Float | Source::TextureDepth => (c.clamp(0.0, 1.0) * field_max(bits) as f32 + 0.5) as u32,
    }
}

/// The byte an 8-bit colour `c` (a window's or texture's value over 255) came from.
pub(crate) fn byte_of(c: f32) -> u32 {
    (c.clamp(0.0, 1.0) * 255.0).round() as u32
}

/// An 8-bit unsigned normalised `byte` as one of `bits` (1 to 32) bits, as Mesa converts
/// between unorm sizes (measured, `pack_types.calls`): to fewer bits rounded to nearest
/// (byte·(2ᵇ − 1)/255 is never halfway: 2ᵇ − 1 is odd), to more the byte's bits repeated from
/// the top (10 bits: 43 = 0b00101011 becomes 0b0010101100 = 172, 31 bits for `GL_INT`: 200
/// becomes 0x64646464).
pub(crate) fn from_unorm8(byte: u32, bits: u32) -> u32 {
    if bits <= 8 {
        return (byte * field_max(bits) + 127) / 255;
    }
    let (mut repeated, mut filled) = (0u64, 0);
    while filled < bits {
        repeated = repeated << 8 | u64::from(byte);
        filled += 8;
    }
    (repeated >> (filled - bits)) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fields of a packed value, worked out by hand from GL 1.2 tables 3.9–3.11.
    #[test]
    fn layouts_put_the_first_component_high_or_low() {
        let p = packed(GL_UNSIGNED_BYTE_3_3_2).unwrap();
        // 3_3_2: bits 7–5 the first, 4–2 the second, 1–0 the third.
        assert_eq!(p.pack(&[1.0, 0.0, 1.0], Source::Unorm8), 0b111 << 5 | 0b11);
        let rev = packed(GL_UNSIGNED_BYTE_2_3_3_REV).unwrap();
        // 2_3_3_REV: bits 2–0 the first, 5–3 the second, 7–6 the third.
        assert_eq!(rev.pack(&[1.0, 0.0, 1.0], Source::Unorm8), 0b11 << 6 | 0b111);
        let p = packed(GL_UNSIGNED_SHORT_1_5_5_5_REV).unwrap();
        // 1_5_5_5_REV: the first in bits 4–0, the fourth (alpha) in bit 15.
        assert_eq!(p.pack(&[0.0, 0.0, 0.0, 1.0], Source::Unorm8), 0x8000);
        assert_eq!(p.pack(&[1.0, 0.0, 0.0, 0.0], Source::Unorm8), 0x001F);
        let p = packed(GL_UNSIGNED_INT_10_10_10_2).unwrap();
        assert_eq!(p.pack(&[0.0, 0.0, 0.0, 1.0], Source::Unorm8), 3);
        assert_eq!(p.pack(&[1.0, 0.0, 0.0, 0.0], Source::Unorm8), 0x3FF << 22);
        let p = packed(GL_UNSIGNED_INT_2_10_10_10_REV).unwrap();
        assert_eq!(p.pack(&[0.0, 1.0, 0.0, 0.0], Source::Unorm8), 0x3FF << 10);
        let mut out = [0.0; 4];
        p.unpack(3 << 30 | 0x3FF, &mut out);
        assert_eq!(out, [1.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn bytes_narrow_by_rounding_and_widen_by_repeating_bits() {
        let byte = |x: u8| f32::from(x) / 255.0;
        // 5 bits: 43·31/255 = 5.23 → 5; 128·31/255 = 15.56 → 16.
        assert_eq!(to_field(byte(43), 5, Source::Unorm8), 5);
        assert_eq!(to_field(byte(128), 5, Source::Unorm8), 16);
        // 2 bits: 43·3/255 = 0.506 → 1 (the byte's top bits, 00, would say 0).
        assert_eq!(to_field(byte(43), 2, Source::Unorm8), 1);
        // 10 bits: 0b00101011 followed by its top two bits 00 → 0b0010101100 = 172.
        assert_eq!(to_field(byte(43), 10, Source::Unorm8), 172);
        assert_eq!(to_field(byte(200), 10, Source::Unorm8), 200 * 4 + 3);
        assert_eq!(to_field(1.0, 10, Source::Unorm8), 1023);
        assert_eq!(to_field(byte(77), 8, Source::Unorm8), 77);
        // GL_SHORT's 15 bits, GL_INT's 31, GL_UNSIGNED_INT's 32.
        assert_eq!(from_unorm8(1, 15), 0x0080);
        assert_eq!(from_unorm8(254, 15), 0x7F7F);
        assert_eq!(from_unorm8(43, 31), 0x1595_9595);
        assert_eq!(from_unorm8(200, 32), 0xC8C8_C8C8);
        assert_eq!(from_unorm8(255, 16), 0xFFFF);
        // GL_BYTE's 7 bits: 127·127/255 = 63.25 → 63, 254·127/255 = 126.5 + 0.002 → 127.
        assert_eq!(from_unorm8(127, 7), 63);
        assert_eq!(from_unorm8(254, 7), 127);
        assert_eq!(from_unorm8(0, 7), 0);
    }

    #[test]
    fn narrow_fields_widen_by_repeating_bits() {
        // Worked out by hand: 5 bits 00011 → 00011000 | 000 = 24; 6 bits 001011 → 00101100 | 00 = 44;
        // 3 bits 101 → 10110110 = 182; 1 bit → 0 or 255.
        assert_eq!(widen_to_byte(3, 5), 24);
        assert_eq!(widen_to_byte(31, 5), 255);
        assert_eq!(widen_to_byte(11, 6), 44);
        assert_eq!(widen_to_byte(5, 3), 182);
        assert_eq!(widen_to_byte(1, 1), 255);
        let p = packed(GL_UNSIGNED_SHORT_5_6_5).unwrap();
        let mut out = [0.0; 4];
        p.unpack(3 << 11 | 11 << 5 | 28, &mut out);
        let bytes = out.map(|c| (c * 255.0).round() as u8);
        assert_eq!(bytes[..3], [24, 44, 231]);
    }

    #[test]
    fn floats_round_half_up_in_f32() {
        // 2.5/31 as an f32 (0x3DA5294A) times 31 is 2.5 exactly in f32 (2.49999993 in reals): 3.
        assert_eq!(to_field(f32::from_bits(0x3DA5_294A), 5, Source::Float), 3);
        // 0.0714285672 · 7 is 0.49999997 in f32, + 0.5 rounds to 1.0 in f32: 1, where the real
        // sum truncates to 0.
        assert_eq!(to_field(f32::from_bits(0x3D92_4924), 3, Source::Float), 1);
        // 43/255·1023 = 172.51 → 173 from a float (172 from the byte).
        assert_eq!(to_field(43.0 / 255.0, 10, Source::Float), 173);
        assert_eq!(to_field(1.5, 4, Source::Float), 15);
        assert_eq!(to_field(-0.5, 4, Source::Float), 0);
    }

    #[test]
    fn elements_read_and_write_in_either_byte_order() {
        let p = packed(GL_UNSIGNED_SHORT_5_6_5).unwrap();
        let mut out = [0u8; 2];
        p.write(0x1234, false, &mut out);
        assert_eq!(out, 0x1234u16.to_ne_bytes());
        assert_eq!(p.read(&out, false), 0x1234);
        p.write(0x1234, true, &mut out);
        assert_eq!(out, 0x3412u16.to_ne_bytes());
        assert_eq!(p.read(&out, true), 0x1234);
        let p = packed(GL_UNSIGNED_INT_8_8_8_8).unwrap();
        let mut out = [0u8; 4];
        p.write(0x1122_3344, true, &mut out);
        assert_eq!(out, 0x4433_2211u32.to_ne_bytes());
        assert!(packed_mismatch(GL_BGR, GL_UNSIGNED_BYTE_3_3_2));
        assert!(packed_mismatch(GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4));
        assert!(packed_mismatch(0x1234, GL_UNSIGNED_INT_8_8_8_8));
        assert!(!packed_mismatch(GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV));
        assert!(!packed_mismatch(GL_LUMINANCE, GL_UNSIGNED_BYTE));
    }
}
