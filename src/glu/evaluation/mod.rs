//! Layer 2 of GLU, the evaluation: the maps as Bezier pieces, how finely each piece is sampled,
//! culling, the position map's patches with their grids, and the values on them (the row
//! kernel's vertices, normals, trim curves as polylines). Nothing here calls GL or a callback.

pub(crate) mod culling;
pub(crate) mod kernel;
pub(crate) mod machine;
pub(crate) mod normals;
pub(crate) mod patch_steps;
pub(crate) mod pieces;
pub(crate) mod sampling;
pub(crate) mod surface;
pub(crate) mod to_bezier;
pub(crate) mod trim_curves;
