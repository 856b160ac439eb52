//! RationalMap.c (tests/reference/pictures), ported line for line: a `GL_MAP1_VERTEX_4`
//! quarter-circle arc drawn four times (a circle), and a lit `GL_MAP2_VERTEX_4` rational patch
//! with `GL_AUTO_NORMAL`.
//!
//! `cargo run --release --example rationalmap -- --png rationalmap.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

fn display(gl: &mut Gl) {
    let r = std::f32::consts::FRAC_1_SQRT_2;
    let arc: [[f32; 4]; 3] = [[1.0, 0.0, 0.0, 1.0], [r, r, 0.0, r], [0.0, 1.0, 0.0, 1.0]];
    let mut patch = [[[0.0f32; 4]; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            let w = if i == 1 && j == 1 {
                3.0
            } else if i == 1 || j == 1 {
                0.6
            } else {
                1.0
            };
            patch[i][j][0] = (i as f32 - 1.0) * w;
            patch[i][j][1] = (j as f32 - 1.0) * w;
            patch[i][j][2] = (if (i == 1) != (j == 1) { 0.5 } else { 0.0 }) * w;
            patch[i][j][3] = w;
        }
    }
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH) / 2, gl.glut_get(GLUT_WINDOW_HEIGHT));
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(-1.2, 1.2, -1.2, 1.2);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.map1f(GL_MAP1_VERTEX_4, 0.0, 1.0, 4, 3, arc.as_flattened());
    gl.enable(GL_MAP1_VERTEX_4);
    gl.map_grid1f(16, 0.0, 1.0);
    gl.color3f(0.8, 0.1, 0.1);
    gl.line_width(3.0);
    for _ in 0..4 {
        gl.eval_mesh1(GL_LINE, 0, 16);
        gl.rotatef(90.0, 0.0, 0.0, 1.0);
    }

    gl.viewport(w, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(35.0, w as f64 / h as f64, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, -3.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_DEPTH_TEST);
    gl.material_fv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.3, 0.8, 0.4, 1.0]);
    gl.map2f(GL_MAP2_VERTEX_4, 0.0, 1.0, 12, 3, 0.0, 1.0, 4, 3, patch.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_4);
    gl.map_grid2f(16, 0.0, 1.0, 16, 0.0, 1.0);
    gl.eval_mesh2(GL_FILL, 0, 16, 0, 16);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Rational maps", 400, 200).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
