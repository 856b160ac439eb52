//! Internals that the integration tests, benchmarks and examples reach, kept out of the
//! documented API (`#[doc(hidden)]`): nothing here is stable or meant for users.

// --- GPU evaluator and rasteriser internals (layouts, packing, pipelines) ---
#[cfg(feature = "gpu")]
pub use crate::gpu::{
    evaluate_job_indices, evaluate_jobs, EvaluatedMeshes, Evaluator, Gpu, GpuMapDesc, GpuMeshJob, PackedJobs,
    EVAL_MESH_WGSL, MESH_RASTER_WGSL, RASTER_WGSL, VERTEX_BYTES,
};

// --- tessellation internals (the row scheduler and kernel, trimmed-domain plans) ---

// --- GLU internals ---

// --- image comparison used by the conformance tests and the gallery ---
