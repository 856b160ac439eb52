//! Property test: any line stipple, clip planes (NaN and infinite ones too), polygon offset,
//! smoothing, sizes and polygon modes, over primitives with any vertices (huge, infinite,
//! NaN), are assembled for the rasteriser without a panic and in bounded work.

use gleval::prelude::*;
use gleval::render::assemble;
use proptest::prelude::*;

fn coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![-2.0f32..2.0, Just(f32::NAN), Just(f32::INFINITY), Just(-1e30), Just(1e30), Just(0.0)]
}

#[derive(Clone, Debug)]
struct Modes {
    stipple: Option<(i32, u16)>,
    plane: Option<[f64; 4]>,
    offset: Option<(f32, f32)>,
    smooth: (bool, bool),
    sizes: (f32, f32),
    polygon_mode: u32,
}

fn modes() -> impl Strategy<Value = Modes> {
    let plane = prop::option::of(prop::array::uniform4(prop_oneof![-2.0f64..2.0, Just(f64::NAN), Just(f64::INFINITY)]));
    (
        prop::option::of((any::<i32>(), any::<u16>())),
        plane,
        prop::option::of((coordinate(), coordinate())),
        (any::<bool>(), any::<bool>()),
        (0.5f32..12.0, 0.5f32..12.0),
        prop_oneof![Just(GL_POINT), Just(GL_LINE), Just(GL_FILL)],
    )
        .prop_map(|(stipple, plane, offset, smooth, sizes, polygon_mode)| Modes {
            stipple,
            plane,
            offset,
            smooth,
            sizes,
            polygon_mode,
        })
}

fn apply(gl: &mut Gl, m: &Modes) {
    if let Some((factor, pattern)) = m.stipple {
        gl.line_stipple(factor, pattern);
        gl.enable(GL_LINE_STIPPLE);
    }
    if let Some(plane) = m.plane {
        gl.clip_plane(GL_CLIP_PLANE0, &plane);
        gl.enable(GL_CLIP_PLANE0);
    }
    if let Some((factor, units)) = m.offset {
        gl.polygon_offset(factor, units);
        gl.enable(GL_POLYGON_OFFSET_FILL);
        gl.enable(GL_POLYGON_OFFSET_LINE);
        gl.enable(GL_POLYGON_OFFSET_POINT);
    }
    if m.smooth.0 {
        gl.enable(GL_POINT_SMOOTH);
    }
    if m.smooth.1 {
        gl.enable(GL_LINE_SMOOTH);
    }
    gl.point_size(m.sizes.0);
    gl.line_width(m.sizes.1);
    gl.polygon_mode(GL_FRONT_AND_BACK, m.polygon_mode);
}

proptest! {
    #[test]
    fn any_raster_mode_assembles_without_panic(
        m in modes(),
        mode in 0u32..10,
        vertices in prop::collection::vec((coordinate(), coordinate(), coordinate(), prop_oneof![Just(1.0f32), -1.0f32..2.0]), 0..12),
    ) {
        let mut gl = Gl::new(64, 48);
        gl.matrix_mode(GL_PROJECTION);
        gl.frustum(-1.0, 1.0, -1.0, 1.0, 0.5, 10.0);
        gl.matrix_mode(GL_MODELVIEW);
        apply(&mut gl, &m);
        gl.begin(mode);
        for &(x, y, z, w) in &vertices {
            gl.vertex4f(x, y, z - 2.0, w);
        }
        gl.end();
        prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
        let list = assemble(&gl.take_frame());
        // Bounded: a stippled line is cut into at most one piece per two steps of the longest
        // line the view volume holds; each piece or smooth quad is a handful of vertices.
        prop_assert!(list.vertices.len() <= 12 * 65536 * 6);
    }
}
