//! GL 1.3's texture units on the client side (ARB_multitexture; GL 1.3 spec §2.7, §2.8): each
//! unit's current texture coordinates (`glMultiTexCoord*`) and the unit whose texture
//! coordinate array the array calls name (`glClientActiveTexture`). The server side (the
//! active unit, its bindings, enables, environment, generation and matrix) lives with each of
//! those areas; `texture.rs` has `glActiveTexture`.
//!
//! Mesa's checks, measured on Mesa 22.3 (`multitexture.calls`): `glMultiTexCoord` takes any
//! target and uses its low three bits as the unit (`vbo_attrib_tmp.h`: `(target & 0x7)`), so
//! `GL_TEXTURE8` sets unit 0's and no call raises an error, in a list too;
//! `glClientActiveTexture` of a unit at or beyond [`MAX_TEXTURE_UNITS`] is
//! `GL_INVALID_ENUM`, and it is client state, never compiled.

use super::consts::*;
use super::frame::Call;
use super::lists::ListCommand;
use super::state_var::{put_enum, row, Kind, StateVar};
use super::types::*;
use super::units::MAX_TEXTURE_UNITS;
use super::variants::GlComponent;
use super::Gl;

impl Gl {
    /// `glClientActiveTexture`: the unit whose texture coordinate array `glTexCoordPointer`,
    /// `glEnableClientState(GL_TEXTURE_COORD_ARRAY)` and their queries name (GL 1.3 §2.8). Not
    /// compiled into lists (client state). A unit beyond [`MAX_TEXTURE_UNITS`] →
    /// `GL_INVALID_ENUM`.
    pub fn client_active_texture(&mut self, texture: GLenum) {
        let Some(unit) = texture.checked_sub(GL_TEXTURE0).filter(|&u| (u as usize) < MAX_TEXTURE_UNITS) else {
            return self.set_error(GL_INVALID_ENUM);
        };
        self.client.arrays.set_client_unit(unit as usize);
    }

    /// `glMultiTexCoord4f`: unit `target & 7`'s current texture coordinates (Mesa's reading of
    /// the target, which raises no error).
    pub fn multi_tex_coord4f(&mut self, target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) {
        let unit = (target & 7) as usize;
        if unit == 0 {
            return self.tex_coord4f(s, t, r, q);
        }
        let call = Call::MultiTexCoord(unit as u8, [s, t, r, q]);
        if self.compiled(|| ListCommand::Immediate(call)) {
            return;
        }
        self.server.current.unit_tex_coords[unit - 1] = [s, t, r, q];
        self.recorder.frame.calls.push(call);
    }

    /// `glMultiTexCoord1f` (t = r = 0, q = 1).
    pub fn multi_tex_coord1f(&mut self, target: GLenum, s: GLfloat) {
        self.multi_tex_coord4f(target, s, 0.0, 0.0, 1.0);
    }

    /// `glMultiTexCoord2f` (r = 0, q = 1).
    pub fn multi_tex_coord2f(&mut self, target: GLenum, s: GLfloat, t: GLfloat) {
        self.multi_tex_coord4f(target, s, t, 0.0, 1.0);
    }

    /// `glMultiTexCoord3f` (q = 1).
    pub fn multi_tex_coord3f(&mut self, target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat) {
        self.multi_tex_coord4f(target, s, t, r, 1.0);
    }

    /// `glMultiTexCoord*` of any type and size: each value converted as it is (GL 1.1 §2.7).
    fn multi_tex_coord_n<T: GlComponent, const N: usize>(&mut self, target: GLenum, v: [T; N]) {
        let f = v.map(GlComponent::plain);
        match N {
            1 => self.multi_tex_coord1f(target, f[0]),
            2 => self.multi_tex_coord2f(target, f[0], f[1]),
            3 => self.multi_tex_coord3f(target, f[0], f[1], f[2]),
            _ => self.multi_tex_coord4f(target, f[0], f[1], f[2], f[3]),
        }
    }
}

/// Scalar forms: `name(target, a, …)` → `multi_tex_coord_n(target, [a, …])`.
macro_rules! scalar_forms {
    ($($name:ident($t:ty; $($arg:ident),+));+ $(;)?) => {
        impl Gl {
            $(
                #[doc = concat!("`gl", stringify!($name), "`: each value converted as it is.")]
                pub fn $name(&mut self, target: GLenum, $($arg: $t),+) {
                    self.multi_tex_coord_n(target, [$($arg),+]);
                }
            )+
        }
    };
}

/// Vector forms: `name(target, &[T])` reading `N` values (a shorter slice →
/// `GL_INVALID_VALUE`).
macro_rules! vector_forms {
    ($($name:ident($t:ty; $n:literal));+ $(;)?) => {
        impl Gl {
            $(
                #[doc = concat!("`gl", stringify!($name), "`: `v` needs ", stringify!($n), " values.")]
                pub fn $name(&mut self, target: GLenum, v: &[$t]) {
                    if let Some(v) = self.first::<$n, $t>(v) {
                        self.multi_tex_coord_n(target, v);
                    }
                }
            )+
        }
    };
}

scalar_forms!(
    multi_tex_coord1s(GLshort; s); multi_tex_coord1i(GLint; s); multi_tex_coord1d(GLdouble; s);
    multi_tex_coord2s(GLshort; s, t); multi_tex_coord2i(GLint; s, t); multi_tex_coord2d(GLdouble; s, t);
    multi_tex_coord3s(GLshort; s, t, r); multi_tex_coord3i(GLint; s, t, r); multi_tex_coord3d(GLdouble; s, t, r);
    multi_tex_coord4s(GLshort; s, t, r, q); multi_tex_coord4i(GLint; s, t, r, q);
    multi_tex_coord4d(GLdouble; s, t, r, q));
vector_forms!(
    multi_tex_coord1sv(GLshort; 1); multi_tex_coord1iv(GLint; 1); multi_tex_coord1fv(GLfloat; 1);
    multi_tex_coord1dv(GLdouble; 1);
    multi_tex_coord2sv(GLshort; 2); multi_tex_coord2iv(GLint; 2); multi_tex_coord2fv(GLfloat; 2);
    multi_tex_coord2dv(GLdouble; 2);
    multi_tex_coord3sv(GLshort; 3); multi_tex_coord3iv(GLint; 3); multi_tex_coord3fv(GLfloat; 3);
    multi_tex_coord3dv(GLdouble; 3);
    multi_tex_coord4sv(GLshort; 4); multi_tex_coord4iv(GLint; 4); multi_tex_coord4fv(GLfloat; 4);
    multi_tex_coord4dv(GLdouble; 4));

/// The names whose answer is the active unit's texture coordinate state: beyond the
/// fixed-function units they are `GL_INVALID_OPERATION` (Mesa's `EXTRA_VALID_TEXTURE_UNIT`
/// reading, measured).
pub(crate) const UNIT_COORD_NAMES: &[GLenum] =
    &[GL_CURRENT_TEXTURE_COORDS, GL_CURRENT_RASTER_TEXTURE_COORDS, GL_TEXTURE_MATRIX, GL_TEXTURE_STACK_DEPTH];

/// The client active unit's `glGet` row.
pub(crate) static GET_ROWS: &[StateVar] = &[row(GL_CLIENT_ACTIVE_TEXTURE, 1, Kind::Int, |gl, o| {
    put_enum(o, GL_TEXTURE0 + gl.client.arrays.client_unit() as GLenum)
})];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_unit_has_its_coordinates_and_the_target_is_read_as_mesa_reads_it() {
        let mut gl = Gl::new(4, 4);
        gl.multi_tex_coord2f(GL_TEXTURE1, 0.5, 0.25);
        gl.multi_tex_coord4f(GL_TEXTURE8, 1.0, 2.0, 3.0, 4.0);
        gl.multi_tex_coord3i(0x1234, 5, 6, 7);
        let coords = |gl: &mut Gl, unit| {
            gl.active_texture(GL_TEXTURE0 + unit);
            let mut v = [0.0; 4];
            gl.get_floatv(GL_CURRENT_TEXTURE_COORDS, &mut v);
            v
        };
        assert_eq!(coords(&mut gl, 0), [1.0, 2.0, 3.0, 4.0]);
        assert_eq!(coords(&mut gl, 1), [0.5, 0.25, 0.0, 1.0]);
        assert_eq!(coords(&mut gl, 4), [5.0, 6.0, 7.0, 1.0]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        // No unit beyond the fixed-function ones (gleval has no shader image units).
        gl.active_texture(GL_TEXTURE8);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.client_active_texture(GL_TEXTURE8);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    }
}
