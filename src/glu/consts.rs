//! GLU constants with their C names and values (`GL/glu.h`, GLU 1.3).
#![allow(missing_docs)]

use crate::gl::types::GLenum;

// NURBS properties.
pub const GLU_AUTO_LOAD_MATRIX: GLenum = 100200;
pub const GLU_CULLING: GLenum = 100201;
pub const GLU_PARAMETRIC_TOLERANCE: GLenum = 100202;
pub const GLU_SAMPLING_TOLERANCE: GLenum = 100203;
pub const GLU_DISPLAY_MODE: GLenum = 100204;
pub const GLU_SAMPLING_METHOD: GLenum = 100205;
pub const GLU_U_STEP: GLenum = 100206;
pub const GLU_V_STEP: GLenum = 100207;
pub const GLU_NURBS_MODE: GLenum = 100160;

// Sampling methods.
pub const GLU_OBJECT_PARAMETRIC_ERROR: GLenum = 100208;
pub const GLU_OBJECT_PATH_LENGTH: GLenum = 100209;
pub const GLU_PATH_LENGTH: GLenum = 100215;
pub const GLU_PARAMETRIC_ERROR: GLenum = 100216;
pub const GLU_DOMAIN_DISTANCE: GLenum = 100217;

// Display modes.
pub const GLU_FILL: GLenum = 100012;
pub const GLU_OUTLINE_POLYGON: GLenum = 100240;
pub const GLU_OUTLINE_PATCH: GLenum = 100241;

// NURBS modes.
pub const GLU_NURBS_TESSELLATOR: GLenum = 100161;
pub const GLU_NURBS_RENDERER: GLenum = 100162;

// Trim curve types.
pub const GLU_MAP1_TRIM_2: GLenum = 100210;
pub const GLU_MAP1_TRIM_3: GLenum = 100211;

// Callbacks.
pub const GLU_ERROR: GLenum = 100103;
pub const GLU_NURBS_ERROR: GLenum = 100103;
pub const GLU_NURBS_BEGIN: GLenum = 100164;
pub const GLU_NURBS_VERTEX: GLenum = 100165;
pub const GLU_NURBS_NORMAL: GLenum = 100166;
pub const GLU_NURBS_COLOR: GLenum = 100167;
pub const GLU_NURBS_TEXTURE_COORD: GLenum = 100168;
pub const GLU_NURBS_END: GLenum = 100169;
pub const GLU_NURBS_BEGIN_DATA: GLenum = 100170;
pub const GLU_NURBS_VERTEX_DATA: GLenum = 100171;
pub const GLU_NURBS_NORMAL_DATA: GLenum = 100172;
pub const GLU_NURBS_COLOR_DATA: GLenum = 100173;
pub const GLU_NURBS_TEXTURE_COORD_DATA: GLenum = 100174;
pub const GLU_NURBS_END_DATA: GLenum = 100175;

// Errors.
pub const GLU_INVALID_ENUM: GLenum = 100900;
pub const GLU_INVALID_VALUE: GLenum = 100901;
pub const GLU_OUT_OF_MEMORY: GLenum = 100902;
pub const GLU_INCOMPATIBLE_GL_VERSION: GLenum = 100903;
pub const GLU_INVALID_OPERATION: GLenum = 100904;
pub const GLU_NURBS_ERROR1: GLenum = 100251;
pub const GLU_NURBS_ERROR2: GLenum = 100252;
pub const GLU_NURBS_ERROR3: GLenum = 100253;
pub const GLU_NURBS_ERROR4: GLenum = 100254;
pub const GLU_NURBS_ERROR5: GLenum = 100255;
pub const GLU_NURBS_ERROR6: GLenum = 100256;
pub const GLU_NURBS_ERROR7: GLenum = 100257;
pub const GLU_NURBS_ERROR8: GLenum = 100258;
pub const GLU_NURBS_ERROR9: GLenum = 100259;
pub const GLU_NURBS_ERROR10: GLenum = 100260;
pub const GLU_NURBS_ERROR11: GLenum = 100261;
pub const GLU_NURBS_ERROR12: GLenum = 100262;
pub const GLU_NURBS_ERROR13: GLenum = 100263;
pub const GLU_NURBS_ERROR14: GLenum = 100264;
pub const GLU_NURBS_ERROR15: GLenum = 100265;
pub const GLU_NURBS_ERROR16: GLenum = 100266;
pub const GLU_NURBS_ERROR17: GLenum = 100267;
pub const GLU_NURBS_ERROR18: GLenum = 100268;
pub const GLU_NURBS_ERROR19: GLenum = 100269;
pub const GLU_NURBS_ERROR20: GLenum = 100270;
pub const GLU_NURBS_ERROR21: GLenum = 100271;
pub const GLU_NURBS_ERROR22: GLenum = 100272;
pub const GLU_NURBS_ERROR23: GLenum = 100273;
pub const GLU_NURBS_ERROR24: GLenum = 100274;
pub const GLU_NURBS_ERROR25: GLenum = 100275;
pub const GLU_NURBS_ERROR26: GLenum = 100276;
pub const GLU_NURBS_ERROR27: GLenum = 100277;
pub const GLU_NURBS_ERROR28: GLenum = 100278;
pub const GLU_NURBS_ERROR29: GLenum = 100279;
pub const GLU_NURBS_ERROR30: GLenum = 100280;
pub const GLU_NURBS_ERROR31: GLenum = 100281;
pub const GLU_NURBS_ERROR32: GLenum = 100282;
pub const GLU_NURBS_ERROR33: GLenum = 100283;
pub const GLU_NURBS_ERROR34: GLenum = 100284;
pub const GLU_NURBS_ERROR35: GLenum = 100285;
pub const GLU_NURBS_ERROR36: GLenum = 100286;
pub const GLU_NURBS_ERROR37: GLenum = 100287;
