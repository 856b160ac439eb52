//! Surface normals for the `GLU_NURBS_NORMAL` callback and for GL's `GL_AUTO_NORMAL` on trimmed
//! surfaces: the cross product of the partials, with the rational correction.

use super::pieces::SurfacePatches;
use crate::math::rational::{cross, normalize, rational_derivative};

/// The unit normal of the position map at (u, v): du × dv with the rational correction, zero
/// left zero. A vanishing partial is re-evaluated slightly inside the domain (GLU's
/// `AVOID_ZERO_NORMAL`).
pub(crate) fn surface_normal(pos: &SurfacePatches, k: usize, u: f64, v: f64, domain: [f64; 4]) -> [f32; 3] {
    let partials = |u: f64, v: f64| pos.eval(u, v);
    let Some(mut s) = partials(u, v) else { return [0.0; 3] };
    let tiny = |d: [f64; 4]| d.iter().all(|c| c.abs() <= 1e-6);
    if tiny(s.du) || tiny(s.dv) {
        let nudge =
            |x: f64, lo: f64, hi: f64| if x - lo < hi - x { x + 0.001 * (hi - lo) } else { x - 0.001 * (hi - lo) };
        if let Some(n) = partials(nudge(u, domain[0], domain[1]), nudge(v, domain[2], domain[3])) {
            if tiny(s.du) {
                s.du = n.du;
            }
            if tiny(s.dv) {
                s.dv = n.dv;
            }
        }
    }
    let (a, b) = if k == 4 {
        (rational_derivative(s.point, s.du), rational_derivative(s.point, s.dv))
    } else {
        ([s.du[0], s.du[1], s.du[2]], [s.dv[0], s.dv[1], s.dv[2]])
    };
    normalize(cross(a, b)).map(|c| c as f32)
}
