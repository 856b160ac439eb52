//! FogBlend.c (tests/reference/pictures), ported line for line: GL's per-fragment operations
//! on evaluated surfaces. Three viewports show the same Bezier surface receding under a
//! perspective projection with fog LINEAR, EXP and EXP2; the fourth blends translucent
//! rectangles (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) over an evaluated curve and drops the faintest
//! with the alpha test.
//!
//! `cargo run --release --example fogblend -- --png fogblend.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

fn init(gl: &mut Gl) {
    let mut ctl = [[[0.0f32; 3]; 4]; 4];
    let curve: [[f32; 3]; 4] = [[-1.2, -0.8, 0.0], [-0.4, 1.2, 0.0], [0.4, -1.2, 0.0], [1.2, 0.8, 0.0]];
    for u in 0..4 {
        for v in 0..4 {
            ctl[u][v][0] = -1.5 + u as f32;
            ctl[u][v][1] = -1.5 + 4.0 * v as f32;
            ctl[u][v][2] = if (u == 1 || u == 2) && (v == 1 || v == 2) { 0.8 } else { -0.4 };
        }
    }
    gl.clear_color(0.5, 0.55, 0.6, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, ctl.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_grid2f(16, 0.0, 1.0, 16, 0.0, 1.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, curve.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(40, 0.0, 1.0);
    gl.fogfv(GL_FOG_COLOR, &[0.5, 0.55, 0.6, 1.0]);
}

fn receding(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32, mode: GLenum) {
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(60.0, f64::from(w) / f64::from(h), 0.5, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, -4.0, 1.5, 0.0, 2.0, 0.0, 0.0, 0.0, 1.0);
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, mode as i32);
    gl.fogf(GL_FOG_START, 2.0);
    gl.fogf(GL_FOG_END, 9.0);
    gl.fogf(GL_FOG_DENSITY, if mode == GL_EXP { 0.25 } else { 0.18 });
    gl.color3f(0.9, 0.3, 0.1);
    gl.eval_mesh2(GL_FILL, 0, 16, 0, 16);
    gl.disable(GL_FOG);
}

fn translucent(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.5, 1.5, -1.5, 1.5, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.line_width(3.0);
    gl.color3f(0.0, 0.0, 0.6);
    gl.eval_mesh1(GL_LINE, 0, 40);
    gl.line_width(1.0);
    gl.disable(GL_DEPTH_TEST);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.enable(GL_ALPHA_TEST);
    gl.alpha_func(GL_GREATER, 0.2);
    for i in 0..4 {
        let f = i as f32;
        gl.color4f(1.0, 0.8 - 0.2 * f, 0.2 * f, 0.15 + 0.25 * f);
        gl.rectf(-1.3 + 0.6 * f, -1.0 + 0.3 * f, -0.3 + 0.6 * f, 0.2 + 0.3 * f);
    }
    gl.disable(GL_ALPHA_TEST);
    gl.disable(GL_BLEND);
    gl.enable(GL_DEPTH_TEST);
}

fn display(gl: &mut Gl) {
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH), gl.glut_get(GLUT_WINDOW_HEIGHT));
    gl.viewport(0, 0, w, h);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    receding(gl, 0, h / 2, w / 2, h / 2, GL_LINEAR);
    receding(gl, w / 2, h / 2, w / 2, h / 2, GL_EXP);
    receding(gl, 0, 0, w / 2, h / 2, GL_EXP2);
    translucent(gl, w / 2, 0, w / 2, h / 2);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Fog and blending", 400, 400).init(init).reshape(|_, _, _| {}).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
