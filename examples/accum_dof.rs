//! AccumDOF.c (tests/reference/pictures), ported line for line: depth of field with the
//! accumulation buffer, as the Red Book's dof.c does it: eight frames from eye positions
//! jittered on a small lens (`acc_frustum`), all focused on the plane z = −5, accumulated with
//! 1/8. Three Bezier patches at depths 3, 5 and 8 with their meshes: the middle one sharp.
//!
//! `cargo run --release --example accum_dof -- --png accum_dof.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const J8: [[f32; 2]; 8] = [
    [-0.334818, 0.435331],
    [0.286438, -0.393495],
    [0.459462, 0.141540],
    [-0.414498, -0.192829],
    [-0.183790, 0.082102],
    [-0.079263, -0.317383],
    [0.102254, 0.299133],
    [0.164216, -0.054399],
];

/// The Red Book's accFrustum without its pixel jitter: the eye moved by (eyedx, eyedy), the
/// plane at distance `focus` kept in place.
#[allow(clippy::too_many_arguments)]
fn acc_frustum(
    gl: &mut Gl,
    left: f64,
    right: f64,
    bottom: f64,
    top: f64,
    near: f64,
    far: f64,
    eye: (f64, f64),
    focus: f64,
) {
    let (eyedx, eyedy) = eye;
    let (dx, dy) = (-(eyedx * near / focus), -(eyedy * near / focus));
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.frustum(left + dx, right + dx, bottom + dy, top + dy, near, far);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(-eyedx as f32, -eyedy as f32, 0.0);
}

fn init(gl: &mut Gl) {
    let mut patch = [[[0.0f32; 3]; 4]; 4];
    for u in 0..4 {
        for v in 0..4 {
            patch[u][v][0] = 2.0 * (u as f32 / 3.0) - 1.0;
            patch[u][v][1] = 2.0 * (v as f32 / 3.0) - 1.0;
            patch[u][v][2] = if (u == 1 || u == 2) && (v == 1 || v == 2) { 0.6 } else { -0.3 };
        }
    }
    gl.clear_color(0.1, 0.1, 0.1, 1.0);
    gl.clear_accum(0.0, 0.0, 0.0, 0.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_POLYGON_OFFSET_FILL);
    gl.polygon_offset(1.0, 1.0);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, patch.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_grid2f(12, 0.0, 1.0, 12, 0.0, 1.0);
}

fn patch_at(gl: &mut Gl, x: f32, z: f32, color: &[f32; 4]) {
    gl.push_matrix();
    gl.translatef(x, 0.0, z);
    gl.rotatef(-50.0, 1.0, 0.0, 0.0);
    gl.scalef(0.7, 0.7, 0.7);
    gl.color4fv(color);
    gl.eval_mesh2(GL_FILL, 0, 12, 0, 12);
    gl.color3f(1.0, 1.0, 1.0);
    gl.eval_mesh2(GL_LINE, 0, 12, 0, 12);
    gl.pop_matrix();
}

fn display(gl: &mut Gl) {
    let (red, green, blue) = ([0.9, 0.2, 0.2, 1.0], [0.2, 0.9, 0.3, 1.0], [0.3, 0.4, 1.0, 1.0]);
    gl.clear(GL_ACCUM_BUFFER_BIT);
    for j in 0..8 {
        gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        let eye = (0.12 * f64::from(J8[j][0]), 0.12 * f64::from(J8[j][1]));
        acc_frustum(gl, -0.8, 0.8, -0.6, 0.6, 1.0, 20.0, eye, 5.0);
        patch_at(gl, -1.6, -3.0, &red);
        patch_at(gl, 0.0, -5.0, &green);
        patch_at(gl, 2.6, -8.0, &blue);
        gl.accum(GL_ACCUM, 0.125);
    }
    gl.accum(GL_RETURN, 1.0);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Depth of field", 320, 240)
        .init_display_mode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH | GLUT_ACCUM)
        .init(init)
        .display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
