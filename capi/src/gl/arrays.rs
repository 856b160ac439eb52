//! Vertex arrays: `gl*Pointer`, `glInterleavedArrays`, client state, `glArrayElement`,
//! `glDrawArrays`, `glDrawElements`, GL 1.2's `glDrawRangeElements` and GL 1.4's multi-draws,
//! `glGetPointerv`, edge flags.
//!
//! GL keeps the caller's pointers and reads through them when it draws (GL 1.1 §2.8): each
//! pointer becomes a [`RawMemory`] that `Gl` reads, at draw time, exactly the elements the draw
//! call's arguments name (the caller's promise, as in GL). While a buffer object is bound
//! (GL 1.5 §2.9) a pointer is an offset into it instead, and no client memory is read: `Gl`
//! decides which ([`CPointer`] is both), and the element draws take their index pointer as an
//! offset when a buffer is bound to `GL_ELEMENT_ARRAY_BUFFER`.

use crate::context::with_gl;
use crate::memory::{array, bytes};
use gleval::gl::consts::*;
use gleval::gl::types::*;
use gleval::gl::{ClientMemory, ClientPointer, Gl, PointerArg};
use std::any::Any;
use std::ffi::c_void;
use std::rc::Rc;

/// The caller's memory at a C pointer.
#[derive(Debug)]
pub struct RawMemory(*const u8);

impl ClientMemory for RawMemory {
    fn read(&self, offset: usize, out: &mut [u8]) -> bool {
        let in_range = (self.0 as usize).checked_add(offset).and_then(|a| a.checked_add(out.len()));
        if self.0.is_null() || in_range.is_none_or(|end| end > isize::MAX as usize) {
            return false;
        }
        // SAFETY: the pointer call's contract: the caller's array holds every element that the
        // draw calls made while it is set read (GL 1.1 §2.8), which is what `Gl` asks for.
        unsafe { std::ptr::copy_nonoverlapping(self.0.wrapping_add(offset), out.as_mut_ptr(), out.len()) };
        true
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// A C pointer argument: client memory, or an offset into the bound buffer (its value).
struct CPointer(*const c_void);

impl PointerArg for CPointer {
    fn into_pointer(self) -> Option<ClientPointer> {
        pointer(self.0)
    }

    fn buffer_offset(&self) -> usize {
        self.0 as usize
    }
}

/// A C pointer as the client pointer `Gl` keeps (`None` for NULL).
fn pointer(p: *const c_void) -> Option<ClientPointer> {
    (!p.is_null()).then(|| ClientPointer::new(Rc::new(RawMemory(p.cast())), 0))
}

/// The C address a client pointer was made from; an offset into a buffer object as the
/// pointer of that value (what `glGetPointerv` answers for it).
fn address(p: &ClientPointer) -> *mut c_void {
    match p.memory().as_any().downcast_ref::<RawMemory>() {
        Some(m) => m.0.wrapping_add(p.offset()).cast_mut().cast(),
        None => std::ptr::without_provenance_mut(p.offset()),
    }
}

entry! {
    /// `glVertexPointer`: `Gl::vertex_pointer`, keeping the pointer.
    unsafe fn glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.vertex_pointer(size, type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glNormalPointer`: `Gl::normal_pointer`.
    unsafe fn glNormalPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.normal_pointer(type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glColorPointer`: `Gl::color_pointer`.
    unsafe fn glColorPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.color_pointer(size, type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glSecondaryColorPointer` (GL 1.4): `Gl::secondary_color_pointer`.
    unsafe fn glSecondaryColorPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.secondary_color_pointer(size, type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glSecondaryColorPointerEXT`: `glSecondaryColorPointer`.
    unsafe fn glSecondaryColorPointerEXT(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.secondary_color_pointer(size, type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glFogCoordPointer` (GL 1.4): `Gl::fog_coord_pointer`.
    unsafe fn glFogCoordPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.fog_coord_pointer(type_, stride, pointer(ptr)))
    }
}

entry! {
    /// `glFogCoordPointerEXT`: `glFogCoordPointer`.
    unsafe fn glFogCoordPointerEXT(type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.fog_coord_pointer(type_, stride, pointer(ptr)))
    }
}

entry! {
    /// `glIndexPointer`: `Gl::index_pointer`.
    unsafe fn glIndexPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.index_pointer(type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glTexCoordPointer`: `Gl::tex_coord_pointer`.
    unsafe fn glTexCoordPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.tex_coord_pointer(size, type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glEdgeFlagPointer`: `Gl::edge_flag_pointer`.
    unsafe fn glEdgeFlagPointer(stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.edge_flag_pointer(stride, CPointer(ptr)))
    }
}

// GL_EXT_vertex_array (1995), GL 1.1's arrays before they were core: the same calls with an
// element count the implementation may ignore, and Mesa does (`_mesa_VertexPointerEXT` and its
// kin in Mesa's varray.c pass everything but `count` on; `glGetPointervEXT` is
// `glGetPointerv`, `glArrayElementEXT` and `glDrawArraysEXT` are the core calls).

entry! {
    /// `glVertexPointerEXT`: `glVertexPointer`, `count` ignored.
    unsafe fn glVertexPointerEXT(size: GLint, type_: GLenum, stride: GLsizei, _count: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.vertex_pointer(size, type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glNormalPointerEXT`: `glNormalPointer`, `count` ignored.
    unsafe fn glNormalPointerEXT(type_: GLenum, stride: GLsizei, _count: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.normal_pointer(type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glColorPointerEXT`: `glColorPointer`, `count` ignored.
    unsafe fn glColorPointerEXT(size: GLint, type_: GLenum, stride: GLsizei, _count: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.color_pointer(size, type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glIndexPointerEXT`: `glIndexPointer`, `count` ignored.
    unsafe fn glIndexPointerEXT(type_: GLenum, stride: GLsizei, _count: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.index_pointer(type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glTexCoordPointerEXT`: `glTexCoordPointer`, `count` ignored.
    unsafe fn glTexCoordPointerEXT(size: GLint, type_: GLenum, stride: GLsizei, _count: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.tex_coord_pointer(size, type_, stride, CPointer(ptr)))
    }
}

entry! {
    /// `glEdgeFlagPointerEXT`: `glEdgeFlagPointer`, `count` ignored.
    unsafe fn glEdgeFlagPointerEXT(stride: GLsizei, _count: GLsizei, ptr: *const GLboolean) {
        with_gl(|gl| gl.edge_flag_pointer(stride, CPointer(ptr.cast())))
    }
}

entry! {
    /// `glGetPointervEXT`: `glGetPointerv`.
    unsafe fn glGetPointervEXT(pname: GLenum, params: *mut *mut c_void) {
        unsafe { glGetPointerv(pname, params) }
    }
}

forward! {
    glArrayElementEXT(i: GLint) => array_element;
    glDrawArraysEXT(mode: GLenum, first: GLint, count: GLsizei) => draw_arrays;
}

entry! {
    /// `glInterleavedArrays`: `Gl::interleaved_arrays`.
    unsafe fn glInterleavedArrays(format: GLenum, stride: GLsizei, ptr: *const c_void) {
        with_gl(|gl| gl.interleaved_arrays(format, stride, CPointer(ptr)))
    }
}

forward! {
    glEnableClientState(array: GLenum) => enable_client_state;
    glDisableClientState(array: GLenum) => disable_client_state;
    glArrayElement(i: GLint) => array_element;
    glDrawArrays(mode: GLenum, first: GLint, count: GLsizei) => draw_arrays;
    glEdgeFlag(flag: GLboolean) => edge_flag;
}

vector! {
    glEdgeFlagv(GLboolean; 1) => edge_flagv;
}

entry! {
    /// `glDrawElements`: `Gl::draw_elements` over the `count` indices at `indices` (read now).
    unsafe fn glDrawElements(mode: GLenum, count: GLsizei, type_: GLenum, indices: *const c_void) {
        let len = Gl::draw_elements_len(count, type_);
        with_gl(|gl| {
            if gl.element_array_buffer_binding() != 0 {
                return gl.draw_elements_offset(mode, count, type_, indices as usize);
            }
            gl.draw_elements(mode, count, type_, unsafe { bytes(indices, len) })
        })
    }
}

entry! {
    /// `glDrawRangeElements` (GL 1.2): `Gl::draw_range_elements` over the `count` indices at
    /// `indices` (read now).
    unsafe fn glDrawRangeElements(mode: GLenum, start: GLuint, end: GLuint, count: GLsizei, type_: GLenum, indices: *const c_void) {
        unsafe { draw_range_elements(mode, start, end, count, type_, indices) }
    }
}

entry! {
    /// `glDrawRangeElementsEXT` (`GL_EXT_draw_range_elements`): `glDrawRangeElements`.
    unsafe fn glDrawRangeElementsEXT(mode: GLenum, start: GLuint, end: GLuint, count: GLsizei, type_: GLenum, indices: *const c_void) {
        unsafe { draw_range_elements(mode, start, end, count, type_, indices) }
    }
}

/// # Safety
/// `indices` is NULL or addresses `count` indices of `type_`.
unsafe fn draw_range_elements(
    mode: GLenum,
    start: GLuint,
    end: GLuint,
    count: GLsizei,
    type_: GLenum,
    indices: *const c_void,
) {
    let len = Gl::draw_elements_len(count, type_);
    with_gl(|gl| {
        if gl.element_array_buffer_binding() != 0 {
            return gl.draw_range_elements_offset(mode, start, end, count, type_, indices as usize);
        }
        gl.draw_range_elements(mode, start, end, count, type_, unsafe { bytes(indices, len) })
    })
}

entry! {
    /// `glMultiDrawArrays` (GL 1.4): `Gl::multi_draw_arrays` over the first `primcount` firsts
    /// and counts.
    unsafe fn glMultiDrawArrays(mode: GLenum, first: *const GLint, count: *const GLsizei, primcount: GLsizei) {
        unsafe { multi_draw_arrays(mode, first, count, primcount) }
    }
}

entry! {
    /// `glMultiDrawArraysEXT` (`GL_EXT_multi_draw_arrays`): `glMultiDrawArrays`.
    unsafe fn glMultiDrawArraysEXT(mode: GLenum, first: *const GLint, count: *const GLsizei, primcount: GLsizei) {
        unsafe { multi_draw_arrays(mode, first, count, primcount) }
    }
}

/// # Safety
/// `first` and `count` are NULL or address `primcount` values each.
unsafe fn multi_draw_arrays(mode: GLenum, first: *const GLint, count: *const GLsizei, primcount: GLsizei) {
    let n = usize::try_from(primcount).ok();
    let (first, count) = unsafe { (array(first, n), array(count, n)) };
    with_gl(|gl| gl.multi_draw_arrays(mode, first, count, primcount))
}

entry! {
    /// `glMultiDrawElements` (GL 1.4): `Gl::multi_draw_elements`, each index array read now
    /// for its count.
    unsafe fn glMultiDrawElements(mode: GLenum, count: *const GLsizei, type_: GLenum, indices: *const *const c_void, primcount: GLsizei) {
        unsafe { multi_draw_elements(mode, count, type_, indices, primcount) }
    }
}

entry! {
    /// `glMultiDrawElementsEXT` (`GL_EXT_multi_draw_arrays`): `glMultiDrawElements`.
    unsafe fn glMultiDrawElementsEXT(mode: GLenum, count: *const GLsizei, type_: GLenum, indices: *const *const c_void, primcount: GLsizei) {
        unsafe { multi_draw_elements(mode, count, type_, indices, primcount) }
    }
}

/// # Safety
/// `count` and `indices` are NULL or address `primcount` values each, and each `indices[i]`
/// NULL or `count[i]` indices of `type_`.
unsafe fn multi_draw_elements(
    mode: GLenum,
    count: *const GLsizei,
    type_: GLenum,
    indices: *const *const c_void,
    primcount: GLsizei,
) {
    let n = usize::try_from(primcount).ok();
    let (count, pointers) = unsafe { (array(count, n), array(indices, n)) };
    let offsets: Vec<usize> = pointers.iter().map(|&p| p as usize).collect();
    if with_gl(|gl| gl.element_array_buffer_binding()) != 0 {
        return with_gl(|gl| gl.multi_draw_elements_offset(mode, count, type_, &offsets, primcount));
    }
    let indices: Vec<&[u8]> =
        pointers.iter().zip(count).map(|(&p, &c)| unsafe { bytes(p, Gl::draw_elements_len(c, type_)) }).collect();
    with_gl(|gl| gl.multi_draw_elements(mode, count, type_, &indices, primcount))
}

entry! {
    /// `glGetPointerv`: an array's pointer as it was given, or the feedback or selection
    /// buffer's; nothing is written when GL raises an error.
    unsafe fn glGetPointerv(pname: GLenum, params: *mut *mut c_void) {
        with_gl(|gl| {
            let known = gl.get_pointerv_error(pname).is_none();
            let p = gl.get_pointerv(pname);
            let value = match pname {
                GL_FEEDBACK_BUFFER_POINTER => super::feedback::feedback_pointer().cast(),
                GL_SELECTION_BUFFER_POINTER => super::select::select_pointer().cast(),
                _ => p.as_ref().map_or(std::ptr::null_mut(), address),
            };
            if known && !params.is_null() {
                // SAFETY: glGetPointerv's contract: `params` addresses one pointer.
                unsafe { params.write(value) };
            }
        })
    }
}
