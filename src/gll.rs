//! The textbook's `gll.h` helpers (seed 004, 9.4.2, 9.4.3 and 9.6.2), written only on the public GL
//! and GLU API, as a student would write them.

use crate::gl::consts::*;
use crate::gl::Gl;
use crate::glu::consts::GLU_SAMPLING_TOLERANCE;

/// `gllBezCurve(pts, npts, un)`: a Bezier curve through `glMap1f` + `glEvalMesh1(GL_LINE)`
/// over `un` segments of [0, 1]. `pts` holds `npts` points of 3 floats.
pub fn bez_curve(gl: &mut Gl, pts: &[f32], npts: i32, un: i32) {
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, npts, pts);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(un, 0.0, 1.0);
    gl.eval_mesh1(GL_LINE, 0, un);
    gl.disable(GL_MAP1_VERTEX_3);
}

/// `gllBezSurface(mode, pts, uorder, vorder, un, vn)`: a Bezier patch whose control points are
/// stored row by row (`uorder` per row, `vorder` rows), drawn with `glEvalMesh2(mode)`.
pub fn bez_surface(gl: &mut Gl, mode: u32, pts: &[f32], uorder: i32, vorder: i32, un: i32, vn: i32) {
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, uorder, 0.0, 1.0, 3 * uorder, vorder, pts);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_grid2f(un, 0.0, 1.0, vn, 0.0, 1.0);
    gl.eval_mesh2(mode, 0, un, 0, vn);
    gl.disable(GL_MAP2_VERTEX_3);
}

/// `gllPoints(pts, npts)`: the control points as `GL_POINTS`.
pub fn points(gl: &mut Gl, pts: &[f32], npts: i32) {
    gl.begin(GL_POINTS);
    for p in pts.chunks_exact(3).take(usize::try_from(npts).unwrap_or(0)) {
        gl.vertex3fv(p);
    }
    gl.end();
}

/// `gllUniknots(knots, npts, order)`: the uniform knot vector 0, 1, ..., npts + order − 1
/// (seed 004, 9.6.2). Writes `npts + order` knots (as many as fit in `knots`).
pub fn uniknots(knots: &mut [f32], npts: i32, order: i32) {
    let nknots = usize::try_from(npts + order).unwrap_or(0);
    for (i, k) in knots.iter_mut().take(nknots).enumerate() {
        *k = i as f32;
    }
}

/// `gllOpenUniknots(knots, npts, order)`: `order` zeros, then 1, 2, ..., then
/// `npts − order + 1` repeated `order` times (the textbook's three loops, kept as written).
pub fn open_uniknots(knots: &mut [f32], npts: i32, order: i32) {
    let nknots = npts + order;
    let mut set = |i: i32, v: i32| {
        if let Some(k) = usize::try_from(i).ok().and_then(|i| knots.get_mut(i)) {
            *k = v as f32;
        }
    };
    for i in 0..order {
        set(i, 0);
    }
    for i in order..npts {
        set(i, i - order + 1);
    }
    for i in npts..nknots {
        set(i, npts - order + 1);
    }
}

/// `gllBCurve(knots, npts, pts, order, value)`: a B-spline curve through GLU NURBS with a
/// sampling tolerance of `value` pixels.
pub fn b_curve(gl: &mut Gl, knots: &[f32], npts: i32, pts: &[f32], order: i32, value: f32) {
    let nknots = npts + order;
    let nobj = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nobj, GLU_SAMPLING_TOLERANCE, value);
    gl.glu_begin_curve(nobj);
    gl.glu_nurbs_curve(nobj, nknots, knots, 3, pts, order, GL_MAP1_VERTEX_3);
    gl.glu_end_curve(nobj);
    gl.glu_delete_nurbs_renderer(nobj);
}

fn knot_buffer(npts: i32, order: i32) -> Vec<f32> {
    vec![0.0; usize::try_from(npts + order).unwrap_or(0)]
}

/// `gllUniBCurve(npts, pts, order, value)`: a uniform B-spline curve.
pub fn uni_b_curve(gl: &mut Gl, npts: i32, pts: &[f32], order: i32, value: f32) {
    let mut knots = knot_buffer(npts, order);
    uniknots(&mut knots, npts, order);
    b_curve(gl, &knots, npts, pts, order, value);
}

/// `gllOpenUniBCurve(npts, pts, order, value)`: an open uniform B-spline curve.
pub fn open_uni_b_curve(gl: &mut Gl, npts: i32, pts: &[f32], order: i32, value: f32) {
    let mut knots = knot_buffer(npts, order);
    open_uniknots(&mut knots, npts, order);
    b_curve(gl, &knots, npts, pts, order, value);
}

/// `gllBSurface(sknot, tknot, nspts, ntpts, pts, sorder, torder)`: a B-spline surface of
/// `nspts` rows of `ntpts` points through GLU NURBS.
#[allow(clippy::too_many_arguments)]
pub fn b_surface(
    gl: &mut Gl,
    sknot: &[f32],
    tknot: &[f32],
    nspts: i32,
    ntpts: i32,
    pts: &[f32],
    sorder: i32,
    torder: i32,
) {
    let (nsknots, ntknots) = (nspts + sorder, ntpts + torder);
    let nobj = gl.glu_new_nurbs_renderer();
    gl.glu_begin_surface(nobj);
    gl.glu_nurbs_surface(nobj, nsknots, sknot, ntknots, tknot, 3 * ntpts, 3, pts, sorder, torder, GL_MAP2_VERTEX_3);
    gl.glu_end_surface(nobj);
    gl.glu_delete_nurbs_renderer(nobj);
}

/// `gllUniBSurface(nspts, ntpts, pts, sorder, torder)`: a uniform B-spline surface.
pub fn uni_b_surface(gl: &mut Gl, nspts: i32, ntpts: i32, pts: &[f32], sorder: i32, torder: i32) {
    let (mut sknot, mut tknot) = (knot_buffer(nspts, sorder), knot_buffer(ntpts, torder));
    uniknots(&mut sknot, nspts, sorder);
    uniknots(&mut tknot, ntpts, torder);
    b_surface(gl, &sknot, &tknot, nspts, ntpts, pts, sorder, torder);
}

/// `gllOpenUniBSurface(nspts, ntpts, pts, sorder, torder)`: an open uniform B-spline surface.
pub fn open_uni_b_surface(gl: &mut Gl, nspts: i32, ntpts: i32, pts: &[f32], sorder: i32, torder: i32) {
    let (mut sknot, mut tknot) = (knot_buffer(nspts, sorder), knot_buffer(ntpts, torder));
    open_uniknots(&mut sknot, nspts, sorder);
    open_uniknots(&mut tknot, ntpts, torder);
    b_surface(gl, &sknot, &tknot, nspts, ntpts, pts, sorder, torder);
}
