//! The current attribute group (GL 1.1 spec §2.7; table 6.3): the colour, normal and texture
//! coordinate a vertex picks up, and GL 1.4's secondary colour and fog coordinate, which `glColor`, `glNormal`,
//! `glTexCoord`, `glSecondaryColor` and `glFogCoord` (`immediate.rs`, `variants.rs`) set and `GL_CURRENT_BIT` saves. The group's other values have their areas:
//! the raster position `raster_pos.rs`, the index `color_index.rs`, the edge flag `arrays.rs`.

use super::consts::*;
use super::state_var::{put, row, Kind, StateVar};

/// The current values that a vertex picks up (GL 1.1 spec §2.7).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Current {
    pub color: [f32; 4],
    pub normal: [f32; 3],
    /// Unit 0's texture coordinates.
    pub tex_coord: [f32; 4],
    /// Units 1 to 7's (GL 1.3 §2.7: each unit has its current texture coordinates).
    pub unit_tex_coords: [[f32; 4]; super::units::MAX_TEXTURE_UNITS - 1],
    /// GL 1.4's secondary colour: (r, g, b, 1) (a size-4 array gives the alpha), initially
    /// (0, 0, 0, 1) as Mesa answers.
    pub secondary_color: [f32; 4],
    /// GL 1.4's fog coordinate (`glFogCoord`), initially 0.
    pub fog_coord: f32,
}

impl Default for Current {
    fn default() -> Self {
        Self {
            color: [1.0; 4],
            normal: [0.0, 0.0, 1.0],
            tex_coord: [0.0, 0.0, 0.0, 1.0],
            unit_tex_coords: [[0.0, 0.0, 0.0, 1.0]; super::units::MAX_TEXTURE_UNITS - 1],
            secondary_color: [0.0, 0.0, 0.0, 1.0],
            fog_coord: 0.0,
        }
    }
}

impl Current {
    /// Unit `unit`'s texture coordinates (a unit beyond the fixed-function ones: unit 0's, never
    /// asked for, since the queries refuse it).
    pub(crate) fn tex_coord_of(&self, unit: usize) -> [f32; 4] {
        match unit {
            1..=7 => self.unit_tex_coords[unit - 1],
            _ => self.tex_coord,
        }
    }
}

/// The group's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_CURRENT_COLOR, 4, Kind::Normalized, |gl, o| put(o, &gl.server.current.color)),
    row(GL_CURRENT_TEXTURE_COORDS, 4, Kind::Float, |gl, o| put(o, &gl.server.current.tex_coord_of(gl.active_unit()))),
    row(GL_CURRENT_NORMAL, 3, Kind::Normalized, |gl, o| put(o, &gl.server.current.normal)),
    row(GL_CURRENT_SECONDARY_COLOR, 4, Kind::Normalized, |gl, o| put(o, &gl.server.current.secondary_color)),
    row(GL_CURRENT_FOG_COORD, 1, Kind::Float, |gl, o| o[0] = gl.server.current.fog_coord.into()),
];

#[cfg(test)]
mod tests {
    use super::super::Gl;
    use super::*;

    /// `glPopAttrib(GL_CURRENT_BIT)` restores the secondary colour: Mesa 22.3 does in a plain
    /// program (glSecondaryColor3f(0.5, ...), push, glSecondaryColor3f(1, 0, 0), pop reads
    /// back 0.5; the call scripts cannot show it, see `color_sum.calls`).
    #[test]
    fn current_bit_saves_the_secondary_colour() {
        let mut gl = Gl::new(4, 4);
        gl.secondary_color3f(0.5, 0.5, 0.5);
        gl.push_attrib(GL_CURRENT_BIT);
        gl.secondary_color3f(1.0, 0.0, 0.0);
        gl.pop_attrib();
        let mut v = [0.0; 4];
        gl.get_floatv(GL_CURRENT_SECONDARY_COLOR, &mut v);
        assert_eq!(v, [0.5, 0.5, 0.5, 1.0]);
    }

    /// `glPopAttrib(GL_CURRENT_BIT)` restores the fog coordinate: Mesa 22.3 does in a plain
    /// program (glFogCoordf(0.5), push, glFogCoordf(9), pop reads back 0.5).
    #[test]
    fn current_bit_saves_the_fog_coordinate() {
        let mut gl = Gl::new(4, 4);
        gl.fog_coordf(0.5);
        gl.push_attrib(GL_CURRENT_BIT);
        gl.fog_coordf(9.0);
        gl.pop_attrib();
        let mut v = [0.0];
        gl.get_floatv(GL_CURRENT_FOG_COORD, &mut v);
        assert_eq!(v, [0.5]);
    }
}
