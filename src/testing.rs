//! Internals that the integration tests, benchmarks and examples reach, kept out of the
//! documented API (`#[doc(hidden)]`): nothing here is stable or meant for users.

// --- GPU evaluator and rasteriser internals (layouts, packing, pipelines) ---

// --- tessellation internals (the row scheduler and kernel, trimmed-domain plans) ---

// --- GLU internals ---
// None: the tests, benchmarks and examples reach GLU through its public `glu_*` calls.

// --- image comparison used by the conformance tests and the gallery ---
