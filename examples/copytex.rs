//! CopyTex.c (tests/reference/pictures), ported line for line: textures copied from the
//! window as drawn so far. A small scene is drawn in the corner, copied into a 64 × 64
//! texture with `copy_tex_image_2d`, a part refreshed with `copy_tex_sub_image_2d` after more
//! drawing, one row copied into a 1D texture and patched with `tex_sub_image_1d`; then the
//! window is cleared and the textures drawn on quads, the 2D one also rotated.
//!
//! `cargo run --release --example copytex -- --png copytex.png`

use gleval::prelude::*;
use std::cell::Cell;
use std::rc::Rc;

fn init(gl: &mut Gl, tex: &Cell<[GLuint; 2]>) {
    let mut names = [0; 2];
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.gen_textures(2, &mut names);
    tex.set(names);
    gl.bind_texture(GL_TEXTURE_2D, names[0]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.bind_texture(GL_TEXTURE_1D, names[1]);
    gl.tex_parameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn corner_scene(gl: &mut Gl) {
    for i in 0..8 {
        for j in 0..8 {
            if (i + j) % 2 == 1 {
                gl.color3f(0.9, 0.9, 0.2);
            } else {
                gl.color3f(0.2, 0.3, 0.9);
            }
            let (x, y) = (8.0 * i as f32, 8.0 * j as f32);
            gl.rectf(x, y, x + 8.0, y + 8.0);
        }
    }
    gl.color3f(0.9, 0.1, 0.1);
    gl.begin(GL_TRIANGLES);
    gl.vertex2f(4.25, 4.25);
    gl.vertex2f(60.75, 12.25);
    gl.vertex2f(20.25, 58.75);
    gl.end();
}

fn display(gl: &mut Gl, tex: [GLuint; 2]) {
    let patch: [u8; 16] = [255, 255, 255, 255, 0, 0, 0, 255, 255, 255, 255, 255, 0, 0, 0, 255];
    gl.clear(GL_COLOR_BUFFER_BIT);
    corner_scene(gl);
    gl.bind_texture(GL_TEXTURE_2D, tex[0]);
    gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 64, 64, 0);
    gl.color3f(0.1, 0.9, 0.3);
    gl.rectf(16.0, 16.0, 48.0, 48.0);
    gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, 0, 32, 32, 24, 24, 32, 32);
    gl.bind_texture(GL_TEXTURE_1D, tex[1]);
    gl.copy_tex_image_1d(GL_TEXTURE_1D, 0, GL_RGBA, 0, 20, 64, 0);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_sub_image_1d(GL_TEXTURE_1D, 0, 28, 4, GL_RGBA, GL_UNSIGNED_BYTE, &patch);
    gl.copy_tex_sub_image_1d(GL_TEXTURE_1D, 0, 0, 30, 30, 8);

    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.enable(GL_TEXTURE_2D);
    gl.bind_texture(GL_TEXTURE_2D, tex[0]);
    gl.begin(GL_QUADS);
    gl.tex_coord2f(0.0, 0.0);
    gl.vertex2f(16.0, 16.0);
    gl.tex_coord2f(1.0, 0.0);
    gl.vertex2f(272.0, 16.0);
    gl.tex_coord2f(1.0, 1.0);
    gl.vertex2f(272.0, 272.0);
    gl.tex_coord2f(0.0, 1.0);
    gl.vertex2f(16.0, 272.0);
    gl.end();
    gl.push_matrix();
    gl.translatef(360.0, 150.0, 0.0);
    gl.rotatef(30.0, 0.0, 0.0, 1.0);
    gl.begin(GL_QUADS);
    gl.tex_coord2f(0.0, 0.0);
    gl.vertex2f(-60.3, -60.3);
    gl.tex_coord2f(1.0, 0.0);
    gl.vertex2f(60.3, -60.3);
    gl.tex_coord2f(1.0, 1.0);
    gl.vertex2f(60.3, 60.3);
    gl.tex_coord2f(0.0, 1.0);
    gl.vertex2f(-60.3, 60.3);
    gl.end();
    gl.pop_matrix();
    gl.disable(GL_TEXTURE_2D);
    gl.enable(GL_TEXTURE_1D);
    gl.bind_texture(GL_TEXTURE_1D, tex[1]);
    gl.begin(GL_QUADS);
    gl.tex_coord1f(0.0);
    gl.vertex2f(16.0, 280.0);
    gl.tex_coord1f(1.0);
    gl.vertex2f(272.0, 280.0);
    gl.tex_coord1f(1.0);
    gl.vertex2f(272.0, 296.0);
    gl.tex_coord1f(0.0);
    gl.vertex2f(16.0, 296.0);
    gl.end();
    gl.disable(GL_TEXTURE_1D);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let tex = Rc::new(Cell::new([0; 2]));
    let at_display = tex.clone();
    App::new("Textures copied from the window", 440, 304)
        .init(move |gl| init(gl, &tex))
        .reshape(reshape)
        .display(move |gl| display(gl, at_display.get()))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
