//! Picking.c (tests/reference/pictures), ported line for line: the control points of a Bezier
//! curve picked with the mouse through selection mode (`select_buffer`, the name stack,
//! `glu_pick_matrix`), the picked one drawn highlighted; dragging moves it and the curve
//! follows (`glu_un_project`). The control polygon and the points are drawn from a vertex array
//! set once in `init`: GL reads it when it draws, so the moved point shows. The C program's
//! static array is a [`ClientArray`] here, shared by the program and the context.
//!
//! The first frame shows the state after a click beside control point 2.
//!
//! `cargo run --release --example picking` (a window: click a point, drag it), or
//! `-- --png picking.png`.

use gleval::gl::ClientArray;
use gleval::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

const NPTS: usize = 5;

/// The program's globals (`static` in C).
struct State {
    ctrl: ClientArray,
    viewport: [GLint; 4],
    selected: i32,
    clicked: bool,
    dragging: bool,
}

/// The projection `reshape` sets with `glu_ortho_2d(-4, 4, -4, 4)`, and the identity modelview.
const PROJ: [GLdouble; 16] = [0.25, 0.0, 0.0, 0.0, 0.0, 0.25, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
const MODEL: [GLdouble; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];

fn init(gl: &mut Gl, s: &State) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.vertex_pointer(3, GL_FLOAT, 0, &s.ctrl);
    gl.enable_client_state(GL_VERTEX_ARRAY);
}

fn draw_points(gl: &mut Gl, mode: GLenum) {
    for i in 0..NPTS {
        if mode == GL_SELECT {
            gl.load_name(i as GLuint);
        }
        gl.begin(GL_POINTS);
        gl.array_element(i as GLint);
        gl.end();
    }
}

/// The control point under window pixel (x, y) (GLUT's y, from the top), or -1: the nearest
/// of the hits in an 8 × 8 pixel pick region.
fn pick(gl: &mut Gl, s: &State, x: i32, y: i32) -> i32 {
    gl.select_buffer(64);
    gl.render_mode(GL_SELECT);
    gl.init_names();
    gl.push_name(!0u32);
    gl.matrix_mode(GL_PROJECTION);
    gl.push_matrix();
    gl.load_identity();
    gl.glu_pick_matrix(f64::from(x), f64::from(s.viewport[3] - y), 8.0, 8.0, &s.viewport);
    gl.glu_ortho_2d(-4.0, 4.0, -4.0, 4.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.point_size(10.0);
    draw_points(gl, GL_SELECT);
    gl.matrix_mode(GL_PROJECTION);
    gl.pop_matrix();
    gl.matrix_mode(GL_MODELVIEW);
    gl.render_mode(GL_RENDER);
    // The nearest named hit, the last of equals (the C loop's `zmin <= best_depth`).
    gl.select_hits()
        .filter(|hit| !hit.names.is_empty())
        .max_by_key(|hit| std::cmp::Reverse(hit.z_min))
        .map_or(-1, |hit| hit.names[0] as i32)
}

fn reshape(gl: &mut Gl, s: &mut State, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    s.viewport = [0, 0, w, h];
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(-4.0, 4.0, -4.0, 4.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn display(gl: &mut Gl, s: &mut State) {
    if !s.clicked {
        // Control point 2 is at window (200, 150): a click 3 pixels right, 2 up.
        s.clicked = true;
        s.selected = pick(gl, s, 203, s.viewport[3] - 152);
    }
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, NPTS as GLint, &s.ctrl.to_vec::<f32>());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(60, 0.0, 1.0);
    gl.color3f(1.0, 1.0, 1.0);
    gl.line_width(2.0);
    gl.eval_mesh1(GL_LINE, 0, 60);
    gl.line_width(1.0);
    gl.color3f(0.4, 0.6, 1.0);
    gl.draw_arrays(GL_LINE_STRIP, 0, NPTS as GLsizei);
    gl.point_size(8.0);
    gl.color3f(1.0, 1.0, 0.0);
    draw_points(gl, GL_RENDER);
    if s.selected >= 0 {
        gl.point_size(14.0);
        gl.color3f(1.0, 0.2, 0.2);
        gl.draw_arrays(GL_POINTS, s.selected, 1);
    }
    gl.flush();
}

fn mouse(gl: &mut Gl, s: &mut State, button: i32, state: i32, x: i32, y: i32) {
    if button != GLUT_LEFT_BUTTON {
        return;
    }
    if state == GLUT_DOWN {
        s.selected = pick(gl, s, x, y);
        s.dragging = s.selected >= 0;
    } else {
        s.dragging = false;
    }
    gl.glut_post_redisplay();
}

fn motion(gl: &mut Gl, s: &mut State, x: i32, y: i32) {
    let (mut ox, mut oy, mut oz) = (0.0, 0.0, 0.0);
    if !s.dragging {
        return;
    }
    let (wx, wy) = (f64::from(x), f64::from(s.viewport[3] - y));
    if gl.glu_un_project(wx, wy, 0.5, &MODEL, &PROJ, &s.viewport, &mut ox, &mut oy, &mut oz) != 0 {
        let i = s.selected as usize;
        s.ctrl.write(3 * i, &[ox as GLfloat, oy as GLfloat]);
    }
    gl.glut_post_redisplay();
}

/// The program, for tests that render it headless or drive its callbacks.
pub fn app() -> App {
    #[rustfmt::skip]
    let ctrl = ClientArray::new(&[
        -3.0f32, -2.0, 0.0,  -2.0, 2.5, 0.2,  0.0, -1.0, 0.4,  2.0, 3.0, 0.6,  3.2, -2.5, 0.8,
    ]);
    let state = Rc::new(RefCell::new(State { ctrl, viewport: [0; 4], selected: -1, clicked: false, dragging: false }));
    let (s1, s2, s3, s4, s5) = (state.clone(), state.clone(), state.clone(), state.clone(), state);
    App::new("Picking control points", 400, 400)
        .init(move |gl| init(gl, &s1.borrow()))
        .reshape(move |gl, w, h| reshape(gl, &mut s2.borrow_mut(), w, h))
        .display(move |gl| display(gl, &mut s3.borrow_mut()))
        .mouse(move |gl, b, st, x, y| mouse(gl, &mut s4.borrow_mut(), b, st, x, y))
        .motion(move |gl, x, y| motion(gl, &mut s5.borrow_mut(), x, y))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
