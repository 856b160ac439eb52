//! Labels.c (tests/reference/pictures), ported line for line: text and images at the raster
//! position. A Bezier curve (`map1f`/`eval_mesh1`) whose control points are labelled with
//! `raster_pos2f` + `glut_bitmap_character` in four GLUT fonts, a title whose colour is the one
//! current at `raster_pos2f` (not the later `color3f`), a right-aligned caption
//! (`glut_bitmap_length` and a zero-sized `bitmap` that moves the raster position back), a label
//! whose raster position is clipped (drawn nowhere), a `draw_pixels` gradient (RGB rows padded to
//! the default alignment of 4) and a luminance checker (alignment 1), and a hand-made `bitmap`
//! arrow (LSB first, rows padded to 4) compiled into a display list and called three times.
//!
//! `cargo run --release --example labels -- --png labels.png`

use gleval::prelude::*;
use std::cell::Cell;
use std::rc::Rc;

const CTRL: [[f32; 3]; 4] = [[-3.2, -2.0, 0.0], [-1.5, 2.6, 0.0], [1.2, -2.6, 0.0], [3.0, 1.8, 0.0]];

fn label(gl: &mut Gl, font: GlutBitmapFont, s: &str) {
    for c in s.bytes() {
        gl.glut_bitmap_character(font, c);
    }
}

fn init(gl: &mut Gl, arrow_list: &Cell<GLuint>) {
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, CTRL.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(40, 0.0, 1.0);

    // A 16 x 12 arrow pointing right: a shaft and a triangular head.
    let mut arrow = [[0u8; 4]; 12];
    for j in 0..12 {
        for i in 0..16 {
            let shaft = i < 9 && (4..8).contains(&j);
            let d: i32 = 2 * j - 11;
            let head = i >= 8 && d.abs() < 2 * (15 - i);
            if shaft || head {
                arrow[j as usize][(i / 8) as usize] |= 1 << (i % 8);
            }
        }
    }

    arrow_list.set(gl.gen_lists(1));
    gl.pixel_storei(GL_UNPACK_LSB_FIRST, GL_TRUE.into());
    gl.new_list(arrow_list.get(), GL_COMPILE);
    gl.bitmap(16, 12, 0.0, 6.0, 20.0, 0.0, arrow.as_flattened());
    gl.end_list();
    gl.pixel_storei(GL_UNPACK_LSB_FIRST, GL_FALSE.into());
}

/// 21 x 16 RGB pixels: 63 bytes a row, padded to 64.
fn gradient() -> [[u8; 64]; 16] {
    let mut gradient = [[0u8; 64]; 16];
    for (j, row) in gradient.iter_mut().enumerate() {
        for i in 0..21 {
            row[3 * i] = (12 * i) as u8;
            row[3 * i + 1] = (16 * j) as u8;
            row[3 * i + 2] = 200;
        }
    }
    gradient
}

fn checker() -> [[u8; 8]; 8] {
    let mut checker = [[0u8; 8]; 8];
    for (j, row) in checker.iter_mut().enumerate() {
        for (i, texel) in row.iter_mut().enumerate() {
            *texel = if (i / 2 + j / 2) % 2 == 1 { 255 } else { 60 };
        }
    }
    checker
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-4.0, 4.0, -4.0, 4.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn display(gl: &mut Gl, arrow_list: GLuint) {
    let names = ["P0", "P1", "P2", "P3"];
    let fonts = [GLUT_BITMAP_HELVETICA_18, GLUT_BITMAP_TIMES_ROMAN_24, GLUT_BITMAP_9_BY_15, GLUT_BITMAP_8_BY_13];
    gl.clear(GL_COLOR_BUFFER_BIT);

    gl.color3f(0.5, 0.5, 0.6);
    gl.begin(GL_LINE_STRIP);
    for p in &CTRL {
        gl.vertex3fv(p);
    }
    gl.end();
    gl.color3f(0.3, 0.9, 1.0);
    gl.line_width(2.0);
    gl.eval_mesh1(GL_LINE, 0, 40);
    gl.line_width(1.0);
    gl.point_size(6.0);
    gl.color3f(1.0, 0.3, 0.2);
    gl.begin(GL_POINTS);
    for p in &CTRL {
        gl.vertex3fv(p);
    }
    gl.end();

    gl.color3f(1.0, 1.0, 0.6);
    for i in 0..4 {
        gl.raster_pos2f(CTRL[i][0] + 0.15, CTRL[i][1] + 0.15);
        label(gl, fonts[i], names[i]);
    }

    gl.color3f(1.0, 0.85, 0.2);
    gl.raster_pos2f(-3.8, 3.4);
    gl.color3f(1.0, 0.0, 0.0); // too late: the raster colour was taken at raster_pos2f
    label(gl, GLUT_BITMAP_TIMES_ROMAN_24, "Bezier curve");
    gl.color3f(0.8, 0.8, 0.8);
    gl.raster_pos2f(-3.8, 3.0);
    label(gl, GLUT_BITMAP_HELVETICA_12, "glMap1f + glEvalMesh1, labels by glutBitmapCharacter");

    let caption = "right-aligned (Helvetica 10)";
    gl.color3f(0.6, 1.0, 0.6);
    gl.raster_pos2f(3.8, -3.8);
    gl.bitmap(0, 0, 0.0, 0.0, -(gl.glut_bitmap_length(GLUT_BITMAP_HELVETICA_10, caption) as GLfloat), 0.0, &[]);
    label(gl, GLUT_BITMAP_HELVETICA_10, caption);

    gl.raster_pos2f(4.5, 0.0); // outside the clip volume: the label is not drawn
    label(gl, GLUT_BITMAP_9_BY_15, "hidden");

    gl.color3f(1.0, 1.0, 1.0);
    gl.raster_pos2f(-3.8, -3.5);
    gl.draw_pixels(21, 16, GL_RGB, GL_UNSIGNED_BYTE, gradient().as_flattened());
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.raster_pos2f(-3.2, -3.5);
    gl.draw_pixels(8, 8, GL_LUMINANCE, GL_UNSIGNED_BYTE, checker().as_flattened());
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 4);
    gl.raster_pos2f(-3.8, -3.0);
    label(gl, GLUT_BITMAP_TIMES_ROMAN_10, "glDrawPixels");

    gl.color3f(1.0, 0.5, 1.0);
    gl.raster_pos2f(0.5, 2.8);
    for _ in 0..3 {
        gl.call_list(arrow_list);
    }
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let arrow_list = Rc::new(Cell::new(0));
    let at_display = arrow_list.clone();
    App::new("Labels", 400, 400)
        .init(move |gl| init(gl, &arrow_list))
        .reshape(reshape)
        .display(move |gl| display(gl, at_display.get()))
}

#[allow(dead_code)]
fn main() {
    app().run();
}
