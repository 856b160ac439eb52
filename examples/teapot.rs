//! Teapot.c (tests/reference/pictures), ported line for line: GLUT's solid teapot, lit.
//! `gl.glut_solid_teapot(1.0)` draws it as freeglut 3.4 does: its 10 bicubic patches of
//! Newell's teapot, turned and mirrored into 32, each evaluated on an 8 × 8 grid with normals
//! from the tangents, and drawn as triangles with (u, v) texture coordinates.
//!
//! `cargo run --release --example teapot -- --png teapot.png`

use gleval::prelude::*;

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(30.0, f64::from(w) / f64::from(h.max(1)), 1.0, 100.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, 1.7, 5.4, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

fn init(gl: &mut Gl) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[-2.0, 4.0, 5.0, 0.0]);
    gl.light_fv(GL_LIGHT0, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.light_fv(GL_LIGHT0, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.material_fv(GL_FRONT, GL_AMBIENT, &[0.25, 0.15, 0.05, 1.0]);
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.8, 0.5, 0.2, 1.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 40.0);
}

fn display(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.push_matrix();
    gl.rotatef(-30.0, 0.0, 1.0, 0.0);
    gl.glut_solid_teapot(1.0);
    gl.pop_matrix();
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Utah teapot", 400, 300).init(init).reshape(reshape).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
