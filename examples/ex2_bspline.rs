//! Seed 004, 9.7.2 exercise 2: a uniform cubic B-spline from four control points (one
//! segment, from (P0 + 4P1 + P2)/6 to (P1 + 4P2 + P3)/6), drawn with `gllUniBCurve`.
//!
//! `cargo run --release --example ex2_bspline` (a window) or `-- --png ex2.png`

use gleval::prelude::*;

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(-0.5, 3.5, -1.5, 1.5);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn paint(gl: &mut Gl) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let pts: [[f32; 3]; 4] = [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, -1.0, 0.0], [3.0, 0.0, 0.0]]; // 控制点
    let pts = pts.as_flattened();
    gl.color3f(0.6, 0.6, 0.6); // 控制多边形
    gl.begin(GL_LINE_STRIP);
    for p in pts.chunks(3) {
        gl.vertex3f(p[0], p[1], p[2]);
    }
    gl.end();
    gl.color3f(1.0, 0.0, 0.0);
    gl.point_size(6.0);
    gll::points(gl, pts, 4);
    gl.color3f(0.0, 0.0, 1.0);
    gl.line_width(2.0);
    gll::uni_b_curve(gl, 4, pts, 4, 1.0); // 三次均匀B-样条曲线(4阶)
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("三次均匀B-样条曲线", 400, 300).reshape(reshape).display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
