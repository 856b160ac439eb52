//! Per-fragment state: blending (`glBlendFunc`, GL 1.1 spec §4.1.6), the alpha test
//! (`glAlphaFunc`, §4.1.3) and fog (`glFog`, §3.9). The values live here; a recorded
//! primitive's [`DrawState`](super::DrawState) carries those that are enabled, and the
//! rasteriser applies them per fragment (fog, alpha test) or in its blend state.

use super::consts::*;
use super::lists::ListCommand;
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
}

impl Default for Fog {
    fn default() -> Self {
        Self { mode: GL_EXP, density: 1.0, start: 0.0, end: 1.0, color: [0.0; 4] }
    }
}

/// The fragment operations' values, enabled or not.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FragmentOps {
    pub blend: [GLenum; 2],
    pub alpha: (GLenum, f32),
    pub fog: Fog,
    /// `GL_FOG_INDEX`: colour-index fog, kept for `glGet` and `GL_FOG_BIT` (nothing is drawn in
    /// colour-index mode).
    pub fog_index: f32,
}

impl Default for FragmentOps {
    fn default() -> Self {
        Self { blend: [GL_ONE, GL_ZERO], alpha: (GL_ALWAYS, 0.0), fog: Fog::default(), fog_index: 0.0 }
    }
}

/// Whether `factor` is a blend factor GL takes (GL 1.1 table 4.1 and 4.2, with GL 1.4's
/// source colour factors, as Mesa accepts them).
fn blend_factor(factor: GLenum) -> bool {
    matches!(factor, GL_ZERO | GL_ONE) || (GL_SRC_COLOR..=GL_SRC_ALPHA_SATURATE).contains(&factor)
}

impl Gl {
    /// `glBlendFunc`: the source and destination factors used while `GL_BLEND` is enabled.
    /// A factor GL does not know → `GL_INVALID_ENUM`.
    pub fn blend_func(&mut self, sfactor: GLenum, dfactor: GLenum) {
        if self.compiled_state_call(|| ListCommand::BlendFunc(sfactor, dfactor)) {
            return;
        }
        if !blend_factor(sfactor) || !blend_factor(dfactor) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.fragment_ops.blend = [sfactor, dfactor];
        self.touch_state();
    }

    /// `glAlphaFunc`: the comparison (`GL_NEVER` .. `GL_ALWAYS`) and reference (clamped to
    /// [0, 1]) of the alpha test. Another function → `GL_INVALID_ENUM`.
    pub fn alpha_func(&mut self, func: GLenum, reference: GLclampf) {
        if self.compiled_state_call(|| ListCommand::AlphaFunc(func, reference)) {
            return;
        }
        if !(GL_NEVER..=GL_ALWAYS).contains(&func) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.fragment_ops.alpha = (func, reference.clamp(0.0, 1.0));
        self.touch_state();
    }

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
    /// values) or `GL_FOG_INDEX` (colour-index mode: kept, not drawn). Another name or mode →
    /// `GL_INVALID_ENUM`; a short slice → `GL_INVALID_VALUE`.
    pub fn fogfv(&mut self, pname: GLenum, params: &[GLfloat]) {
        if self.compiled_state_call(|| ListCommand::Fog(pname, params.to_vec())) {
            return;
        }
        let Some(values) = params.get(..Self::fog_param_count(pname)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        let fog = &mut self.server.fragment_ops.fog;
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
            GL_FOG_INDEX => self.server.fragment_ops.fog_index = values[0],
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

    /// The blend factors while `GL_BLEND` is on.
    pub(crate) fn enabled_blend(&self) -> Option<[GLenum; 2]> {
        self.capability(GL_BLEND).then_some(self.server.fragment_ops.blend)
    }

    /// The alpha test while `GL_ALPHA_TEST` is on.
    pub(crate) fn enabled_alpha_test(&self) -> Option<(GLenum, f32)> {
        self.capability(GL_ALPHA_TEST).then_some(self.server.fragment_ops.alpha)
    }

    /// The fog while `GL_FOG` is on.
    pub(crate) fn enabled_fog(&self) -> Option<Fog> {
        self.capability(GL_FOG).then_some(self.server.fragment_ops.fog)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fragment_state_errors() {
        let mut gl = Gl::new(4, 4);
        gl.blend_func(GL_SRC_ALPHA, 0x1234);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.alpha_func(0x1234, 0.5);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.fogi(GL_FOG_MODE, GL_LINEAR as i32 + 7);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.fogf(GL_FOG_DENSITY, -1.0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.fogfv(GL_FOG_COLOR, &[1.0, 0.0]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        gl.fogi(GL_FOG_MODE, GL_LINEAR as i32);
        gl.enable(GL_BLEND);
        gl.enable(GL_FOG);
        assert_eq!(gl.enabled_blend(), Some([GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA]));
        assert_eq!(gl.enabled_fog().map(|f| f.mode), Some(GL_LINEAR));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}
