//! CopyPixels.c (tests/reference/pictures), ported line for line: pixel rectangles copied and
//! zoomed, in the style of the Red Book's image.c: a checkerboard drawn with `draw_pixels`
//! beside a depth-tested triangle and square, then copied with `copy_pixels` at zoom 1, zoomed
//! by 2 and 1.5, mirrored by negative zooms, stretched to the window's edge by a huge zoom,
//! copied over itself, and the scene's depths copied in the raster colour under the depth test.
//!
//! `cargo run --release --example copypixels -- --png copypixels.png`

use gleval::prelude::*;

const CHECK: usize = 64;

fn make_checker() -> Vec<u8> {
    let mut checker = vec![0u8; CHECK * CHECK * 3];
    for i in 0..CHECK {
        for j in 0..CHECK {
            let c = ((i & 8) == 0) ^ ((j & 8) == 0);
            let p = &mut checker[(i * CHECK + j) * 3..][..3];
            p[0] = if c { 255 } else { (4 * i) as u8 };
            p[1] = if c { 255 } else { (4 * j) as u8 };
            p[2] = if c { 64 } else { (255 - 4 * i) as u8 };
        }
    }
    checker
}

fn init(gl: &mut Gl) {
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.clear_color(0.1, 0.1, 0.25, 1.0);
    gl.clear_depth(1.0);
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn scene(gl: &mut Gl, checker: &[u8]) {
    gl.raster_pos2i(8, 8);
    gl.draw_pixels(CHECK as i32, CHECK as i32, GL_RGB, GL_UNSIGNED_BYTE, checker);
    gl.enable(GL_DEPTH_TEST);
    gl.color3f(0.9, 0.2, 0.1);
    gl.begin(GL_TRIANGLES);
    gl.vertex3f(80.25, 10.25, 0.5);
    gl.vertex3f(140.75, 20.25, -0.5);
    gl.vertex3f(100.25, 70.75, 0.0);
    gl.end();
    gl.color3f(0.2, 0.8, 0.3);
    gl.begin(GL_QUADS);
    gl.vertex3f(100.25, 30.25, 0.2);
    gl.vertex3f(135.75, 30.25, 0.2);
    gl.vertex3f(135.75, 65.75, 0.2);
    gl.vertex3f(100.25, 65.75, 0.2);
    gl.end();
    gl.disable(GL_DEPTH_TEST);
}

fn display(gl: &mut Gl, checker: &[u8]) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene(gl, checker);
    // zoom 1: the whole scene to the right
    gl.raster_pos2i(160, 8);
    gl.copy_pixels(0, 0, 150, 80, GL_COLOR);
    // zoom 2 and 1.5
    gl.pixel_zoom(2.0, 2.0);
    gl.raster_pos2i(8, 90);
    gl.copy_pixels(8, 8, 40, 40, GL_COLOR);
    gl.pixel_zoom(1.5, 1.5);
    gl.raster_pos2i(100, 90);
    gl.copy_pixels(80, 8, 60, 60, GL_COLOR);
    // mirrored
    gl.pixel_zoom(-1.0, -1.0);
    gl.raster_pos2i(300, 250);
    gl.copy_pixels(8, 8, 64, 64, GL_COLOR);
    gl.pixel_zoom(-2.0, 1.0);
    gl.raster_pos2i(300, 260);
    gl.copy_pixels(8, 8, 32, 32, GL_COLOR);
    // a huge zoom stretches one column to the window's edge
    gl.pixel_zoom(1.0e6, 1.0);
    gl.raster_pos2i(200, 180);
    gl.copy_pixels(40, 8, 1, 20, GL_COLOR);
    // overlapping: the source is read before it is written
    gl.pixel_zoom(1.0, 1.0);
    gl.raster_pos2i(20, 20);
    gl.copy_pixels(8, 8, 64, 30, GL_COLOR);
    // the scene's depths, in the raster colour, where they pass the depth test
    gl.enable(GL_DEPTH_TEST);
    gl.color3f(1.0, 0.9, 0.2);
    gl.raster_pos3f(160.0, 200.0, 0.9);
    gl.copy_pixels(60, 0, 90, 80, GL_DEPTH);
    gl.disable(GL_DEPTH_TEST);
    gl.pixel_zoom(1.0, 1.0);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let checker = make_checker();
    App::new("Copied and zoomed pixels", 320, 300).init(init).reshape(reshape).display(move |gl| display(gl, &checker))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
