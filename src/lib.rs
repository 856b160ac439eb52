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
//! Layers, each importing only those above it in this list:
//!
//! | module | what it holds |
//! |---|---|
//! | [`math`] | Bezier, B-spline and NURBS curves and patches, knots, the flat-slice kernels |
//! | [`tess`] | grids and trimmed domains into meshes; mesh export |
//! | [`gl`] | the GL 1.x state machine, one module per attribute group (each with its calls, list record, `glGet` rows and enables): errors, immediate mode, the vertex stage that feedback and both rasterisers share, evaluators, the recorded [`gl::Frame`] |
//! | [`glu`] | GLU: projections and the NURBS object (sampling, trimming, display modes, callbacks) |
//! | [`glut`] | GLUT's constants and the state behind its `Gl` methods |
//! | [`gll`], [`data`] | the textbook's `gll.h` helpers (public API only); demo data (the teapot) |
//! | [`render`] | drawing a frame: primitive assembly (clipping, wide lines, points, viewports); the CPU rasteriser ([`render::soft`], headless pictures with no device); PNG; the wgpu [`render::Renderer`] |
//! | `gpu` (crate-private) | wgpu: the device and read-back, the one WGSL evaluator, the rasterisers behind `Renderer` |
//! | `app` | the GLUT-like `App`: a window, or a headless PNG |
//!
//! One edge runs upward, by the porting rule: GLU and GLUT calls are methods of [`gl::Gl`]
//! (`gluNurbsSurface` is `gl.glu_nurbs_surface`), so `Gl` holds GLU's NURBS objects and GLUT's
//! state and those modules add `impl Gl` blocks. GLU itself reaches GL state only through what
//! GL offers (calls, queries, the attribute stack), as real GLU does. With
//! `--no-default-features` the crate is pure CPU Rust with no GPU or windowing dependency, and
//! still draws pictures ([`render::soft::render_frame`]).
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
