//! `gluNurbsCallback` with C function pointers, and `gluNurbsCallbackData`.
//!
//! GLU declares every callback as `void (*)()` and calls it with the arguments its `which`
//! implies; the pointer is cast back to that signature here. Each call into C makes the
//! context GLU hands the callback current for its duration, so the callback's own GL calls
//! (`glVertex3fv` in a vertex callback) reach that context. The error callback gets no
//! context from GLU (`Gl` reports the code alone): it may call GLU's `gluErrorString`, but GL
//! calls from inside it reach the context of the GLU call that failed while that call is
//! still running, which real GLU allows and gleval does not promise.

use super::nurbs::{handle, GLUnurbs};
use crate::context::{enter, with_gl};
use gleval::gl::types::*;
use gleval::glu::consts::*;
use gleval::glu::NurbsCallback;
use std::any::Any;
use std::ffi::c_void;

/// GLU's `_GLUfuncptr`.
pub type GluFuncPtr = Option<unsafe extern "C" fn()>;

type EnumC = unsafe extern "C" fn(GLenum);
type ValuesC = unsafe extern "C" fn(*mut GLfloat);
type EndC = unsafe extern "C" fn();
type EnumDataC = unsafe extern "C" fn(GLenum, *mut c_void);
type ValuesDataC = unsafe extern "C" fn(*mut GLfloat, *mut c_void);
type DataC = unsafe extern "C" fn(*mut c_void);

/// The `void *` C gave `gluNurbsCallbackData` (NULL when it gave none).
fn user_data(data: &mut dyn Any) -> *mut c_void {
    data.downcast_ref::<UserPointer>().map_or(std::ptr::null_mut(), |p| p.0)
}

/// A C `void *` kept as GLU's user data.
struct UserPointer(*mut c_void);

/// A values callback: GLU hands floats it owns; C's signature says `GLfloat *`.
fn values_ptr(values: &[GLfloat]) -> *mut GLfloat {
    values.as_ptr().cast_mut()
}

/// The callback `which` names, wrapping `f` (cast to the signature `which` implies);
/// `None` for an unknown `which`.
///
/// # Safety
/// `f` has the signature GLU documents for `which`.
unsafe fn wrap(which: GLenum, f: unsafe extern "C" fn()) -> Option<NurbsCallback> {
    use std::mem::transmute as cast;
    // SAFETY (every cast): the caller's promise about `f`'s real signature.
    let callback = unsafe {
        match which {
            GLU_NURBS_BEGIN => {
                let f: EnumC = cast(f);
                NurbsCallback::Begin(Box::new(move |gl, prim| enter(gl, || f(prim))))
            }
            GLU_NURBS_VERTEX | GLU_NURBS_NORMAL | GLU_NURBS_COLOR | GLU_NURBS_TEXTURE_COORD => {
                let f: ValuesC = cast(f);
                let g = Box::new(move |gl: &mut _, v: &[GLfloat]| enter(gl, || f(values_ptr(v))));
                match which {
                    GLU_NURBS_VERTEX => NurbsCallback::Vertex(g),
                    GLU_NURBS_NORMAL => NurbsCallback::Normal(g),
                    GLU_NURBS_COLOR => NurbsCallback::Color(g),
                    _ => NurbsCallback::TexCoord(g),
                }
            }
            GLU_NURBS_END => {
                let f: EndC = f;
                NurbsCallback::End(Box::new(move |gl| enter(gl, || f())))
            }
            GLU_NURBS_ERROR => {
                let f: EnumC = cast(f);
                NurbsCallback::Error(Box::new(move |code| f(code)))
            }
            GLU_NURBS_BEGIN_DATA => {
                let f: EnumDataC = cast(f);
                NurbsCallback::BeginData(Box::new(move |gl, prim, d| enter(gl, || f(prim, user_data(d)))))
            }
            GLU_NURBS_VERTEX_DATA | GLU_NURBS_NORMAL_DATA | GLU_NURBS_COLOR_DATA | GLU_NURBS_TEXTURE_COORD_DATA => {
                let f: ValuesDataC = cast(f);
                let g = Box::new(move |gl: &mut _, v: &[GLfloat], d: &mut dyn Any| {
                    enter(gl, || f(values_ptr(v), user_data(d)))
                });
                match which {
                    GLU_NURBS_VERTEX_DATA => NurbsCallback::VertexData(g),
                    GLU_NURBS_NORMAL_DATA => NurbsCallback::NormalData(g),
                    GLU_NURBS_COLOR_DATA => NurbsCallback::ColorData(g),
                    _ => NurbsCallback::TexCoordData(g),
                }
            }
            GLU_NURBS_END_DATA => {
                let f: DataC = cast(f);
                NurbsCallback::EndData(Box::new(move |gl, d| enter(gl, || f(user_data(d)))))
            }
            _ => return None,
        }
    };
    Some(callback)
}

entry! {
    /// `gluNurbsCallback(nobj, which, fn)`: NULL removes the callback; an unknown `which` is
    /// GLU's `GLU_INVALID_ENUM` (through the error callback).
    unsafe fn gluNurbsCallback(nobj: *mut GLUnurbs, which: GLenum, f: GluFuncPtr) {
        let Some(n) = (unsafe { handle(nobj) }) else { return };
        let callback = f.and_then(|f| unsafe { wrap(which, f) });
        with_gl(|gl| gl.glu_nurbs_callback(n, which, callback))
    }
}

entry! {
    /// `gluNurbsCallbackData`: the `void *` the `_DATA` callbacks receive.
    unsafe fn gluNurbsCallbackData(nobj: *mut GLUnurbs, data: *mut c_void) {
        if let Some(n) = unsafe { handle(nobj) } {
            with_gl(|gl| gl.glu_nurbs_callback_data(n, Box::new(UserPointer(data))))
        }
    }
}

entry! {
    /// `gluNurbsCallbackDataEXT`: the older name of `gluNurbsCallbackData`.
    unsafe fn gluNurbsCallbackDataEXT(nobj: *mut GLUnurbs, data: *mut c_void) {
        unsafe { gluNurbsCallbackData(nobj, data) }
    }
}
