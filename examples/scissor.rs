//! Scissor.c (tests/reference/pictures), ported line for line: scissored viewports. Four
//! viewports, each cleared through a scissor box of its own to its own colour (one with the
//! colour mask letting only red through), each drawing an evaluated Bezier curve and its
//! control points; a smaller scissor box then clips a wide curve across the window; depth
//! writes off (`depth_mask`) let a far square drawn after a near one cover it.
//!
//! `cargo run --release --example scissor -- --png scissor.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const CURVE: [[f32; 3]; 4] = [[-0.9, -0.6, 0.0], [-0.4, 0.9, 0.0], [0.4, -0.9, 0.0], [0.9, 0.6, 0.0]];

fn init(gl: &mut Gl) {
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, CURVE.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(30, 0.0, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.point_size(5.0);
}

fn square(gl: &mut Gl, x0: f32, y0: f32, x1: f32, y1: f32, z: f32) {
    gl.begin(GL_QUADS);
    gl.vertex3f(x0, y0, z);
    gl.vertex3f(x1, y0, z);
    gl.vertex3f(x1, y1, z);
    gl.vertex3f(x0, y1, z);
    gl.end();
}

fn pane(gl: &mut Gl, x: i32, y: i32, clear: &[f32; 4]) {
    gl.viewport(x, y, 180, 180);
    gl.scissor(x + 10, y + 10, 160, 160);
    gl.clear_color(clear[0], clear[1], clear[2], clear[3]);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.color3f(1.0, 1.0, 1.0);
    gl.eval_mesh1(GL_LINE, 0, 30);
    gl.color3f(1.0, 0.9, 0.0);
    gl.begin(GL_POINTS);
    for i in 0..4 {
        gl.vertex3fv(&CURVE[i]);
    }
    gl.end();
}

fn display(gl: &mut Gl) {
    let colors = [[0.5, 0.1, 0.1, 1.0], [0.1, 0.4, 0.1, 1.0], [0.1, 0.1, 0.5, 1.0], [0.6, 0.6, 0.6, 1.0]];
    gl.disable(GL_SCISSOR_TEST);
    gl.clear_color(0.2, 0.2, 0.2, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.enable(GL_SCISSOR_TEST);
    pane(gl, 0, 180, &colors[0]);
    pane(gl, 180, 180, &colors[1]);
    pane(gl, 0, 0, &colors[2]);
    gl.color_mask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
    pane(gl, 180, 0, &colors[3]);
    gl.color_mask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    gl.color3f(0.2, 0.8, 1.0);
    gl.depth_mask(GL_FALSE);
    square(gl, -0.5, -0.5, 0.2, 0.2, -0.5);
    gl.color3f(1.0, 0.4, 0.0);
    square(gl, -0.2, -0.2, 0.5, 0.5, 0.5);
    gl.depth_mask(GL_TRUE);

    gl.viewport(0, 0, 360, 360);
    gl.scissor(100, 60, 160, 240);
    gl.line_width(3.0);
    gl.color3f(0.9, 0.2, 0.9);
    gl.eval_mesh1(GL_LINE, 0, 30);
    gl.line_width(1.0);
    gl.disable(GL_SCISSOR_TEST);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Scissored viewports", 360, 360)
        .init_display_mode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH)
        .init(init)
        .display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
