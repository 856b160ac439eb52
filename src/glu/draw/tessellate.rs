//! Untrimmed surfaces under `GLU_DOMAIN_DISTANCE` in tessellator mode, GLU's fast path
//! (`OPTIMIZE_UNTRIMED_CASE` in `Subdivider::drawSurfaces`): each patch one grid block of
//! max(1, ⌊rate·R⌋) steps a side, v from the top line down, as `GL_QUAD_STRIP`s through the
//! callbacks (`mapmesh2f` with `output_triangles`), the last patch first as GLU evaluates its
//! list of patches. Vertices come from GLU's `f32` evaluator ([`PatchMachine`]). With only
//! begin, vertex and end callbacks the grids are evaluated on rayon's workers, a batch ahead of
//! the strips issued on this thread; this is the path benchmarked as `nurbs_untrimmed`.

use super::sliced::glu_grid;
use super::slicer::output::tessellate_pieces;
use super::slicer::vertex::PatchVertices;
use super::slicer::Piece;
use crate::gl::consts::*;
use crate::gl::Gl;
use crate::glu::evaluation::machine::PatchMachine;
use crate::glu::evaluation::surface::{PatchGrid, Surface};
use crate::glu::model::callbacks::StripSink;
use crate::glu::model::object::NurbsObject;

/// Issues every patch, last first.
pub(crate) fn tessellate_patches(gl: &mut Gl, obj: &mut NurbsObject, surface: &Surface, patches: &[PatchGrid]) {
    let patches: Vec<PatchGrid> = patches.iter().rev().copied().collect();
    if obj.callbacks.sinks().is_some() {
        return tessellate_patches_in_parallel(gl, obj, surface, &patches);
    }
    for patch in &patches {
        tessellate_patch(gl, obj, surface, patch);
    }
}

/// The patch's grid points, row j (v from the top) after row j − 1, as [x, y, z, u, v];
/// `None` if the patch has no evaluator.
fn grid_into(surface: &Surface, patch: &PatchGrid, out: &mut [[f32; 5]]) -> Option<()> {
    let p = &surface.pos.patches;
    let points = surface.pos.on(patch.u, patch.v)?;
    let (u, v) = ((patch.u.0 as f32, patch.u.1 as f32), (patch.v.0 as f32, patch.v.1 as f32));
    let machine = PatchMachine::new(&points, surface.k, (p.uorder, p.vorder), u, v)?;
    let g = glu_grid(patch);
    let us: Vec<f32> = (0..=g.nu).map(|i| g.u_at(i)).collect();
    let ucoeffs = machine.u_coefficients(&us);
    for (j, row) in out.chunks_exact_mut(g.nu + 1).enumerate() {
        machine.position_row(g.v_at(j), &us, &ucoeffs, row)?;
    }
    Some(())
}

/// Grid points per batch of patches: small enough that evaluating the next batch overlaps
/// issuing this one's callbacks, large enough to amortise the hand-over.
const BATCH_POINTS: usize = 1 << 16;

/// Consecutive runs of patches of at most [`BATCH_POINTS`] grid points (at least one patch each).
fn batches(patches: &[PatchGrid]) -> Vec<&[PatchGrid]> {
    let mut out = Vec::new();
    let mut rest = patches;
    while !rest.is_empty() {
        let mut take = 1;
        let mut points = rest[0].points();
        while take < rest.len() && points.saturating_add(rest[take].points()) <= BATCH_POINTS {
            points += rest[take].points();
            take += 1;
        }
        let (batch, tail) = rest.split_at(take);
        out.push(batch);
        rest = tail;
    }
    out
}

/// Evaluates a batch's grids into `out` (resized), in parallel; whether each succeeded.
fn evaluate_batch(surface: &Surface, batch: &[PatchGrid], out: &mut Vec<[f32; 5]>) -> Vec<bool> {
    use rayon::prelude::*;
    // Every entry is overwritten (a patch that fails is redone point by point): no zeroing.
    let size = batch.iter().map(PatchGrid::points).sum();
    if out.len() < size {
        out.resize(size, [0.0; 5]);
    }
    out.truncate(size);
    let mut chunks = Vec::with_capacity(batch.len());
    let mut free = out.as_mut_slice();
    for patch in batch {
        let (chunk, after) = free.split_at_mut(patch.points());
        chunks.push((patch, chunk));
        free = after;
    }
    chunks.into_par_iter().map(|(patch, chunk)| grid_into(surface, patch, chunk).is_some()).collect()
}

/// [`tessellate_patch`] for every patch when only begin, vertex and end callbacks are set. The
/// grids are evaluated a batch ahead on rayon's workers while this thread issues the previous
/// batch's strips, in patch order as GLU issues them (the callbacks need not be `Send`). The two
/// buffers are kept in the object and reused.
fn tessellate_patches_in_parallel(gl: &mut Gl, obj: &mut NurbsObject, surface: &Surface, patches: &[PatchGrid]) {
    let mut current = std::mem::take(&mut obj.vertex_scratch[0]);
    let mut next = std::mem::take(&mut obj.vertex_scratch[1]);
    let batches = batches(patches);
    let mut ok = match batches.first() {
        Some(first) => evaluate_batch(surface, first, &mut current),
        None => Vec::new(),
    };
    for (k, batch) in batches.iter().enumerate() {
        let mut next_ok = Vec::new();
        rayon::in_place_scope(|scope| {
            if let Some(following) = batches.get(k + 1) {
                let (next, next_ok) = (&mut next, &mut next_ok);
                scope.spawn(move |_| *next_ok = evaluate_batch(surface, following, next));
            }
            issue_batch(gl, obj, surface, batch, &ok, &current);
        });
        std::mem::swap(&mut current, &mut next);
        ok = next_ok;
    }
    obj.vertex_scratch = [current, next];
}

/// The strips of a batch whose grids are in `grids` (patch after patch); a patch whose
/// evaluation failed (`ok` false) is issued point by point.
fn issue_batch(
    gl: &mut Gl,
    obj: &mut NurbsObject,
    surface: &Surface,
    batch: &[PatchGrid],
    ok: &[bool],
    grids: &[[f32; 5]],
) {
    let mut start = 0;
    for (patch, &done) in batch.iter().zip(ok) {
        let grid = &grids[start..start + patch.points()];
        start += patch.points();
        match obj.callbacks.sinks() {
            Some(mut sinks) if done => {
                if let Some(mut plain) = sinks.plain() {
                    quad_strips(gl, &mut plain, grid, patch.nu, patch.nv);
                } else {
                    quad_strips(gl, &mut sinks, grid, patch.nu, patch.nv);
                }
            }
            _ => tessellate_patch(gl, obj, surface, patch),
        }
    }
}

/// The grid block of one patch through the callbacks, vertex by vertex.
fn tessellate_patch(gl: &mut Gl, obj: &mut NurbsObject, surface: &Surface, patch: &PatchGrid) {
    if let Some(maps) = PatchVertices::new(obj, surface, patch.u, patch.v) {
        tessellate_pieces(gl, obj, &maps, &[Piece::Grid(glu_grid(patch))]);
    }
}

/// [`tessellate_patch`]'s strips when only begin, vertex and end callbacks are registered:
/// the same primitives, one indirect call per vertex.
fn quad_strips(gl: &mut Gl, sinks: &mut impl StripSink, g: &[[f32; 5]], nu: usize, nv: usize) {
    let at = |i: usize, j: usize| &g[j * (nu + 1) + i];
    if nu >= nv {
        for i in 0..nu {
            sinks.begin(gl, GL_QUAD_STRIP);
            for j in (0..=nv).rev() {
                sinks.vertex(gl, at(i, j));
                sinks.vertex(gl, at(i + 1, j));
            }
            sinks.end(gl);
        }
    } else {
        for j in 0..nv {
            sinks.begin(gl, GL_QUAD_STRIP);
            for i in (0..=nu).rev() {
                sinks.vertex(gl, at(i, j + 1));
                sinks.vertex(gl, at(i, j));
            }
            sinks.end(gl);
        }
    }
}
