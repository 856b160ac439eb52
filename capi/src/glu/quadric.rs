//! GLU's quadrics: `gluNewQuadric` ... `gluPartialDisk`.
//!
//! C holds a `GLUquadric *`: a box around `gleval`'s handle, made by `gluNewQuadric` and freed
//! by `gluDeleteQuadric`. NULL objects are ignored (GLU would crash).

use super::callbacks::GluFuncPtr;
use crate::context::with_gl;
use gleval::gl::types::*;
use gleval::glu::consts::GLU_ERROR;

/// What a C `GLUquadric *` points at.
pub struct GLUquadric(gleval::glu::GLUquadric);

/// The handle behind a C pointer, `None` for NULL.
///
/// # Safety
/// `quad` is NULL or came from `gluNewQuadric` and was not deleted.
unsafe fn handle(quad: *mut GLUquadric) -> Option<gleval::glu::GLUquadric> {
    // SAFETY: the caller's promise.
    unsafe { quad.as_ref() }.map(|q| q.0)
}

/// GLU's quadric error callback: `void (*)(GLenum)` behind `_GLUfuncptr`.
type ErrorC = unsafe extern "C" fn(GLenum);

entry! {
    /// `gluNewQuadric`.
    fn gluNewQuadric() -> *mut GLUquadric {
        with_gl(|gl| Box::into_raw(Box::new(GLUquadric(gl.glu_new_quadric()))))
    }
}

entry! {
    /// `gluDeleteQuadric`: frees the object.
    unsafe fn gluDeleteQuadric(quad: *mut GLUquadric) {
        if quad.is_null() {
            return;
        }
        // SAFETY: made by `gluNewQuadric` (the caller's promise).
        let boxed = unsafe { Box::from_raw(quad) };
        with_gl(|gl| gl.glu_delete_quadric(boxed.0))
    }
}

entry! {
    /// `gluQuadricCallback(quad, GLU_ERROR, fn)`: NULL removes the callback; another `which`
    /// is GLU's `GLU_INVALID_ENUM` (through the error callback).
    unsafe fn gluQuadricCallback(quad: *mut GLUquadric, which: GLenum, f: GluFuncPtr) {
        let Some(q) = (unsafe { handle(quad) }) else { return };
        // SAFETY: GLU's contract: a GLU_ERROR callback takes the error code.
        let f = f.filter(|_| which == GLU_ERROR).map(|f| unsafe { std::mem::transmute::<_, ErrorC>(f) });
        let callback = f.map(|f| Box::new(move |code| unsafe { f(code) }) as gleval::glu::quadric::QuadricErrorFn);
        with_gl(|gl| gl.glu_quadric_callback(q, which, callback))
    }
}

/// Entry points taking the object and one mode.
macro_rules! mode_calls {
    ($($name:ident($t:ty) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`.")]
            unsafe fn $name(quad: *mut GLUquadric, value: $t) {
                if let Some(q) = unsafe { handle(quad) } {
                    with_gl(|gl| gl.$method(q, value))
                }
            }
        })*
    };
}

mode_calls! {
    gluQuadricDrawStyle(GLenum) => glu_quadric_draw_style;
    gluQuadricNormals(GLenum) => glu_quadric_normals;
    gluQuadricOrientation(GLenum) => glu_quadric_orientation;
    gluQuadricTexture(GLboolean) => glu_quadric_texture;
}

entry! {
    /// `gluSphere`.
    unsafe fn gluSphere(quad: *mut GLUquadric, radius: GLdouble, slices: GLint, stacks: GLint) {
        if let Some(q) = unsafe { handle(quad) } {
            with_gl(|gl| gl.glu_sphere(q, radius, slices, stacks))
        }
    }
}

entry! {
    /// `gluCylinder`.
    unsafe fn gluCylinder(
        quad: *mut GLUquadric, base: GLdouble, top: GLdouble, height: GLdouble, slices: GLint, stacks: GLint,
    ) {
        if let Some(q) = unsafe { handle(quad) } {
            with_gl(|gl| gl.glu_cylinder(q, base, top, height, slices, stacks))
        }
    }
}

entry! {
    /// `gluDisk`.
    unsafe fn gluDisk(quad: *mut GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint) {
        if let Some(q) = unsafe { handle(quad) } {
            with_gl(|gl| gl.glu_disk(q, inner, outer, slices, loops))
        }
    }
}

entry! {
    /// `gluPartialDisk`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn gluPartialDisk(
        quad: *mut GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint, start: GLdouble,
        sweep: GLdouble,
    ) {
        if let Some(q) = unsafe { handle(quad) } {
            with_gl(|gl| gl.glu_partial_disk(q, inner, outer, slices, loops, start, sweep))
        }
    }
}
