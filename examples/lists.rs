//! Lists.c (tests/reference/pictures), ported line for line: display lists holding evaluator
//! calls and a NURBS surface, compiled once in `init` and called under several transforms: a
//! lit bicubic NURBS patch (compiled as the `map2f`/`eval_mesh2` calls GLU makes), a Bezier
//! curve through `map1f`/`eval_mesh1` with its control points, a list that calls both, and
//! `call_lists` with a list base.
//!
//! `cargo run --release --example lists -- --png lists.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;
use std::cell::Cell;
use std::rc::Rc;

fn init(gl: &mut Gl, lists: &Cell<GLuint>) {
    let mut ctl = [[[0.0f32; 3]; 4]; 4];
    let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let curve: [[f32; 3]; 4] = [[-1.0, -1.0, 0.5], [-0.5, 1.0, 0.5], [0.5, -1.0, 0.5], [1.0, 1.0, 0.5]];
    for u in 0..4 {
        for v in 0..4 {
            ctl[u][v][0] = 2.0 * (u as f32 / 3.0) - 1.0;
            ctl[u][v][1] = 2.0 * (v as f32 / 3.0) - 1.0;
            ctl[u][v][2] = if (u == 1 || u == 2) && (v == 1 || v == 2) { 0.8 } else { -0.4 };
        }
    }

    gl.clear_color(0.15, 0.15, 0.2, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);

    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    gl.glu_nurbs_property(nurb, GLU_U_STEP, 12.0);
    gl.glu_nurbs_property(nurb, GLU_V_STEP, 12.0);

    lists.set(gl.gen_lists(3));
    let lists = lists.get();
    gl.new_list(lists, GL_COMPILE);
    gl.enable(GL_LIGHTING);
    gl.material_fv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.9, 0.5, 0.2, 1.0]);
    gl.glu_begin_surface(nurb);
    gl.glu_nurbs_surface(
        nurb,
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
    gl.glu_end_surface(nurb);
    gl.disable(GL_LIGHTING);
    gl.end_list();

    gl.new_list(lists + 1, GL_COMPILE);
    gl.color3f(0.2, 0.9, 1.0);
    gl.line_width(2.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, curve.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(30, 0.0, 1.0);
    gl.eval_mesh1(GL_LINE, 0, 30);
    gl.point_size(5.0);
    gl.color3f(1.0, 1.0, 0.0);
    gl.begin(GL_POINTS);
    for i in 0..4 {
        gl.vertex3fv(&curve[i]);
    }
    gl.end();
    gl.end_list();

    gl.new_list(lists + 2, GL_COMPILE);
    gl.call_list(lists);
    gl.call_list(lists + 1);
    gl.end_list();
    gl.glu_delete_nurbs_renderer(nurb);
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-4.0, 4.0, -4.0, 4.0, -10.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn display(gl: &mut Gl, lists: GLuint) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for i in 0..4 {
        gl.push_matrix();
        gl.translatef(if i % 2 == 1 { 2.0 } else { -2.0 }, if i / 2 == 1 { -2.0 } else { 2.0 }, 0.0);
        gl.rotatef(40.0 * i as f32 - 60.0, 1.0, 0.5, 0.0);
        gl.scalef(0.8, 0.8, 0.8);
        gl.call_list(lists + 2);
        gl.pop_matrix();
    }
    gl.push_matrix();
    gl.scalef(0.6, 0.6, 0.6);
    gl.list_base(lists);
    gl.call_lists(2, GL_UNSIGNED_BYTE, b"\x01\x00");
    gl.pop_matrix();
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let lists = Rc::new(Cell::new(0));
    let at_display = lists.clone();
    App::new("Display lists", 400, 400)
        .init(move |gl| init(gl, &lists))
        .reshape(reshape)
        .display(move |gl| display(gl, at_display.get()))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
