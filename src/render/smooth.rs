//! Smooth points and lines (GL 1.1 spec §3.3.2, §3.4.4) as Mesa's llvmpipe draws them: each
//! becomes a quad whose fragments carry coordinates from which the fragment stage computes a
//! coverage that multiplies their alpha (Mesa's draw module, `draw_pipe_aapoint.c`,
//! `draw_pipe_aaline.c` and the NIR passes of `nir_draw_helpers.c`). With blending the edges
//! fade; without it the quad's covered pixels are drawn opaque.
//!
//! - A point of size s is a square of half-side r = s/2 (r = 1 for s ≤ 2) around its centre,
//!   with (u, v) running over [−1, 1]² and k = (1 − 1/r)², the squared distance one pixel in
//!   from the edge: a fragment with d = u² + v² > 1 is discarded, the others get coverage
//!   (1 − d)/(1 − k) where d ≤ k, else 1. That selection (Mesa 22.3's NIR pass) makes the
//!   inner disc more than opaque and the outer ring 1: measured with alpha 0.2 at size 9,
//!   coverage 2.47 one half pixel from the centre, 1.725 at d = 0.32, 1 at d = 0.62, as
//!   (1 − d)/(1 − k) gives. With an opaque colour every kept fragment ends opaque.
//! - A line of width w is a rectangle half as wide as h = 1 (w ≤ 1) or w/2 + 1/2, extended by
//!   half a pixel past each end; across it x runs over [−h, h], along it z over [−l, l] with
//!   l = L/2 + 1/2 for a length L ≥ 1 pixel (l = L below): coverage = sat(h − |x|)·sat(l − |z|).

use super::corner::Corner;
use glam::Vec4;

/// The two triangles of a smooth point's square, or `None` when its centre is behind the eye.
pub(crate) fn point_quad(c: Corner, size: f32, [_, _, vw, vh]: [i32; 4]) -> Option<[Corner; 6]> {
    if c.clip.w <= 0.0 {
        return None;
    }
    let centre = c.clip / c.clip.w;
    let r = if size <= 2.0 { 1.0 } else { 0.5 * size };
    let k = (1.0 - 1.0 / r) * (1.0 - 1.0 / r);
    let (sx, sy) = (2.0 * r / vw.max(1) as f32, 2.0 * r / vh.max(1) as f32);
    let corner = |u: f32, v: f32| Corner {
        clip: Vec4::new(centre.x + u * sx, centre.y + v * sy, centre.z, 1.0),
        aa: Vec4::new(u, v, k, 1.0),
        ..c
    };
    let q = [corner(-1.0, -1.0), corner(1.0, -1.0), corner(1.0, 1.0), corner(-1.0, 1.0)];
    Some([q[0], q[1], q[2], q[0], q[2], q[3]])
}

/// The two triangles of a smooth line's rectangle, or `None` for a line of no length or with
/// an end behind the eye. The rectangle's ends keep the attributes of the line's ends.
pub(crate) fn line_quad(a: Corner, b: Corner, width: f32, [_, _, vw, vh]: [i32; 4]) -> Option<[Corner; 6]> {
    if a.clip.w <= 0.0 || b.clip.w <= 0.0 {
        return None;
    }
    let (pa, pb) = (a.clip / a.clip.w, b.clip / b.clip.w);
    let (hx, hy) = (0.5 * vw.max(1) as f32, 0.5 * vh.max(1) as f32);
    let (dx, dy) = ((pb.x - pa.x) * hx, (pb.y - pa.y) * hy);
    let length = (dx * dx + dy * dy).sqrt();
    if !(length > 0.0 && length.is_finite()) {
        return None;
    }
    let (c, s) = (dx / length, dy / length);
    let h = if width <= 1.0 { 1.0 } else { 0.5 * width + 0.5 };
    let l = if length < 1.0 { length } else { 0.5 * length + 0.5 };
    // Window offsets (along, across) → NDC, the corner at the `end` of the line.
    let corner = |end: Corner, p: Vec4, along: f32, across: f32| Corner {
        clip: Vec4::new(p.x + (along * c - across * s) / hx, p.y + (along * s + across * c) / hy, p.z, 1.0),
        aa: Vec4::new(-across, h, along.signum() * l, l),
        ..end
    };
    let v0 = corner(a, pa, -0.5, h);
    let v1 = corner(a, pa, -0.5, -h);
    let v2 = corner(b, pb, 0.5, h);
    let v3 = corner(b, pb, 0.5, -h);
    Some([v2, v1, v0, v3, v1, v2])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f32, y: f32) -> Corner {
        Corner::at(x, y)
    }

    #[test]
    fn a_line_rectangle_is_extended_by_half_a_pixel_and_one_pixel_each_side() {
        // A horizontal line of 18 pixels in a 24 × 24 viewport, width 1.
        let ndc = |px: f32| px / 12.0 - 1.0;
        let q = line_quad(at(ndc(2.5), ndc(12.3)), at(ndc(20.5), ndc(12.3)), 1.0, [0, 0, 24, 24]).unwrap();
        let xs: Vec<f32> = q.iter().map(|c| (c.clip.x + 1.0) * 12.0).collect();
        let ys: Vec<f32> = q.iter().map(|c| (c.clip.y + 1.0) * 12.0).collect();
        let span = |v: &[f32]| (v.iter().cloned().fold(f32::MAX, f32::min), v.iter().cloned().fold(f32::MIN, f32::max));
        let ((x0, x1), (y0, y1)) = (span(&xs), span(&ys));
        assert!((x0 - 2.0).abs() < 1e-4 && (x1 - 21.0).abs() < 1e-4);
        assert!((y0 - 11.3).abs() < 1e-4 && (y1 - 13.3).abs() < 1e-4);
        // Along: l = 9.5 at the rectangle's ends; across: ±1.
        assert!(q.iter().all(|c| c.aa.w == 9.5 && c.aa.z.abs() == 9.5 && c.aa.x.abs() == 1.0 && c.aa.y == 1.0));
    }

    #[test]
    fn small_points_have_a_radius_of_one_pixel() {
        let q = point_quad(at(0.0, 0.0), 1.0, [0, 0, 20, 20]).unwrap();
        // r = 1 pixel = 0.1 in NDC at 20 pixels.
        assert!(q.iter().all(|c| (c.clip.x.abs() - 0.1).abs() < 1e-6 && c.aa.z == 0.0));
        let q = point_quad(at(0.0, 0.0), 8.0, [0, 0, 20, 20]).unwrap();
        assert!(q.iter().all(|c| (c.clip.x.abs() - 0.4).abs() < 1e-6 && c.aa.z == 0.5625));
    }
}
