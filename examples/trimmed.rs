//! Trimmed.c (tests/reference/pictures), ported line for line: a bicubic NURBS hill with two
//! holes, one bounded by a NURBS curve joined to a piecewise-linear curve, one a triangle.
//!
//! `cargo run --release --example trimmed -- --png trimmed.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

fn ctlpoints() -> [[[f32; 3]; 4]; 4] {
    let mut pts = [[[0.0f32; 3]; 4]; 4];
    for u in 0..4 {
        for v in 0..4 {
            pts[u][v][0] = 2.0 * (u as f32 - 1.5);
            pts[u][v][1] = 2.0 * (v as f32 - 1.5);
            pts[u][v][2] = if (u == 1 || u == 2) && (v == 1 || v == 2) { 3.0 } else { -3.0 };
        }
    }
    pts
}

fn init(gl: &mut Gl) -> GLUnurbs {
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.7, 0.7, 0.7, 1.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 100.0);
    gl.clear_color(0.2, 0.2, 0.3, 1.0);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);
    let the_nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(the_nurb, GLU_SAMPLING_TOLERANCE, 25.0);
    gl.glu_nurbs_property(the_nurb, GLU_DISPLAY_MODE, GLU_FILL as f32);
    the_nurb
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(45.0, w as f64 / h as f64, 3.0, 8.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -5.0);
}

fn display(gl: &mut Gl, the_nurb: GLUnurbs) {
    let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let edge_pt: [[f32; 2]; 5] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]]; // counter clockwise
    let curve_pt: [[f32; 2]; 4] = [[0.25, 0.5], [0.25, 0.75], [0.75, 0.75], [0.75, 0.5]]; // clockwise
    let curve_knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let pwl_pt: [[f32; 2]; 3] = [[0.75, 0.5], [0.5, 0.25], [0.25, 0.5]]; // clockwise
    let triangle_pt: [[f32; 2]; 4] = [[0.1, 0.1], [0.2, 0.3], [0.3, 0.1], [0.1, 0.1]]; // clockwise

    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.push_matrix();
    gl.rotatef(330.0, 1.0, 0.0, 0.0);
    gl.scalef(0.5, 0.5, 0.5);

    let ctl = ctlpoints();
    gl.glu_begin_surface(the_nurb);
    gl.glu_nurbs_surface(
        the_nurb,
        8,
        &knots,
        8,
        &knots,
        4 * 3,
        3,
        ctl.as_flattened().as_flattened(),
        4,
        4,
        GL_MAP2_VERTEX_3,
    );
    gl.glu_begin_trim(the_nurb);
    gl.glu_pwl_curve(the_nurb, 5, edge_pt.as_flattened(), 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(the_nurb);
    gl.glu_begin_trim(the_nurb);
    gl.glu_nurbs_curve(the_nurb, 8, &curve_knots, 2, curve_pt.as_flattened(), 4, GLU_MAP1_TRIM_2);
    gl.glu_pwl_curve(the_nurb, 3, pwl_pt.as_flattened(), 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(the_nurb);
    gl.glu_begin_trim(the_nurb);
    gl.glu_pwl_curve(the_nurb, 4, triangle_pt.as_flattened(), 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(the_nurb);
    gl.glu_end_surface(the_nurb);

    gl.pop_matrix();
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let nurb = std::rc::Rc::new(std::cell::Cell::new(None));
    let for_display = std::rc::Rc::clone(&nurb);
    App::new("Trimmed NURBS", 300, 300).init(move |gl| nurb.set(Some(init(gl)))).reshape(reshape).display(move |gl| {
        if let Some(n) = for_display.get() {
            display(gl, n);
        }
    })
}

#[allow(dead_code)]
fn main() {
    app().run();
}
