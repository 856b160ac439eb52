//! The vertex-callback data of a trimmed surface's points: the sampling lattice evaluated row by
//! row with one row kernel per Bezier piece, the other points (on the loops) by runs of one v
//! through the row kernel or one by one.

use crate::glu::evaluation::kernel::{piece_kernel, vertex_row};
use crate::glu::evaluation::pieces::{locate, SurfacePatches};
use crate::glu::evaluation::surface::Surface;
use crate::math::bezier::bernstein;
use crate::tess::trim::{Lattice, TrimOptions};
use crate::tess::{MapView, Row, RowKernel};

/// The vertex-callback data of every point of a [`Lattice`] (v outer), `None` outside the
/// surface.
pub(super) struct LatticeValues {
    pub lattice: Lattice,
    pub values: Vec<Option<[f32; 5]>>,
}

impl LatticeValues {
    /// Evaluates every lattice point on the row path: one row kernel per Bezier piece (its
    /// basis tables computed once), rows shared out on the pool. `None` when the lattice is
    /// beyond the triangulation's point budget (it would be coarsened and not match).
    pub fn evaluate(pos: &SurfacePatches, k: usize, lattice: Lattice) -> Option<Self> {
        use rayon::prelude::*;
        if lattice.point_count() > TrimOptions::DEFAULT.max_points {
            return None;
        }
        let p = &pos.patches;
        let uruns = piece_runs(&p.uintervals, &lattice.u);
        let vruns = piece_runs(&p.vintervals, &lattice.v);
        let kernels: Vec<Vec<Option<RowKernel<f64>>>> = vruns
            .iter()
            .map(|(b, vrange)| {
                uruns
                    .iter()
                    .map(|(a, urange)| {
                        let (us, vs) = (&lattice.u[urange.clone()], &lattice.v[vrange.clone()]);
                        piece_kernel(p, (*a, *b), p.patch(*a, *b)?, us, vs)
                    })
                    .collect()
            })
            .collect();
        let nu = lattice.u.len();
        let mut values = vec![None; lattice.point_count()];
        // Per v line: its run in `vruns` (None: outside every piece, left None).
        let mut row_run = vec![None; lattice.v.len()];
        for (bi, (_, range)) in vruns.iter().enumerate() {
            range.clone().for_each(|j| row_run[j] = Some(bi));
        }
        values.par_chunks_mut(nu).zip(row_run.par_iter().enumerate()).for_each_init(
            Row::default,
            |row, (line, (j, run))| {
                let Some(bi) = *run else { return };
                let local_j = j - vruns[bi].1.start;
                for ((_, urange), kernel) in uruns.iter().zip(&kernels[bi]) {
                    let Some(kernel) = kernel else { continue };
                    kernel.eval_row(local_j, row);
                    vertex_row(row, k, &lattice.u[urange.clone()], lattice.v[j], &mut line[urange.clone()], Some);
                }
            },
        );
        Some(Self { lattice, values })
    }
}

/// The lines grouped by the Bezier piece they lie on: (piece, range of line indices), lines
/// outside every piece left out.
fn piece_runs(intervals: &[(f64, f64)], lines: &[f64]) -> Vec<(usize, std::ops::Range<usize>)> {
    let mut runs: Vec<(usize, std::ops::Range<usize>)> = Vec::new();
    for (i, &x) in lines.iter().enumerate() {
        let Some(piece) = locate(intervals, x) else { continue };
        match runs.last_mut() {
            Some((last, range)) if *last == piece && range.end == i => range.end = i + 1,
            _ => runs.push((piece, i..i + 1)),
        }
    }
    runs
}

/// The vertex-callback data of a trimmed mesh's points: the grid points from the lattice's
/// values when there are some, the rest (the band's points, or all) evaluated here.
pub(super) struct PointValues<'a> {
    /// Each grid point's index in the lattice (the plan's, not copied).
    grid_index: &'a [u32],
    lattice: Option<LatticeValues>,
    rest: Vec<Option<[f32; 5]>>,
    first_rest: usize,
}

impl<'a> PointValues<'a> {
    /// The data of `grid_points` (lattice indices `grid_index`) then of `extra`.
    pub fn new(
        surface: &Surface,
        grid_points: &[[f64; 2]],
        grid_index: &'a [u32],
        extra: &[[f64; 2]],
        lattice: Option<LatticeValues>,
    ) -> Self {
        let (pos, k) = (&surface.pos, surface.k);
        match lattice {
            Some(l) => Self {
                grid_index,
                lattice: Some(l),
                rest: evaluate_positions(pos, k, extra),
                first_rest: grid_points.len(),
            },
            None => {
                let all: Vec<[f64; 2]> = grid_points.iter().chain(extra).copied().collect();
                Self { grid_index, lattice: None, rest: evaluate_positions(pos, k, &all), first_rest: 0 }
            }
        }
    }

    pub fn get(&self, i: u32) -> Option<&[f32; 5]> {
        let i = i as usize;
        match &self.lattice {
            Some(l) if i < self.first_rest => l.values[self.grid_index[i] as usize].as_ref(),
            _ => self.rest[i - self.first_rest].as_ref(),
        }
    }
}

/// Points evaluated per parallel task in [`evaluate_positions`].
const POINTS_PER_TASK: usize = 4096;

/// Runs of at least this many points with one v on one piece go through the row kernel.
const MIN_KERNEL_RUN: usize = 8;

/// The vertex-callback data ((x, y, z) divided by w, then u, v) of every point, `None` outside
/// the surface. The triangulation lists its grid points row by row: a run of points sharing a
/// v and a Bezier piece is evaluated by the row kernel (basis tables, vectorised sums); the
/// loop points one by one.
fn evaluate_positions(pos: &SurfacePatches, k: usize, points: &[[f64; 2]]) -> Vec<Option<[f32; 5]>> {
    use rayon::prelude::*;
    let mut out = vec![None; points.len()];
    out.par_chunks_mut(POINTS_PER_TASK).zip(points.par_chunks(POINTS_PER_TASK)).for_each(|(out, points)| {
        let mut single = RowCache::default();
        let mut row = Row::default();
        let mut start = 0;
        while start < points.len() {
            let piece =
                |p: &[f64; 2]| Some((locate(&pos.patches.uintervals, p[0])?, locate(&pos.patches.vintervals, p[1])?));
            let key = (points[start][1].to_bits(), piece(&points[start]));
            let len = points[start..].iter().take_while(|p| (p[1].to_bits(), piece(p)) == key).count().max(1);
            let run = &points[start..start + len];
            let done = match key.1 {
                Some((a, b)) if len >= MIN_KERNEL_RUN => {
                    eval_run(pos, k, (a, b), run, &mut row, &mut out[start..start + len])
                }
                _ => false,
            };
            if !done {
                for (o, &[u, v]) in out[start..start + len].iter_mut().zip(run) {
                    *o = single.eval(pos, k, u, v);
                }
            }
            start += len;
        }
    });
    out
}

/// Points of one v on Bezier piece (a, b) through the row kernel; false if it has none.
fn eval_run(
    pos: &SurfacePatches,
    k: usize,
    (a, b): (usize, usize),
    run: &[[f64; 2]],
    row: &mut Row<f64>,
    out: &mut [Option<[f32; 5]>],
) -> bool {
    let p = &pos.patches;
    let ((ua, ub), (va, vb)) = (p.uintervals[a], p.vintervals[b]);
    let Some(points) = p.patch(a, b) else { return false };
    let su: Vec<f64> = run.iter().map(|q| (q[0] - ua) / (ub - ua)).collect();
    let sv = [(run[0][1] - va) / (vb - va)];
    let view = MapView { dim: p.dim, uorder: p.uorder, vorder: p.vorder, points };
    let Some(kernel) = RowKernel::new(view, &su, &sv, false) else { return false };
    kernel.eval_row(0, row);
    let [x, y, z, w] = &row.point;
    for (i, (o, q)) in out.iter_mut().zip(run).enumerate() {
        let w = if k == 4 { w[i] } else { 1.0 };
        *o = Some([(x[i] / w) as f32, (y[i] / w) as f32, (z[i] / w) as f32, q[0] as f32, q[1] as f32]);
    }
    true
}

/// The net of one Bezier piece reduced along v at one v, reused while consecutive points share
/// the piece and the v.
#[derive(Default)]
struct RowCache {
    key: Option<(usize, usize, u64)>,
    reduced: Vec<[f64; 4]>,
    basis: Vec<f64>,
}

impl RowCache {
    fn eval(&mut self, pos: &SurfacePatches, k: usize, u: f64, v: f64) -> Option<[f32; 5]> {
        let p = &pos.patches;
        let (a, b) = (locate(&p.uintervals, u)?, locate(&p.vintervals, v)?);
        let ((ua, ub), (va, vb)) = (p.uintervals[a], p.vintervals[b]);
        if self.key != Some((a, b, v.to_bits())) {
            let net = p.patch(a, b)?;
            self.basis.resize(p.vorder, 0.0);
            bernstein(p.vorder, (v - va) / (vb - va), &mut self.basis);
            self.reduced.clear();
            for column in net.chunks_exact(p.vorder * p.dim) {
                let mut r = [0.0; 4];
                for (bj, point) in self.basis.iter().zip(column.chunks_exact(p.dim)) {
                    for (rc, &c) in r.iter_mut().zip(point) {
                        *rc += bj * c;
                    }
                }
                self.reduced.push(r);
            }
            self.key = Some((a, b, v.to_bits()));
        }
        self.basis.resize(p.uorder, 0.0);
        bernstein(p.uorder, (u - ua) / (ub - ua), &mut self.basis);
        let mut q = [0.0; 4];
        for (bi, r) in self.basis.iter().zip(&self.reduced) {
            for (qc, &c) in q.iter_mut().zip(r) {
                *qc += bi * c;
            }
        }
        let w = if k == 4 { q[3] } else { 1.0 };
        Some([(q[0] / w) as f32, (q[1] / w) as f32, (q[2] / w) as f32, u as f32, v as f32])
    }
}
