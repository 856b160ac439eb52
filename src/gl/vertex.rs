//! The vertex GL hands to the rest of the pipeline, and how an evaluated attribute lands in it.

use super::eval::Slot;

/// One vertex as GL hands it to the rest of the pipeline: object-space position (w not divided),
/// and the current (or evaluated) colour, normal and texture coordinate of unit 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Zeroable)]
pub struct Vertex {
    /// (x, y, z, w); `vertex3f` gives w = 1; `GL_MAP*_VERTEX_4` passes w through.
    pub position: [f32; 4],
    /// RGBA, not clamped here (GL clamps after lighting).
    pub color: [f32; 4],
    /// The normal (unit length only when it came from `GL_AUTO_NORMAL`).
    pub normal: [f32; 3],
    /// (s, t, r, q).
    pub tex_coord: [f32; 4],
}

impl Vertex {
    /// Writes an evaluated attribute (`glEvalCoord`'s result for one map) into the vertex.
    pub(crate) fn set_attribute(&mut self, slot: Slot, p: [f32; 4]) {
        match slot {
            Slot::Color4 => self.color = p,
            Slot::Normal => self.normal = [p[0], p[1], p[2]],
            Slot::TexCoord1 | Slot::TexCoord2 | Slot::TexCoord3 | Slot::TexCoord4 => {
                self.tex_coord = widen(p, slot.components());
            }
            Slot::Vertex3 => self.position = widen(p, 3),
            Slot::Vertex4 => self.position = p,
            Slot::Index => {}
        }
    }
}

/// Widens a k-component result to GL's 4-vector, filling the missing components with the
/// defaults (0, 0, 0, 1), as Mesa does when it evaluates into a vector initialised that way.
fn widen(p: [f32; 4], k: usize) -> [f32; 4] {
    let mut out = [0.0, 0.0, 0.0, 1.0];
    out[..k].copy_from_slice(&p[..k]);
    out
}
