//! Strokes.c (tests/reference/pictures), ported line for line: GLUT's stroke fonts labelling a
//! Bezier curve's control points (`GLUT_STROKE_ROMAN`, scaled and turned along the control
//! polygon), a title in `GLUT_STROKE_MONO_ROMAN` centred with `glutStrokeLength`, a caption of
//! two lines and a row of characters.
//!
//! `cargo run --release --example strokes -- --png strokes.png`

use gleval::prelude::*;

const CTRL: [[f32; 3]; 4] = [[-3.0, -1.6, 0.0], [-1.4, 2.0, 0.0], [1.0, -2.2, 0.0], [3.0, 1.2, 0.0]];

fn text(gl: &mut Gl, font: GlutStrokeFont, s: &str) {
    for c in s.bytes() {
        gl.glut_stroke_character(font, c);
    }
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-4.0, 4.0, -3.0, 3.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn init(gl: &mut Gl) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, CTRL.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(40, 0.0, 1.0);
}

fn display(gl: &mut Gl) {
    let names = ["P0", "P1", "P2", "P3"];
    gl.clear(GL_COLOR_BUFFER_BIT);

    gl.color3f(0.5, 0.5, 0.6);
    gl.begin(GL_LINE_STRIP);
    for p in &CTRL {
        gl.vertex3fv(p);
    }
    gl.end();
    gl.color3f(0.3, 0.9, 1.0);
    gl.eval_mesh1(GL_LINE, 0, 40);
    gl.point_size(5.0);
    gl.color3f(1.0, 0.8, 0.2);
    gl.begin(GL_POINTS);
    for p in &CTRL {
        gl.vertex3fv(p);
    }
    gl.end();

    // Each label along the next leg of the control polygon (the last along the one before).
    gl.color3f(1.0, 1.0, 1.0);
    for i in 0..4 {
        let a = if i < 3 { i } else { 2 };
        let angle = (CTRL[a + 1][1] - CTRL[a][1]).atan2(CTRL[a + 1][0] - CTRL[a][0]) * 180.0 / std::f32::consts::PI;
        gl.push_matrix();
        gl.translatef((f64::from(CTRL[i][0]) + 0.12) as f32, (f64::from(CTRL[i][1]) + 0.12) as f32, 0.0);
        gl.rotatef(angle, 0.0, 0.0, 1.0);
        gl.scalef(0.0035, 0.0035, 1.0);
        text(gl, GLUT_STROKE_ROMAN, names[i]);
        gl.pop_matrix();
    }

    // The title, centred: its width from glutStrokeLength.
    let title = "Bezier curve";
    gl.color3f(1.0, 0.55, 0.3);
    gl.line_width(2.0);
    gl.push_matrix();
    gl.translatef((-0.004 * f64::from(gl.glut_stroke_length(GLUT_STROKE_MONO_ROMAN, title)) / 2.0) as f32, 2.4, 0.0);
    gl.scalef(0.004, 0.004, 1.0);
    text(gl, GLUT_STROKE_MONO_ROMAN, title);
    gl.pop_matrix();
    gl.line_width(1.0);

    // A caption of two lines: back to the start and down by the font's height.
    gl.color3f(0.7, 0.9, 0.6);
    gl.push_matrix();
    gl.translatef(-3.8, -2.3, 0.0);
    gl.scalef(0.0022, 0.0022, 1.0);
    text(gl, GLUT_STROKE_ROMAN, "glMap1f, glEvalMesh1");
    let back = gl.glut_stroke_lengthf(GLUT_STROKE_ROMAN, "glMap1f, glEvalMesh1");
    gl.translatef(-back, -gl.glut_stroke_height(GLUT_STROKE_ROMAN), 0.0);
    text(gl, GLUT_STROKE_ROMAN, "u in [0, 1], 40 steps");
    gl.pop_matrix();

    // Every character once, small, in the mono font, turned a little.
    gl.color3f(0.8, 0.7, 1.0);
    gl.push_matrix();
    gl.translatef(-0.2, -2.8, 0.0);
    gl.rotatef(8.0, 0.0, 0.0, 1.0);
    gl.scalef(0.0011, 0.0011, 1.0);
    for c in (33..128).step_by(3) {
        gl.glut_stroke_character(GLUT_STROKE_MONO_ROMAN, c);
    }
    gl.pop_matrix();
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Stroke fonts", 480, 360).init(init).reshape(reshape).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
