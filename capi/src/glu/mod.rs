//! `GL/glu.h`: projections, mipmaps, error strings, quadrics, the NURBS interface and the
//! polygon tessellator.

mod callbacks;
mod misc;
mod nurbs;
mod project;
mod quadric;
mod tess;
