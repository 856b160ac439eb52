//! Renderer mode's frame around a surface's patches (GLU `glsurfeval.cc`): `glMap2f` for
//! every map of a patch, and `glPushAttrib(GL_EVAL_BIT)` with the polygon mode saved and
//! restored, as GLU's `bgnmap2f`/`endmap2f` do.

use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::Gl;
use crate::glu::evaluation::surface::{PatchGrid, Surface};

/// GLU's `bgnmap2f` in renderer mode: `glPushAttrib(GL_EVAL_BIT)` and the polygon mode saved,
/// then filled polygons (`polymode(N_MESHFILL)` from `Backend::bgnsurf`).
pub(crate) fn save_polygon_mode(gl: &mut Gl) -> [GLenum; 2] {
    gl.push_attrib(GL_EVAL_BIT);
    let saved = gl.polygon_modes();
    gl.polygon_mode(GL_FRONT_AND_BACK, GL_FILL);
    saved
}

/// GLU's `endmap2f`: the attributes popped and the polygon mode put back.
pub(crate) fn restore_polygon_mode(gl: &mut Gl, saved: [GLenum; 2]) {
    gl.pop_attrib();
    gl.polygon_mode(GL_FRONT, saved[0]);
    gl.polygon_mode(GL_BACK, saved[1]);
}

/// `glMap2f` and `glEnable` for every map, restricted to the patch.
pub(crate) fn load_patch(gl: &mut Gl, surface: &Surface, patch: &PatchGrid) {
    let (u, v) = (patch.u, patch.v);
    for map in surface.attributes.iter().chain([&surface.pos]) {
        let Some(points) = map.on(u, v) else { continue };
        let points: Vec<f32> = points.iter().map(|&c| c as f32).collect();
        let p = &map.patches;
        let (k, uo, vo) = (p.dim as i32, p.uorder as i32, p.vorder as i32);
        gl.map2f(map.target, u.0 as f32, u.1 as f32, vo * k, uo, v.0 as f32, v.1 as f32, k, vo, &points);
        gl.enable(map.target);
    }
}
