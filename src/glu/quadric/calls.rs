//! The quadric object (`GLUquadric*`) and GLU's quadric entry points as methods of
//! [`Gl`]: `gluNewQuadric` ... `gluPartialDisk`. GLU reports errors only through the object's
//! `GLU_ERROR` callback (none set: errors vanish), and draws through GL's own calls.

use super::{Quadric, QuadricSink};
use crate::gl::types::*;
use crate::gl::Gl;
use crate::glu::consts::*;

/// A quadric object (`GLUquadric*`): a copyable handle into its [`Gl`] context.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GLUquadric(pub(crate) usize);

/// A quadric's `GLU_ERROR` callback: it receives the GLU error code.
pub type QuadricErrorFn = Box<dyn FnMut(GLenum)>;

/// The state behind a [`GLUquadric`]: its modes and its error callback.
#[derive(Default)]
pub(crate) struct QuadricObject {
    modes: Quadric,
    error: Option<QuadricErrorFn>,
}

impl std::fmt::Debug for QuadricObject {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("QuadricObject").field("modes", &self.modes).finish_non_exhaustive()
    }
}

impl QuadricObject {
    /// Reports `result`'s error through the callback, if there is one.
    fn report(&mut self, result: Result<(), GLenum>) {
        if let (Err(code), Some(callback)) = (result, self.error.as_mut()) {
            callback(code);
        }
    }
}

/// GL is a quadric's sink: `glBegin`, `glNormal3f`, `glTexCoord2f`, `glVertex3f`, `glEnd`.
impl QuadricSink for Gl {
    fn begin(&mut self, mode: GLenum) {
        Gl::begin(self, mode);
    }
    fn end(&mut self) {
        Gl::end(self);
    }
    fn normal(&mut self, n: [f32; 3]) {
        self.normal3f(n[0], n[1], n[2]);
    }
    fn tex_coord(&mut self, t: [f32; 2]) {
        self.tex_coord2f(t[0], t[1]);
    }
    fn vertex(&mut self, v: [f32; 3]) {
        self.vertex3f(v[0], v[1], v[2]);
    }
}

impl Gl {
    fn quadric(&mut self, q: GLUquadric) -> Option<&mut QuadricObject> {
        self.glu.quadrics.get_mut(q.0)
    }

    /// Runs `draw` with the object's modes and GL as the sink; its error goes to the callback.
    fn draw_quadric(&mut self, q: GLUquadric, draw: impl FnOnce(&Quadric, &mut Gl) -> Result<(), GLenum>) {
        let Some(modes) = self.quadric(q).map(|obj| obj.modes) else { return };
        let result = draw(&modes, self);
        if let Some(obj) = self.quadric(q) {
            obj.report(result);
        }
    }

    /// Applies a mode setter; its error goes to the callback.
    fn set_quadric(&mut self, q: GLUquadric, set: impl FnOnce(&mut Quadric) -> Result<(), GLenum>) {
        if let Some(obj) = self.quadric(q) {
            let result = set(&mut obj.modes);
            obj.report(result);
        }
    }

    /// `gluNewQuadric`: a quadric in GLU's initial modes ([`Quadric::DEFAULT`]), no callback.
    pub fn glu_new_quadric(&mut self) -> GLUquadric {
        GLUquadric(self.glu.quadrics.insert(QuadricObject::default()))
    }

    /// `gluDeleteQuadric`. Later calls with the handle do nothing.
    pub fn glu_delete_quadric(&mut self, q: GLUquadric) {
        self.glu.quadrics.remove(q.0);
    }

    /// `gluQuadricCallback(q, GLU_ERROR, f)`: `None` removes the callback. Another `which` is
    /// `GLU_INVALID_ENUM`, reported through the callback already set.
    pub fn glu_quadric_callback(&mut self, q: GLUquadric, which: GLenum, f: Option<QuadricErrorFn>) {
        let Some(obj) = self.quadric(q) else { return };
        if which == GLU_ERROR {
            obj.error = f;
        } else {
            obj.report(Err(GLU_INVALID_ENUM));
        }
    }

    /// `gluQuadricDrawStyle`: `GLU_FILL`, `GLU_LINE`, `GLU_SILHOUETTE` or `GLU_POINT`;
    /// another value is `GLU_INVALID_ENUM` and keeps the style.
    pub fn glu_quadric_draw_style(&mut self, q: GLUquadric, draw_style: GLenum) {
        self.set_quadric(q, |m| m.set_draw_style(draw_style));
    }

    /// `gluQuadricNormals`: `GLU_NONE`, `GLU_FLAT` or `GLU_SMOOTH`; another value is
    /// `GLU_INVALID_ENUM` and keeps the mode.
    pub fn glu_quadric_normals(&mut self, q: GLUquadric, normals: GLenum) {
        self.set_quadric(q, |m| m.set_normals(normals));
    }

    /// `gluQuadricOrientation`: `GLU_OUTSIDE` or `GLU_INSIDE`; another value is
    /// `GLU_INVALID_ENUM` and keeps the orientation.
    pub fn glu_quadric_orientation(&mut self, q: GLUquadric, orientation: GLenum) {
        self.set_quadric(q, |m| m.set_orientation(orientation));
    }

    /// `gluQuadricTexture`: texture coordinates on for any nonzero value.
    pub fn glu_quadric_texture(&mut self, q: GLUquadric, texture: GLboolean) {
        self.set_quadric(q, |m| {
            m.texture = texture != 0;
            Ok(())
        });
    }

    /// `gluSphere` ([`Quadric::sphere`]).
    pub fn glu_sphere(&mut self, q: GLUquadric, radius: GLdouble, slices: GLint, stacks: GLint) {
        self.draw_quadric(q, |m, gl| m.sphere(gl, radius, slices, stacks));
    }

    /// `gluCylinder` ([`Quadric::cylinder`]).
    pub fn glu_cylinder(
        &mut self,
        q: GLUquadric,
        base: GLdouble,
        top: GLdouble,
        height: GLdouble,
        slices: GLint,
        stacks: GLint,
    ) {
        self.draw_quadric(q, |m, gl| m.cylinder(gl, base, top, height, slices, stacks));
    }

    /// `gluDisk` ([`Quadric::disk`]).
    pub fn glu_disk(&mut self, q: GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint) {
        self.draw_quadric(q, |m, gl| m.disk(gl, inner, outer, slices, loops));
    }

    /// `gluPartialDisk` ([`Quadric::partial_disk`]).
    #[allow(clippy::too_many_arguments)]
    pub fn glu_partial_disk(
        &mut self,
        q: GLUquadric,
        inner: GLdouble,
        outer: GLdouble,
        slices: GLint,
        loops: GLint,
        start: GLdouble,
        sweep: GLdouble,
    ) {
        self.draw_quadric(q, |m, gl| m.partial_disk(gl, inner, outer, slices, loops, start, sweep));
    }
}
