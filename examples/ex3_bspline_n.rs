//! Seed 004, 9.7.2 exercise 3: a function that draws the uniform cubic B-spline of any n ≥ 4
//! control points, used for 5, 8 and 13 points (one viewport each, left to right).
//!
//! `cargo run --release --example ex3_bspline_n` (a window) or `-- --png ex3.png`

use gleval::prelude::*;

/// Draws the control polygon, the control points and the uniform cubic B-spline of `pts`
/// (n ≥ 4 points of 3 coordinates): n − 3 segments.
fn uniform_cubic_bspline(gl: &mut Gl, pts: &[f32]) {
    let n = (pts.len() / 3) as i32;
    assert!(n >= 4, "a cubic B-spline needs at least four control points");
    gl.color3f(0.6, 0.6, 0.6);
    gl.line_width(1.0);
    gl.begin(GL_LINE_STRIP);
    for p in pts.chunks(3) {
        gl.vertex3f(p[0], p[1], p[2]);
    }
    gl.end();
    gl.color3f(1.0, 0.0, 0.0);
    gl.point_size(5.0);
    gll::points(gl, pts, n);
    gl.color3f(0.0, 0.0, 1.0);
    gl.line_width(2.0);
    gll::uni_b_curve(gl, n, pts, 4, 1.0);
}

/// `n` control points on a zigzag over x ∈ [0, 4].
fn zigzag(n: usize) -> Vec<f32> {
    (0..n)
        .flat_map(|i| {
            let x = 4.0 * i as f32 / (n - 1) as f32;
            let y = if i % 2 == 0 { -1.0 } else { 1.0 } * (0.4 + 0.6 * ((i * 7 % 5) as f32 / 4.0));
            [x, y, 0.0]
        })
        .collect()
}

fn paint(gl: &mut Gl) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let w = gl.glut_get(GLUT_WINDOW_WIDTH) / 3;
    let h = gl.glut_get(GLUT_WINDOW_HEIGHT);
    for (k, n) in [5, 8, 13].into_iter().enumerate() {
        gl.viewport(k as i32 * w, 0, w, h); // 第k个视区
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.glu_ortho_2d(-0.3, 4.3, -1.6, 1.6);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        uniform_cubic_bspline(gl, &zigzag(n));
    }
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("5、8、13个控制点的三次均匀B-样条曲线", 900, 300).display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
