//! Stipple.c (tests/reference/pictures), ported line for line: GL's rasterisation modes on
//! evaluated curves and surfaces. Top left: an evaluated curve drawn with four line stipples,
//! separate stippled `GL_LINES` (each restarts the pattern) and a wide stippled loop around a
//! bar filled through a polygon stipple of diagonal hatching (its rows 20 to 31 empty, so that
//! the pattern shows where the window's row 0 is). Top right: smooth points and lines,
//! blended. Bottom left: a lit surface cut by a clip plane (given under a rotation, kept in eye
//! space), in fog, under stippled quads, a triangle strip and a polygon drawn in `GL_LINE`
//! mode. Bottom right: a filled surface pushed back by polygon offset under its own wire
//! outline, under a smooth stippled line strip, and a smooth line and point without blending.
//!
//! `cargo run --release --example stipple -- --png stipple.png`

// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const CURVE: [[f32; 3]; 4] = [[-1.3, -0.2, 0.0], [-0.5, 1.0, 0.0], [0.5, -1.0, 0.0], [1.3, 0.2, 0.0]];
const FACTORS: [GLint; 4] = [1, 1, 2, 3];
const PATTERNS: [GLushort; 4] = [0x0F0F, 0x1C47, 0xAAAA, 0x00FF];

fn init(gl: &mut Gl) {
    let mut hatch = [0u8; 128];
    for y in 0..32 {
        for x in 0..32 {
            if (x + y) % 8 < 3 && y < 20 {
                hatch[4 * y + x / 8] |= 0x80 >> (x % 8);
            }
        }
    }
    gl.polygon_stipple(&hatch);
    let mut hill = [[[0.0f32; 3]; 4]; 4];
    for u in 0..4 {
        for v in 0..4 {
            hill[u][v][0] = -1.5 + u as f32;
            hill[u][v][1] = -1.5 + v as f32;
            hill[u][v][2] = if (u == 1 || u == 2) && (v == 1 || v == 2) { 1.5 } else { -0.3 };
        }
    }
    gl.clear_color(0.95, 0.95, 0.9, 1.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, CURVE.as_flattened());
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(30, 0.0, 1.0);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, hill.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.map_grid2f(12, 0.0, 1.0, 12, 0.0, 1.0);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_DEPTH_TEST);
}

fn flat_view(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.5, 1.5, -1.5, 1.5, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn surface_view(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32, eye_x: f64) {
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(40.0, f64::from(w) / f64::from(h), 1.0, 20.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.glu_look_at(eye_x, -5.0, 4.0, 0.0, 0.0, 0.2, 0.0, 0.0, 1.0);
}

fn stippled(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    flat_view(gl, x, y, w, h);
    gl.enable(GL_LINE_STIPPLE);
    for i in 0..4 {
        gl.line_stipple(FACTORS[i], PATTERNS[i]);
        let f = i as f32;
        gl.color3f(0.25 * f, 0.1, 0.7 - 0.15 * f);
        gl.push_matrix();
        gl.translatef(0.0, 1.1 - 0.55 * f, 0.0);
        gl.scalef(1.0, 0.35, 1.0);
        gl.eval_mesh1(GL_LINE, 0, 30);
        gl.pop_matrix();
    }
    gl.line_stipple(2, 0x0F0F);
    gl.color3f(0.8, 0.2, 0.1);
    gl.begin(GL_LINES);
    for k in 0..6 {
        let f = k as f32;
        gl.vertex2f(-1.35 + 0.45 * f, -1.0);
        gl.vertex2f(-1.05 + 0.45 * f, -0.7);
    }
    gl.end();
    gl.enable(GL_POLYGON_STIPPLE);
    gl.color3f(0.5, 0.7, 0.3);
    gl.rectf(-1.4, -1.4, 1.4, -1.15);
    gl.disable(GL_POLYGON_STIPPLE);
    gl.line_width(3.0);
    gl.line_stipple(4, 0x3F3F);
    gl.color3f(0.1, 0.5, 0.2);
    gl.begin(GL_LINE_LOOP);
    gl.vertex2f(-1.4, -1.4);
    gl.vertex2f(1.4, -1.4);
    gl.vertex2f(1.4, -1.15);
    gl.vertex2f(-1.4, -1.15);
    gl.end();
    gl.line_width(1.0);
    gl.disable(GL_LINE_STIPPLE);
}

fn smooth(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    flat_view(gl, x, y, w, h);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.enable(GL_POINT_SMOOTH);
    for i in 0..6 {
        let f = i as f32;
        gl.point_size(1.0 + 1.5 * f);
        gl.color3f(0.1, 0.3 + 0.1 * f, 0.6);
        gl.begin(GL_POINTS);
        gl.vertex2f(-1.25 + 0.5 * f, 1.2);
        gl.vertex2f(-1.25 + 0.5 * f + 0.013, 0.8);
        gl.end();
    }
    gl.point_size(9.0);
    gl.color4f(0.9, 0.2, 0.1, 0.4);
    gl.begin(GL_POINTS);
    for i in 0..3 {
        gl.vertex2f(-0.9 + 0.9 * i as f32, -0.8);
    }
    gl.end();
    gl.point_size(1.0);
    gl.disable(GL_POINT_SMOOTH);
    gl.enable(GL_LINE_SMOOTH);
    for i in 0..3 {
        let f = i as f32;
        gl.line_width(1.0 + f);
        gl.color3f(0.7 - 0.2 * f, 0.1, 0.2 + 0.2 * f);
        gl.push_matrix();
        gl.translatef(0.0, 0.1 - 0.5 * f, 0.0);
        gl.scalef(1.0, 0.4, 1.0);
        gl.eval_mesh1(GL_LINE, 0, 30);
        gl.pop_matrix();
    }
    gl.line_width(1.0);
    gl.disable(GL_LINE_SMOOTH);
    gl.disable(GL_BLEND);
}

fn clipped(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    let cut: [GLdouble; 4] = [1.0, 0.0, 0.0, 0.4];
    surface_view(gl, x, y, w, h, 1.5);
    gl.push_matrix();
    gl.rotatef(30.0, 0.0, 0.0, 1.0);
    gl.clip_plane(GL_CLIP_PLANE0, &cut);
    gl.pop_matrix();
    gl.enable(GL_CLIP_PLANE0);
    gl.enable(GL_LIGHTING);
    gl.material_fv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.9, 0.5, 0.1, 1.0]);
    gl.enable(GL_FOG);
    gl.fogi(GL_FOG_MODE, GL_LINEAR as GLint);
    gl.fogf(GL_FOG_START, 4.0);
    gl.fogf(GL_FOG_END, 9.0);
    gl.fogfv(GL_FOG_COLOR, &[0.95, 0.95, 0.9, 1.0]);
    gl.eval_mesh2(GL_FILL, 0, 12, 0, 12);
    gl.disable(GL_FOG);
    gl.disable(GL_LIGHTING);
    gl.disable(GL_CLIP_PLANE0);
    flat_view(gl, x, y, w, h);
    gl.enable(GL_LINE_STIPPLE);
    gl.line_stipple(1, 0x0F0F);
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    gl.color3f(0.3, 0.2, 0.6);
    gl.begin(GL_QUADS);
    gl.vertex2f(-1.39, 0.81);
    gl.vertex2f(-0.89, 0.81);
    gl.vertex2f(-0.89, 1.34);
    gl.vertex2f(-1.39, 1.34);
    gl.vertex2f(-0.79, 0.81);
    gl.vertex2f(-0.29, 0.81);
    gl.vertex2f(-0.29, 1.34);
    gl.vertex2f(-0.79, 1.34);
    gl.end();
    gl.begin(GL_TRIANGLE_STRIP);
    gl.vertex2f(-0.19, 0.81);
    gl.vertex2f(-0.19, 1.34);
    gl.vertex2f(0.31, 0.81);
    gl.vertex2f(0.31, 1.34);
    gl.end();
    gl.begin(GL_POLYGON);
    gl.vertex2f(0.91, 1.34);
    gl.vertex2f(0.61, 1.16);
    gl.vertex2f(0.71, 0.81);
    gl.vertex2f(1.11, 0.81);
    gl.vertex2f(1.21, 1.16);
    gl.end();
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_FILL);
    gl.disable(GL_LINE_STIPPLE);
}

fn outlined(gl: &mut Gl, x: i32, y: i32, w: i32, h: i32) {
    surface_view(gl, x, y, w, h, -1.5);
    gl.enable(GL_LIGHTING);
    gl.material_fv(GL_FRONT_AND_BACK, GL_DIFFUSE, &[0.3, 0.5, 0.9, 1.0]);
    gl.enable(GL_POLYGON_OFFSET_FILL);
    gl.polygon_offset(1.0, 1.0);
    gl.eval_mesh2(GL_FILL, 0, 12, 0, 12);
    gl.disable(GL_POLYGON_OFFSET_FILL);
    gl.disable(GL_LIGHTING);
    gl.color3f(0.0, 0.0, 0.0);
    gl.eval_mesh2(GL_LINE, 0, 12, 0, 12);
    flat_view(gl, x, y, w, h);
    gl.enable(GL_BLEND);
    gl.blend_func(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.enable(GL_LINE_SMOOTH);
    gl.enable(GL_LINE_STIPPLE);
    gl.line_stipple(2, 0x0F0F);
    gl.line_width(2.0);
    gl.color3f(0.6, 0.1, 0.3);
    gl.begin(GL_LINE_STRIP);
    gl.vertex2f(-1.37, 0.79);
    gl.vertex2f(-0.81, 1.35);
    gl.vertex2f(0.93, 0.83);
    gl.end();
    gl.disable(GL_LINE_STIPPLE);
    gl.disable(GL_BLEND);
    gl.line_width(3.0);
    gl.begin(GL_LINES);
    gl.vertex2f(1.01, 0.83);
    gl.vertex2f(1.43, 1.07);
    gl.end();
    gl.line_width(1.0);
    gl.disable(GL_LINE_SMOOTH);
    gl.enable(GL_POINT_SMOOTH);
    gl.point_size(7.0);
    gl.begin(GL_POINTS);
    gl.vertex2f(1.23, 1.23);
    gl.end();
    gl.point_size(1.0);
    gl.disable(GL_POINT_SMOOTH);
}

fn display(gl: &mut Gl) {
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH), gl.glut_get(GLUT_WINDOW_HEIGHT));
    gl.viewport(0, 0, w, h);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    stippled(gl, 0, h / 2, w / 2, h / 2);
    smooth(gl, w / 2, h / 2, w / 2, h / 2);
    clipped(gl, 0, 0, w / 2, h / 2);
    outlined(gl, w / 2, 0, w / 2, h / 2);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("Stipple, smoothing, clip planes, polygon offset", 400, 400)
        .init(init)
        .reshape(|_, _, _| {})
        .display(display)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
