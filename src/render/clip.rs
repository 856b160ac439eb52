//! Clipping by the user's clip planes (GL 1.1 spec §2.11): a point is kept whole or not at all,
//! a line is cut where it crosses a plane, a polygon is cut into the polygon inside every plane
//! (Sutherland–Hodgman), its attributes interpolated at the cuts. The view volume is left to
//! the rasteriser (the GPU's, or `soft::clip`), except where stippling needs a line's drawn
//! length (`view_volume`). The clippers themselves are `gl::clip`'s, which feedback shares.

use super::corner::Corner;
use crate::gl::clip::{polygon_by, segment_by, Mix};
use glam::Vec4;

impl Mix for Corner {
    fn mix(self, other: Self, t: f32) -> Self {
        self.lerp(other, t)
    }
}

/// Whether `c` is inside every plane: p · eye ≥ 0.
pub(crate) fn point_inside(c: &Corner, planes: &[[f32; 4]]) -> bool {
    planes.iter().all(|p| Vec4::from_array(*p).dot(c.eye) >= 0.0)
}

/// The part of the segment inside every plane, if any.
pub(crate) fn segment(a: Corner, b: Corner, planes: &[[f32; 4]]) -> Option<(Corner, Corner)> {
    segment_by(a, b, planes.iter().map(|p| |c: &Corner| Vec4::from_array(*p).dot(c.eye)))
}

/// The part of the segment inside GL's view volume (−w ≤ x, y, z ≤ w), if any.
pub(crate) fn view_volume(a: Corner, b: Corner) -> Option<(Corner, Corner)> {
    let planes: [fn(&Corner) -> f32; 6] = [
        |c| c.clip.w + c.clip.x,
        |c| c.clip.w - c.clip.x,
        |c| c.clip.w + c.clip.y,
        |c| c.clip.w - c.clip.y,
        |c| c.clip.w + c.clip.z,
        |c| c.clip.w - c.clip.z,
    ];
    segment_by(a, b, planes)
}

/// The polygon inside every plane (empty or fewer than three corners when nothing is left).
pub(crate) fn polygon(corners: Vec<Corner>, planes: &[[f32; 4]]) -> Vec<Corner> {
    planes.iter().fold(corners, |poly, p| {
        let plane = Vec4::from_array(*p);
        polygon_by(&poly, |c: &Corner| plane.dot(c.eye))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f32, y: f32) -> Corner {
        Corner::at(x, y)
    }

    #[test]
    fn a_segment_is_cut_where_it_crosses() {
        // x ≥ 0.25: the segment from x = -1 to 1 keeps [0.25, 1], its colour interpolated.
        let mut a = at(-1.0, 0.0);
        a.color = Vec4::ZERO;
        let (p, q) = segment(a, at(1.0, 0.0), &[[1.0, 0.0, 0.0, -0.25]]).unwrap();
        assert_eq!((p.clip.x, q.clip.x), (0.25, 1.0));
        assert!((p.color.x - 0.625).abs() < 1e-6);
        assert!(segment(at(-1.0, 0.0), at(0.0, 0.0), &[[1.0, 0.0, 0.0, -0.25]]).is_none());
    }

    #[test]
    fn a_square_cut_by_a_diagonal_plane_keeps_its_area_half() {
        let square = vec![at(0.0, 0.0), at(1.0, 0.0), at(1.0, 1.0), at(0.0, 1.0)];
        // x + y ≤ 1 keeps the lower-left triangle, of area 1/2.
        let kept = polygon(square, &[[-1.0, -1.0, 0.0, 1.0]]);
        let area: f32 = (0..kept.len())
            .map(|k| {
                let (a, b) = (kept[k].clip, kept[(k + 1) % kept.len()].clip);
                a.x * b.y - b.x * a.y
            })
            .sum::<f32>()
            / 2.0;
        assert!((area - 0.5).abs() < 1e-6, "{area}");
    }
}
