//! The typed API's output: an indexed triangle mesh, the shape every exporter and every
//! non-GL user wants (positions, unit normals, texture coordinates, counter-clockwise triangles).

use super::grid::{eval_grid2, Grid2, MapView};
use crate::math::rational::cross;
use crate::math::BezierPatch;

/// An indexed triangle mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions (projected: rational maps are divided by w).
    pub positions: Vec<[f32; 3]>,
    /// One unit normal per vertex, or empty. A degenerate point (collapsed edge) has a zero normal.
    pub normals: Vec<[f32; 3]>,
    /// One (s, t) per vertex, or empty.
    pub tex_coords: Vec<[f32; 2]>,
    /// Triangles, three indices each, counter-clockwise seen from the side the normals point to.
    pub indices: Vec<u32>,
}

/// Why a mesh could not be built.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MeshError {
    /// A grid needs at least one segment in each direction.
    EmptyGrid,
    /// More vertices than 32-bit indices can address.
    TooLarge(usize),
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::EmptyGrid => write!(f, "a mesh grid needs at least one segment along u and along v"),
            Self::TooLarge(n) => write!(f, "{n} vertices do not fit 32-bit indices"),
        }
    }
}

impl std::error::Error for MeshError {}

impl Mesh {
    /// Number of triangles.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Appends the two triangles of every cell of an `nu` × `nv` vertex grid (v outer, u inner)
    /// whose first vertex is `base`: (i,j) (i+1,j) (i+1,j+1) and (i,j) (i+1,j+1) (i,j+1), which is
    /// counter-clockwise in (u, v) and so faces along ∂p/∂u × ∂p/∂v.
    pub fn push_grid_triangles(&mut self, base: u32, nu: u32, nv: u32) {
        for j in 0..nv.saturating_sub(1) {
            for i in 0..nu.saturating_sub(1) {
                let a = base + j * nu + i;
                let (b, c, d) = (a + 1, a + nu + 1, a + nu);
                self.indices.extend_from_slice(&[a, b, c, a, c, d]);
            }
        }
    }

    /// Appends `other`, renumbering its indices.
    pub fn append(&mut self, other: &Mesh) {
        let base = self.positions.len() as u32;
        self.positions.extend_from_slice(&other.positions);
        self.normals.extend_from_slice(&other.normals);
        self.tex_coords.extend_from_slice(&other.tex_coords);
        self.indices.extend(other.indices.iter().map(|i| i + base));
    }
}

/// Unit normal of the projected surface from homogeneous point and partials (zero if degenerate).
fn projected_normal(dim: usize, p: [f64; 4], du: [f64; 4], dv: [f64; 4]) -> [f32; 3] {
    let (a, b) = if dim == 4 {
        let w = p[3];
        let a = [du[0] * w - du[3] * p[0], du[1] * w - du[3] * p[1], du[2] * w - du[3] * p[2]];
        let b = [dv[0] * w - dv[3] * p[0], dv[1] * w - dv[3] * p[1], dv[2] * w - dv[3] * p[2]];
        (a, b)
    } else {
        ([du[0], du[1], du[2]], [dv[0], dv[1], dv[2]])
    };
    let n = cross(a, b);
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len > 0.0 && len.is_finite() {
        [(n[0] / len) as f32, (n[1] / len) as f32, (n[2] / len) as f32]
    } else {
        [0.0; 3]
    }
}

impl BezierPatch<f64> {
    /// Tessellates the patch over a uniform `segments_u` × `segments_v` grid of its unit domain
    /// into a mesh with normals and (u, v) texture coordinates.
    ///
    /// ```
    /// use gleval::math::BezierPatch;
    /// let flat = BezierPatch::try_new(3, 2, 2, vec![0.,0.,0., 0.,1.,0., 1.,0.,0., 1.,1.,0.]).unwrap();
    /// let mesh = flat.tessellate(4, 3).unwrap();
    /// assert_eq!(mesh.positions.len(), 5 * 4);
    /// assert_eq!(mesh.triangle_count(), 2 * 4 * 3);
    /// assert_eq!(mesh.normals[7], [0.0, 0.0, 1.0]);
    /// ```
    pub fn tessellate(&self, segments_u: usize, segments_v: usize) -> Result<Mesh, MeshError> {
        if segments_u == 0 || segments_v == 0 {
            return Err(MeshError::EmptyGrid);
        }
        let (nu, nv) = (segments_u + 1, segments_v + 1);
        let count = nu.checked_mul(nv).filter(|&n| n <= u32::MAX as usize).ok_or(MeshError::TooLarge(usize::MAX))?;
        let us: Vec<f64> = (0..nu).map(|i| i as f64 / segments_u as f64).collect();
        let vs: Vec<f64> = (0..nv).map(|j| j as f64 / segments_v as f64).collect();
        let view = MapView { dim: self.dim, uorder: self.uorder, vorder: self.vorder, points: &self.points };
        let mut grid = Grid2::default();
        eval_grid2(&view, &us, &vs, true, &mut grid);
        let mut mesh = Mesh {
            positions: Vec::with_capacity(count),
            normals: Vec::with_capacity(count),
            tex_coords: Vec::with_capacity(count),
            indices: Vec::new(),
        };
        for k in 0..count {
            let p = grid.points[k];
            let w = if self.dim == 4 { p[3] } else { 1.0 };
            mesh.positions.push([(p[0] / w) as f32, (p[1] / w) as f32, (p[2] / w) as f32]);
            mesh.normals.push(projected_normal(self.dim, p, grid.du[k], grid.dv[k]));
            mesh.tex_coords.push([us[k % nu] as f32, vs[k / nu] as f32]);
        }
        mesh.push_grid_triangles(0, nu as u32, nv as u32);
        Ok(mesh)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangles_face_along_the_normals() {
        // A bilinear saddle: every triangle's geometric normal agrees with its vertex normals.
        let patch = BezierPatch::try_new(3, 2, 2, vec![0., 0., 0., 0., 1., 0.3, 1., 0., -0.2, 1., 1., 0.]).unwrap();
        let mesh = patch.tessellate(6, 5).unwrap();
        for t in mesh.indices.chunks(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| mesh.positions[i as usize].map(f64::from));
            let g = cross([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
            let n = mesh.normals[t[0] as usize];
            assert!(g[0] * f64::from(n[0]) + g[1] * f64::from(n[1]) + g[2] * f64::from(n[2]) > 0.0);
        }
    }

    #[test]
    fn empty_grid_is_an_error() {
        let patch = BezierPatch::try_new(3, 2, 2, vec![0.0; 12]).unwrap();
        assert_eq!(patch.tessellate(0, 3), Err(MeshError::EmptyGrid));
        assert!(patch.tessellate(0, 3).unwrap_err().to_string().contains("segment"));
    }
}
