//! PixelMap.c (tests/reference/pictures), ported line for line: the pixel transfer on
//! `draw_pixels`, `copy_pixels` and `glReadPixels`: a grey and a colour ramp drawn plainly;
//! through scale and bias; through `GL_MAP_COLOR` with an inverting, a posterising and a
//! threshold map; a colour-index image drawn through an I_TO_R/G/B palette with an index
//! offset; a copy through the transfer; a rectangle read back under a bias and drawn again.
//!
//! `cargo run --release --example pixelmap -- --png pixelmap.png`

use gleval::prelude::*;

const W: usize = 128;
const H: usize = 16;

struct Images {
    grey: Vec<u8>,
    colors: Vec<u8>,
    indices: Vec<u8>,
}

fn make_images() -> Images {
    let mut images = Images { grey: vec![0; W * H], colors: vec![0; W * H * 3], indices: vec![0; W * H] };
    for j in 0..H {
        for i in 0..W {
            images.grey[j * W + i] = (2 * i) as u8;
            let c = &mut images.colors[(j * W + i) * 3..][..3];
            c[0] = (2 * i) as u8;
            c[1] = (16 * j) as u8;
            c[2] = (255 - 2 * i) as u8;
            images.indices[j * W + i] = (i / 16) as u8;
        }
    }
    images
}

fn init(gl: &mut Gl) {
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.pixel_storei(GL_PACK_ALIGNMENT, 1);
    gl.clear_color(0.3, 0.3, 0.3, 1.0);
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn both(gl: &mut Gl, images: &Images, y: i32) {
    gl.raster_pos2i(8, y);
    gl.draw_pixels(W as i32, H as i32, GL_LUMINANCE, GL_UNSIGNED_BYTE, &images.grey);
    gl.raster_pos2i(144, y);
    gl.draw_pixels(W as i32, H as i32, GL_RGB, GL_UNSIGNED_BYTE, &images.colors);
}

fn display(gl: &mut Gl, images: &Images) {
    let invert = [1.0f32, 0.0];
    let steps = [0.0f32, 0.33, 0.66, 1.0];
    let threshold = [0.1f32, 0.9];
    let identity = [0.0f32, 1.0];
    let pal_r = [1.0f32, 1.0, 1.0, 0.0, 0.0, 0.5, 0.2, 0.9];
    let pal_g = [0.0f32, 0.5, 1.0, 1.0, 0.0, 0.0, 0.8, 0.9];
    let pal_b = [0u16, 0, 0, 0, 65535, 32768, 16384, 65535];
    let mut back = vec![0u8; W * H * 3];
    gl.clear(GL_COLOR_BUFFER_BIT);
    both(gl, images, 8);

    gl.pixel_transferf(GL_RED_SCALE, 0.5);
    gl.pixel_transferf(GL_GREEN_BIAS, 0.25);
    gl.pixel_transferf(GL_BLUE_SCALE, -1.0);
    gl.pixel_transferf(GL_BLUE_BIAS, 1.0);
    both(gl, images, 32);
    gl.pixel_transferf(GL_RED_SCALE, 1.0);
    gl.pixel_transferf(GL_GREEN_BIAS, 0.0);
    gl.pixel_transferf(GL_BLUE_SCALE, 1.0);
    gl.pixel_transferf(GL_BLUE_BIAS, 0.0);

    gl.pixel_transferi(GL_MAP_COLOR, GL_TRUE as i32);
    gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 2, &invert);
    gl.pixel_mapfv(GL_PIXEL_MAP_G_TO_G, 2, &invert);
    gl.pixel_mapfv(GL_PIXEL_MAP_B_TO_B, 2, &invert);
    gl.pixel_mapfv(GL_PIXEL_MAP_A_TO_A, 2, &identity);
    both(gl, images, 56);
    gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 4, &steps);
    gl.pixel_mapfv(GL_PIXEL_MAP_G_TO_G, 4, &steps);
    gl.pixel_mapfv(GL_PIXEL_MAP_B_TO_B, 4, &steps);
    both(gl, images, 80);
    gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 2, &threshold);
    gl.pixel_mapfv(GL_PIXEL_MAP_G_TO_G, 2, &identity);
    gl.pixel_mapfv(GL_PIXEL_MAP_B_TO_B, 2, &threshold);
    both(gl, images, 104);
    gl.pixel_transferi(GL_MAP_COLOR, GL_FALSE as i32);

    // a palette: indices 0..7 shifted by one through I_TO_R/G/B
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_R, 8, &pal_r);
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_G, 8, &pal_g);
    gl.pixel_mapusv(GL_PIXEL_MAP_I_TO_B, 8, &pal_b);
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_A, 1, &identity[1..]);
    gl.pixel_transferi(GL_INDEX_OFFSET, 1);
    gl.raster_pos2i(8, 128);
    gl.draw_pixels(W as i32, H as i32, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, &images.indices);
    gl.pixel_transferi(GL_INDEX_OFFSET, 0);

    // a copy through the transfer
    gl.pixel_transferf(GL_RED_BIAS, -0.5);
    gl.pixel_transferf(GL_GREEN_SCALE, 2.0);
    gl.raster_pos2i(144, 128);
    gl.copy_pixels(144, 8, W as i32, H as i32, GL_COLOR);
    gl.pixel_transferf(GL_RED_BIAS, 0.0);
    gl.pixel_transferf(GL_GREEN_SCALE, 1.0);

    // a read under a bias, drawn back plainly
    gl.pixel_transferf(GL_BLUE_BIAS, 0.5);
    gl.read_window_pixels((8, 8), (W as i32, H as i32), GL_RGB, GL_UNSIGNED_BYTE, &mut back);
    gl.pixel_transferf(GL_BLUE_BIAS, 0.0);
    gl.raster_pos2i(8, 152);
    gl.draw_pixels(W as i32, H as i32, GL_RGB, GL_UNSIGNED_BYTE, &back);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let images = make_images();
    App::new("Pixel maps and transfer", 280, 176).init(init).reshape(reshape).display(move |gl| display(gl, &images))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
