//! Tess.c (tests/reference/pictures), ported line for line: the Red Book's tess.c (a rectangle
//! with a triangular hole compiled into a display list, `vertex3dv` as the vertex callback; a
//! self-intersecting star coloured at its vertices and at the intersections the combine
//! callback makes, winding rule positive), and tesswind.c's winding rules on nested squares
//! and overlapping contours, the last two as boundaries only.
//!
//! `cargo run --release --example tess -- --png tess.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;
use std::cell::Cell;
use std::rc::Rc;

fn begin_callback(gl: &mut Gl, which: GLenum) {
    gl.begin(which);
}

fn end_callback(gl: &mut Gl) {
    gl.end();
}

fn error_callback(_gl: &mut Gl, error_code: GLenum) {
    eprintln!("Tessellation Error: {}", glu_error_string(error_code).unwrap_or(""));
}

fn vertex_callback(gl: &mut Gl, vertex: &[f64; 6]) {
    gl.color3dv(&vertex[3..]);
    gl.vertex3dv(&vertex[..3]);
}

fn combine_callback(coords: &[f64; 3], vertex_data: [Option<&[f64; 6]>; 4], weight: &[f32; 4]) -> [f64; 6] {
    let mut vertex = [coords[0], coords[1], coords[2], 0.0, 0.0, 0.0];
    let d = |k: usize, i: usize| vertex_data[k].map_or(0.0, |v| v[i]);
    for i in 3..6 {
        vertex[i] = f64::from(weight[0]) * d(0, i)
            + f64::from(weight[1]) * d(1, i)
            + f64::from(weight[2]) * d(2, i)
            + f64::from(weight[3]) * d(3, i);
    }
    vertex
}

/// Intersections of plain `[f64; 3]` vertices: a copy of the coordinates.
fn combine_xyz(coords: &[f64; 3], _vertex_data: [Option<&[f64; 3]>; 4], _weight: &[f32; 4]) -> [f64; 3] {
    *coords
}

const RECTS: [[f64; 3]; 12] = [
    [50.0, 50.0, 0.0],
    [300.0, 50.0, 0.0],
    [300.0, 300.0, 0.0],
    [50.0, 300.0, 0.0],
    [100.0, 100.0, 0.0],
    [250.0, 100.0, 0.0],
    [250.0, 250.0, 0.0],
    [100.0, 250.0, 0.0],
    [150.0, 150.0, 0.0],
    [200.0, 150.0, 0.0],
    [200.0, 200.0, 0.0],
    [150.0, 200.0, 0.0],
];
const QUAD1: [[f64; 3]; 4] = [[50.0, 150.0, 0.0], [350.0, 150.0, 0.0], [350.0, 200.0, 0.0], [50.0, 200.0, 0.0]];
const QUAD2: [[f64; 3]; 4] = [[100.0, 100.0, 0.0], [300.0, 100.0, 0.0], [300.0, 350.0, 0.0], [100.0, 350.0, 0.0]];
const TRI2: [[f64; 3]; 3] = [[200.0, 50.0, 0.0], [250.0, 300.0, 0.0], [150.0, 300.0, 0.0]];

fn contour(gl: &mut Gl, tobj: GLUtesselator, v: &[[f64; 3]]) {
    gl.glu_tess_begin_contour(tobj);
    for p in v {
        gl.glu_tess_vertex(tobj, p, *p);
    }
    gl.glu_tess_end_contour(tobj);
}

/// One winding demo at (x, y), scaled into a 100 × 100 cell.
fn winding(gl: &mut Gl, tobj: GLUtesselator, rule: GLenum, overlap: bool, x: f32, y: f32) {
    gl.push_matrix();
    gl.translatef(x, y, 0.0);
    gl.scalef(0.25, 0.25, 1.0);
    gl.glu_tess_property(tobj, GLU_TESS_WINDING_RULE, f64::from(rule));
    gl.glu_tess_begin_polygon(tobj, None);
    if overlap {
        contour(gl, tobj, &QUAD1);
        contour(gl, tobj, &QUAD2);
        contour(gl, tobj, &TRI2);
    } else {
        contour(gl, tobj, &RECTS[..4]);
        contour(gl, tobj, &RECTS[4..8]);
        contour(gl, tobj, &RECTS[8..]);
    }
    gl.glu_tess_end_polygon(tobj);
    gl.pop_matrix();
}

fn init(gl: &mut Gl, start_list: &Cell<GLuint>) {
    let rect: [[f64; 3]; 4] = [[50.0, 50.0, 0.0], [200.0, 50.0, 0.0], [200.0, 200.0, 0.0], [50.0, 200.0, 0.0]];
    let tri: [[f64; 3]; 3] = [[75.0, 75.0, 0.0], [125.0, 175.0, 0.0], [175.0, 75.0, 0.0]];
    let star: [[f64; 6]; 5] = [
        [250.0, 50.0, 0.0, 1.0, 0.0, 1.0],
        [325.0, 200.0, 0.0, 1.0, 1.0, 0.0],
        [400.0, 50.0, 0.0, 0.0, 1.0, 1.0],
        [250.0, 150.0, 0.0, 1.0, 0.0, 0.0],
        [400.0, 150.0, 0.0, 0.0, 1.0, 0.0],
    ];
    gl.clear_color(0.0, 0.0, 0.0, 0.0);
    start_list.set(gl.gen_lists(3));
    let start_list = start_list.get();
    let tobj = gl.glu_new_tess();
    gl.glu_tess_callback(tobj, GLU_TESS_VERTEX, Some(TessCallback::vertex_of(|gl, v: &[f64; 3]| gl.vertex3dv(v))));
    gl.glu_tess_callback(tobj, GLU_TESS_BEGIN, Some(TessCallback::begin(begin_callback)));
    gl.glu_tess_callback(tobj, GLU_TESS_END, Some(TessCallback::end(end_callback)));
    gl.glu_tess_callback(tobj, GLU_TESS_ERROR, Some(TessCallback::error(error_callback)));
    gl.glu_tess_callback(tobj, GLU_TESS_COMBINE, Some(TessCallback::combine_of(combine_xyz)));

    // A rectangle with a triangular hole inside.
    gl.new_list(start_list, GL_COMPILE);
    gl.shade_model(GL_FLAT);
    gl.glu_tess_begin_polygon(tobj, None);
    gl.glu_tess_begin_contour(tobj);
    gl.glu_tess_vertex(tobj, &rect[0], rect[0]);
    gl.glu_tess_vertex(tobj, &rect[1], rect[1]);
    gl.glu_tess_vertex(tobj, &rect[2], rect[2]);
    gl.glu_tess_vertex(tobj, &rect[3], rect[3]);
    gl.glu_tess_end_contour(tobj);
    gl.glu_tess_begin_contour(tobj);
    gl.glu_tess_vertex(tobj, &tri[0], tri[0]);
    gl.glu_tess_vertex(tobj, &tri[1], tri[1]);
    gl.glu_tess_vertex(tobj, &tri[2], tri[2]);
    gl.glu_tess_end_contour(tobj);
    gl.glu_tess_end_polygon(tobj);
    gl.end_list();

    // The winding rules, in a list of their own.
    gl.new_list(start_list + 2, GL_COMPILE);
    gl.color3f(0.9, 0.6, 0.2);
    winding(gl, tobj, GLU_TESS_WINDING_ODD, false, 0.0, 250.0);
    winding(gl, tobj, GLU_TESS_WINDING_NONZERO, false, 100.0, 250.0);
    winding(gl, tobj, GLU_TESS_WINDING_POSITIVE, false, 200.0, 250.0);
    winding(gl, tobj, GLU_TESS_WINDING_ABS_GEQ_TWO, false, 300.0, 250.0);
    gl.color3f(0.3, 0.7, 1.0);
    winding(gl, tobj, GLU_TESS_WINDING_NONZERO, true, 0.0, 375.0);
    winding(gl, tobj, GLU_TESS_WINDING_ODD, true, 100.0, 375.0);
    gl.glu_tess_property(tobj, GLU_TESS_BOUNDARY_ONLY, f64::from(GL_TRUE));
    winding(gl, tobj, GLU_TESS_WINDING_NONZERO, true, 200.0, 375.0);
    winding(gl, tobj, GLU_TESS_WINDING_ODD, true, 300.0, 375.0);
    gl.end_list();

    // A self-intersecting star, coloured at its vertices and at the combined intersections.
    gl.glu_tess_property(tobj, GLU_TESS_BOUNDARY_ONLY, f64::from(GL_FALSE));
    gl.glu_tess_callback(tobj, GLU_TESS_VERTEX, Some(TessCallback::vertex_of(vertex_callback)));
    gl.glu_tess_callback(tobj, GLU_TESS_COMBINE, Some(TessCallback::combine_of(combine_callback)));
    gl.glu_tess_property(tobj, GLU_TESS_WINDING_RULE, f64::from(GLU_TESS_WINDING_POSITIVE));
    gl.new_list(start_list + 1, GL_COMPILE);
    gl.shade_model(GL_SMOOTH);
    gl.glu_tess_begin_polygon(tobj, None);
    gl.glu_tess_begin_contour(tobj);
    for v in &star {
        gl.glu_tess_vertex(tobj, v, *v);
    }
    gl.glu_tess_end_contour(tobj);
    gl.glu_tess_end_polygon(tobj);
    gl.end_list();
    gl.glu_delete_tess(tobj);
}

fn display(gl: &mut Gl, start_list: GLuint) {
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.color3f(1.0, 1.0, 1.0);
    gl.call_list(start_list);
    gl.call_list(start_list + 1);
    gl.shade_model(GL_FLAT);
    gl.call_list(start_list + 2);
    gl.flush();
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(0.0, f64::from(w), 0.0, f64::from(h));
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let start_list = Rc::new(Cell::new(0));
    let at_display = start_list.clone();
    App::new("tess", 500, 500)
        .init(move |gl| init(gl, &start_list))
        .reshape(reshape)
        .display(move |gl| display(gl, at_display.get()))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
