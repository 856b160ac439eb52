//! `GL/gl.h`: the GL 1.x entry points `Gl` implements, one file per area.

mod arrays;
mod compressed;
mod eval;
mod feedback;
mod fragment;
mod fragments;
mod imaging;
mod immediate;
mod lighting;
mod lists;
mod matrix;
mod pixel_transfer;
mod pixels;
mod points;
mod queries;
mod raster_modes;
mod read_pixels;
mod select;
mod state;
mod texgen;
mod texture;
mod variants;
