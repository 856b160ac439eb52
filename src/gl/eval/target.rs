//! The 18 evaluator targets and their component counts (GL 1.2 spec table 5.1; Mesa
//! `_mesa_evaluator_components`).

use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::vertex::Vertex;

/// The attribute a map produces; the discriminant is the offset from `GL_MAP1_COLOR_4`
/// (or `GL_MAP2_COLOR_4`), which is how GL numbers the targets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Slot {
    /// `GL_MAP*_COLOR_4`.
    Color4 = 0,
    /// `GL_MAP*_INDEX` (stored and queryable, never drawn, as in Mesa).
    Index = 1,
    /// `GL_MAP*_NORMAL`.
    Normal = 2,
    /// `GL_MAP*_TEXTURE_COORD_1`.
    TexCoord1 = 3,
    /// `GL_MAP*_TEXTURE_COORD_2`.
    TexCoord2 = 4,
    /// `GL_MAP*_TEXTURE_COORD_3`.
    TexCoord3 = 5,
    /// `GL_MAP*_TEXTURE_COORD_4`.
    TexCoord4 = 6,
    /// `GL_MAP*_VERTEX_3`.
    Vertex3 = 7,
    /// `GL_MAP*_VERTEX_4`.
    Vertex4 = 8,
}

impl Slot {
    pub(crate) const COUNT: usize = 9;
    pub(crate) const ALL: [Slot; Slot::COUNT] = [
        Slot::Color4,
        Slot::Index,
        Slot::Normal,
        Slot::TexCoord1,
        Slot::TexCoord2,
        Slot::TexCoord3,
        Slot::TexCoord4,
        Slot::Vertex3,
        Slot::Vertex4,
    ];

    /// Components per control point (k).
    #[must_use]
    pub fn components(self) -> usize {
        [4, 1, 3, 1, 2, 3, 4, 3, 4][self as usize]
    }

    /// The single control point of the initial map (spec 1.10).
    pub(crate) fn initial_point(self) -> &'static [f32] {
        const UNIT_W: [f32; 4] = [0.0, 0.0, 0.0, 1.0];
        match self {
            Slot::Color4 => &[1.0, 1.0, 1.0, 1.0],
            Slot::Index => &[1.0],
            Slot::Normal => &[0.0, 0.0, 1.0],
            Slot::TexCoord1 => &UNIT_W[..1],
            Slot::TexCoord2 => &UNIT_W[..2],
            Slot::TexCoord3 | Slot::Vertex3 => &UNIT_W[..3],
            Slot::TexCoord4 | Slot::Vertex4 => &UNIT_W,
        }
    }
}

/// A map target decoded: 1D or 2D, and which attribute.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MapTarget {
    /// 1 for `GL_MAP1_*`, 2 for `GL_MAP2_*`.
    pub dims: u8,
    /// The attribute.
    pub slot: Slot,
}

impl MapTarget {
    /// Decodes one of the 18 target enums; anything else is `None` (GL_INVALID_ENUM).
    #[must_use]
    pub fn from_enum(target: GLenum) -> Option<Self> {
        let (dims, base) = match target {
            GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4 => (1, GL_MAP1_COLOR_4),
            GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4 => (2, GL_MAP2_COLOR_4),
            _ => return None,
        };
        let slot = Slot::ALL[(target - base) as usize];
        Some(Self { dims, slot })
    }

    /// Components per control point.
    #[must_use]
    pub fn components(self) -> usize {
        self.slot.components()
    }
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
