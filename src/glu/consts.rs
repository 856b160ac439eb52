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

// GL/glu.h: Boolean.
pub const GLU_FALSE: GLenum = 0;
pub const GLU_TRUE: GLenum = 1;

// GL/glu.h: StringName.
pub const GLU_VERSION: GLenum = 100800;
pub const GLU_EXTENSIONS: GLenum = 100801;

// GL/glu.h: NurbsCallback.
pub const GLU_NURBS_BEGIN_EXT: GLenum = 100164;
pub const GLU_NURBS_VERTEX_EXT: GLenum = 100165;
pub const GLU_NURBS_NORMAL_EXT: GLenum = 100166;
pub const GLU_NURBS_COLOR_EXT: GLenum = 100167;
pub const GLU_NURBS_TEX_COORD_EXT: GLenum = 100168;
pub const GLU_NURBS_END_EXT: GLenum = 100169;
pub const GLU_NURBS_BEGIN_DATA_EXT: GLenum = 100170;
pub const GLU_NURBS_VERTEX_DATA_EXT: GLenum = 100171;
pub const GLU_NURBS_NORMAL_DATA_EXT: GLenum = 100172;
pub const GLU_NURBS_COLOR_DATA_EXT: GLenum = 100173;
pub const GLU_NURBS_TEX_COORD_DATA_EXT: GLenum = 100174;
pub const GLU_NURBS_END_DATA_EXT: GLenum = 100175;

// GL/glu.h: NurbsProperty.
pub const GLU_NURBS_MODE_EXT: GLenum = 100160;
pub const GLU_NURBS_TESSELLATOR_EXT: GLenum = 100161;
pub const GLU_NURBS_RENDERER_EXT: GLenum = 100162;

// GL/glu.h: NurbsSampling.
pub const GLU_OBJECT_PARAMETRIC_ERROR_EXT: GLenum = 100208;
pub const GLU_OBJECT_PATH_LENGTH_EXT: GLenum = 100209;

// GL/glu.h: QuadricDrawStyle.
pub const GLU_POINT: GLenum = 100010;
pub const GLU_LINE: GLenum = 100011;
pub const GLU_SILHOUETTE: GLenum = 100013;

// GL/glu.h: QuadricNormal.
pub const GLU_SMOOTH: GLenum = 100000;
pub const GLU_FLAT: GLenum = 100001;
pub const GLU_NONE: GLenum = 100002;

// GL/glu.h: QuadricOrientation.
pub const GLU_OUTSIDE: GLenum = 100020;
pub const GLU_INSIDE: GLenum = 100021;

// GL/glu.h: TessCallback.
pub const GLU_TESS_BEGIN: GLenum = 100100;
pub const GLU_BEGIN: GLenum = 100100;
pub const GLU_TESS_VERTEX: GLenum = 100101;
pub const GLU_VERTEX: GLenum = 100101;
pub const GLU_TESS_END: GLenum = 100102;
pub const GLU_END: GLenum = 100102;
pub const GLU_TESS_ERROR: GLenum = 100103;
pub const GLU_TESS_EDGE_FLAG: GLenum = 100104;
pub const GLU_EDGE_FLAG: GLenum = 100104;
pub const GLU_TESS_COMBINE: GLenum = 100105;
pub const GLU_TESS_BEGIN_DATA: GLenum = 100106;
pub const GLU_TESS_VERTEX_DATA: GLenum = 100107;
pub const GLU_TESS_END_DATA: GLenum = 100108;
pub const GLU_TESS_ERROR_DATA: GLenum = 100109;
pub const GLU_TESS_EDGE_FLAG_DATA: GLenum = 100110;
pub const GLU_TESS_COMBINE_DATA: GLenum = 100111;

// GL/glu.h: TessContour.
pub const GLU_CW: GLenum = 100120;
pub const GLU_CCW: GLenum = 100121;
pub const GLU_INTERIOR: GLenum = 100122;
pub const GLU_EXTERIOR: GLenum = 100123;
pub const GLU_UNKNOWN: GLenum = 100124;

// GL/glu.h: TessProperty.
pub const GLU_TESS_WINDING_RULE: GLenum = 100140;
pub const GLU_TESS_BOUNDARY_ONLY: GLenum = 100141;
pub const GLU_TESS_TOLERANCE: GLenum = 100142;

// GL/glu.h: TessError.
pub const GLU_TESS_ERROR1: GLenum = 100151;
pub const GLU_TESS_ERROR2: GLenum = 100152;
pub const GLU_TESS_ERROR3: GLenum = 100153;
pub const GLU_TESS_ERROR4: GLenum = 100154;
pub const GLU_TESS_ERROR5: GLenum = 100155;
pub const GLU_TESS_ERROR6: GLenum = 100156;
pub const GLU_TESS_ERROR7: GLenum = 100157;
pub const GLU_TESS_ERROR8: GLenum = 100158;
pub const GLU_TESS_MISSING_BEGIN_POLYGON: GLenum = 100151;
pub const GLU_TESS_MISSING_BEGIN_CONTOUR: GLenum = 100152;
pub const GLU_TESS_MISSING_END_POLYGON: GLenum = 100153;
pub const GLU_TESS_MISSING_END_CONTOUR: GLenum = 100154;
pub const GLU_TESS_COORD_TOO_LARGE: GLenum = 100155;
pub const GLU_TESS_NEED_COMBINE_CALLBACK: GLenum = 100156;

// GL/glu.h: TessWinding.
pub const GLU_TESS_WINDING_ODD: GLenum = 100130;
pub const GLU_TESS_WINDING_NONZERO: GLenum = 100131;
pub const GLU_TESS_WINDING_POSITIVE: GLenum = 100132;
pub const GLU_TESS_WINDING_NEGATIVE: GLenum = 100133;
pub const GLU_TESS_WINDING_ABS_GEQ_TWO: GLenum = 100134;

// GL/glu.h: the polygon tessellator's largest coordinate (a double, not an enum).
pub const GLU_TESS_MAX_COORD: f64 = 1.0e150;
