//! `GL/gl.h`: the GL 1.x entry points `Gl` implements, one file per area.

mod eval;
mod feedback;
mod fragment;
mod fragments;
mod immediate;
mod lighting;
mod lists;
mod matrix;
mod pixels;
mod raster_modes;
mod read_pixels;
mod state;
mod texgen;
mod texture;
mod variants;
