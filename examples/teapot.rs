//! The Utah teapot drawn as GLUT's `glutSolidTeapot` draws it (GLUT 3.7, `teapot.c`): every
//! bicubic patch loaded with `glMap2f` (u along a data row: stride 3, order 4; v across rows:
//! stride 12, order 4) together with a bilinear texture-coordinate map, then
//! `glMapGrid2f(14, 0, 1, 14, 0, 1)` and `glEvalMesh2(GL_FILL, 0, 14, 0, 14)`, with
//! `GL_AUTO_NORMAL` and `GL_NORMALIZE` on, under `glRotatef(270, 1, 0, 0)`,
//! `glScalef(0.5, 0.5, 0.5)` and `glTranslatef(0, 0, -1.5)` so that the pot stands upright on
//! the y axis. GLUT keeps 10 patches and draws their mirror images; here the 32 patches of
//! Newell's data ([`gleval::data::teapot`]) are drawn directly, which is the same surface.
//!
//! `cargo run --release --example teapot -- --png teapot.png`

use gleval::data::teapot::{TEAPOT_PATCHES, TEAPOT_VERTICES};
use gleval::prelude::*;

/// GLUT's tessellation of the solid teapot (`glutSolidTeapot` calls `teapot(14, ...)`).
const GRID: i32 = 14;

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(30.0, f64::from(w) / f64::from(h.max(1)), 1.0, 100.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, 1.7, 5.4, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

fn init(gl: &mut Gl) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[-2.0, 4.0, 5.0, 0.0]);
    gl.light_fv(GL_LIGHT0, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
    gl.light_fv(GL_LIGHT0, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.material_fv(GL_FRONT, GL_AMBIENT, &[0.25, 0.15, 0.05, 1.0]);
    gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.8, 0.5, 0.2, 1.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[0.6, 0.6, 0.6, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 40.0);
}

/// GLUT's `teapot(grid, scale, type)` with the 32-patch data.
fn solid_teapot(gl: &mut Gl, scale: f32) {
    // The texture coordinates run over each patch as (s, t) = (u, v) (GLUT's `tex`).
    let tex: [f32; 8] = [0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_MAP2_TEXTURE_COORD_2);
    gl.push_matrix();
    gl.rotatef(270.0, 1.0, 0.0, 0.0);
    gl.scalef(0.5 * scale, 0.5 * scale, 0.5 * scale);
    gl.translatef(0.0, 0.0, -1.5);
    for patch in &TEAPOT_PATCHES {
        // p[j][k] = control point of row j, column k, as GLUT fills its `p`.
        let mut p = [0.0f32; 48];
        for (slot, &index) in patch.iter().enumerate() {
            for l in 0..3 {
                p[slot * 3 + l] = TEAPOT_VERTICES[index as usize][l] as f32;
            }
        }
        gl.map2f(GL_MAP2_TEXTURE_COORD_2, 0.0, 1.0, 2, 2, 0.0, 1.0, 4, 2, &tex);
        gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p);
        gl.map_grid2f(GRID, 0.0, 1.0, GRID, 0.0, 1.0);
        gl.eval_mesh2(GL_FILL, 0, GRID, 0, GRID);
    }
    gl.pop_matrix();
}

fn display(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.push_matrix();
    gl.rotatef(-30.0, 0.0, 1.0, 0.0);
    solid_teapot(gl, 1.0);
    gl.pop_matrix();
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Utah teapot", 400, 300).init(init).reshape(reshape).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
