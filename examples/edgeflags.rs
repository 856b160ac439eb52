//! EdgeFlags.c (tests/reference/pictures), ported line for line: polygons outlined with
//! `polygon_mode(GL_LINE)` and `GL_POINT`, where `edge_flag` and an edge-flag array hide the
//! inner edges of a shape built from triangles, a quad and a polygon (GL 1.1 §2.6.2). Mesa
//! applies the flags to strips too: a strip drawn with the flag false shows nothing in line
//! mode.
//!
//! `cargo run --release --example edgeflags -- --png edgeflags.png`

use gleval::gl::ClientArray;
use gleval::prelude::*;

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(-3.0, 3.0, -3.0, 3.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

/// A hexagon as four triangles whose inner edges are hidden.
fn hexagon(gl: &mut Gl) {
    let v: [[f32; 2]; 6] = [[-0.4, -0.7], [0.4, -0.7], [0.8, 0.0], [0.4, 0.7], [-0.4, 0.7], [-0.8, 0.0]];
    // fan-like triangles (0 1 2) (0 2 3) (0 3 4) (0 4 5): the edges from 0 inward are hidden
    gl.begin(GL_TRIANGLES);
    for k in 1..=4 {
        gl.edge_flag(if k == 1 { GL_TRUE } else { GL_FALSE });
        gl.vertex2fv(&v[0]);
        gl.edge_flag(GL_TRUE);
        gl.vertex2fv(&v[k]);
        gl.edge_flag(if k == 4 { GL_TRUE } else { GL_FALSE });
        gl.vertex2fv(&v[k + 1]);
    }
    gl.end();
    gl.edge_flag(GL_TRUE);
}

fn display(gl: &mut Gl, star: &ClientArray, star_flags: &ClientArray) {
    gl.clear_color(0.1, 0.1, 0.1, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.line_width(2.0);

    gl.color3f(1.0, 0.9, 0.3);
    gl.translatef(-1.6, 1.5, 0.0);
    hexagon(gl);

    gl.color3f(0.3, 1.0, 0.5);
    gl.load_identity();
    gl.translatef(1.5, 1.5, 0.0);
    gl.begin(GL_QUADS);
    gl.edge_flag(GL_TRUE);
    gl.vertex2f(-0.8, -0.8);
    gl.edge_flag(GL_FALSE);
    gl.vertex2f(0.8, -0.8);
    gl.edge_flag(GL_TRUE);
    gl.vertex2f(0.8, 0.8);
    gl.edge_flag(GL_FALSE);
    gl.vertex2f(-0.8, 0.8);
    gl.end();
    gl.edge_flag(GL_TRUE);

    gl.color3f(0.4, 0.7, 1.0);
    gl.load_identity();
    gl.translatef(-1.5, -1.5, 0.0);
    gl.vertex_pointer(2, GL_FLOAT, 0, star);
    gl.edge_flag_pointer(0, star_flags);
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_EDGE_FLAG_ARRAY);
    gl.draw_arrays(GL_POLYGON, 0, 8);
    gl.disable_client_state(GL_EDGE_FLAG_ARRAY);

    gl.color3f(1.0, 0.4, 0.4);
    gl.load_identity();
    gl.translatef(1.5, -1.5, 0.0);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_POINT);
    gl.point_size(6.0);
    gl.edge_flag(GL_FALSE);
    gl.draw_arrays(GL_POLYGON, 0, 8);
    gl.edge_flag(GL_TRUE);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.line_width(1.0);
    gl.color3f(0.8, 0.8, 0.8);
    gl.scalef(0.5, 0.5, 1.0);
    gl.edge_flag(GL_FALSE);
    gl.begin(GL_TRIANGLE_STRIP);
    gl.vertex2f(-1.0, -0.5);
    gl.vertex2f(-1.0, 0.5);
    gl.vertex2f(0.0, -0.5);
    gl.vertex2f(0.0, 0.5);
    gl.end();
    gl.edge_flag(GL_TRUE);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    #[rustfmt::skip]
    let star = ClientArray::new(&[
        0.0f32, 1.0,  0.25, 0.25,  1.0, 0.0,  0.25, -0.25,  0.0, -1.0,  -0.25, -0.25,  -1.0, 0.0,  -0.25, 0.25,
    ]);
    let star_flags = ClientArray::new(&[GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE]);
    App::new("Edge flags", 300, 300).reshape(reshape).display(move |gl| display(gl, &star, &star_flags))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
