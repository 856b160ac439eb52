//! Untrimmed surfaces in renderer mode (GLU `glsurfeval.cc`): per Bezier patch, `glMap2f` for
//! every map and a `glMapGrid2f`/`glEvalMesh2` (or the patch's outline), inside
//! `glPushAttrib(GL_EVAL_BIT)` with the polygon mode saved and restored, as GLU's
//! `bgnmap2f`/`endmap2f` do.

use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::evaluation::surface::{grid_line, PatchGrid, Surface};
use crate::glu::model::object::NurbsObject;

/// Draws the patches through the GL evaluators, in the object's display mode.
pub(crate) fn render_patches(gl: &mut Gl, obj: &NurbsObject, surface: &Surface, patches: &[PatchGrid]) {
    let saved_mode = save_polygon_mode(gl);
    for patch in patches {
        match obj.props.display_mode {
            GLU_OUTLINE_PATCH => outline_patch(gl, surface, patch),
            // GLU draws grid blocks as quad outlines ("wireframequads"): the mesh's lines.
            GLU_OUTLINE_POLYGON => render_patch(gl, surface, patch, GL_LINE),
            _ => render_patch(gl, surface, patch, GL_FILL),
        }
    }
    restore_polygon_mode(gl, saved_mode);
}

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

/// `glMap2f` per map, then `glMapGrid2f(nu, u0, u1, nv, v1, v0)` — v reversed so that
/// `glEvalMesh2`'s clockwise strips come out counter-clockwise (GLU `slicer.cc`) — and
/// `glEvalMesh2(mode)`: `GL_FILL`, or `GL_LINE` for `GLU_OUTLINE_POLYGON`.
fn render_patch(gl: &mut Gl, surface: &Surface, patch: &PatchGrid, mode: GLenum) {
    load_patch(gl, surface, patch);
    let PatchGrid { u, v, nu, nv } = *patch;
    gl.map_grid2f(nu as i32, u.0 as f32, u.1 as f32, nv as i32, v.1 as f32, v.0 as f32);
    gl.eval_mesh2(mode, 0, nu as i32, 0, nv as i32);
}

/// `GLU_OUTLINE_PATCH`: the patch boundary as line strips along its four edges.
fn outline_patch(gl: &mut Gl, surface: &Surface, patch: &PatchGrid) {
    load_patch(gl, surface, patch);
    let PatchGrid { u, v, nu, nv } = *patch;
    let edges: [Vec<(f64, f64)>; 4] = [
        (0..=nu).map(|i| (grid_line(u, i, nu), v.0)).collect(),
        (0..=nv).map(|j| (u.1, grid_line(v, j, nv))).collect(),
        (0..=nu).map(|i| (grid_line((u.1, u.0), i, nu), v.1)).collect(),
        (0..=nv).map(|j| (u.0, grid_line((v.1, v.0), j, nv))).collect(),
    ];
    for edge in edges {
        gl.begin(GL_LINE_STRIP);
        for (s, t) in edge {
            gl.eval_coord2f(s as f32, t as f32);
        }
        gl.end();
    }
}
