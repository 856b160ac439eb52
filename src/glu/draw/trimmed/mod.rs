//! Trimmed NURBS surfaces: GLU's own tessellation where [`super::subdivided`] reproduces it;
//! otherwise the trim loops become (u, v) polylines, the retained region is
//! triangulated with the surface's sampling grid inside ([`crate::tess::trim`]), and every
//! vertex is evaluated on the exact surface. Loop errors are GLU's numbers 28, 29, 31 and 18.

mod domain;
mod gpu;
mod render;
mod tessellate;
mod values;

use super::sliced;
use super::subdivided::slice_trimmed;
use super::subdivider::Failure;
use crate::gl::Gl;
use crate::glu::evaluation::sampling::Sampler;
use crate::glu::evaluation::surface::Surface;
use crate::glu::model::maps::TrimPiece;
use crate::glu::model::object::NurbsObject;
use crate::tess::trim::TrimLoop;

thread_local! {
    /// How many trimmed surfaces this thread drew by gleval's own triangulation.
    static FALLBACKS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// How many trimmed surfaces this thread has drawn by gleval's own triangulation (regions whose
/// sampling GLU itself mishandles), for the tests that count them.
pub(crate) fn fallbacks() -> usize {
    FALLBACKS.with(std::cell::Cell::get)
}

/// Draws a trimmed surface.
pub(super) fn draw_trimmed(
    gl: &mut Gl,
    obj: &mut NurbsObject,
    surface: &Surface,
    loops: &[Vec<TrimPiece>],
    sampler: &Sampler,
    tessellate: bool,
) {
    let steps = surface.patches(sampler);
    let (us, vs) = domain::grid_lines(&steps);
    let Some(trim_loops) = domain::trim_loops(obj, loops, &steps) else { return };
    match slice_trimmed(obj, surface, loops) {
        Ok(patches) => {
            let patches = sliced::drawable(obj, patches);
            return if tessellate {
                sliced::tessellate_sliced(gl, obj, surface, &patches)
            } else {
                sliced::render_sliced(gl, obj, surface, &patches)
            };
        }
        Err(Failure::Error(n)) => return obj.nurbs_error(n),
        Err(Failure::Unsupported) => FALLBACKS.with(|n| n.set(n.get() + 1)), // gleval's own triangulation below
    }
    let region = Region { surface, loops: &trim_loops, domain: surface.domain(), us: &us, vs: &vs };
    if tessellate {
        tessellate::tessellate_trimmed(gl, obj, &region);
    } else {
        render::render_trimmed(gl, obj, &region);
    }
}

/// A trimmed surface left to gleval's own triangulation, as both modes take it
/// ([`render::render_trimmed`], [`tessellate::tessellate_trimmed`]): the surface over its
/// `domain`, the trim loops as (u, v) polylines, and the sampling grid's lines `us` and `vs`.
#[derive(Clone, Copy)]
struct Region<'a> {
    surface: &'a Surface,
    loops: &'a [TrimLoop],
    domain: [f64; 4],
    us: &'a [f64],
    vs: &'a [f64],
}
