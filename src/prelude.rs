//! `use gleval::prelude::*;` brings in the context, the C type aliases and every GL constant,
//! so that a ported program reads like its C original.

#[cfg(all(feature = "gpu", feature = "png"))]
pub use crate::app::App;
pub use crate::gl::consts::*;
pub use crate::gl::types::*;
pub use crate::gl::{Frame, Gl, Primitive, Vertex};
pub use crate::gll;
pub use crate::glu::consts::*;
pub use crate::glu::{glu_error_string, GLUnurbs, GLUquadric, NurbsCallback};
pub use crate::glu::{GLUtesselator, TessCallback};
pub use crate::glut::consts::*;
pub use crate::glut::fonts::{GlutBitmapFont, GlutCharacter, GlutStrokeFont};
