//! The fog attribute group (GL 1.1 spec §3.9; table 6.6; Mesa `main/fog.c`): `glFog` in its
//! forms, in one struct as `GL_FOG_BIT` saves it, with the group's `glGet` rows and its enable.
//! A recorded primitive's [`DrawState`](super::DrawState) carries the fog while `GL_FOG` is on,
//! and both rasterisers blend it per fragment. A display list holds the call as
//! `ListCommand::Fog`.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put, put_enum, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// `glFog` parameters (GL's initial values: `GL_EXP`, density 1, start 0, end 1, colour 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    /// `GL_LINEAR`, `GL_EXP` or `GL_EXP2`.
    pub mode: GLenum,
    /// `GL_FOG_DENSITY`, for the exponential modes.
    pub density: f32,
    /// `GL_FOG_START`, for `GL_LINEAR`.
    pub start: f32,
    /// `GL_FOG_END`, for `GL_LINEAR`.
    pub end: f32,
    /// `GL_FOG_COLOR`, clamped to [0, 1].
    pub color: [f32; 4],
    /// GL 1.4's `GL_FOG_COORD_SRC`: `GL_FRAGMENT_DEPTH` (the eye-space distance, initially)
    /// or `GL_FOG_COORD` (the vertices' `glFogCoord`, §3.10; Mesa takes its absolute value).
    pub coord_source: GLenum,
}

impl Default for Fog {
    fn default() -> Self {
        Self { mode: GL_EXP, density: 1.0, start: 0.0, end: 1.0, color: [0.0; 4], coord_source: GL_FRAGMENT_DEPTH }
    }
}

/// `GL_FOG_BIT`'s state (its enable aside).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct FogState {
    /// What an RGBA context draws with.
    pub params: Fog,
    /// `GL_FOG_INDEX`: colour-index fog, kept for `glGet` and `GL_FOG_BIT` (nothing is drawn in
    /// colour-index mode).
    pub index: f32,
}

/// The enables GL files under the group (GL 1.1 table 6.6).
pub(crate) const FOG_ENABLES: &[GLenum] = &[GL_FOG];

impl Gl {
    /// Values `glFogfv`/`glFogiv` read for `pname`: 4 for `GL_FOG_COLOR`, else 1 (the first
    /// value is read before the name is checked, as Mesa reads it).
    #[must_use]
    pub fn fog_param_count(pname: GLenum) -> usize {
        if pname == GL_FOG_COLOR {
            4
        } else {
            1
        }
    }

    /// `glFogfv`: `GL_FOG_MODE` (`GL_LINEAR`, `GL_EXP`, `GL_EXP2`), `GL_FOG_DENSITY` (a
    /// negative one → `GL_INVALID_VALUE`), `GL_FOG_START`, `GL_FOG_END`, `GL_FOG_COLOR` (4
    /// values), `GL_FOG_INDEX` (colour-index mode: kept, not drawn) or GL 1.4's
    /// `GL_FOG_COORD_SRC` (`GL_FRAGMENT_DEPTH` or `GL_FOG_COORD`). Another name or mode →
    /// `GL_INVALID_ENUM`; a short slice → `GL_INVALID_VALUE`.
    pub fn fogfv(&mut self, pname: GLenum, params: &[GLfloat]) {
        if self.compiled_state_call(|| ListCommand::Fog(pname, params.to_vec())) {
            return;
        }
        let Some(values) = params.get(..Self::fog_param_count(pname)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        let fog = &mut self.server.fog.params;
        match pname {
            GL_FOG_MODE => match values[0] as GLenum {
                mode @ (GL_LINEAR | GL_EXP | GL_EXP2) => fog.mode = mode,
                _ => return self.set_error(GL_INVALID_ENUM),
            },
            GL_FOG_DENSITY if values[0] < 0.0 => return self.set_error(GL_INVALID_VALUE),
            GL_FOG_DENSITY => fog.density = values[0],
            GL_FOG_START => fog.start = values[0],
            GL_FOG_END => fog.end = values[0],
            GL_FOG_COLOR => fog.color = std::array::from_fn(|i| values[i].clamp(0.0, 1.0)),
            GL_FOG_INDEX => self.server.fog.index = values[0],
            GL_FOG_COORD_SRC => match values[0] as GLenum {
                source @ (GL_FRAGMENT_DEPTH | GL_FOG_COORD) => fog.coord_source = source,
                _ => return self.set_error(GL_INVALID_ENUM),
            },
            _ => return self.set_error(GL_INVALID_ENUM),
        }
        self.touch_state();
    }

    /// `glFogf`: as [`Gl::fogfv`] with one value.
    pub fn fogf(&mut self, pname: GLenum, param: GLfloat) {
        self.fogfv(pname, &[param, 0.0, 0.0, 0.0]);
    }

    /// `glFogi`: as [`Gl::fogfv`] with one value (an enum for `GL_FOG_MODE`).
    pub fn fogi(&mut self, pname: GLenum, param: GLint) {
        self.fogfv(pname, &[param as GLfloat, 0.0, 0.0, 0.0]);
    }

    /// The fog while `GL_FOG` is on.
    pub(crate) fn enabled_fog(&self) -> Option<Fog> {
        self.capability(GL_FOG).then_some(self.server.fog.params)
    }
}

/// The group's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_FOG_COLOR, 4, Kind::Normalized, |gl, o| put(o, &gl.server.fog.params.color)),
    row(GL_FOG_INDEX, 1, Kind::Float, |gl, o| o[0] = gl.server.fog.index.into()),
    row(GL_FOG_DENSITY, 1, Kind::Float, |gl, o| o[0] = gl.server.fog.params.density.into()),
    row(GL_FOG_START, 1, Kind::Float, |gl, o| o[0] = gl.server.fog.params.start.into()),
    row(GL_FOG_END, 1, Kind::Float, |gl, o| o[0] = gl.server.fog.params.end.into()),
    row(GL_FOG_MODE, 1, Kind::Int, |gl, o| put_enum(o, gl.server.fog.params.mode)),
    row(GL_FOG_COORD_SRC, 1, Kind::Int, |gl, o| put_enum(o, gl.server.fog.params.coord_source)),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_as_mesa_keeps_it() {
        let mut gl = Gl::new(4, 4);
        gl.fogi(GL_FOG_MODE, GL_LINEAR as i32 + 7);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.fogf(GL_FOG_DENSITY, -1.0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.fogfv(GL_FOG_COLOR, &[1.0, 0.0]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.push_attrib(GL_FOG_BIT);
        gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
        gl.fogf(GL_FOG_INDEX, 3.0);
        gl.enable(GL_FOG);
        assert_eq!(gl.enabled_fog().map(|f| f.mode), Some(GL_LINEAR));
        let mut index = [0.0];
        gl.get_floatv(GL_FOG_INDEX, &mut index);
        assert_eq!((index, gl.get_error()), ([3.0], GL_NO_ERROR));
        gl.pop_attrib();
        assert_eq!((gl.server.fog, gl.enabled_fog()), (FogState::default(), None));
    }
}
