//! NURBS properties (`gluNurbsProperty`, `gluGetNurbsProperty`, `gluLoadSamplingMatrices`) with
//! GLU's defaults (`glrenderer.cc`, `renderhints.cc`; spec 2.2–2.3).

use crate::gl::types::GLenum;
use crate::glu::consts::*;
use glam::Mat4;

/// The properties of a NURBS object. `DEFAULT` is GLU's initial state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct NurbsProperties {
    /// `GLU_SAMPLING_TOLERANCE`: pixels (object units for the OBJECT_ methods).
    pub sampling_tolerance: f32,
    /// `GLU_PARAMETRIC_TOLERANCE`.
    pub parametric_tolerance: f32,
    /// `GLU_SAMPLING_METHOD`.
    pub sampling_method: GLenum,
    /// `GLU_U_STEP`.
    pub u_step: f32,
    /// `GLU_V_STEP`.
    pub v_step: f32,
    /// `GLU_DISPLAY_MODE`.
    pub display_mode: GLenum,
    /// `GLU_CULLING`.
    pub culling: bool,
    /// `GLU_AUTO_LOAD_MATRIX`.
    pub auto_load_matrix: bool,
    /// `GLU_NURBS_MODE`.
    pub nurbs_mode: GLenum,
}

impl NurbsProperties {
    /// GLU's initial values.
    pub const DEFAULT: Self = Self {
        sampling_tolerance: 50.0,
        parametric_tolerance: 0.5,
        sampling_method: GLU_PATH_LENGTH,
        u_step: 100.0,
        v_step: 100.0,
        display_mode: GLU_FILL,
        culling: false,
        auto_load_matrix: true,
        nurbs_mode: GLU_NURBS_RENDERER,
    };

    /// Applies `gluNurbsProperty`; `Err(code)` is the GLU error to report (nothing changes).
    pub fn set(&mut self, property: GLenum, value: f32) -> Result<(), GLenum> {
        match property {
            GLU_SAMPLING_TOLERANCE => self.sampling_tolerance = value,
            GLU_PARAMETRIC_TOLERANCE => self.parametric_tolerance = value,
            GLU_SAMPLING_METHOD => {
                let method = value as GLenum;
                let known = matches!(
                    method,
                    GLU_PATH_LENGTH
                        | GLU_PARAMETRIC_ERROR
                        | GLU_DOMAIN_DISTANCE
                        | GLU_OBJECT_PATH_LENGTH
                        | GLU_OBJECT_PARAMETRIC_ERROR
                );
                if !known {
                    return Err(GLU_INVALID_VALUE);
                }
                self.sampling_method = method;
                if matches!(method, GLU_OBJECT_PATH_LENGTH | GLU_OBJECT_PARAMETRIC_ERROR) {
                    self.auto_load_matrix = false;
                }
            }
            // Mapdesc::setProperty clamps negative rates to 0.
            GLU_U_STEP => self.u_step = value.max(0.0),
            GLU_V_STEP => self.v_step = value.max(0.0),
            GLU_DISPLAY_MODE => {
                let mode = value as GLenum;
                if !matches!(mode, GLU_FILL | GLU_OUTLINE_POLYGON | GLU_OUTLINE_PATCH) {
                    return Err(GLU_INVALID_VALUE);
                }
                self.display_mode = mode;
            }
            GLU_CULLING => self.culling = value != 0.0,
            GLU_AUTO_LOAD_MATRIX => self.auto_load_matrix = value != 0.0,
            GLU_NURBS_MODE => {
                let mode = value as GLenum;
                if mode != GLU_NURBS_RENDERER && mode != GLU_NURBS_TESSELLATOR {
                    return Err(GLU_INVALID_ENUM);
                }
                self.nurbs_mode = mode;
            }
            _ => return Err(GLU_INVALID_ENUM),
        }
        Ok(())
    }

    /// `gluGetNurbsProperty`; `Err(GLU_INVALID_ENUM)` for an unknown property.
    pub fn get(&self, property: GLenum) -> Result<f32, GLenum> {
        let flag = |b: bool| if b { 1.0 } else { 0.0 };
        Ok(match property {
            GLU_SAMPLING_TOLERANCE => self.sampling_tolerance,
            GLU_PARAMETRIC_TOLERANCE => self.parametric_tolerance,
            GLU_SAMPLING_METHOD => self.sampling_method as f32,
            GLU_U_STEP => self.u_step,
            GLU_V_STEP => self.v_step,
            GLU_DISPLAY_MODE => self.display_mode as f32,
            GLU_CULLING => flag(self.culling),
            GLU_AUTO_LOAD_MATRIX => flag(self.auto_load_matrix),
            GLU_NURBS_MODE => self.nurbs_mode as f32,
            _ => return Err(GLU_INVALID_ENUM),
        })
    }

    /// Whether sampling is in object space (the OBJECT_ methods).
    pub fn object_space(&self) -> bool {
        matches!(self.sampling_method, GLU_OBJECT_PATH_LENGTH | GLU_OBJECT_PARAMETRIC_ERROR)
    }
}

impl Default for NurbsProperties {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// The matrices GLU samples with: `clip = projection · modelview · p`, and the viewport.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SamplingMatrices {
    /// Modelview.
    pub modelview: Mat4,
    /// Projection.
    pub projection: Mat4,
    /// x, y, width, height.
    pub viewport: [i32; 4],
}

impl SamplingMatrices {
    /// Identity matrices: sampling in object space (GLU loads these for the OBJECT_ methods).
    pub const IDENTITY: Self = Self { modelview: Mat4::IDENTITY, projection: Mat4::IDENTITY, viewport: [0, 0, 2, 2] };

    /// The sampling matrix of spec 2.3: clip coordinates scaled so that x/w and y/w are pixel
    /// offsets from the viewport centre (depth dropped).
    pub fn sampling(&self) -> Mat4 {
        let scale =
            Mat4::from_scale(glam::Vec3::new(self.viewport[2] as f32 / 2.0, self.viewport[3] as f32 / 2.0, 0.0));
        scale * self.projection * self.modelview
    }
}
