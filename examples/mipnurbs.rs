//! MipNurbs.c (tests/reference/pictures), ported line for line: a mipmapped NURBS surface. A
//! 64×64 checker goes through `glu_build_2d_mipmaps`; a bicubic NURBS surface with a
//! `GL_MAP2_TEXTURE_COORD_2` companion surface (s, t from 0 to 8) recedes under a perspective
//! projection, so the minification filter (LINEAR_MIPMAP_LINEAR) reads the coarse levels.
//!
//! `cargo run --release --example mipnurbs -- --png mipnurbs.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;
use std::cell::Cell;
use std::rc::Rc;

const SIZE: usize = 64;

fn init(gl: &mut Gl) -> GLUnurbs {
    let mut image = [[[0u8; 3]; SIZE]; SIZE];
    for i in 0..SIZE {
        for j in 0..SIZE {
            let on = ((i / 8) + (j / 8)) % 2 == 1;
            image[i][j][0] = if on { 250 } else { 30 };
            image[i][j][1] = if on { 200 } else { 60 };
            image[i][j][2] = if on { 40 } else { 160 };
        }
    }
    gl.clear_color(0.2, 0.25, 0.3, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.glu_build_2d_mipmaps(GL_TEXTURE_2D, GL_RGB as i32, SIZE as i32, SIZE as i32, GL_RGB, GL_UNSIGNED_BYTE, &image);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    gl.glu_nurbs_property(nurb, GLU_U_STEP, 24.0);
    gl.glu_nurbs_property(nurb, GLU_V_STEP, 24.0);
    nurb
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(50.0, f64::from(w) / f64::from(h), 0.5, 60.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, -3.0, 2.0, 0.0, 12.0, 0.0, 0.0, 0.0, 1.0);
}

fn display(gl: &mut Gl, nurb: GLUnurbs) {
    let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let mut ctl = [[[0.0f32; 3]; 4]; 4];
    let tex = [[[0.0f32, 0.0], [0.0, 8.0]], [[8.0, 0.0], [8.0, 8.0]]];
    let tknots = [0.0, 0.0, 1.0, 1.0];
    for u in 0..4 {
        for v in 0..4 {
            ctl[u][v][0] = -6.0 + 4.0 * u as f32;
            ctl[u][v][1] = -2.0 + 10.0 * v as f32;
            ctl[u][v][2] = if (u == 1 || u == 2) && v == 2 { 1.5 } else { -0.5 };
        }
    }
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.glu_begin_surface(nurb);
    let tex_points = tex.as_flattened().as_flattened();
    gl.glu_nurbs_surface(nurb, 4, &tknots, 4, &tknots, 2 * 2, 2, tex_points, 2, 2, GL_MAP2_TEXTURE_COORD_2);
    let points = ctl.as_flattened().as_flattened();
    gl.glu_nurbs_surface(nurb, 8, &knots, 8, &knots, 4 * 3, 3, points, 4, 4, GL_MAP2_VERTEX_3);
    gl.glu_end_surface(nurb);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let nurb = Rc::new(Cell::new(None));
    let at_display = nurb.clone();
    App::new("Mipmapped NURBS surface", 400, 300).init(move |gl| nurb.set(Some(init(gl)))).reshape(reshape).display(
        move |gl| {
            if let Some(nurb) = at_display.get() {
                display(gl, nurb);
            }
        },
    )
}

#[allow(dead_code)]
fn main() {
    app().run();
}
