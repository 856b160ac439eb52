//! Seed 004, 9.7.2 exercise 4: a function that draws the uniform bicubic B-spline surface of
//! any grid of at least 4 × 4 control points, used for 5 × 4, 8 × 7 and 13 × 10 points (one
//! viewport each), lit, with the control points.
//!
//! `cargo run --release --example ex4_bspline_surface` (a window) or `-- --png ex4.png`

use gleval::prelude::*;

/// Draws the uniform bicubic B-spline surface of `ns` × `nt` control points (3 coordinates
/// each, t fastest) and its control points.
fn uniform_bicubic_surface(gl: &mut Gl, ns: i32, nt: i32, pts: &[f32]) {
    assert!(ns >= 4 && nt >= 4, "a bicubic B-spline surface needs at least 4 x 4 control points");
    gl.enable(GL_LIGHTING);
    gll::uni_b_surface(gl, ns, nt, pts, 4, 4);
    gl.disable(GL_LIGHTING);
    gl.color3f(1.0, 1.0, 0.0);
    gll::points(gl, pts, ns * nt);
}

/// A wavy net of `ns` × `nt` points over [−3, 3]².
fn wavy_net(ns: usize, nt: usize) -> Vec<f32> {
    let mut pts = Vec::with_capacity(ns * nt * 3);
    for i in 0..ns {
        for j in 0..nt {
            let (x, y) = (-3.0 + 6.0 * i as f32 / (ns - 1) as f32, -3.0 + 6.0 * j as f32 / (nt - 1) as f32);
            pts.extend([x, y, 1.5 * (0.9 * x).sin() * (0.7 * y).cos()]);
        }
    }
    pts
}

fn init(gl: &mut Gl) {
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.point_size(3.0);
    gl.material_fv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.9, 0.6, 0.3, 1.0]);
    gl.light_model_i(GL_LIGHT_MODEL_TWO_SIDE, 1);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);
    gl.enable(GL_LIGHT0);
}

fn paint(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    let w = gl.glut_get(GLUT_WINDOW_WIDTH) / 3;
    let h = gl.glut_get(GLUT_WINDOW_HEIGHT);
    for (k, (ns, nt)) in [(5, 4), (8, 7), (13, 10)].into_iter().enumerate() {
        gl.viewport(k as i32 * w, 0, w, h);
        gl.matrix_mode(GL_PROJECTION);
        gl.load_identity();
        gl.glu_perspective(30.0, f64::from(w) / f64::from(h), 1.0, 100.0);
        gl.translatef(0.0, 0.0, -16.0);
        gl.rotatef(-55.0, 1.0, 0.0, 0.0);
        gl.rotatef(20.0, 0.0, 0.0, 1.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.load_identity();
        uniform_bicubic_surface(gl, ns as i32, nt as i32, &wavy_net(ns, nt));
    }
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("5×4、8×7、13×10个控制点的三次均匀B-样条曲面", 900, 300).init(init).display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
