//! The slicer's pieces out: evaluated through the callbacks (`GLU_NURBS_TESSELLATOR`, GLU
//! records the (u, v) of every primitive and evaluates them at the end of each patch,
//! `interface/glsurfeval.cc` and `insurfeval.cc`) or drawn through the GL evaluators
//! (`GLU_NURBS_RENDERER`: `glEvalCoord2f` per vertex, `glMapGrid2d` and `glEvalMesh2` per grid
//! block).

use super::vertex::PatchVertices;
use super::{Grid, Piece};
use crate::gl::consts::*;
use crate::gl::Gl;
use crate::glu::evaluation::machine::{LineTable, Positions};
use crate::glu::model::callbacks::StripSink;
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

/// Vertices per batch of pieces on the fast path: small enough that evaluating the next batch
/// overlaps issuing this one's callbacks, large enough to amortise the hand-over.
const BATCH_POINTS: usize = 1 << 14;

/// Vertices in the first batch, which the callbacks wait for.
const FIRST_BATCH_POINTS: usize = 1 << 11;

/// The grid lines a block covers, as [`tessellate_block`] computes them.
fn block_lines(g: &Grid, (u0, u1): (i64, i64), (v0, v1): (i64, i64)) -> (Vec<f32>, Vec<f32>) {
    let at = |x: i64, n: usize, r: (f32, f32)| super::line(r, n, x.max(0) as usize);
    ((u0..=u1).map(|i| at(i, g.nu, g.u)).collect(), (v0..=v1).map(|j| at(j, g.nv, g.v)).collect())
}

/// Grid lines from the first to the last, inclusive.
type Lines = (i64, i64);

/// A piece's grid block and its line ranges in u and v, if it is one.
fn as_block(piece: &Piece) -> Option<(&Grid, Lines, Lines)> {
    match piece {
        Piece::Block { grid, u, v } => Some((grid, *u, *v)),
        Piece::Grid(g) => Some((g, (0, g.nu as i64), (0, g.nv as i64))),
        _ => None,
    }
}

/// How many positions a piece's evaluation holds: its points, or its block's grid points.
fn evaluated_points(piece: &Piece) -> usize {
    match (piece, as_block(piece)) {
        (Piece::Fan(p) | Piece::QuadStrip(p) | Piece::Line(p), _) => p.len(),
        (_, Some((_, u, v))) => {
            let lines = |(a, b): (i64, i64)| usize::try_from(b - a + 1).unwrap_or(0);
            lines(u).saturating_mul(lines(v))
        }
        _ => 0,
    }
}

/// One grid's lines that a patch's blocks cover, from (`i0`, `j0`) on: where each is in the
/// patch's [`LineTable`].
struct GridSlots {
    grid: Grid,
    i0: i64,
    j0: i64,
    columns: Vec<usize>,
    rows: Vec<usize>,
}

/// Every grid line the blocks of a patch cover (each region's blocks are on its own grid),
/// each once by its bits, with its sums along v or u coefficients worked out once: blocks and
/// fan points on those lines take them from there.
struct PatchLines {
    table: LineTable,
    grids: Vec<GridSlots>,
}

/// The lines of every grid the blocks of `pieces` are on.
fn grid_lines(positions: Positions<'_>, pieces: &[Piece]) -> PatchLines {
    let mut ranges: Vec<(Grid, Lines, Lines)> = Vec::new();
    for (g, (u0, u1), (v0, v1)) in pieces.iter().filter_map(as_block) {
        if u1 < u0 || v1 < v0 {
            continue;
        }
        let (u0, v0) = (u0.max(0), v0.max(0));
        match ranges.iter_mut().find(|r| r.0 == *g) {
            Some((_, u, v)) => {
                *u = (u.0.min(u0), u.1.max(u1));
                *v = (v.0.min(v0), v.1.max(v1));
            }
            None => ranges.push((*g, (u0, u1.max(u0)), (v0, v1.max(v0)))),
        }
    }
    let lines: Vec<(Vec<f32>, Vec<f32>)> = ranges.iter().map(|(g, u, v)| block_lines(g, *u, *v)).collect();
    let distinct = |values: Vec<&Vec<f32>>| {
        let mut bits: Vec<u32> = values.into_iter().flatten().map(|x| x.to_bits()).collect();
        bits.sort_unstable();
        bits.dedup();
        bits.into_iter().map(f32::from_bits).collect()
    };
    let table = positions
        .line_table(distinct(lines.iter().map(|l| &l.0).collect()), distinct(lines.iter().map(|l| &l.1).collect()));
    // Every line is in the table: no slot is missing.
    let slots = |xs: &[f32], slot: &dyn Fn(f32) -> Option<usize>| xs.iter().filter_map(|&x| slot(x)).collect();
    let grids = ranges
        .iter()
        .zip(&lines)
        .map(|((grid, u, v), (us, vs))| GridSlots {
            grid: *grid,
            i0: u.0,
            j0: v.0,
            columns: slots(us, &|x| table.u_slot(x)),
            rows: slots(vs, &|x| table.v_slot(x)),
        })
        .collect();
    PatchLines { table, grids }
}

/// Evaluates a batch of pieces into `out` (resized), piece after piece, on rayon's workers;
/// blocks and points on grid lines from the patch's `lines`.
fn evaluate_pieces(positions: Positions<'_>, lines: &PatchLines, batch: &[Piece], out: &mut Vec<[f32; 5]>) {
    use rayon::prelude::*;
    let size = batch.iter().map(evaluated_points).sum();
    // Every entry is overwritten: no zeroing.
    if out.len() < size {
        out.resize(size, [0.0; 5]);
    }
    out.truncate(size);
    let mut chunks = Vec::with_capacity(batch.len());
    let mut free = out.as_mut_slice();
    for piece in batch {
        let (chunk, after) = free.split_at_mut(evaluated_points(piece));
        chunks.push((piece, chunk));
        free = after;
    }
    chunks.into_par_iter().with_min_len(16).for_each(|(piece, chunk)| evaluate_piece(positions, lines, piece, chunk));
}

/// One piece's positions into `chunk` (as long as [`evaluated_points`]).
fn evaluate_piece(positions: Positions<'_>, lines: &PatchLines, piece: &Piece, chunk: &mut [[f32; 5]]) {
    let table = &lines.table;
    let done = match piece {
        Piece::Fan(p) | Piece::QuadStrip(p) | Piece::Line(p) => positions.points_into_with(p, chunk, table),
        _ => as_block(piece).and_then(|(g, u, v)| evaluate_block(positions, lines, g, u, v, chunk)),
    };
    debug_assert!(done.is_some(), "positions of an empty patch");
}

/// A block's grid points, row after row, into `chunk` from the patch's lines; `None` if its
/// grid has none there.
fn evaluate_block(
    positions: Positions<'_>,
    lines: &PatchLines,
    g: &Grid,
    (u0, u1): Lines,
    (v0, v1): Lines,
    chunk: &mut [[f32; 5]],
) -> Option<()> {
    let width = usize::try_from(u1 - u0 + 1).unwrap_or(0);
    if width == 0 || v1 < v0 {
        return Some(());
    }
    let l = lines.grids.iter().find(|l| l.grid == *g)?;
    // Lines before the first (index < 0) are the first again, as `block_lines` has them.
    let at = |slots: &[usize], x: i64, first: i64| slots.get(usize::try_from(x.max(0) - first).ok()?).copied();
    // The slots run with the lines: both ends there, every column between is.
    at(&l.columns, u0, l.i0)?;
    at(&l.columns, u1, l.i0)?;
    for (row, j) in chunk.chunks_exact_mut(width).zip(v0..) {
        let j = at(&l.rows, j, l.j0)?;
        positions.table_row_into(&lines.table, (u0..).filter_map(|i| at(&l.columns, i, l.i0)), j, row);
    }
    Some(())
}

/// Consecutive runs of pieces of at most [`BATCH_POINTS`] evaluated points, the first of at most
/// [`FIRST_BATCH_POINTS`] (at least one piece each).
fn piece_batches(pieces: &[Piece]) -> Vec<&[Piece]> {
    let mut out = Vec::new();
    let mut rest = pieces;
    // The first batch smaller: nothing overlaps its evaluation.
    let mut limit = FIRST_BATCH_POINTS;
    while !rest.is_empty() {
        let mut take = 1;
        let mut points = evaluated_points(&rest[0]);
        while take < rest.len() && points.saturating_add(evaluated_points(&rest[take])) <= limit {
            points += evaluated_points(&rest[take]);
            take += 1;
        }
        let (batch, tail) = rest.split_at(take);
        out.push(batch);
        limit = BATCH_POINTS;
        rest = tail;
    }
    out
}

/// [`tessellate_pieces`] when only begin, vertex and end callbacks are set and the patch is not
/// empty: the same primitives and vertices, the positions evaluated a batch of pieces ahead on
/// rayon's workers while this thread issues the previous batch's callbacks (which need not be
/// `Send`). `buffers` are reused between calls.
pub(crate) fn tessellate_pieces_sunk(
    gl: &mut Gl,
    sinks: &mut impl StripSink,
    positions: Positions<'_>,
    pieces: &[Piece],
    buffers: &mut [Vec<[f32; 5]>; 2],
) {
    let [current, next] = buffers;
    let batches = piece_batches(pieces);
    let lines = &grid_lines(positions, pieces);
    if let Some(first) = batches.first() {
        evaluate_pieces(positions, lines, first, current);
    }
    for (k, batch) in batches.iter().enumerate() {
        rayon::in_place_scope(|scope| {
            if let Some(following) = batches.get(k + 1) {
                let next = &mut *next;
                scope.spawn(move |_| evaluate_pieces(positions, lines, following, next));
            }
            issue_pieces(gl, sinks, batch, current);
        });
        std::mem::swap(current, next);
    }
}

/// The callbacks of a batch of pieces whose positions are in `evaluated` (piece after piece).
fn issue_pieces(gl: &mut Gl, sinks: &mut impl StripSink, batch: &[Piece], evaluated: &[[f32; 5]]) {
    let mut start = 0;
    for piece in batch {
        let points = &evaluated[start..start + evaluated_points(piece)];
        start += points.len();
        match as_block(piece) {
            None => {
                sinks.begin(gl, kind(piece));
                for p in points {
                    sinks.vertex(gl, p);
                }
                sinks.end(gl);
            }
            Some((g, (u0, u1), (v0, v1))) => {
                let width = usize::try_from(u1 - u0 + 1).unwrap_or(0);
                let at = |i: i64, j: i64| &points[(j - v0) as usize * width + (i - u0) as usize];
                if g.nu >= g.nv {
                    for i in u0..u1 {
                        sinks.begin(gl, GL_QUAD_STRIP);
                        for j in (v0..=v1).rev() {
                            sinks.vertex(gl, at(i, j));
                            sinks.vertex(gl, at(i + 1, j));
                        }
                        sinks.end(gl);
                    }
                } else {
                    for j in v0..v1 {
                        sinks.begin(gl, GL_QUAD_STRIP);
                        for i in (u0..=u1).rev() {
                            sinks.vertex(gl, at(i, j + 1));
                            sinks.vertex(gl, at(i, j));
                        }
                        sinks.end(gl);
                    }
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
