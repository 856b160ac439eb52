//! `GL/glu.h`: projections, mipmaps, error strings, quadrics and the NURBS interface.

mod callbacks;
mod misc;
mod nurbs;
mod quadric;
