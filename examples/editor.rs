//! Editor.c (tests/reference/pictures), ported line for line: a control-point editor of the
//! classic kind. A rational Bezier curve (`map1f` with `GL_MAP1_VERTEX_4`, `eval_mesh1`) over six
//! control points drawn as lit `glu_sphere` balls whose size shows their weight, the control
//! polygon, labels naming the points and a status line with the selected point's coordinates and
//! weight (`glut_bitmap_string`). The left button picks a ball through selection mode
//! (`select_buffer`, the name stack, `glu_pick_matrix`) and drags it in the view plane
//! (`glu_project` for its depth, `glu_un_project` for where it goes); the selected ball wears a
//! yellow ring (`glu_disk`). The right button opens a GLUT menu: the control polygon on or off,
//! the selected point heavier, lighter or in the next colour, the points reset, quit.
//!
//! The first frame shows the state after a click beside point 2 and the menu's "Heavier" and
//! "Next colour" chosen for it.
//!
//! `cargo run --release --example editor` (a window: drag the balls, right button for the
//! menu), or `-- --png editor.png`.
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

const NPTS: usize = 6;
const POLYGON: i32 = 1;
const HEAVIER: i32 = 2;
const LIGHTER: i32 = 3;
const COLOUR: i32 = 4;
const RESET: i32 = 5;
const QUIT: i32 = 6;

#[rustfmt::skip]
const START: [[GLfloat; 3]; NPTS] = [[-3.2, -2.0, 0.0], [-2.4, 2.4, 0.0], [-0.8, -2.6, 0.0],
                                     [0.8, 2.6, 0.0],   [2.4, -2.4, 0.0], [3.2, 2.0, 0.0]];
const PALETTE: [[GLfloat; 4]; 4] =
    [[1.0, 0.55, 0.15, 1.0], [0.3, 0.85, 0.35, 1.0], [0.35, 0.55, 1.0, 1.0], [0.9, 0.35, 0.85, 1.0]];

/// The program's globals (`static` in C).
struct State {
    ctrl: [[GLfloat; 3]; NPTS],
    weight: [GLfloat; NPTS],
    colour: [usize; NPTS],
    selected: i32,
    dragging: bool,
    polygon: bool,
    started: bool,
    viewport: [GLint; 4],
    quad: Option<GLUquadric>,
}

fn reset(s: &mut State) {
    s.ctrl = START;
    for i in 0..NPTS {
        s.weight[i] = 1.0;
        s.colour[i] = 0;
    }
}

/// A ball's radius grows with its point's weight (1/4 .. 4).
fn radius(s: &State, i: usize) -> GLdouble {
    0.1 + 0.08 * f64::from(s.weight[i])
}

/// What a menu entry does.
fn choose(s: &mut State, value: i32) {
    let sel = s.selected as usize;
    match value {
        POLYGON => s.polygon = !s.polygon,
        HEAVIER if s.selected >= 0 && s.weight[sel] < 4.0 => s.weight[sel] *= 2.0,
        LIGHTER if s.selected >= 0 && s.weight[sel] > 0.25 => s.weight[sel] /= 2.0,
        COLOUR if s.selected >= 0 => s.colour[sel] = (s.colour[sel] + 1) % 4,
        RESET => reset(s),
        QUIT => std::process::exit(0),
        _ => {}
    }
}

fn menu(gl: &mut Gl, s: &mut State, value: i32) {
    choose(s, value);
    gl.glut_post_redisplay();
}

fn init(gl: &mut Gl, state: &Rc<RefCell<State>>) {
    let s = &mut state.borrow_mut();
    reset(s);
    gl.clear_color(0.12, 0.12, 0.16, 1.0);
    gl.enable(GL_CULL_FACE);
    gl.enable(GL_LIGHT0);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[-1.0, 2.0, 3.0, 0.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 30.0);
    gl.enable(GL_MAP1_VERTEX_4);
    gl.map_grid1f(80, 0.0, 1.0);
    s.quad = Some(gl.glu_new_quadric());
    let m = state.clone();
    gl.glut_create_menu(move |gl, value| menu(gl, &mut m.borrow_mut(), value));
    gl.glut_add_menu_entry("Control polygon on/off", POLYGON);
    gl.glut_add_menu_entry("Heavier (weight x 2)", HEAVIER);
    gl.glut_add_menu_entry("Lighter (weight / 2)", LIGHTER);
    gl.glut_add_menu_entry("Next colour", COLOUR);
    gl.glut_add_menu_entry("Reset points", RESET);
    gl.glut_add_menu_entry("Quit", QUIT);
    gl.glut_attach_menu(GLUT_RIGHT_BUTTON);
}

/// The balls, lit in their colours, or named for selection.
fn draw_balls(gl: &mut Gl, s: &State, mode: GLenum) {
    let quad = s.quad.expect("init made the quadric");
    for i in 0..NPTS {
        if mode == GL_SELECT {
            gl.load_name(i as GLuint);
        } else {
            gl.material_fv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, &PALETTE[s.colour[i]]);
        }
        gl.push_matrix();
        gl.translatef(s.ctrl[i][0], s.ctrl[i][1], s.ctrl[i][2]);
        gl.glu_sphere(quad, radius(s, i), 16, 12);
        gl.pop_matrix();
    }
}

/// The ball under window pixel (x, y) (GLUT's y, from the top), or -1: the nearest of the hits
/// in a 6 × 6 pixel pick region.
fn pick(gl: &mut Gl, s: &State, x: i32, y: i32) -> i32 {
    let mut proj = [0.0; 16];
    gl.select_buffer(4 * NPTS as GLsizei);
    gl.render_mode(GL_SELECT);
    gl.init_names();
    gl.push_name(!0u32);
    gl.matrix_mode(GL_PROJECTION);
    gl.get_doublev(GL_PROJECTION_MATRIX, &mut proj);
    gl.push_matrix();
    gl.load_identity();
    gl.glu_pick_matrix(f64::from(x), f64::from(s.viewport[3] - y), 6.0, 6.0, &s.viewport);
    gl.mult_matrixd(&proj);
    gl.matrix_mode(GL_MODELVIEW);
    draw_balls(gl, s, GL_SELECT);
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
    gl.get_integerv(GL_VIEWPORT, &mut s.viewport);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-4.0, 4.0, -4.0, 4.0, -10.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn display(gl: &mut Gl, s: &mut State) {
    let mut hom = [[0.0f32; 4]; NPTS];
    if !s.started {
        // Point 2, (-0.8, -2.6), is at window (160, 330) from the top: a click 3 pixels right,
        // 2 up, then two menu entries.
        s.started = true;
        s.selected = pick(gl, s, 163, 328);
        choose(s, HEAVIER);
        choose(s, COLOUR);
    }
    gl.clear(GL_COLOR_BUFFER_BIT);

    // The curve through the weighted points (x w, y w, z w, w).
    for i in 0..NPTS {
        for k in 0..3 {
            hom[i][k] = s.ctrl[i][k] * s.weight[i];
        }
        hom[i][3] = s.weight[i];
    }
    gl.map1f(GL_MAP1_VERTEX_4, 0.0, 1.0, 4, NPTS as GLint, hom.as_flattened());
    gl.color3f(1.0, 1.0, 1.0);
    gl.line_width(2.0);
    gl.eval_mesh1(GL_LINE, 0, 80);
    gl.line_width(1.0);
    if s.polygon {
        gl.color3f(0.45, 0.55, 0.75);
        gl.begin(GL_LINE_STRIP);
        for i in 0..NPTS {
            gl.vertex3fv(&s.ctrl[i]);
        }
        gl.end();
    }

    gl.enable(GL_LIGHTING);
    draw_balls(gl, s, GL_RENDER);
    gl.disable(GL_LIGHTING);
    if s.selected >= 0 {
        let sel = s.selected as usize;
        gl.color3f(1.0, 0.9, 0.1);
        gl.push_matrix();
        gl.translatef(s.ctrl[sel][0], s.ctrl[sel][1], s.ctrl[sel][2]);
        gl.glu_disk(s.quad.expect("init made the quadric"), radius(s, sel) + 0.06, radius(s, sel) + 0.14, 24, 1);
        gl.pop_matrix();
    }

    // Labels beside the balls, the status line and a hint.
    gl.color3f(0.9, 0.9, 0.9);
    for i in 0..NPTS {
        let d = radius(s, i) as GLfloat + 0.08;
        gl.raster_pos3f(s.ctrl[i][0] + d, s.ctrl[i][1] + d, s.ctrl[i][2]);
        let text = format!("P{i}");
        gl.glut_bitmap_string(GLUT_BITMAP_HELVETICA_12, &text);
    }
    gl.color3f(1.0, 0.9, 0.1);
    gl.raster_pos2f(-3.85, 3.6);
    let text = if s.selected >= 0 {
        let sel = s.selected as usize;
        format!("P{} at ({:.2}, {:.2}), weight {}", s.selected, s.ctrl[sel][0], s.ctrl[sel][1], s.weight[sel])
    } else {
        "no point selected".to_string()
    };
    gl.glut_bitmap_string(GLUT_BITMAP_9_BY_15, &text);
    gl.color3f(0.6, 0.6, 0.7);
    gl.raster_pos2f(-3.85, -3.85);
    gl.glut_bitmap_string(GLUT_BITMAP_HELVETICA_10, "left button: pick and drag a ball   right button: menu");
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

/// The selected point follows the pointer at its own depth.
fn motion(gl: &mut Gl, s: &mut State, x: i32, y: i32) {
    let (mut model, mut proj) = ([0.0; 16], [0.0; 16]);
    let (mut wx, mut wy, mut wz, mut ox, mut oy, mut oz) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    if !s.dragging {
        return;
    }
    gl.get_doublev(GL_MODELVIEW_MATRIX, &mut model);
    gl.get_doublev(GL_PROJECTION_MATRIX, &mut proj);
    let p = s.ctrl[s.selected as usize];
    let viewport = s.viewport;
    gl.glu_project(p[0].into(), p[1].into(), p[2].into(), &model, &proj, &viewport, &mut wx, &mut wy, &mut wz);
    let (x, y) = (f64::from(x), f64::from(viewport[3] - y));
    if gl.glu_un_project(x, y, wz, &model, &proj, &viewport, &mut ox, &mut oy, &mut oz) != 0 {
        s.ctrl[s.selected as usize] = [ox as GLfloat, oy as GLfloat, oz as GLfloat];
    }
    gl.glut_post_redisplay();
}

/// The program, for tests that render it headless or drive its callbacks.
pub fn app() -> App {
    let state = Rc::new(RefCell::new(State {
        ctrl: [[0.0; 3]; NPTS],
        weight: [0.0; NPTS],
        colour: [0; NPTS],
        selected: -1,
        dragging: false,
        polygon: true,
        started: false,
        viewport: [0; 4],
        quad: None,
    }));
    let (s1, s2, s3, s4, s5) = (state.clone(), state.clone(), state.clone(), state.clone(), state);
    App::new("Control-point editor", 400, 400)
        .init(move |gl| init(gl, &s1))
        .reshape(move |gl, w, h| reshape(gl, &mut s2.borrow_mut(), w, h))
        .display(move |gl| display(gl, &mut s3.borrow_mut()))
        .mouse(move |gl, b, st, x, y| mouse(gl, &mut s4.borrow_mut(), b, st, x, y))
        .motion(move |gl, x, y| motion(gl, &mut s5.borrow_mut(), x, y))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
