//! Untrimmed surfaces the way GLU covers them when it does not take its domain-distance fast
//! path (`Subdivider::drawSurfaces` with the border loop of `makeBorderTrim`): each Bezier
//! patch's border sampled at its sidesteps, its inside on the grid of its interior steps,
//! joined by fans ([`super::slicer`]). In tessellator mode GLU evaluates the patches' primitives
//! when the surface ends, last patch first (`bezierPatchMeshListInsert` puts each new patch at
//! the head of its list); in renderer mode each patch is drawn as it comes.

use super::patches::{load_patch, restore_polygon_mode, save_polygon_mode};
use super::slicer::output::{render_pieces, tessellate_pieces, tessellate_pieces_sunk};
use super::slicer::split::{leaves, Part, MAX_SUBDIVISIONS};
use super::slicer::vertex::PatchVertices;
use super::slicer::{outline_rect, slice_rect, Grid, Piece};
use crate::gl::consts::*;
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::evaluation::patch_steps::{patch_steps, DirectionSteps, Net};
use crate::glu::evaluation::surface::{PatchGrid, Surface};
use crate::glu::model::object::NurbsObject;
use glam::Mat4;

/// One patch and the pieces covering it.
pub(crate) struct SlicedPatch {
    pub grid: PatchGrid,
    pub pieces: Vec<Piece>,
}

/// Every patch of the surface, u outer, sliced as GLU slices it (bisected first where GLU's
/// sampling subdivision would, [`leaves`]), or outlined for `GLU_OUTLINE_PATCH`.
pub(crate) fn slice_surface(obj: &NurbsObject, surface: &Surface) -> Vec<SlicedPatch> {
    if obj.props.display_mode == GLU_OUTLINE_PATCH {
        // GLU outlines the patches of its border trim as cut along the knot lines: each
        // patch's sides in the order the cuts left its arcs.
        if let Ok(patches) = super::subdivided::slice_trimmed(obj, surface, &[]) {
            return patches;
        }
    }
    let matrix = sampling_matrix(obj);
    let steps = |su: (f32, f32), sv: (f32, f32)| rect_steps(obj, &matrix, surface, su, sv);
    let p = &surface.pos.patches;
    let mut out = Vec::new();
    for &u in &p.uintervals {
        for &v in &p.vintervals {
            let (u32_, v32) = ((u.0 as f32, u.1 as f32), (v.0 as f32, v.1 as f32));
            let linear = (p.uorder == 2, p.vorder == 2);
            let outline = obj.props.display_mode == GLU_OUTLINE_PATCH;
            let levels = if outline { 0 } else { MAX_SUBDIVISIONS };
            let pieces = leaves(u32_, v32, linear, &steps, levels)
                .into_iter()
                .flat_map(|part| match part {
                    Part::Degenerate(t) => vec![Piece::Fan(t.to_vec())],
                    Part::Leaf(rect, _) if outline => outline_rect(&rect),
                    Part::Leaf(rect, interior) => slice_rect(&rect, interior),
                })
                .collect();
            out.push(SlicedPatch { grid: PatchGrid { u, v, nu: 0, nv: 0 }, pieces });
        }
    }
    out
}

/// The matrix GLU samples with: none for the object-space methods.
pub(crate) fn sampling_matrix(obj: &NurbsObject) -> Mat4 {
    if obj.props.object_space() {
        Mat4::IDENTITY
    } else {
        obj.matrices.sampling()
    }
}

/// GLU's steps for the part [su] × [sv] of the surface's patch there (`Patch::getstepsize`).
pub(crate) fn rect_steps(
    obj: &NurbsObject,
    matrix: &Mat4,
    surface: &Surface,
    su: (f32, f32),
    sv: (f32, f32),
) -> [DirectionSteps; 2] {
    let p = &surface.pos.patches;
    let range = |r: (f32, f32)| (f64::from(r.0), f64::from(r.1));
    let points = surface.pos.on(range(su), range(sv)).unwrap_or_default();
    let net = Net { points: &points, k: surface.k, orders: (p.uorder, p.vorder) };
    patch_steps(&obj.props, matrix, &net, (su.1 - su.0, sv.1 - sv.0))
}

/// The patches that can be drawn, less those sampled beyond the façade's mesh limit (a weight
/// near zero under path-length sampling asks for 2^14 segments a side): GLU's convention is
/// `GLU_OUT_OF_MEMORY` through the error callback, once, and the other patches drawn.
pub(crate) fn drawable(obj: &mut NurbsObject, mut patches: Vec<SlicedPatch>) -> Vec<SlicedPatch> {
    let before = patches.len();
    patches.retain(|p| points(&p.pieces) <= crate::tess::MAX_MESH_VERTICES);
    if patches.len() < before {
        obj.callbacks.error(crate::glu::consts::GLU_OUT_OF_MEMORY);
    }
    patches
}

/// The vertices the pieces hand out, saturating.
fn points(pieces: &[Piece]) -> usize {
    pieces.iter().fold(0usize, |sum, piece| {
        let n = match piece {
            Piece::Fan(p) | Piece::QuadStrip(p) | Piece::Line(p) => p.len(),
            Piece::Block { u, v, .. } => {
                let cells = (u.1 - u.0 + 1).max(0).saturating_mul((v.1 - v.0 + 1).max(0));
                2usize.saturating_mul(usize::try_from(cells).unwrap_or(usize::MAX))
            }
            Piece::Grid(g) => 2usize.saturating_mul(g.nu.saturating_add(1)).saturating_mul(g.nv.saturating_add(1)),
        };
        sum.saturating_add(n)
    })
}

/// The patch's grid block on GLU's domain-distance fast path: `surfgrid(u0, u1, nu, v1, v0,
/// nv)`, v from the top line down.
pub(crate) fn glu_grid(patch: &PatchGrid) -> Grid {
    let (u, v) = ((patch.u.0 as f32, patch.u.1 as f32), (patch.v.1 as f32, patch.v.0 as f32));
    Grid { u, nu: patch.nu, v, nv: patch.nv }
}

/// The fast path's patches, each one grid block.
pub(crate) fn grid_patches(patches: &[PatchGrid]) -> Vec<SlicedPatch> {
    patches.iter().map(|p| SlicedPatch { grid: *p, pieces: vec![Piece::Grid(glu_grid(p))] }).collect()
}

/// The patches through the callbacks, last patch first. With only begin, vertex and end
/// callbacks set, the positions are evaluated on rayon's workers ahead of the callbacks
/// ([`tessellate_pieces_sunk`]).
pub(crate) fn tessellate_sliced(gl: &mut Gl, obj: &mut NurbsObject, surface: &Surface, patches: &[SlicedPatch]) {
    let mut buffers = std::mem::take(&mut obj.vertex_scratch);
    for patch in patches.iter().rev() {
        let Some(maps) = PatchVertices::new(obj, surface, patch.grid.u, patch.grid.v) else { continue };
        let positions = maps.positions();
        match obj.callbacks.sinks() {
            Some(mut sinks) if !positions.empty() => {
                if let Some(mut plain) = sinks.plain() {
                    tessellate_pieces_sunk(gl, &mut plain, positions, &patch.pieces, &mut buffers);
                } else {
                    tessellate_pieces_sunk(gl, &mut sinks, positions, &patch.pieces, &mut buffers);
                }
            }
            _ => tessellate_pieces(gl, obj, &maps, &patch.pieces),
        }
    }
    obj.vertex_scratch = buffers;
}

/// The patches through the GL evaluators, each after its maps, in a `GL_EVAL_BIT` push with
/// the polygon mode saved (GLU `bgnmap2f`/`endmap2f`). `GLU_OUTLINE_POLYGON` draws in
/// `GL_LINE` polygon mode (`Backend::bgnsurf`) with grid blocks as line strips.
pub(crate) fn render_sliced(gl: &mut Gl, obj: &NurbsObject, surface: &Surface, patches: &[SlicedPatch]) {
    let saved = save_polygon_mode(gl);
    let wire = obj.props.display_mode == GLU_OUTLINE_POLYGON;
    if wire {
        gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    }
    for patch in patches {
        load_patch(gl, surface, &patch.grid);
        render_pieces(gl, &patch.pieces, wire);
    }
    restore_polygon_mode(gl, saved);
}
