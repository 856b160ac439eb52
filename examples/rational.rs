//! Rational.c (tests/reference/pictures), ported line for line: a rational NURBS surface, a
//! circle of 9 homogeneous control points swept along z into a cylinder, lit on both sides.
//!
//! `cargo run --release --example rational -- --png rational.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(40.0, w as f64 / h as f64, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, -5.0, 4.0, 0.0, 0.0, 0.5, 0.0, 0.0, 1.0);
}

fn display(gl: &mut Gl) {
    let r = std::f32::consts::FRAC_1_SQRT_2;
    let circle: [[f32; 3]; 9] = [
        [1.0, 0.0, 1.0],
        [1.0, 1.0, r],
        [0.0, 1.0, 1.0],
        [-1.0, 1.0, r],
        [-1.0, 0.0, 1.0],
        [-1.0, -1.0, r],
        [0.0, -1.0, 1.0],
        [1.0, -1.0, r],
        [1.0, 0.0, 1.0],
    ];
    let mut ctl = [[[0.0f32; 4]; 2]; 9];
    for i in 0..9 {
        for j in 0..2 {
            let w = circle[i][2];
            ctl[i][j][0] = circle[i][0] * w;
            ctl[i][j][1] = circle[i][1] * w;
            ctl[i][j][2] = (if j == 1 { 1.5 } else { -0.5 }) * w;
            ctl[i][j][3] = w;
        }
    }
    let sknots = [0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0];
    let tknots = [0.0, 0.0, 1.0, 1.0];

    gl.clear_color(0.1, 0.1, 0.1, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);
    gl.light_model_fv(GL_LIGHT_MODEL_TWO_SIDE, &[1.0]);
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.9, 0.6, 0.2, 1.0]);
    gl.material_fv(GL_BACK, GL_DIFFUSE, &[0.2, 0.5, 0.9, 1.0]);

    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_SAMPLING_TOLERANCE, 10.0);
    gl.glu_begin_surface(nurb);
    gl.glu_nurbs_surface(
        nurb,
        12,
        &sknots,
        4,
        &tknots,
        2 * 4,
        4,
        ctl.as_flattened().as_flattened(),
        3,
        2,
        GL_MAP2_VERTEX_4,
    );
    gl.glu_end_surface(nurb);
    gl.glu_delete_nurbs_renderer(nurb);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Rational NURBS", 300, 300).reshape(reshape).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
