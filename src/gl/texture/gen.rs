//! Texture coordinate generation, `glTexGen` (GL 1.1 spec §2.10.4): s, t, r and q computed per
//! vertex from its object or eye coordinates (`GL_OBJECT_LINEAR`, `GL_EYE_LINEAR`), from the
//! eye-space reflection vector (`GL_SPHERE_MAP`, and `GL_REFLECTION_MAP` of GL 1.3) or from the
//! eye-space normal (`GL_NORMAL_MAP`), replacing the current texture coordinates where
//! `GL_TEXTURE_GEN_S/T/R/Q` is enabled, before the texture matrix.
//!
//! Errors as Mesa sets them (checked against OSMesa): an unknown coordinate, name or mode →
//! `GL_INVALID_ENUM`, sphere mapping only for s and t, the normal and reflection maps not for q;
//! the scalar forms also set a plane (its first value, the rest 0), as Mesa's do.

use super::super::consts::*;
use super::super::lists::ListCommand;
use super::super::types::*;
use super::super::Gl;
use super::TextureCall;
use glam::{Vec3, Vec4, Vec4Swizzles};

/// The generation state of one coordinate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGenCoord {
    /// `GL_TEXTURE_GEN_MODE` (initially `GL_EYE_LINEAR`).
    pub mode: GLenum,
    /// `GL_OBJECT_PLANE`.
    pub object_plane: Vec4,
    /// `GL_EYE_PLANE`, as stored: multiplied by the inverse of the modelview matrix current
    /// when it was given.
    pub eye_plane: Vec4,
}

/// The generation state of s, t, r and q; which of them are enabled is in the enables.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGen {
    /// s, t, r and q.
    pub coords: [TexGenCoord; 4],
}

impl Default for TexGen {
    /// GL's initial planes: s = x, t = y, r = q = 0, for object and eye alike.
    fn default() -> Self {
        let plane = |i: usize| if i < 2 { Vec4::AXES[i] } else { Vec4::ZERO };
        Self {
            coords: std::array::from_fn(|i| TexGenCoord {
                mode: GL_EYE_LINEAR,
                object_plane: plane(i),
                eye_plane: plane(i),
            }),
        }
    }
}

/// What a primitive's vertices generate: the state and which coordinates are on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGenState {
    /// The modes and planes.
    pub gen: TexGen,
    /// `GL_TEXTURE_GEN_S/T/R/Q` enabled.
    pub enabled: [bool; 4],
}

impl TexGenState {
    /// The texture coordinates of a vertex after generation (GL 1.1 §2.10.4): `tex` where a
    /// coordinate is not generated. `object` and `eye` are the vertex's coordinates, `normal`
    /// its eye-space normal (normalised when the program asked GL to).
    #[must_use]
    pub fn apply(&self, tex: Vec4, object: Vec4, eye: Vec4, normal: Vec3) -> Vec4 {
        let mut out = tex.to_array();
        // The sphere and reflection maps share the reflection of the eye direction.
        let u = eye.xyz().normalize_or_zero();
        let r = u - 2.0 * normal * normal.dot(u);
        let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0)).sqrt();
        for (i, coord) in self.gen.coords.iter().enumerate() {
            if !self.enabled[i] {
                continue;
            }
            out[i] = match coord.mode {
                GL_OBJECT_LINEAR => coord.object_plane.dot(object),
                GL_EYE_LINEAR => coord.eye_plane.dot(eye),
                GL_SPHERE_MAP if m != 0.0 => r[i] / m + 0.5,
                GL_SPHERE_MAP => 0.5,
                GL_REFLECTION_MAP => r[i],
                GL_NORMAL_MAP => normal[i],
                _ => out[i],
            };
        }
        Vec4::from_array(out)
    }
}

/// The index of `GL_S`..`GL_Q`.
fn coord_index(coord: GLenum) -> Option<usize> {
    match coord {
        GL_S => Some(0),
        GL_T => Some(1),
        GL_R => Some(2),
        GL_Q => Some(3),
        _ => None,
    }
}

/// Whether `mode` may generate coordinate `index` (Mesa: sphere map for s, t; the normal and
/// reflection maps for s, t, r).
fn mode_allowed(index: usize, mode: GLenum) -> bool {
    match mode {
        GL_OBJECT_LINEAR | GL_EYE_LINEAR => true,
        GL_SPHERE_MAP => index < 2,
        GL_NORMAL_MAP | GL_REFLECTION_MAP => index < 3,
        _ => false,
    }
}

impl Gl {
    /// Values `glTexGen*v` read and `glGetTexGen*v` write for `pname`: 1 for
    /// `GL_TEXTURE_GEN_MODE`, 4 for the planes (and any other name, which is then refused).
    #[must_use]
    pub fn tex_gen_param_count(pname: GLenum) -> usize {
        if pname == GL_TEXTURE_GEN_MODE {
            1
        } else {
            4
        }
    }

    /// `glTexGenfv(coord, pname, params)`: `GL_TEXTURE_GEN_MODE` (the first value) or the
    /// `GL_OBJECT_PLANE` / `GL_EYE_PLANE` coefficients (four values; the eye plane is stored
    /// times the inverse of the current modelview matrix). A short slice → `GL_INVALID_VALUE`.
    pub fn tex_genfv(&mut self, coord: GLenum, pname: GLenum, params: &[GLfloat]) {
        let Some(values) = params.get(..Self::tex_gen_param_count(pname)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        if self.compiled_state_call(|| ListCommand::Texture(TextureCall::TexGen(coord, pname, values.to_vec()))) {
            return;
        }
        let Some(unit) = self.coord_unit() else { return };
        let Some(index) = coord_index(coord) else { return self.set_error(GL_INVALID_ENUM) };
        match pname {
            GL_TEXTURE_GEN_MODE => {
                let mode = values[0] as GLint as GLenum;
                if !mode_allowed(index, mode) {
                    return self.set_error(GL_INVALID_ENUM);
                }
                self.server.tex_gen[unit].coords[index].mode = mode;
            }
            GL_OBJECT_PLANE => self.server.tex_gen[unit].coords[index].object_plane = Vec4::from_slice(values),
            GL_EYE_PLANE => {
                self.server.tex_gen[unit].coords[index].eye_plane = self.plane_to_eye(Vec4::from_slice(values));
            }
            _ => return self.set_error(GL_INVALID_ENUM),
        }
        self.touch_state();
    }

    /// `glTexGenf`: the mode, or (as Mesa takes it) a plane of `(param, 0, 0, 0)`.
    pub fn tex_genf(&mut self, coord: GLenum, pname: GLenum, param: GLfloat) {
        self.tex_genfv(coord, pname, &[param, 0.0, 0.0, 0.0]);
    }

    /// `glTexGeni`: as [`Gl::tex_genf`].
    pub fn tex_geni(&mut self, coord: GLenum, pname: GLenum, param: GLint) {
        self.tex_genfv(coord, pname, &[param as GLfloat, 0.0, 0.0, 0.0]);
    }

    /// `glTexGend`: as [`Gl::tex_genf`].
    pub fn tex_gend(&mut self, coord: GLenum, pname: GLenum, param: GLdouble) {
        self.tex_genfv(coord, pname, &[param as GLfloat, 0.0, 0.0, 0.0]);
    }

    /// `glTexGeniv`: as [`Gl::tex_genfv`] with integers.
    pub fn tex_geniv(&mut self, coord: GLenum, pname: GLenum, params: &[GLint]) {
        let values: Vec<GLfloat> = params.iter().take(4).map(|&v| v as GLfloat).collect();
        self.tex_genfv(coord, pname, &values);
    }

    /// `glTexGendv`: as [`Gl::tex_genfv`] with doubles.
    pub fn tex_gendv(&mut self, coord: GLenum, pname: GLenum, params: &[GLdouble]) {
        let values: Vec<GLfloat> = params.iter().take(4).map(|&v| v as GLfloat).collect();
        self.tex_genfv(coord, pname, &values);
    }

    /// `glGetTexGenfv`: the mode (one value) or a plane (four, the eye plane as stored) into
    /// `params`. A short slice → `GL_INVALID_VALUE`.
    pub fn get_tex_genfv(&mut self, coord: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(unit) = self.coord_unit() else { return };
        let Some(index) = coord_index(coord) else { return self.set_error(GL_INVALID_ENUM) };
        let c = self.server.tex_gen[unit].coords[index];
        let values = match pname {
            GL_TEXTURE_GEN_MODE => vec![c.mode as GLfloat],
            GL_OBJECT_PLANE => c.object_plane.to_array().to_vec(),
            GL_EYE_PLANE => c.eye_plane.to_array().to_vec(),
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        match params.get_mut(..values.len()) {
            Some(out) => out.copy_from_slice(&values),
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// `glGetTexGeniv`: as [`Gl::get_tex_genfv`], truncated to integers as C casts (Mesa
    /// `_mesa_GetTexGeniv`; measured: 3.75 → 3, 10¹⁰ → `INT_MIN`).
    pub fn get_tex_geniv(&mut self, coord: GLenum, pname: GLenum, params: &mut [GLint]) {
        let mut values = [0.0; 4];
        let error = self.error;
        self.error = GL_NO_ERROR;
        self.get_tex_genfv(coord, pname, &mut values);
        let failed = self.error != GL_NO_ERROR;
        if error != GL_NO_ERROR {
            self.error = error;
        }
        if failed {
            return;
        }
        let count = Self::tex_gen_param_count(pname);
        match params.get_mut(..count) {
            Some(out) => out.iter_mut().zip(values).for_each(|(o, v)| *o = super::super::state_var::c_int(v)),
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// `glGetTexGendv`: as [`Gl::get_tex_genfv`], widened to doubles.
    pub fn get_tex_gendv(&mut self, coord: GLenum, pname: GLenum, params: &mut [GLdouble]) {
        let mut values = [0.0f32; 4];
        let count = Self::tex_gen_param_count(pname);
        if params.len() < count {
            // Checked after the other arguments, as the float form checks it.
            self.get_tex_genfv(coord, pname, &mut values[..params.len().min(count)]);
            return;
        }
        let before = std::mem::replace(&mut self.error, GL_NO_ERROR);
        self.get_tex_genfv(coord, pname, &mut values);
        let failed = self.error != GL_NO_ERROR;
        if before != GL_NO_ERROR {
            self.error = before;
        }
        if !failed {
            params.iter_mut().zip(&values[..count]).for_each(|(o, v)| *o = f64::from(*v));
        }
    }

    /// What unit `unit` generates for the next primitive, if any of its coordinates is enabled.
    pub(crate) fn tex_gen_state_of(&self, unit: usize) -> Option<TexGenState> {
        let caps = [GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q];
        let enabled = caps.map(|cap| self.server.caps.is_on(super::super::units::unit_cap(cap, unit)));
        enabled.contains(&true).then_some(TexGenState { gen: self.server.tex_gen[unit], enabled })
    }

    /// The active unit when it has texture coordinates (GL 1.3 §2.7: the fixed-function units);
    /// beyond them → `GL_INVALID_OPERATION`, as Mesa's `glTexGen`, `glGetTexGen` and the
    /// coordinate queries answer (measured, `multitexture.calls`).
    pub(crate) fn coord_unit(&mut self) -> Option<usize> {
        let unit = self.active_unit();
        if unit >= super::MAX_TEXTURE_UNITS {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        Some(unit)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_and_values_as_mesa() {
        // Each line's expected error and values were printed by the same calls on OSMesa
        // (Mesa 22.3).
        let mut gl = Gl::new(8, 8);
        gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        for (coord, mode) in [
            (GL_R, GL_SPHERE_MAP),
            (GL_Q, GL_SPHERE_MAP),
            (GL_Q, GL_NORMAL_MAP),
            (GL_Q, GL_REFLECTION_MAP),
            (GL_T, GL_LINEAR),
            (0x1234, GL_OBJECT_LINEAR),
        ] {
            gl.tex_geni(coord, GL_TEXTURE_GEN_MODE, mode as i32);
            assert_eq!(gl.get_error(), GL_INVALID_ENUM, "{coord:#x} {mode:#x}");
        }
        gl.tex_geni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP as i32);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.tex_geni(GL_S, GL_OBJECT_PLANE, 3);
        let mut q = [0.0; 4];
        gl.get_tex_genfv(GL_S, GL_OBJECT_PLANE, &mut q);
        assert_eq!(q, [3.0, 0.0, 0.0, 0.0]);
        gl.tex_geni(GL_S, GL_TEXTURE_ENV_MODE, GL_OBJECT_LINEAR as i32);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.translatef(1.0, 0.0, 0.0);
        gl.scalef(2.0, 2.0, 2.0);
        gl.tex_genfv(GL_T, GL_EYE_PLANE, &[1.0, 2.0, 3.0, 4.0]);
        gl.get_tex_genfv(GL_T, GL_EYE_PLANE, &mut q);
        assert_eq!(q, [0.5, 1.0, 1.5, 3.5]);
        gl.get_tex_genfv(GL_T, GL_OBJECT_PLANE, &mut q);
        assert_eq!(q, [0.0, 1.0, 0.0, 0.0]);
        gl.get_tex_genfv(GL_R, GL_OBJECT_PLANE, &mut q);
        assert_eq!(q, [0.0; 4]);
        let mut m = [0];
        gl.get_tex_geniv(GL_Q, GL_TEXTURE_GEN_MODE, &mut m);
        assert_eq!(m, [GL_EYE_LINEAR as i32]);
        gl.get_tex_geniv(GL_Q, GL_TEXTURE_ENV_MODE, &mut m);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.get_tex_geniv(7, GL_TEXTURE_GEN_MODE, &mut m);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.begin(GL_POINTS);
        gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.tex_genf(GL_S, GL_TEXTURE_GEN_MODE, 9217.5);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.tex_geniv(GL_S, GL_OBJECT_PLANE, &[GL_OBJECT_LINEAR as i32, 5, 6, 7]);
        gl.get_tex_genfv(GL_S, GL_OBJECT_PLANE, &mut q);
        assert_eq!(q, [9217.0, 5.0, 6.0, 7.0]);
        gl.tex_genfv(GL_S, GL_OBJECT_PLANE, &[1.0, 2.0]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn texture_bit_saves_modes_and_enables_enable_bit_only_enables() {
        // OSMesa: after GL_TEXTURE_BIT's pop the mode (OBJECT_LINEAR) and enable come back;
        // after GL_ENABLE_BIT's only the enable.
        let mut gl = Gl::new(8, 8);
        gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as i32);
        gl.enable(GL_TEXTURE_GEN_S);
        gl.push_attrib(GL_TEXTURE_BIT);
        gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        gl.disable(GL_TEXTURE_GEN_S);
        gl.pop_attrib();
        let mut m = [0];
        gl.get_tex_geniv(GL_S, GL_TEXTURE_GEN_MODE, &mut m);
        assert_eq!((m[0] as GLenum, gl.is_enabled(GL_TEXTURE_GEN_S)), (GL_OBJECT_LINEAR, GL_TRUE));
        gl.push_attrib(GL_ENABLE_BIT);
        gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP as i32);
        gl.disable(GL_TEXTURE_GEN_S);
        gl.pop_attrib();
        gl.get_tex_geniv(GL_S, GL_TEXTURE_GEN_MODE, &mut m);
        assert_eq!((m[0] as GLenum, gl.is_enabled(GL_TEXTURE_GEN_S)), (GL_SPHERE_MAP, GL_TRUE));
    }

    #[test]
    fn generation_follows_the_spec_formulas() {
        let mut gen = TexGen::default();
        gen.coords[0] =
            TexGenCoord { mode: GL_OBJECT_LINEAR, object_plane: Vec4::new(1.0, 2.0, 0.0, 1.0), ..gen.coords[0] };
        gen.coords[1] = TexGenCoord { mode: GL_EYE_LINEAR, eye_plane: Vec4::new(0.0, 0.0, -1.0, 0.0), ..gen.coords[1] };
        let state = TexGenState { gen, enabled: [true, true, false, false] };
        let tex = Vec4::new(9.0, 9.0, 7.0, 1.0);
        let out = state.apply(tex, Vec4::new(2.0, 3.0, 4.0, 1.0), Vec4::new(0.0, 0.0, -5.0, 1.0), Vec3::Z);
        // s = 2 + 6 + 1, t = 5, r and q pass through.
        assert_eq!(out, Vec4::new(9.0, 5.0, 7.0, 1.0));
        // Sphere map, looking straight down -z at a surface facing the eye: r = (0, 0, 1),
        // m = 4, (s, t) = (0.5, 0.5); facing 45° to the right, r = (1, 0, 0): s = 1/(2√2)+0.5.
        gen.coords[0].mode = GL_SPHERE_MAP;
        gen.coords[1].mode = GL_SPHERE_MAP;
        let state = TexGenState { gen, enabled: [true, true, false, false] };
        let eye = Vec4::new(0.0, 0.0, -5.0, 1.0);
        assert_eq!(state.apply(tex, Vec4::ZERO, eye, Vec3::Z).xy(), glam::Vec2::new(0.5, 0.5));
        let n = Vec3::new(1.0, 0.0, 1.0).normalize();
        let s = state.apply(tex, Vec4::ZERO, eye, n).x;
        assert!((s - (0.5 + 1.0 / (2.0 * 2f32.sqrt()))).abs() < 1e-6, "{s}");
    }
}
