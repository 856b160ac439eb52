//! Untrimmed surfaces the way GLU covers them when it does not take its domain-distance fast
//! path (`Subdivider::drawSurfaces` with the border loop of `makeBorderTrim`): each Bezier
//! patch's border sampled at its sidesteps, its inside on the grid of its interior steps,
//! joined by fans ([`super::slicer`]). In tessellator mode GLU evaluates the patches' primitives
//! when the surface ends, last patch first (`bezierPatchMeshListInsert` puts each new patch at
//! the head of its list); in renderer mode each patch is drawn as it comes.

use super::patches::{load_patch, restore_polygon_mode, save_polygon_mode};
use super::slicer::border::{RectLoop, SideRates};
use super::slicer::output::{render_pieces, tessellate_pieces};
use super::slicer::vertex::PatchVertices;
use super::slicer::{slice_rect, Interior, Piece};
use crate::gl::Gl;
use crate::glu::evaluation::patch_steps::{patch_steps, Net};
use crate::glu::evaluation::surface::{PatchGrid, Surface};
use crate::glu::model::object::NurbsObject;
use glam::Mat4;

/// One patch and the pieces covering it.
pub(crate) struct SlicedPatch {
    pub grid: PatchGrid,
    pub pieces: Vec<Piece>,
}

/// Every patch of the surface, u outer, sliced as GLU slices it; `None` when some patch is
/// sampled so finely that GLU would bisect it first (`Subdivider::samplingSplit`), which this
/// path does not reproduce.
pub(crate) fn slice_surface(obj: &NurbsObject, surface: &Surface) -> Option<Vec<SlicedPatch>> {
    let matrix = if obj.props.object_space() { Mat4::IDENTITY } else { obj.matrices.sampling() };
    let p = &surface.pos.patches;
    let mut out = Vec::new();
    for (a, &u) in p.uintervals.iter().enumerate() {
        for (b, &v) in p.vintervals.iter().enumerate() {
            let points = p.patch(a, b)?;
            let net = Net { points, k: surface.k, orders: (p.uorder, p.vorder) };
            let (u32_, v32) = ((u.0 as f32, u.1 as f32), (v.0 as f32, v.1 as f32));
            let [s, t] = patch_steps(&obj.props, &matrix, &net, (u32_.1 - u32_.0, v32.1 - v32.0));
            if s.needs_split || t.needs_split {
                return None;
            }
            // GLU `Subdivider::tessellation`: right and left sides at the v sidesteps, top and
            // bottom at the u sidesteps (index 1 where the other parameter is largest).
            let rates = SideRates { bottom: s.side[0], right: t.side[1], top: s.side[1], left: t.side[0] };
            let rect = RectLoop::new(u32_, v32, rates);
            let interior = Interior { du: s.step, dv: t.step, ulinear: p.uorder == 2, vlinear: p.vorder == 2 };
            let pieces = slice_rect(&rect, interior);
            out.push(SlicedPatch { grid: PatchGrid { u, v, nu: 0, nv: 0 }, pieces });
        }
    }
    Some(out)
}

/// The patches through the callbacks, last patch first.
pub(crate) fn tessellate_sliced(gl: &mut Gl, obj: &mut NurbsObject, surface: &Surface, patches: &[SlicedPatch]) {
    for patch in patches.iter().rev() {
        if let Some(maps) = PatchVertices::new(obj, surface, patch.grid.u, patch.grid.v) {
            tessellate_pieces(gl, obj, &maps, &patch.pieces);
        }
    }
}

/// The patches through the GL evaluators, each after its maps, in a `GL_EVAL_BIT` push with
/// the polygon mode saved (GLU `bgnmap2f`/`endmap2f`).
pub(crate) fn render_sliced(gl: &mut Gl, surface: &Surface, patches: &[SlicedPatch]) {
    let saved = save_polygon_mode(gl);
    for patch in patches {
        load_patch(gl, surface, &patch.grid);
        render_pieces(gl, &patch.pieces);
    }
    restore_polygon_mode(gl, saved);
}
