//! The tessellator's GLU entry points as methods of [`Gl`] (the porting rule:
//! `gluTessVertex(tobj, v, v)` → `gl.glu_tess_vertex(tobj, &v, v)`).
//!
//! The object lives in the context; while one of its calls runs (and its callbacks with it)
//! it is taken out, so that the callbacks get the context itself. Calls on a deleted
//! object, or on the object whose callback is running, do nothing (GLU would crash or
//! recurse).

use super::callbacks::{TessCallback, TessData};
use super::object::{GLUtesselator, TessObject};
use crate::gl::types::{GLdouble, GLenum};
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::UserData;
use std::any::Any;
use std::rc::Rc;

impl Gl {
    /// Runs `f` on tessellator `t` with the context at hand.
    fn with_tess(&mut self, t: GLUtesselator, f: impl FnOnce(&mut TessObject, &mut Self)) {
        let Some(mut obj) = self.glu.tessellators.take(t.0) else { return };
        f(&mut obj, self);
        self.glu.tessellators.put_back(t.0, obj);
    }

    /// `gluNewTess`: a tessellator with the odd winding rule, no normal, no callbacks.
    ///
    /// A square with a square hole, as GLU tessellates it: a strip of 7 triangles, then the
    /// one left over alone.
    /// ```
    /// use gleval::prelude::*;
    /// use std::{cell::RefCell, rc::Rc};
    /// let mut gl = Gl::new(8, 8);
    /// let tobj = gl.glu_new_tess();
    /// let seen = Rc::new(RefCell::new(Vec::new()));
    /// let (s1, s2) = (seen.clone(), seen.clone());
    /// gl.glu_tess_callback(tobj, GLU_TESS_BEGIN, Some(TessCallback::begin(move |_, prim| s1.borrow_mut().push(prim))));
    /// gl.glu_tess_callback(tobj, GLU_TESS_VERTEX, Some(TessCallback::vertex_of(move |_, _: &[f64; 3]| s2.borrow_mut().push(0))));
    /// gl.glu_tess_begin_polygon(tobj, None);
    /// for contour in [[[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]], [[1.0, 1.0], [1.0, 3.0], [3.0, 3.0], [3.0, 1.0]]] {
    ///     gl.glu_tess_begin_contour(tobj);
    ///     for [x, y] in contour {
    ///         gl.glu_tess_vertex(tobj, &[x, y, 0.0], [x, y, 0.0]);
    ///     }
    ///     gl.glu_tess_end_contour(tobj);
    /// }
    /// gl.glu_tess_end_polygon(tobj);
    /// gl.glu_delete_tess(tobj);
    /// // Each primitive, then a 0 per vertex.
    /// assert_eq!(*seen.borrow(), [vec![GL_TRIANGLE_STRIP], vec![0; 9], vec![GL_TRIANGLES], vec![0; 3]].concat());
    /// ```
    pub fn glu_new_tess(&mut self) -> GLUtesselator {
        GLUtesselator(self.glu.tessellators.insert(TessObject::new()))
    }

    /// `gluDeleteTess`: a polygon still open is ended as GLU ends it (errors reported, the
    /// polygon discarded).
    pub fn glu_delete_tess(&mut self, t: GLUtesselator) {
        let mut ended = false;
        self.with_tess(t, |obj, gl| {
            obj.delete(gl);
            ended = true;
        });
        // Not from inside the object's own callbacks: the object is busy then.
        if ended {
            self.glu.tessellators.remove(t.0);
        }
    }

    /// `gluTessBeginPolygon`: `data` is handed to the `_DATA` callbacks (C's `void *`; `None`
    /// for NULL) until the polygon ends.
    pub fn glu_tess_begin_polygon(&mut self, t: GLUtesselator, data: Option<UserData>) {
        self.with_tess(t, |obj, gl| obj.begin_polygon(gl, data));
    }

    /// `gluTessBeginContour`.
    pub fn glu_tess_begin_contour(&mut self, t: GLUtesselator) {
        self.with_tess(t, |obj, gl| obj.begin_contour(gl));
    }

    /// `gluTessVertex`: the vertex at `location` (three values), with `data` handed back to
    /// the vertex callback (any type; [`TessCallback::vertex_of`] takes it typed). A
    /// `location` of fewer than three values is `GLU_INVALID_VALUE` through the error
    /// callback.
    pub fn glu_tess_vertex<T: Any>(&mut self, t: GLUtesselator, location: &[GLdouble], data: T) {
        self.glu_tess_vertex_shared(t, location, Some(Rc::new(data)));
    }

    /// `gluTessVertex` with data already shared (or none, C's NULL).
    pub fn glu_tess_vertex_shared(&mut self, t: GLUtesselator, location: &[GLdouble], data: Option<TessData>) {
        self.with_tess(t, |obj, gl| match location {
            [x, y, z, ..] => obj.vertex(gl, [*x, *y, *z], data),
            _ => obj.error(gl, GLU_INVALID_VALUE),
        });
    }

    /// `gluTessEndContour`.
    pub fn glu_tess_end_contour(&mut self, t: GLUtesselator) {
        self.with_tess(t, |obj, gl| obj.end_contour(gl));
    }

    /// `gluTessEndPolygon`: tessellates and calls the callbacks.
    pub fn glu_tess_end_polygon(&mut self, t: GLUtesselator) {
        self.with_tess(t, |obj, gl| obj.end_polygon(gl));
    }

    /// `gluTessProperty`: `GLU_TESS_WINDING_RULE`, `GLU_TESS_BOUNDARY_ONLY` or
    /// `GLU_TESS_TOLERANCE` (kept, without effect, as in GLU).
    pub fn glu_tess_property(&mut self, t: GLUtesselator, which: GLenum, value: GLdouble) {
        self.with_tess(t, |obj, gl| obj.property(gl, which, value));
    }

    /// `gluGetTessProperty`: writes the value to `value[0]` (0 for an unknown property, with
    /// `GLU_INVALID_ENUM`).
    pub fn glu_get_tess_property(&mut self, t: GLUtesselator, which: GLenum, value: &mut [GLdouble]) {
        self.with_tess(t, |obj, gl| {
            let v = obj.get_property(gl, which);
            if let Some(out) = value.first_mut() {
                *out = v;
            }
        });
    }

    /// `gluTessNormal`: the polygon's normal; (0, 0, 0), the default, lets GLU compute one.
    pub fn glu_tess_normal(&mut self, t: GLUtesselator, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.with_tess(t, |obj, _| obj.set_normal([x, y, z]));
    }

    /// `gluTessCallback`: `None` removes the callback. An unknown `which` is
    /// `GLU_INVALID_ENUM`, a callback of another kind than `which` names `GLU_INVALID_VALUE`,
    /// both through the error callback.
    pub fn glu_tess_callback(&mut self, t: GLUtesselator, which: GLenum, callback: Option<TessCallback>) {
        // GLU's private `GLU_TESS_MESH` (100112) is accepted and unused.
        if which == 100_112 && callback.is_none() {
            return;
        }
        self.with_tess(t, |obj, gl| {
            let known = (GLU_TESS_BEGIN..=GLU_TESS_COMBINE_DATA).contains(&which);
            if !obj.callbacks.set(which, callback) {
                obj.error(gl, if known { GLU_INVALID_VALUE } else { GLU_INVALID_ENUM });
            }
        });
    }

    /// `gluBeginPolygon` (GLU 1.0): `gluTessBeginPolygon(t, NULL)` and
    /// `gluTessBeginContour(t)`.
    pub fn glu_begin_polygon(&mut self, t: GLUtesselator) {
        self.glu_tess_begin_polygon(t, None);
        self.glu_tess_begin_contour(t);
    }

    /// `gluNextContour` (GLU 1.0): ends the contour and begins another; the contour type
    /// (`GLU_EXTERIOR`, `GLU_INTERIOR`, `GLU_CCW`, `GLU_CW`, `GLU_UNKNOWN`) is ignored, as in
    /// GLU 1.2 and later.
    pub fn glu_next_contour(&mut self, t: GLUtesselator, _type: GLenum) {
        self.glu_tess_end_contour(t);
        self.glu_tess_begin_contour(t);
    }

    /// `gluEndPolygon` (GLU 1.0): ends the contour and the polygon.
    pub fn glu_end_polygon(&mut self, t: GLUtesselator) {
        self.glu_tess_end_contour(t);
        self.glu_tess_end_polygon(t);
    }
}
