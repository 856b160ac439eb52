//! ColorMap.c (tests/reference/pictures), ported line for line: a `GL_MAP2_COLOR_4` colour map
//! on a bicubic patch (left), and partial `glEvalMesh2` ranges in three modes (right).
//!
//! `cargo run --release --example colormap -- --png colormap.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

fn viewport(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-2.0, 2.0, -2.0, 2.0, -10.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.rotatef(-40.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
}

fn display(gl: &mut Gl) {
    let mut pts = [[[0.0f32; 3]; 4]; 4];
    let colors: [[[f32; 4]; 2]; 2] =
        [[[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 1.0]], [[0.0, 0.0, 1.0, 1.0], [1.0, 1.0, 0.0, 1.0]]];
    for i in 0..4 {
        for j in 0..4 {
            pts[i][j][0] = -1.5 + i as f32;
            pts[i][j][1] = -1.5 + j as f32;
            pts[i][j][2] = if (i + j) % 3 == 0 { 0.8 } else { -0.4 };
        }
    }
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH) / 2, gl.glut_get(GLUT_WINDOW_HEIGHT));
    gl.clear_color(0.0, 0.0, 0.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, pts.as_flattened().as_flattened());
    gl.map2f(GL_MAP2_COLOR_4, 0.0, 1.0, 8, 2, 0.0, 1.0, 4, 2, colors.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_MAP2_COLOR_4);
    gl.map_grid2f(10, 0.0, 1.0, 10, 0.0, 1.0);

    viewport(gl, 0, 0, w, h);
    gl.eval_mesh2(GL_FILL, 0, 10, 0, 10);

    viewport(gl, w, 0, w, h);
    gl.eval_mesh2(GL_FILL, 0, 10, 2, 6);
    gl.line_width(2.0);
    gl.eval_mesh2(GL_LINE, 4, 8, 0, 10);
    gl.point_size(4.0);
    gl.eval_mesh2(GL_POINT, 0, 3, 0, 3);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Colour map and partial meshes", 400, 200).display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
