//! `gluTessCallback`: the tessellator's callbacks, plain and `_DATA`.
//!
//! C passes function pointers and `void *` data; here vertex data is any Rust value, kept as
//! [`TessData`] (an `Rc<dyn Any>`, so that a vertex merged or split by the sweep can share it),
//! and each callback is a closure that gets the context first, as the NURBS and GLUT callbacks
//! do, so that it can call GL (`glBegin`, `glVertex3dv`, `glEnd` are the usual ones). A `_DATA`
//! callback also gets the polygon data given to `gluTessBeginPolygon` (`()` when none, C's
//! NULL), and wins over the plain one when both are set, as in GLU (`tess.h`'s
//! `CALL_*_OR_*_DATA`). Setting none of begin, vertex, end and edge flag makes GLU skip the
//! output altogether; with no callback at all, GLU draws nothing (its defaults do nothing).

use crate::gl::types::{GLboolean, GLenum, GLfloat};
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::UserData;
use std::any::Any;
use std::rc::Rc;

/// The data of one vertex: what was given to `gluTessVertex`, or made by the combine callback.
pub type TessData = Rc<dyn Any>;

/// A begin callback: the context and the primitive (`GL_TRIANGLE_FAN`, `GL_TRIANGLE_STRIP`,
/// `GL_TRIANGLES` or, boundary only, `GL_LINE_LOOP`).
pub type BeginFn = Box<dyn FnMut(&mut Gl, GLenum)>;
/// An edge-flag callback: `GL_TRUE` before vertices that start boundary edges.
pub type EdgeFlagFn = Box<dyn FnMut(&mut Gl, GLboolean)>;
/// A vertex callback: the vertex's data (`&()` where C would pass NULL).
pub type VertexFn = Box<dyn FnMut(&mut Gl, &dyn Any)>;
/// An end callback.
pub type EndFn = Box<dyn FnMut(&mut Gl)>;
/// An error callback: `GLU_TESS_MISSING_BEGIN_POLYGON` ... `GLU_TESS_NEED_COMBINE_CALLBACK`,
/// `GLU_INVALID_ENUM`, `GLU_INVALID_VALUE`, `GLU_OUT_OF_MEMORY`.
pub type ErrorFn = Box<dyn FnMut(&mut Gl, GLenum)>;
/// A combine callback: the new vertex's coordinates, the data of up to four vertices it is
/// made of (`None` for C's NULL) and their weights; returns the new vertex's data.
pub type CombineFn = Box<dyn FnMut(&mut Gl, &[f64; 3], [Option<&dyn Any>; 4], &[GLfloat; 4]) -> Option<TessData>>;
/// The `_DATA` forms take the polygon data last.
pub type BeginDataFn = Box<dyn FnMut(&mut Gl, GLenum, &mut dyn Any)>;
/// `GLU_TESS_EDGE_FLAG_DATA`.
pub type EdgeFlagDataFn = Box<dyn FnMut(&mut Gl, GLboolean, &mut dyn Any)>;
/// `GLU_TESS_VERTEX_DATA`.
pub type VertexDataFn = Box<dyn FnMut(&mut Gl, &dyn Any, &mut dyn Any)>;
/// `GLU_TESS_END_DATA`.
pub type EndDataFn = Box<dyn FnMut(&mut Gl, &mut dyn Any)>;
/// `GLU_TESS_ERROR_DATA`.
pub type ErrorDataFn = Box<dyn FnMut(&mut Gl, GLenum, &mut dyn Any)>;
/// `GLU_TESS_COMBINE_DATA`.
pub type CombineDataFn =
    Box<dyn FnMut(&mut Gl, &[f64; 3], [Option<&dyn Any>; 4], &[GLfloat; 4], &mut dyn Any) -> Option<TessData>>;

/// One tessellator callback, tagged with its `which`.
pub enum TessCallback {
    /// `GLU_TESS_BEGIN`.
    Begin(BeginFn),
    /// `GLU_TESS_EDGE_FLAG`: asking for edge flags makes GLU draw separate triangles only.
    EdgeFlag(EdgeFlagFn),
    /// `GLU_TESS_VERTEX`.
    Vertex(VertexFn),
    /// `GLU_TESS_END`.
    End(EndFn),
    /// `GLU_TESS_ERROR`.
    Error(ErrorFn),
    /// `GLU_TESS_COMBINE`.
    Combine(CombineFn),
    /// `GLU_TESS_BEGIN_DATA`.
    BeginData(BeginDataFn),
    /// `GLU_TESS_EDGE_FLAG_DATA`.
    EdgeFlagData(EdgeFlagDataFn),
    /// `GLU_TESS_VERTEX_DATA`.
    VertexData(VertexDataFn),
    /// `GLU_TESS_END_DATA`.
    EndData(EndDataFn),
    /// `GLU_TESS_ERROR_DATA`.
    ErrorData(ErrorDataFn),
    /// `GLU_TESS_COMBINE_DATA`.
    CombineData(CombineDataFn),
}

impl TessCallback {
    /// A begin callback.
    pub fn begin(f: impl FnMut(&mut Gl, GLenum) + 'static) -> Self {
        Self::Begin(Box::new(f))
    }
    /// An edge-flag callback.
    pub fn edge_flag(f: impl FnMut(&mut Gl, GLboolean) + 'static) -> Self {
        Self::EdgeFlag(Box::new(f))
    }
    /// A vertex callback taking the data as `&dyn Any`.
    pub fn vertex(f: impl FnMut(&mut Gl, &dyn Any) + 'static) -> Self {
        Self::Vertex(Box::new(f))
    }
    /// A vertex callback for data of type `T` (what `gluTessVertex` and the combine callback
    /// gave); vertices whose data is of another type (a combine that gave none) are skipped,
    /// where C would hand the callback a NULL pointer.
    ///
    /// ```
    /// use gleval::prelude::*;
    /// use gleval::glu::TessCallback;
    /// let mut gl = Gl::new(8, 8);
    /// let tobj = gl.glu_new_tess();
    /// gl.glu_tess_callback(tobj, GLU_TESS_VERTEX, Some(TessCallback::vertex_of(|gl, v: &[f64; 3]| gl.vertex3dv(v))));
    /// ```
    pub fn vertex_of<T: Any>(mut f: impl FnMut(&mut Gl, &T) + 'static) -> Self {
        Self::vertex(move |gl, d| {
            if let Some(v) = d.downcast_ref::<T>() {
                f(gl, v);
            }
        })
    }
    /// An end callback.
    pub fn end(f: impl FnMut(&mut Gl) + 'static) -> Self {
        Self::End(Box::new(f))
    }
    /// An error callback.
    pub fn error(f: impl FnMut(&mut Gl, GLenum) + 'static) -> Self {
        Self::Error(Box::new(f))
    }
    /// A combine callback on untyped data.
    pub fn combine(
        f: impl FnMut(&mut Gl, &[f64; 3], [Option<&dyn Any>; 4], &[GLfloat; 4]) -> Option<TessData> + 'static,
    ) -> Self {
        Self::Combine(Box::new(f))
    }
    /// A combine callback for vertex data of type `T`: data of another type is passed as
    /// `None`.
    pub fn combine_of<T: Any>(mut f: impl FnMut(&[f64; 3], [Option<&T>; 4], &[GLfloat; 4]) -> T + 'static) -> Self {
        Self::combine(move |_, coords, data, weight| {
            let typed = data.map(|d| d.and_then(|d| d.downcast_ref::<T>()));
            Some(Rc::new(f(coords, typed, weight)) as TessData)
        })
    }

    /// The `which` this callback fits.
    fn slot(&self) -> GLenum {
        match self {
            Self::Begin(_) => GLU_TESS_BEGIN,
            Self::EdgeFlag(_) => GLU_TESS_EDGE_FLAG,
            Self::Vertex(_) => GLU_TESS_VERTEX,
            Self::End(_) => GLU_TESS_END,
            Self::Error(_) => GLU_TESS_ERROR,
            Self::Combine(_) => GLU_TESS_COMBINE,
            Self::BeginData(_) => GLU_TESS_BEGIN_DATA,
            Self::EdgeFlagData(_) => GLU_TESS_EDGE_FLAG_DATA,
            Self::VertexData(_) => GLU_TESS_VERTEX_DATA,
            Self::EndData(_) => GLU_TESS_END_DATA,
            Self::ErrorData(_) => GLU_TESS_ERROR_DATA,
            Self::CombineData(_) => GLU_TESS_COMBINE_DATA,
        }
    }
}

/// The callbacks of one tessellator: one slot per `which`.
#[derive(Default)]
pub(crate) struct TessCallbacks {
    slots: Vec<TessCallback>,
    /// Edge flags were asked for: draw separate triangles (`flagBoundary`).
    pub flag_boundary: bool,
}

/// The polygon data, `()` for C's NULL (a leaked `Box<()>` allocates nothing).
fn poly(data: &mut Option<UserData>) -> &mut dyn Any {
    match data {
        Some(d) => d.as_mut(),
        None => Box::leak(Box::new(())),
    }
}

impl TessCallbacks {
    /// Stores `cb` for `which` (or clears it); false for a `which` GLU does not know or a
    /// callback of another kind.
    pub fn set(&mut self, which: GLenum, cb: Option<TessCallback>) -> bool {
        if !(GLU_TESS_BEGIN..=GLU_TESS_COMBINE_DATA).contains(&which) || cb.as_ref().is_some_and(|c| c.slot() != which)
        {
            return false;
        }
        if matches!(which, GLU_TESS_EDGE_FLAG | GLU_TESS_EDGE_FLAG_DATA) {
            self.flag_boundary = cb.is_some();
        }
        self.slots.retain(|c| c.slot() != which);
        if let Some(cb) = cb {
            self.slots.push(cb);
        }
        true
    }

    fn has(&self, which: GLenum) -> bool {
        self.slots.iter().any(|c| c.slot() == which)
    }

    fn find(&mut self, which: GLenum) -> Option<&mut TessCallback> {
        self.slots.iter_mut().find(|c| c.slot() == which)
    }

    /// Whether any drawing callback is set: GLU skips the output otherwise.
    pub fn draws(&self) -> bool {
        let drawing = [GLU_TESS_BEGIN, GLU_TESS_END, GLU_TESS_VERTEX, GLU_TESS_EDGE_FLAG];
        drawing.iter().any(|&w| self.has(w) || self.has(w + 6))
    }

    pub fn begin(&mut self, gl: &mut Gl, prim: GLenum, data: &mut Option<UserData>) {
        if let Some(TessCallback::BeginData(f)) = self.find(GLU_TESS_BEGIN_DATA) {
            f(gl, prim, poly(data));
        } else if let Some(TessCallback::Begin(f)) = self.find(GLU_TESS_BEGIN) {
            f(gl, prim);
        }
    }

    pub fn edge_flag(&mut self, gl: &mut Gl, flag: bool, data: &mut Option<UserData>) {
        let flag = GLboolean::from(flag);
        if let Some(TessCallback::EdgeFlagData(f)) = self.find(GLU_TESS_EDGE_FLAG_DATA) {
            f(gl, flag, poly(data));
        } else if let Some(TessCallback::EdgeFlag(f)) = self.find(GLU_TESS_EDGE_FLAG) {
            f(gl, flag);
        }
    }

    pub fn vertex(&mut self, gl: &mut Gl, v: Option<&TessData>, data: &mut Option<UserData>) {
        let v: &dyn Any = match v {
            Some(d) => d.as_ref(),
            None => &(),
        };
        if let Some(TessCallback::VertexData(f)) = self.find(GLU_TESS_VERTEX_DATA) {
            f(gl, v, poly(data));
        } else if let Some(TessCallback::Vertex(f)) = self.find(GLU_TESS_VERTEX) {
            f(gl, v);
        }
    }

    pub fn end(&mut self, gl: &mut Gl, data: &mut Option<UserData>) {
        if let Some(TessCallback::EndData(f)) = self.find(GLU_TESS_END_DATA) {
            f(gl, poly(data));
        } else if let Some(TessCallback::End(f)) = self.find(GLU_TESS_END) {
            f(gl);
        }
    }

    pub fn error(&mut self, gl: &mut Gl, code: GLenum, data: &mut Option<UserData>) {
        if let Some(TessCallback::ErrorData(f)) = self.find(GLU_TESS_ERROR_DATA) {
            f(gl, code, poly(data));
        } else if let Some(TessCallback::Error(f)) = self.find(GLU_TESS_ERROR) {
            f(gl, code);
        }
    }

    pub fn combine(
        &mut self,
        gl: &mut Gl,
        coords: [f64; 3],
        v: [Option<TessData>; 4],
        weight: [GLfloat; 4],
        data: &mut Option<UserData>,
    ) -> Option<TessData> {
        let refs: [Option<&dyn Any>; 4] = [0, 1, 2, 3].map(|i| v[i].as_deref());
        if let Some(TessCallback::CombineData(f)) = self.find(GLU_TESS_COMBINE_DATA) {
            f(gl, &coords, refs, &weight, poly(data))
        } else if let Some(TessCallback::Combine(f)) = self.find(GLU_TESS_COMBINE) {
            f(gl, &coords, refs, &weight)
        } else {
            None
        }
    }
}
