//! GLU's tessellator mode (`GLU_NURBS_TESSELLATOR`): instead of drawing, a NURBS surface and
//! curve are handed to callbacks, which print the primitives and vertices they receive
//! (surface vertices are x y z u v; curve vertices the raw control-space vector).
//!
//! `cargo run --release --example nurbs_callbacks`

use gleval::prelude::*;

fn main() {
    let mut gl = Gl::new(300, 300);
    gl.matrix_mode(GL_PROJECTION);
    gl.glu_ortho_2d(-2.0, 2.0, -2.0, 2.0);
    gl.matrix_mode(GL_MODELVIEW);

    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    gl.glu_nurbs_property(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    gl.glu_nurbs_property(nurb, GLU_U_STEP, 2.0);
    gl.glu_nurbs_property(nurb, GLU_V_STEP, 2.0);
    gl.glu_nurbs_callback(nurb, GLU_NURBS_BEGIN, Some(NurbsCallback::begin(|_, prim| println!("begin 0x{prim:04x}"))));
    gl.glu_nurbs_callback(nurb, GLU_NURBS_VERTEX, Some(NurbsCallback::vertex(|_, v| println!("  vertex {v:?}"))));
    gl.glu_nurbs_callback(nurb, GLU_NURBS_NORMAL, Some(NurbsCallback::normal(|_, n| println!("  normal {n:?}"))));
    gl.glu_nurbs_callback(nurb, GLU_NURBS_END, Some(NurbsCallback::end(|_| println!("end"))));
    gl.glu_nurbs_callback(
        nurb,
        GLU_NURBS_ERROR,
        Some(NurbsCallback::error(|e| eprintln!("error {e}: {:?}", glu_error_string(e)))),
    );

    let knots = [0.0, 0.0, 1.0, 1.0];
    let sheet = [-1.0, -1.0, 0.0, -1.0, 1.0, 0.0, 1.0, -1.0, 0.0, 1.0, 1.0, 1.0];
    gl.glu_begin_surface(nurb);
    gl.glu_nurbs_surface(nurb, 4, &knots, 4, &knots, 6, 3, &sheet, 2, 2, GL_MAP2_VERTEX_3);
    gl.glu_end_surface(nurb);

    let curve_knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    let arc = [1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0];
    gl.glu_begin_curve(nurb);
    gl.glu_nurbs_curve(nurb, 6, &curve_knots, 4, &arc, 3, GL_MAP1_VERTEX_4);
    gl.glu_end_curve(nurb);
    gl.glu_delete_nurbs_renderer(nurb);
}
