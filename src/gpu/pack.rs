//! Packing for the evaluator, on the CPU: every job of a dispatch (one `glEvalMesh` call, or
//! one Bezier piece of a GLU surface) with its control points and the Bernstein tables of its
//! grid columns and rows, computed once per column and row in f64, in one `f32` array; vertex
//! and index offsets by prefix sum, known from the grid sizes alone. No wgpu here.

use super::layout::{GpuMapDesc, GpuMeshJob};
use crate::gl::{GridMesh, MapSample, MeshJob, MeshMode, MeshVertices};

/// The mode number a job carries (the shader's `MODE_*` constants).
#[must_use]
pub(crate) fn mode_number(mode: MeshMode) -> u32 {
    match mode {
        MeshMode::Points => 0,
        MeshMode::CurveLines => 1,
        MeshMode::SurfaceLines => 2,
        MeshMode::Fill => 3,
        // Scattered points: the CPU supplies the triangles.
        MeshMode::Triangles => 4,
    }
}

/// Indices the shader writes for a grid: 6 per cell when filled, 2 per segment for lines.
#[must_use]
pub(crate) fn index_count(mode: MeshMode, nu: usize, nv: usize) -> usize {
    let (cu, cv) = (nu.saturating_sub(1), nv.saturating_sub(1));
    match mode {
        MeshMode::Points | MeshMode::Triangles => 0,
        MeshMode::Fill => 6 * cu * cv,
        MeshMode::CurveLines | MeshMode::SurfaceLines => 2 * (nv * cu + nu * cv),
    }
}

/// Jobs, control points and parameters packed for one dispatch, with per-job ranges.
#[derive(Debug, Default)]
pub struct PackedJobs {
    /// The jobs.
    pub jobs: Vec<GpuMeshJob>,
    /// Control points and Bernstein tables of every job, in one array (one storage binding:
    /// downlevel devices allow only four per stage).
    pub data: Vec<f32>,
    /// Total grid points (vertices).
    pub vertices: u32,
    /// Total indices.
    pub indices: u32,
    /// Index-buffer ranges the CPU fills (first index, values): GLU's trimmed triangles.
    pub explicit: Vec<(u32, Vec<u32>)>,
    /// Whether the backend's flat shading takes a primitive's last vertex, as GL does; if not,
    /// every primitive is rotated to start at GL's provoking vertex.
    pub provoking_last: bool,
}

impl PackedJobs {
    /// No jobs yet, for a backend whose flat shading takes the last vertex or the first.
    pub fn new(provoking_last: bool) -> Self {
        Self { provoking_last, ..Self::default() }
    }

    /// Appends every job of a deferred mesh; scattered meshes bring their triangles, renumbered
    /// to the packed vertices and, unless the backend's provoking vertex is the last (GL's),
    /// rotated so that GL's provoking vertex comes first (rotation keeps the winding).
    pub fn push_mesh(&mut self, mesh: &GridMesh) -> Option<()> {
        let MeshVertices::Deferred(jobs) = &mesh.vertices else { return None };
        let base = self.vertices;
        for job in jobs {
            self.push(job, mesh.mode)?;
        }
        if mesh.mode == MeshMode::Triangles {
            let count = u32::try_from(mesh.triangles.len()).ok()?;
            let total = self.vertices - base;
            if mesh.triangles.iter().any(|&i| i >= total) {
                return None;
            }
            let last = self.provoking_last;
            let rotated = mesh
                .triangles
                .chunks_exact(3)
                .flat_map(|t| if last { [t[0], t[1], t[2]] } else { [t[2], t[0], t[1]] })
                .map(|i| i + base)
                .collect();
            self.explicit.push((self.indices, rotated));
            self.indices = self.indices.checked_add(count)?;
        }
        Some(())
    }

    /// Appends a job (`mode` decides its indices); `None` if 32-bit offsets overflow or the job
    /// is malformed (more than four maps, or parameter lists of the wrong length).
    pub fn push(&mut self, job: &MeshJob, mode: MeshMode) -> Option<()> {
        let u32_of = |v: usize| u32::try_from(v).ok();
        if job.maps.len() > 4 || job.is_empty() || job.scattered != (mode == MeshMode::Triangles) {
            return None;
        }
        let mut gpu = GpuMeshJob {
            map_count: u32_of(job.maps.len())?,
            nu: u32_of(job.nu)?,
            nv: u32_of(job.nv)?,
            mode: mode_number(mode),
            out_offset: self.vertices,
            index_offset: self.indices,
            auto_normal: u32::from(job.auto_normal),
            pad: 0,
            normal: [job.template.normal[0], job.template.normal[1], job.template.normal[2], 0.0],
            color: job.template.color,
            tex: job.template.tex_coord,
            maps: Default::default(),
        };
        for (desc, map) in gpu.maps.iter_mut().zip(&job.maps) {
            *desc = self.push_map(map, job)?;
        }
        self.vertices = self.vertices.checked_add(u32_of(job.len())?)?;
        self.indices = self.indices.checked_add(u32_of(index_count(mode, job.nu, job.nv))?)?;
        self.jobs.push(gpu);
        Some(())
    }

    /// Appends one map's control points and Bernstein tables; `None` if they do not fit the
    /// job's grid or GL's orders (1..=30), or 32-bit offsets overflow.
    fn push_map(&mut self, map: &MapSample, job: &MeshJob) -> Option<GpuMapDesc> {
        let u32_of = |v: usize| u32::try_from(v).ok();
        let dim = map.slot.components();
        let ok = map.points.len() >= map.uorder * map.vorder * dim && map.us.len() == job.nu;
        let rows = if job.scattered { job.nu } else { job.nv };
        if !ok || map.vs.len() != rows || !(1..=30).contains(&map.uorder) || !(1..=30).contains(&map.vorder) {
            return None;
        }
        let point_offset = u32_of(self.data.len())?;
        self.data.extend_from_slice(&map.points[..map.uorder * map.vorder * dim]);
        // Room for the shader's four-wide reads of the last point.
        self.data.extend_from_slice(&[0.0; 3]);
        let u_offset = u32_of(self.data.len())?;
        push_basis_table(&mut self.data, map.uorder, &map.us);
        let v_offset = u32_of(self.data.len())?;
        push_basis_table(&mut self.data, map.vorder, &map.vs);
        Some(GpuMapDesc {
            slot: map.slot as u32,
            dim: u32_of(dim)?,
            uorder: u32_of(map.uorder)?,
            vorder: u32_of(map.vorder)?,
            point_offset,
            u_offset,
            v_offset,
            pad: 0,
        })
    }
}

/// The Bernstein basis of `order` at `t` (de Casteljau's triangle, f64), into `out[..order]`.
fn bernstein(order: usize, t: f64, out: &mut [f64; 30]) {
    out[0] = 1.0;
    for level in 1..order {
        let mut saved = 0.0;
        for i in 0..level {
            let v = out[i];
            out[i] = saved + (1.0 - t) * v;
            saved = t * v;
        }
        out[level] = saved;
    }
}

/// Per parameter: the `order` Bernstein values and the `order − 1` of one degree less.
fn push_basis_table(data: &mut Vec<f32>, order: usize, params: &[f32]) {
    let mut b = [0.0; 30];
    data.reserve(params.len() * (2 * order - 1));
    for &t in params {
        let t = f64::from(t);
        bernstein(order, t, &mut b);
        data.extend(b[..order].iter().map(|&x| x as f32));
        if order > 1 {
            bernstein(order - 1, t, &mut b);
            data.extend(b[..order - 1].iter().map(|&x| x as f32));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::{Slot, Vertex};

    /// The slot and mode numbers the compute shader hard-codes are the Rust enums'.
    #[test]
    fn shader_constants_match_the_enums() {
        let source = super::super::layout::EVAL_MESH_WGSL;
        let module = naga::front::wgsl::parse_str(source).expect("parses");
        let value = |name: &str| -> u32 {
            let (_, c) = module.constants.iter().find(|(_, c)| c.name.as_deref() == Some(name)).expect(name);
            match module.global_expressions[c.init] {
                naga::Expression::Literal(naga::Literal::U32(v)) => v,
                ref other => panic!("{name}: {other:?}"),
            }
        };
        assert_eq!(value("SLOT_COLOR"), Slot::Color4 as u32);
        assert_eq!(value("SLOT_NORMAL"), Slot::Normal as u32);
        assert_eq!(value("SLOT_TEX1"), Slot::TexCoord1 as u32);
        assert_eq!(value("SLOT_TEX4"), Slot::TexCoord4 as u32);
        assert_eq!(value("SLOT_VERTEX3"), Slot::Vertex3 as u32);
        assert_eq!(value("SLOT_VERTEX4"), Slot::Vertex4 as u32);
        assert_eq!(value("MODE_POINTS"), mode_number(MeshMode::Points));
        assert_eq!(value("MODE_FILL"), mode_number(MeshMode::Fill));
        assert_eq!(value("MODE_SCATTERED"), mode_number(MeshMode::Triangles));
    }

    fn job(uorder: usize, vorder: usize, nu: usize, nv: usize) -> MeshJob {
        let map = MapSample {
            slot: Slot::Vertex3,
            uorder,
            vorder,
            points: vec![0.5; uorder * vorder * 3],
            us: vec![0.25; nu],
            vs: vec![0.75; nv],
        };
        MeshJob { maps: vec![map], auto_normal: true, template: Vertex::default(), nu, nv, scattered: false }
    }

    /// Offsets are prefix sums; the tables hold `2·order − 1` values per parameter; jobs the
    /// shader cannot read are refused.
    #[test]
    fn packing_computes_prefix_sums_and_rejects_bad_jobs() {
        let mut packed = PackedJobs::new(false);
        packed.push(&job(4, 4, 2, 3), MeshMode::Fill).expect("packs");
        packed.push(&job(4, 4, 1, 1), MeshMode::Points).expect("packs");
        assert_eq!((packed.jobs[1].out_offset, packed.vertices), (6, 7));
        assert_eq!((packed.jobs[1].index_offset, packed.indices), (12, 12), "two filled cells, no point indices");
        // 48 coordinates, 3 floats of read-ahead, 2 columns and 3 rows of 7 values each.
        let first = 48 + 3 + 2 * 7 + 3 * 7;
        assert_eq!(packed.jobs[1].maps[0].point_offset, first as u32);
        assert_eq!((packed.jobs[0].maps[0].u_offset, packed.jobs[0].maps[0].v_offset), (51, 65));
        assert!(packed.push(&job(31, 4, 2, 2), MeshMode::Fill).is_none(), "order 31");
        let mut short = job(4, 4, 2, 2);
        short.maps[0].vs.pop();
        assert!(packed.push(&short, MeshMode::Fill).is_none(), "v parameters for 1 of 2 rows");
        let mut five = job(2, 2, 2, 2);
        five.maps = vec![five.maps[0].clone(); 5];
        assert!(packed.push(&five, MeshMode::Fill).is_none(), "five maps");
        assert_eq!(packed.jobs.len(), 2);
    }

    /// A table row: the cubic Bernstein values at t, then the quadratic ones (for the partials).
    #[test]
    fn basis_tables_are_bernstein_values() {
        let mut data = Vec::new();
        push_basis_table(&mut data, 4, &[0.0, 0.5]);
        assert_eq!(&data[..7], &[1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
        assert_eq!(&data[7..], &[0.125, 0.375, 0.375, 0.125, 0.25, 0.5, 0.25]);
    }
}
