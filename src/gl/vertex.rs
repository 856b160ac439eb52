//! The vertex GL hands to the rest of the pipeline (how an evaluated attribute lands in it is
//! the evaluators' business: `eval/target.rs`).

/// One vertex as GL hands it to the rest of the pipeline: object-space position (w not divided),
/// the current (or evaluated) colour, normal and texture coordinate of unit 0, and the current
/// secondary colour (GL 1.4 §2.7; no evaluator map sets it).
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
    /// `glSecondaryColor`'s RGB and 1, not clamped here.
    pub secondary_color: [f32; 4],
    /// GL 1.4's `glFogCoord`: what fog is computed from under `GL_FOG_COORD_SRC`
    /// `GL_FOG_COORD` (no evaluator map sets it).
    pub fog_coord: f32,
}
