//! GLU: the NURBS interface (GLU 1.3 as SGI/Mesa GLU 9.0 implements it), quadrics
//! ([`quadric`]), mipmaps, `gluErrorString`, `gluGetString` and `gluCheckExtension`.
//! `gluOrtho2D`, `gluPerspective` and `gluLookAt` are methods of [`crate::gl::Gl`] next to the
//! matrix calls.
//!
//! A NURBS is reduced to Bezier pieces by knot insertion ([`crate::math::kernel::decompose_surface`]) and drawn
//! through the GL evaluators (`GLU_NURBS_RENDERER`) or handed to callbacks
//! (`GLU_NURBS_TESSELLATOR`), as GLU does.
//!
//! Four layers, each importing only those before it:
//! 1. `model`: what a NURBS object holds (its maps, trim pieces, properties, callbacks and
//!    nesting), with [`consts`] and [`glu_error_string`]'s table;
//! 2. `evaluation`: Bezier pieces of the maps, sampling, culling, the surface's patches and
//!    their grids, the row kernel and normals;
//! 3. `draw`: curves and surfaces, untrimmed and trimmed, through GL calls or the callbacks;
//! 4. `calls`: the `glu_*` methods of [`crate::gl::Gl`], GLU's entry points.
//!
//! GLU calls are methods of `Gl` (the porting rule), so `gl` holds the NURBS objects: the one
//! import from `gl` back into `glu`. Like GLU, which only calls GL, the drawing reaches GL state
//! through GL's own calls and queries (`glPushAttrib(GL_EVAL_BIT)`, `glGetIntegerv`, ...).

mod calls;
pub mod consts;
mod draw;
mod element;
mod errors;
mod evaluation;
mod halve_2d;
mod halve_3d;
mod memory;
mod mipmap;
mod mipmap_3d;
mod mipmap_levels;
mod model;
mod objects;
mod packed_pixel;
mod project;
pub mod quadric;
mod scale;
mod scale_3d;
mod strings;
mod tess;

pub(crate) use draw::trim_fallbacks;
pub use errors::glu_error_string;
pub use model::callbacks::{NurbsCallback, UserData};
pub use model::object::GLUnurbs;
pub(crate) use model::object::NurbsObject;
pub use model::targets::nurbs_point_components;
pub(crate) use objects::GluObjects;
pub use quadric::{GLUquadric, Quadric, QuadricSink};
pub use strings::{glu_check_extension, glu_get_string};
pub(crate) use tess::TessObject;
pub use tess::{GLUtesselator, TessCallback, TessData};
