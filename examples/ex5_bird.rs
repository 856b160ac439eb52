//! Seed 004, 9.7.2 exercise 5: the natural cubic spline s(x) through the measured outline of a
//! bird's back (s''(0.9) = s''(13.3) = 0), drawn at 600 × 300: each spline piece as a cubic
//! Bezier curve through `glMap1f`/`glEvalMesh1`, and the data points.
//!
//! `cargo run --release --example ex5_bird` (a window) or `-- --png ex5.png`

use gleval::math::CubicSpline;
use gleval::prelude::*;

/// The measured points (seed 004, 9.7.2).
const X: [f64; 21] =
    [0.9, 1.3, 1.9, 2.1, 2.6, 3.0, 3.9, 4.4, 4.7, 5.0, 6.0, 7.0, 8.0, 9.2, 10.5, 11.3, 11.6, 12.0, 12.6, 13.0, 13.3];
const Y: [f64; 21] =
    [1.3, 1.5, 1.85, 2.1, 2.6, 2.7, 2.4, 2.15, 2.05, 2.1, 2.25, 2.3, 2.25, 1.95, 1.4, 0.9, 0.7, 0.6, 0.5, 0.4, 0.25];

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(0.0, 14.0, -1.0, 4.0); // x ∈ [0, 14], y ∈ [−1, 4]: about the window's 2:1
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn paint(gl: &mut Gl) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let spline = CubicSpline::natural(&X, &Y).expect("the bird data are increasing in x");
    gl.color3f(0.0, 0.0, 1.0);
    gl.line_width(2.0);
    gl.enable(GL_MAP1_VERTEX_3);
    for piece in spline.bezier_pieces() {
        let pts: Vec<f32> = piece.iter().flat_map(|p| [p[0] as f32, p[1] as f32, 0.0]).collect();
        gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &pts);
        gl.map_grid1f(20, 0.0, 1.0);
        gl.eval_mesh1(GL_LINE, 0, 20);
    }
    gl.color3f(1.0, 0.0, 0.0);
    gl.point_size(5.0);
    gl.begin(GL_POINTS);
    for (x, y) in X.iter().zip(Y) {
        gl.vertex2f(*x as f32, y as f32);
    }
    gl.end();
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("飞鸟外形的自然三次样条", 600, 300).reshape(reshape).display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
