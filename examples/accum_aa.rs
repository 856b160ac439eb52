//! AccumAA.c (tests/reference/pictures), ported line for line: antialiasing with the
//! accumulation buffer, as the Red Book's accanti.c does it: the scene drawn eight times, each
//! shifted by a sub-pixel jitter (the Red Book's table for 8), accumulated with 1/8 and
//! returned. `GL_POLYGON_SMOOTH` is on, which llvmpipe (and gleval) draw aliased.
//!
//! `cargo run --release --example accum_aa -- --png accum_aa.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;
use std::cell::Cell;
use std::rc::Rc;

/// The Red Book's jitter.h offsets for 8 passes, in pixels.
pub const J8: [[f32; 2]; 8] = [
    [-0.334818, 0.435331],
    [0.286438, -0.393495],
    [0.459462, 0.141540],
    [-0.414498, -0.192829],
    [-0.183790, 0.082102],
    [-0.079263, -0.317383],
    [0.102254, 0.299133],
    [0.164216, -0.054399],
];
const CURVE: [[f32; 3]; 4] = [[-0.9, -0.9, 0.0], [-0.6, 0.9, 0.0], [0.6, -0.9, 0.0], [0.9, 0.7, 0.0]];

fn init(gl: &mut Gl) {
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    gl.clear_accum(0.0, 0.0, 0.0, 0.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, CURVE.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(30, 0.0, 1.0);
    gl.enable(GL_POLYGON_SMOOTH);
}

fn scene(gl: &mut Gl) {
    gl.color3f(0.9, 0.3, 0.2);
    gl.begin(GL_TRIANGLES);
    gl.vertex2f(-0.8, -0.2);
    gl.vertex2f(0.1, -0.7);
    gl.vertex2f(-0.3, 0.8);
    gl.end();
    gl.push_matrix();
    gl.translatef(0.45, 0.35, 0.0);
    gl.rotatef(25.0, 0.0, 0.0, 1.0);
    gl.color3f(0.2, 0.5, 1.0);
    gl.begin(GL_QUADS);
    gl.vertex2f(-0.3, -0.3);
    gl.vertex2f(0.3, -0.3);
    gl.vertex2f(0.3, 0.3);
    gl.vertex2f(-0.3, 0.3);
    gl.end();
    gl.pop_matrix();
    gl.color3f(1.0, 1.0, 0.3);
    gl.eval_mesh1(GL_LINE, 0, 30);
    gl.color3f(0.6, 0.6, 0.6);
    gl.begin(GL_LINE_STRIP);
    for i in 0..4 {
        gl.vertex3fv(&CURVE[i]);
    }
    gl.end();
}

fn display(gl: &mut Gl, (width, height): (i32, i32)) {
    gl.clear(GL_ACCUM_BUFFER_BIT);
    for j in 0..8 {
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.push_matrix();
        gl.translatef(J8[j][0] * 2.0 / width as f32, J8[j][1] * 2.0 / height as f32, 0.0);
        scene(gl);
        gl.pop_matrix();
        gl.accum(GL_ACCUM, 1.0 / 8.0);
    }
    gl.accum(GL_RETURN, 1.0);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let size = Rc::new(Cell::new((300, 300)));
    let at_display = size.clone();
    App::new("Accumulation antialiasing", 300, 300)
        .init_display_mode(GLUT_SINGLE | GLUT_RGB | GLUT_ACCUM)
        .init(init)
        .reshape(move |gl, w, h| {
            size.set((w, h));
            gl.viewport(0, 0, w, h);
        })
        .display(move |gl| display(gl, at_display.get()))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
