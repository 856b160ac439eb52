//! Drawing a recorded [`Frame`](crate::gl::Frame): the CPU vertex stage and primitive
//! assembly (always available, testable without a GPU), and the wgpu rasteriser (feature `gpu`).

mod assemble;
mod shade;

pub use assemble::{assemble, Batch, DrawList, Op, RasterVertex, Topology};
