//! `gluNurbsCallback`: the tessellator-mode callbacks and the error callback. C passes function
//! pointers that may call GL (the usual way to draw GLU's tessellation yourself: `glBegin`,
//! `glNormal3fv`, `glVertex3fv`, `glEnd` in the callbacks); here each callback is a closure that
//! gets the context first, as GLUT's callbacks do, and the `_DATA` forms also receive the user
//! data set with `gluNurbsCallbackData`. The error callback gets the error code only (GLU
//! reports some errors while the context is busy with the call that caused them).

use crate::gl::types::{GLenum, GLfloat};
use crate::gl::Gl;
use crate::glu::consts::*;
use std::any::Any;

/// User data handed to the `_DATA` callbacks (`gluNurbsCallbackData`).
pub type UserData = Box<dyn Any>;

/// A begin callback: the context and the primitive type.
pub type EnumFn = Box<dyn FnMut(&mut Gl, GLenum)>;
/// An error callback: the error code.
pub type ErrorFn = Box<dyn FnMut(GLenum)>;
/// A callback taking the context and an attribute's floats.
pub type ValuesFn = Box<dyn FnMut(&mut Gl, &[GLfloat])>;
/// An end callback.
pub type EndFn = Box<dyn FnMut(&mut Gl)>;
/// A `_DATA` callback taking the context, a primitive type and the user data.
pub type EnumDataFn = Box<dyn FnMut(&mut Gl, GLenum, &mut dyn Any)>;
/// A `_DATA` callback taking the context, an attribute's floats and the user data.
pub type ValuesDataFn = Box<dyn FnMut(&mut Gl, &[GLfloat], &mut dyn Any)>;
/// A `_DATA` end callback.
pub type DataFn = Box<dyn FnMut(&mut Gl, &mut dyn Any)>;

/// One callback, tagged with its signature.
pub enum NurbsCallback {
    /// `GLU_NURBS_BEGIN`: the primitive type.
    Begin(EnumFn),
    /// `GLU_NURBS_VERTEX`: 5 floats (x, y, z, u, v) for surfaces, the raw k-vector for curves.
    Vertex(ValuesFn),
    /// `GLU_NURBS_NORMAL`: 3 floats.
    Normal(ValuesFn),
    /// `GLU_NURBS_COLOR`: 4 floats.
    Color(ValuesFn),
    /// `GLU_NURBS_TEXTURE_COORD`: 1 to 4 floats.
    TexCoord(ValuesFn),
    /// `GLU_NURBS_END`.
    End(EndFn),
    /// `GLU_NURBS_ERROR`: `GLU_NURBS_ERRORn` or `GLU_INVALID_ENUM`/`VALUE`.
    Error(ErrorFn),
    /// `GLU_NURBS_BEGIN_DATA`.
    BeginData(EnumDataFn),
    /// `GLU_NURBS_VERTEX_DATA`.
    VertexData(ValuesDataFn),
    /// `GLU_NURBS_NORMAL_DATA`.
    NormalData(ValuesDataFn),
    /// `GLU_NURBS_COLOR_DATA`.
    ColorData(ValuesDataFn),
    /// `GLU_NURBS_TEXTURE_COORD_DATA`.
    TexCoordData(ValuesDataFn),
    /// `GLU_NURBS_END_DATA`.
    EndData(DataFn),
}

impl NurbsCallback {
    /// A begin callback.
    pub fn begin(f: impl FnMut(&mut Gl, GLenum) + 'static) -> Self {
        Self::Begin(Box::new(f))
    }
    /// A vertex callback.
    pub fn vertex(f: impl FnMut(&mut Gl, &[GLfloat]) + 'static) -> Self {
        Self::Vertex(Box::new(f))
    }
    /// A normal callback.
    pub fn normal(f: impl FnMut(&mut Gl, &[GLfloat]) + 'static) -> Self {
        Self::Normal(Box::new(f))
    }
    /// A colour callback.
    pub fn color(f: impl FnMut(&mut Gl, &[GLfloat]) + 'static) -> Self {
        Self::Color(Box::new(f))
    }
    /// A texture-coordinate callback.
    pub fn tex_coord(f: impl FnMut(&mut Gl, &[GLfloat]) + 'static) -> Self {
        Self::TexCoord(Box::new(f))
    }
    /// An end callback.
    pub fn end(f: impl FnMut(&mut Gl) + 'static) -> Self {
        Self::End(Box::new(f))
    }
    /// An error callback.
    pub fn error(f: impl FnMut(GLenum) + 'static) -> Self {
        Self::Error(Box::new(f))
    }

    /// The `which` this callback fits.
    fn slot(&self) -> GLenum {
        match self {
            Self::Begin(_) => GLU_NURBS_BEGIN,
            Self::Vertex(_) => GLU_NURBS_VERTEX,
            Self::Normal(_) => GLU_NURBS_NORMAL,
            Self::Color(_) => GLU_NURBS_COLOR,
            Self::TexCoord(_) => GLU_NURBS_TEXTURE_COORD,
            Self::End(_) => GLU_NURBS_END,
            Self::Error(_) => GLU_NURBS_ERROR,
            Self::BeginData(_) => GLU_NURBS_BEGIN_DATA,
            Self::VertexData(_) => GLU_NURBS_VERTEX_DATA,
            Self::NormalData(_) => GLU_NURBS_NORMAL_DATA,
            Self::ColorData(_) => GLU_NURBS_COLOR_DATA,
            Self::TexCoordData(_) => GLU_NURBS_TEXTURE_COORD_DATA,
            Self::EndData(_) => GLU_NURBS_END_DATA,
        }
    }
}

/// The callbacks of one NURBS object; the `_DATA` form wins when both are set (GLU).
#[derive(Default)]
pub(crate) struct Callbacks {
    slots: Vec<NurbsCallback>,
    pub data: Option<UserData>,
}

impl Callbacks {
    /// Stores `cb` for `which`, or clears `which` when `cb` is `None`. Returns false for a
    /// `which` GLU does not know or a callback of the wrong kind.
    pub fn set(&mut self, which: GLenum, cb: Option<NurbsCallback>) -> bool {
        let known = matches!(which, GLU_NURBS_ERROR | GLU_NURBS_BEGIN..=GLU_NURBS_END_DATA);
        if !known || cb.as_ref().is_some_and(|c| c.slot() != which) {
            return false;
        }
        self.slots.retain(|c| c.slot() != which);
        if let Some(cb) = cb {
            self.slots.push(cb);
        }
        true
    }

    fn find(&mut self, which: GLenum) -> Option<&mut NurbsCallback> {
        self.slots.iter_mut().find(|c| c.slot() == which)
    }

    /// Whether a normal callback (plain or data) is registered: GLU computes analytic normals
    /// in tessellator mode only then.
    pub fn wants_normals(&self) -> bool {
        self.slots.iter().any(|c| matches!(c, NurbsCallback::Normal(_) | NurbsCallback::NormalData(_)))
    }

    pub fn error(&mut self, code: GLenum) {
        if let Some(NurbsCallback::Error(f)) = self.find(GLU_NURBS_ERROR) {
            f(code);
        }
    }

    /// Runs `f` with the user data (or `()` when none was set, C's NULL).
    fn with_data<R>(&mut self, f: impl FnOnce(&mut Self, &mut dyn Any) -> R) -> R {
        let mut data = self.data.take();
        let mut none = ();
        let r = match data.as_mut() {
            Some(d) => f(self, d.as_mut()),
            None => f(self, &mut none),
        };
        self.data = data;
        r
    }

    pub fn begin(&mut self, gl: &mut Gl, prim: GLenum) {
        self.with_data(|cbs, d| match cbs.find(GLU_NURBS_BEGIN_DATA) {
            Some(NurbsCallback::BeginData(f)) => f(gl, prim, d),
            _ => {
                if let Some(NurbsCallback::Begin(f)) = cbs.find(GLU_NURBS_BEGIN) {
                    f(gl, prim);
                }
            }
        });
    }

    pub fn end(&mut self, gl: &mut Gl) {
        self.with_data(|cbs, d| match cbs.find(GLU_NURBS_END_DATA) {
            Some(NurbsCallback::EndData(f)) => f(gl, d),
            _ => {
                if let Some(NurbsCallback::End(f)) = cbs.find(GLU_NURBS_END) {
                    f(gl);
                }
            }
        });
    }

    /// Sends an attribute through the (data) callback of `kind` (`GLU_NURBS_VERTEX`, `_NORMAL`,
    /// `_COLOR` or `_TEXTURE_COORD`).
    pub fn attribute(&mut self, gl: &mut Gl, kind: GLenum, values: &[f32]) {
        let with_data = kind + (GLU_NURBS_BEGIN_DATA - GLU_NURBS_BEGIN);
        self.with_data(|cbs, d| match cbs.find(with_data) {
            Some(
                NurbsCallback::VertexData(f)
                | NurbsCallback::NormalData(f)
                | NurbsCallback::ColorData(f)
                | NurbsCallback::TexCoordData(f),
            ) => f(gl, values, d),
            _ => {
                if let Some(
                    NurbsCallback::Vertex(f)
                    | NurbsCallback::Normal(f)
                    | NurbsCallback::Color(f)
                    | NurbsCallback::TexCoord(f),
                ) = cbs.find(kind)
                {
                    f(gl, values);
                }
            }
        });
    }
}

/// The begin, vertex and end callbacks of one object looked up once, for the tessellator's
/// tight loops: a vertex then costs one indirect call instead of a search of the slots and a
/// round trip of the user data. The `_DATA` forms win, as in [`Callbacks`].
pub(crate) struct Sinks<'a> {
    begin: Option<&'a mut NurbsCallback>,
    vertex: Option<&'a mut NurbsCallback>,
    end: Option<&'a mut NurbsCallback>,
    data: Option<&'a mut UserData>,
}

impl Callbacks {
    /// The begin, vertex and end sinks; `None` when another callback (normal, colour, texture
    /// coordinate) is registered, since those interleave with the vertices.
    pub fn sinks(&mut self) -> Option<Sinks<'_>> {
        let others = [GLU_NURBS_NORMAL, GLU_NURBS_COLOR, GLU_NURBS_TEXTURE_COORD];
        let data_form = |w: GLenum| w + (GLU_NURBS_BEGIN_DATA - GLU_NURBS_BEGIN);
        if self.slots.iter().any(|c| others.iter().any(|&w| c.slot() == w || c.slot() == data_form(w))) {
            return None;
        }
        let has = |w: GLenum| self.slots.iter().any(|c| c.slot() == data_form(w));
        let pick = [GLU_NURBS_BEGIN, GLU_NURBS_VERTEX, GLU_NURBS_END].map(|w| if has(w) { data_form(w) } else { w });
        let mut sinks = Sinks { begin: None, vertex: None, end: None, data: self.data.as_mut() };
        for c in &mut self.slots {
            let slot = c.slot();
            if slot == pick[0] {
                sinks.begin = Some(c);
            } else if slot == pick[1] {
                sinks.vertex = Some(c);
            } else if slot == pick[2] {
                sinks.end = Some(c);
            }
        }
        Some(sinks)
    }
}

/// Where the tessellator's tight loops send primitives: [`Sinks`], or [`PlainSinks`] when no
/// `_DATA` form is registered.
pub(crate) trait StripSink {
    fn begin(&mut self, gl: &mut Gl, prim: GLenum);
    fn vertex(&mut self, gl: &mut Gl, values: &[f32]);
    fn end(&mut self, gl: &mut Gl);
}

/// The plain begin, vertex and end callbacks, their forms resolved: a vertex is one indirect
/// call, with no look-up of the callback's form and no user data to thread through.
pub(crate) struct PlainSinks<'a> {
    begin: Option<&'a mut EnumFn>,
    vertex: &'a mut ValuesFn,
    end: Option<&'a mut EndFn>,
}

impl<'a> Sinks<'a> {
    /// The plain sinks; `None` when a `_DATA` form or no vertex callback is registered.
    pub fn plain(&mut self) -> Option<PlainSinks<'_>> {
        let begin = match self.begin.as_deref_mut() {
            Some(NurbsCallback::Begin(f)) => Some(f),
            None => None,
            Some(_) => return None,
        };
        let Some(NurbsCallback::Vertex(vertex)) = self.vertex.as_deref_mut() else { return None };
        let end = match self.end.as_deref_mut() {
            Some(NurbsCallback::End(f)) => Some(f),
            None => None,
            Some(_) => return None,
        };
        Some(PlainSinks { begin, vertex, end })
    }
}

impl StripSink for PlainSinks<'_> {
    fn begin(&mut self, gl: &mut Gl, prim: GLenum) {
        if let Some(f) = self.begin.as_deref_mut() {
            f(gl, prim);
        }
    }

    #[inline]
    fn vertex(&mut self, gl: &mut Gl, values: &[f32]) {
        (self.vertex)(gl, values);
    }

    fn end(&mut self, gl: &mut Gl) {
        if let Some(f) = self.end.as_deref_mut() {
            f(gl);
        }
    }
}

impl StripSink for Sinks<'_> {
    fn begin(&mut self, gl: &mut Gl, prim: GLenum) {
        Sinks::begin(self, gl, prim);
    }

    #[inline]
    fn vertex(&mut self, gl: &mut Gl, values: &[f32]) {
        Sinks::vertex(self, gl, values);
    }

    fn end(&mut self, gl: &mut Gl) {
        Sinks::end(self, gl);
    }
}

impl Sinks<'_> {
    fn with_data(data: &mut Option<&mut UserData>, f: impl FnOnce(&mut dyn Any)) {
        match data {
            Some(d) => f(d.as_mut()),
            None => f(&mut ()),
        }
    }

    pub fn begin(&mut self, gl: &mut Gl, prim: GLenum) {
        match self.begin.as_deref_mut() {
            Some(NurbsCallback::Begin(f)) => f(gl, prim),
            Some(NurbsCallback::BeginData(f)) => Self::with_data(&mut self.data, |d| f(gl, prim, d)),
            _ => {}
        }
    }

    #[inline]
    pub fn vertex(&mut self, gl: &mut Gl, values: &[f32]) {
        match self.vertex.as_deref_mut() {
            Some(NurbsCallback::Vertex(f)) => f(gl, values),
            Some(NurbsCallback::VertexData(f)) => Self::with_data(&mut self.data, |d| f(gl, values, d)),
            _ => {}
        }
    }

    pub fn end(&mut self, gl: &mut Gl) {
        match self.end.as_deref_mut() {
            Some(NurbsCallback::End(f)) => f(gl),
            Some(NurbsCallback::EndData(f)) => Self::with_data(&mut self.data, |d| f(gl, d)),
            _ => {}
        }
    }
}
