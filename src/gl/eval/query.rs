//! `glGetMap{f,d,i}v` (Mesa `_mesa_GetnMap*vARB`): `GL_COEFF`, `GL_ORDER`, `GL_DOMAIN`.

use super::target::MapTarget;
use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;

impl Gl {
    /// Values `glGetMap*v` writes for `target` and `query`: `GL_ORDER` one a dimension,
    /// `GL_DOMAIN` two, `GL_COEFF` the map's points times its components; 0 where GL writes
    /// nothing (an unknown target or query). What a binding with only a pointer (the C ABI)
    /// makes its slice of.
    #[must_use]
    pub fn get_map_len(&self, target: GLenum, query: GLenum) -> usize {
        let Some(t) = MapTarget::from_enum(target) else { return 0 };
        let dims = usize::from(t.dims);
        match query {
            GL_ORDER => dims,
            GL_DOMAIN => 2 * dims,
            GL_COEFF => self.server.eval.map(t.dims, t.slot).points.len(),
            _ => 0,
        }
    }

    /// `glGetMapfv`. Unknown target, then unknown query → `GL_INVALID_ENUM`; `GL_COEFF` returns
    /// the packed points u-major (the original strides are not kept); a slice shorter than the
    /// answer → `GL_INVALID_VALUE` and nothing written.
    pub fn get_mapfv(&mut self, target: GLenum, query: GLenum, v: &mut [GLfloat]) {
        if let Some(values) = self.map_query(target, query) {
            self.write_query(&values, v, |x| x);
        }
    }

    /// `glGetMapdv` (the stored floats widened to double).
    pub fn get_mapdv(&mut self, target: GLenum, query: GLenum, v: &mut [GLdouble]) {
        if let Some(values) = self.map_query(target, query) {
            self.write_query(&values, v, f64::from);
        }
    }

    /// `glGetMapiv`: coefficients and domains rounded half away from zero (Mesa's `lroundf`).
    pub fn get_mapiv(&mut self, target: GLenum, query: GLenum, v: &mut [GLint]) {
        if let Some(values) = self.map_query(target, query) {
            self.write_query(&values, v, |x| x.round() as GLint);
        }
    }

    fn write_query<T>(&mut self, values: &[f32], out: &mut [T], convert: impl Fn(f32) -> T) {
        if out.len() < values.len() {
            return self.set_error(GL_INVALID_VALUE);
        }
        for (o, &x) in out.iter_mut().zip(values) {
            *o = convert(x);
        }
    }

    fn map_query(&mut self, target: GLenum, query: GLenum) -> Option<Vec<f32>> {
        if self.reject_inside_begin_end() {
            return None;
        }
        let Some(t) = MapTarget::from_enum(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let map = self.server.eval.map(t.dims, t.slot);
        let values = match (query, t.dims) {
            (GL_COEFF, _) => map.points.clone(),
            (GL_ORDER, 1) => vec![map.uorder as f32],
            (GL_ORDER, _) => vec![map.uorder as f32, map.vorder as f32],
            (GL_DOMAIN, 1) => vec![map.u1, map.u2],
            (GL_DOMAIN, _) => vec![map.u1, map.u2, map.v1, map.v2],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(values)
    }
}
