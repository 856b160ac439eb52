//! FlatTwoViewports.c (tests/reference/pictures), ported line for line: flat shading, polygon
//! mode, face culling with `glFrontFace(GL_CW)`, colour material and two viewports, on a curled
//! bicubic patch with a colour map and two immediate-mode triangles of opposite winding.
//!
//! `cargo run --release --example flattwoviewports -- --png flattwoviewports.png`

use gleval::prelude::*;

fn viewport(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(38.0, w as f64 / h as f64, 1.0, 50.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(0.5, -7.0, 6.0, 0.0, 0.2, 0.2, 0.0, 0.0, 1.0);
}

fn scene(gl: &mut Gl) {
    #[rustfmt::skip]
    let pts: [[[f32; 3]; 4]; 4] = [ // rows: v (along the curl); columns: u (along x)
        [[-1.5, -1.2, 0.0], [-0.5, -1.2, 0.2], [0.5, -1.2, -0.1], [1.5, -1.2, 0.1]],
        [[-1.5, 2.2, 0.1], [-0.5, 2.2, 0.0], [0.5, 2.2, 0.2], [1.5, 2.2, 0.0]],
        [[-1.5, 1.8, 2.4], [-0.5, 1.9, 2.2], [0.5, 1.8, 2.5], [1.5, 1.9, 2.3]],
        [[-1.5, -0.9, 1.5], [-0.5, -0.8, 1.7], [0.5, -0.9, 1.4], [1.5, -0.8, 1.6]],
    ];
    let colors: [[[f32; 4]; 2]; 2] =
        [[[1.0, 0.2, 0.2, 1.0], [1.0, 0.9, 0.1, 1.0]], [[0.2, 0.4, 1.0, 1.0], [0.1, 0.9, 0.4, 1.0]]];

    gl.normal3f(0.0, 0.0, 1.0);
    gl.color3f(1.0, 1.0, 1.0); // current values, set before any evaluation
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, pts.as_flattened().as_flattened());
    gl.map2f(GL_MAP2_COLOR_4, 0.0, 1.0, 4, 2, 0.0, 1.0, 8, 2, colors.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_MAP2_COLOR_4);
    gl.map_grid2f(8, 0.0, 1.0, 10, 0.0, 1.0);
    gl.eval_mesh2(GL_FILL, 0, 8, 0, 10);
    gl.disable(GL_MAP2_COLOR_4);
    gl.disable(GL_MAP2_VERTEX_3);

    gl.begin(GL_TRIANGLES);
    // clockwise as seen from the eye (which looks along +y)
    gl.color3f(1.0, 0.0, 0.0);
    gl.vertex3f(-2.1, -2.0, -1.3);
    gl.color3f(0.0, 1.0, 0.0);
    gl.vertex3f(-1.3, -2.0, -0.5);
    gl.color3f(0.0, 0.0, 1.0);
    gl.vertex3f(-0.5, -2.0, -1.2);
    // counter-clockwise
    gl.color3f(1.0, 1.0, 0.0);
    gl.vertex3f(0.6, -2.0, -1.3);
    gl.color3f(0.0, 1.0, 1.0);
    gl.vertex3f(2.0, -2.0, -1.2);
    gl.color3f(1.0, 0.0, 1.0);
    gl.vertex3f(1.2, -2.0, -0.5);
    gl.end();
}

fn paint(gl: &mut Gl) {
    gl.clear_color(0.95, 0.95, 0.9, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    let w = gl.glut_get(GLUT_WINDOW_WIDTH) / 2;
    let h = gl.glut_get(GLUT_WINDOW_HEIGHT);
    gl.shade_model(GL_FLAT);

    viewport(gl, 0, 0, w, h);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.disable(GL_CULL_FACE);
    gl.disable(GL_LIGHTING);
    gl.line_width(1.0);
    scene(gl);

    viewport(gl, w, 0, w, h);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_FILL);
    gl.front_face(GL_CW);
    gl.cull_face(GL_BACK);
    gl.enable(GL_CULL_FACE);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[-1.0, -2.0, 3.0, 0.0]); // world coordinates
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);
    gl.enable(GL_COLOR_MATERIAL); // the colours (map and glColor) drive ambient and diffuse
    gl.color_material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    scene(gl);
    gl.disable(GL_COLOR_MATERIAL);
    gl.disable(GL_AUTO_NORMAL);
    gl.disable(GL_LIGHTING);
    gl.disable(GL_CULL_FACE);
    gl.front_face(GL_CCW);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("FlatTwoViewports", 500, 250).display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
