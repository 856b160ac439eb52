//! Polygon offset (GL 1.1 spec §3.5.5): o = factor · DZ + units · r, added to the window depth
//! of every fragment of the polygon, where DZ = max(|∂z/∂x|, |∂z/∂y|) over the polygon's plane
//! in window coordinates and r the depth buffer's smallest resolvable difference.

use super::corner::Corner;
use crate::gl::PolygonOffset;
use glam::Vec3;

/// r as llvmpipe takes it for the 24-bit depth buffer of the reference programs: twice
/// 1/(2²⁴ − 1) (`lp_state_setup.c` scales the units by `mrd · 2`).
const RESOLVABLE: f32 = 2.0 / 16_777_215.0;

/// The offset of the polygon `corners` (clip coordinates) drawn in `viewport` with the depth
/// range `[near, far]`.
pub(crate) fn polygon_offset(
    corners: &[Corner],
    viewport: [i32; 4],
    [near, far]: [f32; 2],
    offset: &PolygonOffset,
) -> f32 {
    let (sx, sy, sz) = (viewport[2] as f32 * 0.5, viewport[3] as f32 * 0.5, (far - near) * 0.5);
    let window: Vec<Vec3> = corners
        .iter()
        .map(|c| {
            let n = c.clip / c.clip.w;
            Vec3::new(n.x * sx, n.y * sy, n.z * sz)
        })
        .collect();
    offset.factor * depth_slope(&window) + offset.units * RESOLVABLE
}

/// max(|∂z/∂x|, |∂z/∂y|) of the polygon's plane, from its normal by Newell's method (robust
/// to collinear leading corners); 0 for a polygon seen edge-on (it covers no pixel).
fn depth_slope(points: &[Vec3]) -> f32 {
    let normal: Vec3 = (0..points.len())
        .map(|k| {
            let (a, b) = (points[k], points[(k + 1) % points.len()]);
            Vec3::new((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y))
        })
        .sum();
    if normal.z == 0.0 {
        return 0.0;
    }
    (normal.x / normal.z).abs().max((normal.y / normal.z).abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_slope_of_a_tilted_plane() {
        // z = 0.25·x − 0.5·y: DZ = 0.5.
        let z = |x: f32, y: f32| 0.25 * x - 0.5 * y;
        let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (0.0, 2.0)].map(|(x, y)| Vec3::new(x, y, z(x, y)));
        assert!((depth_slope(&pts) - 0.5).abs() < 1e-6);
    }
}
