//! `GL/glu.h`: projections, mipmaps, error strings, the NURBS interface and the polygon
//! tessellator.

mod callbacks;
mod misc;
mod nurbs;
mod tess;
mod project;
