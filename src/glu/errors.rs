//! `gluErrorString` (GLU 9.0 `libutil/error.c`, the NURBS table of `libutil/glue.c` and the
//! tessellator's of `libtess`), with GLU's exact texts, typos included: every GL and GLU code
//! real GLU 9.0.2 answers (`tests/reference/glu/error_strings.txt` scans them all).

use super::consts::*;
use crate::gl::consts::*;
use crate::gl::types::GLenum;

/// The 37 NURBS error messages, entry n−1 for `GLU_NURBS_ERRORn`.
const NURBS_ERRORS: [&str; 37] = [
    "spline order un-supported",
    "too few knots",
    "valid knot range is empty",
    "decreasing knot sequence knot",
    "knot multiplicity greater than order of spline",
    "gluEndCurve() must follow gluBeginCurve()",
    "gluBeginCurve() must precede gluEndCurve()",
    "missing or extra geometric data",
    "can't draw piecewise linear trimming curves",
    "missing or extra domain data",
    "missing or extra domain data",
    "gluEndTrim() must precede gluEndSurface()",
    "gluBeginSurface() must precede gluEndSurface()",
    "curve of improper type passed as trim curve",
    "gluBeginSurface() must precede gluBeginTrim()",
    "gluEndTrim() must follow gluBeginTrim()",
    "gluBeginTrim() must precede gluEndTrim()",
    "invalid or missing trim curve",
    "gluBeginTrim() must precede gluPwlCurve()",
    "piecewise linear trimming curve referenced twice",
    "piecewise linear trimming curve and nurbs curve mixed",
    "improper usage of trim data type",
    "nurbs curve referenced twice",
    "nurbs curve and piecewise linear trimming curve mixed",
    "nurbs surface referenced twice",
    "invalid property",
    "gluEndSurface() must follow gluBeginSurface()",
    "intersecting or misoriented trim curves",
    "intersecting trim curves",
    "UNUSED",
    "unconnected trim curves",
    "unknown knot error",
    "negative vertex count encountered",
    "negative byte-stride encounteed",
    "unknown type descriptor",
    "null control point reference",
    "duplicate point on piecewise linear trimming curve",
];

/// The 6 tessellator error messages, entry n−1 for `GLU_TESS_ERRORn`.
const TESS_ERRORS: [&str; 6] = [
    "gluTessBeginPolygon() must precede a gluTessEndPolygon()",
    "gluTessBeginContour() must precede a gluTessEndContour()",
    "gluTessEndPolygon() must follow a gluTessBeginPolygon()",
    "gluTessEndContour() must follow a gluTessBeginContour()",
    "a coordinate is too large",
    "need combine callback",
];

/// `GL_INVALID_FRAMEBUFFER_OPERATION` (`GL_EXT_framebuffer_object`, not a GL 1.1 code), which
/// GLU's table names too.
const INVALID_FRAMEBUFFER_OPERATION: GLenum = 0x0506;

/// `gluErrorString(code)`: GL and GLU error codes, the tessellator's and the NURBS errors;
/// `None` (C's NULL) for anything else.
///
/// ```
/// use gleval::glu::consts::GLU_NURBS_ERROR34;
/// use gleval::glu::glu_error_string;
/// assert_eq!(glu_error_string(GLU_NURBS_ERROR34), Some("negative byte-stride encounteed"));
/// ```
#[must_use]
pub fn glu_error_string(code: GLenum) -> Option<&'static str> {
    let text = match code {
        GL_NO_ERROR => "no error",
        GL_INVALID_ENUM | GLU_INVALID_ENUM => "invalid enumerant",
        GL_INVALID_VALUE | GLU_INVALID_VALUE => "invalid value",
        GL_INVALID_OPERATION | GLU_INVALID_OPERATION => "invalid operation",
        GL_STACK_OVERFLOW => "stack overflow",
        GL_STACK_UNDERFLOW => "stack underflow",
        GL_OUT_OF_MEMORY | GLU_OUT_OF_MEMORY => "out of memory",
        INVALID_FRAMEBUFFER_OPERATION => "invalid framebuffer operation",
        GL_TABLE_TOO_LARGE => "table too large",
        GLU_INCOMPATIBLE_GL_VERSION => "incompatible gl version",
        GLU_TESS_ERROR1..=GLU_TESS_ERROR6 => TESS_ERRORS[(code - GLU_TESS_ERROR1) as usize],
        GLU_NURBS_ERROR1..=GLU_NURBS_ERROR37 => NURBS_ERRORS[(code - GLU_NURBS_ERROR1) as usize],
        _ => return None,
    };
    Some(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_matches_glu_numbering() {
        assert_eq!(glu_error_string(GLU_NURBS_ERROR1), Some("spline order un-supported"));
        assert_eq!(glu_error_string(GLU_NURBS_ERROR4), Some("decreasing knot sequence knot"));
        assert_eq!(glu_error_string(GLU_NURBS_ERROR37), Some("duplicate point on piecewise linear trimming curve"));
        assert_eq!(glu_error_string(GLU_NURBS_ERROR1 + 37), None);
        assert_eq!(glu_error_string(GLU_INVALID_VALUE), Some("invalid value"));
    }
}
