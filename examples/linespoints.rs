//! LinesPoints.c (tests/reference/pictures), ported line for line: GL's aliased wide lines and
//! square points of several sizes, from the evaluators and from immediate mode.
//!
//! `cargo run --release --example linespoints -- --png linespoints.png`

use gleval::prelude::*;

fn display(gl: &mut Gl) {
    let curve: [[f32; 3]; 4] = [[-0.9, -0.2, 0.0], [-0.4, 0.25, 0.0], [0.2, -0.45, 0.0], [0.9, 0.2, 0.0]];
    let widths = [1.0, 2.0, 3.0, 5.0];
    let sizes = [1.0, 2.0, 4.0, 7.0, 10.0];
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, curve.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(24, 0.0, 1.0);
    for (i, width) in widths.into_iter().enumerate() {
        gl.push_matrix();
        gl.translatef(0.0, 0.62 - 0.3 * i as f32, 0.0);
        gl.scalef(1.0, 0.5, 1.0);
        gl.color3f(0.1 * i as f32, 0.2, 0.9 - 0.2 * i as f32);
        gl.line_width(width);
        gl.eval_mesh1(GL_LINE, 0, 24);
        gl.pop_matrix();
    }
    for (i, size) in sizes.into_iter().enumerate() {
        gl.point_size(size);
        gl.color3f(0.9, 0.3 * (i % 2) as f32, 0.1);
        gl.begin(GL_POINTS);
        gl.vertex2f(-0.8 + 0.35 * i as f32, -0.72);
        gl.end();
        gl.push_matrix();
        gl.translatef(0.0, -0.5, 0.0);
        gl.scalef(1.0, 0.2, 1.0);
        gl.eval_mesh1(GL_POINT, 4 * i as i32, 4 * i as i32 + 2);
        gl.pop_matrix();
    }
    gl.line_width(4.0);
    gl.color3f(0.0, 0.6, 0.0);
    gl.begin(GL_LINE_LOOP);
    gl.vertex2f(-0.95, -0.95);
    gl.vertex2f(0.95, -0.9);
    gl.vertex2f(0.9, 0.95);
    gl.vertex2f(-0.9, 0.9);
    gl.end();
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Lines and points", 300, 300).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
