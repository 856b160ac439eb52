//! Grid evaluation of Bezier curves and patches with the basis precomputed per row and column.
//!
//! For an nu × nv grid of a patch of orders (p, q) in `dim` components, the cost is
//! O(nv·p·q·dim) to reduce each v row, then O(nu·nv·p·dim) for the points, instead of
//! O(nu·nv·p·q·dim) for point-by-point evaluation. Every grid point is evaluated once: the
//! strips and line loops of `glEvalMesh2` index shared points.

use crate::math::bezier::{bernstein, Vec4, MAX_DIM};
use crate::math::Scalar;

/// Bernstein basis values of one order at a list of normalised parameters, and (optionally) the
/// basis of one order lower for derivatives taken on control-point differences.
#[derive(Clone, Debug, Default)]
pub struct BasisTable<S: Scalar> {
    order: usize,
    values: Vec<S>,
    lower: Vec<S>,
}

impl<S: Scalar> BasisTable<S> {
    /// Builds the table for `params`; `lower` also stores the order−1 basis.
    #[must_use]
    pub fn new(order: usize, params: &[S], lower: bool) -> Self {
        let mut values = vec![S::ZERO; params.len() * order];
        let low_order = if lower { order.saturating_sub(1) } else { 0 };
        let mut low = vec![S::ZERO; params.len() * low_order];
        for (k, &t) in params.iter().enumerate() {
            bernstein(order, t, &mut values[k * order..(k + 1) * order]);
            if low_order > 0 {
                bernstein(low_order, t, &mut low[k * low_order..(k + 1) * low_order]);
            }
        }
        Self { order, values, lower: low }
    }

    /// Basis values at parameter number `k`.
    #[must_use]
    pub fn at(&self, k: usize) -> &[S] {
        &self.values[k * self.order..(k + 1) * self.order]
    }

    /// Order−1 basis values at parameter number `k` (empty for order 1 or without `lower`).
    #[must_use]
    pub fn lower_at(&self, k: usize) -> &[S] {
        let lo = self.order.saturating_sub(1);
        if self.lower.is_empty() {
            return &[];
        }
        &self.lower[k * lo..(k + 1) * lo]
    }
}

/// A packed Bezier map: `points[(i * vorder + j) * dim + c]` (a curve has `vorder` = 1).
#[derive(Clone, Copy, Debug)]
pub struct MapView<'a, S: Scalar> {
    /// Components per point, 1..=4.
    pub dim: usize,
    /// Order along u.
    pub uorder: usize,
    /// Order along v (1 for a curve).
    pub vorder: usize,
    /// The packed control points.
    pub points: &'a [S],
}

impl<S: Scalar> MapView<'_, S> {
    pub(crate) fn is_valid(&self) -> bool {
        self.dim >= 1
            && self.dim <= MAX_DIM
            && self.uorder >= 1
            && self.vorder >= 1
            && self.points.len() >= self.uorder * self.vorder * self.dim
    }
}

/// Evaluates a curve (a map with `vorder` = 1) at each normalised parameter in `us`.
#[cfg(test)]
pub fn eval_grid1<S: Scalar>(map: &MapView<'_, S>, us: &[S], out: &mut Vec<Vec4<S>>) {
    out.clear();
    if !map.is_valid() {
        out.resize(us.len(), [S::ZERO; MAX_DIM]);
        return;
    }
    let table = BasisTable::new(map.uorder, us, false);
    let dim = map.dim;
    out.extend((0..us.len()).map(|k| {
        let mut p = [S::ZERO; MAX_DIM];
        for (a, &b) in table.at(k).iter().enumerate() {
            for c in 0..dim {
                p[c] += b * map.points[a * dim + c];
            }
        }
        p
    }));
}

/// Points (and optionally partial derivatives) of a patch over a grid, row-major with v outer:
/// the value at (`us[i]`, `vs[j]`) is at `j * us.len() + i`.
#[derive(Clone, Debug, Default)]
pub struct Grid2<S: Scalar> {
    /// Grid points.
    pub points: Vec<Vec4<S>>,
    /// ∂p/∂u with respect to the normalised u (empty unless asked for).
    pub du: Vec<Vec4<S>>,
    /// ∂p/∂v with respect to the normalised v (empty unless asked for).
    pub dv: Vec<Vec4<S>>,
}

/// Evaluates a patch over the grid `us` × `vs` (normalised parameters) into `out`.
/// With `partials`, derivatives are computed on control-point differences, so a collapsed
/// edge gives exactly zero, as Mesa's de Casteljau does.
pub fn eval_grid2<S: Scalar>(map: &MapView<'_, S>, us: &[S], vs: &[S], partials: bool, out: &mut Grid2<S>) {
    let n = us.len() * vs.len();
    out.points.clear();
    out.du.clear();
    out.dv.clear();
    if !map.is_valid() {
        out.points.resize(n, [S::ZERO; MAX_DIM]);
        if partials {
            out.du.resize(n, [S::ZERO; MAX_DIM]);
            out.dv.resize(n, [S::ZERO; MAX_DIM]);
        }
        return;
    }
    let ut = BasisTable::new(map.uorder, us, partials);
    let vt = BasisTable::new(map.vorder, vs, partials);
    let mut rows = vec![[S::ZERO; MAX_DIM]; map.uorder];
    let mut rows_dv = vec![[S::ZERO; MAX_DIM]; map.uorder];
    for j in 0..vs.len() {
        reduce_rows(map, vt.at(j), vt.lower_at(j), partials, &mut rows, &mut rows_dv);
        for i in 0..us.len() {
            out.points.push(combine(ut.at(i), &rows, map.dim));
            if partials {
                out.du.push(combine_differences(ut.lower_at(i), &rows, map.dim, map.uorder));
                out.dv.push(combine(ut.at(i), &rows_dv, map.dim));
            }
        }
    }
}

/// Reduces every u row of the net along v: `rows[i] = Σⱼ Bⱼ(v) Pᵢⱼ`, and with `partials`
/// `rows_dv[i] = q Σⱼ Bⱼ^{q−1}(v) (Pᵢ,ⱼ₊₁ − Pᵢⱼ)`.
pub(crate) fn reduce_rows<S: Scalar>(
    map: &MapView<'_, S>,
    bv: &[S],
    bv_low: &[S],
    partials: bool,
    rows: &mut [Vec4<S>],
    rows_dv: &mut [Vec4<S>],
) {
    if !partials {
        // Points only (the GLU tessellator, meshes without normals): the component loop fixed
        // at compile time. The same sums in the same order as below.
        match map.dim {
            1 => reduce_points::<S, 1>(map, bv, rows),
            2 => reduce_points::<S, 2>(map, bv, rows),
            3 => reduce_points::<S, 3>(map, bv, rows),
            _ => reduce_points::<S, 4>(map, bv, rows),
        }
        rows_dv.iter_mut().take(map.uorder).for_each(|r| *r = [S::ZERO; MAX_DIM]);
        return;
    }
    // With partials (meshes with normals): the component loop fixed at compile time too.
    // Three components of v order 2 to 6 (the usual surfaces) with the v order fixed too, so
    // that the sums along v unroll.
    match (map.dim, map.vorder) {
        (3, 2) => reduce_with_partials::<S, 3, 2>(map, bv, bv_low, rows, rows_dv),
        (3, 3) => reduce_with_partials::<S, 3, 3>(map, bv, bv_low, rows, rows_dv),
        (3, 4) => reduce_with_partials::<S, 3, 4>(map, bv, bv_low, rows, rows_dv),
        (3, 5) => reduce_with_partials::<S, 3, 5>(map, bv, bv_low, rows, rows_dv),
        (3, 6) => reduce_with_partials::<S, 3, 6>(map, bv, bv_low, rows, rows_dv),
        (1, _) => reduce_with_partials::<S, 1, 0>(map, bv, bv_low, rows, rows_dv),
        (2, _) => reduce_with_partials::<S, 2, 0>(map, bv, bv_low, rows, rows_dv),
        (3, _) => reduce_with_partials::<S, 3, 0>(map, bv, bv_low, rows, rows_dv),
        _ => reduce_with_partials::<S, 4, 0>(map, bv, bv_low, rows, rows_dv),
    }
}

/// [`reduce_rows`] with partials for maps of `D` components and v order `V` (0: the map's, read
/// at run time): each sum from zero up, over j in order, the v partial's scaled by q at the end.
fn reduce_with_partials<S: Scalar, const D: usize, const V: usize>(
    map: &MapView<'_, S>,
    bv: &[S],
    bv_low: &[S],
    rows: &mut [Vec4<S>],
    rows_dv: &mut [Vec4<S>],
) {
    let vorder = if V == 0 { map.vorder } else { V };
    let q = S::from_usize(vorder - 1);
    let column = vorder * D;
    let nets = map.points.chunks_exact(column).take(map.uorder);
    for ((row_out, dv_out), net) in rows.iter_mut().zip(rows_dv.iter_mut()).zip(nets) {
        let point = |j: usize| -> [S; D] { std::array::from_fn(|c| net[j * D + c]) };
        let mut row = [S::ZERO; D];
        let mut row_dv = [S::ZERO; D];
        for (j, &b) in bv.iter().enumerate().take(vorder) {
            let p = point(j);
            for c in 0..D {
                row[c] += b * p[c];
            }
            if j + 1 < vorder {
                let (next, low) = (point(j + 1), bv_low[j]);
                for c in 0..D {
                    row_dv[c] += low * (next[c] - p[c]);
                }
            }
        }
        *row_out = std::array::from_fn(|c| if c < D { row[c] } else { S::ZERO });
        *dv_out = std::array::from_fn(|c| if c < D { row_dv[c] * q } else { S::ZERO });
    }
}

/// [`reduce_rows`]' point sums for maps of `D` components.
fn reduce_points<S: Scalar, const D: usize>(map: &MapView<'_, S>, bv: &[S], rows: &mut [Vec4<S>]) {
    let column = map.vorder * D;
    for (row, net) in rows.iter_mut().zip(map.points.chunks_exact(column)).take(map.uorder) {
        let mut sum = [S::ZERO; MAX_DIM];
        for (&b, point) in bv.iter().zip(net.chunks_exact(D)) {
            for c in 0..D {
                sum[c] += b * point[c];
            }
        }
        *row = sum;
    }
}

fn combine<S: Scalar>(basis: &[S], rows: &[Vec4<S>], dim: usize) -> Vec4<S> {
    let mut p = [S::ZERO; MAX_DIM];
    for (b, row) in basis.iter().zip(rows) {
        for c in 0..dim {
            p[c] += *b * row[c];
        }
    }
    p
}

fn combine_differences<S: Scalar>(low: &[S], rows: &[Vec4<S>], dim: usize, order: usize) -> Vec4<S> {
    let mut d = [S::ZERO; MAX_DIM];
    if order < 2 {
        return d;
    }
    let n = S::from_usize(order - 1);
    for (a, b) in low.iter().enumerate() {
        for c in 0..dim {
            d[c] += *b * (rows[a + 1][c] - rows[a][c]);
        }
    }
    for v in d.iter_mut().take(dim) {
        *v *= n;
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::patch::{horner_patch, patch_with_partials};

    fn net(uo: usize, vo: usize, dim: usize) -> Vec<f64> {
        (0..uo * vo * dim).map(|k| ((k * 53 % 17) as f64) * 0.25 - 2.0).collect()
    }

    /// The basis of order `vo` at `t` and the one an order lower (at least order 1).
    fn v_bases(vo: usize, t: f64) -> (Vec<f64>, Vec<f64>) {
        let mut bv = vec![0.0; vo];
        crate::math::bezier::bernstein(vo, t, &mut bv);
        let low_order = vo.saturating_sub(1).max(1);
        let mut low = vec![0.0; low_order];
        crate::math::bezier::bernstein(low_order, t, &mut low);
        (bv, low)
    }

    /// The points-only reduction gives the bits of the one that also reduces the partials.
    #[test]
    fn points_only_rows_match_the_general_reduction() {
        for dim in 1..=4 {
            for (uo, vo) in [(1, 1), (4, 4), (3, 7), (30, 2)] {
                let pts = net(uo, vo, dim);
                let map = MapView { dim, uorder: uo, vorder: vo, points: &pts };
                let (bv, low) = v_bases(vo, 0.37);
                let (mut fast, mut general) = (vec![[9.0; 4]; uo], vec![[9.0; 4]; uo]);
                let mut dv = vec![[0.0; 4]; uo];
                reduce_rows(&map, &bv, &low, false, &mut fast, &mut dv);
                reduce_rows(&map, &bv, &low, true, &mut general, &mut dv);
                let bits = |rows: &[[f64; 4]]| rows.iter().map(|r| r.map(f64::to_bits)).collect::<Vec<_>>();
                assert_eq!(bits(&fast), bits(&general), "{dim} {uo}x{vo}");
            }
        }
    }

    /// The reduction with partials (its v order fixed at compile time for three components of
    /// orders 2 to 6, read at run time otherwise) gives the bits of the plain sums written as
    /// documented: Σⱼ Bⱼ(v) Pᵢⱼ and q Σⱼ Bⱼ^{q−1}(v) (Pᵢ,ⱼ₊₁ − Pᵢⱼ), j in order from zero.
    #[test]
    fn rows_with_partials_are_the_plain_sums() {
        for dim in 1..=4 {
            for vo in 1..=8 {
                let uo = 3;
                let pts = net(uo, vo, dim);
                let map = MapView { dim, uorder: uo, vorder: vo, points: &pts };
                let (bv, low) = v_bases(vo, 0.37);
                let (mut rows, mut rows_dv) = (vec![[9.0; 4]; uo], vec![[9.0; 4]; uo]);
                reduce_rows(&map, &bv, &low, true, &mut rows, &mut rows_dv);
                for i in 0..uo {
                    let at = |j: usize, c: usize| pts[(i * vo + j) * dim + c];
                    let (mut p, mut d) = ([0.0f64; 4], [0.0f64; 4]);
                    for c in 0..dim {
                        for j in 0..vo {
                            p[c] += bv[j] * at(j, c);
                        }
                        for j in 0..vo - 1 {
                            d[c] += low[j] * (at(j + 1, c) - at(j, c));
                        }
                        d[c] *= (vo - 1) as f64;
                    }
                    assert_eq!(rows[i].map(f64::to_bits), p.map(f64::to_bits), "{dim} components, v order {vo}");
                    assert_eq!(rows_dv[i].map(f64::to_bits), d.map(f64::to_bits), "{dim} components, v order {vo}");
                }
            }
        }
    }

    #[test]
    fn grid_matches_pointwise_evaluation() {
        for (uo, vo) in [(1, 1), (1, 4), (4, 1), (4, 4), (2, 7), (30, 3)] {
            let pts = net(uo, vo, 4);
            let map = MapView { dim: 4, uorder: uo, vorder: vo, points: &pts };
            let us = [0.0, 0.25, 0.6, 1.0, -0.3];
            let vs = [0.0, 0.5, 1.0, 1.2];
            let mut g = Grid2::default();
            eval_grid2(&map, &us, &vs, true, &mut g);
            for (j, &v) in vs.iter().enumerate() {
                for (i, &u) in us.iter().enumerate() {
                    let k = j * us.len() + i;
                    let want = horner_patch(&pts, 4, uo, vo, u, v);
                    let s = patch_with_partials(&pts, 4, uo, vo, u, v);
                    for c in 0..4 {
                        let tol = 1e-9 * (1.0 + want[c].abs());
                        assert!((g.points[k][c] - want[c]).abs() < tol, "{uo}x{vo} point");
                        assert!((g.du[k][c] - s.du[c]).abs() < 1e-7 * (1.0 + s.du[c].abs()));
                        assert!((g.dv[k][c] - s.dv[c]).abs() < 1e-7 * (1.0 + s.dv[c].abs()));
                    }
                }
            }
        }
    }

    #[test]
    fn curve_grid_matches_horner() {
        let pts = net(7, 1, 3);
        let map = MapView { dim: 3, uorder: 7, vorder: 1, points: &pts };
        let us = [0.0, 0.1, 0.5, 0.99, 1.0];
        let mut out = Vec::new();
        eval_grid1(&map, &us, &mut out);
        for (k, &u) in us.iter().enumerate() {
            let want = crate::math::bezier::horner(&pts, 3, 7, u);
            for c in 0..3 {
                assert!((out[k][c] - want[c]).abs() < 1e-10);
            }
        }
    }

    #[test]
    fn invalid_map_gives_zeros_not_panic() {
        let map = MapView { dim: 3, uorder: 4, vorder: 4, points: &[1.0f32; 5] };
        let mut g = Grid2::default();
        eval_grid2(&map, &[0.0, 1.0], &[0.5], true, &mut g);
        assert_eq!(g.points.len(), 2);
        assert_eq!(g.du[1], [0.0; 4]);
    }
}
