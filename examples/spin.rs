//! A course-style NURBS demo, as students write them with GLUT: a bicubic NURBS surface that
//! the arrow keys rotate and the idle callback spins; `m` switches the display mode (FILL,
//! OUTLINE_POLYGON, OUTLINE_PATCH), `t` the checker texture (a `GL_MAP2_TEXTURE_COORD_2`
//! companion surface gives (s, t)), space starts and stops the spin, `p` shows the control
//! points, labelled with GLUT bitmap text. The right mouse button opens a GLUT menu that does
//! the same (the display modes in a sub-menu). The title says the state.
//!
//! `cargo run --release --example spin` (a window), or headless:
//! `cargo run --release --example spin -- --frames 30 --png spin.png` (30 frames of the spin on
//! a virtual 60 Hz clock, the last one written).

use gleval::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

/// What the callbacks share (a C program keeps it in globals).
struct State {
    nurb: Option<GLUnurbs>,
    spin_x: f32,
    spin_y: f32,
    spinning: bool,
    mode: usize,
    show_points: bool,
    textured: bool,
}

const MODES: [(GLenum, &str); 3] =
    [(GLU_FILL, "FILL"), (GLU_OUTLINE_POLYGON, "OUTLINE_POLYGON"), (GLU_OUTLINE_PATCH, "OUTLINE_PATCH")];

/// A 4×4 net over [-3, 3]², raised in the middle: two bumps along the diagonal.
fn control_points() -> [[[f32; 3]; 4]; 4] {
    std::array::from_fn(|u| {
        std::array::from_fn(|v| {
            let (x, y) = (2.0 * (u as f32 - 1.5), 2.0 * (v as f32 - 1.5));
            let z = match (u, v) {
                (1, 1) | (2, 2) => 3.0,
                (1, 2) | (2, 1) => -1.0,
                _ => -2.0,
            };
            [x, y, z]
        })
    })
}

fn init(gl: &mut Gl, state: &mut State) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.8, 0.5, 0.2, 1.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 60.0);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);
    // An 8×8 checker, one texel per square, repeated over the surface.
    let checker: Vec<u8> =
        (0..64).flat_map(|i| if (i / 8 + i % 8) % 2 == 0 { [240, 240, 220] } else { [60, 90, 160] }).collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, &checker);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_SAMPLING_TOLERANCE, 25.0);
    state.nurb = Some(nurb);
    update_title(gl, state);
}

/// The right-button menu: a sub-menu of display modes, then the toggles. Its callback hands
/// the entry's value to the same code the keyboard uses.
fn make_menu(gl: &mut Gl, on_choice: impl FnMut(&mut Gl, i32) + Clone + 'static) {
    let modes = gl.glut_create_menu(on_choice.clone());
    gl.glut_add_menu_entry("Fill", MENU_FILL);
    gl.glut_add_menu_entry("Outline polygon", MENU_FILL + 1);
    gl.glut_add_menu_entry("Outline patch", MENU_FILL + 2);
    gl.glut_create_menu(on_choice);
    gl.glut_add_sub_menu("Display mode", modes);
    gl.glut_add_menu_entry("Texture on/off", 't' as i32);
    gl.glut_add_menu_entry("Control points on/off", 'p' as i32);
    gl.glut_add_menu_entry("Spin on/off", ' ' as i32);
    gl.glut_attach_menu(GLUT_RIGHT_BUTTON);
}

/// Menu values of the display modes (the toggles use their keys' codes).
const MENU_FILL: i32 = 1000;

/// A key or menu choice: returns false if it means nothing.
fn command(state: &mut State, choice: i32) -> bool {
    match choice {
        MENU_FILL..=1002 => state.mode = (choice - MENU_FILL) as usize,
        _ => match char::from_u32(choice as u32) {
            Some('m') => state.mode = (state.mode + 1) % MODES.len(),
            Some('p') => state.show_points = !state.show_points,
            Some('t') => state.textured = !state.textured,
            Some(' ') => state.spinning = !state.spinning,
            _ => return false,
        },
    }
    true
}

fn update_title(gl: &mut Gl, state: &State) {
    let spin = if state.spinning { "spinning" } else { "still" };
    let texture = if state.textured { "textured" } else { "plain" };
    gl.glut_set_window_title(&format!(
        "spin: {} {texture} ({spin}; arrows rotate, m mode, t texture, space spin, right button menu)",
        MODES[state.mode].1
    ));
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(45.0, f64::from(w) / f64::from(h.max(1)), 3.0, 12.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -7.0);
}

fn display(gl: &mut Gl, state: &State) {
    let Some(nurb) = state.nurb else { return };
    let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let ctl = control_points();
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.push_matrix();
    gl.rotatef(state.spin_x - 60.0, 1.0, 0.0, 0.0);
    gl.rotatef(state.spin_y, 0.0, 0.0, 1.0);
    gl.scalef(0.5, 0.5, 0.5);
    gl.glu_nurbs_property(nurb, GLU_DISPLAY_MODE, MODES[state.mode].0 as f32);
    if state.textured {
        gl.enable(GL_TEXTURE_2D);
    }
    // (s, t) from 0 to 3 over the surface: a bilinear companion surface (GLU evaluates it beside
    // the position, as GL_MAP2_TEXTURE_COORD_2).
    let tex = [[[0.0f32, 0.0], [0.0, 3.0]], [[3.0, 0.0], [3.0, 3.0]]];
    let tknots = [0.0, 0.0, 1.0, 1.0];
    gl.glu_begin_surface(nurb);
    gl.glu_nurbs_surface(
        nurb,
        4,
        &tknots,
        4,
        &tknots,
        2 * 2,
        2,
        tex.as_flattened().as_flattened(),
        2,
        2,
        GL_MAP2_TEXTURE_COORD_2,
    );
    let points = ctl.as_flattened().as_flattened();
    gl.glu_nurbs_surface(nurb, 8, &knots, 8, &knots, 4 * 3, 3, points, 4, 4, GL_MAP2_VERTEX_3);
    gl.glu_end_surface(nurb);
    gl.disable(GL_TEXTURE_2D);
    if state.show_points {
        gl.disable(GL_LIGHTING);
        gl.point_size(5.0);
        gl.color3f(1.0, 1.0, 0.0);
        gl.begin(GL_POINTS);
        for p in ctl.as_flattened() {
            gl.vertex3fv(p);
        }
        gl.end();
        // Label the corner points, as course demos do: P(u,v) beside each.
        for (u, v) in [(0, 0), (3, 0), (0, 3), (3, 3)] {
            let p = ctl[u][v];
            gl.raster_pos3f(p[0], p[1], p[2] + 0.3);
            for c in format!("P{u}{v}").bytes() {
                gl.glut_bitmap_character(GLUT_BITMAP_HELVETICA_12, c);
            }
        }
        gl.enable(GL_LIGHTING);
    }
    gl.pop_matrix();
    gl.flush();
}

fn special(state: &mut State, key: i32) {
    match key {
        GLUT_KEY_LEFT => state.spin_y -= 5.0,
        GLUT_KEY_RIGHT => state.spin_y += 5.0,
        GLUT_KEY_UP => state.spin_x -= 5.0,
        GLUT_KEY_DOWN => state.spin_x += 5.0,
        _ => {}
    }
}

fn main() {
    let state = Rc::new(RefCell::new(State {
        nurb: None,
        spin_x: 0.0,
        spin_y: 0.0,
        spinning: true,
        mode: 0,
        show_points: true,
        textured: true,
    }));
    let (s_init, s_display, s_key, s_special, s_idle, s_menu) =
        (state.clone(), state.clone(), state.clone(), state.clone(), state.clone(), state.clone());
    let on_choice = move |gl: &mut Gl, value: i32| {
        let mut state = s_menu.borrow_mut();
        if command(&mut state, value) {
            update_title(gl, &state);
            gl.glut_post_redisplay();
        }
    };
    App::new("spin", 500, 500)
        .init_display_mode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH)
        .init(move |gl| {
            init(gl, &mut s_init.borrow_mut());
            make_menu(gl, on_choice.clone());
        })
        .reshape(reshape)
        .display(move |gl| display(gl, &s_display.borrow()))
        .keyboard(move |gl, key, _, _| {
            let mut state = s_key.borrow_mut();
            if !command(&mut state, key as i32) {
                return;
            }
            update_title(gl, &state);
            gl.glut_post_redisplay();
        })
        .special(move |gl, key, _, _| {
            special(&mut s_special.borrow_mut(), key);
            gl.glut_post_redisplay();
        })
        .idle(move |gl| {
            let mut state = s_idle.borrow_mut();
            if state.spinning {
                state.spin_y = (state.spin_y + 1.0) % 360.0;
                gl.glut_post_redisplay();
            }
        })
        .run();
}
