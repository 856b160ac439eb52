//! C pointers to slices, with lengths the caller's call promises.
//!
//! GL reads as much as its arguments say (`order × stride`, an image's rows under the unpack
//! modes); the caller promises that much memory is there, as in GL. Three cases:
//! - NULL becomes an empty slice: `Gl` answers a short slice with `GL_INVALID_VALUE` where GL
//!   reads an array, and takes it as "no data" where GL allows NULL (`glTexImage2D`);
//! - a length the arguments give: a slice of exactly that length;
//! - arguments GL rejects before it reads (an unknown target, a negative size): a one-element
//!   stand-in that is not the caller's memory, so `Gl` reports the error GL reports for the
//!   bad argument (not the NULL error) and nothing of the caller's is read.

use gleval::gl::types::*;

/// The element types C hands us arrays of.
pub trait Element: Copy + 'static {
    /// The one-element stand-in for arrays GL will not read.
    const STAND_IN: &'static [Self];
}

macro_rules! element {
    ($($t:ty = $zero:expr),*) => { $(impl Element for $t { const STAND_IN: &'static [Self] = &[$zero]; })* };
}
element!(f32 = 0.0, f64 = 0.0, i32 = 0, u32 = 0, u8 = 0, i8 = 0, i16 = 0, u16 = 0, *const std::ffi::c_void = std::ptr::null());

/// The slice GL reads at `ptr`: `len` elements, or the stand-in when `len` is `None`.
///
/// # Safety
/// `ptr` is NULL or addresses `len` readable elements.
pub unsafe fn array<'a, T: Element>(ptr: *const T, len: Option<usize>) -> &'a [T] {
    if ptr.is_null() {
        return &[];
    }
    match len.filter(|&n| n.checked_mul(size_of::<T>()).is_some_and(|b| b <= isize::MAX as usize)) {
        // SAFETY: the caller's promise, and a length that fits an allocation.
        Some(n) => unsafe { std::slice::from_raw_parts(ptr, n) },
        None => T::STAND_IN,
    }
}

/// The bytes GL reads at a `const void *`.
///
/// # Safety
/// As [`array()`].
pub unsafe fn bytes<'a>(ptr: *const std::ffi::c_void, len: Option<usize>) -> &'a [u8] {
    unsafe { array(ptr.cast::<u8>(), len) }
}

/// The slice GL writes at `ptr` (`len` elements); NULL gives an empty slice, which `Gl`
/// answers with `GL_INVALID_VALUE` when it has something to write.
///
/// # Safety
/// `ptr` is NULL or addresses `len` writable elements.
pub unsafe fn array_mut<'a, T: Element>(ptr: *mut T, len: usize) -> &'a mut [T] {
    if ptr.is_null() || len.checked_mul(size_of::<T>()).is_none_or(|b| b > isize::MAX as usize) {
        return &mut [];
    }
    // SAFETY: the caller's promise.
    unsafe { std::slice::from_raw_parts_mut(ptr, len) }
}

/// A count from C (`GLint`, `GLsizei`) as a length, `None` if negative.
pub fn count(n: GLint) -> Option<usize> {
    usize::try_from(n).ok()
}

/// Elements a strided layout reads: `k` values at the last point of each dimension's
/// `(stride, order)`; `None` for a negative stride, an order below 1 or above GL's maximum
/// (GL rejects those before reading) or an overflow. A stride below `k` is read as given: GL
/// rejects it when it executes the call, but a display list copies the points first, with the
/// caller's stride (Mesa's `_mesa_copy_map_points1f`).
pub fn strided_len(k: usize, layout: &[(GLint, GLint)], max_order: GLint) -> Option<usize> {
    let mut last = k;
    for &(stride, order) in layout {
        if !(1..=max_order).contains(&order) {
            return None;
        }
        let stride = usize::try_from(stride).ok()?;
        last = last.checked_add(stride.checked_mul(order as usize - 1)?)?;
    }
    Some(last)
}
