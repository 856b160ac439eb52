//! `glGetLightfv/iv` and `glGetMaterialfv/iv` (GL 1.1 spec §6.1.3; Mesa `main/light.c`), and
//! the integer and scalar forms of `glLight`, `glLightModel` and `glMaterial`, which convert
//! and call the float vector forms as Mesa's do (so lists, errors and state are theirs).

use super::super::consts::*;
use super::super::state_var::{c_int, float_to_int};
use super::super::types::*;
use super::super::variants::GlComponent;
use super::super::Gl;
use super::{Light, Material};

/// Whether a light or material name is a colour (normalised in the integer forms).
fn is_color(pname: GLenum) -> bool {
    matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE)
}

/// Up to four integers as `glLightiv`/`glMaterialiv` hand them on: colours through Mesa's
/// `INT_TO_FLOAT`, the rest as they are.
fn int_params(color: bool, params: &[GLint]) -> Vec<GLfloat> {
    params.iter().take(4).map(|&p| if color { p.normalized() } else { p as GLfloat }).collect()
}

/// A light's value of `pname`, `None` for a name lights do not have.
fn light_value(l: &Light, pname: GLenum) -> Option<Vec<f32>> {
    Some(match pname {
        GL_AMBIENT => l.ambient.to_array().to_vec(),
        GL_DIFFUSE => l.diffuse.to_array().to_vec(),
        GL_SPECULAR => l.specular.to_array().to_vec(),
        GL_POSITION => l.position.to_array().to_vec(),
        GL_SPOT_DIRECTION => l.spot_direction.to_array().to_vec(),
        GL_SPOT_EXPONENT => vec![l.spot_exponent],
        GL_SPOT_CUTOFF => vec![l.spot_cutoff],
        GL_CONSTANT_ATTENUATION => vec![l.attenuation.x],
        GL_LINEAR_ATTENUATION => vec![l.attenuation.y],
        GL_QUADRATIC_ATTENUATION => vec![l.attenuation.z],
        _ => return None,
    })
}

/// A material's value of `pname`, `None` for a name `glGetMaterial` does not take.
fn material_value(m: &Material, pname: GLenum) -> Option<Vec<f32>> {
    Some(match pname {
        GL_AMBIENT => m.ambient.to_array().to_vec(),
        GL_DIFFUSE => m.diffuse.to_array().to_vec(),
        GL_SPECULAR => m.specular.to_array().to_vec(),
        GL_EMISSION => m.emission.to_array().to_vec(),
        GL_SHININESS => vec![m.shininess],
        _ => return None,
    })
}

impl Gl {
    /// `glLighti`: as [`Gl::light_f`].
    pub fn light_i(&mut self, light: GLenum, pname: GLenum, param: GLint) {
        self.light_iv(light, pname, &[param, 0, 0, 0]);
    }

    /// `glLightiv`: colours are normalised (c · 2 + 1) / (2³² − 1), positions, directions and
    /// the scalars converted as they are (Mesa `_mesa_Lightiv`); then [`Gl::light_fv`].
    pub fn light_iv(&mut self, light: GLenum, pname: GLenum, params: &[GLint]) {
        let values = int_params(is_color(pname), params);
        self.light_fv(light, pname, &values);
    }

    /// `glLightModelf`: as [`Gl::light_model_fv`] with (param, 0, 0, 0).
    pub fn light_model_f(&mut self, pname: GLenum, param: GLfloat) {
        self.light_model_fv(pname, &[param, 0.0, 0.0, 0.0]);
    }

    /// `glLightModeliv`: the ambient colour normalised, the flags as they are.
    pub fn light_model_iv(&mut self, pname: GLenum, params: &[GLint]) {
        let values = int_params(pname == GL_LIGHT_MODEL_AMBIENT, params);
        self.light_model_fv(pname, &values);
    }

    /// `glMateriali`: as [`Gl::material_iv`] with (param, 0, 0, 0).
    pub fn material_i(&mut self, face: GLenum, pname: GLenum, param: GLint) {
        self.material_iv(face, pname, &[param, 0, 0, 0]);
    }

    /// `glMaterialiv`: colours normalised, the shininess as it is (Mesa `_mesa_Materialiv`).
    pub fn material_iv(&mut self, face: GLenum, pname: GLenum, params: &[GLint]) {
        let values = int_params(is_color(pname), params);
        self.material_fv(face, pname, &values);
    }

    /// `glGetLightfv`: 4 values for the colours and the position (eye coordinates), 3 for the
    /// spot direction, else 1. A light other than `GL_LIGHT0..7` or an unknown name →
    /// `GL_INVALID_ENUM`; inside `begin`/`end` → `GL_INVALID_OPERATION`; a short slice →
    /// `GL_INVALID_VALUE`.
    pub fn get_light_fv(&mut self, light: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        if let Some(v) = self.light_answer(light, pname, params.len()) {
            params[..v.len()].copy_from_slice(&v);
        }
    }

    /// `glGetLightiv`: colours as `glGetIntegerv` scales them, the rest truncated (Mesa).
    pub fn get_light_iv(&mut self, light: GLenum, pname: GLenum, params: &mut [GLint]) {
        if let Some(v) = self.light_answer(light, pname, params.len()) {
            let color = is_color(pname);
            for (out, x) in params.iter_mut().zip(v) {
                *out = if color { float_to_int(x.into()) } else { c_int(x) };
            }
        }
    }

    fn light_answer(&mut self, light: GLenum, pname: GLenum, room: usize) -> Option<Vec<f32>> {
        if self.reject_inside_begin_end() {
            return None;
        }
        let index = light.checked_sub(GL_LIGHT0).filter(|i| *i < 8);
        let Some(v) = index.and_then(|i| light_value(&self.server.lighting.lights[i as usize], pname)) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        self.room_for(v, room)
    }

    /// `glGetMaterialfv`: `face` `GL_FRONT` or `GL_BACK` (not both); 4 values for the colours,
    /// 1 for the shininess. Errors as [`Gl::get_light_fv`]. Waiting `glMaterial` calls land first
    /// (Mesa flushes here).
    pub fn get_material_fv(&mut self, face: GLenum, pname: GLenum, params: &mut [GLfloat]) {
        if let Some(v) = self.material_answer(face, pname, params.len()) {
            params[..v.len()].copy_from_slice(&v);
        }
    }

    /// `glGetMaterialiv`: colours scaled as `glGetIntegerv` does, the shininess rounded.
    pub fn get_material_iv(&mut self, face: GLenum, pname: GLenum, params: &mut [GLint]) {
        if let Some(v) = self.material_answer(face, pname, params.len()) {
            let color = is_color(pname);
            for (out, x) in params.iter_mut().zip(v) {
                *out = if color { float_to_int(x.into()) } else { super::super::state_var::iround(x.into()) };
            }
        }
    }

    fn material_answer(&mut self, face: GLenum, pname: GLenum, room: usize) -> Option<Vec<f32>> {
        if self.reject_inside_begin_end() {
            return None;
        }
        let f = match face {
            GL_FRONT => 0,
            GL_BACK => 1,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        self.flush_current();
        let Some(v) = material_value(&self.server.lighting.materials[f], pname) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        self.room_for(v, room)
    }

    /// `values` if a slice of `room` holds them, else `GL_INVALID_VALUE`.
    pub(crate) fn room_for<T>(&mut self, values: Vec<T>, room: usize) -> Option<Vec<T>> {
        if room < values.len() {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        Some(values)
    }
}
