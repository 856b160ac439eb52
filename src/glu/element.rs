//! GLU's arithmetic on one component of the GL 1.1 types while it halves an image (SGI GLU 9.0
//! `libutil/mipmap.c`): `extractUbyte` ... `shoveFloat` for 3D images, and the averages of
//! `halveImage_ubyte` ... `halve1Dimage_float` for 2D ones, each type with its own rounding.

use super::memory::{bits, c_int, c_uint, store};
use crate::gl::consts::*;
use crate::gl::types::*;

/// A GL 1.1 component type GLU halves.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Element {
    UByte,
    Byte,
    UShort,
    Short,
    UInt,
    Int,
    Float,
}

impl Element {
    /// The element type of `type_`, `None` for a packed type (and `GL_BITMAP`).
    pub(super) fn of(type_: GLenum) -> Option<Self> {
        Some(match type_ {
            GL_UNSIGNED_BYTE => Self::UByte,
            GL_BYTE => Self::Byte,
            GL_UNSIGNED_SHORT => Self::UShort,
            GL_SHORT => Self::Short,
            GL_UNSIGNED_INT => Self::UInt,
            GL_INT => Self::Int,
            GL_FLOAT => Self::Float,
            _ => return None,
        })
    }

    /// Bytes per component.
    pub(super) fn size(self) -> usize {
        match self {
            Self::UByte | Self::Byte => 1,
            Self::UShort | Self::Short => 2,
            _ => 4,
        }
    }

    fn raw(self, buf: &[u8], at: isize, swap: bool) -> u32 {
        bits(buf, at, self.size(), swap)
    }

    /// `extract*`: the component at `at` as a double. A swapped float is GLU's
    /// `__GLU_SWAP_4_BYTES` converted as the integer it is, not its bits.
    pub(super) fn extract(self, buf: &[u8], at: isize, swap: bool) -> f64 {
        let raw = self.raw(buf, at, swap);
        match self {
            Self::UByte | Self::UShort | Self::UInt => f64::from(raw),
            Self::Byte => f64::from(raw as u8 as i8),
            Self::Short => f64::from(raw as u16 as i16),
            Self::Int => f64::from(raw as i32),
            Self::Float if swap => f64::from(raw as f32),
            Self::Float => f64::from(f32::from_bits(raw)),
        }
    }

    /// `shove*`: `value` converted as C converts a double to the type, component `index`.
    pub(super) fn shove(self, value: f64, index: usize, out: &mut [u8]) {
        let at = index * self.size();
        match self {
            Self::UByte | Self::Byte => store(out, at, &[c_int(value) as u8]),
            Self::UShort | Self::Short => store(out, at, &(c_int(value) as u16).to_ne_bytes()),
            Self::UInt => store(out, at, &c_uint(value).to_ne_bytes()),
            Self::Int => store(out, at, &c_int(value).to_ne_bytes()),
            Self::Float => store(out, at, &(value as f32).to_ne_bytes()),
        }
    }

    /// `halveImage_*`'s average of four components (a 2×2 block), as the element's bytes:
    /// integers `(a + b + c + d + 2) / 4`, unsigned ints in doubles and ints in floats plus a
    /// half, floats in floats.
    pub(super) fn average4(self, buf: &[u8], at: [isize; 4], swap: bool) -> [u8; 4] {
        let raw = at.map(|a| self.raw(buf, a, swap));
        match self {
            Self::UByte | Self::UShort => {
                let sum: u32 = raw.iter().sum();
                self.bytes((sum + 2) / 4)
            }
            Self::Byte => self.bytes(((raw.iter().map(|&r| i32::from(r as u8 as i8)).sum::<i32>() + 2) / 4) as u32),
            Self::Short => self.bytes(((raw.iter().map(|&r| i32::from(r as u16 as i16)).sum::<i32>() + 2) / 4) as u32),
            Self::UInt => {
                let sum: f64 = raw.iter().map(|&r| f64::from(r)).sum();
                self.bytes(c_uint(sum / 4.0 + 0.5))
            }
            Self::Int => {
                let sum = raw.iter().fold(0.0f32, |s, &r| s + r as i32 as f32);
                self.bytes(c_int(f64::from(sum / 4.0) + 0.5) as u32)
            }
            Self::Float => {
                let sum = raw.iter().fold(0.0f32, |s, &r| s + f32::from_bits(r));
                self.bytes((sum / 4.0).to_bits())
            }
        }
    }

    /// `halve1Dimage_*`'s average of two components: integers `(a + b) / 2`, unsigned ints
    /// in doubles truncated, ints read as unsigned and averaged in floats, floats in floats
    /// (a swapped float again converted as an integer).
    pub(super) fn average2(self, buf: &[u8], at: [isize; 2], swap: bool) -> [u8; 4] {
        let [a, b] = at.map(|a| self.raw(buf, a, swap));
        match self {
            Self::UByte | Self::UShort => self.bytes((a + b) / 2),
            Self::Byte => self.bytes(((i32::from(a as u8 as i8) + i32::from(b as u8 as i8)) / 2) as u32),
            Self::Short => self.bytes(((i32::from(a as u16 as i16) + i32::from(b as u16 as i16)) / 2) as u32),
            Self::UInt => self.bytes(c_uint((f64::from(a) + f64::from(b)) / 2.0)),
            Self::Int => self.bytes(c_int(f64::from(a as f32 + b as f32) / 2.0) as u32),
            Self::Float => {
                let f = |r: u32| if swap { r as f32 } else { f32::from_bits(r) };
                self.bytes(((f64::from(f(a) + f(b)) / 2.0) as f32).to_bits())
            }
        }
    }

    /// `value`'s low bytes as the element (machine order).
    fn bytes(self, value: u32) -> [u8; 4] {
        match self.size() {
            1 => [value as u8, 0, 0, 0],
            2 => {
                let b = (value as u16).to_ne_bytes();
                [b[0], b[1], 0, 0]
            }
            _ => value.to_ne_bytes(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn averages_round_as_glu_does() {
        // Worked out from mipmap.c's expressions: bytes (0 + 1 + 1 + 1 + 2) / 4 = 1, a pair
        // (0 + 1) / 2 = 0; signed bytes truncate toward 0: (-1 - 1 - 1 - 2 + 2) / 4 = 0.
        assert_eq!(Element::UByte.average4(&[0, 1, 1, 1], [0, 1, 2, 3], false)[0], 1);
        assert_eq!(Element::UByte.average2(&[0, 1], [0, 1], false)[0], 0);
        assert_eq!(Element::Byte.average4(&[255, 255, 255, 254], [0, 1, 2, 3], false)[0], 0);
        // 3D: the mean of eight truncated, a signed one toward 0.
        assert_eq!(Element::Byte.extract(&[0xFF], 0, false), -1.0);
        let mut out = [0u8; 2];
        Element::Byte.shove(-1.5, 1, &mut out);
        assert_eq!(out, [0, 0xFF]);
        // A swapped float is its integer: bits 0x3F800000 as 1065353216.0.
        assert_eq!(Element::Float.extract(&1.0f32.to_le_bytes(), 0, true), 1_065_353_216.0);
    }
}
