//! The surface calls: `gluBeginSurface`, `gluEndSurface`, `gluNurbsSurface`, `gluBeginTrim`
//! and `gluEndTrim`.

use super::validate::validate_surface;
use crate::gl::types::*;
use crate::gl::Gl;
use crate::glu::draw::surface::draw_surface;
use crate::glu::model::maps::SurfaceDef;
use crate::glu::model::object::GLUnurbs;

impl Gl {
    /// `gluBeginSurface`: inside a surface → error 27 and the old surface is ended first.
    pub fn glu_begin_surface(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.surface.is_some() {
            obj.nurbs_error(27);
            self.glu_end_surface(nobj);
        }
        self.auto_load_matrices(nobj);
        if let Some(obj) = self.nurbs(nobj) {
            obj.nesting.surface = Some(SurfaceDef { valid: true, ..SurfaceDef::default() });
        }
    }

    /// `gluEndSurface`: inside a trim → error 12 (the trim is ended); without a begin →
    /// error 13. Draws the surface if its definition was valid.
    pub fn glu_end_surface(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.trim.is_some() {
            obj.nurbs_error(12);
            self.glu_end_trim(nobj);
        }
        let Some(obj) = self.nurbs(nobj) else { return };
        let Some(surface) = obj.nesting.surface.take() else {
            return obj.nurbs_error(13);
        };
        // A surface begun by `gluBeginTrim` is over too (GLU's `inSurface = 0`): the next
        // `gluNurbsSurface` must not end its own surface early.
        obj.nesting.auto_surface = false;
        if surface.valid {
            self.with_nurbs(nobj, |gl, obj| draw_surface(gl, obj, &surface));
        }
    }

    /// `gluNurbsSurface(nobj, sknot_count, sknots, tknot_count, tknots, s_stride, t_stride,
    /// ctlarray, sorder, torder, type)`: point (i, j) at `i*s_stride + j*t_stride` floats.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_nurbs_surface(
        &mut self,
        nobj: GLUnurbs,
        sknot_count: GLint,
        sknots: &[GLfloat],
        tknot_count: GLint,
        tknots: &[GLfloat],
        s_stride: GLint,
        t_stride: GLint,
        ctlarray: &[GLfloat],
        sorder: GLint,
        torder: GLint,
        kind: GLenum,
    ) {
        let Some(obj) = self.nurbs(nobj) else { return };
        let map = validate_surface(
            obj,
            (sknot_count, sknots, sorder),
            (tknot_count, tknots, torder),
            (s_stride, t_stride),
            ctlarray,
            kind,
        );
        let auto = obj.nesting.surface.is_none() || std::mem::take(&mut obj.nesting.auto_surface);
        if self.nurbs(nobj).is_some_and(|o| o.nesting.surface.is_none()) {
            self.glu_begin_surface(nobj);
        }
        if let Some(s) = self.nurbs(nobj).and_then(|o| o.nesting.surface.as_mut()) {
            match map {
                Some(m) => s.maps.push(m),
                None => s.valid = false,
            }
        }
        if auto {
            self.glu_end_surface(nobj);
        }
    }

    /// `gluBeginTrim`: outside a surface → error 15 (a surface is begun, and the next
    /// `gluNurbsSurface` ends it); inside a trim → error 16 (the open trim is ended first).
    pub fn glu_begin_trim(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.surface.is_none() {
            obj.nurbs_error(15);
            self.glu_begin_surface(nobj);
            if let Some(obj) = self.nurbs(nobj) {
                obj.nesting.auto_surface = true;
            }
        }
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.trim.is_some() {
            obj.nurbs_error(16);
            self.glu_end_trim(nobj);
        }
        if let Some(obj) = self.nurbs(nobj) {
            obj.nesting.trim = Some(Vec::new());
        }
    }

    /// `gluEndTrim`: without a begin → error 17; an empty loop → error 18 (the surface is not
    /// drawn).
    pub fn glu_end_trim(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        let Some(mut pieces) = obj.nesting.trim.take() else {
            return obj.nurbs_error(17);
        };
        if let Some(group) = obj.nesting.trim_group.take() {
            pieces.extend(group);
        }
        let empty = pieces.is_empty();
        if empty {
            obj.nurbs_error(18);
        }
        if let Some(s) = obj.nesting.surface.as_mut() {
            if empty {
                s.valid = false;
            } else {
                s.loops.push(pieces);
            }
        }
    }
}
