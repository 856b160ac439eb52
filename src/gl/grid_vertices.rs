//! A CPU-evaluated grid's vertices, stored by attribute: an array for each attribute a map
//! evaluates over the grid, and one value for each attribute that is the same at every point
//! (the current colour, normal or texture coordinate when the mesh was recorded). A surface
//! with `GL_AUTO_NORMAL` keeps 28 bytes a point (position and normal) rather than a whole
//! 60-byte [`Vertex`]: the bytes written per point are most of a first `glEvalMesh`'s cost
//! (fresh memory is faulted in page by page).

use super::vertex::Vertex;

/// The vertices of a grid, v outer and u inner.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GridVertices {
    /// The attributes no map evaluates (its position is used only without a vertex map).
    pub template: Vertex,
    /// (x, y, z, w) of every point: one entry per point.
    pub positions: Vec<[f32; 4]>,
    /// Every point's normal, or empty when the template's holds for all.
    pub normals: Vec<[f32; 3]>,
    /// Every point's colour, or empty when the template's holds for all.
    pub colors: Vec<[f32; 4]>,
    /// Every point's (s, t, r, q), or empty when the template's holds for all.
    pub tex_coords: Vec<[f32; 4]>,
}

impl GridVertices {
    /// Number of points.
    #[must_use]
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// True without points.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Point `k` as a whole vertex (the template beyond the last point).
    #[must_use]
    pub fn vertex(&self, k: usize) -> Vertex {
        let mut v = self.template;
        if let Some(&p) = self.positions.get(k) {
            v.position = p;
        }
        if let Some(&n) = self.normals.get(k) {
            v.normal = n;
        }
        if let Some(&c) = self.colors.get(k) {
            v.color = c;
        }
        if let Some(&t) = self.tex_coords.get(k) {
            v.tex_coord = t;
        }
        v
    }

    /// Every point as a whole vertex.
    #[must_use]
    pub fn to_vertices(&self) -> Vec<Vertex> {
        (0..self.len()).map(|k| self.vertex(k)).collect()
    }

    /// Vertices that may differ in every attribute (every array filled).
    #[must_use]
    pub fn from_vertices(vertices: &[Vertex]) -> Self {
        Self {
            template: vertices.first().copied().unwrap_or_default(),
            positions: vertices.iter().map(|v| v.position).collect(),
            normals: vertices.iter().map(|v| v.normal).collect(),
            colors: vertices.iter().map(|v| v.color).collect(),
            tex_coords: vertices.iter().map(|v| v.tex_coord).collect(),
        }
    }
}
