//! BCurve.c (seed 004, 9.6.3), ported line for line: a uniform cubic B-spline (left) and an
//! open uniform one (right) through the same six control points.
//!
//! `cargo run --release --example bcurve -- --png bcurve.png`

use gleval::prelude::*;

fn viewport(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    gl.viewport(x, y, w, h); // 根据指定位置和大小创建视口
    gl.matrix_mode(GL_PROJECTION); // 投影矩阵栈
    gl.load_identity(); // 当前矩阵改为单位矩阵
    gl.glu_ortho_2d(-0.25, 5.25, -2.2, 2.2); // 裁剪窗口，比[0, 5][-2, 2]稍大
    gl.matrix_mode(GL_MODELVIEW); // 视图造型矩阵栈
    gl.load_identity(); // 当前矩阵改为单位矩阵
}

fn paint(gl: &mut Gl) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0); // 白色背景
    gl.clear(GL_COLOR_BUFFER_BIT); // 清除颜色缓冲
    let w = gl.glut_get(GLUT_WINDOW_WIDTH) / 2; // 视口宽度
    let h = gl.glut_get(GLUT_WINDOW_HEIGHT); // 视口高度
    let pts: [[f32; 3]; 6] = // 控制点坐标
        [[0.0, 0.0, 0.0], [1.0, -2.0, 0.0], [2.0, 0.0, 0.0], [3.0, 2.0, 0.0], [4.0, 0.0, 0.0], [5.0, -2.0, 0.0]];
    let (npts, order) = (6, 4); // 控制点个数,阶数
    let pts = pts.as_flattened();

    viewport(gl, 0, 0, w, h); // 左视区, 均匀B-曲线
    gl.color3f(1.0, 0.0, 0.0);
    gl.point_size(5.0); // 控制点颜色和大小
    gll::points(gl, pts, npts); // 控制点
    gl.color3f(0.0, 0.0, 1.0);
    gl.line_width(2.5); // 曲线颜色和线宽
    gll::uni_b_curve(gl, npts, pts, order, 1.0); // 均匀B-曲线

    viewport(gl, w, 0, w, h); // 右视区, 开放均匀B-曲线
    gl.color3f(1.0, 0.0, 0.0);
    gl.point_size(5.0); // 控制点颜色和大小
    gll::points(gl, pts, npts); // 控制点
    gl.color3f(0.0, 0.0, 1.0);
    gl.line_width(2.5); // 曲线颜色和线宽
    gll::open_uni_b_curve(gl, npts, pts, order, 1.0); // 开放均匀B-曲线
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("B-曲线", 500, 200) // 程序窗口大小(5:2)
        .display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
