//! Clipping against GL's view volume (GL 1.1 spec §2.11) for the CPU rasteriser, in clip
//! space with z in wgpu's [0, w] convention: −w ≤ x ≤ w, −w ≤ y ≤ w, 0 ≤ z ≤ w. Every
//! attribute of a [`RasterVertex`] is linear in clip space, so a new vertex on a plane is a
//! plain linear mix of the two it lies between.

use crate::render::RasterVertex;

/// The signed distances to the six planes: inside where all are ≥ 0.
fn distances(v: &RasterVertex) -> [f32; 6] {
    let [x, y, z, w] = v.clip;
    [w + x, w - x, w + y, w - y, z, w - z]
}

/// Whether the vertex lies inside the view volume.
pub(super) fn inside(v: &RasterVertex) -> bool {
    distances(v).iter().all(|&d| d >= 0.0)
}

/// The vertex a share `t` of the way from `a` to `b`.
fn mix(a: &RasterVertex, b: &RasterVertex, t: f32) -> RasterVertex {
    let m4 = |p: [f32; 4], q: [f32; 4]| std::array::from_fn(|k| p[k] + (q[k] - p[k]) * t);
    RasterVertex {
        clip: m4(a.clip, b.clip),
        color: m4(a.color, b.color),
        tex: m4(a.tex, b.tex),
        fog: a.fog + (b.fog - a.fog) * t,
        aa: m4(a.aa, b.aa),
    }
}

/// A triangle clipped to the view volume (Sutherland–Hodgman, one plane at a time): a convex
/// polygon of up to nine vertices, empty when nothing is inside.
pub(super) fn polygon(triangle: &[RasterVertex; 3]) -> Vec<RasterVertex> {
    let mut poly: Vec<RasterVertex> = triangle.to_vec();
    for plane in 0..6 {
        if poly.is_empty() {
            break;
        }
        let mut out = Vec::with_capacity(poly.len() + 1);
        for k in 0..poly.len() {
            let (a, b) = (&poly[k], &poly[(k + 1) % poly.len()]);
            let (da, db) = (distances(a)[plane], distances(b)[plane]);
            if da >= 0.0 {
                out.push(*a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                out.push(mix(a, b, da / (da - db)));
            }
        }
        poly = out;
    }
    poly
}

/// A line segment clipped to the view volume (Liang–Barsky on the six distances), or `None`
/// when nothing of it is inside.
pub(super) fn line(a: &RasterVertex, b: &RasterVertex) -> Option<(RasterVertex, RasterVertex)> {
    let (da, db) = (distances(a), distances(b));
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for plane in 0..6 {
        let (p, q) = (da[plane], db[plane]);
        if p < 0.0 && q < 0.0 {
            return None;
        }
        if p < 0.0 {
            t0 = t0.max(p / (p - q));
        } else if q < 0.0 {
            t1 = t1.min(p / (p - q));
        }
    }
    (t0 <= t1).then(|| (mix(a, b, t0), mix(a, b, t1)))
}
