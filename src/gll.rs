//! The textbook's `gll.h` helpers (seed 004, 9.4.2 and 9.4.3), written only on the public GL
//! façade, as a student would write them. The B-spline helpers arrive with GLU NURBS.

use crate::gl::consts::*;
use crate::gl::Gl;

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
