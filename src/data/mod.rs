//! Ready-made geometry for demos, examples and tests: data, not algorithms.
//!
//! - [`teapot`]: Newell's Utah teapot, 32 bicubic Bezier patches (GLUT's `glutSolidTeapot`
//!   draws the same surface from freeglut's 10 patches and their copies).

pub mod teapot;
