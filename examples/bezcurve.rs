//! BezCurve.c (seed 004, 9.4.3), ported line for line: a quartic Bezier curve in blue with its
//! control points in red, on white, in a 400x200 window.
//!
//! `cargo run --release --example bezcurve -- --png bezcurve.png`

use gleval::prelude::*;

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h); // 根据指定位置和大小创建视口
    gl.matrix_mode(GL_PROJECTION); // 投影矩阵栈
    gl.load_identity(); // 当前矩阵改为单位矩阵
    gl.glu_ortho_2d(-2.2, 2.2, -1.1, 1.1); // 裁剪窗口，比[-2, 2][-1, 1]稍大
    gl.matrix_mode(GL_MODELVIEW); // 视图造型矩阵栈
    gl.load_identity(); // 当前矩阵改为单位矩阵
}

fn paint(gl: &mut Gl) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0); // 白色背景
    gl.clear(GL_COLOR_BUFFER_BIT); // 清除颜色缓冲
                                   // 控制点数组
    let pts: [[f32; 3]; 5] = [[-2.0, 0.0, 0.0], [-1.0, 1.0, 0.0], [0.0, 0.0, 0.0], [1.0, -1.0, 0.0], [2.0, 0.0, 0.0]];
    let (npts, un) = (5, 100); // 控制点个数, 参数区间分割数

    gl.color3f(0.0, 0.0, 1.0);
    gl.line_width(2.0); // 曲线颜色和线宽
    gll::bez_curve(gl, pts.as_flattened(), npts, un); // Bézier曲线
    gl.color3f(1.0, 0.0, 0.0);
    gl.point_size(5.0); // 控制点颜色和大小
    gll::points(gl, pts.as_flattened(), npts); // 控制点

    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Bézier曲线", 400, 200) // 程序窗口大小(4:2)
        .display(paint)
        .reshape(reshape)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
