//! The CPU rasteriser against closed forms: coverage (every pixel of a tiled area drawn
//! exactly once, counted by additive blending), interpolation at pixel centres, perspective
//! correction, clipping, GL's line rule, and no panic on any input.

use super::rasterize;
use crate::gl::consts::*;
use crate::render::assemble::{Batch, DrawList, FragmentState, Op, RasterVertex, Topology};
use proptest::prelude::*;

const W: u32 = 16;
const H: u32 = 12;

/// A vertex at window position (x, y) (GL's, origin bottom-left) of a W × H viewport.
fn at(x: f32, y: f32, color: [f32; 4]) -> RasterVertex {
    let clip = [2.0 * x / W as f32 - 1.0, 2.0 * y / H as f32 - 1.0, 0.5, 1.0];
    RasterVertex { clip, color, ..RasterVertex::default() }
}

fn list(topology: Topology, vertices: Vec<RasterVertex>, blend: Option<crate::gl::Blend>) -> DrawList {
    let batch = Batch {
        viewport: [0, 0, W as i32, H as i32],
        depth_test: None,
        topology,
        first: 0,
        count: vertices.len() as u32,
        fragment: None,
        blend,
        tests: crate::gl::FragmentTests::default(),
    };
    DrawList { vertices, ops: vec![Op::Draw(batch)], ..DrawList::default() }
}

/// The red channel of GL window pixel (x, y).
fn red(pixels: &[u8], x: u32, y: u32) -> u8 {
    pixels[(((H - 1 - y) * W + x) * 4) as usize]
}

/// Counts how often each pixel is drawn: every fragment adds 1/255 of red.
fn counts(topology: Topology, vertices: Vec<RasterVertex>) -> Vec<u8> {
    let image = rasterize(
        &list(topology, vertices, Some(crate::gl::Blend { factors: [GL_ONE; 4], ..Default::default() })),
        W,
        H,
    );
    (0..H).flat_map(|y| (0..W).map(move |x| (x, y))).map(|(x, y)| red(&image.pixels, x, y)).collect()
}

const ONE: [f32; 4] = [1.0 / 255.0, 0.0, 0.0, 0.0];

/// A grid of points `(i·W/n + jitter, …)` split into triangles both ways round: the triangles
/// tile the whole window, so each pixel centre is covered exactly once.
fn tiled(n: usize, jitter: &[f32]) -> Vec<RasterVertex> {
    let point = |i: usize, j: usize| {
        let inner = |k: usize| k > 0 && k < n;
        let dx = if inner(i) && inner(j) { jitter[(i * 7 + j) % jitter.len()] } else { 0.0 };
        let dy = if inner(i) && inner(j) { jitter[(i * 3 + j * 5) % jitter.len()] } else { 0.0 };
        at(i as f32 * W as f32 / n as f32 + dx, j as f32 * H as f32 / n as f32 + dy, ONE)
    };
    let mut out = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1));
            if (i + j) % 2 == 0 {
                out.extend([a, b, c, a, c, d]);
            } else {
                // Clockwise this time: both windings are drawn.
                out.extend([a, d, b, b, d, c]);
            }
        }
    }
    out
}

#[test]
fn tiled_triangles_cover_every_pixel_once() {
    for n in [1, 2, 3, 4, 8] {
        let drawn = counts(Topology::Triangles, tiled(n, &[0.0]));
        assert!(drawn.iter().all(|&c| c == 1), "{n}×{n}: {drawn:?}");
    }
}

proptest! {
    /// Shared edges through pixel centres or anywhere else: still exactly once (the top-left
    /// rule), whatever the jitter of the inner grid points. (Jitter up to 0.45 pixel keeps the
    /// 4 × 3-pixel cells convex, so that their two triangles tile them: a corner is 2.4 pixels
    /// from the opposite diagonal, and two corners close in by at most 2 · 0.45 · √2.)
    #[test]
    fn jittered_tilings_cover_every_pixel_once(jitter in prop::collection::vec(-0.45f32..0.45, 1..9)) {
        let snapped: Vec<f32> = jitter.iter().map(|j| (j * 2.0).round() / 2.0).collect();
        for offsets in [&jitter, &snapped] {
            let drawn = counts(Topology::Triangles, tiled(4, offsets));
            prop_assert!(drawn.iter().all(|&c| c == 1), "{drawn:?}");
        }
    }

    /// No input panics: vertices anywhere, behind the eye, at infinity or not numbers.
    #[test]
    fn any_vertices_draw_without_panic(
        coords in prop::collection::vec(prop_oneof![-1e30f32..1e30, -4.0f32..4.0, Just(f32::NAN), Just(f32::INFINITY), Just(0.0)], 24),
    ) {
        let vertices: Vec<RasterVertex> = coords
            .chunks_exact(4)
            .map(|c| RasterVertex { clip: [c[0], c[1], c[2], c[3]], color: [1.0; 4], tex: [c[0], c[1], 0.0, 1.0], ..RasterVertex::default() })
            .collect();
        for topology in [Topology::Triangles, Topology::Lines, Topology::Points] {
            let mut l = list(topology, vertices.clone(), None);
            l.fragments.push(FragmentState { texture: Some(crate::gl::BoundTexture::blank()), more_textures: Vec::new(), fog: None, alpha_test: None, smooth: crate::render::Smooth::None, polygon_stipple: None });
            if let Op::Draw(b) = &mut l.ops[0] { b.fragment = Some(0); }
            let image = rasterize(&l, W, H);
            prop_assert_eq!(image.pixels.len(), (W * H * 4) as usize);
        }
    }
}

/// A viewport far beyond GL's limits (GL clamps it; `Gl` keeps what it was given) draws
/// without overflowing the triangle setup.
#[test]
fn huge_viewports_draw_without_panic() {
    for viewport in
        [[0, 0, i32::MAX, i32::MAX], [i32::MIN, i32::MIN, i32::MAX, i32::MAX], [-40_000_000, 5, 90_000_000, 7]]
    {
        let mut l = list(Topology::Triangles, tiled(2, &[0.3]), None);
        if let Op::Draw(b) = &mut l.ops[0] {
            b.viewport = viewport;
        }
        assert_eq!(rasterize(&l, W, H).pixels.len(), (W * H * 4) as usize);
        let mut lines = l.clone();
        if let Op::Draw(b) = &mut lines.ops[0] {
            b.topology = Topology::Lines;
        }
        assert_eq!(rasterize(&lines, W, H).pixels.len(), (W * H * 4) as usize);
    }
}

/// Colour at a pixel centre is the barycentric mix of the vertices' colours (w = 1: no
/// perspective), worked out by hand for the right triangle (0, 0), (16, 0), (0, 12).
#[test]
fn colours_interpolate_at_pixel_centres() {
    let tri = vec![at(0.0, 0.0, [0.0, 0.0, 0.0, 1.0]), at(16.0, 0.0, [1.0, 0.0, 0.0, 1.0]), at(0.0, 12.0, [0.0; 4])];
    let image = rasterize(&list(Topology::Triangles, tri, None), W, H);
    for (x, y) in [(0, 0), (3, 2), (7, 5), (10, 1)] {
        // Red is the share of vertex (16, 0): x/16 at the centre (x + ½, y + ½).
        let want = ((x as f32 + 0.5) / 16.0 * 255.0 + 0.5) as u8;
        assert_eq!(red(&image.pixels, x, y), want, "pixel ({x}, {y})");
    }
}

/// Perspective-correct interpolation: the same window triangle with the far vertex at w = 4
/// gives red = (λ/4) / (λ/4 + 1 − λ) at window share λ (GL 1.1 eq. 3.4), not λ.
#[test]
fn attributes_interpolate_with_perspective() {
    let mut far = at(16.0, 0.0, [1.0, 0.0, 0.0, 1.0]);
    far.clip = far.clip.map(|c| c * 4.0);
    let tri = vec![at(0.0, 0.0, [0.0, 0.0, 0.0, 1.0]), far, at(0.0, 12.0, [0.0; 4])];
    let image = rasterize(&list(Topology::Triangles, tri, None), W, H);
    for (x, y) in [(3, 2), (7, 5), (10, 1)] {
        let l = (x as f32 + 0.5) / 16.0;
        let want = ((l / 4.0) / (l / 4.0 + 1.0 - l) * 255.0 + 0.5) as u8;
        let got = red(&image.pixels, x, y);
        assert!(got.abs_diff(want) <= 1, "pixel ({x}, {y}): {got} against {want}");
    }
}

/// A triangle crossing the near plane (z < 0 at one vertex) draws only its part in front:
/// the clipped edge lies where z reaches 0.
#[test]
fn triangles_are_clipped_at_the_near_plane() {
    let mut a = at(0.0, 0.0, [1.0; 4]);
    let mut b = at(16.0, 0.0, [1.0; 4]);
    let mut c = at(0.0, 12.0, [1.0; 4]);
    // z from 0.5 at x = 0 to −0.5 at x = 16: z = 0 at x = 8.
    (a.clip[2], b.clip[2], c.clip[2]) = (0.5, -0.5, 0.5);
    let image = rasterize(&list(Topology::Triangles, vec![a, b, c], None), W, H);
    assert_eq!(red(&image.pixels, 7, 0), 255);
    assert_eq!(red(&image.pixels, 8, 0), 0);
    assert_eq!(red(&image.pixels, 12, 0), 0);
}

/// GL's line rule: a horizontal line from x = 2.5 to 9.5 on row 3 lights the pixels whose
/// centres lie in [2.5, 9.5): columns 2..9, one row; the vertical one likewise.
#[test]
fn lines_light_the_pixels_of_their_half_open_span() {
    let image =
        counts(Topology::Lines, vec![at(2.5, 3.5, ONE), at(9.5, 3.5, ONE), at(12.5, 1.0, ONE), at(12.5, 8.0, ONE)]);
    let lit: Vec<(u32, u32)> =
        (0..H).flat_map(|y| (0..W).map(move |x| (x, y))).filter(|&(x, y)| image[(y * W + x) as usize] == 1).collect();
    let mut want: Vec<(u32, u32)> = (2..9).map(|x| (x, 3)).collect();
    // Rows with centres in [1, 8): 1..7.
    want.extend((1..8).map(|y| (12, y)));
    want.sort_by_key(|&(x, y)| (y, x));
    assert_eq!(lit, want);
}

/// A point lights the pixel holding it, and none when outside the view volume.
#[test]
fn points_light_their_pixel() {
    let inside = at(5.7, 2.2, ONE);
    let mut behind = at(9.5, 9.5, ONE);
    behind.clip[2] = -1.0;
    let drawn = counts(Topology::Points, vec![inside, behind]);
    let lit: Vec<usize> = (0..drawn.len()).filter(|&k| drawn[k] == 1).collect();
    assert_eq!(lit, vec![(2 * W + 5) as usize]);
}

/// The window pixels (GL's, origin bottom-left) a list draws in a 64 × 64 window, as the
/// bounding box (first and last column, first and last row).
fn drawn_box(topology: Topology, points: &[(f32, f32)]) -> [u32; 4] {
    let size = 64u32;
    let vertices = points
        .iter()
        .map(|&(x, y)| {
            let clip = [2.0 * x / size as f32 - 1.0, 2.0 * y / size as f32 - 1.0, 0.5, 1.0];
            RasterVertex { clip, color: [1.0; 4], ..RasterVertex::default() }
        })
        .collect::<Vec<_>>();
    let mut l = list(topology, vertices, None);
    if let Op::Draw(b) = &mut l.ops[0] {
        b.viewport = [0, 0, size as i32, size as i32];
    }
    let image = rasterize(&l, size, size);
    let mut bounds = [u32::MAX, 0, u32::MAX, 0];
    for y in 0..size {
        for x in 0..size {
            if image.pixels[(((size - 1 - y) * size + x) * 4) as usize] > 0 {
                bounds = [bounds[0].min(x), bounds[1].max(x), bounds[2].min(y), bounds[3].max(y)];
            }
        }
    }
    bounds
}

/// llvmpipe's tie-breaking, measured on Mesa 22.3 (OSMesa, `glOrtho(0, 64, 0, 64, -1, 1)` on a
/// 64 × 64 buffer): a square with edges on pixel centres 10.5 and 20.5 fills columns and rows
/// 10..19; a horizontal line at y = 30 from x = 10 to 40 fills columns 10..39 of row 29; a
/// vertical one at x = 30 column 29, rows 10..39; a loop around 10..40 columns and rows 9..39.
#[test]
fn pixel_tie_breaking_is_llvmpipe_s() {
    let square = [(10.5, 10.5), (20.5, 10.5), (20.5, 20.5), (10.5, 10.5), (20.5, 20.5), (10.5, 20.5)];
    assert_eq!(drawn_box(Topology::Triangles, &square), [10, 19, 10, 19]);
    assert_eq!(drawn_box(Topology::Lines, &[(10.0, 30.0), (40.0, 30.0)]), [10, 39, 29, 29]);
    assert_eq!(drawn_box(Topology::Lines, &[(30.0, 10.0), (30.0, 40.0)]), [29, 29, 10, 39]);
    let corners = [(10.0, 10.0), (40.0, 10.0), (40.0, 40.0), (10.0, 40.0)];
    let lines: Vec<(f32, f32)> = (0..4).flat_map(|k| [corners[k], corners[(k + 1) % 4]]).collect();
    assert_eq!(drawn_box(Topology::Lines, &lines), [9, 39, 9, 39]);
    assert_eq!(drawn_box(Topology::Lines, &[(10.5, 30.5), (40.5, 30.5)]), [10, 39, 30, 30]);
}

/// A polygon of one window depth has that depth at every fragment, whatever its vertices'
/// w (piglit's `gl-1.4-polygon-offset` reads depth slopes off a quad facing the eye through a
/// perspective projection, and finds the slope 0 on Mesa).
#[test]
fn a_polygon_of_one_depth_is_flat() {
    let mut gl = crate::gl::Gl::new(W as i32, H as i32);
    gl.matrix_mode(GL_PROJECTION);
    gl.frustum(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.rotatef(17.0, 0.0, 0.0, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.begin(GL_QUADS);
    for (x, y) in [(-4.3, -4.1), (4.7, -4.2), (4.4, 4.5), (-4.2, 4.6)] {
        gl.vertex3f(x, y, -2.5);
    }
    gl.end();
    let window = super::render_window(&gl.take_frame(), W, H);
    let drawn: Vec<f32> = window.depth.iter().copied().filter(|&d| d < 1.0).collect();
    assert_eq!(drawn.len(), (W * H) as usize, "the quad covers the window");
    assert!(drawn.iter().all(|&d| d == drawn[0]), "depths {:?}", &drawn[..8]);
}
