//! Enables, errors, queries, viewport, clearing and rasterisation state.

use crate::context::with_gl;
use crate::memory::array_mut;
use crate::strings::static_c_string;
use gleval::gl::types::*;

/// `glFlush`/`glFinish`: `Gl`'s checks, then what was drawn reaches the current drawable (a
/// single-buffered window shows it) or OSMesa buffer (not between `glBegin` and `glEnd`, where
/// the call is an error).
fn flush(finish: bool) {
    let open: GLboolean = with_gl(|gl| {
        if finish {
            gl.finish();
        } else {
            gl.flush();
        }
        gl.inside_begin_end().into()
    });
    if open == 0 {
        crate::surface::flush_and_show();
    }
}

entry! {
    /// `glFlush`: `Gl::flush`, and the drawable or OSMesa buffer brought up to date.
    fn glFlush() {
        flush(false)
    }
}

entry! {
    /// `glFinish`: `Gl::finish`, and the drawable or OSMesa buffer brought up to date.
    fn glFinish() {
        flush(true)
    }
}

forward! {
    glEnable(cap: GLenum) => enable;
    glDisable(cap: GLenum) => disable;
    glIsEnabled(cap: GLenum) -> GLboolean => is_enabled;
    glGetError() -> GLenum => get_error;
    glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei) => viewport;
    glDepthRange(near: GLclampd, far: GLclampd) => depth_range;
    glClear(mask: GLbitfield) => clear;
    glClearColor(r: GLclampf, g: GLclampf, b: GLclampf, a: GLclampf) => clear_color;
    glClearDepth(depth: GLclampd) => clear_depth;
    glDepthFunc(func: GLenum) => depth_func;
    glCullFace(mode: GLenum) => cull_face;
    glFrontFace(mode: GLenum) => front_face;
    glPolygonMode(face: GLenum, mode: GLenum) => polygon_mode;
    glPointSize(size: GLfloat) => point_size;
    glLineWidth(width: GLfloat) => line_width;
    glActiveTexture(texture: GLenum) => active_texture;
    glPushAttrib(mask: GLbitfield) => push_attrib;
    glPopAttrib() => pop_attrib;
}

entry! {
    /// `glGetDoublev`: `Gl::get_doublev`.
    unsafe fn glGetDoublev(pname: GLenum, params: *mut GLdouble) {
        with_gl(|gl| gl.get_doublev(pname, unsafe { array_mut(params, gl.get_len(pname)) }))
    }
}

entry! {
    /// `glGetBooleanv`: `Gl::get_booleanv`.
    unsafe fn glGetBooleanv(pname: GLenum, params: *mut GLboolean) {
        with_gl(|gl| gl.get_booleanv(pname, unsafe { array_mut(params, gl.get_len(pname)) }))
    }
}

forward! {
    glHint(target: GLenum, mode: GLenum) => hint;
}

entry! {
    /// `glGetIntegerv`: `Gl::get_integerv`.
    unsafe fn glGetIntegerv(pname: GLenum, params: *mut GLint) {
        with_gl(|gl| gl.get_integerv(pname, unsafe { array_mut(params, gl.get_len(pname)) }))
    }
}

entry! {
    /// `glGetFloatv`: `Gl::get_floatv`.
    unsafe fn glGetFloatv(pname: GLenum, params: *mut GLfloat) {
        with_gl(|gl| gl.get_floatv(pname, unsafe { array_mut(params, gl.get_len(pname)) }))
    }
}

entry! {
    /// `glGetString`: `Gl::get_string`, as a NUL-terminated string that lives as long as the
    /// program (NULL for an unknown name).
    fn glGetString(name: GLenum) -> *const GLubyte {
        with_gl(|gl| gl.get_string(name).map_or(std::ptr::null(), |s| static_c_string(s).cast()))
    }
}
