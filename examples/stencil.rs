//! Stencil.c (tests/reference/pictures), ported line for line: the stencil buffer four ways,
//! one viewport each. Top left: a diamond written into the stencil buffer with colour writes
//! off masks evaluated Bezier curves (`GL_EQUAL`) and a grid drawn outside it (`GL_NOTEQUAL`).
//! Top right: three discs counted with `GL_INCR`, coloured by how many overlap. Bottom left: a
//! Bezier patch outlined (filled writing 1, then its mesh drawn as wide lines where the stencil
//! is not 1). Bottom right: `GL_INVERT` through a stencil write mask of one bit.
//!
//! `cargo run --release --example stencil -- --png stencil.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const CURVE: [[f32; 3]; 4] = [[-0.9, -0.5, 0.0], [-0.3, 0.9, 0.0], [0.3, -0.9, 0.0], [0.9, 0.5, 0.0]];

fn init(gl: &mut Gl) {
    let mut patch = [[[0.0f32; 3]; 4]; 4];
    for u in 0..4 {
        for v in 0..4 {
            patch[u][v][0] = -0.6 + 0.4 * u as f32 + if v == 1 || v == 2 { 0.25 } else { 0.0 };
            patch[u][v][1] = -0.6 + 0.4 * v as f32 + if u == 1 || u == 2 { -0.25 } else { 0.0 };
            patch[u][v][2] = 0.0;
        }
    }
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.clear_stencil(0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, CURVE.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, patch.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_grid1f(40, 0.0, 1.0);
    gl.map_grid2f(8, 0.0, 1.0, 8, 0.0, 1.0);
}

fn disc(gl: &mut Gl, x: f32, y: f32, r: f32) {
    gl.begin(GL_TRIANGLE_FAN);
    gl.vertex2f(x, y);
    for i in 0..=32 {
        // The C program's 6.2831853f is this float.
        let a = std::f32::consts::TAU * i as f32 / 32.0;
        gl.vertex2f(x + r * a.cos(), y + r * a.sin());
    }
    gl.end();
}

fn square(gl: &mut Gl, x0: f32, y0: f32, x1: f32, y1: f32) {
    gl.begin(GL_QUADS);
    gl.vertex2f(x0, y0);
    gl.vertex2f(x1, y0);
    gl.vertex2f(x1, y1);
    gl.vertex2f(x0, y1);
    gl.end();
}

fn masked_curves(gl: &mut Gl) {
    gl.color_mask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.stencil_func(GL_ALWAYS, 1, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.begin(GL_POLYGON);
    gl.vertex2f(0.0, -0.85);
    gl.vertex2f(0.85, 0.0);
    gl.vertex2f(0.0, 0.85);
    gl.vertex2f(-0.85, 0.0);
    gl.end();
    gl.color_mask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    gl.stencil_func(GL_EQUAL, 1, 0xFF);
    gl.color3f(1.0, 0.8, 0.2);
    for k in -4..=4 {
        gl.push_matrix();
        gl.translatef(0.0, 0.15 * k as f32, 0.0);
        gl.eval_mesh1(GL_LINE, 0, 40);
        gl.pop_matrix();
    }
    gl.stencil_func(GL_NOTEQUAL, 1, 0xFF);
    gl.color3f(0.3, 0.5, 1.0);
    gl.begin(GL_LINES);
    for k in -9..=9 {
        gl.vertex2f(0.1 * k as f32 + 0.03, -1.0);
        gl.vertex2f(0.1 * k as f32 + 0.03, 1.0);
    }
    gl.end();
}

fn counted_discs(gl: &mut Gl) {
    gl.color_mask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.stencil_func(GL_ALWAYS, 0, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_INCR);
    disc(gl, -0.25, 0.2, 0.5);
    disc(gl, 0.25, 0.2, 0.5);
    disc(gl, 0.0, -0.25, 0.5);
    gl.color_mask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    let colors = [[0.2, 0.4, 0.9], [0.2, 0.8, 0.3], [1.0, 0.3, 0.2]];
    for n in 1..=3 {
        gl.stencil_func(GL_EQUAL, n, 0xFF);
        gl.color3fv(&colors[n as usize - 1]);
        square(gl, -1.0, -1.0, 1.0, 1.0);
    }
}

fn outlined_patch(gl: &mut Gl) {
    gl.stencil_func(GL_ALWAYS, 1, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_REPLACE);
    gl.color3f(0.2, 0.6, 0.3);
    gl.eval_mesh2(GL_FILL, 0, 8, 0, 8);
    gl.stencil_func(GL_NOTEQUAL, 1, 0xFF);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    gl.line_width(3.0);
    gl.color3f(1.0, 1.0, 1.0);
    gl.eval_mesh2(GL_LINE, 0, 8, 0, 8);
    gl.line_width(1.0);
}

fn inverted_squares(gl: &mut Gl) {
    gl.color_mask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.stencil_mask(0x01);
    gl.stencil_func(GL_ALWAYS, 0, 0xFF);
    gl.stencil_op(GL_INVERT, GL_INVERT, GL_INVERT);
    square(gl, -0.7, -0.7, 0.3, 0.3);
    square(gl, -0.3, -0.3, 0.7, 0.7);
    gl.stencil_mask(0xFF);
    gl.color_mask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.stencil_op(GL_KEEP, GL_KEEP, GL_KEEP);
    gl.stencil_func(GL_EQUAL, 1, 0x01);
    gl.color3f(0.9, 0.5, 0.9);
    square(gl, -1.0, -1.0, 1.0, 1.0);
}

fn display(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl.enable(GL_STENCIL_TEST);
    gl.viewport(0, 200, 200, 200);
    masked_curves(gl);
    gl.viewport(200, 200, 200, 200);
    counted_discs(gl);
    gl.viewport(0, 0, 200, 200);
    outlined_patch(gl);
    gl.viewport(200, 0, 200, 200);
    inverted_squares(gl);
    gl.disable(GL_STENCIL_TEST);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Stencil", 400, 400).init_display_mode(GLUT_SINGLE | GLUT_RGB | GLUT_STENCIL).init(init).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
