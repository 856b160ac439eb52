//! The point attribute group (GL 1.1 spec §3.3, GL 1.4 §3.3 and table 6.12; Mesa
//! `main/points.c`): `glPointSize` and GL 1.4's `glPointParameter` (`GL_ARB_point_parameters`),
//! in one struct as `GL_POINT_BIT` saves it with `GL_POINT_SMOOTH`, their list records, the
//! group's `glGet` rows. The pattern of `depth.rs`.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{limit, put, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// `GL_POINT_BIT`'s state (its enable aside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Point {
    /// `glPointSize`: the diameter, in pixels, of a rasterised point.
    pub size: f32,
    /// GL 1.4's `glPointParameter` values.
    pub parameters: PointParameters,
    /// `GL_ARB_point_sprite`'s `GL_COORD_REPLACE` of each texture unit, a bit a unit (unit 0
    /// the lowest): Mesa keeps it in the point group (`gl_point_attrib`'s `CoordReplace`).
    pub coord_replace: u8,
}

/// GL 1.4's point parameters (§3.3): the size a point is drawn with is `glPointSize`'s,
/// divided by the square root of the distance attenuation `a + b·d + c·d²` (d the eye's
/// distance, taken as `|z_eye|` as Mesa's fixed-function vertex program takes it), then
/// clamped to `[min_size, max_size]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointParameters {
    /// `GL_POINT_SIZE_MIN`: 0 initially.
    pub min_size: f32,
    /// `GL_POINT_SIZE_MAX`: initially the largest size (Mesa's llvmpipe: 255).
    pub max_size: f32,
    /// `GL_POINT_FADE_THRESHOLD_SIZE`: 1 initially. GL fades points below it only while
    /// multisampling (§3.3.3), which no gleval buffer does, and Mesa draws none faded without it.
    pub fade_threshold: f32,
    /// `GL_POINT_DISTANCE_ATTENUATION`: (a, b, c), initially (1, 0, 0): no attenuation.
    pub attenuation: [f32; 3],
}

impl Default for Point {
    fn default() -> Self {
        Self { size: 1.0, parameters: PointParameters::default(), coord_replace: 0 }
    }
}

impl Default for PointParameters {
    fn default() -> Self {
        Self { min_size: 0.0, max_size: MAX_POINT_SIZE, fade_threshold: 1.0, attenuation: [1.0, 0.0, 0.0] }
    }
}

/// The largest point size (`GL_POINT_SIZE_RANGE`'s and `GL_ALIASED_POINT_SIZE_RANGE`'s upper
/// end): llvmpipe's 255.
const MAX_POINT_SIZE: f32 = 255.0;

impl PointParameters {
    /// The diameter a point of `glPointSize` `size` at eye-space `z` is drawn with (GL 1.4
    /// §3.3): attenuated by distance, then clamped to the minimum and maximum, and clamped so
    /// even without attenuation, as Mesa draws it (measured on llvmpipe: `GL_POINT_SIZE_MAX` 5
    /// draws a `glPointSize(8)` point 5 pixels wide; a minimum above the maximum wins).
    #[must_use]
    pub fn derived_size(&self, size: f32, z: f32) -> f32 {
        let [a, b, c] = self.attenuation;
        let attenuated = if self.attenuation == [1.0, 0.0, 0.0] {
            size
        } else {
            let d = z.abs();
            size / (a + b * d + c * d * d).sqrt()
        };
        // `f32::min`/`max` rather than `clamp`: a NaN parameter must not panic.
        attenuated.min(self.max_size).max(self.min_size)
    }
}

/// A point call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum PointCall {
    Size(GLfloat),
    Parameter(GLenum, [GLfloat; 3]),
}

/// The enables GL files under the group (GL 1.1 table 6.8).
pub(crate) const POINT_ENABLES: &[GLenum] = &[GL_POINT_SMOOTH, GL_POINT_SPRITE];

impl Gl {
    /// `glTexEnv(GL_POINT_SPRITE, GL_COORD_REPLACE, value)` (`GL_ARB_point_sprite`): whether
    /// the active unit's coordinates are replaced across a point sprite. Mesa takes `GL_TRUE`
    /// or `GL_FALSE` only (another value `GL_INVALID_VALUE`, `main/texenv.c`), and a unit
    /// beyond the fixed-function ones keeps none.
    pub(super) fn set_coord_replace(&mut self, value: GLfloat) {
        // Mesa converts the value to an enum first (measured: 0.5 is GL_FALSE).
        let on = match value as GLenum {
            1 => true,
            0 => false,
            _ => return self.set_error(GL_INVALID_VALUE),
        };
        let unit = self.active_unit();
        if unit < super::units::MAX_TEXTURE_UNITS {
            let bit = 1u8 << unit;
            let replace = &mut self.server.point.coord_replace;
            *replace = if on { *replace | bit } else { *replace & !bit };
            self.touch_state();
        }
    }

    /// The active unit's `GL_COORD_REPLACE`, for `glGetTexEnv`.
    pub(super) fn coord_replace(&self) -> bool {
        let unit = self.active_unit();
        unit < super::units::MAX_TEXTURE_UNITS && self.server.point.coord_replace & (1 << unit) != 0
    }

    /// `glPointSize`: `size <= 0` (or NaN) → `GL_INVALID_VALUE`; inside `begin`/`end` →
    /// `GL_INVALID_OPERATION`. Compiled into display lists.
    pub fn point_size(&mut self, size: GLfloat) {
        if self.compiled_state_call(|| ListCommand::Point(PointCall::Size(size))) {
            return;
        }
        if size.is_nan() || size <= 0.0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        self.server.point.size = size;
        self.touch_state();
    }

    /// Values `glPointParameterfv`/`iv` read for `pname`: 3 for
    /// `GL_POINT_DISTANCE_ATTENUATION`, else 1.
    #[must_use]
    pub fn point_parameter_count(pname: GLenum) -> usize {
        if pname == GL_POINT_DISTANCE_ATTENUATION {
            3
        } else {
            1
        }
    }

    /// `glPointParameterf`: as `glPointParameterfv` with `(param, 0, 0)` (Mesa's
    /// `_mesa_PointParameterf`, so `GL_POINT_DISTANCE_ATTENUATION` takes (param, 0, 0)).
    pub fn point_parameterf(&mut self, pname: GLenum, param: GLfloat) {
        self.point_parameter(pname, [param, 0.0, 0.0]);
    }

    /// `glPointParameteri`: as `glPointParameterf` of the integer.
    pub fn point_parameteri(&mut self, pname: GLenum, param: GLint) {
        self.point_parameter(pname, [param as f32, 0.0, 0.0]);
    }

    /// `glPointParameterfv`: `GL_POINT_SIZE_MIN`, `GL_POINT_SIZE_MAX` and
    /// `GL_POINT_FADE_THRESHOLD_SIZE` (a negative value → `GL_INVALID_VALUE`),
    /// `GL_POINT_DISTANCE_ATTENUATION` (3 values); another name → `GL_INVALID_ENUM` (GL 2.0's
    /// `GL_POINT_SPRITE_COORD_ORIGIN` too: Mesa takes it from a 2.0 context only). Too few
    /// values → `GL_INVALID_VALUE`. Compiled into display lists.
    pub fn point_parameterfv(&mut self, pname: GLenum, params: &[GLfloat]) {
        let Some(values) = self.point_parameter_values(pname, params) else { return };
        self.point_parameter(pname, values);
    }

    /// `glPointParameteriv`: as `glPointParameterfv` of the integers.
    pub fn point_parameteriv(&mut self, pname: GLenum, params: &[GLint]) {
        let floats: Vec<f32> = params.iter().map(|&v| v as f32).collect();
        self.point_parameterfv(pname, &floats);
    }

    /// The three values a `v` form passes (the unread ones zero); `None`, with
    /// `GL_INVALID_VALUE`, when the slice is shorter than `pname` reads.
    fn point_parameter_values(&mut self, pname: GLenum, params: &[GLfloat]) -> Option<[GLfloat; 3]> {
        let n = Self::point_parameter_count(pname);
        if params.len() < n {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let mut values = [0.0; 3];
        values[..n].copy_from_slice(&params[..n]);
        Some(values)
    }

    /// Every form of `glPointParameter`, in Mesa's order of checks (`main/points.c`).
    fn point_parameter(&mut self, pname: GLenum, values: [GLfloat; 3]) {
        if self.compiled_state_call(|| ListCommand::Point(PointCall::Parameter(pname, values))) {
            return;
        }
        let p = &mut self.server.point.parameters;
        let target = match pname {
            GL_POINT_DISTANCE_ATTENUATION => {
                p.attenuation = values;
                return self.touch_state();
            }
            GL_POINT_SIZE_MIN => &mut p.min_size,
            GL_POINT_SIZE_MAX => &mut p.max_size,
            GL_POINT_FADE_THRESHOLD_SIZE => &mut p.fade_threshold,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        if values[0] < 0.0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        *target = values[0];
        self.touch_state();
    }

    /// Replays a listed point call.
    pub(crate) fn replay_point_call(&mut self, call: PointCall) {
        match call {
            PointCall::Size(size) => self.point_size(size),
            PointCall::Parameter(pname, values) => self.point_parameter(pname, values),
        }
    }
}

/// The group's `glGet` row.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_POINT_SIZE, 1, Kind::Float, |gl, o| o[0] = gl.server.point.size.into()),
    limit!(GL_POINT_SIZE_RANGE, 1, 255),
    limit!(GL_POINT_SIZE_GRANULARITY, 0.1f32),
    limit!(GL_ALIASED_POINT_SIZE_RANGE, 1, 255),
    row(GL_POINT_SIZE_MIN, 1, Kind::Float, |gl, o| o[0] = gl.server.point.parameters.min_size.into()),
    row(GL_POINT_SIZE_MAX, 1, Kind::Float, |gl, o| o[0] = gl.server.point.parameters.max_size.into()),
    row(GL_POINT_FADE_THRESHOLD_SIZE, 1, Kind::Float, |gl, o| {
        o[0] = gl.server.point.parameters.fade_threshold.into();
    }),
    row(GL_POINT_DISTANCE_ATTENUATION, 3, Kind::Float, |gl, o| put(o, &gl.server.point.parameters.attenuation)),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_as_mesa_keeps_it() {
        let mut gl = Gl::new(4, 4);
        gl.point_size(0.0);
        gl.point_size(f32::NAN);
        assert_eq!((gl.get_error(), gl.server.point.size), (GL_INVALID_VALUE, 1.0));
        gl.push_attrib(GL_POINT_BIT);
        gl.point_size(5.0);
        gl.enable(GL_POINT_SMOOTH);
        let mut v = [0];
        gl.get_integerv(GL_POINT_SIZE, &mut v);
        assert_eq!(v, [5]);
        gl.pop_attrib();
        assert_eq!((gl.server.point, gl.is_enabled(GL_POINT_SMOOTH)), (Point::default(), GL_FALSE));
    }
}
