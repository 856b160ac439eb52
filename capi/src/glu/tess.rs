//! The polygon tessellator: `gluNewTess` ... `gluTessEndPolygon`, `gluTessCallback` with C
//! function pointers, and GLU 1.0's `gluBeginPolygon`/`gluNextContour`/`gluEndPolygon`.
//!
//! C holds a `GLUtesselator *`: a box around `gleval`'s handle. The `void *` vertex and
//! polygon data travel through `gleval` untouched and come back to the callbacks as the same
//! pointers; the combine callback's `*outData` becomes the new vertex's data. Each call into
//! C makes the context GLU hands the callback current, so that `glBegin`/`glVertex3dv`/
//! `glEnd` passed directly as callbacks (the Red Book's way) draw into it. NULL objects are
//! ignored (GLU would crash).

use super::callbacks::GluFuncPtr;
use crate::context::{enter, with_gl};
use crate::memory::{array, array_mut};
use gleval::gl::types::*;
use gleval::glu::consts::*;
use gleval::glu::{TessCallback, TessData};
use std::any::Any;
use std::ffi::c_void;
use std::rc::Rc;

/// What a C `GLUtesselator *` points at.
pub struct GLUtesselator(gleval::glu::GLUtesselator);

/// A C `void *` kept as vertex or polygon data.
struct CPointer(*mut c_void);

/// The pointer C gave, NULL for data of any other kind (none given).
fn pointer(data: &dyn Any) -> *mut c_void {
    data.downcast_ref::<CPointer>().map_or(std::ptr::null_mut(), |p| p.0)
}

fn pointer_of(data: Option<&dyn Any>) -> *mut c_void {
    data.map_or(std::ptr::null_mut(), pointer)
}

/// The handle behind a C pointer, `None` for NULL.
///
/// # Safety
/// `tess` is NULL or came from `gluNewTess` and was not deleted.
unsafe fn handle(tess: *mut GLUtesselator) -> Option<gleval::glu::GLUtesselator> {
    // SAFETY: the caller's promise.
    unsafe { tess.as_ref() }.map(|t| t.0)
}

type EnumC = unsafe extern "C" fn(GLenum);
type FlagC = unsafe extern "C" fn(GLboolean);
type PtrC = unsafe extern "C" fn(*mut c_void);
type EndC = unsafe extern "C" fn();
type CombineC = unsafe extern "C" fn(*mut GLdouble, *mut *mut c_void, *mut GLfloat, *mut *mut c_void);
type EnumDataC = unsafe extern "C" fn(GLenum, *mut c_void);
type FlagDataC = unsafe extern "C" fn(GLboolean, *mut c_void);
type PtrDataC = unsafe extern "C" fn(*mut c_void, *mut c_void);
type CombineDataC = unsafe extern "C" fn(*mut GLdouble, *mut *mut c_void, *mut GLfloat, *mut *mut c_void, *mut c_void);

/// Calls a C combine callback (`call` given the coordinates, data, weights and `outData`) and
/// keeps what it wrote to `*outData`; NULL is no data.
fn combine_c(
    coords: &[f64; 3],
    data: [Option<&dyn Any>; 4],
    weight: &[GLfloat; 4],
    call: impl FnOnce(*mut GLdouble, *mut *mut c_void, *mut GLfloat, *mut *mut c_void),
) -> Option<TessData> {
    // Copies: GLU hands the callback arrays it may write.
    let (mut c, mut d, mut w) = (*coords, data.map(pointer_of), *weight);
    let mut out: *mut c_void = std::ptr::null_mut();
    call(c.as_mut_ptr(), d.as_mut_ptr(), w.as_mut_ptr(), &mut out);
    (!out.is_null()).then(|| Rc::new(CPointer(out)) as TessData)
}

/// The callback `which` names, wrapping `f`; `None` for a `which` GLU does not know.
///
/// # Safety
/// `f` has the signature GLU documents for `which`.
unsafe fn wrap(which: GLenum, f: unsafe extern "C" fn()) -> Option<TessCallback> {
    use std::mem::transmute as cast;
    // SAFETY (every cast and call): the caller's promise about `f`'s real signature.
    let callback = unsafe {
        match which {
            GLU_TESS_BEGIN => {
                let f: EnumC = cast(f);
                TessCallback::Begin(Box::new(move |gl, t| enter(gl, || f(t))))
            }
            GLU_TESS_EDGE_FLAG => {
                let f: FlagC = cast(f);
                TessCallback::EdgeFlag(Box::new(move |gl, b| enter(gl, || f(b))))
            }
            GLU_TESS_VERTEX => {
                let f: PtrC = cast(f);
                TessCallback::Vertex(Box::new(move |gl, d| enter(gl, || f(pointer(d)))))
            }
            GLU_TESS_END => {
                let f: EndC = f;
                TessCallback::End(Box::new(move |gl| enter(gl, || f())))
            }
            GLU_TESS_ERROR => {
                let f: EnumC = cast(f);
                TessCallback::Error(Box::new(move |gl, e| enter(gl, || f(e))))
            }
            GLU_TESS_COMBINE => {
                let f: CombineC = cast(f);
                TessCallback::Combine(Box::new(move |gl, c, d, w| {
                    enter(gl, || combine_c(c, d, w, |c, d, w, o| f(c, d, w, o)))
                }))
            }
            GLU_TESS_BEGIN_DATA => {
                let f: EnumDataC = cast(f);
                TessCallback::BeginData(Box::new(move |gl, t, p| enter(gl, || f(t, pointer(p)))))
            }
            GLU_TESS_EDGE_FLAG_DATA => {
                let f: FlagDataC = cast(f);
                TessCallback::EdgeFlagData(Box::new(move |gl, b, p| enter(gl, || f(b, pointer(p)))))
            }
            GLU_TESS_VERTEX_DATA => {
                let f: PtrDataC = cast(f);
                TessCallback::VertexData(Box::new(move |gl, d, p| enter(gl, || f(pointer(d), pointer(p)))))
            }
            GLU_TESS_END_DATA => {
                let f: PtrC = cast(f);
                TessCallback::EndData(Box::new(move |gl, p| enter(gl, || f(pointer(p)))))
            }
            GLU_TESS_ERROR_DATA => {
                let f: EnumDataC = cast(f);
                TessCallback::ErrorData(Box::new(move |gl, e, p| enter(gl, || f(e, pointer(p)))))
            }
            GLU_TESS_COMBINE_DATA => {
                let f: CombineDataC = cast(f);
                TessCallback::CombineData(Box::new(move |gl, c, d, w, p| {
                    let poly = pointer(p);
                    enter(gl, || combine_c(c, d, w, |c, d, w, o| f(c, d, w, o, poly)))
                }))
            }
            _ => return None,
        }
    };
    Some(callback)
}

entry! {
    /// `gluNewTess`.
    fn gluNewTess() -> *mut GLUtesselator {
        with_gl(|gl| Box::into_raw(Box::new(GLUtesselator(gl.glu_new_tess()))))
    }
}

entry! {
    /// `gluDeleteTess`: frees the object.
    unsafe fn gluDeleteTess(tess: *mut GLUtesselator) {
        if tess.is_null() {
            return;
        }
        // SAFETY: made by `gluNewTess` (the caller's promise).
        let boxed = unsafe { Box::from_raw(tess) };
        with_gl(|gl| gl.glu_delete_tess(boxed.0))
    }
}

/// Entry points taking only the object.
macro_rules! object_calls {
    ($($name:ident => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`.")]
            unsafe fn $name(tess: *mut GLUtesselator) {
                if let Some(t) = unsafe { handle(tess) } {
                    with_gl(|gl| gl.$method(t))
                }
            }
        })*
    };
}

object_calls! {
    gluTessBeginContour => glu_tess_begin_contour;
    gluTessEndContour => glu_tess_end_contour;
    gluTessEndPolygon => glu_tess_end_polygon;
    gluBeginPolygon => glu_begin_polygon;
    gluEndPolygon => glu_end_polygon;
}

entry! {
    /// `gluTessBeginPolygon`: `data` goes to the `_DATA` callbacks.
    unsafe fn gluTessBeginPolygon(tess: *mut GLUtesselator, data: *mut c_void) {
        if let Some(t) = unsafe { handle(tess) } {
            with_gl(|gl| gl.glu_tess_begin_polygon(t, Some(Box::new(CPointer(data)))))
        }
    }
}

entry! {
    /// `gluTessVertex`: reads three doubles; `data` comes back to the vertex callback.
    unsafe fn gluTessVertex(tess: *mut GLUtesselator, location: *mut GLdouble, data: *mut c_void) {
        if let Some(t) = unsafe { handle(tess) } {
            let location = unsafe { array(location.cast_const(), Some(3)) };
            with_gl(|gl| gl.glu_tess_vertex(t, location, CPointer(data)))
        }
    }
}

entry! {
    /// `gluTessProperty`.
    unsafe fn gluTessProperty(tess: *mut GLUtesselator, which: GLenum, data: GLdouble) {
        if let Some(t) = unsafe { handle(tess) } {
            with_gl(|gl| gl.glu_tess_property(t, which, data))
        }
    }
}

entry! {
    /// `gluGetTessProperty`: writes one double.
    unsafe fn gluGetTessProperty(tess: *mut GLUtesselator, which: GLenum, data: *mut GLdouble) {
        if let Some(t) = unsafe { handle(tess) } {
            with_gl(|gl| gl.glu_get_tess_property(t, which, unsafe { array_mut(data, 1) }))
        }
    }
}

entry! {
    /// `gluTessNormal`.
    unsafe fn gluTessNormal(tess: *mut GLUtesselator, x: GLdouble, y: GLdouble, z: GLdouble) {
        if let Some(t) = unsafe { handle(tess) } {
            with_gl(|gl| gl.glu_tess_normal(t, x, y, z))
        }
    }
}

entry! {
    /// `gluTessCallback(tess, which, fn)`: NULL removes the callback; an unknown `which` is
    /// `GLU_INVALID_ENUM` through the error callback.
    unsafe fn gluTessCallback(tess: *mut GLUtesselator, which: GLenum, f: GluFuncPtr) {
        let Some(t) = (unsafe { handle(tess) }) else { return };
        match f {
            Some(f) => match unsafe { wrap(which, f) } {
                Some(cb) => with_gl(|gl| gl.glu_tess_callback(t, which, Some(cb))),
                // An unknown `which`: `Gl` reports it.
                None => with_gl(|gl| gl.glu_tess_callback(t, which, None)),
            },
            None => with_gl(|gl| gl.glu_tess_callback(t, which, None)),
        }
    }
}

entry! {
    /// `gluNextContour` (GLU 1.0): the contour type is ignored, as in GLU.
    unsafe fn gluNextContour(tess: *mut GLUtesselator, type_: GLenum) {
        if let Some(t) = unsafe { handle(tess) } {
            with_gl(|gl| gl.glu_next_contour(t, type_))
        }
    }
}
