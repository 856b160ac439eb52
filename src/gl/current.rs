//! The current attribute group (GL 1.1 spec §2.7; table 6.3): the colour, normal and texture
//! coordinate a vertex picks up, which `glColor`, `glNormal` and `glTexCoord` (`immediate.rs`,
//! `variants.rs`) set and `GL_CURRENT_BIT` saves. The group's other values have their areas:
//! the raster position `raster_pos.rs`, the index `color_index.rs`, the edge flag `arrays.rs`.

use super::consts::*;
use super::state_var::{put, row, Kind, StateVar};

/// The current values that a vertex picks up (GL 1.1 spec §2.7).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Current {
    pub color: [f32; 4],
    pub normal: [f32; 3],
    pub tex_coord: [f32; 4],
}

impl Default for Current {
    fn default() -> Self {
        Self { color: [1.0; 4], normal: [0.0, 0.0, 1.0], tex_coord: [0.0, 0.0, 0.0, 1.0] }
    }
}

/// The group's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_CURRENT_COLOR, 4, Kind::Normalized, |gl, o| put(o, &gl.server.current.color)),
    row(GL_CURRENT_TEXTURE_COORDS, 4, Kind::Float, |gl, o| put(o, &gl.server.current.tex_coord)),
    row(GL_CURRENT_NORMAL, 3, Kind::Normalized, |gl, o| put(o, &gl.server.current.normal)),
];
