//! GLU's image buffers as its C reads and writes them (SGI GLU 9.0 `libutil/mipmap.c`): bytes
//! at offsets its pointer arithmetic computes. That arithmetic is not always right (an odd side
//! halved in 3D steps one pixel short, a slice of images steps by whole images), so an offset
//! may fall outside the buffer, where C reads the heap's bytes and writes over them: here such a
//! read is 0 and such a write is dropped, and nothing panics.

use std::cell::Cell;

thread_local! {
    /// The end of the furthest read while [`furthest_read`] watches.
    static FURTHEST: Cell<Option<isize>> = const { Cell::new(None) };
}

/// The end of the furthest byte `f` reads through [`load`] (from offset 0 of its buffer),
/// `None` if it reads nothing: how much of the client's memory a GLU routine reads, slips
/// past the image included.
pub(super) fn furthest_read(f: impl FnOnce()) -> Option<isize> {
    FURTHEST.set(Some(isize::MIN));
    f();
    FURTHEST.replace(None).filter(|&end| end != isize::MIN)
}

/// The `N` bytes at `at`, zeros where they fall outside `buf`.
pub(super) fn load<const N: usize>(buf: &[u8], at: isize) -> [u8; N] {
    if let Some(end) = FURTHEST.get() {
        FURTHEST.set(Some(end.max(at.saturating_add(N as isize))));
    }
    let mut out = [0u8; N];
    if let Some(bytes) = usize::try_from(at).ok().and_then(|at| buf.get(at..at.checked_add(N)?)) {
        out.copy_from_slice(bytes);
    }
    out
}

/// `bytes` written at `at`, dropped where they would not fit in `buf`.
pub(super) fn store(buf: &mut [u8], at: usize, bytes: &[u8]) {
    if let Some(place) = at.checked_add(bytes.len()).and_then(|end| buf.get_mut(at..end)) {
        place.copy_from_slice(bytes);
    }
}

/// The bits of an element of `size` bytes (1, 2 or 4) at `at`: in the machine's order, or
/// assembled little end first when `swap`, as GLU's `__GLU_SWAP_2_BYTES` and
/// `__GLU_SWAP_4_BYTES` do. Those macros were written for a big-endian machine; on a
/// little-endian one a "swapped" read is the plain one, so GLU swaps nothing there.
pub(super) fn bits(buf: &[u8], at: isize, size: usize, swap: bool) -> u32 {
    match (size, swap) {
        (1, _) => u32::from(load::<1>(buf, at)[0]),
        (2, false) => u32::from(u16::from_ne_bytes(load(buf, at))),
        (2, true) => u32::from(u16::from_le_bytes(load(buf, at))),
        (_, false) => u32::from_ne_bytes(load(buf, at)),
        (_, true) => u32::from_le_bytes(load(buf, at)),
    }
}

/// C's conversion of a double to `int` on x86 (`cvttsd2si`): truncation, and the "integer
/// indefinite" `INT_MIN` for NaN and values out of range.
pub(super) fn c_int(v: f64) -> i32 {
    if v.is_nan() || !(-2_147_483_648.0..2_147_483_648.0).contains(&v) {
        i32::MIN
    } else {
        v as i32
    }
}

/// C's conversion of a double to `unsigned int` on x86-64 (through a 64-bit `cvttsd2si`):
/// truncation, then the low 32 bits.
pub(super) fn c_uint(v: f64) -> u32 {
    // ±2⁶³, the 64-bit conversion's range.
    let limit = 2.0f64.powi(63);
    if v.is_nan() || !(-limit..limit).contains(&v) {
        0
    } else {
        v as i64 as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_outside_are_zero_and_writes_outside_dropped() {
        let mut buf = [1u8, 2, 3];
        assert_eq!(load::<2>(&buf, 1), [2, 3]);
        assert_eq!(load::<2>(&buf, 2), [0, 0]);
        assert_eq!(load::<2>(&buf, -1), [0, 0]);
        store(&mut buf, 2, &[9, 9]);
        assert_eq!(buf, [1, 2, 3]);
        store(&mut buf, usize::MAX, &[9]);
        assert_eq!(bits(&[0x34, 0x12], 0, 2, true), 0x1234);
    }

    #[test]
    fn conversions_are_x86s() {
        assert_eq!(c_int(-2.7), -2);
        assert_eq!(c_int(3e9), i32::MIN);
        assert_eq!(c_int(f64::NAN), i32::MIN);
        assert_eq!(c_uint(4_294_967_295.9), u32::MAX);
        assert_eq!(c_uint(-1.0), u32::MAX);
    }
}
