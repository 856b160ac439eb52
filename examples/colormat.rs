//! ColorMat.c (tests/reference/pictures), ported line for line: `GL_COLOR_MATERIAL` set up as
//! the Red Book's colormat.c does (a `glMaterial` diffuse of 0.5, then `glColorMaterial` and
//! `glEnable(GL_COLOR_MATERIAL)`). The left sphere, with no `glColor` of its own, is lit with
//! the material's 0.5 as on Mesa 22.3; the right one follows a `glColor` (see
//! docs/conventions.md, "`GL_COLOR_MATERIAL`", for where Mesa and the spec part).
//!
//! `cargo run --release --example colormat -- --png colormat.png`

use gleval::prelude::*;

fn reshape(gl: &mut Gl, _w: i32, _h: i32) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.2, 1.2, -1.2, 1.2, -2.0, 2.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn display(gl: &mut Gl) {
    let (width, height) = (gl.glut_get(GLUT_WINDOW_WIDTH), gl.glut_get(GLUT_WINDOW_HEIGHT));
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[1.0, 1.0, 1.0, 0.0]);
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.5, 0.5, 0.5, 1.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 25.0);
    gl.color_material(GL_FRONT, GL_DIFFUSE);
    gl.enable(GL_COLOR_MATERIAL);
    gl.viewport(0, 0, width / 2, height);
    gl.glut_solid_sphere(1.0, 24, 16);
    gl.color3f(0.9, 0.3, 0.2);
    gl.viewport(width / 2, 0, width / 2, height);
    gl.glut_solid_sphere(1.0, 24, 16);
    gl.disable(GL_COLOR_MATERIAL);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Colour material", 240, 120).reshape(reshape).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
