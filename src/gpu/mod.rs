//! Everything that runs on wgpu (feature `gpu`): one evaluator, two rasterisers, the renderer.
//!
//! Files, each one concept, with imports running one way (never back up this list):
//!
//! | file | holds | imports |
//! |---|---|---|
//! | `device.rs` | adapter and device set-up, the device's error slot, the one read-back, [`RenderError`] | - |
//! | `layout.rs` | the WGSL sources and the `#[repr(C)]` twins of their structs, with layout tests against naga | - |
//! | `pack.rs` | jobs, control points and Bernstein tables packed for one dispatch (CPU only) | `layout` |
//! | `evaluate.rs` | the compute pipeline of `shaders/eval_mesh.wgsl`; read-backs for the typed API and the tests | `device`, `layout`, `pack` |
//! | `raster.rs` | the one raster-pipeline builder (topology, depth test, culling) | - |
//! | `frame_raster.rs` | pipelines for the CPU's assembled vertices (`shaders/raster.wgsl`) | `device`, `layout`, `raster` |
//! | `draw_uniform.rs` | GL's state as the mesh rasteriser's uniform | `layout` |
//! | `mesh_raster.rs` | a frame's deferred meshes: one evaluator dispatch, drawn by `shaders/mesh_raster.wgsl` | `device`, `draw_uniform`, `evaluate`, `layout`, `pack`, `raster` |
//! | `passes.rs` | render passes split at GL's clears, scissors from GL's viewports | - |
//! | `target.rs` | the headless colour and depth target, read back | `device`, `raster` |
//! | `timer.rs` | compute passes' GPU time from timestamp queries, for benchmarks | `device` |
//! | `renderer.rs` | [`Renderer`], and [`tessellate_patches`] on it | `device`, `evaluate`, `frame_raster`, `mesh_raster`, `passes`, `target` |
//!
//! Below the module: `gl` (the recorded frame), `math`, `tess` (the mesh type) and the CPU
//! stages of `render` (assembly). Users reach the renderer through [`crate::render`]; the rest
//! is crate-private, with what tests, benchmarks and examples drive re-exported from the
//! hidden `testing` module.

mod blend;
mod clear_quads;
mod device;
mod draw_uniform;
mod evaluate;
mod fallback;
mod frame_raster;
mod layout;
mod mesh_raster;
mod pack;
mod passes;
mod raster;
mod renderer;
mod target;
mod textures;
mod timer;

pub use device::{Gpu, RenderError};
pub use evaluate::{evaluate_job_indices, evaluate_jobs, EvaluatedMeshes, Evaluator};
pub use layout::{GpuMapDesc, GpuMeshJob, EVAL_MESH_WGSL, FRAGMENT_WGSL, MESH_RASTER_WGSL, RASTER_WGSL, VERTEX_BYTES};
pub use pack::PackedJobs;
#[cfg(feature = "window")]
pub(crate) use renderer::Attachments;
pub use renderer::{tessellate_patches, Renderer};
pub use timer::PassTimer;

#[cfg(feature = "window")]
pub(crate) use device::backend_order;
// `App`'s profiled run (features gpu + png) and nothing else outside this module.
#[cfg(feature = "png")]
pub(crate) use device::first_adapter;
#[cfg(feature = "window")]
pub(crate) use raster::DEPTH_FORMAT;
