//! Seed 004, 9.7.2 exercise 1: a cubic Bezier curve from four control points, drawn with the
//! textbook's `gllBezCurve` (glMap1f + glMapGrid1f + glEvalMesh1), with its control polygon.
//!
//! `cargo run --release --example ex1_bezier` (a window) or `-- --png ex1.png`

use gleval::prelude::*;

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h); // 视口与窗口同大小
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(-0.5, 3.5, -1.5, 1.5); // 裁剪窗口包住控制点
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn paint(gl: &mut Gl) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0); // 白色背景
    gl.clear(GL_COLOR_BUFFER_BIT);
    let pts: [[f32; 3]; 4] = [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, -1.0, 0.0], [3.0, 0.0, 0.0]]; // 控制点
    let pts = pts.as_flattened();
    gl.color3f(0.6, 0.6, 0.6); // 控制多边形: 灰色
    gl.begin(GL_LINE_STRIP);
    for p in pts.chunks(3) {
        gl.vertex3f(p[0], p[1], p[2]);
    }
    gl.end();
    gl.color3f(1.0, 0.0, 0.0);
    gl.point_size(6.0);
    gll::points(gl, pts, 4); // 控制点: 红色
    gl.color3f(0.0, 0.0, 1.0);
    gl.line_width(2.0);
    gll::bez_curve(gl, pts, 4, 100); // 三次Bézier曲线: 蓝色
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("三次Bézier曲线", 400, 300).reshape(reshape).display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
