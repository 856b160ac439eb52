//! A vertex of an assembled primitive, between the vertex stage and the rasteriser: the unit
//! that clipping, stippling and polygon offset cut and move.

use glam::Vec4;

/// A shaded vertex with the colour chosen for its primitive (face, flat shading).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Corner {
    /// Clip coordinates (GL's, z in [−w, w]).
    pub clip: Vec4,
    /// Eye coordinates, where clip planes are tested (GL 1.1 §2.11).
    pub eye: Vec4,
    pub color: Vec4,
    /// The secondary colour the colour sum adds after texturing (zero without one).
    pub secondary: Vec4,
    pub tex: Vec4,
    /// Units 1 to 7's texture coordinates (zero but for the units that draw).
    pub units: [Vec4; 7],
    pub fog: f32,
    /// Polygon offset in window depth units ([0, 1]), added after the depth range.
    pub depth_offset: f32,
    /// The coordinates a smooth point's or line's coverage is computed from (`smooth`).
    pub aa: Vec4,
}

impl Corner {
    /// A white corner at (x, y, 0, 1) in clip and eye space alike, for tests.
    #[cfg(test)]
    pub fn at(x: f32, y: f32) -> Corner {
        let p = Vec4::new(x, y, 0.0, 1.0);
        Corner {
            clip: p,
            eye: p,
            color: Vec4::ONE,
            secondary: Vec4::ZERO,
            tex: Vec4::ZERO,
            units: [Vec4::ZERO; 7],
            fog: 0.0,
            depth_offset: 0.0,
            aa: Vec4::ZERO,
        }
    }

    /// The point a fraction `t` of the way from `self` to `other`, every attribute linear in
    /// clip space (GL 1.1 §2.12: clipped attributes are interpolated so).
    pub fn lerp(self, other: Corner, t: f32) -> Corner {
        Corner {
            clip: self.clip.lerp(other.clip, t),
            eye: self.eye.lerp(other.eye, t),
            color: self.color.lerp(other.color, t),
            secondary: self.secondary.lerp(other.secondary, t),
            tex: self.tex.lerp(other.tex, t),
            units: std::array::from_fn(|k| self.units[k].lerp(other.units[k], t)),
            fog: self.fog + (other.fog - self.fog) * t,
            depth_offset: self.depth_offset + (other.depth_offset - self.depth_offset) * t,
            aa: self.aa.lerp(other.aa, t),
        }
    }
}
