//! Clipping against GL's view volume (GL 1.1 spec §2.11) for the CPU rasteriser, in clip
//! space with z in wgpu's [0, w] convention: −w ≤ x ≤ w, −w ≤ y ≤ w, 0 ≤ z ≤ w. Every
//! attribute of a [`RasterVertex`] is linear in clip space, so a new vertex on a plane is a
//! plain linear mix of the two it lies between.

use super::units::SoftVertex;
use crate::gl::clip::{polygon_by, segment_by, Mix};
use crate::render::RasterVertex;

/// The six planes as distance functions (inside where ≥ 0).
const PLANES: [fn(&RasterVertex) -> f32; 6] = [
    |v| v.clip[3] + v.clip[0],
    |v| v.clip[3] - v.clip[0],
    |v| v.clip[3] + v.clip[1],
    |v| v.clip[3] - v.clip[1],
    |v| v.clip[2],
    |v| v.clip[3] - v.clip[2],
];

/// Whether the vertex lies inside the view volume.
pub(super) fn inside<V: SoftVertex>(v: &V) -> bool {
    PLANES.iter().all(|d| d(v.raster()) >= 0.0)
}

impl Mix for RasterVertex {
    fn mix(self, other: Self, t: f32) -> Self {
        let m4 = |p: [f32; 4], q: [f32; 4]| std::array::from_fn(|k| p[k] + (q[k] - p[k]) * t);
        RasterVertex {
            clip: m4(self.clip, other.clip),
            color: m4(self.color, other.color),
            secondary: m4(self.secondary, other.secondary),
            tex: m4(self.tex, other.tex),
            fog: self.fog + (other.fog - self.fog) * t,
            aa: m4(self.aa, other.aa),
        }
    }
}

/// A triangle clipped to the view volume (Sutherland–Hodgman, one plane at a time): a convex
/// polygon of up to nine vertices, empty when nothing is inside.
pub(super) fn polygon<V: SoftVertex>(triangle: &[V; 3]) -> Vec<V> {
    PLANES.iter().fold(
        triangle.to_vec(),
        |poly, d| {
            if poly.is_empty() {
                poly
            } else {
                polygon_by(&poly, |v: &V| d(v.raster()))
            }
        },
    )
}

/// A line segment clipped to the view volume (Liang–Barsky), or `None` when nothing of it is
/// inside.
pub(super) fn line<V: SoftVertex>(a: &V, b: &V) -> Option<(V, V)> {
    segment_by(*a, *b, PLANES.map(|d| move |v: &V| d(v.raster())))
}
