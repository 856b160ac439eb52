//! Quadrics.c (tests/reference/pictures), ported line for line: GLU's quadrics in every draw
//! style. A Bezier curve with its control points drawn as lit `glu_sphere` balls, a textured
//! sphere and disk, a smooth cone, a flat cylinder facing in, wire and silhouette shapes,
//! partial disks filled, as points and as silhouettes.
//!
//! `cargo run --release --example quadrics -- --png quadrics.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const SIZE: usize = 16;

const CTL: [[f32; 3]; 4] = [[-2.6, -1.4, 0.0], [-1.6, 1.6, 0.5], [0.2, -1.8, -0.5], [1.2, 1.2, 0.0]];

fn init(gl: &mut Gl) -> GLUquadric {
    let mut checker = [[[0u8; 3]; SIZE]; SIZE];
    for i in 0..SIZE {
        for j in 0..SIZE {
            let on = ((i / 4) + (j / 4)) % 2 == 1;
            checker[i][j][0] = if on { 250 } else { 40 };
            checker[i][j][1] = if on { 200 } else { 90 };
            checker[i][j][2] = (i * 16) as u8;
        }
    }
    gl.clear_color(0.08, 0.08, 0.12, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHT0);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[2.0, 3.0, 4.0, 0.0]);
    gl.light_model_fv(GL_LIGHT_MODEL_AMBIENT, &[0.25, 0.25, 0.25, 1.0]);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let texels = checker.as_flattened().as_flattened();
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, SIZE as i32, SIZE as i32, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, CTL.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.glu_new_quadric()
}

fn material(gl: &mut Gl, r: f32, g: f32, b: f32) {
    gl.material_fv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, &[r, g, b, 1.0]);
}

fn at(gl: &mut Gl, x: f32, y: f32, z: f32) {
    gl.push_matrix();
    gl.translatef(x, y, z);
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(40.0, f64::from(w) / f64::from(h), 1.0, 30.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, -1.0, 10.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

fn display(gl: &mut Gl, quad: GLUquadric) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // The curve, unlit, and its control points as lit balls.
    gl.color3f(1.0, 1.0, 0.3);
    gl.begin(GL_LINE_STRIP);
    for i in 0..=40 {
        gl.eval_coord1f(i as f32 / 40.0);
    }
    gl.end();
    gl.enable(GL_LIGHTING);
    gl.glu_quadric_draw_style(quad, GLU_FILL);
    gl.glu_quadric_normals(quad, GLU_SMOOTH);
    material(gl, 0.9, 0.2, 0.2);
    for i in 0..4 {
        at(gl, CTL[i][0], CTL[i][1], CTL[i][2]);
        gl.glu_sphere(quad, 0.18, 12, 8);
        gl.pop_matrix();
    }

    // A textured sphere and a textured disk.
    gl.enable(GL_TEXTURE_2D);
    gl.glu_quadric_texture(quad, GL_TRUE);
    material(gl, 1.0, 1.0, 1.0);
    at(gl, 2.6, 1.4, 0.0);
    gl.rotatef(-70.0, 1.0, 0.0, 0.0);
    gl.glu_sphere(quad, 0.8, 16, 12);
    gl.pop_matrix();
    at(gl, -2.9, 1.5, 0.0);
    gl.glu_disk(quad, 0.2, 0.7, 12, 3);
    gl.pop_matrix();
    gl.glu_quadric_texture(quad, GL_FALSE);
    gl.disable(GL_TEXTURE_2D);

    // A smooth cone and a flat cylinder seen from inside.
    material(gl, 0.2, 0.6, 0.9);
    at(gl, 2.7, -1.6, 0.0);
    gl.rotatef(-60.0, 1.0, 0.0, 0.0);
    gl.glu_cylinder(quad, 0.6, 0.0, 1.2, 14, 3);
    gl.pop_matrix();
    gl.glu_quadric_normals(quad, GLU_FLAT);
    gl.glu_quadric_orientation(quad, GLU_INSIDE);
    material(gl, 0.3, 0.8, 0.3);
    at(gl, 0.9, 2.2, 0.0);
    gl.rotatef(-75.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 1.0, 0.0);
    gl.glu_cylinder(quad, 0.5, 0.5, 0.8, 10, 2);
    gl.pop_matrix();
    gl.glu_quadric_orientation(quad, GLU_OUTSIDE);

    // A filled partial disk, flat.
    material(gl, 0.9, 0.6, 0.2);
    at(gl, -0.9, 2.0, 0.0);
    gl.glu_partial_disk(quad, 0.2, 0.7, 10, 2, 30.0, 240.0);
    gl.pop_matrix();
    gl.disable(GL_LIGHTING);

    // Wire, silhouette and point styles, unlit.
    gl.glu_quadric_normals(quad, GLU_NONE);
    gl.glu_quadric_draw_style(quad, GLU_LINE);
    gl.color3f(0.6, 0.9, 1.0);
    at(gl, -0.6, -2.3, 0.0);
    gl.rotatef(-60.0, 1.0, 0.0, 0.0);
    gl.glu_sphere(quad, 0.6, 10, 6);
    gl.pop_matrix();
    at(gl, -3.0, -2.4, 0.0);
    gl.rotatef(-50.0, 1.0, 0.0, 0.0);
    gl.glu_cylinder(quad, 0.4, 0.2, 0.8, 8, 2);
    gl.pop_matrix();
    gl.glu_quadric_draw_style(quad, GLU_SILHOUETTE);
    gl.color3f(1.0, 0.5, 0.8);
    at(gl, 0.9, -0.4, 0.0);
    gl.glu_disk(quad, 0.3, 0.6, 16, 2);
    gl.pop_matrix();
    at(gl, -1.2, 0.2, 0.0);
    gl.glu_partial_disk(quad, 0.0, 0.5, 8, 2, -45.0, -120.0);
    gl.pop_matrix();
    gl.glu_quadric_draw_style(quad, GLU_POINT);
    gl.point_size(2.0);
    gl.color3f(1.0, 1.0, 1.0);
    at(gl, 0.9, -2.4, 0.0);
    gl.glu_partial_disk(quad, 0.1, 0.6, 9, 3, 0.0, 300.0);
    gl.pop_matrix();
    gl.point_size(1.0);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let quad = std::rc::Rc::new(std::cell::Cell::new(None));
    let at_display = quad.clone();
    App::new("Quadrics", 320, 240).init(move |gl| quad.set(Some(init(gl)))).reshape(reshape).display(move |gl| {
        if let Some(q) = at_display.get() {
            display(gl, q);
        }
    })
}

#[allow(dead_code)]
fn main() {
    app().run();
}
