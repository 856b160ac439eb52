//! The state queries beside `glGet*v` (`glGetLight`, `glGetMaterial`, `glGetTexEnv`,
//! `glGetTexParameter`, `glGetTexLevelParameter`, `glGetTexImage`, `glGetPolygonStipple`,
//! `glGetTexGendv`) and the integer and vector forms of the parameter calls (`glLighti/iv`,
//! `glLightModelf/iv`, `glMateriali/iv`, `glFogiv`, `glTexEnviv`, `glTexParameterfv/iv`).
//! Each reads or writes as many values as GL does for its name.

use super::pixel_buffers::pack_with;
use crate::context::with_gl;
use crate::memory::{array, array_mut};
use gleval::gl::types::*;
use gleval::gl::Gl;
use std::ffi::c_void;

forward! {
    glLighti(light: GLenum, pname: GLenum, param: GLint) => light_i;
    glLightModelf(pname: GLenum, param: GLfloat) => light_model_f;
    glMateriali(face: GLenum, pname: GLenum, param: GLint) => material_i;
}

entry! {
    /// `glLightiv`: `Gl::light_iv`.
    unsafe fn glLightiv(light: GLenum, pname: GLenum, params: *const GLint) {
        let params = unsafe { array(params, Some(Gl::light_param_count(pname).unwrap_or(0))) };
        with_gl(|gl| gl.light_iv(light, pname, params))
    }
}

entry! {
    /// `glLightModeliv`: `Gl::light_model_iv`.
    unsafe fn glLightModeliv(pname: GLenum, params: *const GLint) {
        let params = unsafe { array(params, Some(Gl::light_model_param_count(pname).unwrap_or(0))) };
        with_gl(|gl| gl.light_model_iv(pname, params))
    }
}

entry! {
    /// `glMaterialiv`: `Gl::material_iv`.
    unsafe fn glMaterialiv(face: GLenum, pname: GLenum, params: *const GLint) {
        let params = unsafe { array(params, Some(Gl::material_param_count(pname).unwrap_or(0))) };
        with_gl(|gl| gl.material_iv(face, pname, params))
    }
}

entry! {
    /// `glFogiv`: `Gl::fogiv`.
    unsafe fn glFogiv(pname: GLenum, params: *const GLint) {
        let params = unsafe { array(params, Some(Gl::fog_param_count(pname))) };
        with_gl(|gl| gl.fogiv(pname, params))
    }
}

entry! {
    /// `glTexEnviv`: `Gl::tex_enviv`.
    unsafe fn glTexEnviv(target: GLenum, pname: GLenum, params: *const GLint) {
        let params = unsafe { array(params, Some(Gl::tex_env_param_count(pname))) };
        with_gl(|gl| gl.tex_enviv(target, pname, params))
    }
}

entry! {
    /// `glTexParameterfv`: `Gl::tex_parameterfv`.
    unsafe fn glTexParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
        let params = unsafe { array(params, Some(Gl::tex_parameter_param_count(pname))) };
        with_gl(|gl| gl.tex_parameterfv(target, pname, params))
    }
}

entry! {
    /// `glTexParameteriv`: `Gl::tex_parameteriv`.
    unsafe fn glTexParameteriv(target: GLenum, pname: GLenum, params: *const GLint) {
        let params = unsafe { array(params, Some(Gl::tex_parameter_param_count(pname))) };
        with_gl(|gl| gl.tex_parameteriv(target, pname, params))
    }
}

entry! {
    /// `glGetLightfv`: `Gl::get_light_fv`.
    unsafe fn glGetLightfv(light: GLenum, pname: GLenum, params: *mut GLfloat) {
        let params = unsafe { array_mut(params, Gl::light_param_count(pname).unwrap_or(0)) };
        with_gl(|gl| gl.get_light_fv(light, pname, params))
    }
}

entry! {
    /// `glGetLightiv`: `Gl::get_light_iv`.
    unsafe fn glGetLightiv(light: GLenum, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, Gl::light_param_count(pname).unwrap_or(0)) };
        with_gl(|gl| gl.get_light_iv(light, pname, params))
    }
}

entry! {
    /// `glGetMaterialfv`: `Gl::get_material_fv`.
    unsafe fn glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat) {
        let params = unsafe { array_mut(params, Gl::material_param_count(pname).unwrap_or(0)) };
        with_gl(|gl| gl.get_material_fv(face, pname, params))
    }
}

entry! {
    /// `glGetMaterialiv`: `Gl::get_material_iv`.
    unsafe fn glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, Gl::material_param_count(pname).unwrap_or(0)) };
        with_gl(|gl| gl.get_material_iv(face, pname, params))
    }
}

entry! {
    /// `glGetTexEnvfv`: `Gl::get_tex_envfv`.
    unsafe fn glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
        let params = unsafe { array_mut(params, Gl::tex_env_param_count(pname)) };
        with_gl(|gl| gl.get_tex_envfv(target, pname, params))
    }
}

entry! {
    /// `glGetTexEnviv`: `Gl::get_tex_enviv`.
    unsafe fn glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, Gl::tex_env_param_count(pname)) };
        with_gl(|gl| gl.get_tex_enviv(target, pname, params))
    }
}

entry! {
    /// `glGetTexParameterfv`: `Gl::get_tex_parameterfv`.
    unsafe fn glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
        let params = unsafe { array_mut(params, Gl::tex_parameter_param_count(pname)) };
        with_gl(|gl| gl.get_tex_parameterfv(target, pname, params))
    }
}

entry! {
    /// `glGetTexParameteriv`: `Gl::get_tex_parameteriv`.
    unsafe fn glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, Gl::tex_parameter_param_count(pname)) };
        with_gl(|gl| gl.get_tex_parameteriv(target, pname, params))
    }
}

entry! {
    /// `glGetTexLevelParameterfv`: one value.
    unsafe fn glGetTexLevelParameterfv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLfloat) {
        let params = unsafe { array_mut(params, 1) };
        with_gl(|gl| gl.get_tex_level_parameterfv(target, level, pname, params))
    }
}

entry! {
    /// `glGetTexLevelParameteriv`: one value.
    unsafe fn glGetTexLevelParameteriv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, 1) };
        with_gl(|gl| gl.get_tex_level_parameteriv(target, level, pname, params))
    }
}

entry! {
    /// `glGetTexImage`: writes the level packed with the pack modes (`Gl::tex_image_len`).
    unsafe fn glGetTexImage(target: GLenum, level: GLint, format: GLenum, type_: GLenum, pixels: *mut c_void) {
        let len = |gl: &Gl| gl.tex_image_len(target, level, format, type_).unwrap_or(0);
        unsafe { pack_with(pixels.cast::<u8>(), len, |gl, out| gl.get_tex_image(target, level, format, type_, out)) }
    }
}

entry! {
    /// `glGetPolygonStipple`: writes the 32 × 32 mask packed with the pack modes.
    unsafe fn glGetPolygonStipple(mask: *mut GLubyte) {
        unsafe { pack_with(mask, Gl::polygon_stipple_len, Gl::get_polygon_stipple) }
    }
}

entry! {
    /// `glGetTexGendv`: the mode 1 value, a plane 4.
    unsafe fn glGetTexGendv(coord: GLenum, pname: GLenum, params: *mut GLdouble) {
        let params = unsafe { array_mut(params, Gl::tex_gen_param_count(pname)) };
        with_gl(|gl| gl.get_tex_gendv(coord, pname, params))
    }
}
