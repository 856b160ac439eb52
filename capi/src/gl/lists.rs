//! Display lists.

use crate::context::with_gl;
use crate::memory::bytes;
use gleval::gl::types::*;
use gleval::gl::Gl;
use std::ffi::c_void;

forward! {
    glGenLists(range: GLsizei) -> GLuint => gen_lists;
    glNewList(list: GLuint, mode: GLenum) => new_list;
    glEndList() => end_list;
    glCallList(list: GLuint) => call_list;
    glListBase(base: GLuint) => list_base;
    glDeleteLists(list: GLuint, range: GLsizei) => delete_lists;
    glIsList(list: GLuint) -> GLboolean => is_list;
}

entry! {
    /// `glCallLists`: reads `n` names of `type_`'s size.
    unsafe fn glCallLists(n: GLsizei, type_: GLenum, lists: *const c_void) {
        let lists = unsafe { bytes(lists, Gl::call_lists_len(n, type_)) };
        with_gl(|gl| gl.call_lists(n, type_, lists))
    }
}
