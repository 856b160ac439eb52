//! The CPU rasteriser against wgpu's (lavapipe in CI, an independent implementation of the
//! same rules): random scenes of triangles, quads, lines and points, inside and across the
//! view volume, flat and smooth, with and without the depth test and blending, drawn both
//! ways from the same recorded frame, must give the same picture by the conformance metric
//! (a pixel matches one within one pixel and 24/255 per channel). Measured when written: of
//! 3,072 pixels, 0 to 50 differ by more than 2/255 per scene (edge pixels of one-pixel lines,
//! which lavapipe steps by Vulkan's rules), and a depth test switched off in the CPU rasteriser
//! fails the test.

use gleval::gl::{Blend, ClientArray, Frame};
use gleval::prelude::*;
use gleval::render::{soft, Renderer};
use gleval::testing::compare::{compare, RgbImage};
use proptest::prelude::*;
use proptest::test_runner::{RngAlgorithm, TestRng, TestRunner};

const W: u32 = 64;
const H: u32 = 48;

/// One primitive: its mode and vertices (x, y, z in [-1.3, 1.3], some outside the volume) with
/// colours.
#[derive(Clone, Debug)]
struct Shape {
    mode: GLenum,
    vertices: Vec<([f32; 3], [f32; 3])>,
}

fn shape() -> impl Strategy<Value = Shape> {
    let mode = prop::sample::select(vec![GL_TRIANGLES, GL_QUADS, GL_TRIANGLE_STRIP, GL_LINES, GL_LINE_LOOP, GL_POINTS]);
    let vertex = ([-1.3f32..1.3, -1.3f32..1.3, -1.3f32..1.3], [0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0]);
    (mode, prop::collection::vec(vertex, 3..9)).prop_map(|(mode, vertices)| Shape { mode, vertices })
}

/// Blending with any of GL 1.4's factors and equations and a constant colour.
fn blend() -> impl Strategy<Value = Blend> {
    let factor = prop::sample::select(vec![
        GL_ZERO,
        GL_ONE,
        GL_SRC_COLOR,
        GL_ONE_MINUS_SRC_COLOR,
        GL_SRC_ALPHA,
        GL_ONE_MINUS_SRC_ALPHA,
        GL_DST_ALPHA,
        GL_ONE_MINUS_DST_ALPHA,
        GL_DST_COLOR,
        GL_ONE_MINUS_DST_COLOR,
        GL_SRC_ALPHA_SATURATE,
        GL_CONSTANT_COLOR,
        GL_ONE_MINUS_CONSTANT_COLOR,
        GL_CONSTANT_ALPHA,
        GL_ONE_MINUS_CONSTANT_ALPHA,
    ]);
    let equation = prop::sample::select(vec![GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX]);
    let classic = Just(Blend {
        factors: [GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA],
        ..Blend::default()
    });
    let any = (
        [factor.clone(), factor.clone(), factor.clone(), factor],
        [equation.clone(), equation],
        [0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0],
    )
        .prop_map(|(factors, equations, color)| Blend { factors, equations, color });
    prop_oneof![classic, any]
}

/// The scene's frame: a clear, then the shapes under the given state.
fn record(shapes: &[Shape], depth: Option<GLenum>, blend: Option<Blend>, flat: bool) -> Frame {
    let mut gl = Gl::new(W as i32, H as i32);
    gl.viewport(0, 0, W as i32, H as i32);
    gl.clear_color(0.1, 0.2, 0.3, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if let Some(func) = depth {
        gl.enable(GL_DEPTH_TEST);
        gl.depth_func(func);
    }
    if let Some(b) = blend {
        gl.blend_func_separate(b.factors[0], b.factors[1], b.factors[2], b.factors[3]);
        gl.blend_equation_separate(b.equations[0], b.equations[1]);
        gl.blend_color(b.color[0], b.color[1], b.color[2], b.color[3]);
    }
    if flat {
        gl.shade_model(GL_FLAT);
    }
    for s in shapes {
        // Blending only on filled primitives: one-pixel lines step by GL's diamond-exit rule
        // here and by Vulkan's rules in lavapipe, so where two lines of a scene overlap they
        // share different pixels, and blending shows every pixel drawn twice (measured: a
        // loop of two nearly parallel lines, 1.5% of pixels). Against real Mesa such lines
        // are covered by the reference pictures (`stipple`: smooth lines blended).
        let filled = !matches!(s.mode, GL_LINES | GL_LINE_LOOP | GL_POINTS);
        if blend.is_some() && filled {
            gl.enable(GL_BLEND);
        } else {
            gl.disable(GL_BLEND);
        }
        gl.begin(s.mode);
        for (p, c) in &s.vertices {
            gl.color4f(c[0], c[1], c[2], 0.6);
            gl.vertex3f(p[0], p[1], p[2]);
        }
        gl.end();
    }
    gl.take_frame()
}

#[test]
fn the_cpu_rasteriser_draws_what_wgpu_draws() {
    let renderer = match Renderer::new() {
        Ok(r) => std::cell::RefCell::new(r),
        Err(e) if std::env::var("GLEVAL_REQUIRE_ADAPTER").is_ok_and(|v| v == "1") => panic!("{e}"),
        Err(e) => return eprintln!("skipping: {e}"),
    };
    let scenes = (
        prop::collection::vec(shape(), 1..6),
        prop::option::of(prop::sample::select(vec![GL_LESS, GL_LEQUAL, GL_GREATER, GL_ALWAYS])),
        prop::option::of(blend()),
        any::<bool>(),
    );
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|n| n.parse().ok()).unwrap_or(48);
    let config = ProptestConfig { cases, ..ProptestConfig::default() };
    // The same scenes on every run: a CI result does not depend on the draw.
    let mut runner = TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    let result = runner.run(&scenes, |(shapes, depth, blend, flat)| {
        let frame = record(&shapes, depth, blend, flat);
        let soft = RgbImage::from_rgba(&soft::render_frame(&frame, W, H));
        let wgpu = renderer.borrow_mut().render_frame(&frame, W, H).expect("wgpu renders");
        let wgpu = RgbImage::from_rgba(&wgpu);
        let fraction = compare(&wgpu, &soft).expect("same size").fraction;
        prop_assert!(fraction <= 0.01, "{:.3}% of pixels differ", fraction * 100.0);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}

/// wgpu's renderer where an adapter exists (lavapipe in CI; `GLEVAL_REQUIRE_ADAPTER=1` makes a
/// missing one a failure), for the tests that check both rasterisers against Mesa's pixels.
fn optional_renderer() -> Option<Renderer> {
    match Renderer::new() {
        Ok(r) => Some(r),
        Err(e) if std::env::var("GLEVAL_REQUIRE_ADAPTER").is_ok_and(|v| v == "1") => panic!("{e}"),
        Err(_) => None,
    }
}

/// Both rasterisers draw `frame` (8 × 8), and the diagonal (i, i) in GL's rows (the image's
/// rows run top down) is Mesa's within `tolerance`; `what` names the set-up when it is not.
fn assert_diagonal_is_mesas(
    renderer: &mut Option<Renderer>,
    frame: &Frame,
    expected: &[[u8; 4]; 8],
    tolerance: u8,
    what: &str,
) {
    let diagonal = |pixels: &[u8]| -> Vec<[u8; 4]> {
        (0..8).map(|i| pixels[((7 - i) * 8 + i) * 4..][..4].try_into().unwrap()).collect()
    };
    let close = |got: &[[u8; 4]]| {
        got.iter().zip(expected).all(|(g, e)| g.iter().zip(e).all(|(a, b)| a.abs_diff(*b) <= tolerance))
    };
    let soft = diagonal(&soft::render_frame(frame, 8, 8).pixels);
    assert!(close(&soft), "CPU, {what}: {soft:?}, Mesa {expected:?}");
    if let Some(renderer) = renderer.as_mut() {
        let wgpu = diagonal(&renderer.render_frame(frame, 8, 8).expect("wgpu renders").pixels);
        assert!(close(&wgpu), "wgpu, {what}: {wgpu:?}, Mesa {expected:?}");
    }
}

/// An intensity texture under each texture function, drawn by both rasterisers, against what
/// Mesa 22.3 (llvmpipe, OSMesa) drew for the same calls: I = 153/255 with the fragment colour
/// (0.5, 0.25, 1, 0.5) and the environment colour (0.2, 0.4, 0.8, 0.1). Intensity is I in all
/// four components; `GL_BLEND` blends alpha as colour, `GL_ADD` adds it, `GL_DECAL` leaves the
/// fragment as it is (GL 1.1 tables 3.17 and 3.18).
#[test]
fn intensity_textures_are_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    let mesa = [
        (GL_MODULATE, [76, 38, 153, 76]),
        (GL_DECAL, [128, 64, 255, 128]),
        (GL_BLEND, [82, 87, 224, 66]),
        (GL_REPLACE, [153, 153, 153, 153]),
        (GL_ADD, [255, 217, 255, 255]),
    ];
    for (mode, expected) in mesa {
        let mut gl = Gl::new(4, 4);
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_INTENSITY as GLint, 1, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &[153u8]);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as GLint);
        gl.enable(GL_TEXTURE_2D);
        gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.2, 0.4, 0.8, 0.1]);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode as GLint);
        gl.color4f(0.5, 0.25, 1.0, 0.5);
        gl.begin(GL_QUADS);
        gl.tex_coord2f(0.0, 0.0);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            gl.vertex2f(x, y);
        }
        gl.end();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        let pixel = |pixels: &[u8]| -> [u8; 4] { pixels[(4 + 1) * 4..][..4].try_into().unwrap() };
        let close = |got: [u8; 4]| got.iter().zip(expected).all(|(&g, e)| g.abs_diff(e) <= 1);
        let soft = soft::render_frame(&frame, 4, 4);
        assert!(close(pixel(&soft.pixels)), "CPU, mode {mode:#x}: {:?}, Mesa {expected:?}", pixel(&soft.pixels));
        if let Some(renderer) = renderer.as_mut() {
            let wgpu = renderer.render_frame(&frame, 4, 4).expect("wgpu renders");
            assert!(close(pixel(&wgpu.pixels)), "wgpu, mode {mode:#x}: {:?}, Mesa {expected:?}", pixel(&wgpu.pixels));
        }
    }
}

/// GL 1.2–2.0's blending (constant colours, the equations, separate RGB and alpha factors and
/// equations), drawn by both rasterisers, against what Mesa 22.3 (llvmpipe, OSMesa) wrote for
/// the same calls (`tests/reference/pixels/blend.c` prints these values): a buffer cleared to
/// (0.2, 0.4, 0.6, 0.8), the constant colour (0.1, 0.3, 0.5, 0.7), a fragment of colour
/// (0.5, 0.25, 0.9, 0.3). Within 1/255 per channel: llvmpipe blends in 8-bit fixed point.
#[test]
fn blend_equations_are_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    let mesa: [([GLenum; 4], [GLenum; 2], [u8; 4]); 7] = [
        (
            [GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_CONSTANT_ALPHA, GL_ONE],
            [GL_FUNC_ADD; 2],
            [28, 50, 161, 255],
        ),
        ([GL_ONE; 4], [GL_FUNC_REVERSE_SUBTRACT, GL_FUNC_SUBTRACT], [0, 38, 0, 0]),
        ([GL_ZERO; 4], [GL_MIN, GL_MAX], [51, 64, 153, 204]),
        ([GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE], [GL_MAX, GL_FUNC_ADD], [128, 102, 230, 255]),
        ([GL_ONE, GL_SRC_ALPHA_SATURATE, GL_ONE, GL_SRC_ALPHA_SATURATE], [GL_FUNC_ADD; 2], [138, 84, 255, 255]),
        (
            [GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_ALPHA],
            [GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT],
            [110, 15, 38, 0],
        ),
        (
            [GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_DST_ALPHA],
            [GL_FUNC_ADD, GL_MIN],
            [89, 92, 222, 76],
        ),
    ];
    for (factors, [rgb, alpha], expected) in mesa {
        let mut gl = Gl::new(4, 4);
        gl.clear_color(0.2, 0.4, 0.6, 0.8);
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.blend_color(0.1, 0.3, 0.5, 0.7);
        gl.enable(GL_BLEND);
        gl.blend_func_separate(factors[0], factors[1], factors[2], factors[3]);
        gl.blend_equation_separate(rgb, alpha);
        gl.color4f(0.5, 0.25, 0.9, 0.3);
        gl.rectf(-1.0, -1.0, 1.0, 1.0);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        let pixel = |pixels: &[u8]| -> [u8; 4] { pixels[(4 + 1) * 4..][..4].try_into().unwrap() };
        let close = |got: [u8; 4]| got.iter().zip(expected).all(|(&g, e)| g.abs_diff(e) <= 1);
        let soft = soft::render_frame(&frame, 4, 4);
        assert!(
            close(pixel(&soft.pixels)),
            "CPU, {factors:x?} {rgb:#x} {alpha:#x}: {:?}, Mesa {expected:?}",
            pixel(&soft.pixels)
        );
        if let Some(renderer) = renderer.as_mut() {
            let wgpu = renderer.render_frame(&frame, 4, 4).expect("wgpu renders");
            let got = pixel(&wgpu.pixels);
            assert!(close(got), "wgpu, {factors:x?} {rgb:#x} {alpha:#x}: {got:?}, Mesa {expected:?}");
        }
    }
}

/// GL 1.2's base and maximum levels and LOD clamp, drawn by both rasterisers, against what Mesa
/// 22.3 (llvmpipe, OSMesa) sampled for the same calls (`tests/reference/pixels/texture_lod.c`
/// prints these values): a 32 × 32 texture whose six levels are each one colour, modulating
/// grey (0.5), on a square of `size` pixels, so λ = log2(32 / size) from level 0 (from the base
/// level's size when the base moves). An incomplete chain (base 3 above maximum 2) leaves the
/// square untextured.
#[test]
fn texture_lod_is_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    const COLOURS: [[u8; 3]; 6] = [[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 0], [0, 255, 255], [255, 0, 255]];
    /// Size, base level, max level, min LOD, max LOD, min filter, Mesa's centre pixel.
    type Case = (i32, i32, i32, f32, f32, GLenum, [u8; 4]);
    let mesa: [Case; 9] = [
        (8, 2, 1000, -1000.0, 1000.0, GL_NEAREST_MIPMAP_NEAREST, [0, 0, 128, 255]),
        (4, 0, 1, -1000.0, 1000.0, GL_NEAREST_MIPMAP_NEAREST, [0, 128, 0, 255]),
        (32, 0, 1000, 4.0, 1000.0, GL_NEAREST_MIPMAP_NEAREST, [0, 128, 128, 255]),
        (4, 0, 1000, -1000.0, 1.0, GL_NEAREST_MIPMAP_NEAREST, [0, 128, 0, 255]),
        (4, 1, 1000, -1000.0, 1000.0, GL_NEAREST, [0, 128, 0, 255]),
        (8, 3, 2, -1000.0, 1000.0, GL_NEAREST_MIPMAP_NEAREST, [128, 128, 128, 255]),
        (32, 0, 1000, 2.5, 1000.0, GL_NEAREST_MIPMAP_LINEAR, [64, 64, 64, 255]),
        (16, 1, 3, -1000.0, 1000.0, GL_LINEAR_MIPMAP_LINEAR, [0, 128, 0, 255]),
        (2, 2, 1000, 0.5, 1.5, GL_NEAREST_MIPMAP_LINEAR, [64, 128, 64, 255]),
    ];
    for (size, base, max, min_lod, max_lod, min_filter, expected) in mesa {
        let mut gl = Gl::new(32, 32);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        for (level, colour) in COLOURS.iter().enumerate() {
            let side = 32 >> level;
            let texels: Vec<u8> = (0..side * side).flat_map(|_| *colour).collect();
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                level as i32,
                GL_RGB as i32,
                side,
                side,
                0,
                GL_RGB,
                GL_UNSIGNED_BYTE,
                &texels,
            );
        }
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, base);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, max);
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, min_lod);
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, max_lod);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min_filter as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.color3f(0.5, 0.5, 0.5);
        gl.viewport(0, 0, size, size);
        gl.begin(GL_QUADS);
        for (x, y) in [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)] {
            gl.tex_coord2f(x, y);
            gl.vertex2f(2.0 * x - 1.0, 2.0 * y - 1.0);
        }
        gl.end();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        // The centre pixel (size / 2, size / 2) in GL's rows, the image's rows top down.
        let at = |pixels: &[u8]| -> [u8; 4] {
            let (x, row) = ((size / 2) as usize, (32 - 1 - size / 2) as usize);
            pixels[(row * 32 + x) * 4..][..4].try_into().unwrap()
        };
        let close = |got: [u8; 4]| got.iter().zip(expected).all(|(&g, e)| g.abs_diff(e) <= 1);
        let case = format!("size {size}, levels {base}..={max}, LOD {min_lod}..={max_lod}, filter {min_filter:#x}");
        let soft = at(&soft::render_frame(&frame, 32, 32).pixels);
        assert!(close(soft), "CPU, {case}: {soft:?}, Mesa {expected:?}");
        if let Some(renderer) = renderer.as_mut() {
            let wgpu = at(&renderer.render_frame(&frame, 32, 32).expect("wgpu renders").pixels);
            assert!(close(wgpu), "wgpu, {case}: {wgpu:?}, Mesa {expected:?}");
        }
    }
}

/// GL 1.2's `GL_CLAMP_TO_EDGE` beside GL 1.1's `GL_CLAMP` and `GL_REPEAT`, drawn by both
/// rasterisers, against what Mesa 22.3 (llvmpipe, OSMesa) sampled for the same calls
/// (`tests/reference/pixels/edge_clamp.c` prints these values): a 2 × 2 texture (red, green /
/// blue, white) filtered linearly with border colour (1, 0, 1, 1), on an 8 × 8 square whose
/// coordinates run from −0.5 to 1.5; the diagonal's pixels. Clamping to the edge never mixes in
/// the border; `GL_CLAMP` does, as Mesa's does. Within 2/255: lavapipe weighs texels in fixed
/// point.
#[test]
fn edge_clamp_is_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    let shared = [[159, 64, 64, 255], [159, 191, 191, 255]];
    let mesa: [([GLenum; 2], [[u8; 4]; 8]); 4] = [
        (
            [GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE],
            [[255, 0, 0, 255], [255, 0, 0, 255], [255, 0, 0, 255], shared[0], shared[1], [255; 4], [255; 4], [255; 4]],
        ),
        (
            [GL_CLAMP, GL_CLAMP],
            [
                [255, 0, 191, 255],
                [255, 0, 191, 255],
                [255, 0, 112, 255],
                shared[0],
                shared[1],
                [255, 143, 255, 255],
                [255, 64, 255, 255],
                [255, 64, 255, 255],
            ],
        ),
        (
            [GL_CLAMP_TO_EDGE, GL_CLAMP],
            [
                [255, 0, 128, 255],
                [255, 0, 128, 255],
                [255, 0, 64, 255],
                shared[0],
                shared[1],
                [255, 191, 255, 255],
                [255, 128, 255, 255],
                [255, 128, 255, 255],
            ],
        ),
        (
            [GL_REPEAT, GL_CLAMP_TO_EDGE],
            [
                [64, 191, 0, 255],
                [64, 191, 0, 255],
                [191, 64, 0, 255],
                shared[0],
                shared[1],
                [191, 191, 255, 255],
                [64, 64, 255, 255],
                [64, 64, 255, 255],
            ],
        ),
    ];
    for ([wrap_s, wrap_t], expected) in mesa {
        let mut gl = Gl::new(8, 8);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        let texels = [255u8, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255];
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, &texels);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        gl.tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &[1.0, 0.0, 1.0, 1.0]);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap_s as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap_t as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.begin(GL_QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            gl.tex_coord2f(0.5 + x, 0.5 + y);
            gl.vertex2f(x, y);
        }
        gl.end();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        let what = format!("wraps {wrap_s:#x} {wrap_t:#x}");
        assert_diagonal_is_mesas(&mut renderer, &frame, &expected, 2, &what);
    }
}

/// LOD bounds that are not numbers reach wgpu's sampler as no bound (WebGPU takes no NaN), and
/// both rasterisers draw the frame.
#[test]
fn lod_bounds_that_are_not_numbers_draw() {
    let mut gl = Gl::new(4, 4);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, &[0u8, 255, 0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, f32::NAN);
    gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, f32::NAN);
    gl.enable(GL_TEXTURE_2D);
    gl.rectf(-1.0, -1.0, 1.0, 1.0);
    let frame = gl.take_frame();
    let green = |pixels: &[u8]| pixels.chunks_exact(4).all(|p| p == [0, 255, 0, 255]);
    assert!(green(&soft::render_frame(&frame, 4, 4).pixels));
    if let Some(mut renderer) = optional_renderer() {
        assert!(green(&renderer.render_frame(&frame, 4, 4).expect("wgpu renders").pixels));
    }
}

/// The calls of `tests/reference/pixels/color_sum.c`: GL 1.4's colour sum and GL 1.2's
/// separate specular colour in eleven set-ups (that file lists them).
fn color_sum_scene(gl: &mut Gl, k: usize) {
    let quad = |gl: &mut Gl| {
        gl.begin(GL_QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            gl.vertex2f(x, y);
        }
        gl.end();
    };
    let square = |gl: &mut Gl| {
        let secondary = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.5, 0.5, 0.0]];
        gl.begin(GL_QUADS);
        for ((x, y), s) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].into_iter().zip(secondary) {
            gl.secondary_color3fv(&s);
            gl.vertex2f(x, y);
        }
        gl.end();
    };
    let lit = |gl: &mut Gl, control: GLenum| {
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.material_fv(GL_FRONT_AND_BACK, GL_SPECULAR, &[0.5, 0.25, 0.0, 1.0]);
        gl.material_f(GL_FRONT_AND_BACK, GL_SHININESS, 0.0);
        gl.light_model_i(GL_LIGHT_MODEL_COLOR_CONTROL, control as GLint);
        gl.normal3f(0.0, 0.0, 1.0);
    };
    let textured = |gl: &mut Gl| {
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as GLint, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, &[128u8, 255, 64, 255]);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as GLint);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as GLint);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as GLint);
        gl.enable(GL_TEXTURE_2D);
    };
    let patch = |gl: &mut Gl| {
        let points = [-1.0, -1.0, 0.0, 1.0, -1.0, 0.0, -1.0, 1.0, 0.0, 1.0, 1.0, 0.0];
        gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 6, 2, &points);
        gl.enable(GL_MAP2_VERTEX_3);
        gl.map_grid2f(4, 0.0, 1.0, 4, 0.0, 1.0);
        gl.eval_mesh2(GL_FILL, 0, 4, 0, 4);
    };
    gl.color4f(0.25, 0.5, 0.125, 0.5);
    gl.secondary_color3f(0.5, 0.25, 0.5);
    match k {
        0 => {
            gl.enable(GL_COLOR_SUM);
            quad(gl);
        }
        1 => quad(gl),
        2 => {
            gl.color4f(1.0, 0.5, 0.5, 1.0);
            textured(gl);
            gl.enable(GL_COLOR_SUM);
            quad(gl);
        }
        3..=5 => {
            textured(gl);
            lit(gl, if k == 4 { GL_SINGLE_COLOR } else { GL_SEPARATE_SPECULAR_COLOR });
            if k == 5 {
                gl.enable(GL_COLOR_SUM);
            }
            quad(gl);
        }
        6 => {
            gl.enable(GL_COLOR_SUM);
            gl.enable(GL_FOG);
            gl.fogi(GL_FOG_MODE, GL_LINEAR as GLint);
            gl.fogf(GL_FOG_END, 2.0);
            gl.fogfv(GL_FOG_COLOR, &[0.0, 0.0, 1.0, 1.0]);
            gl.begin(GL_QUADS);
            for (x, y, z) in [(-1.0, -1.0, 0.5), (1.0, -1.0, 0.5), (1.0, 1.0, -0.5), (-1.0, 1.0, -0.5)] {
                gl.vertex3f(x, y, z);
            }
            gl.end();
        }
        7 | 8 => {
            gl.enable(GL_COLOR_SUM);
            if k == 8 {
                gl.shade_model(GL_FLAT);
            }
            square(gl);
        }
        9 => {
            textured(gl);
            lit(gl, GL_SEPARATE_SPECULAR_COLOR);
            patch(gl);
        }
        _ => {
            gl.enable(GL_COLOR_SUM);
            patch(gl);
        }
    }
}

/// The colour sum on both rasterisers against what Mesa 22.3 (llvmpipe, OSMesa) drew for the
/// same calls (`tests/reference/pixels/color_sum.c`): the secondary colour is added after
/// texturing and before fog, lit with `GL_SEPARATE_SPECULAR_COLOR` whether or not
/// `GL_COLOR_SUM` is on, unlit only with it; flat shading takes the provoking vertex's. Cases 9
/// and 10 are evaluator patches, which wgpu draws with its mesh rasteriser. Within 1/255.
#[test]
fn color_sum_is_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    let same = |p: [u8; 4]| [p; 8];
    let mesa: [[[u8; 4]; 8]; 11] = [
        same([191, 191, 159, 128]),
        same([64, 128, 32, 128]),
        same([255, 191, 160, 255]),
        same([235, 255, 54, 255]),
        same([128, 255, 54, 255]),
        same([235, 255, 54, 255]),
        same([143, 143, 183, 128]),
        [
            [255, 128, 48, 128],
            [255, 128, 80, 128],
            [239, 128, 112, 128],
            [207, 128, 143, 128],
            [175, 128, 175, 128],
            [143, 128, 207, 128],
            [112, 128, 239, 128],
            [80, 128, 255, 128],
        ],
        same([191, 255, 32, 128]),
        same([235, 255, 54, 255]),
        same([191, 191, 159, 128]),
    ];
    for (k, expected) in mesa.iter().enumerate() {
        let mut gl = Gl::new(8, 8);
        color_sum_scene(&mut gl, k);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        assert_diagonal_is_mesas(&mut renderer, &frame, expected, 1, &format!("case {k}"));
    }
}

/// Where a quad is split into triangles, on both rasterisers against Mesa 22.3's pixels for the
/// same calls (`tests/reference/pixels/quads.c`): along v0–v2 from `glBegin`/`glEnd`,
/// `glDrawArrays` and `glArrayElement`; along v1–v3 from a display list, `glDrawElements`, and
/// with a polygon stipple or an unfilled face.
#[test]
fn quad_diagonals_are_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    let fan = [
        [239, 0, 16, 255],
        [207, 0, 48, 255],
        [175, 0, 80, 255],
        [143, 0, 112, 255],
        [112, 0, 143, 255],
        [80, 0, 175, 255],
        [48, 0, 207, 255],
        [16, 0, 239, 255],
    ];
    let split = [
        [231, 24, 0, 255],
        [183, 72, 0, 255],
        [135, 120, 0, 255],
        [88, 167, 0, 255],
        [56, 167, 32, 255],
        [40, 120, 96, 255],
        [24, 72, 159, 255],
        [8, 24, 223, 255],
    ];
    let mesa = [fan, split, fan, split, fan, split, split];
    let corners = [[-1.0f32, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    let colours = [[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.5, 0.5, 0.0]];
    let immediate = |gl: &mut Gl| {
        gl.begin(GL_QUADS);
        for (c, p) in colours.iter().zip(&corners) {
            gl.color3fv(c);
            gl.vertex2fv(p);
        }
        gl.end();
    };
    for (k, expected) in mesa.iter().enumerate() {
        let mut gl = Gl::new(8, 8);
        let vertices = ClientArray::new(corners.as_flattened());
        let colour_array = ClientArray::new(colours.as_flattened());
        gl.vertex_pointer(2, GL_FLOAT, 0, &vertices);
        gl.color_pointer(3, GL_FLOAT, 0, &colour_array);
        gl.enable_client_state(GL_VERTEX_ARRAY);
        gl.enable_client_state(GL_COLOR_ARRAY);
        match k {
            0 => immediate(&mut gl),
            1 => {
                gl.new_list(1, GL_COMPILE);
                immediate(&mut gl);
                gl.end_list();
                gl.call_list(1);
            }
            2 => gl.draw_arrays(GL_QUADS, 0, 4),
            3 => gl.draw_elements(GL_QUADS, 4, GL_UNSIGNED_BYTE, &[0u8, 1, 2, 3]),
            4 => {
                gl.begin(GL_QUADS);
                (0..4).for_each(|i| gl.array_element(i));
                gl.end();
            }
            5 => {
                gl.polygon_stipple(&[0xff; 128]);
                gl.enable(GL_POLYGON_STIPPLE);
                immediate(&mut gl);
            }
            _ => {
                gl.polygon_mode(GL_BACK, GL_LINE);
                immediate(&mut gl);
            }
        }
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        assert_diagonal_is_mesas(&mut renderer, &frame, expected, 1, &format!("case {k}"));
    }
}

/// GL 1.2's 3D textures drawn by both rasterisers, against what Mesa 22.3 (llvmpipe, OSMesa)
/// drew for the same calls (`tests/reference/pixels/texture_3d.c` prints these values): a
/// 2 × 2 × 2 texture of eight colours on an 8 × 8 square at several r, filters and r wraps (r
/// interpolated across the square in 6 and 7; `GL_CLAMP` mixes in the border colour in 5),
/// a mipmapped 4 × 4 × 4 texture minified by two (8), and `GL_TEXTURE_3D` before
/// `GL_TEXTURE_2D` (9); the diagonal's pixels, within 2/255 (lavapipe weighs texels in fixed
/// point).
#[test]
fn texture_3d_is_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    let setups = [
        (GL_NEAREST, GL_REPEAT, 0.25, 0.25),
        (GL_NEAREST, GL_REPEAT, 0.75, 0.75),
        (GL_LINEAR, GL_CLAMP_TO_EDGE, 0.5, 0.5),
        (GL_LINEAR, GL_CLAMP_TO_EDGE, 0.375, 0.375),
        (GL_LINEAR, GL_REPEAT, 0.0, 0.0),
        (GL_LINEAR, GL_CLAMP, 0.0, 0.0),
        (GL_LINEAR, GL_CLAMP_TO_EDGE, 0.0, 1.0),
        (GL_NEAREST, GL_REPEAT, 0.0, 1.0),
    ];
    let mesa: [[[u8; 4]; 8]; 10] = [
        [
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
        ],
        [
            [0, 255, 255, 255],
            [0, 255, 255, 255],
            [0, 255, 255, 255],
            [0, 255, 255, 255],
            [128, 128, 128, 255],
            [128, 128, 128, 255],
            [128, 128, 128, 255],
            [128, 128, 128, 255],
        ],
        [
            [128, 128, 128, 255],
            [128, 128, 128, 255],
            [129, 129, 129, 255],
            [137, 137, 137, 255],
            [153, 153, 153, 255],
            [177, 177, 177, 255],
            [192, 192, 192, 255],
            [192, 192, 192, 255],
        ],
        [
            [191, 64, 64, 255],
            [191, 64, 64, 255],
            [164, 80, 80, 255],
            [136, 116, 116, 255],
            [144, 156, 156, 255],
            [188, 200, 200, 255],
            [223, 223, 223, 255],
            [223, 223, 223, 255],
        ],
        [
            [128, 128, 128, 255],
            [128, 128, 128, 255],
            [129, 129, 129, 255],
            [137, 137, 137, 255],
            [153, 153, 153, 255],
            [177, 177, 177, 255],
            [192, 192, 192, 255],
            [192, 192, 192, 255],
        ],
        [
            [255, 0, 128, 255],
            [255, 0, 128, 255],
            [227, 16, 143, 255],
            [195, 48, 175, 255],
            [195, 80, 207, 255],
            [227, 112, 239, 255],
            [255, 128, 255, 255],
            [255, 128, 255, 255],
        ],
        [
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [181, 56, 56, 255],
            [136, 126, 126, 255],
            [157, 151, 151, 255],
            [160, 142, 142, 255],
            [128, 128, 128, 255],
            [128, 128, 128, 255],
        ],
        [
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [128, 128, 128, 255],
            [128, 128, 128, 255],
            [128, 128, 128, 255],
            [128, 128, 128, 255],
        ],
        [
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
        ],
        [
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
        ],
    ];
    let square = |gl: &mut Gl, (r0, r1): (f32, f32), st: f32| {
        gl.begin(GL_QUADS);
        for (s, t, x, y) in [(0.0, 0.0, -1.0, -1.0), (st, 0.0, 1.0, -1.0), (st, st, 1.0, 1.0), (0.0, st, -1.0, 1.0)] {
            gl.tex_coord3f(s, t, if s == 0.0 { r0 } else { r1 });
            gl.vertex2f(x, y);
        }
        gl.end();
    };
    let mut gl = Gl::new(8, 8);
    let mut frames = Vec::new();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.bind_texture(GL_TEXTURE_3D, 1);
    let texels =
        [255u8, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 0, 255, 255, 255, 0, 255, 255, 255, 0, 128, 128, 128];
    gl.tex_image_3d(GL_TEXTURE_3D, 0, GL_RGB as i32, 2, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, &texels);
    gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    gl.tex_parameterfv(GL_TEXTURE_3D, GL_TEXTURE_BORDER_COLOR, &[1.0, 0.0, 1.0, 1.0]);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_3D);
    for (filter, wrap_r, r0, r1) in setups {
        gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, filter as i32);
        gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, filter as i32);
        gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, wrap_r as i32);
        square(&mut gl, (r0, r1), 1.0);
        frames.push(gl.take_frame());
    }
    gl.bind_texture(GL_TEXTURE_3D, 2);
    for (level, colour) in [[255u8, 0, 0], [0, 255, 0], [0, 0, 255]].into_iter().enumerate() {
        let side = 4 >> level;
        let image = colour.repeat((side * side * side) as usize);
        gl.tex_image_3d(
            GL_TEXTURE_3D,
            level as i32,
            GL_RGB as i32,
            side,
            side,
            side,
            0,
            GL_RGB,
            GL_UNSIGNED_BYTE,
            &image,
        );
    }
    gl.tex_parameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST as i32);
    square(&mut gl, (0.5, 0.5), 4.0);
    frames.push(gl.take_frame());
    gl.bind_texture(GL_TEXTURE_2D, 3);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, &[0u8, 0, 255]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    square(&mut gl, (0.5, 0.5), 1.0);
    frames.push(gl.take_frame());
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    for (k, (frame, expected)) in frames.iter().zip(&mesa).enumerate() {
        assert_diagonal_is_mesas(&mut renderer, frame, expected, 2, &format!("set-up {k}"));
    }
}

/// GL 1.3's `GL_COMBINE` environment drawn by both rasterisers, against what Mesa 22.3
/// (llvmpipe, OSMesa) drew for the same calls (`tests/reference/pixels/combine.c` prints these
/// values): a 1 × 1 texture (0.8, 0.6, 0.4, 0.5) of several base formats, the primary colour
/// (0.5, 0.25, 1, 0.75), the constant (0.9, 0.8, 0.1, 0.3); each function, source, operand and
/// scale, DOT3 (whose RGBA form scales its alpha by the alpha scale), the crossbar's
/// `GL_TEXTURE0`. One pixel each, within 2/255.
#[test]
fn combine_is_mesas_on_both_rasterisers() {
    const T: GLenum = GL_TEXTURE;
    const K: GLenum = GL_CONSTANT;
    const P: GLenum = GL_PRIMARY_COLOR;
    const V: GLenum = GL_PREVIOUS;
    const SC: GLenum = GL_SRC_COLOR;
    const MC: GLenum = GL_ONE_MINUS_SRC_COLOR;
    const SA: GLenum = GL_SRC_ALPHA;
    const MA: GLenum = GL_ONE_MINUS_SRC_ALPHA;
    type Half = (GLenum, [GLenum; 3], [GLenum; 3], f32);
    let setups: [(GLenum, Half, Half); 16] = [
        (GL_RGBA, (GL_MODULATE, [T, V, K], [SC, SC, SA], 1.0), (GL_MODULATE, [T, V, K], [SA, SA, SA], 1.0)),
        (GL_RGBA, (GL_REPLACE, [K, V, K], [SC, SC, SA], 1.0), (GL_REPLACE, [K, V, K], [SA, SA, SA], 1.0)),
        (GL_RGBA, (GL_ADD, [T, P, K], [SC, SC, SA], 1.0), (GL_ADD, [T, P, K], [SA, SA, SA], 1.0)),
        (GL_RGBA, (GL_ADD_SIGNED, [T, P, K], [SC, SC, SA], 2.0), (GL_ADD_SIGNED, [T, K, K], [SA, SA, SA], 2.0)),
        (GL_RGBA, (GL_INTERPOLATE, [T, P, K], [SC, SC, SA], 1.0), (GL_INTERPOLATE, [T, P, K], [SA, SA, SA], 1.0)),
        (GL_RGBA, (GL_SUBTRACT, [T, K, K], [SC, SC, SA], 1.0), (GL_SUBTRACT, [P, T, K], [SA, SA, SA], 4.0)),
        (GL_RGBA, (GL_DOT3_RGB, [T, K, K], [SC, SC, SA], 1.0), (GL_REPLACE, [P, T, K], [SA, SA, SA], 1.0)),
        (GL_RGBA, (GL_DOT3_RGBA, [T, T, K], [SC, SC, SA], 1.0), (GL_REPLACE, [P, T, K], [SA, SA, SA], 4.0)),
        (GL_RGBA, (GL_DOT3_RGB, [T, P, K], [MC, SC, SA], 4.0), (GL_MODULATE, [P, K, K], [MA, SA, SA], 2.0)),
        (GL_RGBA, (GL_MODULATE, [T, K, K], [MC, SA, SA], 2.0), (GL_MODULATE, [T, K, K], [MA, MA, SA], 1.0)),
        (GL_RGBA, (GL_INTERPOLATE, [K, P, T], [SC, MC, MA], 1.0), (GL_INTERPOLATE, [K, P, T], [SA, MA, MA], 1.0)),
        (GL_LUMINANCE, (GL_MODULATE, [T, V, K], [SC, SC, SA], 1.0), (GL_REPLACE, [T, V, K], [SA, SA, SA], 1.0)),
        (GL_ALPHA, (GL_ADD, [T, V, K], [SC, SC, SA], 1.0), (GL_REPLACE, [T, V, K], [SA, SA, SA], 1.0)),
        (GL_INTENSITY, (GL_ADD, [T, K, K], [SC, SC, SA], 1.0), (GL_ADD, [T, K, K], [SA, SA, SA], 1.0)),
        (GL_LUMINANCE_ALPHA, (GL_REPLACE, [T, V, K], [SA, SC, SA], 1.0), (GL_REPLACE, [T, V, K], [MA, SA, SA], 1.0)),
        (
            GL_RGB,
            (GL_REPLACE, [GL_TEXTURE0, V, K], [SC, SC, SA], 1.0),
            (GL_REPLACE, [GL_TEXTURE0, V, K], [SA, SA, SA], 1.0),
        ),
    ];
    let mesa: [[u8; 4]; 16] = [
        [102, 38, 102, 96],
        [230, 204, 26, 76],
        [255, 217, 255, 255],
        [255, 179, 255, 154],
        [150, 91, 209, 172],
        [0, 0, 77, 253],
        [194, 194, 194, 191],
        [112, 112, 112, 255],
        [255, 255, 255, 38],
        [31, 61, 92, 89],
        [178, 198, 13, 70],
        [102, 51, 204, 255],
        [128, 64, 255, 128],
        [255, 255, 230, 255],
        [128, 128, 128, 127],
        [204, 153, 102, 255],
    ];
    let mut renderer = optional_renderer();
    let texel = [204u8, 153, 102, 128];
    for (k, ((format, rgb, alpha), expected)) in setups.into_iter().zip(mesa).enumerate() {
        let mut gl = Gl::new(2, 2);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
        gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.9, 0.8, 0.1, 0.3]);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as i32);
        gl.enable(GL_TEXTURE_2D);
        // The texel's components as the format reads them, as combine.c gives them.
        let (image_format, image) = match format {
            GL_ALPHA => (GL_ALPHA, vec![texel[3]]),
            GL_LUMINANCE_ALPHA => (GL_LUMINANCE_ALPHA, vec![texel[0], texel[3]]),
            GL_LUMINANCE | GL_INTENSITY => (GL_LUMINANCE, vec![texel[0]]),
            _ => (GL_RGBA, texel.to_vec()),
        };
        gl.tex_image_2d(GL_TEXTURE_2D, 0, format as i32, 1, 1, 0, image_format, GL_UNSIGNED_BYTE, &image);
        gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_RGB, rgb.0 as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha.0 as i32);
        for i in 0..3 {
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i as u32, rgb.1[i] as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i as u32, alpha.1[i] as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i as u32, rgb.2[i] as i32);
            gl.tex_envi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i as u32, alpha.2[i] as i32);
        }
        gl.tex_envf(GL_TEXTURE_ENV, GL_RGB_SCALE, rgb.3);
        gl.tex_envf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, alpha.3);
        gl.color4f(0.5, 0.25, 1.0, 0.75);
        gl.rectf(-1.0, -1.0, 1.0, 1.0);
        assert_eq!(gl.get_error(), GL_NO_ERROR, "set-up {k}");
        let frame = gl.take_frame();
        let close = |got: &[u8]| got.iter().zip(&expected).all(|(a, b)| a.abs_diff(*b) <= 2);
        let soft = soft::render_frame(&frame, 2, 2).pixels[8..12].to_vec();
        assert!(close(&soft), "CPU, set-up {k}: {soft:?}, Mesa {expected:?}");
        if let Some(renderer) = renderer.as_mut() {
            let wgpu = renderer.render_frame(&frame, 2, 2).expect("wgpu renders").pixels[8..12].to_vec();
            assert!(close(&wgpu), "wgpu, set-up {k}: {wgpu:?}, Mesa {expected:?}");
        }
    }
}

/// GL 1.3's `GL_CLAMP_TO_BORDER` and GL 1.4's `GL_MIRRORED_REPEAT` on both rasterisers, against
/// what Mesa 22.3 (llvmpipe, OSMesa) drew for the same calls
/// (`tests/reference/pixels/wrap_modes.c` prints these values): a 2 × 2 texture (red, green /
/// blue, white) with border colour (1, 0, 1, 1), nearest and linear, on an 8 × 8 square whose
/// coordinates reach a half (or one and a half) beyond the texture on each side; the diagonal's
/// pixels, within 2/255.
#[test]
fn wrap_modes_are_mesas_on_both_rasterisers() {
    let setups = [
        (GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER, GL_NEAREST, 0.5),
        (GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER, GL_LINEAR, 0.5),
        (GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT, GL_NEAREST, 1.5),
        (GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT, GL_LINEAR, 1.5),
        (GL_MIRRORED_REPEAT, GL_CLAMP_TO_BORDER, GL_LINEAR, 0.5),
        (GL_CLAMP_TO_BORDER, GL_REPEAT, GL_LINEAR, 1.5),
    ];
    let mesa: [[[u8; 4]; 8]; 6] = [
        [
            [255, 0, 255, 255],
            [255, 0, 255, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 0, 255, 255],
            [255, 0, 255, 255],
        ],
        [
            [255, 0, 255, 255],
            [255, 0, 239, 255],
            [255, 0, 112, 255],
            [159, 64, 64, 255],
            [159, 191, 191, 255],
            [255, 143, 255, 255],
            [255, 16, 255, 255],
            [255, 0, 255, 255],
        ],
        [
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
        ],
        [
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
        ],
        [
            [255, 0, 255, 255],
            [255, 0, 191, 255],
            [255, 0, 64, 255],
            [159, 64, 64, 255],
            [159, 191, 191, 255],
            [255, 191, 255, 255],
            [255, 64, 255, 255],
            [255, 0, 255, 255],
        ],
        [
            [255, 0, 255, 255],
            [255, 0, 255, 255],
            [255, 0, 255, 255],
            [255, 0, 0, 255],
            [255, 255, 255, 255],
            [255, 0, 255, 255],
            [255, 0, 255, 255],
            [255, 0, 255, 255],
        ],
    ];
    let mut renderer = optional_renderer();
    for (k, ((wrap_s, wrap_t, filter, reach), expected)) in setups.into_iter().zip(mesa).enumerate() {
        let mut gl = Gl::new(8, 8);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        let texels = [255u8, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255];
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, &texels);
        gl.tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &[1.0, 0.0, 1.0, 1.0]);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap_s as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap_t as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter as i32);
        let (lo, hi) = (-reach, 1.0 + reach);
        gl.begin(GL_QUADS);
        for (s, t, x, y) in [(lo, lo, -1.0, -1.0), (hi, lo, 1.0, -1.0), (hi, hi, 1.0, 1.0), (lo, hi, -1.0, 1.0)] {
            gl.tex_coord2f(s, t);
            gl.vertex2f(x, y);
        }
        gl.end();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        assert_diagonal_is_mesas(&mut renderer, &frame, &expected, 2, &format!("set-up {k}"));
    }
}

/// GL 1.4's point parameters on both rasterisers, against what Mesa 22.3 (llvmpipe, OSMesa)
/// drew for the same calls (`tests/reference/pixels/point_parameters.c` prints these values):
/// one aliased point a frame, its size attenuated by the distance and clamped to the minimum
/// and maximum; the number of pixels drawn and their bounding box (x0, y0, x1, y1, GL's
/// window coordinates), exactly.
#[test]
fn point_parameters_are_mesas_on_both_rasterisers() {
    // (size, attenuation, min, max, eye z)
    let setups: [(f32, [f32; 3], f32, f32, f32); 11] = [
        (8.0, [1.0, 0.0, 0.0], 0.0, 255.0, 0.0),
        (8.0, [0.0, 1.0, 0.0], 0.0, 255.0, -2.0),
        (8.0, [0.0, 1.0, 0.0], 0.0, 255.0, -3.0),
        (8.0, [0.0, 0.0, 1.0], 0.0, 255.0, -1.5),
        (1.0, [1.0, 0.0, 0.0], 3.0, 255.0, 0.0),
        (8.0, [1.0, 0.0, 0.0], 0.0, 5.0, 0.0),
        (8.0, [0.0, 0.0, 1.0], 3.0, 255.0, -10.0),
        (1.0, [1.0, 0.0, 0.0], 7.0, 2.0, 0.0),
        (8.0, [2.0, 0.0, 0.0], 0.0, 255.0, 0.0),
        (6.0, [0.0, 1.0, 0.0], 0.0, 255.0, 2.0),
        (9.0, [0.5, 0.25, 0.0], 0.0, 255.0, -6.0),
    ];
    let mesa: [[i32; 5]; 11] = [
        [64, 12, 12, 19, 19],
        [36, 13, 13, 18, 18],
        [25, 14, 14, 18, 18],
        [25, 14, 14, 18, 18],
        [9, 15, 15, 17, 17],
        [25, 14, 14, 18, 18],
        [9, 15, 15, 17, 17],
        [49, 13, 13, 19, 19],
        [36, 13, 13, 18, 18],
        [16, 14, 14, 17, 17],
        [36, 13, 13, 18, 18],
    ];
    const W: usize = 32;
    let drawn = |pixels: &[u8]| {
        let (mut n, mut x0, mut y0, mut x1, mut y1) = (0, W as i32, W as i32, -1, -1);
        for row in 0..W {
            for x in 0..W {
                if pixels[(row * W + x) * 4] != 0 {
                    let (x, y) = (x as i32, (W - 1 - row) as i32);
                    n += 1;
                    (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
                }
            }
        }
        [n, x0, y0, x1, y1]
    };
    let mut renderer = optional_renderer();
    for (k, ((size, attenuation, min, max, z), expected)) in setups.into_iter().zip(mesa).enumerate() {
        let mut gl = Gl::new(W as i32, W as i32);
        gl.matrix_mode(GL_PROJECTION);
        gl.ortho(-1.0, 1.0, -1.0, 1.0, -100.0, 100.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.point_size(size);
        gl.point_parameterfv(GL_POINT_DISTANCE_ATTENUATION, &attenuation);
        gl.point_parameterf(GL_POINT_SIZE_MIN, min);
        gl.point_parameterf(GL_POINT_SIZE_MAX, max);
        gl.begin(GL_POINTS);
        gl.vertex3f(0.0, 0.0, z);
        gl.end();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        let soft = drawn(&soft::render_frame(&frame, W as u32, W as u32).pixels);
        assert_eq!(soft, expected, "CPU, set-up {k}");
        if let Some(renderer) = renderer.as_mut() {
            let wgpu = drawn(&renderer.render_frame(&frame, W as u32, W as u32).expect("wgpu renders").pixels);
            assert_eq!(wgpu, expected, "wgpu, set-up {k}");
        }
    }
}

/// GL 1.4's fog coordinate on both rasterisers (and the GPU mesh path), against what Mesa 22.3
/// (llvmpipe, OSMesa) drew for the same calls (`tests/reference/pixels/fog_coord.c` prints
/// these values): a red square fogged blue from its vertices' `glFogCoord` (left edge c0, right
/// edge c1; Mesa takes each vertex's absolute value, so -2 and 2 fog alike), in linear and
/// exponential fog, from immediate calls and from a fog coordinate array; the eye distance
/// under `GL_FRAGMENT_DEPTH`; an evaluated patch, which takes the current coordinate. The
/// diagonal's pixels, within 2/255.
#[test]
fn fog_coordinates_are_mesas_on_both_rasterisers() {
    #[derive(Clone, Copy)]
    enum How {
        Immediate,
        Array,
        Evaluated,
    }
    let setups = [
        (GL_FOG_COORD, GL_LINEAR, 0.0, 2.0, How::Immediate),
        (GL_FOG_COORD, GL_LINEAR, -2.0, 2.0, How::Immediate),
        (GL_FOG_COORD, GL_EXP, 0.0, 3.0, How::Immediate),
        (GL_FOG_COORD, GL_LINEAR, 0.5, 1.5, How::Array),
        (GL_FRAGMENT_DEPTH, GL_LINEAR, 0.0, 2.0, How::Immediate),
        (GL_FOG_COORD, GL_LINEAR, 0.5, 0.5, How::Evaluated),
    ];
    let mesa: [[[u8; 4]; 8]; 6] = [
        [
            [239, 0, 16, 255],
            [207, 0, 48, 255],
            [175, 0, 80, 255],
            [143, 0, 112, 255],
            [112, 0, 143, 255],
            [80, 0, 175, 255],
            [48, 0, 207, 255],
            [16, 0, 239, 255],
        ],
        [
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
        ],
        [
            [211, 0, 44, 255],
            [145, 0, 110, 255],
            [100, 0, 155, 255],
            [69, 0, 186, 255],
            [47, 0, 208, 255],
            [32, 0, 223, 255],
            [22, 0, 233, 255],
            [15, 0, 240, 255],
        ],
        [
            [183, 0, 72, 255],
            [167, 0, 88, 255],
            [151, 0, 104, 255],
            [135, 0, 120, 255],
            [120, 0, 135, 255],
            [104, 0, 151, 255],
            [88, 0, 167, 255],
            [72, 0, 183, 255],
        ],
        [
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
        ],
        [
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
            [191, 0, 64, 255],
        ],
    ];
    let patch = [-1.0, -1.0, 0.5, 1.0, -1.0, 0.5, -1.0, 1.0, 0.5, 1.0, 1.0, 0.5];
    let mut renderer = optional_renderer();
    for (k, ((source, mode, c0, c1, how), expected)) in setups.into_iter().zip(mesa).enumerate() {
        let mut gl = Gl::new(8, 8);
        gl.enable(GL_FOG);
        gl.fogfv(GL_FOG_COLOR, &[0.0, 0.0, 1.0, 1.0]);
        gl.fogf(GL_FOG_START, 0.0);
        gl.fogf(GL_FOG_END, 2.0);
        gl.fogf(GL_FOG_DENSITY, 1.0);
        gl.color3f(1.0, 0.0, 0.0);
        gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 2, 0.0, 1.0, 6, 2, &patch);
        gl.enable(GL_MAP2_VERTEX_3);
        gl.map_grid2f(4, 0.0, 1.0, 4, 0.0, 1.0);
        gl.fogi(GL_FOG_COORD_SRC, source as i32);
        gl.fogi(GL_FOG_MODE, mode as i32);
        let xy = ClientArray::new(&[-1.0f32, -1.0, 1.0, -1.0, 1.0, 1.0, -1.0, 1.0]);
        let coords = [c0, c1, c1, c0];
        match how {
            How::Immediate => {
                gl.begin(GL_QUADS);
                for (v, &c) in coords.iter().enumerate() {
                    gl.fog_coordf(c);
                    gl.vertex3f([-1.0, 1.0, 1.0, -1.0][v], [-1.0, -1.0, 1.0, 1.0][v], -0.5);
                }
                gl.end();
            }
            How::Array => {
                let fog = ClientArray::new(&coords);
                gl.vertex_pointer(2, GL_FLOAT, 0, &xy);
                gl.fog_coord_pointer(GL_FLOAT, 0, &fog);
                gl.enable_client_state(GL_VERTEX_ARRAY);
                gl.enable_client_state(GL_FOG_COORD_ARRAY);
                gl.draw_arrays(GL_QUADS, 0, 4);
            }
            How::Evaluated => {
                gl.fog_coordf(c0);
                gl.eval_mesh2(GL_FILL, 0, 4, 0, 4);
            }
        }
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        assert_diagonal_is_mesas(&mut renderer, &frame, &expected, 2, &format!("set-up {k}"));
    }
}

/// GL 1.3's texture units (§3.8.15), each enabled unit applying its environment to the previous
/// unit's result, against what Mesa 22.3 (llvmpipe, OSMesa) drew for the same calls
/// (`tests/reference/pixels/multitexture.c` prints these values): three 2 × 2 nearest textures
/// (RGB on unit 0, RGBA on unit 1, luminance on unit 2) over an 8 × 8 quad; modulate then add,
/// replace then decal, unit 0 disabled, three units, texgen on unit 1, a texture matrix on
/// unit 1, `GL_COMBINE` on unit 1 reading unit 0's texel (the crossbar), `glDrawPixels` with
/// unit 1 alone (llvmpipe samples it at (0, 0), not at the raster position's coordinates). The
/// diagonal within 2/255. The wgpu renderer hands such a frame to the CPU rasteriser (`gpu/fallback.rs`).
#[test]
fn multitexture_is_mesas_on_both_rasterisers() {
    let mesa: [[[u8; 4]; 8]; 8] = [
        [
            [120, 90, 140, 128],
            [120, 90, 140, 128],
            [120, 90, 140, 128],
            [120, 90, 140, 128],
            [120, 180, 240, 96],
            [120, 180, 240, 96],
            [120, 180, 240, 96],
            [120, 180, 240, 96],
        ],
        [
            [20, 60, 100, 128],
            [20, 60, 100, 128],
            [20, 60, 100, 128],
            [20, 60, 100, 128],
            [59, 59, 59, 128],
            [59, 59, 59, 128],
            [59, 59, 59, 128],
            [59, 59, 59, 128],
        ],
        [
            [10, 45, 100, 128],
            [10, 45, 100, 128],
            [10, 45, 100, 128],
            [10, 45, 100, 128],
            [0, 0, 0, 96],
            [0, 0, 0, 96],
            [0, 0, 0, 96],
            [0, 0, 0, 96],
        ],
        [
            [109, 98, 150, 128],
            [109, 98, 150, 128],
            [109, 98, 150, 128],
            [109, 98, 150, 128],
            [75, 138, 201, 96],
            [75, 138, 201, 96],
            [75, 138, 201, 96],
            [75, 138, 201, 96],
        ],
        [
            [100, 20, 60, 64],
            [100, 20, 60, 64],
            [100, 20, 60, 64],
            [100, 20, 60, 64],
            [60, 100, 20, 128],
            [60, 100, 20, 128],
            [60, 100, 20, 128],
            [60, 100, 20, 128],
        ],
        [
            [8, 7, 16, 128],
            [8, 7, 16, 128],
            [39, 2, 9, 32],
            [39, 2, 9, 32],
            [0, 0, 0, 96],
            [0, 0, 0, 96],
            [28, 71, 19, 64],
            [28, 71, 19, 64],
        ],
        [
            [110, 50, 70, 128],
            [110, 50, 70, 128],
            [110, 50, 70, 128],
            [110, 50, 70, 128],
            [120, 120, 120, 96],
            [120, 120, 120, 96],
            [120, 120, 120, 96],
            [120, 120, 120, 96],
        ],
        [[20, 60, 100, 255]; 8],
    ];
    let images: [(GLenum, &[u8]); 3] = [
        (GL_RGB, &[200, 40, 40, 40, 200, 40, 40, 40, 200, 240, 240, 240]),
        (GL_RGBA, &[20, 60, 100, 255, 100, 20, 60, 64, 60, 100, 20, 128, 0, 0, 0, 192]),
        (GL_LUMINANCE, &[51, 102, 153, 204]),
    ];
    let unit = |gl: &mut Gl, u: GLenum, enabled: bool, mode: GLenum| {
        gl.active_texture(u);
        if enabled {
            gl.enable(GL_TEXTURE_2D);
        } else {
            gl.disable(GL_TEXTURE_2D);
        }
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode as GLint);
    };
    let mut renderer = optional_renderer();
    for (setup, expected) in mesa.iter().enumerate() {
        let mut gl = Gl::new(8, 8);
        for (k, (format, image)) in images.iter().enumerate() {
            gl.active_texture(GL_TEXTURE0 + k as GLenum);
            gl.bind_texture(GL_TEXTURE_2D, k as GLuint + 1);
            gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
            gl.tex_image_2d(GL_TEXTURE_2D, 0, *format as GLint, 2, 2, 0, *format, GL_UNSIGNED_BYTE, image);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as GLint);
            gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as GLint);
        }
        gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[0.25, 0.5, 0.75, 1.0]);
        unit(&mut gl, GL_TEXTURE2, setup == 3, GL_BLEND);
        match setup {
            0 | 3 => {
                unit(&mut gl, GL_TEXTURE0, true, GL_MODULATE);
                unit(&mut gl, GL_TEXTURE1, true, GL_ADD);
            }
            1 => {
                unit(&mut gl, GL_TEXTURE0, true, GL_REPLACE);
                unit(&mut gl, GL_TEXTURE1, true, GL_DECAL);
            }
            2 => {
                unit(&mut gl, GL_TEXTURE0, false, GL_REPLACE);
                unit(&mut gl, GL_TEXTURE1, true, GL_MODULATE);
            }
            4 => {
                unit(&mut gl, GL_TEXTURE0, true, GL_MODULATE);
                unit(&mut gl, GL_TEXTURE1, true, GL_REPLACE);
                gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as GLint);
                gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR as GLint);
                gl.tex_genfv(GL_S, GL_OBJECT_PLANE, &[-0.5, 0.0, 0.0, 0.5]);
                gl.tex_genfv(GL_T, GL_OBJECT_PLANE, &[0.0, 0.5, 0.0, 0.5]);
                gl.enable(GL_TEXTURE_GEN_S);
                gl.enable(GL_TEXTURE_GEN_T);
            }
            5 => {
                unit(&mut gl, GL_TEXTURE0, true, GL_MODULATE);
                unit(&mut gl, GL_TEXTURE1, true, GL_MODULATE);
                gl.matrix_mode(GL_TEXTURE);
                gl.translatef(0.25, 0.0, 0.0);
                gl.matrix_mode(GL_MODELVIEW);
            }
            6 => {
                unit(&mut gl, GL_TEXTURE0, true, GL_REPLACE);
                unit(&mut gl, GL_TEXTURE1, true, GL_COMBINE);
                for (pname, value) in [
                    (GL_COMBINE_RGB, GL_INTERPOLATE),
                    (GL_SOURCE0_RGB, GL_TEXTURE0),
                    (GL_SOURCE1_RGB, GL_TEXTURE),
                    (GL_SOURCE2_RGB, GL_PRIMARY_COLOR),
                    (GL_OPERAND2_RGB, GL_SRC_ALPHA),
                    (GL_COMBINE_ALPHA, GL_MODULATE),
                    (GL_SOURCE0_ALPHA, GL_PREVIOUS),
                    (GL_SOURCE1_ALPHA, GL_TEXTURE),
                ] {
                    gl.tex_envi(GL_TEXTURE_ENV, pname, value as GLint);
                }
            }
            _ => {
                unit(&mut gl, GL_TEXTURE0, false, GL_REPLACE);
                unit(&mut gl, GL_TEXTURE1, true, GL_MODULATE);
            }
        }
        gl.color4f(0.5, 0.75, 1.0, 0.5);
        if setup == 7 {
            gl.multi_tex_coord2f(GL_TEXTURE1, 0.75, 0.25);
            gl.raster_pos2f(-1.0, -1.0);
            gl.draw_pixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, &[255u8; 8 * 8 * 4]);
        } else {
            gl.begin(GL_QUADS);
            for [x, y] in [[-1.0f32, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]] {
                for u in 0..3 {
                    gl.multi_tex_coord2f(GL_TEXTURE0 + u, (x + 1.0) / 2.0, (y + 1.0) / 2.0);
                }
                gl.vertex2f(x, y);
            }
            gl.end();
        }
        assert_eq!(gl.get_error(), GL_NO_ERROR, "set-up {setup}");
        let frame = gl.take_frame();
        assert_diagonal_is_mesas(&mut renderer, &frame, expected, 2, &format!("set-up {setup}"));
    }
}

/// GL 1.4's LOD bias on both rasterisers (wgpu through the CPU rasteriser, `gpu/fallback.rs`),
/// against what Mesa 22.3 (llvmpipe, OSMesa) drew for the same calls
/// (`tests/reference/pixels/lod_bias.c` prints these values): levels red, green, blue and white
/// on an 8 × 8 square at λ = log2(scale), biased by the unit's bias and the object's (their sum
/// clamped to ±16), then clamped by `GL_TEXTURE_MAX_LOD`; the diagonal's pixels, within 2/255.
#[test]
fn lod_bias_is_mesas_on_both_rasterisers() {
    // (filter, unit bias, object bias, scale, max LOD)
    let setups = [
        (GL_NEAREST_MIPMAP_NEAREST, 1.0, 0.0, 1.0, 1000.0),
        (GL_NEAREST_MIPMAP_NEAREST, 0.0, 2.0, 1.0, 1000.0),
        (GL_NEAREST_MIPMAP_NEAREST, 1.5, 1.5, 1.0, 1000.0),
        (GL_LINEAR_MIPMAP_LINEAR, 0.5, 0.0, 1.0, 1000.0),
        (GL_NEAREST_MIPMAP_NEAREST, 20.0, 0.0, 1.0, 1000.0),
        (GL_NEAREST_MIPMAP_NEAREST, -1.0, 0.0, 2.0, 1000.0),
        (GL_NEAREST_MIPMAP_NEAREST, 2.0, 0.0, 1.0, 1.0),
        (GL_LINEAR_MIPMAP_LINEAR, -0.25, 1.0, 1.0, 1000.0),
    ];
    let mesa: [[[u8; 4]; 8]; 8] = [
        [
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
        ],
        [
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
            [0, 0, 255, 255],
        ],
        [
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
        ],
        [
            [128, 128, 0, 255],
            [128, 128, 0, 255],
            [128, 128, 0, 255],
            [128, 128, 0, 255],
            [128, 128, 0, 255],
            [128, 128, 0, 255],
            [128, 128, 0, 255],
            [128, 128, 0, 255],
        ],
        [
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
            [255, 255, 255, 255],
        ],
        [
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
            [255, 0, 0, 255],
        ],
        [
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
            [0, 255, 0, 255],
        ],
        [
            [64, 191, 0, 255],
            [64, 191, 0, 255],
            [64, 191, 0, 255],
            [64, 191, 0, 255],
            [64, 191, 0, 255],
            [64, 191, 0, 255],
            [64, 191, 0, 255],
            [64, 191, 0, 255],
        ],
    ];
    let colours: [[u8; 3]; 4] = [[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 255]];
    let mut renderer = optional_renderer();
    for (k, ((filter, unit, object, scale, max_lod), expected)) in setups.into_iter().zip(mesa).enumerate() {
        let mut gl = Gl::new(8, 8);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        for (level, colour) in colours.iter().enumerate() {
            let side = 8 >> level;
            let texels: Vec<u8> = colour.iter().copied().cycle().take(side * side * 3).collect();
            gl.tex_image_2d(
                GL_TEXTURE_2D,
                level as i32,
                GL_RGB as i32,
                side as i32,
                side as i32,
                0,
                GL_RGB,
                GL_UNSIGNED_BYTE,
                &texels,
            );
        }
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
        gl.enable(GL_TEXTURE_2D);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter as i32);
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, object);
        gl.tex_parameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, max_lod);
        gl.tex_envf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, unit);
        gl.begin(GL_QUADS);
        for (s, t, x, y) in
            [(0.0, 0.0, -1.0, -1.0), (scale, 0.0, 1.0, -1.0), (scale, scale, 1.0, 1.0), (0.0, scale, -1.0, 1.0)]
        {
            gl.tex_coord2f(s, t);
            gl.vertex2f(x, y);
        }
        gl.end();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.take_frame();
        assert_diagonal_is_mesas(&mut renderer, &frame, &expected, 2, &format!("set-up {k}"));
    }
}

/// GL 1.3's cube maps drawn by both rasterisers, against what Mesa 22.3 (llvmpipe, OSMesa) drew
/// for the same calls (`tests/reference/pixels/cube_map.c` prints these values): six 2 × 2
/// faces whose texels name the face and the texel, on an 8 × 8 square whose directions point
/// at each face (0-5, nearest; 6 and 7 linear), a direction that crosses from +Y to ±X along
/// the diagonal (8), and an incomplete cube map: the unit draws with the enabled 2D texture
/// (9), or untextured without one (10), and the completed cube map goes first again (11).
#[test]
fn cube_maps_are_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    #[rustfmt::skip]
    let mesa: [[[u8; 4]; 8]; 12] = [
        [[20, 120, 120, 255], [20, 120, 120, 255], [20, 120, 120, 255], [20, 120, 120, 255], [20, 0, 0, 255], [20, 0, 0, 255], [20, 0, 0, 255], [20, 0, 0, 255]],
        [[60, 0, 120, 255], [60, 0, 120, 255], [60, 0, 120, 255], [60, 0, 120, 255], [60, 120, 0, 255], [60, 120, 0, 255], [60, 120, 0, 255], [60, 120, 0, 255]],
        [[100, 0, 0, 255], [100, 0, 0, 255], [100, 0, 0, 255], [100, 0, 0, 255], [100, 120, 120, 255], [100, 120, 120, 255], [100, 120, 120, 255], [100, 120, 120, 255]],
        [[140, 0, 120, 255], [140, 0, 120, 255], [140, 0, 120, 255], [140, 0, 120, 255], [140, 120, 0, 255], [140, 120, 0, 255], [140, 120, 0, 255], [140, 120, 0, 255]],
        [[180, 0, 120, 255], [180, 0, 120, 255], [180, 0, 120, 255], [180, 0, 120, 255], [180, 120, 0, 255], [180, 120, 0, 255], [180, 120, 0, 255], [180, 120, 0, 255]],
        [[220, 120, 120, 255], [220, 120, 120, 255], [220, 120, 120, 255], [220, 120, 120, 255], [220, 0, 0, 255], [220, 0, 0, 255], [220, 0, 0, 255], [220, 0, 0, 255]],
        [[20, 120, 120, 255], [20, 120, 120, 255], [20, 105, 105, 255], [20, 75, 75, 255], [20, 45, 45, 255], [20, 15, 15, 255], [20, 0, 0, 255], [20, 0, 0, 255]],
        [[220, 120, 120, 255], [220, 120, 120, 255], [220, 105, 105, 255], [220, 75, 75, 255], [220, 45, 45, 255], [220, 15, 15, 255], [220, 0, 0, 255], [220, 0, 0, 255]],
        [[60, 0, 0, 255], [60, 0, 0, 255], [100, 0, 0, 255], [100, 0, 0, 255], [100, 120, 120, 255], [100, 120, 120, 255], [20, 0, 0, 255], [20, 0, 0, 255]],
        [[0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255]],
        [[255, 0, 255, 255], [255, 0, 255, 255], [255, 0, 255, 255], [255, 0, 255, 255], [255, 0, 255, 255], [255, 0, 255, 255], [255, 0, 255, 255], [255, 0, 255, 255]],
        [[0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255]],
    ];
    // The square with direction component `axis` = `sign` and the next two (x, y, z order
    // after it) the square's x and y, scaled.
    let square = |gl: &mut Gl, axis: usize, sign: f32, (sx, sy): (f32, f32)| {
        gl.begin(GL_QUADS);
        for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let mut d = [0.0; 3];
            d[axis] = sign;
            d[(axis + 1) % 3] = x * sx;
            d[(axis + 2) % 3] = y * sy;
            gl.tex_coord3f(d[0], d[1], d[2]);
            gl.vertex2f(x, y);
        }
        gl.end();
    };
    let mut gl = Gl::new(8, 8);
    let mut frames = Vec::new();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, 1);
    for face in 0..6u8 {
        let texels: Vec<u8> = (0..4).flat_map(|i| [40 * face + 20, 120 * (i & 1), 120 * (i >> 1)]).collect();
        let target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + GLenum::from(face);
        gl.tex_image_2d(target, 0, GL_RGB as i32, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, &texels);
    }
    let filter = |gl: &mut Gl, filter: GLenum| {
        gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, filter as i32);
        gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, filter as i32);
    };
    filter(&mut gl, GL_NEAREST);
    gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_CUBE_MAP);
    for face in 0..6 {
        square(&mut gl, face / 2, if face % 2 == 1 { -1.0 } else { 1.0 }, (1.0, 1.0));
        frames.push(gl.take_frame());
    }
    filter(&mut gl, GL_LINEAR);
    square(&mut gl, 0, 1.0, (1.0, 1.0));
    frames.push(gl.take_frame());
    square(&mut gl, 2, -1.0, (1.0, 1.0));
    frames.push(gl.take_frame());
    filter(&mut gl, GL_NEAREST);
    square(&mut gl, 1, 0.5, (0.9, 1.0));
    frames.push(gl.take_frame());
    let (blue, green) = ([0u8, 0, 255], [0u8, 255, 0]);
    gl.bind_texture(GL_TEXTURE_CUBE_MAP, 2);
    for face in 0..5 {
        let target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + face;
        gl.tex_image_2d(target, 0, GL_RGB as i32, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, &blue);
    }
    gl.tex_parameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.bind_texture(GL_TEXTURE_2D, 3);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, &green);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.color3f(1.0, 0.0, 1.0);
    square(&mut gl, 0, 1.0, (1.0, 1.0));
    frames.push(gl.take_frame());
    gl.disable(GL_TEXTURE_2D);
    square(&mut gl, 0, 1.0, (1.0, 1.0));
    frames.push(gl.take_frame());
    gl.tex_image_2d(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGB as i32, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, &blue);
    gl.enable(GL_TEXTURE_2D);
    square(&mut gl, 0, 1.0, (1.0, 1.0));
    frames.push(gl.take_frame());
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    for (k, (frame, expected)) in frames.iter().zip(&mesa).enumerate() {
        assert_diagonal_is_mesas(&mut renderer, frame, expected, 1, &format!("set-up {k}"));
    }
}

/// GL 1.4's depth textures drawn by both rasterisers, against what Mesa 22.3 (llvmpipe, OSMesa)
/// drew for the same calls (`tests/reference/pixels/depth_texture.c` prints these values): a
/// 4 × 1 texture of depths 0.1, 0.4, 0.6 and 0.9 on an 8 × 8 square whose r runs from r0 at
/// the left to r1 at the right, under each `GL_DEPTH_TEXTURE_MODE` (0-3), with `GL_ARB_shadow`'s
/// comparison under several functions (4, 5, 8, 10, 11; r outside [0, 1] in 8), compared
/// before the linear filter (6), the depths filtered (9), and modulated (7, 10); the
/// diagonal's pixels, within 1/255.
#[test]
fn depth_textures_are_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    let compare = GL_COMPARE_R_TO_TEXTURE;
    let setups = [
        (GL_LUMINANCE, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, (0.0, 1.0)),
        (GL_INTENSITY, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, (0.0, 1.0)),
        (GL_ALPHA, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, (0.0, 1.0)),
        (GL_RED, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, (0.0, 1.0)),
        (GL_LUMINANCE, compare, GL_LEQUAL, GL_NEAREST, GL_REPLACE, (0.0, 1.0)),
        (GL_INTENSITY, compare, GL_GREATER, GL_NEAREST, GL_REPLACE, (0.0, 1.0)),
        (GL_LUMINANCE, compare, GL_LEQUAL, GL_LINEAR, GL_REPLACE, (0.0, 1.0)),
        (GL_LUMINANCE, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_MODULATE, (0.0, 1.0)),
        (GL_LUMINANCE, compare, GL_LEQUAL, GL_NEAREST, GL_REPLACE, (-1.0, 2.0)),
        (GL_LUMINANCE, GL_NONE, GL_LEQUAL, GL_LINEAR, GL_REPLACE, (0.0, 1.0)),
        (GL_ALPHA, compare, GL_LESS, GL_NEAREST, GL_MODULATE, (0.5, 0.5)),
        (GL_LUMINANCE, compare, GL_ALWAYS, GL_NEAREST, GL_REPLACE, (0.0, 1.0)),
    ];
    #[rustfmt::skip]
    let mesa: [[[u8; 4]; 8]; 12] = [
        [[25, 25, 25, 128], [25, 25, 25, 128], [102, 102, 102, 128], [102, 102, 102, 128], [153, 153, 153, 128], [153, 153, 153, 128], [230, 230, 230, 128], [230, 230, 230, 128]],
        [[25, 25, 25, 25], [25, 25, 25, 25], [102, 102, 102, 102], [102, 102, 102, 102], [153, 153, 153, 153], [153, 153, 153, 153], [230, 230, 230, 230], [230, 230, 230, 230]],
        [[128, 255, 64, 25], [128, 255, 64, 25], [128, 255, 64, 102], [128, 255, 64, 102], [128, 255, 64, 153], [128, 255, 64, 153], [128, 255, 64, 230], [128, 255, 64, 230]],
        [[25, 0, 0, 128], [25, 0, 0, 128], [102, 0, 0, 128], [102, 0, 0, 128], [153, 0, 0, 128], [153, 0, 0, 128], [230, 0, 0, 128], [230, 0, 0, 128]],
        [[255, 255, 255, 128], [0, 0, 0, 128], [255, 255, 255, 128], [0, 0, 0, 128], [255, 255, 255, 128], [0, 0, 0, 128], [255, 255, 255, 128], [0, 0, 0, 128]],
        [[0, 0, 0, 0], [255, 255, 255, 255], [0, 0, 0, 0], [255, 255, 255, 255], [0, 0, 0, 0], [255, 255, 255, 255], [0, 0, 0, 0], [255, 255, 255, 255]],
        [[255, 255, 255, 128], [64, 64, 64, 128], [191, 191, 191, 128], [64, 64, 64, 128], [191, 191, 191, 128], [64, 64, 64, 128], [191, 191, 191, 128], [0, 0, 0, 128]],
        [[13, 25, 6, 128], [13, 25, 6, 128], [51, 102, 26, 128], [51, 102, 26, 128], [76, 153, 38, 128], [76, 153, 38, 128], [115, 230, 57, 128], [115, 230, 57, 128]],
        [[255, 255, 255, 128], [255, 255, 255, 128], [255, 255, 255, 128], [255, 255, 255, 128], [0, 0, 0, 128], [0, 0, 0, 128], [0, 0, 0, 128], [0, 0, 0, 128]],
        [[25, 25, 25, 128], [45, 45, 45, 128], [83, 83, 83, 128], [115, 115, 115, 128], [140, 140, 140, 128], [172, 172, 172, 128], [210, 210, 210, 128], [230, 230, 230, 128]],
        [[128, 255, 64, 0], [128, 255, 64, 0], [128, 255, 64, 0], [128, 255, 64, 0], [128, 255, 64, 128], [128, 255, 64, 128], [128, 255, 64, 128], [128, 255, 64, 128]],
        [[255, 255, 255, 128], [255, 255, 255, 128], [255, 255, 255, 128], [255, 255, 255, 128], [255, 255, 255, 128], [255, 255, 255, 128], [255, 255, 255, 128], [255, 255, 255, 128]],
    ];
    let mut gl = Gl::new(8, 8);
    let mut frames = Vec::new();
    gl.bind_texture(GL_TEXTURE_2D, 1);
    let depths = [0.1f32, 0.4, 0.6, 0.9];
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT as i32, 4, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &depths);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.color4f(0.5, 1.0, 0.25, 0.5);
    for (mode, compare_mode, func, filter, env, (r0, r1)) in setups {
        gl.tex_parameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, mode as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, compare_mode as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, func as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter as i32);
        gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter as i32);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env as i32);
        gl.begin(GL_QUADS);
        for (s, x, y) in [(0.0, -1.0, -1.0), (1.0, 1.0, -1.0), (1.0, 1.0, 1.0), (0.0, -1.0, 1.0)] {
            gl.tex_coord3f(s, 0.5, if s == 0.0 { r0 } else { r1 });
            gl.vertex2f(x, y);
        }
        gl.end();
        frames.push(gl.take_frame());
    }
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    for (k, (frame, expected)) in frames.iter().zip(&mesa).enumerate() {
        assert_diagonal_is_mesas(&mut renderer, frame, expected, 1, &format!("set-up {k}"));
    }
}

/// `GL_ARB_point_sprite` drawn by both rasterisers, against what Mesa 22.3 (llvmpipe, OSMesa)
/// drew for the same calls (`tests/reference/pixels/point_sprite.c` prints these values): an
/// 8-pixel point over the 8 × 8 window textured with a 2 × 2 texture (red, green / blue,
/// white): with `GL_COORD_REPLACE` the texture spans the point from its upper left (0), without
/// it the vertex's (0.75, 0.25) is green everywhere (1), `GL_POINT_SMOOTH` does not round a
/// sprite (2), no sprite (3), and a sprite on unit 1 alone, modulating unit 0's green (4).
#[test]
fn point_sprites_are_mesas_on_both_rasterisers() {
    let mut renderer = optional_renderer();
    #[rustfmt::skip]
    let mesa: [[[u8; 4]; 8]; 5] = [
        [[0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255]],
        [[0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255]],
        [[0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 0, 255, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255]],
        [[0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255]],
        [[0, 0, 0, 255], [0, 0, 0, 255], [0, 0, 0, 255], [0, 0, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255], [0, 255, 0, 255]],
    ];
    let mut gl = Gl::new(8, 8);
    let mut frames = Vec::new();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    for (unit, mode) in [(GL_TEXTURE0, GL_REPLACE), (GL_TEXTURE1, GL_MODULATE)] {
        gl.active_texture(unit);
        gl.bind_texture(GL_TEXTURE_2D, 1);
        gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, mode as i32);
    }
    gl.active_texture(GL_TEXTURE0);
    let texels = [255u8, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255];
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, &texels);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.point_size(8.0);
    let point = |gl: &mut Gl| {
        gl.begin(GL_POINTS);
        gl.multi_tex_coord2f(GL_TEXTURE0, 0.75, 0.25);
        gl.multi_tex_coord2f(GL_TEXTURE1, 0.75, 0.25);
        gl.vertex2f(0.0, 0.0);
        gl.end();
        gl.take_frame()
    };
    gl.enable(GL_POINT_SPRITE);
    gl.tex_envi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE as i32);
    frames.push(point(&mut gl));
    gl.tex_envi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE as i32);
    frames.push(point(&mut gl));
    gl.tex_envi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE as i32);
    gl.enable(GL_POINT_SMOOTH);
    frames.push(point(&mut gl));
    gl.disable(GL_POINT_SMOOTH);
    gl.disable(GL_POINT_SPRITE);
    frames.push(point(&mut gl));
    gl.enable(GL_POINT_SPRITE);
    gl.tex_envi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE as i32);
    gl.active_texture(GL_TEXTURE1);
    gl.enable(GL_TEXTURE_2D);
    gl.tex_envi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE as i32);
    frames.push(point(&mut gl));
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    for (k, (frame, expected)) in frames.iter().zip(&mesa).enumerate() {
        assert_diagonal_is_mesas(&mut renderer, frame, expected, 1, &format!("set-up {k}"));
    }
}
