//! Internals that the integration tests, benchmarks and examples reach, kept out of the
//! documented API (`#[doc(hidden)]`): nothing here is stable or meant for users.

// --- GPU evaluator and rasteriser internals (layouts, packing, pipelines) ---
#[cfg(feature = "gpu")]
pub use crate::gpu::{
    evaluate_job_indices, evaluate_jobs, EvaluatedMeshes, Evaluator, Gpu, GpuMapDesc, GpuMeshJob, PackedJobs,
    PassTimer, EVAL_MESH_WGSL, FRAGMENT_WGSL, MESH_RASTER_WGSL, RASTER_WGSL, VERTEX_BYTES,
};

// --- tessellation internals: the f64 grid evaluator, the oracle of the GPU parity tests ---
pub use crate::tess::grid::{eval_grid2, Grid2, MapView};

// --- GLU internals ---
// The tests, benchmarks and examples reach GLU through its public `glu_*` calls; the one
// window into it: how many trimmed surfaces this thread drew by gleval's own triangulation.
pub fn trim_fallbacks() -> usize {
    crate::glu::trim_fallbacks()
}

// --- image comparison used by the conformance tests and the gallery ---
#[cfg(all(feature = "gpu", feature = "png"))]
pub mod compare {
    //! The image metric (`render/compare.rs`).
    pub use crate::render::compare::*;
}
