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
            Piece::Block { grid, u, v } => {
                for strip in block_strips(grid, *u, *v) {
                    obj.callbacks.begin(gl, GL_QUAD_STRIP);
                    for p in strip {
                        emit(gl, obj, p);
                    }
                    obj.callbacks.end(gl);
                }
            }
            Piece::Grid(grid) => {
                for strip in grid_strips(grid) {
                    obj.callbacks.begin(gl, GL_QUAD_STRIP);
                    for p in strip {
                        emit(gl, obj, p);
                    }
                    obj.callbacks.end(gl);
                }
            }
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

/// A grid block as GLU's callback-mode `mapmesh2f` emits it: one quad strip per column when
/// the grid is at least as wide as high (v running down), otherwise one per row (u running
/// down).
/// The strips of part of a grid, as GLU's callback-mode `mapmesh2f` makes them: by columns
/// when the whole grid has at least as many columns as rows, else by rows (an empty strip
/// for a row of no width, as GLU begins and ends it).
fn block_strips(g: &Grid, (u0, u1): (i64, i64), (v0, v1): (i64, i64)) -> Vec<Vec<[f32; 2]>> {
    let at = |x: i64, n: usize, r: (f32, f32)| super::line(r, n, x.max(0) as usize);
    if g.nu >= g.nv {
        (u0..u1)
            .map(|i| {
                let (a, b) = (at(i, g.nu, g.u), at(i + 1, g.nu, g.u));
                (v0..=v1).rev().flat_map(|j| [[a, at(j, g.nv, g.v)], [b, at(j, g.nv, g.v)]]).collect()
            })
            .collect()
    } else {
        (v0..v1)
            .map(|i| {
                let (a, b) = (at(i, g.nv, g.v), at(i + 1, g.nv, g.v));
                (u0..=u1).rev().flat_map(|j| [[at(j, g.nu, g.u), b], [at(j, g.nu, g.u), a]]).collect()
            })
            .collect()
    }
}

pub(crate) fn grid_strips(g: &Grid) -> impl Iterator<Item = Vec<[f32; 2]>> + '_ {
    let columns = g.nu >= g.nv;
    let count = if columns { g.nu } else { g.nv };
    (0..count).map(move |i| {
        if columns {
            let (a, b) = (g.u_at(i), g.u_at(i + 1));
            (0..=g.nv).rev().flat_map(|j| [[a, g.v_at(j)], [b, g.v_at(j)]]).collect()
        } else {
            let (a, b) = (g.v_at(i), g.v_at(i + 1));
            (0..=g.nu).rev().flat_map(|j| [[g.u_at(j), b], [g.u_at(j), a]]).collect()
        }
    })
}
