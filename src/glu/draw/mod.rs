//! Layer 3 of GLU, the drawing: curves and surfaces, untrimmed and trimmed, as GL evaluator
//! calls (`GLU_NURBS_RENDERER`) or through the callbacks (`GLU_NURBS_TESSELLATOR`).
//! [`surface::draw_surface`] picks the way for a surface; [`curve::draw_curve`] draws a curve.

pub(crate) mod curve;
mod emit;
mod patches;
mod sliced;
pub(crate) mod slicer;
mod subdivided;
mod subdivider;
pub(crate) mod surface;
mod tessellate;
mod trimmed;

pub(crate) use trimmed::fallbacks as trim_fallbacks;
