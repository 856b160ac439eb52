//! RubberBand.c (tests/reference/pictures), ported line for line: an XOR rubber band with
//! `logic_op`, as drawing programs make it: a Bezier curve and its control polygon, then, in
//! the front buffer with `GL_XOR`, a rubber-band rectangle drawn at an old position, drawn again
//! there (which erases it exactly) and drawn at the new one; a filled XOR rectangle inverts what
//! lies under it.
//!
//! `cargo run --release --example rubber_band -- --png rubber_band.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const CURVE: [[f32; 3]; 4] = [[-0.8, -0.7, 0.0], [-0.5, 0.9, 0.0], [0.4, -0.9, 0.0], [0.8, 0.6, 0.0]];

fn init(gl: &mut Gl) {
    gl.clear_color(0.15, 0.15, 0.3, 1.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, CURVE.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(40, 0.0, 1.0);
}

fn band(gl: &mut Gl, x0: f32, y0: f32, x1: f32, y1: f32) {
    gl.begin(GL_LINE_LOOP);
    gl.vertex2f(x0, y0);
    gl.vertex2f(x1, y0);
    gl.vertex2f(x1, y1);
    gl.vertex2f(x0, y1);
    gl.end();
}

fn display(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color3f(0.6, 0.6, 0.6);
    gl.begin(GL_LINE_STRIP);
    for i in 0..4 {
        gl.vertex3fv(&CURVE[i]);
    }
    gl.end();
    gl.color3f(1.0, 0.8, 0.1);
    gl.line_width(2.0);
    gl.eval_mesh1(GL_LINE, 0, 40);
    gl.line_width(1.0);

    gl.draw_buffer(GL_FRONT);
    gl.enable(GL_COLOR_LOGIC_OP);
    gl.logic_op(GL_XOR);
    gl.color3f(1.0, 1.0, 1.0);
    band(gl, -0.6, -0.5, 0.1, 0.3);
    band(gl, -0.6, -0.5, 0.1, 0.3);
    band(gl, -0.4, -0.6, 0.5, 0.5);
    gl.color3f(0.0, 1.0, 1.0);
    gl.rectf(0.2, 0.1, 0.7, 0.8);
    gl.disable(GL_COLOR_LOGIC_OP);
    gl.draw_buffer(GL_BACK);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("XOR rubber band", 300, 300).init_display_mode(GLUT_SINGLE | GLUT_RGB).init(init).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
