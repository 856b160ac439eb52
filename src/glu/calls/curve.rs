//! The curve calls: `gluBeginCurve`, `gluEndCurve`, `gluNurbsCurve` and `gluPwlCurve`, also
//! inside a trim (a curve group of a trim loop).

use super::validate::{gather, validate_curve};
use crate::gl::types::*;
use crate::gl::Gl;
use crate::glu::draw::curve::draw_curve;
use crate::glu::model::maps::TrimPiece;
use crate::glu::model::object::GLUnurbs;
use crate::glu::model::targets::{curve_type, is_trim_type};

impl Gl {
    /// `gluBeginCurve`: inside a curve → error 6 and the old curve is ended first.
    pub fn glu_begin_curve(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.trim.is_some() {
            if obj.nesting.trim_group.is_some() {
                obj.nurbs_error(6);
            }
            obj.nesting.trim_group = Some(Vec::new());
            return;
        }
        if obj.nesting.curve.is_some() {
            obj.nurbs_error(6);
            self.glu_end_curve(nobj);
        }
        self.auto_load_matrices(nobj);
        if let Some(obj) = self.nurbs(nobj) {
            obj.nesting.curve = Some(Vec::new());
            obj.nesting.curve_valid = true;
        }
    }

    /// `gluEndCurve`: without a begin → error 7. Draws the curve.
    pub fn glu_end_curve(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.trim.is_some() {
            match obj.nesting.trim_group.take() {
                Some(group) => obj.nesting.trim.get_or_insert_with(Vec::new).extend(group),
                None => obj.nurbs_error(7),
            }
            return;
        }
        let Some(maps) = obj.nesting.curve.take() else {
            return obj.nurbs_error(7);
        };
        if maps.is_empty() {
            // GLU treats a curve without data as a piecewise-linear one it cannot draw.
            return obj.nurbs_error(9);
        }
        if obj.nesting.curve_valid {
            self.with_nurbs(nobj, |gl, obj| draw_curve(gl, obj, &maps));
        }
    }

    /// `gluNurbsCurve(nobj, nknots, knots, stride, ctlarray, order, type)`: stride in floats.
    /// Checks in GLU's order: unknown type (35), empty control array (36), negative stride (34),
    /// knots (1–5); then a knot or control slice shorter than the call reads (10, 8). Outside a
    /// begin/end pair the curve is drawn at once.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_nurbs_curve(
        &mut self,
        nobj: GLUnurbs,
        nknots: GLint,
        knots: &[GLfloat],
        stride: GLint,
        ctlarray: &[GLfloat],
        order: GLint,
        kind: GLenum,
    ) {
        let Some(obj) = self.nurbs(nobj) else { return };
        let Some(map) = validate_curve(obj, nknots, knots, stride, ctlarray, order, kind) else {
            obj.nesting.curve_valid = false;
            if let Some(s) = obj.nesting.surface.as_mut() {
                s.valid &= obj.nesting.trim.is_none();
            }
            return;
        };
        if obj.nesting.trim.is_some() {
            if !is_trim_type(kind) {
                return obj.nurbs_error(14);
            }
            let piece = TrimPiece::Curve(map);
            match obj.nesting.trim_group.as_mut() {
                Some(group) if group.iter().any(|p| matches!(p, TrimPiece::Pwl(_))) => obj.nurbs_error(24),
                Some(group) => group.push(piece),
                None => obj.nesting.trim.get_or_insert_with(Vec::new).push(piece),
            }
            return;
        }
        if is_trim_type(kind) {
            return obj.nurbs_error(22);
        }
        if let Some(curve) = obj.nesting.curve.as_mut() {
            curve.push(map);
            return;
        }
        self.glu_begin_curve(nobj);
        if let Some(curve) = self.nurbs(nobj).and_then(|o| o.nesting.curve.as_mut()) {
            curve.push(map);
        }
        self.glu_end_curve(nobj);
    }

    /// `gluPwlCurve(nobj, count, data, stride, type)`: a piecewise-linear trim curve. Unknown
    /// type (35), a non-trim type (22), `count < 0` (33), `stride < 0` (34), outside a trim (19).
    pub fn glu_pwl_curve(&mut self, nobj: GLUnurbs, count: GLint, data: &[GLfloat], stride: GLint, kind: GLenum) {
        let Some(obj) = self.nurbs(nobj) else { return };
        let Some(k) = curve_type(kind) else { return obj.nurbs_error(35) };
        let checks = [(!is_trim_type(kind), 22), (count < 0, 33), (stride < 0, 34), (obj.nesting.trim.is_none(), 19)];
        if let Some((_, n)) = checks.iter().find(|(bad, _)| *bad) {
            return obj.nurbs_error(*n);
        }
        let Some(values) = gather(data, count as usize, stride as usize, k) else {
            return obj.nurbs_error(8);
        };
        // TRIM_3 points are homogeneous: divide by w.
        let points: Vec<[f64; 2]> =
            values.chunks_exact(k).map(|p| if k == 3 { [p[0] / p[2], p[1] / p[2]] } else { [p[0], p[1]] }).collect();
        let piece = TrimPiece::Pwl(points);
        match obj.nesting.trim_group.as_mut() {
            Some(group) if group.iter().any(|p| matches!(p, TrimPiece::Curve(_))) => obj.nurbs_error(21),
            Some(group) => group.push(piece),
            None => obj.nesting.trim.get_or_insert_with(Vec::new).push(piece),
        }
    }
}
