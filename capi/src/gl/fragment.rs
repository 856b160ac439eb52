//! Blending, the alpha test and fog.

use crate::context::with_gl;
use crate::memory::array;
use gleval::gl::consts::*;
use gleval::gl::types::*;

forward! {
    glBlendFunc(sfactor: GLenum, dfactor: GLenum) => blend_func;
    glAlphaFunc(func: GLenum, reference: GLclampf) => alpha_func;
    glFogf(pname: GLenum, param: GLfloat) => fogf;
    glFogi(pname: GLenum, param: GLint) => fogi;
}

entry! {
    /// `glFogfv`: the colour reads 4 values, the other names 1.
    unsafe fn glFogfv(pname: GLenum, params: *const GLfloat) {
        let n = if pname == GL_FOG_COLOR { 4 } else { 1 };
        let params = unsafe { array(params, Some(n)) };
        with_gl(|gl| gl.fogfv(pname, params))
    }
}
