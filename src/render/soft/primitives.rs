//! Triangles, lines and points to fragments, for the CPU rasteriser. Positions are snapped to
//! 1/256 of a pixel, as llvmpipe's setup does (its `FIXED_ORDER`), and a triangle covers the
//! pixels whose centres lie inside its three edge functions, those exactly on an edge only for
//! left and bottom edges in GL's window coordinates (y up): llvmpipe's rule for GL's
//! framebuffers (its `bottom_edge_rule`), measured on Mesa 22.3 (a square with edges on pixel
//! centres 10.5 and 20.5 fills columns and rows 10 to 19). GL 1.1 §3.5.1 asks for such a rule.
//! Attributes are interpolated perspective-correctly (§3.5.1, eq. 3.4), depth linearly in
//! window space.

use super::clip;
use super::fragment::{Fragment, TexSlope};
use super::units::{SoftVertex, UnitCoords};
use super::Target;

/// Sub-pixel steps per pixel.
const SUBPIXEL: f32 = 256.0;

/// The farthest window coordinate the triangle setup takes, in pixels.
const WINDOW_LIMIT: f32 = (1 << 20) as f32;

/// The fragment whose vertices carry `weights` (perspective-corrected, summing to 1), as the
/// first vertex's values plus the weighted differences to the others: a value equal at every
/// vertex comes out exactly (a flat colour of 0.9 stays 0.9 and is stored as 230, as llvmpipe's
/// plane equations give it, where a weighted sum may give 0.8999999 and 229).
fn mix<V: SoftVertex, const N: usize>(v: &[&V; N], weights: [f32; N]) -> Fragment<V::Units> {
    let first_units = v[0].units();
    let first = v[0].raster();
    let mut f = Fragment {
        color: first.color,
        secondary: first.secondary,
        tex: first.tex,
        units: first_units,
        fog: first.fog,
        aa: first.aa,
    };
    for (vertex, w) in v.iter().zip(weights).skip(1) {
        f.units.add_weighted(&first_units, &vertex.units(), w);
        let v = vertex.raster();
        for k in 0..4 {
            f.color[k] += (v.color[k] - first.color[k]) * w;
            f.secondary[k] += (v.secondary[k] - first.secondary[k]) * w;
            f.tex[k] += (v.tex[k] - first.tex[k]) * w;
            f.aa[k] += (v.aa[k] - first.aa[k]) * w;
        }
        f.fog += (v.fog - first.fog) * w;
    }
    f
}

/// Window-space barycentric weights `l` made perspective-correct with each vertex's 1/w.
fn perspective<const N: usize>(l: [f32; N], inv_w: [f32; N]) -> [f32; N] {
    let b: [f32; N] = std::array::from_fn(|k| l[k] * inv_w[k]);
    let sum: f32 = b.iter().sum();
    if sum == 0.0 || !sum.is_finite() {
        return l;
    }
    b.map(|x| x / sum)
}

/// The texture coordinates' change from `here` to `there` (fragments of the same primitive).
fn tex_delta<U: UnitCoords>(here: &Fragment<U>, there: &Fragment<U>) -> ([f32; 4], U) {
    (std::array::from_fn(|k| there.tex[k] - here.tex[k]), U::delta(&here.units, &there.units))
}

/// The slope of a fragment with neighbours `right` and `below`.
fn slope<U: UnitCoords>(f: &Fragment<U>, right: &Fragment<U>, below: &Fragment<U>) -> TexSlope<U> {
    let ((dx, units_dx), (dy, units_dy)) = (tex_delta(f, right), tex_delta(f, below));
    TexSlope { dx, dy, units_dx, units_dy }
}

/// Draws a triangle, clipped to the view volume when it crosses it.
pub(super) fn triangle<V: SoftVertex>(target: &mut Target<'_>, v: [V; 3]) {
    if v.iter().all(clip::inside) {
        fill(target, [&v[0], &v[1], &v[2]]);
        return;
    }
    let poly = clip::polygon(&v);
    for k in 1..poly.len().saturating_sub(1) {
        fill(target, [&poly[0], &poly[k], &poly[k + 1]]);
    }
}

/// A triangle inside the view volume: its pixels within the scissor.
fn fill<V: SoftVertex>(target: &mut Target<'_>, mut v: [&V; 3]) {
    let mut p = v.map(|v| target.map.project(v.raster().clip));
    if p.iter().flatten().any(|c| !c.is_finite()) {
        return;
    }
    // Clipped, a vertex lies within its viewport; clamping keeps the edge functions' products
    // inside i64 for viewports far beyond any GL's maximum (Mesa clamps them to 16384).
    let fixed = |c: f32| (c.clamp(-WINDOW_LIMIT, WINDOW_LIMIT) * SUBPIXEL).round() as i64;
    let mut xy: [[i64; 2]; 3] = p.map(|p| [fixed(p[0]), fixed(p[1])]);
    let edge = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    let mut area = edge(xy[1], xy[2], xy[0]);
    if area == 0 {
        return;
    }
    if area < 0 {
        // Both windings are drawn (the assembler culled already): make the area positive.
        v.swap(1, 2);
        p.swap(1, 2);
        xy.swap(1, 2);
        area = -area;
    }
    // Edge k runs from a = vertex k+1 to b = vertex k+2, opposite vertex k:
    // E_k(p) = (bx − ax)(py − ay) − (by − ay)(px − ax), kept as its changes per sub-pixel
    // step in x (dx) and y (dy); E_k at vertex k is the doubled area.
    let ends = |k: usize| (xy[(k + 1) % 3], xy[(k + 2) % 3]);
    let dx: [i64; 3] = std::array::from_fn(|k| -(ends(k).1[1] - ends(k).0[1]));
    let dy: [i64; 3] = std::array::from_fn(|k| ends(k).1[0] - ends(k).0[0]);
    // A fragment exactly on an edge belongs to the triangle if the edge is a left edge
    // (inside lies to its right) or a bottom edge in GL's window (horizontal, inside above it
    // there, below it in these rows counted from the top).
    let top_left: [bool; 3] = std::array::from_fn(|k| dx[k] > 0 || (dx[k] == 0 && dy[k] < 0));
    let [sx0, sy0, sx1, sy1] = target.scissor;
    let pixel = |c: i64, lo: u32, hi: u32| c.div_euclid(SUBPIXEL as i64).clamp(i64::from(lo), i64::from(hi)) as u32;
    let (x0, x1) = (
        pixel(xy.iter().map(|c| c[0]).min().unwrap_or(0), sx0, sx1),
        pixel(xy.iter().map(|c| c[0]).max().unwrap_or(0) + 256, sx0, sx1),
    );
    let (y0, y1) = (
        pixel(xy.iter().map(|c| c[1]).min().unwrap_or(0), sy0, sy1),
        pixel(xy.iter().map(|c| c[1]).max().unwrap_or(0) + 256, sy0, sy1),
    );
    let inv_w = p.map(|p| p[3]);
    let z = p.map(|p| p[2]);
    let inv_area = 1.0 / area as f32;
    let step = SUBPIXEL as i64;
    let textured = target.textured();
    let at = |e: [i64; 3]| {
        let l: [f32; 3] = e.map(|e| e as f32 * inv_area);
        (l, mix(&v, perspective(l, inv_w)))
    };
    for y in y0..y1 {
        let py = i64::from(y) * step + step / 2;
        let px = i64::from(x0) * step + step / 2;
        let mut e: [i64; 3] = std::array::from_fn(|k| {
            let a = ends(k).0;
            dy[k] * (py - a[1]) + dx[k] * (px - a[0])
        });
        for x in x0..x1 {
            let covered = (0..3).all(|k| e[k] > 0 || (e[k] == 0 && top_left[k]));
            if covered {
                let (l, f) = at(e);
                // From vertex 0 by the other two's differences, as llvmpipe's plane equation
                // does: a polygon of one depth has that depth at every fragment (the three
                // weights need not add up to exactly 1 in floats).
                let depth = z[0] + l[1] * (z[1] - z[0]) + l[2] * (z[2] - z[0]);
                let slope = if textured {
                    let right = at(std::array::from_fn(|k| e[k] + dx[k] * step)).1;
                    let below = at(std::array::from_fn(|k| e[k] + dy[k] * step)).1;
                    slope(&f, &right, &below)
                } else {
                    TexSlope::default()
                };
                target.fragment((x, y), depth, &f, &slope);
            }
            for k in 0..3 {
                e[k] += dx[k] * step;
            }
        }
    }
}

/// Draws a one-pixel line, clipped to the view volume: GL's diamond-exit rule as the usual
/// approximation has it (§3.4.1): along the major axis, each pixel whose centre lies in
/// [start, end) gets the fragment on the line at that centre. Ends are snapped to 1/256 of a
/// pixel as llvmpipe's are; a line exactly on the boundary between two pixels takes the one
/// below or to the left in GL's window (llvmpipe draws a line as a one-pixel-wide quad under
/// its fill rule; measured on Mesa 22.3: a horizontal line at window y = 30 fills row 29, a
/// vertical one at x = 30 column 29).
pub(super) fn line<V: SoftVertex>(target: &mut Target<'_>, a: &V, b: &V) {
    let Some((a, b)) = clip::line(a, b) else { return };
    let snap = |mut p: [f32; 4]| {
        p[0] = (p[0] * SUBPIXEL).round() / SUBPIXEL;
        p[1] = (p[1] * SUBPIXEL).round() / SUBPIXEL;
        p
    };
    let (pa, pb) = (snap(target.map.project(a.raster().clip)), snap(target.map.project(b.raster().clip)));
    if pa.iter().chain(&pb).any(|c| !c.is_finite()) {
        return;
    }
    let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
    if dx == 0.0 && dy == 0.0 {
        return;
    }
    let x_major = dx.abs() >= dy.abs();
    let (major, minor) = if x_major { (0, 1) } else { (1, 0) };
    let (start, end) = (pa[major], pb[major]);
    let length = end - start;
    // Pixels k with centre k + ½ in [start, end) (or (end, start] backwards).
    let (first, last) = if length > 0.0 {
        ((start - 0.5).ceil(), (end - 0.5).ceil() - 1.0)
    } else {
        ((end - 0.5).floor() + 1.0, (start - 0.5).floor())
    };
    let [sx0, sy0, sx1, sy1] = target.scissor;
    let (lo, hi) = if x_major { (sx0, sx1) } else { (sy0, sy1) };
    let first = first.max(lo as f32) as i64;
    let last = last.min(hi as f32 - 1.0) as i64;
    let (lo_minor, hi_minor) = if x_major { (sy0, sy1) } else { (sx0, sx1) };
    let ends = [&a, &b];
    let inv_w = [pa[3], pb[3]];
    let textured = target.textured();
    let at = |t: f32| mix(&ends, perspective([1.0 - t, t], inv_w));
    for k in first..=last {
        let centre = k as f32 + 0.5;
        let t = (centre - start) / length;
        let m = pa[minor] + t * (pb[minor] - pa[minor]);
        // Rows count down from the top: the lower GL row is the floor; columns count up: the
        // left column of a boundary is the one below it.
        let m = if x_major { m.floor() } else { m.ceil() - 1.0 };
        if m < lo_minor as f32 || m >= hi_minor as f32 {
            continue;
        }
        let f = at(t);
        let depth = pa[2] + t * (pb[2] - pa[2]);
        let slope = if textured {
            let (along, units) = tex_delta(&f, &at(t + 1.0 / length.abs()));
            let none = ([0.0; 4], V::Units::default());
            let ((dx, units_dx), (dy, units_dy)) =
                if x_major { ((along, units), none) } else { (none, (along, units)) };
            TexSlope { dx, dy, units_dx, units_dy }
        } else {
            TexSlope::default()
        };
        let pixel = if x_major { (k as u32, m as u32) } else { (m as u32, k as u32) };
        target.fragment(pixel, depth, &f, &slope);
    }
}

/// Draws a one-pixel point: the pixel holding its window position, if the point lies inside
/// the view volume (§3.3).
pub(super) fn point<V: SoftVertex>(target: &mut Target<'_>, v: &V) {
    if !clip::inside(v) {
        return;
    }
    let p = target.map.project(v.raster().clip);
    if p.iter().any(|c| !c.is_finite()) {
        return;
    }
    let (x, y) = (p[0].floor(), p[1].floor());
    let [sx0, sy0, sx1, sy1] = target.scissor;
    if x < sx0 as f32 || y < sy0 as f32 || x >= sx1 as f32 || y >= sy1 as f32 {
        return;
    }
    let f = mix(&[v], [1.0]);
    target.fragment((x as u32, y as u32), p[2], &f, &TexSlope::default());
}
