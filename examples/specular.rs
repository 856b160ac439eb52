//! Specular.c (tests/reference/pictures), ported line for line: a lit bicubic patch with a
//! specular material, a positional and a directional light, the light model's ambient term.
//!
//! `cargo run --release --example specular -- --png specular.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    let aspect = f64::from(h) / f64::from(w);
    gl.frustum(-0.6, 0.6, -0.6 * aspect, 0.6 * aspect, 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -6.0);
    gl.rotatef(-55.0, 1.0, 0.0, 0.0);
}

fn display(gl: &mut Gl) {
    let mut pts = [[[0.0f32; 3]; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            pts[i][j][0] = -1.5 + i as f32;
            pts[i][j][1] = -1.5 + j as f32;
            pts[i][j][2] = if (i == 1 || i == 2) && (j == 1 || j == 2) { 1.5 } else { 0.0 };
        }
    }
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.shade_model(GL_SMOOTH);
    gl.enable(GL_LIGHTING);
    gl.light_model_fv(GL_LIGHT_MODEL_AMBIENT, &[0.1, 0.1, 0.15, 1.0]);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[1.5, -1.0, 3.0, 1.0]);
    gl.light_fv(GL_LIGHT0, GL_DIFFUSE, &[0.9, 0.8, 0.7, 1.0]);
    gl.light_fv(GL_LIGHT0, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.light_f(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1);
    gl.light_fv(GL_LIGHT1, GL_POSITION, &[-1.0, 1.0, 1.0, 0.0]);
    gl.light_fv(GL_LIGHT1, GL_DIFFUSE, &[0.2, 0.3, 0.6, 1.0]);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_LIGHT1);
    gl.material_fv(GL_FRONT, GL_AMBIENT, &[0.3, 0.3, 0.3, 1.0]);
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.6, 0.6, 0.6, 1.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[0.9, 0.9, 0.9, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 40.0);
    gl.enable(GL_AUTO_NORMAL);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, pts.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_grid2f(30, 0.0, 1.0, 30, 0.0, 1.0);
    gl.eval_mesh2(GL_FILL, 0, 30, 0, 30);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Specular lighting", 300, 240).reshape(reshape).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
