//! BSurf.c (seed 004, 9.6.3), ported line for line: a uniform bicubic B-spline surface (left)
//! and an open uniform one (right) over the same 4x4 control points, lit.
//!
//! `cargo run --release --example bsurf -- --png bsurf.png`

use gleval::prelude::*;

fn viewport(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    gl.viewport(x, y, w, h); // 根据指定位置和大小创建视口
    gl.matrix_mode(GL_PROJECTION); // 投影矩阵栈
    gl.load_identity(); // 当前矩阵改为单位矩阵
                        // 透视变换(视角30度, 宽高比, 近平面, 远平面)
    gl.glu_perspective(30.0, w as f64 / h as f64, 1.0, 1000.0);
    gl.translatef(0.5, 0.5, -14.0); // 场景右移0.5, 上移0.5, 远移14
    gl.rotatef(30.0, -1.0, 1.0, 0.0); // 场景绕(-1, 1, 0)方向旋转30度
    gl.matrix_mode(GL_MODELVIEW); // 视图造型矩阵栈
    gl.load_identity(); // 当前矩阵改为单位矩阵
}

fn hint(gl: &mut Gl) {
    gl.point_size(3.0); // 点的大小
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]); // 白色材质
    gl.enable(GL_AUTO_NORMAL); // 自动计算表面法向量
    gl.enable(GL_NORMALIZE); // 自动单位化法向量
    gl.enable(GL_LIGHT0); // 启用0号光源
    gl.enable(GL_LIGHTING); // 启用光照效果
}

fn paint(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // 清除颜色缓存和深度缓存
    let w = gl.glut_get(GLUT_WINDOW_WIDTH) / 2; // 视口宽度
    let h = gl.glut_get(GLUT_WINDOW_HEIGHT); // 视口高度
    #[rustfmt::skip]
    let pts: [[[f32; 3]; 4]; 4] = [ // 控制点坐标
        [[-3.0, -3.0, -3.0], [-3.0, -1.0, -3.0], [-3.0, 1.0, -3.0], [-3.0, 3.0, -3.0]],
        [[-1.0, -3.0, -3.0], [-1.0, -1.0, 3.0], [-1.0, 1.0, 3.0], [-1.0, 3.0, -3.0]],
        [[1.0, -3.0, -3.0], [1.0, -1.0, 3.0], [1.0, 1.0, 3.0], [1.0, 3.0, -3.0]],
        [[3.0, -3.0, -3.0], [3.0, -1.0, -3.0], [3.0, 1.0, -3.0], [3.0, 3.0, -3.0]],
    ];
    let pts = pts.as_flattened().as_flattened();

    viewport(gl, 0, 0, w, h); // 左侧, 均匀B-曲面
    gll::uni_b_surface(gl, 4, 4, pts, 4, 4); // 均匀B-曲面
    gll::points(gl, pts, 4 * 4); // 绘制控制点

    viewport(gl, w, 0, w, h); // 右侧, 开放均匀B-曲面
    gll::open_uni_b_surface(gl, 4, 4, pts, 4, 4); // 开放均匀B-曲面
    gll::points(gl, pts, 4 * 4); // 绘制控制点
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("B-曲面", 500, 200) // 程序窗口大小(5:2)
        .init(hint) // 初始化(材质属性和光照属性等)
        .display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
