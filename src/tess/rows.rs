//! The grid fast path: a patch evaluated one grid row at a time into structure-of-arrays rows,
//! and rows shared out between the machine's cores.
//!
//! Per row j the net is first reduced along v (`uorder` points, O(uorder·vorder·dim)); every
//! point of the row is then a short sum over those reduced points with the u basis, which is
//! stored order-major (`B_a(u_i)` at `a·nu + i`) so that the inner loop runs over i with unit
//! stride and the compiler vectorises it. Partials follow Mesa's de Casteljau in using
//! control-point differences, so a collapsed edge gives an exactly zero derivative; the normal
//! direction is ∂p/∂u × ∂p/∂v, with the rational correction `d·w − p·d_w` for homogeneous maps
//! (Mesa `vbo_exec_do_EvalCoord2f`). The sums run in the same order as [`super::grid::eval_grid2`],
//! so both paths give the same bits.

use super::grid::{reduce_rows, BasisTable, MapView};
use crate::math::bezier::{Vec4, MAX_DIM};
use crate::math::Scalar;
use std::sync::Arc;

/// A patch over a fixed grid, ready to evaluate any of its rows.
#[derive(Clone, Debug)]
pub struct RowKernel<'a, S: Scalar> {
    map: MapView<'a, S>,
    nu: usize,
    normals: bool,
    bases: Arc<RowBases<S>>,
}

/// The basis tables of a [`RowKernel`]: what depends on the grid and the orders, not on the
/// control points, so that patches of the same orders over the same grid (a frame of many
/// small patches) share them.
#[derive(Debug)]
pub struct RowBases<S: Scalar> {
    uorder: usize,
    vorder: usize,
    normals: bool,
    /// The grid's parameters, by bits (what [`RowBases::fits`] compares).
    us: Vec<S>,
    vs: Vec<S>,
    /// `B_a(u_i)` at `a · nu + i`.
    basis_u: Vec<S>,
    /// The order−1 basis, same layout (empty without normals).
    lower_u: Vec<S>,
    basis_v: BasisTable<S>,
}

impl<S: Scalar> RowBases<S> {
    /// The tables of orders (`uorder`, `vorder`) over `us` × `vs`; `normals` adds the lower
    /// orders' (for the partials).
    #[must_use]
    pub fn new(uorder: usize, vorder: usize, us: &[S], vs: &[S], normals: bool) -> Self {
        let lower_u = if normals && uorder > 1 { order_major_basis(uorder - 1, us) } else { Vec::new() };
        Self {
            uorder,
            vorder,
            normals,
            us: us.to_vec(),
            vs: vs.to_vec(),
            basis_u: order_major_basis(uorder, us),
            lower_u,
            basis_v: BasisTable::new(vorder, vs, normals),
        }
    }

    /// Whether these are the tables [`RowBases::new`] would make of these arguments (the
    /// parameters compared bit for bit: −0 and 0 give different bits in places).
    #[must_use]
    pub fn fits(&self, uorder: usize, vorder: usize, us: &[S], vs: &[S], normals: bool) -> bool {
        let same = |a: &[S], b: &[S]| {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_f64().to_bits() == y.to_f64().to_bits())
        };
        self.uorder == uorder
            && self.vorder == vorder
            && self.normals == normals
            && same(&self.us, us)
            && same(&self.vs, vs)
    }
}

/// One evaluated row in structure-of-arrays form.
#[derive(Clone, Debug, Default)]
pub struct Row<S: Scalar> {
    /// Component c of point i at `point[c][i]` (c < the map's dimension).
    pub point: [Vec<S>; MAX_DIM],
    /// ∂p/∂u × ∂p/∂v (rational-corrected, not normalised) at `cross[c][i]`; empty without
    /// normals.
    pub cross: [Vec<S>; 3],
    du: [Vec<S>; MAX_DIM],
    dv: [Vec<S>; MAX_DIM],
    reduced: Vec<Vec4<S>>,
    reduced_dv: Vec<Vec4<S>>,
    coeffs: Vec<S>,
}

impl<S: Scalar> Row<S> {
    /// The first `k` components of point `i`, the rest (0, 0, 0, 1) as GL widens.
    #[must_use]
    pub fn point_at(&self, i: usize, k: usize) -> Vec4<S> {
        let mut p = [S::ZERO, S::ZERO, S::ZERO, S::ONE];
        for (c, value) in p.iter_mut().enumerate().take(k) {
            *value = self.point[c][i];
        }
        p
    }

    /// The unnormalised normal direction at point `i`.
    #[must_use]
    pub fn cross_at(&self, i: usize) -> [S; 3] {
        [self.cross[0][i], self.cross[1][i], self.cross[2][i]]
    }
}

/// `B(t)` for every t in `params`, order-major.
///
/// [`bernstein`](crate::math::bezier::bernstein)'s degree-raising recurrence, run for a block of parameters at once: each step
/// is one simple loop over the block, which vectorises, where point by point the recurrence is
/// a chain of dependent scalar steps (O(order²) per point: the whole cost of a long
/// high-degree curve). Each point sees the same operations in the same order, so the same bits.
fn order_major_basis<S: Scalar>(order: usize, params: &[S]) -> Vec<S> {
    const BLOCK: usize = 64;
    let n = params.len();
    let mut table = vec![S::ZERO; order * n];
    if order == 0 {
        return table;
    }
    let (mut one_minus_t, mut saved) = ([S::ZERO; BLOCK], [S::ZERO; BLOCK]);
    for (block, ts) in params.chunks(BLOCK).enumerate() {
        let (start, m) = (block * BLOCK, ts.len());
        let (s, saved) = (&mut one_minus_t[..m], &mut saved[..m]);
        for (s, &t) in s.iter_mut().zip(ts) {
            *s = S::ONE - t;
        }
        table[start..start + m].fill(S::ONE);
        for level in 1..order {
            // Raise degree level-1 -> level: B_i <- saved + (1-t) B_i, saved <- t B_i.
            saved.fill(S::ZERO);
            for i in 0..level {
                let row = &mut table[i * n + start..i * n + start + m];
                for (((b, saved), &s), &t) in row.iter_mut().zip(saved.iter_mut()).zip(s.iter()).zip(ts) {
                    let old = *b;
                    *b = *saved + s * old;
                    *saved = t * old;
                }
            }
            table[level * n + start..level * n + start + m].copy_from_slice(saved);
        }
    }
    table
}

/// `out[i] = Σ_a basis[a·n + i] · coeffs[a]`, summed from a = 0 up.
///
/// Orders up to 8 (every cubic and the textbook's higher degrees) run a kernel with the order
/// fixed at compile time: one pass over the row with the sum unrolled, instead of one pass per
/// term through memory. The sum runs in the same order either way, so the bits are the same.
fn combine_row<S: Scalar>(basis: &[S], coeffs: &[S], n: usize, out: &mut Vec<S>) {
    match coeffs.len() {
        1 => combine_fixed::<S, 1>(basis, coeffs, n, out),
        2 => combine_fixed::<S, 2>(basis, coeffs, n, out),
        3 => combine_fixed::<S, 3>(basis, coeffs, n, out),
        4 => combine_fixed::<S, 4>(basis, coeffs, n, out),
        5 => combine_fixed::<S, 5>(basis, coeffs, n, out),
        6 => combine_fixed::<S, 6>(basis, coeffs, n, out),
        7 => combine_fixed::<S, 7>(basis, coeffs, n, out),
        8 => combine_fixed::<S, 8>(basis, coeffs, n, out),
        _ => combine_any(basis, coeffs, n, out),
    }
}

/// [`combine_row`] for `K` terms, four points at a time in registers.
fn combine_fixed<S: Scalar, const K: usize>(basis: &[S], coeffs: &[S], n: usize, out: &mut Vec<S>) {
    const W: usize = 4;
    let coeffs: [S; K] = std::array::from_fn(|a| coeffs[a]);
    let rows: [&[S]; K] = std::array::from_fn(|a| &basis[a * n..(a + 1) * n]);
    // Every entry is written below; a reused row of the right length is not zeroed first.
    if out.len() != n {
        out.clear();
        out.resize(n, S::ZERO);
    }
    let (body, tail) = out.split_at_mut(n - n % W);
    for (k, o) in body.chunks_exact_mut(W).enumerate() {
        let mut sum = [S::ZERO; W];
        for (row, &c) in rows.iter().zip(&coeffs) {
            for (s, &b) in sum.iter_mut().zip(&row[k * W..k * W + W]) {
                *s += b * c;
            }
        }
        o.copy_from_slice(&sum);
    }
    let first = body.len();
    for (i, o) in tail.iter_mut().enumerate() {
        *o = rows.iter().zip(&coeffs).fold(S::ZERO, |s, (row, &c)| s + row[first + i] * c);
    }
}

/// [`combine_row`] for any number of terms: one pass per term.
fn combine_any<S: Scalar>(basis: &[S], coeffs: &[S], n: usize, out: &mut Vec<S>) {
    out.clear();
    out.resize(n, S::ZERO);
    for (a, &c) in coeffs.iter().enumerate() {
        for (o, &b) in out.iter_mut().zip(&basis[a * n..(a + 1) * n]) {
            *o += b * c;
        }
    }
}

impl<'a, S: Scalar> RowKernel<'a, S> {
    /// The kernel for `map` over `us` × `vs` (normalised parameters); `normals` adds the normal
    /// direction. `None` if the map is malformed (see [`MapView`]).
    #[must_use]
    pub fn new(map: MapView<'a, S>, us: &[S], vs: &[S], normals: bool) -> Option<Self> {
        if !map.is_valid() {
            return None;
        }
        Self::with_bases(map, Arc::new(RowBases::new(map.uorder, map.vorder, us, vs, normals)))
    }

    /// The kernel for `map` with tables made before (for its orders: `None` otherwise, or if
    /// the map is malformed).
    #[must_use]
    pub fn with_bases(map: MapView<'a, S>, bases: Arc<RowBases<S>>) -> Option<Self> {
        if !map.is_valid() || bases.uorder != map.uorder || bases.vorder != map.vorder {
            return None;
        }
        Some(Self { map, nu: bases.us.len(), normals: bases.normals, bases })
    }

    /// Evaluates row `j` (the row at `vs[j]`) into `row`.
    pub fn eval_row(&self, j: usize, row: &mut Row<S>) {
        let (dim, uorder, nu) = (self.map.dim, self.map.uorder, self.nu);
        row.reduced.resize(uorder, [S::ZERO; MAX_DIM]);
        row.reduced_dv.resize(uorder, [S::ZERO; MAX_DIM]);
        let bv = self.bases.basis_v.at(j);
        reduce_rows(&self.map, bv, self.bases.basis_v.lower_at(j), self.normals, &mut row.reduced, &mut row.reduced_dv);
        for c in 0..dim {
            row.coeffs.clear();
            row.coeffs.extend(row.reduced.iter().map(|r| r[c]));
            combine_row(&self.bases.basis_u, &row.coeffs, nu, &mut row.point[c]);
        }
        if !self.normals {
            return;
        }
        let n = S::from_usize(uorder.saturating_sub(1));
        for c in 0..dim {
            row.coeffs.clear();
            row.coeffs.extend(row.reduced.windows(2).map(|w| w[1][c] - w[0][c]));
            combine_row(&self.bases.lower_u, &row.coeffs, nu, &mut row.du[c]);
            row.du[c].iter_mut().for_each(|d| *d *= n);
            row.coeffs.clear();
            row.coeffs.extend(row.reduced_dv.iter().map(|r| r[c]));
            combine_row(&self.bases.basis_u, &row.coeffs, nu, &mut row.dv[c]);
        }
        if dim == 4 {
            rational_correction(&mut row.du, &row.point);
            rational_correction(&mut row.dv, &row.point);
        }
        cross_rows(&row.du, &row.dv, dim, nu, &mut row.cross);
    }
}

impl<S: Scalar> RowKernel<'_, S> {
    /// Row `j` of a three-component map of u order up to 8, point by point: `emit(i, p, n)`
    /// with the point and, when the kernel makes normals, the normal direction ∂p/∂u × ∂p/∂v
    /// (zero otherwise). The same operations in the same order as [`RowKernel::eval_row`]
    /// (each sum from zero up, Mesa's `CROSS3`), so the same bits, without its per-component
    /// passes: what a short row (a small patch's 9 points) spends most of its time on.
    /// Returns false, emitting nothing, for other maps.
    pub fn eval_row_points(&self, j: usize, row: &mut Row<S>, emit: impl FnMut(usize, [S; 3], [S; 3])) -> bool {
        if self.map.dim != 3 {
            return false;
        }
        match self.map.uorder {
            1 => self.points_fixed::<1>(j, row, emit),
            2 => self.points_fixed::<2>(j, row, emit),
            3 => self.points_fixed::<3>(j, row, emit),
            4 => self.points_fixed::<4>(j, row, emit),
            5 => self.points_fixed::<5>(j, row, emit),
            6 => self.points_fixed::<6>(j, row, emit),
            7 => self.points_fixed::<7>(j, row, emit),
            8 => self.points_fixed::<8>(j, row, emit),
            _ => return false,
        }
        true
    }

    fn points_fixed<const K: usize>(&self, j: usize, row: &mut Row<S>, mut emit: impl FnMut(usize, [S; 3], [S; 3])) {
        let nu = self.nu;
        row.reduced.resize(K, [S::ZERO; MAX_DIM]);
        row.reduced_dv.resize(K, [S::ZERO; MAX_DIM]);
        reduce_rows(
            &self.map,
            self.bases.basis_v.at(j),
            self.bases.basis_v.lower_at(j),
            self.normals,
            &mut row.reduced,
            &mut row.reduced_dv,
        );
        let r: [[S; 3]; K] = std::array::from_fn(|a| [row.reduced[a][0], row.reduced[a][1], row.reduced[a][2]]);
        let basis: [&[S]; K] = std::array::from_fn(|a| &self.bases.basis_u[a * nu..(a + 1) * nu]);
        if !self.normals {
            for i in 0..nu {
                let mut p = [S::ZERO; 3];
                for a in 0..K {
                    for c in 0..3 {
                        p[c] += basis[a][i] * r[a][c];
                    }
                }
                emit(i, p, [S::ZERO; 3]);
            }
            return;
        }
        let rv: [[S; 3]; K] =
            std::array::from_fn(|a| [row.reduced_dv[a][0], row.reduced_dv[a][1], row.reduced_dv[a][2]]);
        // Control-point differences along u, as `eval_row` takes them (K − 1 of them).
        let diff: [[S; 3]; K] =
            std::array::from_fn(
                |a| if a + 1 < K { std::array::from_fn(|c| r[a + 1][c] - r[a][c]) } else { [S::ZERO; 3] },
            );
        let lower: [&[S]; K] =
            std::array::from_fn(|a| if a + 1 < K { &self.bases.lower_u[a * nu..(a + 1) * nu] } else { &[][..] });
        let n = S::from_usize(K - 1);
        for i in 0..nu {
            let (mut p, mut du, mut dv) = ([S::ZERO; 3], [S::ZERO; 3], [S::ZERO; 3]);
            for a in 0..K {
                let b = basis[a][i];
                for c in 0..3 {
                    p[c] += b * r[a][c];
                    dv[c] += b * rv[a][c];
                }
                if a + 1 < K {
                    let l = lower[a][i];
                    for c in 0..3 {
                        du[c] += l * diff[a][c];
                    }
                }
            }
            let du = du.map(|d| d * n);
            let cross = [du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]];
            emit(i, p, cross);
        }
    }
}

/// `d ← d·w − p·d_w` per point (the direction of the projected derivative, times w²).
fn rational_correction<S: Scalar>(d: &mut [Vec<S>; MAX_DIM], p: &[Vec<S>; MAX_DIM]) {
    let (xyz, w) = d.split_at_mut(3);
    let dw = &w[0];
    for (c, dc) in xyz.iter_mut().enumerate() {
        for (((x, &dwi), &pc), &w) in dc.iter_mut().zip(dw).zip(&p[c]).zip(&p[3]) {
            *x = *x * w - dwi * pc;
        }
    }
}

/// `out = a × b` per point, written as Mesa's `CROSS3`; components past `dim` count as zero.
fn cross_rows<S: Scalar>(a: &[Vec<S>; MAX_DIM], b: &[Vec<S>; MAX_DIM], dim: usize, n: usize, out: &mut [Vec<S>; 3]) {
    let zero = vec![S::ZERO; if dim < 3 { n } else { 0 }];
    let [ax, ay, az] = [0, 1, 2].map(|c| if c < dim { a[c].as_slice() } else { zero.as_slice() });
    let [bx, by, bz] = [0, 1, 2].map(|c| if c < dim { b[c].as_slice() } else { zero.as_slice() });
    for (c, o) in out.iter_mut().enumerate() {
        o.clear();
        let (p, q, r, s) = match c {
            0 => (ay, bz, az, by),
            1 => (az, bx, ax, bz),
            _ => (ax, by, ay, bx),
        };
        o.extend(p.iter().zip(q).zip(r.iter().zip(s)).map(|((&p, &q), (&r, &s))| p * q - r * s));
    }
}

/// Grids with fewer points than this run on one thread (handing work to the pool costs more
/// than it saves).
pub(crate) const MIN_POINTS_PER_THREAD: usize = 1 << 11;

/// Rows per band when `rows` rows of `row_len` items are shared out: all of them (one band)
/// for small grids, else about one band per thread of rayon's pool.
#[must_use]
pub fn rows_per_band(rows: usize, row_len: usize) -> usize {
    let threads = rayon::current_num_threads().min(rows.saturating_mul(row_len) / MIN_POINTS_PER_THREAD);
    rows.div_ceil(threads.clamp(1, rows.max(1))).max(1)
}

/// Runs `work(k, band)` for every band `k`, on rayon's pool when there is more than one.
pub fn run_bands<B: Send>(bands: impl Iterator<Item = B>, work: impl Fn(usize, B) + Sync) {
    let mut bands: Vec<B> = bands.collect();
    if bands.len() <= 1 {
        if let Some(band) = bands.pop() {
            work(0, band);
        }
        return;
    }
    // The caller takes the first band itself (it would only wait otherwise), so the first band's
    // memory stays with one core from call to call, and one pool thread fewer has to wake.
    let mut bands = bands.into_iter().enumerate();
    let first = bands.next();
    rayon::in_place_scope(|scope| {
        let work = &work;
        for (k, band) in bands {
            scope.spawn(move |_| work(k, band));
        }
        if let Some((k, band)) = first {
            work(k, band);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tess::grid::{eval_grid2, Grid2};

    fn net(uo: usize, vo: usize, dim: usize) -> Vec<f64> {
        (0..uo * vo * dim).map(|k| ((k * 37 % 23) as f64) * 0.3 - 2.5 + if k % dim == 3 { 4.0 } else { 0.0 }).collect()
    }

    /// The blocked basis table holds, bit for bit, what `bernstein` gives point by point: every
    /// order up to 30, parameter counts either side of the block size, in f32 and f64.
    #[test]
    fn blocked_basis_matches_bernstein_point_by_point() {
        fn check<S: Scalar + std::fmt::Debug>(from: fn(f64) -> S) {
            for order in 0..=30 {
                for n in [0, 1, 7, 63, 64, 65, 200] {
                    let params: Vec<S> = (0..n).map(|i| from(-0.25 + 1.5 * i as f64 / n.max(2) as f64)).collect();
                    let table = order_major_basis(order, &params);
                    let mut b = vec![S::ZERO; order];
                    for (i, &t) in params.iter().enumerate() {
                        crate::math::bezier::bernstein(order, t, &mut b);
                        for (a, &value) in b.iter().enumerate() {
                            assert!(table[a * n + i] == value, "order {order}, n {n}, point {i}, term {a}");
                        }
                    }
                }
            }
        }
        check::<f32>(|x| x as f32);
        check::<f64>(|x| x);
    }

    /// The row kernel gives the same bits as the point-by-point grid path, normals included.
    #[test]
    fn rows_match_the_reference_grid() {
        for dim in 1..=4 {
            for (uo, vo) in [(1, 1), (1, 4), (4, 1), (4, 4), (2, 7), (30, 3)] {
                let pts = net(uo, vo, dim);
                let map = MapView { dim, uorder: uo, vorder: vo, points: &pts };
                let us = [0.0, 0.25, 0.6, 1.0, -0.3];
                let vs = [0.0, 0.5, 1.0, 1.2];
                let mut g = Grid2::default();
                eval_grid2(&map, &us, &vs, true, &mut g);
                let kernel = RowKernel::new(map, &us, &vs, true).expect("valid");
                let mut row = Row::default();
                for j in 0..vs.len() {
                    kernel.eval_row(j, &mut row);
                    for i in 0..us.len() {
                        let k = j * us.len() + i;
                        assert_eq!(&row.point_at(i, dim)[..dim], &g.points[k][..dim], "{dim} {uo}x{vo}");
                        let (a, b) = if dim == 4 {
                            let r = crate::math::rational::rational_derivative;
                            (r(g.points[k], g.du[k]), r(g.points[k], g.dv[k]))
                        } else {
                            ([g.du[k][0], g.du[k][1], g.du[k][2]], [g.dv[k][0], g.dv[k][1], g.dv[k][2]])
                        };
                        assert_eq!(row.cross_at(i), crate::math::rational::cross(a, b), "{dim} {uo}x{vo} normal");
                    }
                }
            }
        }
    }

    /// Point by point gives the row kernel's bits (points and normal directions), in f32 and
    /// f64, for every u order it takes, with and without normals, also at parameters off the
    /// unit interval; other maps are refused.
    #[test]
    fn point_by_point_rows_match_the_row_kernel() {
        fn check<S: Scalar + std::fmt::Debug>(from: fn(f64) -> S) {
            for normals in [false, true] {
                for uo in 1..=8 {
                    for vo in [1, 2, 4, 7] {
                        let pts: Vec<S> = net(uo, vo, 3).into_iter().map(from).collect();
                        let map = MapView { dim: 3, uorder: uo, vorder: vo, points: &pts };
                        let us: Vec<S> = [0.0, 0.1, 0.25, 0.6, 0.99, 1.0, -0.3, 1.7, 0.5].map(from).to_vec();
                        let vs: Vec<S> = [0.0, 0.5, 1.0, 1.2].map(from).to_vec();
                        let kernel = RowKernel::new(map, &us, &vs, normals).expect("valid");
                        let (mut row, mut points) = (Row::default(), Row::default());
                        for j in 0..vs.len() {
                            kernel.eval_row(j, &mut row);
                            let mut got = Vec::new();
                            assert!(kernel.eval_row_points(j, &mut points, |i, p, n| got.push((i, p, n))));
                            assert_eq!(got.len(), us.len());
                            // Bits, zero signs included.
                            let bits = |v: [S; 3]| v.map(|x| x.to_f64().to_bits());
                            for (i, p, n) in got {
                                let want = [row.point[0][i], row.point[1][i], row.point[2][i]];
                                assert_eq!(bits(p), bits(want), "{uo}x{vo} point {i}");
                                let want = if normals { row.cross_at(i) } else { [S::ZERO; 3] };
                                assert_eq!(bits(n), bits(want), "{uo}x{vo} normal {i}");
                            }
                        }
                    }
                }
            }
            for (dim, uo) in [(4, 4), (2, 3), (3, 9)] {
                let pts: Vec<S> = net(uo, 2, dim).into_iter().map(from).collect();
                let map = MapView { dim, uorder: uo, vorder: 2, points: &pts };
                let kernel = RowKernel::new(map, &[S::ZERO], &[S::ZERO], true).expect("valid");
                assert!(!kernel.eval_row_points(0, &mut Row::default(), |_, _, _| panic!("emitted")));
            }
        }
        check::<f32>(|x| x as f32);
        check::<f64>(|x| x);
    }

    /// The fixed-order kernels give the bits of the one-pass-per-term sum, for every order and
    /// for rows that do and do not fill whole blocks of four.
    #[test]
    fn fixed_order_sums_match_the_plain_sum() {
        for k in 1..=10 {
            for n in 0..=13 {
                let basis: Vec<f64> = (0..k * n).map(|x| ((x * 7919 % 101) as f64 - 50.0) / 37.0).collect();
                let coeffs: Vec<f64> = (0..k).map(|a| (a as f64 - 2.5) * 1.3).collect();
                let (mut fast, mut plain) = (vec![9.0; 3], Vec::new());
                combine_row(&basis, &coeffs, n, &mut fast);
                combine_any(&basis, &coeffs, n, &mut plain);
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&fast), bits(&plain), "order {k}, {n} points");
            }
        }
    }

    #[test]
    fn malformed_map_has_no_kernel() {
        let map = MapView { dim: 3, uorder: 4, vorder: 4, points: &[1.0f32; 5] };
        assert!(RowKernel::new(map, &[0.0], &[0.0], true).is_none());
    }

    /// Tables fit only the orders, grid (bit for bit) and partials they were made for, and a
    /// kernel on tables made before evaluates as one made afresh; a map of other orders is
    /// refused them.
    #[test]
    fn shared_bases_fit_their_own_grid_only() {
        let (us, vs) = ([0.0f32, 0.25, 0.5, 1.0], [0.0f32, 0.5, 1.0]);
        let bases = Arc::new(RowBases::new(3, 2, &us, &vs, true));
        assert!(bases.fits(3, 2, &us, &vs, true));
        assert!(!bases.fits(3, 2, &us, &vs, false));
        assert!(!bases.fits(2, 3, &us, &vs, true));
        assert!(!bases.fits(3, 2, &[-0.0, 0.25, 0.5, 1.0], &vs, true));
        assert!(!bases.fits(3, 2, &us[..3], &vs, true));
        let points: Vec<f32> = (0..3 * 2 * 3).map(|x| ((x * 37 % 23) as f32) * 0.3 - 2.5).collect();
        let map = MapView { dim: 3, uorder: 3, vorder: 2, points: &points };
        let (shared, fresh) =
            (RowKernel::with_bases(map, Arc::clone(&bases)).unwrap(), RowKernel::new(map, &us, &vs, true).unwrap());
        for j in 0..vs.len() {
            let (mut a, mut b) = (Row::default(), Row::default());
            shared.eval_row(j, &mut a);
            fresh.eval_row(j, &mut b);
            let bits = |r: &Row<f32>| r.point.iter().chain(&r.cross).flatten().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&a), bits(&b));
        }
        let other = MapView { dim: 3, uorder: 2, vorder: 3, points: &points };
        assert!(RowKernel::with_bases(other, bases).is_none());
    }
}
