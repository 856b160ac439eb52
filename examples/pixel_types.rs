//! PixelTypes.c (tests/reference/pictures), ported line for line: the pixel path past bytes
//! and floats. Bottom row: one colour ramp drawn from seven client types (`GL_BYTE`,
//! `GL_SHORT`, `GL_UNSIGNED_SHORT`, `GL_INT`, `GL_UNSIGNED_INT`, and the packed
//! `GL_UNSIGNED_BYTE_3_3_2` and `GL_BGRA` `GL_UNSIGNED_INT_8_8_8_8_REV`). Then a depth ramp
//! drawn with `draw_pixels` and a green quad tested against it; a checker of stencil indices
//! drawn with `draw_pixels` and a blue quad through the stencil test; a grey ramp drawn with a
//! texture bound, coloured by the texel at the raster position's coordinates; an intensity
//! texture under `GL_MODULATE` and `GL_BLEND`, blended over the background; a texture given
//! with a one-texel border (which Mesa strips) under `GL_CLAMP` and a linear filter; and a
//! colour-index bitmap made a texture through the I_TO_R/G/B/A maps.
//!
//! `cargo run --release --example pixel_types -- --png pixeltypes.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const W: usize = 32;
const H: usize = 16;

/// The C program's arrays, as the bytes `glDrawPixels` reads (native byte order).
struct Images {
    bytes: Vec<u8>,
    shorts: Vec<u8>,
    ushorts: Vec<u8>,
    ints: Vec<u8>,
    uints: Vec<u8>,
    packed332: Vec<u8>,
    packed8888: Vec<u8>,
    depths: Vec<u8>,
    stencils: Vec<u8>,
    greys: Vec<u8>,
}

fn init(gl: &mut Gl) {
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.clear_color(0.3, 0.3, 0.3, 1.0);
}

fn make_images() -> Images {
    let mut m = Images {
        bytes: Vec::new(),
        shorts: Vec::new(),
        ushorts: Vec::new(),
        ints: Vec::new(),
        uints: Vec::new(),
        packed332: Vec::new(),
        packed8888: Vec::new(),
        depths: Vec::new(),
        stencils: Vec::new(),
        greys: Vec::new(),
    };
    for j in 0..H {
        for i in 0..W {
            let c = [i as f64 / 31.0, j as f64 / 15.0, 0.5];
            for k in 0..3 {
                m.bytes.push((c[k] * 127.0 + 0.5) as i8 as u8);
                m.shorts.extend(((c[k] * 32767.0 + 0.5) as i16).to_ne_bytes());
                m.ushorts.extend(((c[k] * 65535.0 + 0.5) as u16).to_ne_bytes());
                m.ints.extend(((c[k] * 2147483647.0) as i32).to_ne_bytes());
                m.uints.extend(((c[k] * 4294967295.0) as u32).to_ne_bytes());
            }
            m.packed332.push((((i * 7 / 31) << 5) | ((j * 7 / 15) << 2) | 2) as u8);
            let p = 255u32 << 24 | ((i * 255 / 31) as u32) << 16 | ((j * 17) as u32) << 8 | 128;
            m.packed8888.extend(p.to_ne_bytes());
        }
    }
    for j in 0..H {
        for i in 0..96 {
            m.depths.extend((i as f32 / 95.0).to_ne_bytes());
            m.stencils.push(((i / 8 + j / 8) % 2) as u8);
        }
        for i in 0..64 {
            m.greys.push((4 * i) as u8);
        }
    }
    m
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn quad(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    gl.begin(GL_QUADS);
    gl.tex_coord2f(0.0, 0.0);
    gl.vertex2i(x, y);
    gl.tex_coord2f(1.0, 0.0);
    gl.vertex2i(x + w, y);
    gl.tex_coord2f(1.0, 1.0);
    gl.vertex2i(x + w, y + h);
    gl.tex_coord2f(0.0, 1.0);
    gl.vertex2i(x, y + h);
    gl.end();
}

fn types(gl: &mut Gl, m: &Images) {
    let (w, h) = (W as i32, H as i32);
    gl.raster_pos2i(8, 8);
    gl.draw_pixels(w, h, GL_RGB, GL_BYTE, &m.bytes);
    gl.raster_pos2i(44, 8);
    gl.draw_pixels(w, h, GL_RGB, GL_SHORT, &m.shorts);
    gl.raster_pos2i(80, 8);
    gl.draw_pixels(w, h, GL_RGB, GL_UNSIGNED_SHORT, &m.ushorts);
    gl.raster_pos2i(116, 8);
    gl.draw_pixels(w, h, GL_RGB, GL_INT, &m.ints);
    gl.raster_pos2i(152, 8);
    gl.draw_pixels(w, h, GL_RGB, GL_UNSIGNED_INT, &m.uints);
    gl.raster_pos2i(188, 8);
    gl.draw_pixels(w, h, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &m.packed332);
    gl.raster_pos2i(224, 8);
    gl.draw_pixels(w, h, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, &m.packed8888);
}

fn depth_and_stencil(gl: &mut Gl, m: &Images) {
    gl.enable(GL_DEPTH_TEST);
    gl.color3f(1.0, 0.0, 0.0);
    gl.raster_pos2i(8, 32);
    gl.draw_pixels(96, H as i32, GL_DEPTH_COMPONENT, GL_FLOAT, &m.depths);
    gl.color3f(0.0, 1.0, 0.0);
    quad(gl, 8, 32, 96, H as i32);
    gl.disable(GL_DEPTH_TEST);

    gl.raster_pos2i(140, 32);
    gl.draw_pixels(96, H as i32, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &m.stencils);
    gl.enable(GL_STENCIL_TEST);
    gl.stencil_func(GL_EQUAL, 1, 0xFF);
    gl.color3f(0.2, 0.4, 1.0);
    quad(gl, 140, 32, 96, H as i32);
    gl.disable(GL_STENCIL_TEST);
}

fn textured_pixels(gl: &mut Gl, m: &Images) {
    let four: [u8; 16] = [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255];
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as i32, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, &four);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    gl.enable(GL_TEXTURE_2D);
    gl.color3f(1.0, 1.0, 1.0);
    gl.tex_coord2f(0.75, 0.25);
    gl.raster_pos2i(8, 56);
    gl.draw_pixels(64, H as i32, GL_LUMINANCE, GL_UNSIGNED_BYTE, &m.greys);
    gl.tex_coord2f(0.25, 0.75);
    gl.raster_pos2i(80, 56);
    gl.draw_pixels(64, H as i32, GL_LUMINANCE, GL_UNSIGNED_BYTE, &m.greys);
    gl.disable(GL_TEXTURE_2D);
}

fn intensity(gl: &mut Gl) {
    let mut ramp = [0u8; 16];
    let env = [1.0f32, 0.5, 0.0, 1.0];
    for j in 0..4 {
        for i in 0..4 {
            ramp[j * 4 + i] = (i * 80 + j * 5) as u8;
        }
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_INTENSITY as i32, 4, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, &ramp);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &env);
    gl.enable(GL_TEXTURE_2D);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.color4f(0.0, 0.4, 1.0, 1.0);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as i32);
    quad(gl, 8, 80, 64, H as i32);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND as i32);
    quad(gl, 80, 80, 64, H as i32);
    gl.disable(GL_BLEND);
    gl.disable(GL_TEXTURE_2D);
}

fn border_and_bitmap(gl: &mut Gl) {
    let mut bordered = [0u8; 6 * 6 * 4];
    let yellow = [1.0f32, 1.0, 0.0, 1.0];
    let bits: [u8; 8] = [0xF0, 0xF0, 0xF0, 0xF0, 0x0F, 0x0F, 0x0F, 0x0F];
    let (to_r, to_g, to_b, to_a) = ([0.1f32, 1.0], [0.6f32, 0.2], [0.3f32, 0.8], [1.0f32, 1.0]);
    for j in 0..6 {
        for i in 0..6 {
            let edge = i == 0 || j == 0 || i == 5 || j == 5;
            let t = &mut bordered[(j * 6 + i) * 4..][..4];
            t[0] = if edge { 255 } else { (60 * i) as u8 };
            t[1] = if edge { 0 } else { (60 * j) as u8 };
            t[2] = if edge { 0 } else { 200 };
            t[3] = 255;
        }
    }
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP as i32);
    gl.tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &yellow);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as i32, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, &bordered);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as i32);
    gl.enable(GL_TEXTURE_2D);
    quad(gl, 8, 104, 64, 48);

    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_R, 2, &to_r);
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_G, 2, &to_g);
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_B, 2, &to_b);
    gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_A, 2, &to_a);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST as i32);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as i32, 8, 8, 0, GL_COLOR_INDEX, GL_BITMAP, &bits);
    quad(gl, 80, 104, 64, 48);
    gl.disable(GL_TEXTURE_2D);
}

fn display(gl: &mut Gl, m: &Images) {
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    types(gl, m);
    depth_and_stencil(gl, m);
    textured_pixels(gl, m);
    intensity(gl);
    border_and_bitmap(gl);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let images = make_images();
    App::new("Pixel types", 264, 160)
        .init_display_mode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH | GLUT_STENCIL)
        .init(init)
        .reshape(reshape)
        .display(move |gl| display(gl, &images))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
