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
/// hands it out; with `wire` (`GLU_OUTLINE_POLYGON`) grid blocks are GLU's zig-zag line strips.
pub(crate) fn tessellate_pieces(
    gl: &mut Gl,
    obj: &mut NurbsObject,
    maps: &PatchVertices,
    pieces: &[Piece],
    wire: bool,
) {
    let emit = |gl: &mut Gl, obj: &mut NurbsObject, [u, v]: [f32; 2]| maps.emit(gl, obj, u, v);
    for piece in pieces {
        match piece {
            Piece::Fan(points) | Piece::QuadStrip(points) => {
                obj.callbacks.begin(gl, kind(piece));
                for &p in points {
                    emit(gl, obj, p);
                }
                obj.callbacks.end(gl);
            }
            Piece::Grid(grid) => {
                let (kind, strips): (u32, Vec<Vec<[f32; 2]>>) = if wire {
                    (
                        GL_LINE_STRIP,
                        wire_strips(grid.nu, grid.nv)
                            .map(|s| s.map(|(i, j)| [grid.u_at(i), grid.v_at(j)]).collect())
                            .collect(),
                    )
                } else {
                    (GL_QUAD_STRIP, grid_strips(grid).collect())
                };
                for strip in strips {
                    obj.callbacks.begin(gl, kind);
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
/// (`GLU_OUTLINE_POLYGON`) grid blocks are drawn as GLU's zig-zag line strips.
pub(crate) fn render_pieces(gl: &mut Gl, pieces: &[Piece], wire: bool) {
    for piece in pieces {
        match piece {
            Piece::Fan(points) | Piece::QuadStrip(points) => {
                gl.begin(kind(piece));
                for &[u, v] in points {
                    gl.eval_coord2f(u, v);
                }
                gl.end();
            }
            Piece::Grid(g) => {
                let (u, v) = (g.u, g.v);
                gl.map_grid2d(g.nu as i32, u.0.into(), u.1.into(), g.nv as i32, v.0.into(), v.1.into());
                if wire {
                    wire_grid(gl, g.nu as i32, g.nv as i32);
                } else {
                    gl.eval_mesh2(GL_FILL, 0, g.nu as i32, 0, g.nv as i32);
                }
            }
        }
    }
}

/// GLU's `Backend::surfmesh` with `wireframequads`: one line strip per pair of neighbouring v
/// lines (the first pair being line 0 twice), zig-zagging across u, the zig-zag's phase
/// carried from strip to strip.
fn wire_grid(gl: &mut Gl, nu: i32, nv: i32) {
    for strip in wire_strips(nu as usize, nv as usize) {
        gl.begin(GL_LINE_STRIP);
        for (i, j) in strip {
            gl.eval_point2(i as i32, j as i32);
        }
        gl.end();
    }
}

/// The grid points (i, j) of each of [`wire_grid`]'s line strips.
fn wire_strips(nu: usize, nv: usize) -> impl Iterator<Item = std::vec::IntoIter<(usize, usize)>> {
    let mut odd = false;
    let pairs = std::iter::once((0, 0)).chain((0..nv).map(|v| (v, v + 1)));
    let strips: Vec<_> = pairs
        .map(|(v0, v1)| {
            let mut strip = Vec::with_capacity(2 * nu + 2);
            for u in 0..=nu {
                let (a, b) = if odd { (v0, v1) } else { (v1, v0) };
                strip.extend([(u, a), (u, b)]);
                odd = !odd;
            }
            strip.into_iter()
        })
        .collect();
    strips.into_iter()
}

fn kind(piece: &Piece) -> u32 {
    match piece {
        Piece::Fan(_) => GL_TRIANGLE_FAN,
        _ => GL_QUAD_STRIP,
    }
}

/// A grid block as GLU's callback-mode `mapmesh2f` emits it: one quad strip per column when
/// the grid is at least as wide as high (v running down), otherwise one per row (u running
/// down).
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
