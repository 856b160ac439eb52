//! GLU's own reading and writing of GL 1.2's packed pixel types (SGI GLU 9.0
//! `libutil/mipmap.c`: `extract332` ... `shove2101010rev`), which is not GL's: each field
//! becomes a float by division by its largest value, and goes back as the float times that
//! value plus a half, truncated (in float arithmetic, but in double for 2_3_3_REV and
//! 5_6_5_REV, whose constants are written `7.0` and `31.0`).

use super::memory::{bits, c_uint, store};
use crate::gl::consts::*;
use crate::gl::types::*;

/// One packed type's layout: bytes a pixel, each component's (shift, bits) in the order GLU
/// extracts them, and whether its shove multiplies in double.
#[derive(Clone, Copy, Debug)]
pub(super) struct PackedPixel {
    pub size: usize,
    fields: &'static [(u32, u32)],
    double: bool,
}

impl PackedPixel {
    /// The layout of `type_`, `None` for a type that is not packed.
    pub(super) fn of(type_: GLenum) -> Option<Self> {
        let (size, fields, double): (usize, &'static [(u32, u32)], bool) = match type_ {
            GL_UNSIGNED_BYTE_3_3_2 => (1, &[(5, 3), (2, 3), (0, 2)], false),
            GL_UNSIGNED_BYTE_2_3_3_REV => (1, &[(0, 3), (3, 3), (6, 2)], true),
            GL_UNSIGNED_SHORT_5_6_5 => (2, &[(11, 5), (5, 6), (0, 5)], false),
            GL_UNSIGNED_SHORT_5_6_5_REV => (2, &[(0, 5), (5, 6), (11, 5)], true),
            GL_UNSIGNED_SHORT_4_4_4_4 => (2, &[(12, 4), (8, 4), (4, 4), (0, 4)], false),
            GL_UNSIGNED_SHORT_4_4_4_4_REV => (2, &[(0, 4), (4, 4), (8, 4), (12, 4)], false),
            GL_UNSIGNED_SHORT_5_5_5_1 => (2, &[(11, 5), (6, 5), (1, 5), (0, 1)], false),
            GL_UNSIGNED_SHORT_1_5_5_5_REV => (2, &[(0, 5), (5, 5), (10, 5), (15, 1)], false),
            GL_UNSIGNED_INT_8_8_8_8 => (4, &[(24, 8), (16, 8), (8, 8), (0, 8)], false),
            GL_UNSIGNED_INT_8_8_8_8_REV => (4, &[(0, 8), (8, 8), (16, 8), (24, 8)], false),
            GL_UNSIGNED_INT_10_10_10_2 => (4, &[(22, 10), (12, 10), (2, 10), (0, 2)], false),
            GL_UNSIGNED_INT_2_10_10_10_REV => (4, &[(0, 10), (10, 10), (20, 10), (30, 2)], false),
            _ => return None,
        };
        Some(Self { size, fields, double })
    }

    /// Components a pixel: 3 or 4.
    pub(super) fn components(&self) -> usize {
        self.fields.len()
    }

    /// `extract*`: the pixel at `at` as components in [0, 1]. `swap` is GLU's
    /// `__GLU_SWAP_*_BYTES`, a little-endian read (see [`bits`]); the byte types ignore it.
    pub(super) fn extract(&self, buf: &[u8], at: isize, swap: bool) -> [f32; 4] {
        let value = bits(buf, at, self.size, swap);
        let mut out = [0.0; 4];
        for (c, &(shift, b)) in out.iter_mut().zip(self.fields) {
            let max = (1u32 << b) - 1;
            *c = (f64::from((value >> shift) & max) / f64::from(max)) as f32;
        }
        out
    }

    /// `shove*`: `components` as pixel `index` of `out` (machine order).
    pub(super) fn shove(&self, components: &[f32; 4], index: usize, out: &mut [u8]) {
        let value = self.pack(components);
        let at = index * self.size;
        match self.size {
            1 => store(out, at, &[value as u8]),
            2 => store(out, at, &(value as u16).to_ne_bytes()),
            _ => store(out, at, &value.to_ne_bytes()),
        }
    }

    /// The packed value of `components`, each `(c · max + 0.5)` truncated to the element's
    /// type, then shifted into its field and masked.
    pub(super) fn pack(&self, components: &[f32; 4]) -> u32 {
        let type_mask = match self.size {
            1 => 0xFF,
            2 => 0xFFFF,
            _ => u64::from(u32::MAX),
        };
        let mut value = 0u64;
        for (&c, &(shift, b)) in components.iter().zip(self.fields) {
            let max = (1u32 << b) - 1;
            let scaled = if self.double { f64::from(c) * f64::from(max) } else { f64::from(c * max as f32) };
            let field = u64::from(c_uint(scaled + 0.5)) & type_mask;
            value |= (field << shift) & (u64::from(max) << shift);
        }
        value as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_round_trip_as_glu_writes_them() {
        // Worked out from extract565/shove565: 0xF81F is red 31, green 0, blue 31.
        let p = PackedPixel::of(GL_UNSIGNED_SHORT_5_6_5).unwrap();
        let c = p.extract(&0xF81Fu16.to_ne_bytes(), 0, false);
        assert_eq!(c[..3], [1.0, 0.0, 1.0]);
        assert_eq!(p.pack(&c), 0xF81F);
        // Half of 7 is 3.5, plus 0.5 truncates to 4; of 3, 1.5 + 0.5 = 2.
        let p = PackedPixel::of(GL_UNSIGNED_BYTE_3_3_2).unwrap();
        assert_eq!(p.pack(&[0.5, 0.0, 0.5, 0.0]), 4 << 5 | 2);
        assert!(PackedPixel::of(GL_UNSIGNED_BYTE).is_none());
    }
}
