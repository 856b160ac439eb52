//! The slicer's pieces out: evaluated through the callbacks (`GLU_NURBS_TESSELLATOR`, GLU
//! records the (u, v) of every primitive and evaluates them at the end of each patch,
//! `interface/glsurfeval.cc` and `insurfeval.cc`) or drawn through the GL evaluators
//! (`GLU_NURBS_RENDERER`: `glEvalCoord2f` per vertex, `glMapGrid2d` and `glEvalMesh2` per grid
//! block).

use super::vertex::PatchVertices;
use super::{Grid, Piece};
use crate::gl::consts::*;
use crate::gl::Gl;
use crate::glu::model::object::NurbsObject;

/// The pieces of one patch through the callbacks, each vertex as GLU's `inDoEvalCoord2EM`
/// hands it out. The display mode changes nothing here: GLU's callback-mode `mapmesh2f`
/// ignores the mesh style.
pub(crate) fn tessellate_pieces(gl: &mut Gl, obj: &mut NurbsObject, maps: &PatchVertices, pieces: &[Piece]) {
    let emit = |gl: &mut Gl, obj: &mut NurbsObject, [u, v]: [f32; 2]| maps.emit(gl, obj, u, v);
    for piece in pieces {
        match piece {
            Piece::Fan(points) | Piece::QuadStrip(points) | Piece::Line(points) => {
                obj.callbacks.begin(gl, kind(piece));
                for &p in points {
                    emit(gl, obj, p);
                }
                obj.callbacks.end(gl);
            }
            Piece::Block { grid, u, v } => tessellate_block(gl, obj, maps, grid, *u, *v),
            Piece::Grid(grid) => tessellate_block(gl, obj, maps, grid, (0, grid.nu as i64), (0, grid.nv as i64)),
        }
    }
}

/// Grid lines `u.0..=u.1` × `v.0..=v.1` of `g` as GLU's callback-mode `mapmesh2f` emits
/// them: quad strips by columns when the whole grid has at least as many columns as rows (v
/// running down), else by rows (u running down; a row of no width still begins and ends a
/// strip, as GLU's does). Every grid point is evaluated once ([`PatchVertices::sample_grid`])
/// and handed out as often as the strips meet it.
fn tessellate_block(
    gl: &mut Gl,
    obj: &mut NurbsObject,
    maps: &PatchVertices,
    g: &Grid,
    (u0, u1): (i64, i64),
    (v0, v1): (i64, i64),
) {
    let at = |x: i64, n: usize, r: (f32, f32)| super::line(r, n, x.max(0) as usize);
    let us: Vec<f32> = (u0..=u1).map(|i| at(i, g.nu, g.u)).collect();
    let vs: Vec<f32> = (v0..=v1).map(|j| at(j, g.nv, g.v)).collect();
    let samples = maps.sample_grid(&us, &vs);
    let emit = |gl: &mut Gl, obj: &mut NurbsObject, i: i64, j: i64| {
        let (a, b) = ((i - u0) as usize, (j - v0) as usize);
        maps.emit_sampled(gl, obj, &samples, b * us.len() + a, us[a], vs[b]);
    };
    if g.nu >= g.nv {
        for i in u0..u1 {
            obj.callbacks.begin(gl, GL_QUAD_STRIP);
            for j in (v0..=v1).rev() {
                emit(gl, obj, i, j);
                emit(gl, obj, i + 1, j);
            }
            obj.callbacks.end(gl);
        }
    } else {
        for j in v0..v1 {
            obj.callbacks.begin(gl, GL_QUAD_STRIP);
            for i in (u0..=u1).rev() {
                emit(gl, obj, i, j + 1);
                emit(gl, obj, i, j);
            }
            obj.callbacks.end(gl);
        }
    }
}

/// The pieces through the GL evaluators (the patch's maps already loaded); with `wire`
/// (`GLU_OUTLINE_POLYGON`) grid blocks are `glEvalMesh2(GL_LINE)` (GLU is built with
/// `NOWIREFRAME`, so `Backend::surfmesh` asks for line meshes rather than drawing its own).
pub(crate) fn render_pieces(gl: &mut Gl, pieces: &[Piece], wire: bool) {
    for piece in pieces {
        match piece {
            Piece::Fan(points) | Piece::QuadStrip(points) | Piece::Line(points) => {
                gl.begin(kind(piece));
                for &[u, v] in points {
                    gl.eval_coord2f(u, v);
                }
                gl.end();
            }
            Piece::Block { grid: g, u: bu, v: bv } => {
                let (u, v) = (g.u, g.v);
                gl.map_grid2d(g.nu as i32, u.0.into(), u.1.into(), g.nv as i32, v.0.into(), v.1.into());
                let mode = if wire { GL_LINE } else { GL_FILL };
                gl.eval_mesh2(mode, bu.0 as i32, bu.1 as i32, bv.0 as i32, bv.1 as i32);
            }
            Piece::Grid(g) => {
                let (u, v) = (g.u, g.v);
                gl.map_grid2d(g.nu as i32, u.0.into(), u.1.into(), g.nv as i32, v.0.into(), v.1.into());
                gl.eval_mesh2(if wire { GL_LINE } else { GL_FILL }, 0, g.nu as i32, 0, g.nv as i32);
            }
        }
    }
}

fn kind(piece: &Piece) -> u32 {
    match piece {
        Piece::Fan(_) => GL_TRIANGLE_FAN,
        Piece::Line(_) => GL_LINE_STRIP,
        _ => GL_QUAD_STRIP,
    }
}
