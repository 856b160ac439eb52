//! Outline.c (tests/reference/pictures), ported line for line: GLU's outline display modes on
//! the Red Book hill, GLU_OUTLINE_POLYGON on the left, GLU_OUTLINE_PATCH (trimmed) on the right.
//!
//! `cargo run --release --example outline -- --png outline.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

fn viewport(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(45.0, w as f64 / h as f64, 3.0, 8.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -5.0);
    gl.rotatef(330.0, 1.0, 0.0, 0.0);
    gl.scalef(0.5, 0.5, 0.5);
}

fn surface(gl: &mut Gl, nurb: GLUnurbs, ctlpoints: &[f32], trimmed: bool) {
    let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let edge_pt: [[f32; 2]; 5] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]]; // counter clockwise
    let hole_pt: [[f32; 2]; 5] = [[0.3, 0.3], [0.3, 0.7], [0.7, 0.7], [0.7, 0.3], [0.3, 0.3]]; // clockwise
    gl.glu_begin_surface(nurb);
    gl.glu_nurbs_surface(nurb, 8, &knots, 8, &knots, 4 * 3, 3, ctlpoints, 4, 4, GL_MAP2_VERTEX_3);
    if trimmed {
        gl.glu_begin_trim(nurb);
        gl.glu_pwl_curve(nurb, 5, edge_pt.as_flattened(), 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(nurb);
        gl.glu_begin_trim(nurb);
        gl.glu_pwl_curve(nurb, 5, hole_pt.as_flattened(), 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(nurb);
    }
    gl.glu_end_surface(nurb);
}

fn display(gl: &mut Gl) {
    let w = gl.glut_get(GLUT_WINDOW_WIDTH) / 2;
    let h = gl.glut_get(GLUT_WINDOW_HEIGHT);
    let mut ctlpoints = [[[0.0f32; 3]; 4]; 4];
    for u in 0..4 {
        for v in 0..4 {
            ctlpoints[u][v][0] = 2.0 * (u as f32 - 1.5);
            ctlpoints[u][v][1] = 2.0 * (v as f32 - 1.5);
            ctlpoints[u][v][2] = if (u == 1 || u == 2) && (v == 1 || v == 2) { 3.0 } else { -3.0 };
        }
    }
    let ctl = ctlpoints.as_flattened().as_flattened();
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color3f(0.0, 0.0, 0.6);
    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_SAMPLING_TOLERANCE, 40.0);

    viewport(gl, 0, 0, w, h);
    gl.glu_nurbs_property(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON as f32);
    surface(gl, nurb, ctl, false);

    viewport(gl, w, 0, w, h);
    gl.glu_nurbs_property(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_PATCH as f32);
    surface(gl, nurb, ctl, true);

    gl.glu_delete_nurbs_renderer(nurb);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("GLU outlines", 500, 250).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
