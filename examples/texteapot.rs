//! TexTeapot.c (tests/reference/pictures), ported line for line: GLUT's teapots as course
//! programs draw them. On the left `glut_solid_teapot`, lit and textured (freeglut's teapot carries
//! (u, v) per patch as texture coordinates) with a striped image in `GL_MODULATE`;
//! on the right `glut_wire_teapot`, unlit.
//!
//! `cargo run --release --example texteapot -- --png texteapot.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const SIZE: usize = 32;

fn init(gl: &mut Gl) {
    let mut stripes = [[[0u8; 3]; SIZE]; SIZE];
    for i in 0..SIZE {
        for j in 0..SIZE {
            let on = (j / 4) % 2 == 1;
            stripes[i][j][0] = if on { 255 } else { 90 };
            stripes[i][j][1] = if on { 230 } else { 40 };
            stripes[i][j][2] = if on { 120 } else { 30 };
        }
    }
    gl.clear_color(0.1, 0.12, 0.16, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHT0);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[-2.0, 4.0, 5.0, 0.0]);
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 30.0);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, SIZE as i32, SIZE as i32, 0, GL_RGB, GL_UNSIGNED_BYTE, &stripes);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(30.0, f64::from(w) / f64::from(h), 1.0, 100.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, 1.8, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

fn display(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.push_matrix();
    gl.translatef(-1.1, 0.0, 0.0);
    gl.rotatef(-30.0, 0.0, 1.0, 0.0);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_TEXTURE_2D);
    gl.glut_solid_teapot(0.9);
    gl.disable(GL_TEXTURE_2D);
    gl.disable(GL_LIGHTING);
    gl.pop_matrix();
    gl.push_matrix();
    gl.translatef(1.1, 0.0, 0.0);
    gl.rotatef(40.0, 0.0, 1.0, 0.0);
    gl.color3f(0.4, 0.9, 1.0);
    gl.glut_wire_teapot(0.9);
    gl.pop_matrix();
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("GLUT teapots", 400, 300).init(init).reshape(reshape).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
