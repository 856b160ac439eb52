//! The typed API's output: an indexed triangle mesh, the shape every exporter and every
//! non-GL user wants (positions, unit normals, texture coordinates, counter-clockwise triangles).

use super::grid::MapView;
use super::rows::{rows_per_band, run_bands, Row, RowKernel};
use crate::math::{BezierPatch, Scalar};

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
    /// More vertices than [`MAX_MESH_VERTICES`].
    TooLarge(usize),
    /// The patch's dimension, orders and number of control values disagree.
    MalformedPatch,
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::EmptyGrid => write!(f, "a mesh grid needs at least one segment along u and along v"),
            Self::TooLarge(n) => write!(f, "{n} vertices are more than one mesh may hold ({MAX_MESH_VERTICES})"),
            Self::MalformedPatch => write!(f, "the patch's dimension, orders and control values disagree"),
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

/// A unit normal from an unnormalised direction; zero where the direction is zero or not finite
/// (a collapsed edge, a point at infinity).
fn unit_normal<S: Scalar>(n: [S; 3]) -> [f32; 3] {
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len > S::ZERO && len.is_finite() {
        n.map(|c| (c / len).to_f64() as f32)
    } else {
        [0.0; 3]
    }
}

/// Writes the two triangles of every cell of the cell rows starting at `first_row` into
/// `indices` (`6 (nu − 1)` per cell row), as [`Mesh::push_grid_triangles`] orders them.
fn write_cell_rows(nu: usize, first_row: usize, indices: &mut [u32]) {
    let row_len = 6 * nu.saturating_sub(1);
    if row_len == 0 {
        return;
    }
    for (r, row) in indices.chunks_mut(row_len).enumerate() {
        let start = ((first_row + r) * nu) as u32;
        for (i, cell) in row.chunks_exact_mut(6).enumerate() {
            let a = start + i as u32;
            let (b, c, d) = (a + 1, a + nu as u32 + 1, a + nu as u32);
            cell.copy_from_slice(&[a, b, c, a, c, d]);
        }
    }
}

impl<S: Scalar> BezierPatch<S> {
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
        let count = segments_u.saturating_add(1).saturating_mul(segments_v.saturating_add(1));
        if count > MAX_MESH_VERTICES {
            return Err(MeshError::TooLarge(count));
        }
        let param = |k: usize, n: usize| S::from_f64(k as f64 / n as f64);
        let us: Vec<S> = (0..=segments_u).map(|i| param(i, segments_u)).collect();
        let vs: Vec<S> = (0..=segments_v).map(|j| param(j, segments_v)).collect();
        self.tessellate_grid(&us, &vs)
    }

    /// Tessellates the patch over the grid `us` × `vs` of its unit domain (v outer, u inner):
    /// every grid point evaluated once, a row at a time, rows shared out between the cores.
    /// Texture coordinates are the (u, v) parameters.
    pub fn tessellate_grid(&self, us: &[S], vs: &[S]) -> Result<Mesh, MeshError> {
        let mut mesh = Mesh::default();
        self.tessellate_grid_into(us, vs, &mut mesh)?;
        Ok(mesh)
    }

    /// [`BezierPatch::tessellate_grid`] into `mesh`, replacing its contents but reusing its
    /// memory: a loop that re-tessellates allocates (and faults in) nothing after the first time.
    pub fn tessellate_grid_into(&self, us: &[S], vs: &[S], mesh: &mut Mesh) -> Result<(), MeshError> {
        let out = GridOut {
            positions: &mut mesh.positions,
            normals: &mut mesh.normals,
            tex_coords: Some(&mut mesh.tex_coords),
            indices: Some(&mut mesh.indices),
        };
        self.fill_grid(us, vs, out)
    }

    /// Only the grid's points and unit normals (v outer, u inner), into `positions` and
    /// `normals` (replaced, memory reused): for callers with their own connectivity.
    ///
    /// ```
    /// use gleval::math::BezierPatch;
    /// let flat = BezierPatch::try_new(3, 2, 2, vec![0.,0.,0., 0.,1.,0., 1.,0.,0., 1.,1.,0.]).unwrap();
    /// let (mut p, mut n) = (Vec::new(), Vec::new());
    /// flat.grid_with_normals_into(&[0.0, 0.5, 1.0], &[0.0, 1.0], &mut p, &mut n).unwrap();
    /// assert_eq!(p[4], [0.5, 1.0, 0.0]);
    /// assert_eq!(n[4], [0.0, 0.0, 1.0]);
    /// ```
    pub fn grid_with_normals_into(
        &self,
        us: &[S],
        vs: &[S],
        positions: &mut Vec<[f32; 3]>,
        normals: &mut Vec<[f32; 3]>,
    ) -> Result<(), MeshError> {
        self.fill_grid(us, vs, GridOut { positions, normals, tex_coords: None, indices: None })
    }

    /// The grid path behind both: bands of rows on the pool, each writing its rows' outputs
    /// and (with indices) the cell rows that start in them.
    fn fill_grid(&self, us: &[S], vs: &[S], out: GridOut<'_>) -> Result<(), MeshError> {
        let (nu, nv) = (us.len(), vs.len());
        if nu < 2 || nv < 2 {
            return Err(MeshError::EmptyGrid);
        }
        let count = nu.saturating_mul(nv);
        if count > MAX_MESH_VERTICES {
            return Err(MeshError::TooLarge(count));
        }
        let view = MapView { dim: self.dim, uorder: self.uorder, vorder: self.vorder, points: &self.points };
        let kernel = RowKernel::new(view, us, vs, true).ok_or(MeshError::MalformedPatch)?;
        let (rational, dim) = (self.dim == 4, self.dim.min(3));
        reuse_or_calloc(out.positions, count);
        reuse_or_calloc(out.normals, count);
        let band_rows = rows_per_band(nv, nu);
        let band = band_rows * nu;
        // Optional outputs: their bands, or empty slices when not asked for.
        let tex_bands: Box<dyn Iterator<Item = &mut [[f32; 2]]>> = match out.tex_coords {
            Some(t) => {
                reuse_or_calloc(t, count);
                Box::new(t.chunks_mut(band))
            }
            None => Box::new(std::iter::repeat_with(|| &mut [][..])),
        };
        // Band k also writes the cell rows starting in its rows (the last band has one fewer).
        let cell_bands: Box<dyn Iterator<Item = &mut [u32]>> = match out.indices {
            Some(i) => {
                reuse_or_calloc(i, 6 * (nu - 1) * (nv - 1));
                Box::new(i.chunks_mut(band_rows * 6 * (nu - 1)).chain(std::iter::repeat_with(|| &mut [][..])))
            }
            None => Box::new(std::iter::repeat_with(|| &mut [][..])),
        };
        let bands = out.positions.chunks_mut(band).zip(out.normals.chunks_mut(band)).zip(tex_bands).zip(cell_bands);
        let us_f32: Vec<f32> = us.iter().map(|u| u.to_f64() as f32).collect();
        run_bands(bands, |k, (((positions, normals), tex_coords), cells)| {
            write_cell_rows(nu, k * band_rows, cells);
            let mut row = Row::default();
            for (r, (positions, normals)) in positions.chunks_mut(nu).zip(normals.chunks_mut(nu)).enumerate() {
                let j = k * band / nu + r;
                kernel.eval_row(j, &mut row);
                // One simple loop per output, so that each vectorises.
                write_positions(&row, dim, rational, positions);
                let [x, y, z] = &row.cross;
                for (normal, ((x, y), z)) in normals.iter_mut().zip(x.iter().zip(y).zip(z)) {
                    *normal = unit_normal([*x, *y, *z]);
                }
                if let Some(tex) = tex_coords.get_mut(r * nu..(r + 1) * nu) {
                    let t = vs[j].to_f64() as f32;
                    for (tex, &u) in tex.iter_mut().zip(&us_f32) {
                        *tex = [u, t];
                    }
                }
            }
        });
        Ok(())
    }
}

/// Where [`BezierPatch::fill_grid`] writes; `None` outputs are skipped.
struct GridOut<'a> {
    positions: &'a mut Vec<[f32; 3]>,
    normals: &'a mut Vec<[f32; 3]>,
    tex_coords: Option<&'a mut Vec<[f32; 2]>>,
    indices: Option<&'a mut Vec<u32>>,
}

/// The row's points as f32 positions, divided by w for a rational patch.
fn write_positions<S: Scalar>(row: &Row<S>, dim: usize, rational: bool, positions: &mut [[f32; 3]]) {
    let p = &row.point;
    match (dim, rational) {
        (3, false) => {
            for (out, ((x, y), z)) in positions.iter_mut().zip(p[0].iter().zip(&p[1]).zip(&p[2])) {
                *out = [x.to_f64() as f32, y.to_f64() as f32, z.to_f64() as f32];
            }
        }
        (3, true) => {
            for (out, (((x, y), z), w)) in positions.iter_mut().zip(p[0].iter().zip(&p[1]).zip(&p[2]).zip(&p[3])) {
                *out = [(*x / *w).to_f64() as f32, (*y / *w).to_f64() as f32, (*z / *w).to_f64() as f32];
            }
        }
        _ => {
            for (i, out) in positions.iter_mut().enumerate() {
                let w = if rational { p[3][i] } else { S::ONE };
                for c in 0..dim {
                    out[c] = (p[c][i] / w).to_f64() as f32;
                }
            }
        }
    }
}

/// The most vertices one tessellation may produce (as `glEvalMesh`'s limit): 2²⁷, about 7 GiB
/// of mesh. Beyond it `tessellate` answers [`MeshError::TooLarge`] instead of exhausting memory.
pub const MAX_MESH_VERTICES: usize = 1 << 27;

/// Makes `v` hold `len` elements: in place when its memory suffices, else zeros from calloc
/// (whose pages are then faulted in by the threads that fill them, not all by this one).
fn reuse_or_calloc<T: Copy + Default>(v: &mut Vec<T>, len: usize) {
    if v.capacity() >= len {
        // Every element is overwritten by the caller: only the length needs to change.
        v.resize(len, T::default());
    } else {
        *v = vec![T::default(); len];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rational::cross;

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

    /// A rational patch on a grid big enough to be split between cores, tessellated into a mesh
    /// that held a bigger one: every position is the pointwise Horner value divided by w.
    #[test]
    fn reused_and_banded_meshes_match_pointwise_evaluation() {
        let points: Vec<f64> = (0..4 * 3 * 4)
            .map(|k| if k % 4 == 3 { 1.0 + (k % 5) as f64 * 0.5 } else { (k * 7 % 11) as f64 * 0.2 })
            .collect();
        let patch = BezierPatch::try_new(4, 4, 3, points.clone()).unwrap();
        let mut mesh = patch.tessellate(400, 300).unwrap();
        let (su, sv) = (250, 199);
        let us: Vec<f64> = (0..=su).map(|i| i as f64 / su as f64).collect();
        let vs: Vec<f64> = (0..=sv).map(|j| j as f64 / sv as f64).collect();
        patch.tessellate_grid_into(&us, &vs, &mut mesh).unwrap();
        assert_eq!(mesh, patch.tessellate(su, sv).unwrap());
        assert_eq!(mesh.positions.len(), us.len() * vs.len());
        let mut cells = Mesh::default();
        cells.push_grid_triangles(0, us.len() as u32, vs.len() as u32);
        assert_eq!(mesh.indices, cells.indices, "banded cell rows = the one-loop reference");
        for (k, p) in mesh.positions.iter().enumerate() {
            let (u, v) = (us[k % us.len()], vs[k / us.len()]);
            let h = crate::math::patch::horner_patch(&points, 4, 4, 3, u, v);
            for c in 0..3 {
                assert!((f64::from(p[c]) - h[c] / h[3]).abs() < 1e-5, "{k}");
            }
        }
    }

    #[test]
    fn points_and_normals_alone_are_the_meshs() {
        let points: Vec<f64> = (0..4 * 4 * 3).map(|k| ((k * 13 % 7) as f64) * 0.3).collect();
        let patch = BezierPatch::try_new(3, 4, 4, points).unwrap();
        let us: Vec<f64> = (0..=300).map(|i| f64::from(i) / 300.0).collect();
        let vs: Vec<f64> = (0..=250).map(|j| f64::from(j) / 250.0).collect();
        let mesh = patch.tessellate_grid(&us, &vs).unwrap();
        let (mut p, mut n) = (vec![[9.0; 3]; 7], Vec::new());
        patch.grid_with_normals_into(&us, &vs, &mut p, &mut n).unwrap();
        assert_eq!((p, n), (mesh.positions, mesh.normals));
    }

    #[test]
    fn absurd_grids_are_refused_not_allocated() {
        let patch = BezierPatch::try_new(3, 2, 2, vec![0.0; 12]).unwrap();
        for (su, sv) in [(60_000, 60_000), (usize::MAX, 2), (1 << 14, 1 << 13)] {
            let err = patch.tessellate(su, sv).unwrap_err();
            assert!(matches!(err, MeshError::TooLarge(_)), "{su} x {sv}");
            assert!(err.to_string().contains("more than one mesh"));
        }
    }

    #[test]
    fn empty_grid_is_an_error() {
        let patch = BezierPatch::try_new(3, 2, 2, vec![0.0; 12]).unwrap();
        assert_eq!(patch.tessellate(0, 3), Err(MeshError::EmptyGrid));
        assert!(patch.tessellate(0, 3).unwrap_err().to_string().contains("segment"));
    }
}
