//! # gleval-c: the C ABI of gleval
//!
//! A C program written for OpenGL 1.x, GLU and GLUT includes `<GL/gl.h>`, `<GL/glu.h>` and
//! `<GL/glut.h>` from `capi/include` and links `libgleval`: the same source that runs on a
//! legacy GL driver then draws through wgpu, in a window or headless to PNG (`--png PATH`).
//!
//! This crate is a thin skin over [`gleval::gl::Gl`] and [`gleval::app::App`]; it holds no GL
//! rule of its own. Each `extern "C"` function
//! - finds the thread's current context (GL's is thread-local, so is ours: [`context`]);
//! - turns C pointers into slices of the length the call's own arguments say GL reads
//!   (`order × stride`, the image size under the unpack modes), the caller's promise as in
//!   GL; a NULL array becomes an empty slice, which `Gl` answers with `GL_INVALID_VALUE`
//!   ([`memory`]);
//! - forwards to the `Gl` method of the same name (the porting rule, `glMap1f` → `map1f`);
//! - never lets a panic unwind into C: it is caught and becomes `GL_OUT_OF_MEMORY`
//!   ([`boundary`]).
//!
//! Files follow the headers' areas: `gl/` (state, immediate mode, matrices, evaluators,
//! lighting, lists, textures, pixels, fragments, feedback), `glu/` (projections, NURBS,
//! callbacks, mipmaps), `glut/` (the main loop over `App`, callbacks, fonts and the teapot),
//! and `osmesa.rs` (`GL/osmesa.h`'s context calls, for off-screen programs such as the
//! scripted-call interpreter of `tests/reference/calls`).

#[macro_use]
pub mod boundary;
mod configs;
pub mod context;
mod dl;
mod egl;
mod launcher;
mod live_contexts;
pub mod memory;
mod strings;
mod surface;
mod x11;

mod gl;
mod glew;
mod glu;
mod glut;
mod glx;
mod osmesa;
