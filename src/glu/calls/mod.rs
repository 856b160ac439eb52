//! Layer 4 of GLU: its entry points, methods of [`Gl`](crate::gl::Gl) with a `glu_` prefix (the
//! porting rule). They keep GLU's nesting rules, automatic begin/end, validation order and error
//! numbers (`nurbsinterfac.cc`, `nurbstess.cc`; spec 2.8), and draw through the layers below.

mod curve;
mod setup;
mod surface;
mod validate;
