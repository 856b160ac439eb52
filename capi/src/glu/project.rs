//! `gluProject`, `gluUnProject`, `gluUnProject4`, `gluPickMatrix`.

use crate::context::with_gl;
use crate::memory::array;
use gleval::gl::types::*;

/// Writes `value` through an output pointer C may leave NULL.
fn put(out: *mut GLdouble, value: GLdouble) {
    if !out.is_null() {
        // SAFETY: GLU's contract: a non-NULL output pointer addresses one double.
        unsafe { out.write(value) };
    }
}

entry! {
    /// `gluProject`: `Gl::glu_project`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluProject(
        obj_x: GLdouble, obj_y: GLdouble, obj_z: GLdouble, model: *const GLdouble, proj: *const GLdouble,
        view: *const GLint, win_x: *mut GLdouble, win_y: *mut GLdouble, win_z: *mut GLdouble,
    ) -> GLint {
        let (model, proj, view) = unsafe { (array(model, Some(16)), array(proj, Some(16)), array(view, Some(4))) };
        let mut w = [0.0f64; 3];
        let [x, y, z] = &mut w;
        let ok = with_gl(|gl| gl.glu_project(obj_x, obj_y, obj_z, model, proj, view, x, y, z));
        if ok != 0 {
            put(win_x, w[0]);
            put(win_y, w[1]);
            put(win_z, w[2]);
        }
        ok
    }
}

entry! {
    /// `gluUnProject`: `Gl::glu_un_project`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluUnProject(
        win_x: GLdouble, win_y: GLdouble, win_z: GLdouble, model: *const GLdouble, proj: *const GLdouble,
        view: *const GLint, obj_x: *mut GLdouble, obj_y: *mut GLdouble, obj_z: *mut GLdouble,
    ) -> GLint {
        let (model, proj, view) = unsafe { (array(model, Some(16)), array(proj, Some(16)), array(view, Some(4))) };
        let mut o = [0.0f64; 3];
        let [x, y, z] = &mut o;
        let ok = with_gl(|gl| gl.glu_un_project(win_x, win_y, win_z, model, proj, view, x, y, z));
        if ok != 0 {
            put(obj_x, o[0]);
            put(obj_y, o[1]);
            put(obj_z, o[2]);
        }
        ok
    }
}

entry! {
    /// `gluUnProject4`: `Gl::glu_un_project4`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluUnProject4(
        win_x: GLdouble, win_y: GLdouble, win_z: GLdouble, clip_w: GLdouble, model: *const GLdouble,
        proj: *const GLdouble, view: *const GLint, near_val: GLdouble, far_val: GLdouble, obj_x: *mut GLdouble,
        obj_y: *mut GLdouble, obj_z: *mut GLdouble, obj_w: *mut GLdouble,
    ) -> GLint {
        let (model, proj, view) = unsafe { (array(model, Some(16)), array(proj, Some(16)), array(view, Some(4))) };
        let mut o = [0.0f64; 4];
        let [x, y, z, w] = &mut o;
        let ok = with_gl(|gl| {
            gl.glu_un_project4(win_x, win_y, win_z, clip_w, model, proj, view, near_val, far_val, x, y, z, w)
        });
        if ok != 0 {
            put(obj_x, o[0]);
            put(obj_y, o[1]);
            put(obj_z, o[2]);
            put(obj_w, o[3]);
        }
        ok
    }
}

entry! {
    /// `gluPickMatrix`: `Gl::glu_pick_matrix`.
    unsafe fn gluPickMatrix(x: GLdouble, y: GLdouble, delta_x: GLdouble, delta_y: GLdouble, view: *mut GLint) {
        let view = unsafe { array(view.cast_const(), Some(4)) };
        with_gl(|gl| gl.glu_pick_matrix(x, y, delta_x, delta_y, view))
    }
}
