//! Texture parameters and the texture environment (GL 1.1 spec §3.8.3, §3.8.9; Mesa
//! `main/texparam.c`, `main/texenv.c`): `glTexParameter*` of the bound object, `glTexEnv*` of
//! unit 0.

use super::combine::is_combine_name;
use super::TextureCall;
use super::{target_index, DepthParams};
use crate::gl::consts::*;
use crate::gl::lists::ListCommand;
use crate::gl::types::*;
use crate::gl::Gl;

impl Gl {
    /// `glTexParameteri` for `GL_TEXTURE_MIN_FILTER`, `GL_TEXTURE_MAG_FILTER`,
    /// `GL_TEXTURE_WRAP_S`, `GL_TEXTURE_WRAP_T` and `GL_TEXTURE_WRAP_R` (`GL_REPEAT`,
    /// `GL_CLAMP`, GL 1.2's `GL_CLAMP_TO_EDGE`, 1.3's `GL_CLAMP_TO_BORDER`, 1.4's
    /// `GL_MIRRORED_REPEAT`), and GL 1.2's
    /// `GL_TEXTURE_BASE_LEVEL` and `GL_TEXTURE_MAX_LEVEL`, and GL 1.4's
    /// `GL_DEPTH_TEXTURE_MODE`, `GL_TEXTURE_COMPARE_MODE` and `GL_TEXTURE_COMPARE_FUNC`
    /// ([`DepthParams`]), of the bound object. Another target or
    /// name, or a value the name does not take → `GL_INVALID_ENUM`; a negative level →
    /// `GL_INVALID_VALUE`.
    pub fn tex_parameteri(&mut self, target: GLenum, pname: GLenum, param: GLint) {
        if matches!(pname, GL_TEXTURE_PRIORITY | GL_TEXTURE_MIN_LOD | GL_TEXTURE_MAX_LOD | GL_TEXTURE_LOD_BIAS) {
            // A float parameter: Mesa converts the integer as it is.
            return self.tex_parameterfv(target, pname, &[param as GLfloat]);
        }
        if pname == GL_TEXTURE_BORDER_COLOR && self.compiling_list() {
            // Mesa's display lists keep a scalar call as its vector form, (param, 0, 0, 0),
            // which then sets the colour where the call itself is an error (`save_TexParameteri`;
            // piglit's gl-1.0-beginend-coverage compiles one).
            return self.tex_parameteriv(target, pname, &[param, 0, 0, 0]);
        }
        if self.compiled_state_call(|| ListCommand::Texture(TextureCall::TexParameter(target, pname, param))) {
            return;
        }
        let Some(t) = target_index(target) else { return self.set_error(GL_INVALID_ENUM) };
        let value = param as GLenum;
        let mipmap_filters = GL_NEAREST_MIPMAP_NEAREST..=GL_LINEAR_MIPMAP_LINEAR;
        let ok = match pname {
            GL_TEXTURE_MIN_FILTER => value == GL_NEAREST || value == GL_LINEAR || mipmap_filters.contains(&value),
            GL_TEXTURE_MAG_FILTER => value == GL_NEAREST || value == GL_LINEAR,
            GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R => {
                matches!(value, GL_REPEAT | GL_CLAMP | GL_CLAMP_TO_EDGE | GL_CLAMP_TO_BORDER | GL_MIRRORED_REPEAT)
            }
            GL_TEXTURE_BASE_LEVEL | GL_TEXTURE_MAX_LEVEL | GL_GENERATE_MIPMAP => true,
            _ => DepthParams::accepts(pname, value).unwrap_or(false),
        };
        if !ok || (t == super::RECT && !super::rectangle::takes(pname, value)) {
            return self.set_error(GL_INVALID_ENUM);
        }
        if t == super::RECT && pname == GL_TEXTURE_BASE_LEVEL && param != 0 {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if matches!(pname, GL_TEXTURE_BASE_LEVEL | GL_TEXTURE_MAX_LEVEL) {
            return self.set_level_range(t, pname, param);
        }
        let object = self.bound_object_mut(t);
        let mut params = object.params;
        if DepthParams::accepts(pname, value).is_some() {
            *params.depth.field(pname) = value;
            object.set_params(params);
            return self.touch_state();
        }
        if pname == GL_GENERATE_MIPMAP {
            // Any value: GL_TRUE unless 0 (measured on Mesa: 7 reads back as 1).
            params.generate_mipmap = param != 0;
            object.set_params(params);
            return self.touch_state();
        }
        let field = match pname {
            GL_TEXTURE_MIN_FILTER => &mut params.min_filter,
            GL_TEXTURE_MAG_FILTER => &mut params.mag_filter,
            GL_TEXTURE_WRAP_S => &mut params.wrap_s,
            GL_TEXTURE_WRAP_T => &mut params.wrap_t,
            _ => &mut params.wrap_r,
        };
        *field = value;
        object.set_params(params);
        self.touch_state();
    }

    /// `GL_TEXTURE_BASE_LEVEL` or `GL_TEXTURE_MAX_LEVEL` of target `t`'s bound object.
    fn set_level_range(&mut self, t: usize, pname: GLenum, level: GLint) {
        if level < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let object = self.bound_object_mut(t);
        let mut params = object.params;
        if pname == GL_TEXTURE_BASE_LEVEL {
            params.base_level = level;
        } else {
            params.max_level = level;
        }
        object.set_params(params);
        self.touch_state();
    }

    /// `glTexParameterf`: as [`Gl::tex_parameterfv`] with one value (an enum passed as a float is
    /// truncated); the border colour, a vector, is `GL_INVALID_ENUM` here, as in Mesa.
    pub fn tex_parameterf(&mut self, target: GLenum, pname: GLenum, param: GLfloat) {
        if pname == GL_TEXTURE_BORDER_COLOR && self.compiling_list() {
            // As `tex_parameteri` (Mesa's `save_TexParameterf`).
            return self.tex_parameterfv(target, pname, &[param, 0.0, 0.0, 0.0]);
        }
        if pname == GL_TEXTURE_BORDER_COLOR {
            // Mesa: a vector name in a scalar call.
            return self.tex_parameteri(target, pname, 0);
        }
        self.tex_parameterfv(target, pname, &[param]);
    }

    /// `glTexEnvi` for `GL_TEXTURE_ENV_MODE`: `GL_MODULATE` (initial), `GL_DECAL`, `GL_BLEND`,
    /// `GL_REPLACE`, `GL_ADD` or GL 1.3's `GL_COMBINE`, and the combiner's names
    /// ([`super::Combine`]). Another target, name or mode → `GL_INVALID_ENUM`.
    pub fn tex_envi(&mut self, target: GLenum, pname: GLenum, param: GLint) {
        if target == GL_TEXTURE_FILTER_CONTROL || target == GL_POINT_SPRITE {
            return self.tex_envfv(target, pname, &[param as GLfloat]);
        }
        if self.compiled_state_call(|| ListCommand::Texture(TextureCall::TexEnv(target, pname, vec![param as f32]))) {
            return;
        }
        if target == GL_TEXTURE_ENV && is_combine_name(pname) {
            return self.set_combine(pname, param as GLfloat);
        }
        let mode = param as GLenum;
        let known = matches!(mode, GL_MODULATE | GL_DECAL | GL_BLEND | GL_REPLACE | GL_ADD | GL_COMBINE);
        if target != GL_TEXTURE_ENV || pname != GL_TEXTURE_ENV_MODE || !known {
            return self.set_error(GL_INVALID_ENUM);
        }
        if let Some(env) = self.active_env_mut() {
            env.mode = mode;
        }
        self.touch_state();
    }

    /// `glTexEnvf`: as [`Gl::tex_envi`] (a combiner scale as the float it is).
    pub fn tex_envf(&mut self, target: GLenum, pname: GLenum, param: GLfloat) {
        if is_combine_name(pname) || target == GL_TEXTURE_FILTER_CONTROL {
            return self.tex_envfv(target, pname, &[param]);
        }
        self.tex_envi(target, pname, param as GLint);
    }

    /// A combiner name set, as Mesa checks it ([`super::Combine`]).
    fn set_combine(&mut self, pname: GLenum, value: GLfloat) {
        let Some(env) = self.active_env_mut() else { return };
        match env.combine.set(pname, value) {
            Ok(()) => self.touch_state(),
            Err(error) => self.set_error(error),
        }
    }

    /// `glTexEnvfv`: `GL_TEXTURE_ENV_COLOR` (4 values, clamped to [0, 1]) or
    /// `GL_TEXTURE_ENV_MODE` (the first value) of `GL_TEXTURE_ENV`, or GL 1.4's
    /// `GL_TEXTURE_LOD_BIAS` of `GL_TEXTURE_FILTER_CONTROL` (kept as given; sampling clamps
    /// the sum with the object's). A short slice → `GL_INVALID_VALUE`.
    pub fn tex_envfv(&mut self, target: GLenum, pname: GLenum, params: &[GLfloat]) {
        if pname == GL_TEXTURE_ENV_MODE && target == GL_TEXTURE_ENV {
            let Some(&mode) = params.first() else { return self.set_error(GL_INVALID_VALUE) };
            return self.tex_envi(target, pname, mode as GLint);
        }
        if self.compiled_state_call(|| ListCommand::Texture(TextureCall::TexEnv(target, pname, params.to_vec()))) {
            return;
        }
        if target == GL_TEXTURE_ENV && is_combine_name(pname) {
            let Some(&value) = params.first() else { return self.set_error(GL_INVALID_VALUE) };
            return self.set_combine(pname, value);
        }
        if target == GL_POINT_SPRITE && pname == GL_COORD_REPLACE {
            let Some(&value) = params.first() else { return self.set_error(GL_INVALID_VALUE) };
            return self.set_coord_replace(value);
        }
        if target == GL_TEXTURE_FILTER_CONTROL && pname == GL_TEXTURE_LOD_BIAS {
            let Some(&bias) = params.first() else { return self.set_error(GL_INVALID_VALUE) };
            if let Some(env) = self.active_env_mut() {
                env.lod_bias = bias;
            }
            return self.touch_state();
        }
        if target != GL_TEXTURE_ENV || pname != GL_TEXTURE_ENV_COLOR {
            return self.set_error(GL_INVALID_ENUM);
        }
        let Some(color) = self.needs::<4>(params) else { return };
        if let Some(env) = self.active_env_mut() {
            env.color = color.map(|c| c.clamp(0.0, 1.0));
        }
        self.touch_state();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `glPopAttrib(GL_TEXTURE_BIT)` leaves the unit's LOD bias 0 and restores the object's, as
    /// Mesa 22.3 does in a plain program (1.5 set, pushed, 9 set, popped: 0; the object's 2,
    /// pushed, 5, popped: 2).
    #[test]
    fn texture_bit_pop_zeroes_the_units_lod_bias() {
        let mut gl = Gl::new(4, 4);
        gl.tex_envf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5);
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 2.0);
        gl.push_attrib(GL_TEXTURE_BIT);
        gl.tex_envf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 9.0);
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 5.0);
        gl.pop_attrib();
        let (mut unit, mut object) = ([-1.0], [-1.0]);
        gl.get_tex_envfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &mut unit);
        gl.get_tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, &mut object);
        assert_eq!((unit, object, gl.get_error()), ([0.0], [2.0], GL_NO_ERROR));
    }
}
