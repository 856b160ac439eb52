//! The polygon offset (GL 1.1 spec §3.5.5; `glPolygonOffset` is the polygon group's,
//! `polygon.rs`): a depth offset for polygons drawn filled, as lines or as points, each mode
//! with its own enable. The renderer adds it to each polygon's window
//! depth (`render::offset`).

use super::consts::*;
use super::types::*;
use super::Gl;

/// The offset a polygon is drawn with: `factor · DZ + units · r` (§3.5.5), for the polygon
/// modes whose enable is on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolygonOffset {
    /// The factor of the polygon's depth slope.
    pub factor: f32,
    /// The multiple of the depth buffer's smallest resolvable difference.
    pub units: f32,
    /// `GL_POLYGON_OFFSET_POINT`, `_LINE`, `_FILL` enabled, in that order.
    pub modes: [bool; 3],
}

impl PolygonOffset {
    /// Whether polygons drawn in `mode` (`GL_POINT`, `GL_LINE`, `GL_FILL`) are offset.
    #[must_use]
    pub fn applies_to(&self, mode: GLenum) -> bool {
        match mode {
            GL_POINT => self.modes[0],
            GL_LINE => self.modes[1],
            _ => self.modes[2],
        }
    }
}

impl Gl {
    /// Whether a clip plane, polygon offset or line stipple is on (the CPU assembler's work).
    pub(crate) fn raster_modes_on(&self) -> bool {
        self.enabled_polygon_offset().is_some()
            || self.enabled_line_stipple().is_some()
            || self.enabled_polygon_stipple().is_some()
            || !self.enabled_clip_planes().is_empty()
    }

    /// The offset while any of its three enables is on.
    pub(crate) fn enabled_polygon_offset(&self) -> Option<PolygonOffset> {
        let modes =
            [GL_POLYGON_OFFSET_POINT, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_FILL].map(|c| self.capability(c));
        let (factor, units) = self.server.polygon.offset;
        modes.contains(&true).then_some(PolygonOffset { factor, units, modes })
    }
}
