//! `glEvalCoord1/2` (Mesa `vbo_exec_eval.c`): evaluate the active maps at one parameter and
//! issue the vertex. Evaluated attributes go to that vertex only; the current colour, normal and
//! texture coordinate are left unchanged (GL 1.1 spec §5.1).

use super::target::Slot;
use super::ActiveMaps;
use super::EvalCall;
use crate::gl::lists::ListCommand;
use crate::gl::types::*;
use crate::gl::Gl;
use crate::math::bezier::horner;
use crate::math::patch::{horner_patch, patch_with_partials};
use crate::math::rational::{cross, normalize, rational_derivative};

/// The unit normal from the partial derivatives of the vertex map: du × dv, with the rational
/// correction for a 4-component map (Mesa `vbo_exec_do_EvalCoord2f`); zero stays zero.
pub(crate) fn auto_normal(k: usize, point: [f32; 4], du: [f32; 4], dv: [f32; 4]) -> [f32; 3] {
    let (a, b) = if k == 4 {
        (rational_derivative(point, du), rational_derivative(point, dv))
    } else {
        ([du[0], du[1], du[2]], [dv[0], dv[1], dv[2]])
    };
    normalize(cross(a, b))
}

impl ActiveMaps {
    /// The non-position attribute maps, in the order Mesa evaluates them.
    pub(crate) fn attributes(&self) -> impl Iterator<Item = Slot> {
        [self.color, self.tex, self.normal].into_iter().flatten()
    }
}

impl Gl {
    /// `glEvalCoord1f`: with no `GL_MAP1_VERTEX_3/4` enabled it does nothing; outside
    /// `begin`/`end` the vertex only moves the current position, so nothing is recorded.
    pub fn eval_coord1f(&mut self, u: GLfloat) {
        if self.compiled(|| ListCommand::Eval(EvalCall::EvalCoord1(u))) {
            return;
        }
        let act = self.server.eval.active(1);
        let Some(vertex_slot) = act.vertex else {
            return;
        };
        let mut v = self.current_vertex([0.0, 0.0, 0.0, 1.0]);
        for slot in act.attributes().chain([vertex_slot]) {
            let m = self.server.eval.map(1, slot);
            let p = horner(&m.points, slot.components(), m.uorder, m.norm_u(u));
            v.set_attribute(slot, p);
        }
        self.emit_vertex(v);
    }

    /// `glEvalCoord1d` (cast to float).
    pub fn eval_coord1d(&mut self, u: GLdouble) {
        self.eval_coord1f(u as f32);
    }

    /// `glEvalCoord1fv`: `u` needs 1 value.
    pub fn eval_coord1fv(&mut self, u: &[GLfloat]) {
        if let Some([u]) = self.needs::<1>(u) {
            self.eval_coord1f(u);
        }
    }

    /// `glEvalCoord2f`: evaluates the MAP2 maps; with `GL_AUTO_NORMAL` the vertex map's unit
    /// normal replaces the normal map's value.
    pub fn eval_coord2f(&mut self, u: GLfloat, v: GLfloat) {
        if self.compiled(|| ListCommand::Eval(EvalCall::EvalCoord2(u, v))) {
            return;
        }
        let act = self.server.eval.active(2);
        let Some(vertex_slot) = act.vertex else {
            return;
        };
        let mut out = self.current_vertex([0.0, 0.0, 0.0, 1.0]);
        for slot in act.attributes() {
            let m = self.server.eval.map(2, slot);
            let p = horner_patch(&m.points, slot.components(), m.uorder, m.vorder, m.norm_u(u), m.norm_v(v));
            out.set_attribute(slot, p);
        }
        let m = self.server.eval.map(2, vertex_slot);
        let k = vertex_slot.components();
        let (uu, vv) = (m.norm_u(u), m.norm_v(v));
        if self.server.eval.auto_normal {
            let s = patch_with_partials(&m.points, k, m.uorder, m.vorder, uu, vv);
            out.normal = auto_normal(k, s.point, s.du, s.dv);
            out.set_attribute(vertex_slot, s.point);
        } else {
            let p = horner_patch(&m.points, k, m.uorder, m.vorder, uu, vv);
            out.set_attribute(vertex_slot, p);
        }
        self.emit_vertex(out);
    }

    /// `glEvalCoord2d` (cast to float).
    pub fn eval_coord2d(&mut self, u: GLdouble, v: GLdouble) {
        self.eval_coord2f(u as f32, v as f32);
    }

    /// `glEvalCoord2fv`: `uv` needs 2 values.
    pub fn eval_coord2fv(&mut self, uv: &[GLfloat]) {
        if let Some([u, v]) = self.needs::<2>(uv) {
            self.eval_coord2f(u, v);
        }
    }

    /// `glEvalCoord1dv`: `u` needs 1 value.
    pub fn eval_coord1dv(&mut self, u: &[GLdouble]) {
        match u.first() {
            Some(&u) => self.eval_coord1d(u),
            None => self.set_error(crate::gl::consts::GL_INVALID_VALUE),
        }
    }

    /// `glEvalCoord2dv`: `uv` needs 2 values.
    pub fn eval_coord2dv(&mut self, uv: &[GLdouble]) {
        match uv {
            [u, v, ..] => self.eval_coord2d(*u, *v),
            _ => self.set_error(crate::gl::consts::GL_INVALID_VALUE),
        }
    }
}
