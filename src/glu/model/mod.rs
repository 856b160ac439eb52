//! Layer 1 of GLU, the data model: what a NURBS object holds between calls. Nothing here
//! evaluates or draws, and nothing imports the other GLU layers.

pub(crate) mod callbacks;
pub(crate) mod maps;
pub(crate) mod object;
pub(crate) mod props;
pub(crate) mod targets;
