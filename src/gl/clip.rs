//! `glClipPlane` / `glGetClipPlane` (GL 1.1 spec §2.11): half-spaces in eye coordinates that
//! clip every primitive. A plane is given in object coordinates and stored transformed by the
//! inverse of the modelview matrix current at the call, so later matrix changes do not move
//! it. The clippers every stage uses are here: [`segment_by`] (Liang–Barsky) and [`polygon_by`]
//! (Sutherland–Hodgman) over any vertex that can be [`Mix`]ed: the renderer's (`render::clip`,
//! `render::soft::clip`) and feedback's (`feedback_prims`).

use super::consts::*;
use super::lists::ListCommand;
use super::matrix::TransformCall;
use super::state_var::{int_limit, StateVar};
use super::types::*;
use super::Gl;
use glam::Vec4;

/// Mesa's `MAX_CLIP_PLANES` on llvmpipe (`glGetIntegerv(GL_MAX_CLIP_PLANES)` answers 8).
pub(crate) const MAX_CLIP_PLANES: usize = 8;

/// The plane index of `GL_CLIP_PLANEi`, if `plane` names one.
pub(crate) fn plane_index(plane: GLenum) -> Option<usize> {
    let i = plane.checked_sub(GL_CLIP_PLANE0)? as usize;
    (i < MAX_CLIP_PLANES).then_some(i)
}

/// A vertex whose attributes are mixed linearly where a plane cuts an edge.
pub(crate) trait Mix: Copy {
    /// The vertex a share `t` of the way to `other`.
    fn mix(self, other: Self, t: f32) -> Self;
}

/// Cuts the segment by each distance function (inside where ≥ 0), both ends at once
/// (Liang–Barsky's parameter interval on [0, 1]).
pub(crate) fn segment_by<V: Mix, F: Fn(&V) -> f32>(
    a: V,
    b: V,
    distances: impl IntoIterator<Item = F>,
) -> Option<(V, V)> {
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for d in distances {
        let (da, db) = (d(&a), d(&b));
        if da < 0.0 && db < 0.0 {
            return None;
        }
        if da < 0.0 {
            t0 = t0.max(da / (da - db));
        } else if db < 0.0 {
            t1 = t1.min(da / (da - db));
        }
    }
    // An end inside every plane stays as it is (Mesa's clipper copies it).
    (t0 <= t1).then(|| (if t0 > 0.0 { a.mix(b, t0) } else { a }, if t1 < 1.0 { a.mix(b, t1) } else { b }))
}

/// One Sutherland–Hodgman step: the vertices inside (`distance` ≥ 0), and a new vertex where
/// an edge crosses.
pub(crate) fn polygon_by<V: Mix>(poly: &[V], distance: impl Fn(&V) -> f32) -> Vec<V> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (k, &c) in poly.iter().enumerate() {
        let next = poly[(k + 1) % poly.len()];
        let (dc, dn) = (distance(&c), distance(&next));
        if dc >= 0.0 {
            out.push(c);
        }
        if (dc >= 0.0) != (dn >= 0.0) {
            out.push(c.mix(next, dc / (dc - dn)));
        }
    }
    out
}

impl Gl {
    /// `glClipPlane(plane, equation)`: `equation` needs 4 values (else `GL_INVALID_VALUE`);
    /// `plane` other than `GL_CLIP_PLANE0..7` → `GL_INVALID_ENUM`; inside `begin`/`end` →
    /// `GL_INVALID_OPERATION`. Stored as (a b c d)·M⁻¹ with M the modelview, in `f32` as Mesa
    /// stores it.
    pub fn clip_plane(&mut self, plane: GLenum, equation: &[GLdouble]) {
        if self.compiled_state_call(|| ListCommand::Transform(TransformCall::ClipPlane(plane, equation.to_vec()))) {
            return;
        }
        let Some(i) = plane_index(plane) else { return self.set_error(GL_INVALID_ENUM) };
        let Some(eq) = equation.get(..4) else { return self.set_error(GL_INVALID_VALUE) };
        let eq = [eq[0], eq[1], eq[2], eq[3]];
        let object = Vec4::from_array(eq.map(|c| c as f32));
        let eye = self.plane_to_eye(object);
        self.server.clip_planes[i] = eye.to_array();
        self.touch_state();
    }

    /// `glGetClipPlane(plane, equation)`: the stored eye-space plane; `equation` needs room
    /// for 4 values (else `GL_INVALID_VALUE`).
    pub fn get_clip_plane(&mut self, plane: GLenum, equation: &mut [GLdouble]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(i) = plane_index(plane) else { return self.set_error(GL_INVALID_ENUM) };
        let Some(out) = equation.get_mut(..4) else { return self.set_error(GL_INVALID_VALUE) };
        for (o, c) in out.iter_mut().zip(self.server.clip_planes[i]) {
            *o = f64::from(c);
        }
    }

    /// The enabled planes, in eye coordinates, in plane order.
    pub(crate) fn enabled_clip_planes(&self) -> Vec<[f32; 4]> {
        (0..MAX_CLIP_PLANES)
            .filter(|&i| self.capability(GL_CLIP_PLANE0 + i as GLenum))
            .map(|i| self.server.clip_planes[i])
            .collect()
    }
}

/// The clip planes' limit (the planes answer through `glGetClipPlane`).
pub(crate) static GET_ROWS: &[StateVar] = &[int_limit!(GL_MAX_CLIP_PLANES, MAX_CLIP_PLANES)];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_plane_is_kept_in_eye_coordinates() {
        let mut gl = Gl::new(4, 4);
        gl.translatef(0.0, 0.0, -5.0);
        // z >= 1 in object coordinates is z >= -4 in eye coordinates.
        gl.clip_plane(GL_CLIP_PLANE2, &[0.0, 0.0, 1.0, -1.0]);
        gl.load_identity();
        let mut eq = [0.0; 4];
        gl.get_clip_plane(GL_CLIP_PLANE2, &mut eq);
        assert_eq!(eq, [0.0, 0.0, 1.0, 4.0]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.clip_plane(GL_CLIP_PLANE0 + 8, &eq);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.get_clip_plane(GL_CLIP_PLANE0, &mut eq[..3]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }
}
