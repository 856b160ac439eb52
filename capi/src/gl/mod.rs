//! `GL/gl.h`: the GL 1.x entry points `Gl` implements, one file per area.

mod arrays;
mod eval;
mod feedback;
mod fragment;
mod fragments;
mod immediate;
mod lighting;
mod lists;
mod matrix;
mod multitexture;
mod pixel_transfer;
mod pixels;
mod queries;
mod raster_modes;
mod read_pixels;
mod select;
mod state;
mod texgen;
mod texture;
mod variants;
