//! GLU: the NURBS interface (GLU 1.3 as SGI/Mesa GLU 9.0 implements it) and `gluErrorString`.
//! `gluOrtho2D`, `gluPerspective` and `gluLookAt` are methods of [`crate::gl::Gl`] next to the
//! matrix calls.
//!
//! A NURBS is reduced to Bezier pieces by knot insertion ([`crate::math::kernel::decompose_surface`]) and drawn
//! through the GL evaluators (`GLU_NURBS_RENDERER`) or handed to callbacks
//! (`GLU_NURBS_TESSELLATOR`), as GLU does.

mod callbacks;
pub mod consts;
mod draw;
mod errors;
mod nurbs;
mod pieces;
mod props;
mod sampling;
mod trimmed;

pub use callbacks::{NurbsCallback, UserData};
pub use consts::*;
pub use errors::glu_error_string;
pub use nurbs::GLUnurbs;
pub(crate) use nurbs::NurbsObject;
pub use props::{NurbsProperties, SamplingMatrices};
