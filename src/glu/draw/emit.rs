//! One surface vertex through the callbacks, when more than begin, vertex and end are
//! registered: its attribute maps' values and normal, then its position (GLU `inDoEvalCoord`).

use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::evaluation::normals::surface_normal;
use crate::glu::evaluation::pieces::SurfacePatches;
use crate::glu::model::object::NurbsObject;
use crate::glu::model::targets::callback_kind;

/// The attribute maps' values and the normal (if wanted) of the vertex at (u, v).
pub(crate) fn emit_attributes(
    gl: &mut Gl,
    obj: &mut NurbsObject,
    (pos, attributes, k): (&SurfacePatches, &[SurfacePatches], usize),
    u: f64,
    v: f64,
) {
    let mut has_normal_map = false;
    for map in attributes {
        let (Some(s), Some(kind)) = (map.eval(u, v), callback_kind(map.target)) else { continue };
        has_normal_map |= kind == GLU_NURBS_NORMAL;
        let values: Vec<f32> = s.point[..map.patches.dim].iter().map(|&c| c as f32).collect();
        obj.callbacks.attribute(gl, kind, &values);
    }
    if !has_normal_map && obj.callbacks.wants_normals() {
        let p = &pos.patches;
        let domain = [
            p.uintervals[0].0,
            p.uintervals[p.uintervals.len() - 1].1,
            p.vintervals[0].0,
            p.vintervals[p.vintervals.len() - 1].1,
        ];
        obj.callbacks.attribute(gl, GLU_NURBS_NORMAL, &surface_normal(pos, k, u, v, domain));
    }
}
