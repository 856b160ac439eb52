//! Ready-made geometry for demos, examples and tests: data, not algorithms.
//!
//! - [`teapot`]: Newell's Utah teapot, 32 bicubic Bezier patches (GLUT's `glutSolidTeapot`
//!   draws the same surface).

pub mod teapot;
