//! `GLU_CULLING`: a curve or surface whose control points all lie outside one clip plane is not
//! drawn (GLU `mapdesc.cc`, `Mapdesc::cullCheck`; spec 2.5).

use crate::glu::model::object::NurbsObject;
use glam::Vec4;

/// True when culling is on and every control point lies outside one clip plane.
pub(crate) fn culled(obj: &NurbsObject, points: &[f64], k: usize) -> bool {
    if !obj.props.culling {
        return false;
    }
    let m = obj.matrices.projection * obj.matrices.modelview;
    let mut inside_any = [false; 6];
    for p in points.chunks_exact(k) {
        let w = if k == 4 { p[3] } else { 1.0 };
        let c = m * Vec4::new(p[0] as f32, p[1] as f32, p.get(2).copied().unwrap_or(0.0) as f32, w as f32);
        let tests = [c.x >= -c.w, c.x <= c.w, c.y >= -c.w, c.y <= c.w, c.z >= -c.w, c.z <= c.w];
        for (seen, ok) in inside_any.iter_mut().zip(tests) {
            *seen |= ok;
        }
    }
    inside_any.iter().any(|seen| !seen)
}
