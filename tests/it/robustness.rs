//! Property tests: random call sequences with bad arguments never panic, only ever set GL's
//! error codes, and leave the context fit for the next valid program (which then draws exactly
//! what it draws in a fresh context).

use gleval::prelude::*;
use proptest::prelude::*;

/// A GL call with arbitrary arguments.
#[derive(Clone, Debug)]
enum Call {
    Map1(u32, f32, f32, i32, i32, usize),
    Map2(u32, f32, f32, i32, i32, f32, f32, i32, i32, usize),
    Grid1(i32, f32, f32),
    Grid2(i32, f32, f32, i32, f32, f32),
    Mesh1(u32, i32, i32),
    Mesh2(u32, i32, i32, i32, i32),
    Coord2(f32, f32),
    Point2(i32, i32),
    Enable(u32),
    Disable(u32),
    Begin(u32),
    End,
    Vertex(f32, f32, f32),
    GetMap(u32, u32, usize),
    ActiveTexture(u32),
    PointSize(f32),
    Viewport(i32, i32, i32, i32),
    PushMatrix,
    PopMatrix,
}

fn target() -> impl Strategy<Value = u32> {
    prop_oneof![0x0D8Eu32..0x0D9A, 0x0DAEu32..0x0DBA, Just(GL_AUTO_NORMAL), Just(GL_LIGHTING), any::<u32>()]
}

fn small() -> impl Strategy<Value = i32> {
    prop_oneof![-3i32..40, Just(i32::MAX), Just(i32::MIN)]
}

fn float() -> impl Strategy<Value = f32> {
    prop_oneof![-2.0f32..2.0, Just(f32::NAN), Just(f32::INFINITY), Just(0.0)]
}

fn call() -> impl Strategy<Value = Call> {
    prop_oneof![
        (target(), float(), float(), small(), small(), 0usize..200)
            .prop_map(|(t, a, b, s, o, n)| Call::Map1(t, a, b, s, o, n)),
        (target(), float(), float(), small(), small(), float(), float(), small(), small(), 0usize..400)
            .prop_map(|(t, a, b, us, uo, c, d, vs, vo, n)| Call::Map2(t, a, b, us, uo, c, d, vs, vo, n)),
        (small(), float(), float()).prop_map(|(n, a, b)| Call::Grid1(n, a, b)),
        (small(), float(), float(), small(), float(), float())
            .prop_map(|(n, a, b, m, c, d)| Call::Grid2(n, a, b, m, c, d)),
        (prop_oneof![Just(GL_POINT), Just(GL_LINE), Just(GL_FILL), any::<u32>()], small(), small())
            .prop_map(|(m, a, b)| Call::Mesh1(m, a, b)),
        (
            prop_oneof![Just(GL_POINT), Just(GL_LINE), Just(GL_FILL), any::<u32>()],
            -2i32..30,
            -2i32..30,
            -2i32..30,
            -2i32..30
        )
            .prop_map(|(m, a, b, c, d)| Call::Mesh2(m, a, b, c, d)),
        (float(), float()).prop_map(|(u, v)| Call::Coord2(u, v)),
        (small(), small()).prop_map(|(i, j)| Call::Point2(i, j)),
        target().prop_map(Call::Enable),
        target().prop_map(Call::Disable),
        (0u32..12).prop_map(Call::Begin),
        Just(Call::End),
        (float(), float(), float()).prop_map(|(x, y, z)| Call::Vertex(x, y, z)),
        (target(), 0x09FFu32..0x0A04, 0usize..40).prop_map(|(t, q, n)| Call::GetMap(t, q, n)),
        (0x84BFu32..0x84E2).prop_map(Call::ActiveTexture),
        float().prop_map(Call::PointSize),
        (small(), small(), small(), small()).prop_map(|(a, b, c, d)| Call::Viewport(a, b, c, d)),
        Just(Call::PushMatrix),
        Just(Call::PopMatrix),
    ]
}

fn apply(gl: &mut Gl, c: &Call) {
    let points: Vec<f32> = (0..1200).map(|i| (i % 13) as f32 * 0.1 - 0.6).collect();
    match *c {
        Call::Map1(t, a, b, s, o, n) => gl.map1f(t, a, b, s, o, &points[..n]),
        Call::Map2(t, a, b, us, uo, c, d, vs, vo, n) => gl.map2f(t, a, b, us, uo, c, d, vs, vo, &points[..n]),
        Call::Grid1(n, a, b) => gl.map_grid1f(n, a, b),
        Call::Grid2(n, a, b, m, c, d) => gl.map_grid2f(n, a, b, m, c, d),
        Call::Mesh1(m, a, b) => gl.eval_mesh1(m, a, b.min(a.saturating_add(5000))),
        Call::Mesh2(m, a, b, c, d) => gl.eval_mesh2(m, a, b, c, d),
        Call::Coord2(u, v) => gl.eval_coord2f(u, v),
        Call::Point2(i, j) => gl.eval_point2(i, j),
        Call::Enable(t) => gl.enable(t),
        Call::Disable(t) => gl.disable(t),
        Call::Begin(m) => gl.begin(m),
        Call::End => gl.end(),
        Call::Vertex(x, y, z) => gl.vertex3f(x, y, z),
        Call::GetMap(t, q, n) => gl.get_mapfv(t, q, &mut vec![0.0; n]),
        Call::ActiveTexture(u) => gl.active_texture(u),
        Call::PointSize(s) => gl.point_size(s),
        Call::Viewport(a, b, c, d) => gl.viewport(a, b, c, d),
        Call::PushMatrix => gl.push_matrix(),
        Call::PopMatrix => gl.pop_matrix(),
    }
}

/// A valid program that sets every piece of state it relies on.
fn valid_program(gl: &mut Gl) -> Frame {
    if gl.get_error() == GL_NO_ERROR {
        // Nothing: the flag is read either way.
    }
    let patch: Vec<f32> = (0..16).flat_map(|k| [(k / 4) as f32, (k % 4) as f32, ((k * 7) % 5) as f32 * 0.2]).collect();
    gl.active_texture(GL_TEXTURE0);
    gl.viewport(0, 0, 64, 64);
    gl.point_size(1.0);
    for t in (GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4).chain(GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4) {
        gl.disable(t);
    }
    gl.enable(GL_AUTO_NORMAL);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &patch);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_grid2f(6, 0.0, 1.0, 5, 0.0, 1.0);
    gl.color4f(1.0, 0.5, 0.25, 1.0);
    gl.normal3f(0.0, 0.0, 1.0);
    gl.tex_coord4f(0.0, 0.0, 0.0, 1.0);
    gl.eval_mesh2(GL_FILL, 0, 6, 0, 5);
    gl.eval_mesh2(GL_LINE, 1, 4, 2, 5);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut frame = gl.take_frame();
    // Draw states carry the matrices, which the garbage may have changed: compare geometry.
    frame.states.clear();
    frame.calls.clear();
    frame
}

fn known_error(e: u32) -> bool {
    matches!(
        e,
        GL_NO_ERROR
            | GL_INVALID_ENUM
            | GL_INVALID_VALUE
            | GL_INVALID_OPERATION
            | GL_STACK_OVERFLOW
            | GL_STACK_UNDERFLOW
            | GL_OUT_OF_MEMORY
    )
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(400),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_calls_never_panic_and_leave_a_usable_context(calls in proptest::collection::vec(call(), 0..40)) {
        let mut gl = Gl::new(64, 64);
        for c in &calls {
            apply(&mut gl, c);
            let e = gl.get_error();
            prop_assert!(known_error(e), "unknown error code {e:#x} after {c:?}");
        }
        // Close any open primitive, as a program would before its next frame.
        gl.end();
        let _ = gl.get_error();
        let _ = gl.take_frame();
        let after_garbage = valid_program(&mut gl);
        let fresh = valid_program(&mut Gl::new(64, 64));
        prop_assert_eq!(after_garbage.vertices, fresh.vertices);
    }
}

/// A stencil, accumulation, mask, scissor, logic-op or buffer call with arbitrary arguments,
/// or a draw (a triangle and a line across the window).
#[derive(Clone, Debug)]
enum FragmentCall {
    StencilFunc(u32, i32, u32),
    StencilOp([u32; 3]),
    StencilMask(u32),
    ClearStencil(i32),
    Accum(u32, f32),
    ClearAccum([f32; 4]),
    Masks(u8, [u8; 4]),
    Scissor([i32; 4]),
    LogicOp(u32),
    Buffers(u32, u32),
    Enable(u32, bool),
    Clear(u32),
    Draw(f32),
    Swap,
}

fn fragment_call() -> impl Strategy<Value = FragmentCall> {
    let any_enum = prop_oneof![
        0x0200u32..0x0208,
        0x1E00u32..0x1E04,
        0x1500u32..0x1510,
        0x0100u32..0x0105,
        0x0400u32..0x040D,
        any::<u32>()
    ];
    let value = prop_oneof![
        Just(0.0f32),
        Just(1.0),
        Just(-1.0),
        Just(1e30),
        Just(-1e30),
        Just(f32::NAN),
        Just(f32::INFINITY),
        -4.0f32..4.0
    ];
    let int = prop_oneof![Just(i32::MIN), Just(i32::MAX), Just(-1), Just(0), Just(255), Just(256), -70i32..70];
    prop_oneof![
        (any_enum.clone(), int.clone(), any::<u32>()).prop_map(|(f, r, m)| FragmentCall::StencilFunc(f, r, m)),
        [any_enum.clone(), any_enum.clone(), any_enum.clone()].prop_map(FragmentCall::StencilOp),
        any::<u32>().prop_map(FragmentCall::StencilMask),
        int.clone().prop_map(FragmentCall::ClearStencil),
        (any_enum.clone(), value.clone()).prop_map(|(op, v)| FragmentCall::Accum(op, v)),
        [value.clone(), value.clone(), value.clone(), value.clone()].prop_map(FragmentCall::ClearAccum),
        (0u8..3, [0u8..2, 0u8..2, 0u8..2, 0u8..2]).prop_map(|(d, c)| FragmentCall::Masks(d, c)),
        [int.clone(), int.clone(), int.clone(), int].prop_map(FragmentCall::Scissor),
        any_enum.clone().prop_map(FragmentCall::LogicOp),
        (any_enum.clone(), any_enum.clone()).prop_map(|(d, r)| FragmentCall::Buffers(d, r)),
        (
            prop_oneof![Just(GL_STENCIL_TEST), Just(GL_SCISSOR_TEST), Just(GL_COLOR_LOGIC_OP), Just(GL_DEPTH_TEST)],
            any::<bool>()
        )
            .prop_map(|(c, on)| FragmentCall::Enable(c, on)),
        (0u32..0x4800).prop_map(FragmentCall::Clear),
        value.prop_map(FragmentCall::Draw),
        Just(FragmentCall::Swap),
    ]
}

fn apply_fragment(gl: &mut Gl, c: &FragmentCall) {
    match *c {
        FragmentCall::StencilFunc(f, r, m) => gl.stencil_func(f, r, m),
        FragmentCall::StencilOp([a, b, d]) => gl.stencil_op(a, b, d),
        FragmentCall::StencilMask(m) => gl.stencil_mask(m),
        FragmentCall::ClearStencil(s) => gl.clear_stencil(s),
        FragmentCall::Accum(op, v) => gl.accum(op, v),
        FragmentCall::ClearAccum([r, g, b, a]) => gl.clear_accum(r, g, b, a),
        FragmentCall::Masks(d, [r, g, b, a]) => {
            gl.depth_mask(d);
            gl.color_mask(r, g, b, a);
        }
        FragmentCall::Scissor([x, y, w, h]) => gl.scissor(x, y, w, h),
        FragmentCall::LogicOp(op) => gl.logic_op(op),
        FragmentCall::Buffers(d, r) => {
            gl.draw_buffer(d);
            gl.read_buffer(r);
        }
        FragmentCall::Enable(cap, on) => {
            if on {
                gl.enable(cap)
            } else {
                gl.disable(cap)
            }
        }
        FragmentCall::Clear(mask) => gl.clear(mask),
        FragmentCall::Draw(z) => {
            gl.begin(GL_TRIANGLES);
            gl.color4f(z, 0.5, -z, 1.0);
            gl.vertex3f(-1.0, -1.0, z.clamp(-2.0, 2.0));
            gl.vertex3f(1.0, -0.5, 0.0);
            gl.vertex3f(0.0, 1.0, -z.clamp(-2.0, 2.0));
            gl.end();
            gl.begin(GL_LINES);
            gl.vertex2f(-1.0, 0.3);
            gl.vertex2f(1.0, -0.3);
            gl.end();
        }
        FragmentCall::Swap => gl.glut_swap_buffers(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(200),
        ..ProptestConfig::default()
    })]

    /// Stencil and accumulation on every framebuffer shape (with and without a stencil, an
    /// accumulation and a back buffer), huge and non-finite values: only GL's errors, no panic,
    /// and the CPU rasteriser draws the frame and reads the stencil buffer back.
    #[test]
    fn fragment_calls_on_every_buffer_shape_never_panic(
        calls in proptest::collection::vec(fragment_call(), 0..30),
        (stencil, accum, double) in (prop_oneof![Just(0u8), Just(8)], prop_oneof![Just(0u8), Just(16)], any::<bool>()),
        read in (-3i32..20, -3i32..20, -1i32..20, -1i32..20, prop_oneof![Just(GL_UNSIGNED_BYTE), Just(GL_FLOAT), Just(GL_SHORT), Just(0x1234u32)]),
    ) {
        let mut gl = Gl::new(16, 16);
        gl.set_buffer_config(gleval::gl::BufferConfig { stencil_bits: stencil, accum_bits: accum, double });
        for c in &calls {
            apply_fragment(&mut gl, c);
            let e = gl.get_error();
            prop_assert!(known_error(e), "unknown error code {e:#x} after {c:?}");
        }
        let frame = gl.take_frame();
        let mut canvas = gleval::render::soft::Canvas::new(16, 16);
        canvas.draw_frame(&frame);
        let image = canvas.image();
        prop_assert_eq!(image.pixels.len(), 16 * 16 * 4);
        let stencil_buffer = canvas.stencil().to_vec();
        let (x, y, w, h, type_) = read;
        let mut out = vec![0u8; gl.packed_image_len(w, h, GL_STENCIL_INDEX, type_).unwrap_or(0)];
        gl.read_stencil_pixels((x, y), (w, h), type_, |_| Some(stencil_buffer), &mut out);
        prop_assert!(known_error(gl.get_error()));
    }
}
