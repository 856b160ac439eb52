//! GLU's polygon tessellator (`gluNewTess` ... `gluTessEndPolygon`, and GLU 1.0's
//! `gluBeginPolygon`/`gluNextContour`/`gluEndPolygon`), written after SGI's libtess as GLU 9.0
//! ships it, so that it hands the callbacks the same primitives, vertices and combine calls
//! in the same order.
//!
//! The pipeline of `gluTessEndPolygon`:
//! 1. `object`: the contours as collected (the first one cached for the quick path of a
//!    single fan-shaped contour, `render::render_cache`);
//! 2. `normal`: the plane's normal and the projection to `(s, t)`;
//! 3. `sweep` and `sweep_fix` over `mesh`, with the event `queue` and the sweep line's
//!    `dict`: the planar subdivision with every face marked inside or outside by the winding
//!    rule, inside faces monotone, intersections made vertices through the combine callback;
//! 4. `mono`: monotone faces split into triangles, or only the boundary kept;
//! 5. `render`: fans, strips and lone triangles (or line loops) through `callbacks`.
//!
//! The geometric predicates are in `geom`. `GLU_TESS_TOLERANCE` is kept and answered but,
//! as in GLU, does not change the result (libtess merges only vertices at exactly the same
//! place).

pub(crate) mod callbacks;
mod calls;
mod dict;
mod geom;
mod mesh;
mod mono;
mod normal;
mod object;
mod queue;
mod render;
mod sweep;
mod sweep_fix;

pub use callbacks::{TessCallback, TessData};
pub use object::GLUtesselator;
pub(crate) use object::TessObject;
