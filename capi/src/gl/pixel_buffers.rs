//! GL 2.1's pixel buffer objects in the entry points that read or write images
//! (`GL_ARB_pixel_buffer_object`; the rules are `Gl`'s `pixel_buffers.rs`), and GL 3.0's
//! `glMapBufferRange` and `glFlushMappedBufferRange` (`GL_ARB_map_buffer_range`).
//!
//! While a buffer is bound to `GL_PIXEL_UNPACK_BUFFER`, an image pointer is an offset into it:
//! [`unpack_source`] gives the call the buffer's bytes instead of the client's. While one is
//! bound to `GL_PIXEL_PACK_BUFFER`, [`pack_into`] lets the call write into the buffer. Both
//! check the range before the call runs (Mesa checks it after the target, level, format and
//! type: a call wrong in those and out of the buffer gets `GL_INVALID_OPERATION` here where
//! Mesa gives the other error).

use crate::context::with_gl;
use crate::memory::{array, array_mut, Element};
use gleval::gl::types::*;
use gleval::gl::Gl;
use std::borrow::Cow;
use std::ffi::c_void;

/// The `len` values an unpacking call reads at `ptr`: the client's memory, or with a buffer
/// bound to `GL_PIXEL_UNPACK_BUFFER` the buffer's from byte offset `ptr`; `len` `None` (GL
/// rejects the call before it reads) gives the one-value stand-in either way. `None` when the
/// buffer cannot be read (`Gl` has raised `GL_INVALID_OPERATION`): the call does nothing.
///
/// # Safety
/// Without a buffer bound, `ptr` is NULL or addresses `len` readable values.
pub(crate) unsafe fn unpack_source<'a, T: Element + bytemuck::Pod>(
    gl: &mut Gl,
    ptr: *const T,
    len: Option<usize>,
) -> Option<Cow<'a, [T]>> {
    if gl.pixel_unpack_buffer_binding() == 0 {
        return Some(Cow::Borrowed(unsafe { array(ptr, len) }));
    }
    let Some(n) = len else { return Some(Cow::Borrowed(T::STAND_IN)) };
    let bytes = gl.read_unpack_buffer(ptr as usize, n.checked_mul(size_of::<T>())?)?;
    Some(Cow::Owned(bytemuck::pod_collect_to_vec(&bytes)))
}

/// [`unpack_source`] of an image's bytes.
///
/// # Safety
/// As [`unpack_source`].
pub(crate) unsafe fn unpack_bytes<'a>(gl: &mut Gl, ptr: *const c_void, len: Option<usize>) -> Option<Cow<'a, [u8]>> {
    unsafe { unpack_source(gl, ptr.cast::<u8>(), len) }
}

/// Runs a packing call's `write` on the `len` values it writes at `ptr`: the client's memory,
/// or with a buffer bound to `GL_PIXEL_PACK_BUFFER` the buffer's from byte offset `ptr` (left
/// untouched, with `GL_INVALID_OPERATION`, when the range is outside it or it is mapped).
///
/// # Safety
/// Without a buffer bound, `ptr` is NULL or addresses `len` writable values.
pub(crate) unsafe fn pack_into<T: Element + bytemuck::Pod>(
    gl: &mut Gl,
    ptr: *mut T,
    len: usize,
    write: impl FnOnce(&mut Gl, &mut [T]),
) {
    if gl.pixel_pack_buffer_binding() == 0 {
        return write(gl, unsafe { array_mut(ptr, len) });
    }
    if len == 0 {
        return write(gl, &mut []);
    }
    // A length past memory is past any buffer too.
    let size = len.saturating_mul(size_of::<T>());
    gl.write_pack_buffer(ptr as usize, size, |gl, bytes| {
        let mut values: Vec<T> = bytemuck::pod_collect_to_vec(bytes);
        write(gl, &mut values);
        bytes.copy_from_slice(bytemuck::cast_slice(&values));
    });
}

/// [`pack_into`] for a call whose length comes from the context (`Gl::packed_image_len`...).
///
/// # Safety
/// As [`pack_into`].
pub(crate) unsafe fn pack_with<T: Element + bytemuck::Pod>(
    ptr: *mut T,
    len: impl FnOnce(&Gl) -> usize,
    write: impl FnOnce(&mut Gl, &mut [T]),
) {
    with_gl(|gl| {
        let n = len(gl);
        unsafe { pack_into(gl, ptr, n, write) }
    })
}

entry! {
    /// `glMapBufferRange` (GL 3.0): the mapped range's address, NULL on an error.
    fn glMapBufferRange(target: GLenum, offset: GLintptr, length: GLsizeiptr, access: GLbitfield) -> *mut c_void {
        with_gl(|gl| gl.map_buffer_range(target, offset, length, access).map_or(std::ptr::null_mut(), |m| m.as_ptr().cast()))
    }
}

forward! {
    glFlushMappedBufferRange(target: GLenum, offset: GLintptr, length: GLsizeiptr) => flush_mapped_buffer_range;
}
