//! TexSurf.c (tests/reference/pictures), ported line for line: a texture-mapped Bezier surface.
//! `map2f` gives `GL_MAP2_VERTEX_3` and `GL_MAP2_TEXTURE_COORD_2` (s and t from 0 to 2, so
//! `GL_REPEAT` shows), `eval_mesh2` draws it in four viewports, one texture environment each:
//! MODULATE (lit, LINEAR, REPEAT), DECAL (NEAREST, CLAMP_TO_EDGE), REPLACE (NEAREST, REPEAT)
//! and BLEND (LINEAR, CLAMP), with two texture objects of procedural images.
//!
//! `cargo run --release --example texsurf -- --png texsurf.png`
// The C program's index loops are kept as written.
#![allow(clippy::needless_range_loop)]

use gleval::prelude::*;

const SIZE: usize = 16;

/// What `display` needs of `init` (globals in the C program).
struct Scene {
    names: [GLuint; 2],
}

/// A `SIZE`×`SIZE` image of `N` bytes a pixel (C's `GLubyte image[SIZE][SIZE][N]`).
type Image<const N: usize> = [[[u8; N]; SIZE]; SIZE];

fn make_images() -> (Image<3>, Image<2>) {
    let mut stripes = [[[0u8; 3]; SIZE]; SIZE];
    let mut checker = [[[0u8; 2]; SIZE]; SIZE];
    for i in 0..SIZE {
        for j in 0..SIZE {
            stripes[i][j][0] = if j < SIZE / 2 { 255 } else { 40 };
            stripes[i][j][1] = (i * 16) as u8;
            stripes[i][j][2] = if (i / 4) % 2 == 1 { 230 } else { 20 };
            let on = ((i / 4) + (j / 4)) % 2 == 1;
            checker[i][j][0] = if on { 255 } else { 60 };
            checker[i][j][1] = if on { 255 } else { 120 };
        }
    }
    (stripes, checker)
}

fn init(gl: &mut Gl) -> Scene {
    let mut ctl = [[[0.0f32; 3]; 4]; 4];
    for u in 0..4 {
        for v in 0..4 {
            ctl[u][v][0] = 2.0 * (u as f32 / 3.0) - 1.0;
            ctl[u][v][1] = 2.0 * (v as f32 / 3.0) - 1.0;
            ctl[u][v][2] = if (u == 1 || u == 2) && (v == 1 || v == 2) { 1.0 } else { -0.3 };
        }
    }
    let texpts = [[[0.0, 0.0], [0.0, 2.0]], [[2.0, 0.0], [2.0, 2.0]]];
    let (stripes, checker) = make_images();
    gl.clear_color(0.1, 0.1, 0.15, 1.0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);
    gl.enable(GL_LIGHT0);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, ctl.as_flattened().as_flattened());
    gl.map2f(GL_MAP2_TEXTURE_COORD_2, 0.0, 1.0, 2, 2, 0.0, 1.0, 4, 2, texpts.as_flattened().as_flattened());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_MAP2_TEXTURE_COORD_2);
    gl.map_grid2f(20, 0.0, 1.0, 20, 0.0, 1.0);

    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    let mut names = [0; 2];
    gl.gen_textures(2, &mut names);
    gl.bind_texture(GL_TEXTURE_2D, names[0]);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB as i32, SIZE as i32, SIZE as i32, 0, GL_RGB, GL_UNSIGNED_BYTE, &stripes);
    gl.bind_texture(GL_TEXTURE_2D, names[1]);
    let la = GL_LUMINANCE_ALPHA;
    gl.tex_image_2d(GL_TEXTURE_2D, 0, la as i32, SIZE as i32, SIZE as i32, 0, la, GL_UNSIGNED_BYTE, &checker);
    gl.enable(GL_TEXTURE_2D);
    Scene { names }
}

fn quadrant(gl: &mut Gl, i: i32, w: i32, h: i32) {
    gl.viewport((i % 2) * w / 2, (i / 2) * h / 2, w / 2, h / 2);
}

fn surface(gl: &mut Gl) {
    gl.push_matrix();
    gl.rotatef(-50.0, 1.0, 0.0, 0.0);
    gl.rotatef(20.0, 0.0, 0.0, 1.0);
    gl.eval_mesh2(GL_FILL, 0, 20, 0, 20);
    gl.pop_matrix();
}

fn texture(gl: &mut Gl, name: GLuint, env: GLenum, filter: GLenum, wrap: GLenum) {
    gl.bind_texture(GL_TEXTURE_2D, name);
    gl.tex_envi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap as i32);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap as i32);
}

fn reshape(gl: &mut Gl, _w: i32, _h: i32) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-1.6, 1.6, -1.6, 1.6, -4.0, 4.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn display(gl: &mut Gl, scene: &Scene) {
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH), gl.glut_get(GLUT_WINDOW_HEIGHT));
    gl.viewport(0, 0, w, h);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    quadrant(gl, 0, w, h);
    gl.enable(GL_LIGHTING);
    texture(gl, scene.names[0], GL_MODULATE, GL_LINEAR, GL_REPEAT);
    surface(gl);
    gl.disable(GL_LIGHTING);

    quadrant(gl, 1, w, h);
    gl.color3f(1.0, 0.6, 0.2);
    texture(gl, scene.names[0], GL_DECAL, GL_NEAREST, GL_CLAMP_TO_EDGE);
    surface(gl);

    quadrant(gl, 2, w, h);
    texture(gl, scene.names[1], GL_REPLACE, GL_NEAREST, GL_REPEAT);
    surface(gl);

    quadrant(gl, 3, w, h);
    gl.color3f(0.2, 0.4, 1.0);
    gl.tex_envfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, &[1.0, 0.9, 0.2, 1.0]);
    texture(gl, scene.names[1], GL_BLEND, GL_LINEAR, GL_CLAMP);
    surface(gl);
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    let scene = std::rc::Rc::new(std::cell::RefCell::new(None));
    let at_display = scene.clone();
    App::new("Textured Bezier surface", 400, 400)
        .init(move |gl| *scene.borrow_mut() = Some(init(gl)))
        .reshape(reshape)
        .display(move |gl| {
            if let Some(scene) = at_display.borrow().as_ref() {
                display(gl, scene);
            }
        })
}

#[allow(dead_code)]
fn main() {
    app().run();
}
