//! Lights, materials, the light model, colour material and the shade model (GL 1.1 spec
//! §2.13), with GL's initial values. Positions and spot directions are stored in eye
//! coordinates, transformed by the modelview matrix current when they were set.

mod color_material;
mod query;

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{int_limit, put, put_enum, put_flag, row, Kind, StateVar};
use super::types::*;
use super::Gl;
use color_material::material_bits;
pub(crate) use color_material::ColorMaterialSync;
use glam::{Mat3, Vec3, Vec4};

/// One light source (`GL_LIGHTi`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Whether `GL_LIGHTi` is enabled.
    pub enabled: bool,
    /// Ambient intensity, initially (0, 0, 0, 1).
    pub ambient: Vec4,
    /// Diffuse intensity: (1, 1, 1, 1) for light 0, else (0, 0, 0, 1).
    pub diffuse: Vec4,
    /// Specular intensity: as diffuse.
    pub specular: Vec4,
    /// Eye-space position; w = 0 is a directional light. Initially (0, 0, 1, 0).
    pub position: Vec4,
    /// Eye-space spot direction, initially (0, 0, −1).
    pub spot_direction: Vec3,
    /// Spot exponent, 0..=128.
    pub spot_exponent: f32,
    /// Spot cutoff in degrees, 0..=90 or 180 (no spot).
    pub spot_cutoff: f32,
    /// Constant, linear and quadratic attenuation.
    pub attenuation: Vec3,
}

impl Light {
    fn initial(index: usize) -> Self {
        let colour = if index == 0 { Vec4::ONE } else { Vec4::new(0.0, 0.0, 0.0, 1.0) };
        Self {
            enabled: false,
            ambient: Vec4::new(0.0, 0.0, 0.0, 1.0),
            diffuse: colour,
            specular: colour,
            position: Vec4::new(0.0, 0.0, 1.0, 0.0),
            spot_direction: Vec3::new(0.0, 0.0, -1.0),
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            attenuation: Vec3::new(1.0, 0.0, 0.0),
        }
    }
}

/// A material (front or back).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Initially (0.2, 0.2, 0.2, 1).
    pub ambient: Vec4,
    /// Initially (0.8, 0.8, 0.8, 1).
    pub diffuse: Vec4,
    /// Initially (0, 0, 0, 1).
    pub specular: Vec4,
    /// Initially (0, 0, 0, 1).
    pub emission: Vec4,
    /// Specular exponent 0..=128, initially 0.
    pub shininess: f32,
}

impl Default for Material {
    fn default() -> Self {
        Self {
            ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            diffuse: Vec4::new(0.8, 0.8, 0.8, 1.0),
            specular: Vec4::new(0.0, 0.0, 0.0, 1.0),
            emission: Vec4::new(0.0, 0.0, 0.0, 1.0),
            shininess: 0.0,
        }
    }
}

/// Everything per-vertex lighting needs.
#[derive(Clone, Debug, PartialEq)]
pub struct Lighting {
    /// The eight lights.
    pub lights: [Light; 8],
    /// Front (0) and back (1) materials.
    pub materials: [Material; 2],
    /// `GL_LIGHT_MODEL_AMBIENT`, initially (0.2, 0.2, 0.2, 1).
    pub model_ambient: Vec4,
    /// `GL_LIGHT_MODEL_LOCAL_VIEWER`.
    pub local_viewer: bool,
    /// `GL_LIGHT_MODEL_TWO_SIDE`.
    pub two_side: bool,
    /// `glColorMaterial` face and mode (used when `GL_COLOR_MATERIAL` is enabled).
    pub color_material: (GLenum, GLenum),
    /// GL 1.2's `GL_LIGHT_MODEL_COLOR_CONTROL`: `GL_SINGLE_COLOR`, or
    /// `GL_SEPARATE_SPECULAR_COLOR`, which lights the specular terms into the secondary colour
    /// that the colour sum adds after texturing (GL 1.2 §2.13.1, §3.9).
    pub color_control: GLenum,
}

impl Lighting {
    /// Whether the specular terms go to the secondary colour.
    #[must_use]
    pub fn separate_specular(&self) -> bool {
        self.color_control == GL_SEPARATE_SPECULAR_COLOR
    }
}

impl Default for Lighting {
    fn default() -> Self {
        Self {
            lights: std::array::from_fn(Light::initial),
            materials: [Material::default(); 2],
            model_ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            local_viewer: false,
            two_side: false,
            color_material: (GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE),
            color_control: GL_SINGLE_COLOR,
        }
    }
}

fn vec4_from(p: &[f32]) -> Vec4 {
    Vec4::new(p[0], p[1], p[2], p[3])
}

/// The lighting group's calls as a display list holds them.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum LightingCall {
    Light(GLenum, GLenum, Vec<f32>),
    Material(GLenum, GLenum, Vec<f32>),
    LightModel(GLenum, Vec<f32>),
    ColorMaterial(GLenum, GLenum),
    ShadeModel(GLenum),
}

impl Gl {
    /// Replays a listed call of the group.
    pub(crate) fn replay_lighting_call(&mut self, call: &LightingCall) {
        use LightingCall as C;
        match call {
            C::Light(light, pname, params) => self.light_fv(*light, *pname, params),
            C::Material(face, pname, params) => self.material_fv(*face, *pname, params),
            C::LightModel(pname, params) => self.light_model_fv(*pname, params),
            C::ColorMaterial(face, mode) => self.color_material(*face, *mode),
            C::ShadeModel(mode) => self.shade_model(*mode),
        }
    }
}

impl Gl {
    /// Values `glLightfv`/`glLightiv` read and `glGetLight*v` write for `pname` (GL 1.1 table
    /// 2.9): 4 for the colours and the position, 3 for the spot direction, 1 for the spot
    /// exponent, cutoff and attenuations; `None` for a name lights do not have.
    #[must_use]
    pub fn light_param_count(pname: GLenum) -> Option<usize> {
        match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => Some(4),
            GL_SPOT_DIRECTION => Some(3),
            GL_SPOT_EXPONENT | GL_SPOT_CUTOFF | GL_CONSTANT_ATTENUATION..=GL_QUADRATIC_ATTENUATION => Some(1),
            _ => None,
        }
    }

    /// Values `glMaterialfv`/`glMaterialiv` read and `glGetMaterial*v` write for `pname` (GL
    /// 1.1 table 2.8): 4 for the colours, 1 for the shininess; `None` for another name.
    #[must_use]
    pub fn material_param_count(pname: GLenum) -> Option<usize> {
        match pname {
            GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => Some(4),
            GL_SHININESS => Some(1),
            _ => None,
        }
    }

    /// Values `glLightModelfv`/`glLightModeliv` read for `pname` (GL 1.1 table 2.10): 4 for
    /// the ambient colour, 1 for the local viewer and two-sided flags and GL 1.2's colour
    /// control; `None` for another name.
    #[must_use]
    pub fn light_model_param_count(pname: GLenum) -> Option<usize> {
        match pname {
            GL_LIGHT_MODEL_AMBIENT => Some(4),
            GL_LIGHT_MODEL_LOCAL_VIEWER | GL_LIGHT_MODEL_TWO_SIDE | GL_LIGHT_MODEL_COLOR_CONTROL => Some(1),
            _ => None,
        }
    }

    /// `glLightfv`. Unknown light or name → `GL_INVALID_ENUM`; a spot exponent outside 0..=128,
    /// a cutoff outside 0..=90 other than 180, or a negative attenuation → `GL_INVALID_VALUE`.
    /// `params` needs 4 values for colours and positions, 3 for the spot direction, else 1.
    pub fn light_fv(&mut self, light: GLenum, pname: GLenum, params: &[GLfloat]) {
        if self.compiled(|| ListCommand::Lighting(LightingCall::Light(light, pname, params.to_vec()))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(index) = light.checked_sub(GL_LIGHT0).filter(|i| *i < 8).map(|i| i as usize) else {
            return self.set_error(GL_INVALID_ENUM);
        };
        let Some(needed) = Self::light_param_count(pname) else { return self.set_error(GL_INVALID_ENUM) };
        if params.len() < needed {
            return self.set_error(GL_INVALID_VALUE);
        }
        let p = params[0];
        let invalid = match pname {
            GL_SPOT_EXPONENT => !(0.0..=128.0).contains(&p),
            GL_SPOT_CUTOFF => !((0.0..=90.0).contains(&p) || p == 180.0),
            GL_CONSTANT_ATTENUATION..=GL_QUADRATIC_ATTENUATION => p < 0.0,
            _ => false,
        };
        if invalid {
            return self.set_error(GL_INVALID_VALUE);
        }
        let modelview = self.server.matrices.modelview();
        let l = &mut self.server.lighting.lights[index];
        match pname {
            GL_AMBIENT => l.ambient = vec4_from(params),
            GL_DIFFUSE => l.diffuse = vec4_from(params),
            GL_SPECULAR => l.specular = vec4_from(params),
            GL_POSITION => l.position = modelview * vec4_from(params),
            GL_SPOT_DIRECTION => {
                l.spot_direction = Mat3::from_mat4(modelview) * Vec3::new(params[0], params[1], params[2])
            }
            GL_SPOT_EXPONENT => l.spot_exponent = p,
            GL_SPOT_CUTOFF => l.spot_cutoff = p,
            GL_CONSTANT_ATTENUATION => l.attenuation.x = p,
            GL_LINEAR_ATTENUATION => l.attenuation.y = p,
            _ => l.attenuation.z = p,
        }
        self.touch_state();
    }

    /// `glLightf` for the single-valued names.
    /// Like Mesa, a vector name gets (param, 0, 0, 0).
    pub fn light_f(&mut self, light: GLenum, pname: GLenum, param: GLfloat) {
        self.light_fv(light, pname, &[param, 0.0, 0.0, 0.0]);
    }

    /// `glMaterialfv` (allowed between begin and end). Bad face or name → `GL_INVALID_ENUM`;
    /// shininess outside 0..=128 → `GL_INVALID_VALUE`.
    pub fn material_fv(&mut self, face: GLenum, pname: GLenum, params: &[GLfloat]) {
        if self.compiled(|| ListCommand::Lighting(LightingCall::Material(face, pname, params.to_vec()))) {
            return;
        }
        let faces: &[usize] = match face {
            GL_FRONT => &[0],
            GL_BACK => &[1],
            GL_FRONT_AND_BACK => &[0, 1],
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        let Some(needed) = Self::material_param_count(pname) else { return self.set_error(GL_INVALID_ENUM) };
        if params.len() < needed {
            return self.set_error(GL_INVALID_VALUE);
        }
        if pname == GL_SHININESS && !(0.0..=128.0).contains(&params[0]) {
            return self.set_error(GL_INVALID_VALUE);
        }
        for &f in faces {
            // While tracking, Mesa drops a glMaterial of a tracked parameter (`vbo`'s material
            // call masks them out).
            let bits = material_bits(pname) & !self.tracked_bits(f);
            let m = &mut self.server.lighting.materials[f];
            if pname == GL_SHININESS {
                m.shininess = params[0];
                continue;
            }
            let value = vec4_from(params);
            for (bit, slot) in [(1, &mut m.ambient), (2, &mut m.diffuse), (4, &mut m.specular), (8, &mut m.emission)] {
                if bits & bit != 0 {
                    *slot = value;
                }
            }
        }
        self.note_pending_material(face, pname);
        self.touch_state();
        self.note_material_change();
    }

    /// `glMaterialf`: `GL_SHININESS`; a colour name gets (param, 0, 0, 0), as in Mesa.
    pub fn material_f(&mut self, face: GLenum, pname: GLenum, param: GLfloat) {
        // Mesa passes (param, 0, 0, 0), so a colour name sets that colour without an error.
        self.material_fv(face, pname, &[param, 0.0, 0.0, 0.0]);
    }

    /// `glLightModelfv`: `GL_LIGHT_MODEL_AMBIENT` (4 values), `_LOCAL_VIEWER`, `_TWO_SIDE`,
    /// GL 1.2's `_COLOR_CONTROL` (`GL_SINGLE_COLOR` or `GL_SEPARATE_SPECULAR_COLOR`, another
    /// value `GL_INVALID_ENUM`, as Mesa's `_mesa_LightModelfv`).
    pub fn light_model_fv(&mut self, pname: GLenum, params: &[GLfloat]) {
        if self.compiled(|| ListCommand::Lighting(LightingCall::LightModel(pname, params.to_vec()))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(needed) = Self::light_model_param_count(pname) else { return self.set_error(GL_INVALID_ENUM) };
        if params.len() < needed {
            return self.set_error(GL_INVALID_VALUE);
        }
        match pname {
            GL_LIGHT_MODEL_AMBIENT => self.server.lighting.model_ambient = vec4_from(params),
            GL_LIGHT_MODEL_LOCAL_VIEWER => self.server.lighting.local_viewer = params[0] != 0.0,
            GL_LIGHT_MODEL_COLOR_CONTROL => {
                let control =
                    [GL_SINGLE_COLOR, GL_SEPARATE_SPECULAR_COLOR].into_iter().find(|&e| e as f32 == params[0]);
                let Some(control) = control else { return self.set_error(GL_INVALID_ENUM) };
                self.server.lighting.color_control = control;
            }
            _ => self.server.lighting.two_side = params[0] != 0.0,
        }
        self.touch_state();
    }

    /// `glLightModeli`.
    pub fn light_model_i(&mut self, pname: GLenum, param: GLint) {
        self.light_model_fv(pname, &[param as f32, 0.0, 0.0, 0.0]);
    }

    /// `glColorMaterial(face, mode)`.
    pub fn color_material(&mut self, face: GLenum, mode: GLenum) {
        if self.compiled(|| ListCommand::Lighting(LightingCall::ColorMaterial(face, mode))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let face_ok = matches!(face, GL_FRONT | GL_BACK | GL_FRONT_AND_BACK);
        let mode_ok = matches!(mode, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE);
        if !face_ok || !mode_ok {
            return self.set_error(GL_INVALID_ENUM);
        }
        if self.server.lighting.color_material == (face, mode) {
            // Mesa returns early: no flush, no copy (a waiting glMaterial still lands).
            return;
        }
        self.server.lighting.color_material = (face, mode);
        self.touch_state();
        self.color_material_changed();
    }

    /// `glShadeModel`: `GL_FLAT` or `GL_SMOOTH`.
    pub fn shade_model(&mut self, mode: GLenum) {
        if self.compiled(|| ListCommand::Lighting(LightingCall::ShadeModel(mode))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        if mode != GL_FLAT && mode != GL_SMOOTH {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.server.shade_model = mode;
        self.touch_state();
    }
}

/// The lighting group's `glGet` rows (lights and materials answer through `glGetLight` and `glGetMaterial`), and the limit.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_SHADE_MODEL, 1, Kind::Int, |gl, o| put_enum(o, gl.server.shade_model)),
    row(GL_COLOR_MATERIAL_PARAMETER, 1, Kind::Int, |gl, o| put_enum(o, gl.server.lighting.color_material.1)),
    row(GL_COLOR_MATERIAL_FACE, 1, Kind::Int, |gl, o| put_enum(o, gl.server.lighting.color_material.0)),
    row(GL_LIGHT_MODEL_AMBIENT, 4, Kind::Normalized, |gl, o| put(o, &gl.server.lighting.model_ambient.to_array())),
    row(GL_LIGHT_MODEL_LOCAL_VIEWER, 1, Kind::Bool, |gl, o| put_flag(o, gl.server.lighting.local_viewer)),
    row(GL_LIGHT_MODEL_TWO_SIDE, 1, Kind::Bool, |gl, o| put_flag(o, gl.server.lighting.two_side)),
    row(GL_LIGHT_MODEL_COLOR_CONTROL, 1, Kind::Int, |gl, o| put_enum(o, gl.server.lighting.color_control)),
    int_limit!(GL_MAX_LIGHTS, 8),
];
