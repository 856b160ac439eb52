//! `GL/glu.h`: projections, mipmaps, error strings and the NURBS interface.

mod callbacks;
mod misc;
mod nurbs;
mod project;
