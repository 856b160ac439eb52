//! GL 1.5's occlusion queries counted through a context's reader on the CPU rasteriser (as the
//! C ABI's OSMesa and GLX contexts count them; `capi/tests/occlusion.c` compares those with
//! Mesa's): exact counts of pixel-aligned squares by GL's rasterisation rules, the depth test's
//! share, draws outside begin and end not counted, a query open across frames adding each
//! frame's part, and no count without a reader.

use gleval::prelude::*;
use gleval::render::soft;

fn quad(gl: &mut Gl, s: f32, z: f32) {
    gl.begin(GL_QUADS);
    for (x, y) in [(-s, -s), (s, -s), (s, s), (-s, s)] {
        gl.vertex3f(x, y, z);
    }
    gl.end();
}

fn counted(gl: &mut Gl, id: GLuint) -> GLuint {
    let mut r = [0];
    gl.get_query_objectuiv(id, GL_QUERY_RESULT, &mut r);
    r[0]
}

#[test]
fn queries_count_the_samples_that_pass() {
    let mut gl = Gl::new(64, 64);
    gl.set_window_reader(|frame, w, h| Some(soft::render_window(frame, w, h)));
    let mut q = [0; 3];
    gl.gen_queries(3, &mut q);
    gl.begin_query(GL_SAMPLES_PASSED, q[0]);
    quad(&mut gl, 0.5, 0.0);
    gl.end_query(GL_SAMPLES_PASSED);
    quad(&mut gl, 1.0, 0.0); // after the end
    assert_eq!(counted(&mut gl, q[0]), 32 * 32);
    gl.enable(GL_DEPTH_TEST);
    gl.clear(GL_DEPTH_BUFFER_BIT);
    quad(&mut gl, 0.5, 0.0);
    gl.begin_query(GL_SAMPLES_PASSED, q[1]);
    quad(&mut gl, 0.75, 0.5);
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(counted(&mut gl, q[1]), 48 * 48 - 32 * 32);
    assert_eq!(counted(&mut gl, q[0]), 32 * 32, "asked again: the same count");
    // Open across two frames: each frame's part, the second drawn on a fresh window here.
    gl.disable(GL_DEPTH_TEST);
    gl.begin_query(GL_SAMPLES_PASSED, q[2]);
    quad(&mut gl, 0.5, 0.0);
    let _ = gl.take_frame();
    quad(&mut gl, 0.25, 0.0);
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(counted(&mut gl, q[2]), 32 * 32 + 16 * 16);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn without_a_reader_nothing_is_counted() {
    let mut gl = Gl::new(8, 8);
    gl.begin_query(GL_SAMPLES_PASSED, 1);
    quad(&mut gl, 0.5, 0.0);
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(counted(&mut gl, 1), 0);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn a_query_deleted_while_active_stops_counting() {
    let mut gl = Gl::new(64, 64);
    gl.set_window_reader(|frame, w, h| Some(soft::render_window(frame, w, h)));
    gl.begin_query(GL_SAMPLES_PASSED, 1);
    quad(&mut gl, 0.5, 0.0);
    gl.delete_queries(1, &[1]);
    quad(&mut gl, 1.0, 0.0);
    gl.begin_query(GL_SAMPLES_PASSED, 2);
    quad(&mut gl, 0.25, 0.0);
    gl.end_query(GL_SAMPLES_PASSED);
    assert_eq!(counted(&mut gl, 2), 16 * 16);
    assert_eq!(gl.is_query(1), GL_FALSE);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}
