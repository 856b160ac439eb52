//! Blending, the alpha test, multisample coverage and fog.

use crate::context::with_gl;
use crate::memory::array;
use gleval::gl::consts::*;
use gleval::gl::types::*;

forward! {
    glBlendFunc(sfactor: GLenum, dfactor: GLenum) => blend_func;
    glBlendFuncSeparate(src_rgb: GLenum, dst_rgb: GLenum, src_alpha: GLenum, dst_alpha: GLenum) => blend_func_separate;
    glBlendFuncSeparateEXT(src_rgb: GLenum, dst_rgb: GLenum, src_alpha: GLenum, dst_alpha: GLenum) => blend_func_separate;
    glBlendEquation(mode: GLenum) => blend_equation;
    glBlendEquationEXT(mode: GLenum) => blend_equation;
    glBlendEquationSeparate(mode_rgb: GLenum, mode_alpha: GLenum) => blend_equation_separate;
    glBlendEquationSeparateEXT(mode_rgb: GLenum, mode_alpha: GLenum) => blend_equation_separate;
    glBlendColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) => blend_color;
    glBlendColorEXT(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) => blend_color;
    glAlphaFunc(func: GLenum, reference: GLclampf) => alpha_func;
    glSampleCoverage(value: GLclampf, invert: GLboolean) => sample_coverage;
    glSampleCoverageARB(value: GLclampf, invert: GLboolean) => sample_coverage;
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
