//! What a map's type means to GLU: the GL evaluator target it names (or a trim type), whether
//! it is the position map, and which callback receives its values in tessellator mode.

use crate::gl::types::GLenum;
use crate::gl::{MapTarget, Slot};
use crate::glu::consts::*;

/// Component count of a curve type; trim types are 2 and 3.
pub(crate) fn curve_type(target: GLenum) -> Option<usize> {
    match target {
        GLU_MAP1_TRIM_2 => Some(2),
        GLU_MAP1_TRIM_3 => Some(3),
        _ => MapTarget::from_enum(target).filter(|t| t.dims == 1).map(|t| t.components()),
    }
}

/// Values a control point of `kind` has in `gluNurbsCurve`, `gluNurbsSurface` and
/// `gluPwlCurve`: 2 and 3 for the trim types, a map target's components for the others;
/// `None` for a type GLU does not know. What a binding that has only a pointer (the C ABI)
/// must know to read the points.
#[must_use]
pub fn nurbs_point_components(kind: GLenum) -> Option<usize> {
    match kind {
        GLU_MAP1_TRIM_2 => Some(2),
        GLU_MAP1_TRIM_3 => Some(3),
        _ => MapTarget::from_enum(kind).map(|t| t.components()),
    }
}

pub(crate) fn is_trim_type(target: GLenum) -> bool {
    target == GLU_MAP1_TRIM_2 || target == GLU_MAP1_TRIM_3
}

fn slot_of(target: GLenum) -> Option<Slot> {
    MapTarget::from_enum(target).map(|t| t.slot)
}

/// Whether the map gives the vertex position (`GL_MAP*_VERTEX_3` or `_4`).
pub(crate) fn is_position(target: GLenum) -> bool {
    matches!(slot_of(target), Some(Slot::Vertex3 | Slot::Vertex4))
}

/// The callback that receives a map's values in tessellator mode.
pub(crate) fn callback_kind(target: GLenum) -> Option<GLenum> {
    match slot_of(target)? {
        Slot::Color4 | Slot::Index => Some(GLU_NURBS_COLOR),
        Slot::Normal => Some(GLU_NURBS_NORMAL),
        Slot::TexCoord1 | Slot::TexCoord2 | Slot::TexCoord3 | Slot::TexCoord4 => Some(GLU_NURBS_TEXTURE_COORD),
        Slot::Vertex3 | Slot::Vertex4 => Some(GLU_NURBS_VERTEX),
    }
}

/// Callback order per vertex (GLU `inDoEvalCoord`): texture coordinate, colour, normal.
pub(crate) fn attribute_rank(target: GLenum) -> u8 {
    match callback_kind(target) {
        Some(GLU_NURBS_TEXTURE_COORD) => 0,
        Some(GLU_NURBS_COLOR) => 1,
        _ => 2,
    }
}
