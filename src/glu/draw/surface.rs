//! Surfaces (`gluEndSurface`): culling, the patches and their grids, then the trimmed or the
//! untrimmed way, through GL calls or the callbacks.

use super::{sliced, tessellate, trimmed};
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::evaluation::culling::culled;
use crate::glu::evaluation::sampling::Sampler;
use crate::glu::evaluation::surface::{PatchGrid, Surface};
use crate::glu::model::maps::SurfaceDef;
use crate::glu::model::object::NurbsObject;
use crate::glu::model::targets::is_position;

/// Draws a surface (`gluEndSurface`).
pub(crate) fn draw_surface(gl: &mut Gl, obj: &mut NurbsObject, def: &SurfaceDef) {
    if def.maps.is_empty() {
        return; // GLU ends an empty surface silently.
    }
    let Some(position) = def.maps.iter().rev().find(|m| is_position(m.target)) else {
        return obj.nurbs_error(8);
    };
    if culled(obj, &position.points, position.k) {
        return;
    }
    let Some(surface) = Surface::new(obj, def) else { return };
    let sampler = Sampler::new(obj.props, &obj.matrices);
    let tessellate = obj.props.nurbs_mode == GLU_NURBS_TESSELLATOR;
    if !def.loops.is_empty() {
        return trimmed::draw_trimmed(gl, obj, &surface, &def.loops, &sampler, tessellate);
    }
    // GLU's fast path is taken for domain-distance sampling unless outlining patches.
    if obj.props.sampling_method != GLU_DOMAIN_DISTANCE || obj.props.display_mode == GLU_OUTLINE_PATCH {
        let sliced = sliced::drawable(obj, sliced::slice_surface(obj, &surface));
        return if tessellate {
            sliced::tessellate_sliced(gl, obj, &surface, &sliced)
        } else {
            sliced::render_sliced(gl, obj, &surface, &sliced)
        };
    }
    let patches = drawable_patches(obj, &surface, &sampler);
    if tessellate {
        tessellate::tessellate_patches(gl, obj, &surface, &patches);
    } else {
        sliced::render_sliced(gl, obj, &surface, &sliced::grid_patches(&patches));
    }
}

/// The patches with their grids, less those too large to draw.
///
/// A patch sampled beyond the façade's mesh limit (a weight near zero under path-length
/// sampling asks for 2^14 segments a side) would fail in glEvalMesh2 with a GL error, or
/// allocate gigabytes in tessellator mode: GLU's own convention is to report
/// GLU_OUT_OF_MEMORY through the error callback. The other patches are drawn.
fn drawable_patches(obj: &mut NurbsObject, surface: &Surface, sampler: &Sampler) -> Vec<PatchGrid> {
    let mut patches = surface.patches(sampler);
    let before = patches.len();
    patches.retain(|patch| patch.points() <= crate::tess::MAX_MESH_VERTICES);
    if patches.len() < before {
        obj.callbacks.error(GLU_OUT_OF_MEMORY);
    }
    patches
}
