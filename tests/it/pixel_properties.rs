//! Property tests for the pixel path: any zoom (huge, negative, zero, NaN, infinite), odd
//! image sizes, maps of every size, copies from anywhere, copies to textures and reads never
//! panic, only set GL's errors, and draw only inside the window on both rasterisers' CPU
//! stages; the zoomed fragments are exactly the window pixels the zoom rule covers.

use gleval::gl::pixel_zoom::{zoom_extent, zoomed_pixels};
use gleval::gl::WindowImage;
use gleval::prelude::*;
use gleval::render::soft;
use proptest::prelude::*;

/// A pixel-path call with arbitrary arguments.
#[derive(Clone, Debug)]
enum Call {
    Zoom(f32, f32),
    Transfer(u32, f32),
    Map(u32, i32, usize),
    RasterPos(f32, f32),
    Draw(i32, i32, u32, usize),
    Copy(i32, i32, i32, i32, u32),
    CopyTex(i32, u32, i32, i32, i32, i32, i32),
    CopySubTex(i32, i32, i32, i32, i32, i32, i32),
    Read(i32, i32, i32, i32, u32),
    Index(f32),
}

fn zoom() -> impl Strategy<Value = f32> {
    prop_oneof![
        -4.0f32..4.0,
        Just(0.0),
        Just(1e30),
        Just(-1e30),
        Just(f32::MAX),
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(1e-30)
    ]
}

fn size() -> impl Strategy<Value = i32> {
    prop_oneof![-2i32..40, Just(i32::MAX), Just(i32::MIN), Just(1 << 20)]
}

fn coord() -> impl Strategy<Value = i32> {
    prop_oneof![-40i32..80, Just(i32::MAX), Just(i32::MIN)]
}

fn pname() -> impl Strategy<Value = u32> {
    prop_oneof![0x0D10u32..0x0D20, Just(0x1234u32)]
}

fn map() -> impl Strategy<Value = u32> {
    prop_oneof![0x0C6Fu32..0x0C7B, any::<u32>()]
}

fn buffer() -> impl Strategy<Value = u32> {
    prop_oneof![Just(GL_COLOR), Just(GL_DEPTH), Just(GL_STENCIL), Just(0x1234u32)]
}

fn call() -> impl Strategy<Value = Call> {
    prop_oneof![
        (zoom(), zoom()).prop_map(|(x, y)| Call::Zoom(x, y)),
        (pname(), prop_oneof![-3.0f32..3.0, Just(f32::NAN), Just(1e30)]).prop_map(|(p, v)| Call::Transfer(p, v)),
        (map(), -2i32..300, 0usize..300).prop_map(|(m, n, len)| Call::Map(m, n, len)),
        (-5.0f32..40.0, -5.0f32..40.0).prop_map(|(x, y)| Call::RasterPos(x, y)),
        (size(), size(), prop_oneof![Just(GL_RGB), Just(GL_LUMINANCE), Just(GL_COLOR_INDEX)], 0usize..5000)
            .prop_map(|(w, h, f, len)| Call::Draw(w, h, f, len)),
        (coord(), coord(), size(), size(), buffer()).prop_map(|(x, y, w, h, b)| Call::Copy(x, y, w, h, b)),
        (
            -1i32..3,
            prop_oneof![Just(GL_RGB), Just(GL_DEPTH_COMPONENT), Just(3u32)],
            coord(),
            coord(),
            size(),
            size(),
            -1i32..2
        )
            .prop_map(|(l, f, x, y, w, h, b)| Call::CopyTex(l, f, x, y, w, h, b)),
        (-1i32..2, -2i32..20, -2i32..20, coord(), coord(), size(), size())
            .prop_map(|(l, ox, oy, x, y, w, h)| Call::CopySubTex(l, ox, oy, x, y, w, h)),
        (coord(), coord(), size(), size(), prop_oneof![Just(GL_RGBA), Just(GL_DEPTH_COMPONENT), Just(GL_LUMINANCE)])
            .prop_map(|(x, y, w, h, f)| Call::Read(x, y, w, h, f)),
        prop_oneof![Just(f32::NAN), -1e10f32..1e10].prop_map(Call::Index),
    ]
}

fn apply(gl: &mut Gl, c: &Call) {
    match *c {
        Call::Zoom(x, y) => gl.pixel_zoom(x, y),
        Call::Transfer(p, v) => gl.pixel_transferf(p, v),
        Call::Map(m, n, len) => gl.pixel_mapfv(m, n, &vec![0.5; len]),
        Call::RasterPos(x, y) => gl.raster_pos2f(x, y),
        Call::Draw(w, h, f, len) => gl.draw_pixels(w, h, f, GL_UNSIGNED_BYTE, &vec![200u8; len]),
        Call::Copy(x, y, w, h, b) => gl.copy_pixels(x, y, w, h, b),
        Call::CopyTex(l, f, x, y, w, h, b) => gl.copy_tex_image_2d(GL_TEXTURE_2D, l, f, x, y, w, h, b),
        Call::CopySubTex(l, ox, oy, x, y, w, h) => gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, l, ox, oy, x, y, w, h),
        Call::Read(x, y, w, h, f) => {
            let mut out = vec![0u8; 64 * 1024];
            gl.read_window_pixels((x, y), (w, h), f, GL_FLOAT, &mut out);
        }
        Call::Index(c) => gl.indexf(c),
    }
}

fn known_error(e: u32) -> bool {
    matches!(e, GL_NO_ERROR | GL_INVALID_ENUM | GL_INVALID_VALUE | GL_INVALID_OPERATION)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn random_pixel_calls_never_panic_and_stay_in_the_window(calls in proptest::collection::vec(call(), 0..24)) {
        let mut gl = Gl::new(32, 24);
        gl.set_window_reader(|frame, w, h| Some(soft::render_window(frame, w, h)));
        gl.matrix_mode(GL_PROJECTION);
        gl.ortho(0.0, 32.0, 0.0, 24.0, -1.0, 1.0);
        for c in &calls {
            apply(&mut gl, c);
            let e = gl.get_error();
            prop_assert!(known_error(e), "{c:?} gave 0x{e:x}");
        }
        let frame = gl.take_frame();
        let window = soft::render_window(&frame, 32, 24);
        prop_assert_eq!((window.width, window.height, window.color.len()), (32, 24, 32 * 24 * 4));
        for v in &frame.vertices {
            // Pixel fragments are recorded only inside the window, at pixel centres.
            prop_assert!((0.0..=32.0).contains(&v.position[0]) && (0.0..=24.0).contains(&v.position[1]));
        }
    }

    #[test]
    fn maps_of_every_size_read_back_whole(size in 1i32..=256, index in 0u32..10) {
        let mut gl = Gl::new(4, 4);
        let map = GL_PIXEL_MAP_I_TO_I + index;
        let values: Vec<f32> = (0..size).map(|k| k as f32 / size as f32).collect();
        gl.pixel_mapfv(map, size, &values);
        let power_of_two_needed = (GL_PIXEL_MAP_S_TO_S..=GL_PIXEL_MAP_I_TO_A).contains(&map);
        let accepted = !power_of_two_needed || (size as u32).is_power_of_two();
        prop_assert_eq!(gl.get_error(), if accepted { GL_NO_ERROR } else { GL_INVALID_VALUE });
        let expected = if accepted { size as usize } else { 1 };
        prop_assert_eq!(gl.pixel_map_size(map), expected);
        let mut out = vec![0.0f32; 256];
        gl.get_pixel_mapfv(map, &mut out);
        prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn zoomed_fragments_are_the_covered_window_pixels(
        origin in (-40i32..40, -40i32..40),
        z in (zoom(), zoom()),
        size in (0usize..12, 0usize..12),
    ) {
        let window = (16u32, 12u32);
        let mut seen = std::collections::HashSet::new();
        let columns = zoom_extent(origin.0, z.0, size.0, window.0);
        let rows = zoom_extent(origin.1, z.1, size.1, window.1);
        for ((i, j), (x, y)) in zoomed_pixels([origin.0, origin.1], [z.0, z.1], size, window) {
            prop_assert!(i < size.0 && j < size.1);
            prop_assert!(x < window.0 && y < window.1);
            prop_assert!(columns.contains(&x) && rows.contains(&y));
            prop_assert!(seen.insert((x, y)), "window pixel ({x}, {y}) drawn twice");
        }
        prop_assert_eq!(seen.len(), columns.len() * rows.len());
    }
}

#[test]
fn a_copy_reads_what_was_drawn_before_it_and_not_after() {
    let mut gl = Gl::new(8, 4);
    gl.matrix_mode(GL_PROJECTION);
    gl.ortho(0.0, 8.0, 0.0, 4.0, -1.0, 1.0);
    gl.color3f(1.0, 0.0, 0.0);
    gl.rectf(0.0, 0.0, 2.0, 2.0);
    gl.raster_pos2i(4, 0);
    gl.copy_pixels(0, 0, 2, 2, GL_COLOR);
    gl.color3f(0.0, 0.0, 1.0);
    gl.rectf(0.0, 0.0, 2.0, 2.0);
    let window: WindowImage = soft::render_window(&gl.take_frame(), 8, 4);
    assert_eq!(window.color_at(4, 0), Some([1.0, 0.0, 0.0, 1.0]), "the copy saw red");
    assert_eq!(window.color_at(0, 0), Some([0.0, 0.0, 1.0, 1.0]));
}

/// An 8 × 8 context whose window coordinates are its object coordinates, as the stencil tests'
/// OSMesa programs set it up.
fn pixel_window() -> Gl {
    let mut gl = Gl::new(8, 8);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 8.0, 0.0, 8.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl
}

/// The stencil buffer the CPU rasteriser leaves after `gl`'s frame, rows top first.
fn stencil_after(gl: &mut Gl) -> Vec<u8> {
    let mut canvas = gleval::render::soft::Canvas::new(8, 8);
    canvas.draw_frame(gl.frame());
    canvas.stencil().to_vec()
}

/// `glDrawPixels(GL_STENCIL_INDEX)` as Mesa 22.3 on llvmpipe does it, measured with an OSMesa
/// program (8 × 8, 8 stencil bits) making these calls and reading the stencil buffer back: the
/// low 8 bits of each index, truncated (−1 → 255, 1000 → 232, 300.0 → 44); the write mask and
/// the scissor apply, the stencil and depth tests do not, and neither do the index offset, the
/// index shift or `GL_MAP_STENCIL`. The expected buffer is Mesa's, but for two pixels of the
/// zoomed draw (2 × 1.5 at (1, 4)): Mesa's middle row takes its right half from the image's
/// first row and its left half from the second, where gleval, as for a zoomed colour image and
/// as Mesa's own stencil copy, takes both from the second (not reproduced: marked below).
#[test]
fn stencil_draws_are_mesas() {
    let mut gl = pixel_window();
    gl.clear_stencil(0);
    gl.clear(GL_STENCIL_BUFFER_BIT);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let v = [1u8, 2, 3, 250];
    let draw = |gl: &mut Gl, x: i32, y: i32| {
        gl.raster_pos2i(x, y);
        gl.draw_pixels(2, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &v);
    };
    draw(&mut gl, 0, 0);
    gl.pixel_transferi(GL_INDEX_OFFSET, 3);
    draw(&mut gl, 2, 0);
    gl.pixel_transferi(GL_INDEX_OFFSET, 0);
    gl.pixel_transferi(GL_INDEX_SHIFT, 1);
    draw(&mut gl, 4, 0);
    gl.pixel_transferi(GL_INDEX_SHIFT, 0);
    gl.pixel_mapuiv(GL_PIXEL_MAP_S_TO_S, 2, &[7, 8]);
    gl.pixel_transferi(GL_MAP_STENCIL, 1);
    draw(&mut gl, 6, 0);
    gl.pixel_transferi(GL_MAP_STENCIL, 0);
    gl.stencil_mask(3);
    draw(&mut gl, 0, 2);
    gl.stencil_mask(0xFF);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_NEVER, 0, 0xFF);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_NEVER);
    draw(&mut gl, 2, 2);
    gl.disable(GL_STENCIL_TEST);
    gl.disable(GL_DEPTH_TEST);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(0, 0, 5, 8);
    draw(&mut gl, 4, 2);
    gl.disable(GL_SCISSOR_TEST);
    gl.pixel_zoom(2.0, 1.5);
    draw(&mut gl, 1, 4);
    gl.pixel_zoom(1.0, 1.0);
    let shorts: Vec<u8> = [-1i16, 256, 257, 1000].iter().flat_map(|s| s.to_ne_bytes()).collect();
    gl.raster_pos2i(6, 4);
    gl.draw_pixels(2, 2, GL_STENCIL_INDEX, GL_SHORT, &shorts);
    let floats: Vec<u8> = [1.7f32, 2.2, -1.0, 300.0].iter().flat_map(|f| f.to_ne_bytes()).collect();
    gl.raster_pos2i(6, 6);
    gl.draw_pixels(2, 2, GL_STENCIL_INDEX, GL_FLOAT, &floats);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    // Rows top to bottom, as Mesa's program printed them.
    #[rustfmt::skip]
    let mesa = [
        0, 0, 0, 0, 0, 0, 255, 44,
        0, 3, 3, 250, 250, 0, 1, 2,
        0, 3, 3, 250, 250, 0, 1, 232, // Mesa: 0, 3, 3, 2, 2, 0, 1, 232
        0, 1, 1, 2, 2, 0, 255, 0,
        3, 2, 3, 250, 3, 0, 0, 0,
        1, 2, 1, 2, 1, 0, 0, 0,
        3, 250, 3, 250, 3, 250, 3, 250,
        1, 2, 1, 2, 1, 2, 1, 2,
    ];
    assert_eq!(stencil_after(&mut gl), mesa);
}

/// `glCopyPixels(GL_STENCIL)` as Mesa 22.3 on llvmpipe does it, measured with an OSMesa
/// program (8 × 8, 8 stencil bits) making these calls and reading the stencil buffer back:
/// the write mask and the scissor box apply, the stencil and depth tests and the index shift
/// and offset do not, the zoom covers its rectangle. The expected buffers are Mesa's.
#[test]
fn stencil_copies_are_mesas() {
    let mut gl = pixel_window();
    let clear_source = |gl: &mut Gl| {
        gl.clear_stencil(0);
        gl.clear(GL_STENCIL_BUFFER_BIT);
        gl.enable(GL_SCISSOR_TEST);
        gl.scissor(0, 0, 2, 2);
        gl.clear_stencil(5);
        gl.clear(GL_STENCIL_BUFFER_BIT);
    };
    clear_source(&mut gl);
    gl.scissor(1, 0, 1, 1);
    gl.clear_stencil(9);
    gl.clear(GL_STENCIL_BUFFER_BIT);
    gl.disable(GL_SCISSOR_TEST);
    let copy = |gl: &mut Gl, x: i32, y: i32| {
        gl.raster_pos2i(x, y);
        gl.copy_pixels(0, 0, 2, 2, GL_STENCIL);
    };
    copy(&mut gl, 4, 4);
    gl.pixel_transferi(GL_INDEX_OFFSET, 3);
    copy(&mut gl, 0, 4);
    gl.pixel_transferi(GL_INDEX_OFFSET, 0);
    gl.pixel_transferi(GL_INDEX_SHIFT, 1);
    copy(&mut gl, 2, 6);
    gl.pixel_transferi(GL_INDEX_SHIFT, 0);
    gl.stencil_mask(3);
    copy(&mut gl, 6, 0);
    gl.stencil_mask(0xFF);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(0, 0, 3, 8);
    copy(&mut gl, 2, 2);
    gl.disable(GL_SCISSOR_TEST);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let stencil = |gl: &mut Gl| stencil_after(gl);
    // Rows top to bottom, as Mesa's program printed them.
    #[rustfmt::skip]
    let mesa = [
        0, 0, 5, 5, 0, 0, 0, 0,
        0, 0, 5, 9, 0, 0, 0, 0,
        5, 5, 0, 0, 5, 5, 0, 0,
        5, 9, 0, 0, 5, 9, 0, 0,
        0, 0, 5, 0, 0, 0, 0, 0,
        0, 0, 5, 0, 0, 0, 0, 0,
        5, 5, 0, 0, 0, 0, 1, 1,
        5, 9, 0, 0, 0, 0, 1, 1,
    ];
    assert_eq!(stencil(&mut gl), mesa);
    clear_source(&mut gl);
    gl.disable(GL_SCISSOR_TEST);
    gl.pixel_zoom(2.0, 1.5);
    copy(&mut gl, 3, 3);
    gl.pixel_zoom(1.0, 1.0);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_NEVER, 0, 0xFF);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_NEVER);
    copy(&mut gl, 5, 5);
    #[rustfmt::skip]
    let mesa = [
        0, 0, 0, 0, 0, 0, 0, 0,
        0, 0, 0, 0, 0, 5, 5, 0,
        0, 0, 0, 5, 5, 5, 5, 0,
        0, 0, 0, 5, 5, 5, 5, 0,
        0, 0, 0, 5, 5, 5, 5, 0,
        0, 0, 0, 0, 0, 0, 0, 0,
        5, 5, 0, 0, 0, 0, 0, 0,
        5, 5, 0, 0, 0, 0, 0, 0,
    ];
    assert_eq!(stencil(&mut gl), mesa);
}

/// `glCopyPixels(GL_DEPTH_STENCIL)` (EXT_packed_depth_stencil, which Mesa takes in every
/// context) as Mesa 22.3 on llvmpipe does it, measured with an OSMesa program (8 × 8, 24 depth
/// and 8 stencil bits) making these calls and reading both buffers back: depths and stencil
/// indices copied together, whatever the depth test (off, `GL_ALWAYS` or `GL_NEVER`) and the
/// stencil test and its operations; the stencil write mask applies. The expected buffers are
/// Mesa's.
#[test]
fn depth_and_stencil_copies_are_mesas() {
    let mut gl = pixel_window();
    gl.clear_depth(0.0);
    gl.clear_stencil(0);
    gl.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_SCISSOR_TEST);
    gl.scissor(0, 0, 2, 2);
    gl.clear_depth(0.5);
    gl.clear_stencil(5);
    gl.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.scissor(1, 0, 1, 1);
    gl.clear_depth(0.25);
    gl.clear_stencil(9);
    gl.clear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.disable(GL_SCISSOR_TEST);
    let copy = |gl: &mut Gl, x: i32, y: i32| {
        gl.raster_pos2i(x, y);
        gl.copy_pixels(0, 0, 2, 2, GL_DEPTH_STENCIL);
    };
    copy(&mut gl, 4, 4);
    gl.enable(GL_DEPTH_TEST);
    gl.depth_func(GL_ALWAYS);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_ALWAYS, 7, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    copy(&mut gl, 0, 4);
    gl.depth_func(GL_NEVER);
    copy(&mut gl, 4, 0);
    gl.depth_func(GL_ALWAYS);
    gl.stencil_func(GL_NEVER, 0, 0xFF);
    gl.stencil_op(GL_INCR, GL_KEEP, GL_KEEP);
    copy(&mut gl, 2, 2);
    gl.disable(GL_DEPTH_TEST);
    gl.disable(GL_STENCIL_TEST);
    gl.stencil_mask(3);
    copy(&mut gl, 6, 6);
    gl.stencil_mask(0xFF);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut canvas = gleval::render::soft::Canvas::new(8, 8);
    canvas.draw_frame(gl.frame());
    // Rows top to bottom, as Mesa's program printed them: depth / stencil.
    #[rustfmt::skip]
    let mesa: [(f32, u8); 64] = [
        (0.0, 0), (0.0, 0), (0.0, 0), (0.0, 0), (0.0, 0), (0.0, 0), (0.5, 1), (0.5, 1),
        (0.0, 0), (0.0, 0), (0.0, 0), (0.0, 0), (0.0, 0), (0.0, 0), (0.5, 1), (0.25, 1),
        (0.5, 5), (0.5, 5), (0.0, 0), (0.0, 0), (0.5, 5), (0.5, 5), (0.0, 0), (0.0, 0),
        (0.5, 5), (0.25, 9), (0.0, 0), (0.0, 0), (0.5, 5), (0.25, 9), (0.0, 0), (0.0, 0),
        (0.0, 0), (0.0, 0), (0.5, 5), (0.5, 5), (0.0, 0), (0.0, 0), (0.0, 0), (0.0, 0),
        (0.0, 0), (0.0, 0), (0.5, 5), (0.25, 9), (0.0, 0), (0.0, 0), (0.0, 0), (0.0, 0),
        (0.5, 5), (0.5, 5), (0.0, 0), (0.0, 0), (0.5, 5), (0.5, 5), (0.0, 0), (0.0, 0),
        (0.5, 5), (0.25, 9), (0.0, 0), (0.0, 0), (0.5, 5), (0.25, 9), (0.0, 0), (0.0, 0),
    ];
    let depth = canvas.window_image().depth;
    let ours: Vec<(f32, u8)> = depth.iter().zip(canvas.stencil()).map(|(&d, &s)| (d, s)).collect();
    for (k, ((d, s), (md, ms))) in ours.iter().zip(&mesa).enumerate() {
        assert!((d - md).abs() < 1e-6 && s == ms, "pixel {k} (row {} from the top): {d}/{s}, Mesa {md}/{ms}", k / 8);
    }
}
