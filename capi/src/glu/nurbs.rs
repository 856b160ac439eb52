//! The NURBS object: creation, properties, curves, surfaces and trims.
//!
//! C holds a `GLUnurbs *`: a box around `gleval`'s handle, made by `gluNewNurbsRenderer` and
//! freed by `gluDeleteNurbsRenderer`. NULL objects are ignored (GLU would crash).

use crate::context::with_gl;
use crate::memory::{array, array_mut, count, strided_len};
use gleval::gl::types::*;

/// What a C `GLUnurbs *` points at.
pub struct GLUnurbs(pub(crate) gleval::glu::GLUnurbs);

/// The handle behind a C pointer, `None` for NULL.
///
/// # Safety
/// `nobj` is NULL or came from `gluNewNurbsRenderer` and was not deleted.
pub(crate) unsafe fn handle(nobj: *mut GLUnurbs) -> Option<gleval::glu::GLUnurbs> {
    // SAFETY: the caller's promise.
    unsafe { nobj.as_ref() }.map(|n| n.0)
}

/// Control values a strided net reads: `count` points per dimension (knots − order).
fn net_len(kind: GLenum, dims: &[(GLint, GLint, GLint)]) -> Option<usize> {
    let k = gleval::glu::nurbs_point_components(kind)?;
    let layout: Vec<(GLint, GLint)> =
        dims.iter().map(|&(knots, order, stride)| (stride, knots.saturating_sub(order))).collect();
    // GLU takes any number of control points; only a positive count is read.
    strided_len(k, &layout, GLint::MAX)
}

entry! {
    /// `gluNewNurbsRenderer`.
    fn gluNewNurbsRenderer() -> *mut GLUnurbs {
        with_gl(|gl| Box::into_raw(Box::new(GLUnurbs(gl.glu_new_nurbs_renderer()))))
    }
}

entry! {
    /// `gluDeleteNurbsRenderer`: frees the object.
    unsafe fn gluDeleteNurbsRenderer(nobj: *mut GLUnurbs) {
        if nobj.is_null() {
            return;
        }
        // SAFETY: made by `gluNewNurbsRenderer` (the caller's promise).
        let boxed = unsafe { Box::from_raw(nobj) };
        with_gl(|gl| gl.glu_delete_nurbs_renderer(boxed.0))
    }
}

/// Entry points taking only the object.
macro_rules! object_calls {
    ($($name:ident => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`.")]
            unsafe fn $name(nobj: *mut GLUnurbs) {
                if let Some(n) = unsafe { handle(nobj) } {
                    with_gl(|gl| gl.$method(n))
                }
            }
        })*
    };
}

object_calls! {
    gluBeginCurve => glu_begin_curve;
    gluEndCurve => glu_end_curve;
    gluBeginSurface => glu_begin_surface;
    gluEndSurface => glu_end_surface;
    gluBeginTrim => glu_begin_trim;
    gluEndTrim => glu_end_trim;
}

entry! {
    /// `gluNurbsProperty`.
    unsafe fn gluNurbsProperty(nobj: *mut GLUnurbs, property: GLenum, value: GLfloat) {
        if let Some(n) = unsafe { handle(nobj) } {
            with_gl(|gl| gl.glu_nurbs_property(n, property, value))
        }
    }
}

entry! {
    /// `gluGetNurbsProperty`: writes one value.
    unsafe fn gluGetNurbsProperty(nobj: *mut GLUnurbs, property: GLenum, value: *mut GLfloat) {
        if let Some(n) = unsafe { handle(nobj) } {
            with_gl(|gl| gl.glu_get_nurbs_property(n, property, unsafe { array_mut(value, 1) }))
        }
    }
}

entry! {
    /// `gluLoadSamplingMatrices`: reads two 4 × 4 matrices and a viewport.
    unsafe fn gluLoadSamplingMatrices(
        nobj: *mut GLUnurbs, model: *const GLfloat, perspective: *const GLfloat, view: *const GLint,
    ) {
        if let Some(n) = unsafe { handle(nobj) } {
            let (m, p, v) = unsafe { (array(model, Some(16)), array(perspective, Some(16)), array(view, Some(4))) };
            with_gl(|gl| gl.glu_load_sampling_matrices(n, m, p, v))
        }
    }
}

entry! {
    /// `gluNurbsCurve`: reads `nknots` knots and `nknots − order` control points of `stride`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluNurbsCurve(
        nobj: *mut GLUnurbs, nknots: GLint, knots: *const GLfloat, stride: GLint, ctlarray: *const GLfloat,
        order: GLint, kind: GLenum,
    ) {
        let Some(n) = (unsafe { handle(nobj) }) else { return };
        let knots_read = unsafe { array(knots, count(nknots)) };
        let ctl = unsafe { array(ctlarray, net_len(kind, &[(nknots, order, stride)])) };
        with_gl(|gl| gl.glu_nurbs_curve(n, nknots, knots_read, stride, ctl, order, kind))
    }
}

entry! {
    /// `gluNurbsSurface`: reads both knot vectors and the `(sknots − sorder) × (tknots −
    /// torder)` control net.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluNurbsSurface(
        nobj: *mut GLUnurbs, sknot_count: GLint, sknots: *const GLfloat, tknot_count: GLint,
        tknots: *const GLfloat, s_stride: GLint, t_stride: GLint, ctlarray: *const GLfloat,
        sorder: GLint, torder: GLint, kind: GLenum,
    ) {
        let Some(n) = (unsafe { handle(nobj) }) else { return };
        let (s, t) = unsafe { (array(sknots, count(sknot_count)), array(tknots, count(tknot_count))) };
        let net = [(sknot_count, sorder, s_stride), (tknot_count, torder, t_stride)];
        let ctl = unsafe { array(ctlarray, net_len(kind, &net)) };
        with_gl(|gl| gl.glu_nurbs_surface(n, sknot_count, s, tknot_count, t, s_stride, t_stride, ctl, sorder, torder, kind))
    }
}

entry! {
    /// `gluPwlCurve`: reads `count` points of `stride`.
    unsafe fn gluPwlCurve(nobj: *mut GLUnurbs, count_: GLint, data: *const GLfloat, stride: GLint, kind: GLenum) {
        let Some(n) = (unsafe { handle(nobj) }) else { return };
        let len = gleval::glu::nurbs_point_components(kind).and_then(|k| strided_len(k, &[(stride, count_)], GLint::MAX));
        let data = unsafe { array(data, len) };
        with_gl(|gl| gl.glu_pwl_curve(n, count_, data, stride, kind))
    }
}
