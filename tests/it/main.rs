//! Integration tests: one binary to save link time (STYLE.md §9).
#![allow(clippy::needless_range_loop)]

mod conformance;
mod eval_mesh;
mod glu_errors;
mod glu_surfpoints;
mod glu_tessellation;
mod glu_trimcases;
mod glut_loop;
mod gpu_parity;
mod interactive_demo;
mod mesa_calls;
mod properties;
mod query_properties;
mod raster_images;
mod raster_modes;
mod rasterizers;
mod robustness;
mod shaders;
mod spec_errors;
mod textbook;
