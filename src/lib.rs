//! # gleval
//!
//! The OpenGL 1.x evaluators (`glMap1`/`glMap2`, `glMapGrid`, `glEvalMesh`, `glEvalCoord`,
//! `glEvalPoint`) and the GLU NURBS interface, re-created in Rust.
//!
//! Two ways in:
//! - the **GL façade**, [`gl::Gl`]: a ported C program reads line for line like the original
//!   (`glMap2f(...)` becomes `gl.map2f(...)`), sets GL's error flag exactly as Mesa does, and
//!   records what it draws into a [`gl::Frame`] that tests read and the renderer draws;
//! - the **typed API** in [`math`]: Bezier and B-spline curves and patches with `Result` errors,
//!   no GL state at all.
//!
//! Layers, each depending only on those above it: `math` → `tess` → `gl` (→ `glu`, whose
//! calls are `Gl` methods, the one upward edge) → `gll`, `render` (the CPU stages of drawing)
//! → the crate-private `gpu` module (wgpu: the evaluator, the rasterisers, the
//! `render::Renderer`) → `app`. With `--no-default-features` the crate is pure CPU Rust with
//! no GPU or windowing dependency.
#![forbid(unsafe_code)]
#![warn(missing_docs)]
// Numeric kernels index several component arrays in lockstep; iterator chains would hide that.
#![allow(clippy::needless_range_loop)]

#[cfg(all(feature = "gpu", feature = "png"))]
pub mod app;
pub mod data;
pub mod gl;
pub mod gll;
pub mod glu;
pub mod glut;
#[cfg(feature = "gpu")]
mod gpu;
pub mod math;
pub mod prelude;
pub mod render;
pub mod tess;
#[doc(hidden)]
pub mod testing;
#[cfg(feature = "window")]
mod window;
