//! Integration tests: one binary to save link time (STYLE.md §9).
#![allow(clippy::needless_range_loop)]

mod arrays_properties;
mod buffer_objects;
mod conformance;
mod editor_demo;
mod eval_mesh;
mod glu_errors;
mod glu_mipmaps;
mod glu_project;
mod glu_quadrics;
mod glu_surfpoints;
mod glu_tess;
mod glu_tessellation;
mod glu_trimcases;
mod glut_loop;
mod glut_robustness;
mod glut_shapes;
mod glut_windows;
mod gpu_parity;
mod interactive_demo;
mod layout;
mod mesa_calls;
mod occlusion_queries;
mod picking_demo;
mod pixel_properties;
mod properties;
mod query_properties;
mod raster_images;
mod raster_modes;
mod rasterizers;
mod robustness;
mod shaders;
mod spec_errors;
mod tess_properties;
mod textbook;
