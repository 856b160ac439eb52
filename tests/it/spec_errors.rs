//! Every Mesa error case of spec Part 1, sections 1.3 to 1.9, asserting the code GL sets, the
//! order of the checks, and that a failed call leaves the previous map untouched.

use gleval::prelude::*;

const CUBIC: [f32; 12] = [0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 2.0, -1.0, 0.0, 3.0, 0.0, 0.0];

fn gl_with_cubic() -> Gl {
    let mut gl = Gl::new(64, 64);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &CUBIC);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl
}

fn coeffs(gl: &mut Gl, target: GLenum) -> (Vec<f32>, Vec<f32>) {
    let mut c = vec![0.0; 30 * 30 * 4];
    let mut d = vec![0.0; 4];
    gl.get_mapfv(target, GL_COEFF, &mut c);
    gl.get_mapfv(target, GL_DOMAIN, &mut d);
    (c, d)
}

/// Runs `bad` on a context holding the cubic, checks the error and that the map is unchanged.
fn assert_map1_error(expected: GLenum, bad: impl FnOnce(&mut Gl)) {
    let mut gl = gl_with_cubic();
    let before = coeffs(&mut gl, GL_MAP1_VERTEX_3);
    bad(&mut gl);
    assert_eq!(gl.get_error(), expected);
    assert_eq!(coeffs(&mut gl, GL_MAP1_VERTEX_3), before, "failed map1 changed the map");
    assert_eq!(gl.get_error(), GL_NO_ERROR, "the flag is cleared by the read");
}

#[test]
fn map1_checks_in_mesa_order() {
    let p = [0.0f32; 3 * 31];
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_MAP1_VERTEX_3, 1.0, 1.0, 3, 4, &p));
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 0, &p));
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 31, &p));
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &[]));
    assert_map1_error(GL_INVALID_ENUM, |gl| gl.map1f(GL_FILL, 0.0, 1.0, 3, 4, &p));
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 2, 4, &p));
    // Value checks come before the enum check: u1 == u2 with a bad target is INVALID_VALUE.
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_FILL, 1.0, 1.0, 3, 4, &p));
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_FILL, 0.0, 1.0, 3, 0, &p));
    // ... and the target check before the stride check.
    assert_map1_error(GL_INVALID_ENUM, |gl| gl.map1f(GL_FILL, 0.0, 1.0, 0, 4, &p));
    // A MAP2 target passes the component lookup, so stride < k wins over its INVALID_ENUM.
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_MAP2_VERTEX_3, 0.0, 1.0, 2, 4, &p));
    assert_map1_error(GL_INVALID_ENUM, |gl| gl.map1f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 4, &p));
    // Order 30 is the largest accepted (MAX_EVAL_ORDER).
    let mut gl = Gl::new(1, 1);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 30, &p);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn map1d_compares_the_float_domain() {
    // 1 and 1 + 1e-12 are equal once cast to float, so this is u1 == u2.
    let p = [0.0f64; 12];
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1d(GL_MAP1_VERTEX_3, 1.0, 1.0 + 1e-12, 3, 4, &p));
}

#[test]
fn map1_with_texture_unit_other_than_0() {
    let p = [0.0f32; 12];
    assert_map1_error(GL_INVALID_OPERATION, |gl| {
        gl.active_texture(GL_TEXTURE1);
        gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &p);
    });
}

#[test]
fn map1_inside_begin_end() {
    let p = [0.0f32; 12];
    assert_map1_error(GL_INVALID_OPERATION, |gl| {
        gl.begin(GL_POINTS);
        gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &p);
        gl.end();
    });
}

#[test]
fn map1_slice_shorter_than_layout_is_invalid_value() {
    // Order 4 with stride 5 reads up to index 3*5 + 2 = 17.
    assert_map1_error(GL_INVALID_VALUE, |gl| gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 5, 4, &[0.0; 17]));
    let mut gl = Gl::new(1, 1);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 5, 4, &[0.0; 18]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

fn gl_with_patch() -> (Gl, (Vec<f32>, Vec<f32>)) {
    let mut gl = Gl::new(64, 64);
    let p: Vec<f32> = (0..2 * 3 * 3).map(|i| i as f32).collect();
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 9, 2, 0.0, 1.0, 3, 3, &p);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let before = coeffs(&mut gl, GL_MAP2_VERTEX_3);
    (gl, before)
}

fn assert_map2_error(expected: GLenum, bad: impl FnOnce(&mut Gl)) {
    let (mut gl, before) = gl_with_patch();
    bad(&mut gl);
    assert_eq!(gl.get_error(), expected);
    assert_eq!(coeffs(&mut gl, GL_MAP2_VERTEX_3), before, "failed map2 changed the map");
}

#[test]
fn map2_checks_in_mesa_order() {
    let p = [0.0f32; 4 * 4 * 4 * 31];
    let t = GL_MAP2_VERTEX_3;
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 1.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 0.0, 1.0, 3, 4, 2.0, 2.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 0.0, 1.0, 3, 0, 0.0, 1.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 0.0, 1.0, 3, 31, 0.0, 1.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 0, &p));
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 31, &p));
    assert_map2_error(GL_INVALID_ENUM, |gl| gl.map2f(GL_LINE, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 0.0, 1.0, 2, 4, 0.0, 1.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 0.0, 1.0, 3, 4, 0.0, 1.0, 2, 4, &p));
    // Order of checks: v1 == v2 before the orders, values before the enum, enum before strides.
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(GL_LINE, 0.0, 1.0, 3, 4, 1.0, 1.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_ENUM, |gl| gl.map2f(GL_LINE, 0.0, 1.0, 0, 4, 0.0, 1.0, 0, 4, &p));
    // A MAP1 target: strides checked with its k, then INVALID_ENUM from the missing 2D map.
    assert_map2_error(GL_INVALID_ENUM, |gl| gl.map2f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(GL_MAP1_VERTEX_4, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p));
    assert_map2_error(GL_INVALID_OPERATION, |gl| {
        gl.active_texture(GL_TEXTURE1);
        gl.map2f(t, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p);
    });
    assert_map2_error(GL_INVALID_OPERATION, |gl| {
        gl.begin(GL_TRIANGLES);
        gl.map2f(t, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p);
        gl.end();
    });
    // Shorter than the layout reads: (4-1)*3 + (4-1)*12 + 3 = 48 values needed.
    assert_map2_error(GL_INVALID_VALUE, |gl| gl.map2f(t, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p[..47]));
    assert_map2_error(GL_NO_ERROR, |_| {});
}

#[test]
fn map2_strides_are_copied_exactly() {
    // Points interleaved with junk: ustride 5, vstride 20 (u-major packed result).
    let mut src = vec![-99.0f32; 3 * 20 + 2 * 5 + 3];
    for i in 0..3 {
        for j in 0..2 {
            for c in 0..3 {
                src[i * 5 + j * 20 + c] = (100 * i + 10 * j + c) as f32;
            }
        }
    }
    let mut gl = Gl::new(1, 1);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 5, 3, 0.0, 1.0, 20, 2, &src);
    let mut c = [0.0f32; 18];
    gl.get_mapfv(GL_MAP2_VERTEX_3, GL_COEFF, &mut c);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let want: Vec<f32> =
        (0..3).flat_map(|i| (0..2).flat_map(move |j| (0..3).map(move |c| (100 * i + 10 * j + c) as f32))).collect();
    assert_eq!(c.to_vec(), want);
}

#[test]
fn map_grid_rejects_fewer_than_one_segment() {
    let mut gl = Gl::new(1, 1);
    for (un, vn) in [(0, 1), (1, 0), (-3, 5), (5, -3)] {
        gl.map_grid2f(un, 0.0, 1.0, vn, 0.0, 1.0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE, "({un},{vn})");
    }
    for un in [0, -1] {
        gl.map_grid1f(un, 0.0, 1.0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.map_grid1d(un, 0.0, 1.0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }
    // The failed calls left the initial grid (1 segment over [0,1]).
    let mut seg = [0; 2];
    gl.get_integerv(GL_MAP2_GRID_SEGMENTS, &mut seg);
    assert_eq!(seg, [1, 1]);
    // u1 == u2 and reversed domains are allowed.
    gl.map_grid1f(4, 2.0, 2.0);
    gl.map_grid2f(4, 1.0, 0.0, 2, 3.0, -3.0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let mut dom = [0.0f32; 4];
    gl.get_floatv(GL_MAP2_GRID_DOMAIN, &mut dom);
    assert_eq!(dom, [1.0, 0.0, 3.0, -3.0]);
    gl.begin(GL_POINTS);
    gl.map_grid1f(4, 0.0, 1.0);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn eval_mesh_mode_and_begin_end_errors() {
    let mut gl = gl_with_cubic();
    gl.enable(GL_MAP1_VERTEX_3);
    gl.eval_mesh1(GL_FILL, 0, 1);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.eval_mesh2(GL_POINTS, 0, 1, 0, 1);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.begin(GL_POINTS);
    gl.eval_mesh1(GL_LINE, 0, 1);
    gl.eval_mesh2(GL_FILL, 0, 1, 0, 1);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    // The bad mode is reported even when no vertex map is enabled (Mesa checks mode first).
    gl.disable(GL_MAP1_VERTEX_3);
    gl.eval_mesh1(GL_FILL, 0, 1);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    let f = gl.frame().expanded();
    assert_eq!((f.primitives.len(), f.vertices.len()), (1, 0), "only the user's empty begin/end");
}

#[test]
fn get_map_errors() {
    let mut gl = gl_with_cubic();
    let mut v = [0.0f32; 16];
    gl.get_mapfv(GL_FILL, GL_COEFF, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    gl.get_mapfv(GL_MAP1_VERTEX_3, GL_FILL, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    // Target is checked before query.
    gl.get_mapfv(GL_FILL, GL_FILL, &mut v);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    let mut short = [0.0f32; 11];
    gl.get_mapfv(GL_MAP1_VERTEX_3, GL_COEFF, &mut short);
    assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    assert_eq!(short, [0.0; 11], "nothing written on error");
    gl.begin(GL_POINTS);
    gl.get_mapfv(GL_MAP1_VERTEX_3, GL_ORDER, &mut v);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
}

#[test]
fn get_map_values_and_integer_rounding() {
    let mut gl = Gl::new(1, 1);
    let pts = [0.5f32, 1.5, -0.5, 2.4999, -1.5, 7.0];
    gl.map1f(GL_MAP1_VERTEX_3, -2.5, 3.5, 3, 2, &pts);
    let mut i = [0i32; 6];
    gl.get_mapiv(GL_MAP1_VERTEX_3, GL_COEFF, &mut i);
    // lroundf: halves away from zero.
    assert_eq!(i, [1, 2, -1, 2, -2, 7]);
    gl.get_mapiv(GL_MAP1_VERTEX_3, GL_DOMAIN, &mut i[..2]);
    assert_eq!(&i[..2], &[-3, 4]);
    let mut d = [0.0f64; 2];
    gl.get_mapdv(GL_MAP1_VERTEX_3, GL_ORDER, &mut d[..1]);
    assert_eq!(d[0], 2.0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn initial_state_matches_spec_1_10() {
    let mut gl = Gl::new(1, 1);
    let expect: [(GLenum, &[f32]); 9] = [
        (GL_MAP1_COLOR_4, &[1.0, 1.0, 1.0, 1.0]),
        (GL_MAP1_INDEX, &[1.0]),
        (GL_MAP1_NORMAL, &[0.0, 0.0, 1.0]),
        (GL_MAP1_TEXTURE_COORD_1, &[0.0]),
        (GL_MAP1_TEXTURE_COORD_2, &[0.0, 0.0]),
        (GL_MAP1_TEXTURE_COORD_3, &[0.0, 0.0, 0.0]),
        (GL_MAP1_TEXTURE_COORD_4, &[0.0, 0.0, 0.0, 1.0]),
        (GL_MAP1_VERTEX_3, &[0.0, 0.0, 0.0]),
        (GL_MAP1_VERTEX_4, &[0.0, 0.0, 0.0, 1.0]),
    ];
    for (t1, coeff) in expect {
        for target in [t1, t1 + (GL_MAP2_COLOR_4 - GL_MAP1_COLOR_4)] {
            let mut c = [9.0f32; 5];
            gl.get_mapfv(target, GL_COEFF, &mut c);
            assert_eq!(&c[..coeff.len()], coeff, "{target:#x}");
            assert_eq!(c[coeff.len()], 9.0, "{target:#x} wrote too much");
            let mut o = [0.0f32; 2];
            gl.get_mapfv(target, GL_ORDER, &mut o);
            assert_eq!(o[0], 1.0);
            let mut dom = [0.0f32; 4];
            gl.get_mapfv(target, GL_DOMAIN, &mut dom);
            assert_eq!(&dom[..2], &[0.0, 1.0]);
            assert_eq!(gl.is_enabled(target), GL_FALSE);
        }
    }
    assert_eq!(gl.is_enabled(GL_AUTO_NORMAL), GL_FALSE);
    let mut max = [0];
    gl.get_integerv(GL_MAX_EVAL_ORDER, &mut max);
    assert_eq!(max, [30]);
    let mut seg = [0; 2];
    gl.get_integerv(GL_MAP2_GRID_SEGMENTS, &mut seg);
    assert_eq!(seg, [1, 1]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn enable_errors_and_sticky_flag() {
    let mut gl = Gl::new(1, 1);
    gl.enable(0x1234_5678);
    assert_eq!(gl.is_enabled(0xDEAD), GL_FALSE);
    // The first error sticks until read; the second is lost.
    gl.begin(GL_POINTS);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    assert_eq!(gl.is_enabled(GL_MAP1_VERTEX_3), GL_FALSE);
    // glGetError inside begin/end returns 0 and records INVALID_OPERATION.
    gl.begin(GL_POINTS);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.end();
    gl.begin(GL_POLYGON + 1);
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    gl.begin(GL_POLYGON + 1);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
}

#[test]
fn nan_and_infinity_propagate_without_panic() {
    let mut gl = Gl::new(1, 1);
    let pts = [f32::NAN, 0.0, 0.0, f32::INFINITY, 1.0, 0.0, 1.0, 1.0, 0.0];
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 3, &pts);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(2, 0.0, 1.0);
    gl.eval_mesh1(GL_POINT, 0, 2);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let v = &gl.frame().expanded().vertices;
    assert!(v[1].position[0].is_nan());
    assert!(v[1].position[1].is_finite());
    // A NaN domain is accepted (NaN != NaN), and evaluates to NaN.
    gl.map1f(GL_MAP1_VERTEX_3, f32::NAN, 1.0, 3, 3, &pts);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

/// Without shaders GL 1.5 has `GL_MAX_TEXTURE_UNITS` units in all: the next one is
/// `GL_INVALID_ENUM` and leaves the active unit as it was (piglit's `texunits`; llvmpipe, which
/// has shader image units, takes it: a deviation of `multitexture.calls`).
#[test]
fn active_texture_stops_at_the_fixed_function_units() {
    let mut gl = Gl::new(4, 4);
    let mut units = [0];
    gl.get_integerv(GL_MAX_TEXTURE_UNITS, &mut units);
    assert_eq!(units[0], 8);
    gl.active_texture(GL_TEXTURE7);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl.active_texture(GL_TEXTURE0 + 8);
    assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    let mut active = [0];
    gl.get_integerv(GL_ACTIVE_TEXTURE, &mut active);
    assert_eq!(active[0], GL_TEXTURE7 as GLint);
}
