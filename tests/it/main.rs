//! Integration tests: one binary to save link time (STYLE.md §9).

mod eval_mesh;
mod mesa_calls;
mod spec_errors;
