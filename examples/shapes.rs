//! Shapes.c (tests/reference/pictures), ported line for line: GLUT's sphere, cube, cone and
//! torus, each in a viewport of its own, the solid ones lit with back faces culled, the wire ones
//! unlit; a lit plate after the solid cube shows that the shapes keep the current normal.
//!
//! `cargo run --release --example shapes -- --png shapes.png`

use gleval::prelude::*;

const COLOURS: [[f32; 4]; 4] =
    [[0.9, 0.3, 0.2, 1.0], [0.3, 0.8, 0.3, 1.0], [0.3, 0.5, 0.95, 1.0], [0.9, 0.75, 0.2, 1.0]];

fn shape(gl: &mut Gl, k: usize, wire: bool) {
    match k {
        0 => {
            if wire {
                gl.glut_wire_sphere(0.8, 16, 12)
            } else {
                gl.glut_solid_sphere(0.8, 16, 12)
            }
        }
        1 => {
            if wire {
                gl.glut_wire_cube(1.1)
            } else {
                gl.glut_solid_cube(1.1)
            }
        }
        2 => {
            gl.translatef(0.0, -0.6, 0.0);
            gl.rotatef(-90.0, 1.0, 0.0, 0.0);
            if wire {
                gl.glut_wire_cone(0.7, 1.4, 16, 6)
            } else {
                gl.glut_solid_cone(0.7, 1.4, 16, 6)
            }
        }
        _ => {
            gl.rotatef(-50.0, 1.0, 0.0, 0.0);
            if wire {
                gl.glut_wire_torus(0.25, 0.6, 12, 24)
            } else {
                gl.glut_solid_torus(0.25, 0.6, 12, 24)
            }
        }
    }
}

fn cell(gl: &mut Gl, k: usize, wire: bool) {
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH) / 4, gl.glut_get(GLUT_WINDOW_HEIGHT) / 2);
    gl.viewport(k as i32 * w, if wire { 0 } else { h }, w, h);
    gl.push_matrix();
    gl.rotatef(25.0, 1.0, 0.0, 0.0);
    gl.rotatef(-35.0 + 20.0 * k as f32, 0.0, 1.0, 0.0);
    if wire {
        gl.color3fv(&COLOURS[k]);
    } else {
        gl.enable(GL_LIGHTING);
        gl.enable(GL_CULL_FACE);
        gl.material_fv(GL_FRONT, GL_DIFFUSE, &COLOURS[k]);
    }
    shape(gl, k, wire);
    gl.disable(GL_LIGHTING);
    gl.disable(GL_CULL_FACE);
    gl.pop_matrix();
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(30.0, f64::from(w / 4) / f64::from((h / 2).max(1)), 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.0, 0.0, 4.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

fn init(gl: &mut Gl) {
    gl.clear_color(0.12, 0.12, 0.16, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_NORMALIZE);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[-2.0, 3.0, 4.0, 0.0]);
    gl.light_fv(GL_LIGHT0, GL_SPECULAR, &[1.0, 1.0, 1.0, 1.0]);
    gl.material_fv(GL_FRONT, GL_SPECULAR, &[0.5, 0.5, 0.5, 1.0]);
    gl.material_f(GL_FRONT, GL_SHININESS, 30.0);
}

fn display(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for k in 0..4 {
        cell(gl, k, false);
        cell(gl, k, true);
    }
    // The plate: lit with the normal set before the cube (0, 0.6, 0.8): the cube's own
    // normals do not stay current.
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH) / 4, gl.glut_get(GLUT_WINDOW_HEIGHT) / 2);
    gl.viewport(w, h, w, h);
    gl.enable(GL_LIGHTING);
    gl.normal3f(0.0, 0.6, 0.8);
    gl.push_matrix();
    gl.translatef(0.0, -0.9, 0.0);
    gl.glut_solid_cube(0.3);
    gl.begin(GL_QUADS);
    gl.vertex3f(-0.9, -0.1, 0.6);
    gl.vertex3f(-0.5, -0.1, 0.6);
    gl.vertex3f(-0.5, 0.1, 0.6);
    gl.vertex3f(-0.9, 0.1, 0.6);
    gl.end();
    gl.pop_matrix();
    gl.disable(GL_LIGHTING);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("GLUT shapes", 640, 320).init(init).reshape(reshape).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
