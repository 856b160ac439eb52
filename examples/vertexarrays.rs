//! VertexArrays.c (tests/reference/pictures), ported line for line: small meshes from client
//! vertex arrays, one cell per `interleaved_arrays` format (all 14, with GL's default stride,
//! drawn as quads through `draw_elements` with `GLubyte` indices), then separate arrays through
//! `draw_elements` with `GLushort` and `GLuint` indices and `draw_arrays` with padded strides.
//! Normals light the N3F cells; texture coordinates pick a checker texture's squares.
//!
//! The C program's static arrays are [`ClientArray`]s: the interleaved blocks mix bytes and
//! floats, so they are built as bytes, as C's `memcpy` builds them.
//!
//! `cargo run --release --example vertexarrays -- --png vertexarrays.png`
#![allow(clippy::needless_range_loop)]

use gleval::gl::ClientArray;
use gleval::prelude::*;

/// tex, colour (0, 3 = 3f, 4 = 4f, 5 = 4ub), normal, vertex.
struct Format {
    name: GLenum,
    tex: usize,
    color: usize,
    normal: bool,
    vertex: usize,
}

const fn f(name: GLenum, tex: usize, color: usize, normal: bool, vertex: usize) -> Format {
    Format { name, tex, color, normal, vertex }
}

const FORMATS: [Format; 14] = [
    f(GL_V2F, 0, 0, false, 2),
    f(GL_V3F, 0, 0, false, 3),
    f(GL_C4UB_V2F, 0, 5, false, 2),
    f(GL_C4UB_V3F, 0, 5, false, 3),
    f(GL_C3F_V3F, 0, 3, false, 3),
    f(GL_N3F_V3F, 0, 0, true, 3),
    f(GL_C4F_N3F_V3F, 0, 4, true, 3),
    f(GL_T2F_V3F, 2, 0, false, 3),
    f(GL_T4F_V4F, 4, 0, false, 4),
    f(GL_T2F_C4UB_V3F, 2, 5, false, 3),
    f(GL_T2F_C3F_V3F, 2, 3, false, 3),
    f(GL_T2F_N3F_V3F, 2, 0, true, 3),
    f(GL_T2F_C4F_N3F_V3F, 2, 4, true, 3),
    f(GL_T4F_C4F_N3F_V4F, 4, 4, true, 4),
];

/// The arrays `init` fills.
struct Arrays {
    blocks: Vec<ClientArray>,
    quads: Vec<GLubyte>,
    triangles: Vec<GLushort>,
    strip: Vec<GLuint>,
    positions: ClientArray,
    colors: ClientArray,
    padded: ClientArray,
}

fn put(p: &mut Vec<u8>, v: &[f32]) {
    p.extend(v.iter().flat_map(|x| x.to_ne_bytes()));
}

/// Grid vertex (i, j) of a 4 × 3 grid in the unit cell.
fn grid(i: usize, j: usize) -> (f32, f32) {
    let (i, j) = (i as f32, j as f32);
    (0.12 + 0.76 * i / 3.0, 0.12 + 0.76 * j / 2.0 + 0.06 * (1.7 * i + 2.3 * j).sin())
}

fn init(gl: &mut Gl) -> Arrays {
    let mut checker = [[[0u8; 4]; 8]; 8];
    for s in 0..8 {
        for t in 0..8 {
            let c = if (s + t) & 1 == 1 { 255 } else { 60 };
            checker[t][s] = [c, c, 255, 255];
        }
    }
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let texels = checker.as_flattened().as_flattened();
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as GLint, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as GLint);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as GLint);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as GLint);
    gl.enable(GL_LIGHT0);
    gl.light_fv(GL_LIGHT0, GL_POSITION, &[0.3, 0.5, 1.0, 0.0]);
    gl.clear_color(0.15, 0.15, 0.15, 1.0);

    let mut blocks = Vec::new();
    for (k, format) in FORMATS.iter().enumerate() {
        let mut p = Vec::new();
        for j in 0..3 {
            for i in 0..4 {
                let (x, y) = grid(i, j);
                let w = if format.vertex == 4 { 2.0 } else { 1.0 };
                let tex = [(0.05 + 0.3 * i as f32) * w, (0.05 + 0.45 * j as f32) * w, 0.0, w];
                let rgba = [i as f32 / 3.0, j as f32 / 2.0, 0.3 + 0.1 * k as f32 / 2.0, 1.0];
                let rgba8 = [(255.0 * rgba[0]) as u8, (255.0 * rgba[1]) as u8, (255.0 * rgba[2]) as u8, 255];
                let n = [0.6 * (2.0 * i as f32).sin(), 0.6 * (3.0 * j as f32).cos(), 0.8];
                let v = [x * w, y * w, 0.0, w];
                put(&mut p, &tex[..format.tex]);
                match format.color {
                    5 => p.extend(rgba8),
                    c => put(&mut p, &rgba[..c]),
                }
                if format.normal {
                    put(&mut p, &n);
                }
                put(&mut p, &v[..format.vertex]);
            }
        }
        blocks.push(ClientArray::from_bytes(p));
    }
    let (mut quads, mut triangles, mut strip) = (Vec::new(), Vec::new(), Vec::new());
    for j in 0..2 {
        for i in 0..3 {
            let a = j * 4 + i;
            quads.extend([a, a + 1, a + 5, a + 4].map(|x| x as GLubyte));
            triangles.extend([a, a + 1, a + 5, a, a + 5, a + 4].map(|x| x as GLushort));
        }
    }
    for i in 0..4 {
        strip.extend([4 + i, i]);
    }
    let (mut positions, mut padded, mut colors) = (Vec::new(), Vec::new(), Vec::new());
    for j in 0..3 {
        for i in 0..4 {
            let (x, y) = grid(i, j);
            positions.extend([x, y, 0.0]);
            padded.extend([x, y, 0.0, 99.0, 99.0]);
            colors.extend([(80 * i) as u8, 200, (120 * j) as u8, 255]);
        }
    }
    Arrays {
        blocks,
        quads,
        triangles,
        strip,
        positions: ClientArray::new(&positions),
        colors: ClientArray::new(&colors),
        padded: ClientArray::new(&padded),
    }
}

fn reshape(gl: &mut Gl, w: i32, h: i32) {
    gl.viewport(0, 0, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, 4.0, 0.0, 4.0, -1.0, 1.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn cell(gl: &mut Gl, k: usize) {
    gl.load_identity();
    gl.translatef((k % 4) as f32, (3 - k / 4) as f32, 0.0);
}

fn display(gl: &mut Gl, a: &Arrays) {
    gl.clear(GL_COLOR_BUFFER_BIT);
    for (k, format) in FORMATS.iter().enumerate() {
        cell(gl, k);
        gl.color3f(0.9, 0.8, 0.5);
        if format.normal && format.color == 0 {
            gl.enable(GL_LIGHTING);
        }
        if format.tex > 0 {
            gl.enable(GL_TEXTURE_2D);
        }
        gl.interleaved_arrays(format.name, 0, &a.blocks[k]);
        gl.draw_elements(GL_QUADS, 24, GL_UNSIGNED_BYTE, &a.quads);
        gl.disable(GL_LIGHTING);
        gl.disable(GL_TEXTURE_2D);
    }
    gl.disable_client_state(GL_TEXTURE_COORD_ARRAY);
    gl.disable_client_state(GL_NORMAL_ARRAY);
    gl.vertex_pointer(3, GL_FLOAT, 0, &a.positions);
    gl.color_pointer(4, GL_UNSIGNED_BYTE, 0, &a.colors);
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    cell(gl, 14);
    gl.draw_elements(GL_TRIANGLES, 36, GL_UNSIGNED_SHORT, &a.triangles);
    cell(gl, 15);
    gl.push_matrix();
    gl.translatef(0.0, 0.45, 0.0);
    gl.scalef(1.0, 0.5, 1.0);
    gl.draw_elements(GL_TRIANGLE_STRIP, 8, GL_UNSIGNED_INT, &a.strip);
    gl.pop_matrix();
    gl.disable_client_state(GL_COLOR_ARRAY);
    gl.color3f(1.0, 0.5, 0.2);
    gl.vertex_pointer(3, GL_FLOAT, 5 * 4, &a.padded);
    gl.scalef(1.0, 0.45, 1.0);
    gl.point_size(4.0);
    gl.draw_arrays(GL_POINTS, 0, 12);
    gl.draw_arrays(GL_LINE_LOOP, 0, 4);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let arrays = std::rc::Rc::new(std::cell::RefCell::new(None));
    let at_display = arrays.clone();
    App::new("Vertex arrays", 400, 400).init(move |gl| *arrays.borrow_mut() = Some(init(gl))).reshape(reshape).display(
        move |gl| {
            if let Some(a) = at_display.borrow().as_ref() {
                display(gl, a);
            }
        },
    )
}

#[allow(dead_code)]
fn main() {
    app().run();
}
