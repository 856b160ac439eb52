//! The NURBS object (`GLUnurbs*`): its handle, and the state GLU keeps in it between calls
//! (properties, callbacks, sampling matrices, and where it is in the begin/end nesting;
//! `nurbsinterfac.cc`).

use super::callbacks::Callbacks;
use super::maps::{CurveMap, SurfaceDef, TrimPiece};
use super::props::{NurbsProperties, SamplingMatrices};
use crate::glu::consts::GLU_NURBS_ERROR1;

/// A NURBS object (`GLUnurbs*`): a copyable handle into its [`Gl`](crate::gl::Gl) context.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GLUnurbs(pub(crate) usize);

/// Where the object is in the begin/end nesting.
#[derive(Debug, Default)]
pub(crate) struct Nesting {
    pub curve: Option<Vec<CurveMap>>,
    /// Pieces of a curve group inside a trim (`gluBeginCurve` within `gluBeginTrim`).
    pub trim_group: Option<Vec<TrimPiece>>,
    pub surface: Option<SurfaceDef>,
    /// The surface was begun by `gluBeginTrim` (GLU's `inSurface == 2`): the next
    /// `gluNurbsSurface` ends it.
    pub auto_surface: bool,
    pub trim: Option<Vec<TrimPiece>>,
    pub curve_valid: bool,
}

/// The state of one NURBS object.
pub(crate) struct NurbsObject {
    pub props: NurbsProperties,
    pub callbacks: Callbacks,
    pub matrices: SamplingMatrices,
    /// Two buffers of evaluated tessellator vertices (one filled while the other is issued),
    /// kept between surfaces so that memory is reused.
    pub vertex_scratch: [Vec<[f32; 5]>; 2],
    pub nesting: Nesting,
}

impl std::fmt::Debug for NurbsObject {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("NurbsObject").field("props", &self.props).field("nesting", &self.nesting).finish()
    }
}

impl NurbsObject {
    /// A new object in GLU's initial state.
    pub fn new() -> Self {
        Self {
            props: NurbsProperties::DEFAULT,
            callbacks: Callbacks::default(),
            matrices: SamplingMatrices::IDENTITY,
            vertex_scratch: [Vec::new(), Vec::new()],
            nesting: Nesting::default(),
        }
    }

    /// Reports `GLU_NURBS_ERRORn` through the error callback (errors are not latched).
    pub fn nurbs_error(&mut self, n: u32) {
        self.callbacks.error(GLU_NURBS_ERROR1 + n - 1);
    }
}
