//! GLU's own evaluator for tessellator mode, in `f32` as GLU computes it: a Bezier patch held
//! as GLU's `surfEvalMachine` (`interface/insurfeval.cc`), evaluated by Bernstein coefficients
//! built up order by order (`inPreEvaluateWithDeriv`), summed row by row
//! (`inDoDomain2WithDerivsEM`), with the analytic normal of `inDoEvalCoord2EM`: the partials
//! w-corrected for rational maps (`inComputeFirstPartials`), crossed and normalised
//! (`inComputeNormal2`), a vanishing partial re-taken a little inside the patch
//! (`AVOID_ZERO_NORMAL`). Reproducing the arithmetic rather than only the mathematics keeps the
//! printed vertices and normals GLU's to the last digit.

use std::cell::RefCell;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// GLU's `MAXORDER`; larger orders are refused before they get here.
pub(crate) const MAX_ORDER: usize = 24;
/// `MYZERO`: a partial no larger than this in every component counts as vanishing.
const ZERO: f32 = 0.000001;
/// `MYDELTA`: how far (as a fraction of the patch) GLU moves to re-take a vanishing partial.
const DELTA: f32 = 0.001;

/// One map's Bezier patch over [u1, u2] × [v1, v2]: `k` floats a point, v fastest.
#[derive(Clone, Debug)]
pub(crate) struct PatchMachine {
    k: usize,
    u: (f32, f32),
    v: (f32, f32),
    uorder: usize,
    vorder: usize,
    points: Vec<f32>,
    /// Whether samples carry the partials (else they are left zero: a map whose values are
    /// all that is handed out, with no automatic normal, needs a third of the work).
    partials: bool,
    /// What the last samples worked out, by parameter (see [`Recent`]).
    recent: RefCell<Recent>,
    /// Every grid line's row sums and coefficients worked out so far (see [`Lines`]).
    lines: RefCell<Lines>,
}

/// The row sums and u coefficients of the grid lines a machine's grid blocks have sampled, by
/// the normalised parameter's bits: a patch's blocks (a trimmed region's rows and columns of
/// quads) share its grid lines, so each line's work is done once per patch. Grid lines only:
/// points along the trim curves, each on lines of its own, go through [`Recent`].
#[derive(Clone, Debug, Default)]
struct Lines {
    rows: HashMap<u32, Box<RowSums>, BuildHasherDefault<BitsHasher>>,
    coefficients: HashMap<u32, Box<UCoefficients>, BuildHasherDefault<BitsHasher>>,
}

/// A hasher for `f32` bits: one multiplication (Fibonacci hashing), the keys being few and
/// never adversarial.
#[derive(Default)]
struct BitsHasher(u64);

impl Hasher for BitsHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0.rotate_left(8) ^ u64::from(b)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        }
    }

    fn write_u32(&mut self, v: u32) {
        self.0 = u64::from(v).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    }
}

/// The sums along v of each row of control points (and of their v derivative) at one v: all
/// of a sample's work that does not depend on u.
#[derive(Clone, Debug)]
struct RowSums {
    t: u32,
    p: [[f32; 4]; MAX_ORDER],
    pdv: [[f32; 4]; MAX_ORDER],
}

/// The u coefficients and their derivatives at one u.
#[derive(Clone, Copy, Debug)]
struct UCoefficients {
    s: u32,
    c: [f32; MAX_ORDER],
    d: [f32; MAX_ORDER],
}

/// The two latest v rows and u coefficients a machine worked out, keyed by the normalised
/// parameter's bits: GLU's strips alternate between two v values and step u every other vertex,
/// so most samples find both here (GLU's `surfEvalMachine` keeps the last u and v likewise,
/// `uprime`/`vprime`). The values are the ones a fresh evaluation gives, bit for bit.
#[derive(Clone, Debug, Default)]
struct Recent {
    rows: [Option<Box<RowSums>>; 2],
    coefficients: [Option<UCoefficients>; 2],
}

/// A point (k values) and its partials in the patch's normalised parameters.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct MachineSample {
    pub point: [f32; 4],
    pub du: [f32; 4],
    pub dv: [f32; 4],
}

impl PatchMachine {
    /// The machine for control points `points` (u-major), or `None` for orders GLU refuses.
    pub fn new(points: &[f64], k: usize, orders: (usize, usize), u: (f32, f32), v: (f32, f32)) -> Option<Self> {
        let (uorder, vorder) = orders;
        let fits = (1..=MAX_ORDER).contains(&uorder) && (1..=MAX_ORDER).contains(&vorder) && (1..=4).contains(&k);
        if !fits || points.len() < uorder * vorder * k {
            return None;
        }
        let points = points[..uorder * vorder * k].iter().map(|&c| c as f32).collect();
        Some(Self {
            k,
            u,
            v,
            uorder,
            vorder,
            points,
            partials: true,
            recent: RefCell::default(),
            lines: RefCell::default(),
        })
    }

    /// The machine, its samples without partials (the values are the same bits).
    #[must_use]
    pub fn without_partials(self) -> Self {
        Self { partials: false, ..self }
    }

    /// The value and partials at (u, v); `None` on an empty patch (GLU evaluates nothing).
    pub fn sample(&self, u: f32, v: f32) -> Option<MachineSample> {
        if self.u.1 == self.u.0 || self.v.1 == self.v.0 {
            return None;
        }
        let s = (u - self.u.0) / (self.u.1 - self.u.0);
        let t = (v - self.v.0) / (self.v.1 - self.v.0);
        let mut recent = self.recent.borrow_mut();
        let (r, c) = (self.row_sums(&mut recent, t), self.u_coefficients_at(&mut recent, s));
        let (Some(rows), Some(uc)) = (recent.rows[r].as_deref(), recent.coefficients[c].as_ref()) else {
            return None;
        };
        Some(self.combine(rows, uc))
    }

    /// [`Self::sample`] at every (us[i], vs[j]), j outer: the sums along v once per v and the
    /// u coefficients once per u, so every point costs its sum along u alone (what a grid
    /// block's strips, which meet each point twice and each line many times, would otherwise
    /// work out again and again). The same bits as [`Self::sample`] point by point. `None` on
    /// an empty patch.
    pub fn sample_grid(&self, us: &[f32], vs: &[f32]) -> Option<Vec<MachineSample>> {
        if self.u.1 == self.u.0 || self.v.1 == self.v.0 {
            return None;
        }
        let mut lines = self.lines.borrow_mut();
        let Lines { rows, coefficients: line_coefficients } = &mut *lines;
        let normalised = |u: f32| (u - self.u.0) / (self.u.1 - self.u.0);
        for &u in us {
            let s = normalised(u);
            line_coefficients.entry(s.to_bits()).or_insert_with(|| {
                let (c, d) = coefficients(self.uorder, s);
                Box::new(UCoefficients { s: s.to_bits(), c, d })
            });
        }
        let ucs: Vec<&UCoefficients> = us.iter().map(|&u| &*line_coefficients[&normalised(u).to_bits()]).collect();
        let mut out = Vec::with_capacity(us.len() * vs.len());
        for &v in vs {
            let t = (v - self.v.0) / (self.v.1 - self.v.0);
            let sums = rows.entry(t.to_bits()).or_insert_with(|| Box::new(self.sums_at(t)));
            out.extend(ucs.iter().map(|uc| self.combine(sums, uc)));
        }
        Some(out)
    }

    /// A sample from its row sums and u coefficients: each component summed over the rows in
    /// GLU's order (`inDoDomain2WithDerivsEM`).
    fn combine(&self, rows: &RowSums, uc: &UCoefficients) -> MachineSample {
        let mut out = MachineSample::default();
        if !self.partials {
            for j in 0..self.k {
                for row in 0..self.uorder {
                    out.point[j] += uc.c[row] * rows.p[row][j];
                }
            }
            return out;
        }
        for j in 0..self.k {
            for row in 0..self.uorder {
                let (p, pdv) = (rows.p[row][j], rows.pdv[row][j]);
                out.point[j] += uc.c[row] * p;
                out.du[j] += uc.d[row] * p;
                out.dv[j] += uc.c[row] * pdv;
            }
        }
        out
    }

    /// Where in `recent` the row sums at normalised v = `t` are (worked out if missing).
    fn row_sums(&self, recent: &mut Recent, t: f32) -> usize {
        if let Some(k) = recent.rows.iter().position(|r| r.as_ref().is_some_and(|r| r.t == t.to_bits())) {
            return k;
        }
        let sums = self.sums_at(t);
        // The older entry makes way.
        recent.rows.swap(0, 1);
        recent.rows[0] = Some(Box::new(sums));
        0
    }

    /// The row sums at normalised v = `t`.
    fn sums_at(&self, t: f32) -> RowSums {
        let (vc, vd) = coefficients(self.vorder, t);
        let mut sums = RowSums { t: t.to_bits(), p: [[0.0; 4]; MAX_ORDER], pdv: [[0.0; 4]; MAX_ORDER] };
        for row in 0..self.uorder {
            for j in 0..self.k {
                let at = |col: usize| self.points[(row * self.vorder + col) * self.k + j];
                let mut p = vc[0] * at(0);
                for col in 1..self.vorder {
                    p += vc[col] * at(col);
                }
                sums.p[row][j] = p;
                if self.partials {
                    let mut pdv = vd[0] * at(0);
                    for col in 1..self.vorder {
                        pdv += vd[col] * at(col);
                    }
                    sums.pdv[row][j] = pdv;
                }
            }
        }
        sums
    }

    /// Where in `recent` the u coefficients at normalised u = `s` are (worked out if missing).
    fn u_coefficients_at(&self, recent: &mut Recent, s: f32) -> usize {
        if let Some(k) = recent.coefficients.iter().position(|c| c.is_some_and(|c| c.s == s.to_bits())) {
            return k;
        }
        let (c, d) = coefficients(self.uorder, s);
        recent.coefficients.swap(0, 1);
        recent.coefficients[0] = Some(UCoefficients { s: s.to_bits(), c, d });
        0
    }

    /// The position (divided by w for k = 4) and the unit normal at (u, v) from the sample
    /// there, as GLU's automatic normal computes them (the sample taken again near by where a
    /// partial vanishes).
    pub fn point_and_normal_of(&self, s: MachineSample, u: f32, v: f32) -> Option<([f32; 3], [f32; 3])> {
        let (p, mut du, mut dv) = (s.point, s.du, s.dv);
        if self.k == 4 {
            first_partials(&p, &mut du, &mut dv);
        }
        let vanishing = |d: &[f32; 4]| d[..3].iter().all(|c| c.abs() <= ZERO);
        if vanishing(&dv) {
            let (lo, hi) = self.u;
            let u = if u - DELTA * (hi - lo) < lo { u + DELTA * (hi - lo) } else { u - DELTA * (hi - lo) };
            dv = self.sample(u, v)?.dv;
            if self.k == 4 {
                first_partials(&p, &mut du, &mut dv);
            }
        } else if vanishing(&du) {
            let (lo, hi) = self.v;
            let v = if v - DELTA * (hi - lo) < lo { v + DELTA * (hi - lo) } else { v - DELTA * (hi - lo) };
            du = self.sample(u, v)?.du;
            if self.k == 4 {
                first_partials(&p, &mut du, &mut dv);
            }
        }
        Some((project(&p, self.k), normal(&du, &dv)))
    }

    /// [`Self::position_of`] the sample at (us[i], v) for every i, into `out` as [x, y, z, u, v]: the same
    /// arithmetic, with the sums along v (which depend on v only) and the u coefficients
    /// (given per column in `ucoeffs`, from [`Self::u_coefficients`]) taken once per row.
    pub fn position_row(&self, v: f32, us: &[f32], ucoeffs: &[[f32; MAX_ORDER]], out: &mut [[f32; 5]]) -> Option<()> {
        if self.u.1 == self.u.0 || self.v.1 == self.v.0 {
            return None;
        }
        let (vc, _) = coefficients(self.vorder, (v - self.v.0) / (self.v.1 - self.v.0));
        let mut p = [[0.0f32; 4]; MAX_ORDER];
        for (row, sums) in p.iter_mut().enumerate().take(self.uorder) {
            for (j, sum) in sums.iter_mut().enumerate().take(self.k) {
                let at = |col: usize| self.points[(row * self.vorder + col) * self.k + j];
                *sum = vc[0] * at(0);
                for col in 1..self.vorder {
                    *sum += vc[col] * at(col);
                }
            }
        }
        match self.uorder {
            2 => row_along_u::<2>(&p, self.k, v, us, ucoeffs, out),
            3 => row_along_u::<3>(&p, self.k, v, us, ucoeffs, out),
            4 => row_along_u::<4>(&p, self.k, v, us, ucoeffs, out),
            5 => row_along_u::<5>(&p, self.k, v, us, ucoeffs, out),
            6 => row_along_u::<6>(&p, self.k, v, us, ucoeffs, out),
            _ => row_along_u::<MAX_ORDER>(&p[..self.uorder], self.k, v, us, ucoeffs, out),
        }
        Some(())
    }

    /// The machine's positions alone, without its caches: shareable between threads.
    pub fn positions(&self) -> Positions<'_> {
        Positions { k: self.k, u: self.u, v: self.v, uorder: self.uorder, vorder: self.vorder, points: &self.points }
    }

    /// The u coefficients of every value of `us`, for [`Self::position_row`].
    pub fn u_coefficients(&self, us: &[f32]) -> Vec<[f32; MAX_ORDER]> {
        us.iter().map(|&u| coefficients(self.uorder, (u - self.u.0) / (self.u.1 - self.u.0)).0).collect()
    }

    /// The position (divided by w for k = 4) of a sample: GLU's `inDoDomain2EM`.
    pub fn position_of(&self, s: &MachineSample) -> [f32; 3] {
        project(&s.point, self.k)
    }
}

/// A [`PatchMachine`]'s positions (x, y, z divided by w for k = 4) with nothing cached, so
/// that threads can share it: each point's arithmetic is [`PatchMachine::sample`]'s followed
/// by [`PatchMachine::position_of`], to the bit. `None` on an empty patch.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Positions<'a> {
    k: usize,
    u: (f32, f32),
    v: (f32, f32),
    uorder: usize,
    vorder: usize,
    points: &'a [f32],
}

/// A grid's lines with their row sums and u coefficients (see [`Positions::line_table`]),
/// each line's `uorder` of them side by side.
#[derive(Clone, Debug)]
pub(crate) struct LineTable {
    pub us: Vec<f32>,
    pub vs: Vec<f32>,
    uorder: usize,
    rows: Vec<[f32; 4]>,
    ucs: Vec<f32>,
    /// Where each line is, by its parameter's bits.
    uindex: HashMap<u32, usize, BuildHasherDefault<BitsHasher>>,
    vindex: HashMap<u32, usize, BuildHasherDefault<BitsHasher>>,
}

impl Positions<'_> {
    /// Whether the patch is empty (GLU evaluates nothing on it).
    pub fn empty(&self) -> bool {
        self.u.1 == self.u.0 || self.v.1 == self.v.0
    }

    /// The sums along v of every row of control points at v (`sums_at`'s point sums).
    fn row_sums(&self, v: f32) -> [[f32; 4]; MAX_ORDER] {
        let mut p = [[0.0f32; 4]; MAX_ORDER];
        self.row_sums_into(v, &mut p);
        p
    }

    /// [`Self::row_sums`] into `p`, whose entries past the first `uorder` rows and `k`
    /// components are left as they are (nothing reads them but [`Self::combine`], which
    /// ignores them: `project` reads `k` components).
    fn row_sums_into(&self, v: f32, p: &mut [[f32; 4]; MAX_ORDER]) {
        let t = (v - self.v.0) / (self.v.1 - self.v.0);
        let vc = values(self.vorder, t);
        match self.k {
            3 => self.row_sums_as::<3>(&vc, p),
            4 => self.row_sums_as::<4>(&vc, p),
            2 => self.row_sums_as::<2>(&vc, p),
            _ => self.row_sums_as::<1>(&vc, p),
        }
    }

    /// [`Self::row_sums_into`] for `K` = k components: each component's sum over the row's
    /// control points from the first, in the same order (the components side by side).
    #[inline(always)]
    fn row_sums_as<const K: usize>(&self, vc: &[f32; MAX_ORDER], p: &mut [[f32; 4]; MAX_ORDER]) {
        let n = self.vorder * K;
        for (row, sums) in p.iter_mut().enumerate().take(self.uorder) {
            let points = &self.points[row * n..(row + 1) * n];
            let mut acc = [0.0f32; K];
            for (a, x) in acc.iter_mut().zip(&points[..K]) {
                *a = vc[0] * x;
            }
            for (w, col) in vc.iter().zip(points.chunks_exact(K)).skip(1) {
                for (a, x) in acc.iter_mut().zip(col) {
                    *a += w * x;
                }
            }
            sums[..K].copy_from_slice(&acc);
        }
    }

    /// The u coefficients at u.
    fn u_values(&self, u: f32) -> [f32; MAX_ORDER] {
        values(self.uorder, (u - self.u.0) / (self.u.1 - self.u.0))
    }

    /// The position from the row sums and the u coefficients (`combine`, then `project`).
    #[inline]
    fn combine(&self, p: &[[f32; 4]], uc: &[f32]) -> [f32; 3] {
        if self.k == 4 {
            self.combine_as::<true>(p, uc)
        } else {
            self.combine_as::<false>(p, uc)
        }
    }

    /// [`Self::combine`] with the division by w (k = 4) or without, decided by the caller
    /// outside its loops (so that no division is worked out and thrown away per point).
    #[inline(always)]
    fn combine_as<const RATIONAL: bool>(&self, p: &[[f32; 4]], uc: &[f32]) -> [f32; 3] {
        // Each component's sum runs over the rows in GLU's order, from zero as `combine`'s.
        let mut point = [0.0f32; 4];
        for (w, sums) in uc.iter().zip(p).take(self.uorder) {
            for (c, s) in point.iter_mut().zip(sums) {
                *c += w * s;
            }
        }
        if RATIONAL {
            [point[0] / point[3], point[1] / point[3], point[2] / point[3]]
        } else {
            [point[0], point[1], point[2]]
        }
    }

    /// The position at (u, v) as [x, y, z, u, v].
    #[cfg(test)]
    pub fn at(&self, u: f32, v: f32) -> Option<[f32; 5]> {
        if self.empty() {
            return None;
        }
        let q = self.combine(&self.row_sums(v), &self.u_values(u));
        Some([q[0], q[1], q[2], u, v])
    }

    #[cfg(test)]
    /// The positions at (u, v) for every point of `uvs`, into `out` (as long), a v row's sums
    /// kept while consecutive points share it.
    #[cfg(test)]
    pub fn points_into(&self, uvs: &[[f32; 2]], out: &mut [[f32; 5]]) -> Option<()> {
        if self.empty() {
            return None;
        }
        let mut row: Option<(u32, [[f32; 4]; MAX_ORDER])> = None;
        for (&[u, v], slot) in uvs.iter().zip(out) {
            let sums = match &row {
                Some((bits, sums)) if *bits == v.to_bits() => sums,
                _ => &row.insert((v.to_bits(), self.row_sums(v))).1,
            };
            let q = self.combine(sums, &self.u_values(u));
            *slot = [q[0], q[1], q[2], u, v];
        }
        Some(())
    }

    /// The row sums and u coefficients of the grid lines `us` × `vs`, for [`Self::table_at`]
    /// (a few hundred lines: not worth waking the pool for).
    pub fn line_table(&self, us: Vec<f32>, vs: Vec<f32>) -> LineTable {
        let n = self.uorder;
        let rows = vs.iter().flat_map(|&v| self.row_sums(v).into_iter().take(n)).collect();
        let ucs = us.iter().flat_map(|&u| self.u_values(u).into_iter().take(n)).collect();
        let index = |values: &[f32]| values.iter().zip(0..).map(|(x, k)| (x.to_bits(), k)).collect();
        LineTable { uindex: index(&us), vindex: index(&vs), us, vs, uorder: n, rows, ucs }
    }

    /// [`Self::points_into`], the sums and u coefficients of points on the lines of `table`
    /// (made by [`Self::line_table`] on this patch) taken from there: the same bits.
    pub fn points_into_with(&self, uvs: &[[f32; 2]], out: &mut [[f32; 5]], table: &LineTable) -> Option<()> {
        if self.empty() {
            return None;
        }
        // The sums of the last v off the table's lines, worked out in place.
        let mut row = [[0.0f32; 4]; MAX_ORDER];
        let mut row_v: Option<u32> = None;
        for (&[u, v], slot) in uvs.iter().zip(out) {
            let sums = match table.v_slot(v) {
                Some(j) => table.row(j),
                None => {
                    if row_v != Some(v.to_bits()) {
                        self.row_sums_into(v, &mut row);
                        row_v = Some(v.to_bits());
                    }
                    &row[..]
                }
            };
            let q = match table.u_slot(u) {
                Some(i) => self.combine(sums, table.u_coefficients(i)),
                None => self.combine(sums, &self.u_values(u)),
            };
            *slot = [q[0], q[1], q[2], u, v];
        }
        Some(())
    }

    /// The position at grid point (i, j) of `table` (made by [`Self::line_table`] on this
    /// patch) as [x, y, z, u, v]: [`Self::points_into`]'s bits at (us[i], vs[j]).
    #[inline]
    #[cfg(test)]
    pub fn table_at(&self, table: &LineTable, i: usize, j: usize) -> [f32; 5] {
        let q = self.combine(table.row(j), table.u_coefficients(i));
        [q[0], q[1], q[2], table.us[i], table.vs[j]]
    }

    /// [`Self::table_at`] at (columns[n], j) into `out[n]`, for every n.
    pub fn table_row_into(
        &self,
        table: &LineTable,
        columns: impl Iterator<Item = usize>,
        j: usize,
        out: &mut [[f32; 5]],
    ) {
        if self.k == 4 {
            self.table_row_as::<true>(table, columns, j, out);
        } else {
            self.table_row_as::<false>(table, columns, j, out);
        }
    }

    #[inline(always)]
    fn table_row_as<const RATIONAL: bool>(
        &self,
        table: &LineTable,
        columns: impl Iterator<Item = usize>,
        j: usize,
        out: &mut [[f32; 5]],
    ) {
        let (sums, v) = (table.row(j), table.vs[j]);
        for (slot, i) in out.iter_mut().zip(columns) {
            let q = self.combine_as::<RATIONAL>(sums, table.u_coefficients(i));
            *slot = [q[0], q[1], q[2], table.us[i], v];
        }
    }

    /// The positions at every (us[i], vs[j]), j outer, into `out` (`us.len() × vs.len()`).
    #[cfg(test)]
    pub fn grid_into(&self, us: &[f32], vs: &[f32], out: &mut [[f32; 5]]) -> Option<()> {
        if self.empty() || us.is_empty() {
            return (!self.empty()).then_some(());
        }
        let ucs: Vec<[f32; MAX_ORDER]> = us.iter().map(|&u| self.u_values(u)).collect();
        for (&v, row) in vs.iter().zip(out.chunks_exact_mut(us.len())) {
            let sums = self.row_sums(v);
            for ((slot, &u), uc) in row.iter_mut().zip(us).zip(&ucs) {
                let q = self.combine(&sums, uc);
                *slot = [q[0], q[1], q[2], u, v];
            }
        }
        Some(())
    }
}

impl LineTable {
    /// Where the line u is in the table, by its bits.
    #[inline]
    pub fn u_slot(&self, u: f32) -> Option<usize> {
        self.uindex.get(&u.to_bits()).copied()
    }

    /// Where the line v is in the table, by its bits.
    #[inline]
    pub fn v_slot(&self, v: f32) -> Option<usize> {
        self.vindex.get(&v.to_bits()).copied()
    }

    /// The row sums of line `vs[j]`.
    #[inline]
    fn row(&self, j: usize) -> &[[f32; 4]] {
        &self.rows[j * self.uorder..(j + 1) * self.uorder]
    }

    /// The u coefficients of line `us[i]`.
    #[inline]
    fn u_coefficients(&self, i: usize) -> &[f32] {
        &self.ucs[i * self.uorder..(i + 1) * self.uorder]
    }
}

/// One map's Bezier piece over [u1, u2] as GLU's curve evaluator holds it
/// (`curveEvalMachine`, `interface/incurveeval.cc`).
#[derive(Clone, Debug)]
pub(crate) struct CurveMachine {
    k: usize,
    u: (f32, f32),
    order: usize,
    points: Vec<f32>,
}

impl CurveMachine {
    /// The machine for control points `points`, or `None` for orders GLU refuses.
    pub fn new(points: &[f64], k: usize, order: usize, u: (f32, f32)) -> Option<Self> {
        let fits = (1..=MAX_ORDER).contains(&order) && (1..=4).contains(&k) && points.len() >= order * k;
        fits.then(|| Self { k, u, order, points: points[..order * k].iter().map(|&c| c as f32).collect() })
    }

    /// The raw k values at u (GLU `inDoDomain1`); `None` on an empty piece.
    pub fn values(&self, u: f32) -> Option<[f32; 4]> {
        if self.u.1 == self.u.0 {
            return None;
        }
        let (c, _) = coefficients(self.order, (u - self.u.0) / (self.u.1 - self.u.0));
        let mut out = [0.0f32; 4];
        for (j, slot) in out.iter_mut().enumerate().take(self.k) {
            for row in 0..self.order {
                *slot += c[row] * self.points[row * self.k + j];
            }
        }
        Some(out)
    }
}

/// (x, y, z), divided by w when the map is rational.
fn project(p: &[f32; 4], k: usize) -> [f32; 3] {
    if k == 4 {
        [p[0] / p[3], p[1] / p[3], p[2] / p[3]]
    } else {
        [p[0], p[1], p[2]]
    }
}

/// GLU `inComputeFirstPartials`: the partials of the projected point, scaled by w².
fn first_partials(p: &[f32; 4], du: &mut [f32; 4], dv: &mut [f32; 4]) {
    for d in [du, dv] {
        for c in 0..3 {
            d[c] = d[c] * p[3] - d[3] * p[c];
        }
    }
}

/// GLU `inComputeNormal2`: du × dv over its length (taken in double), left alone if zero.
fn normal(du: &[f32; 4], dv: &[f32; 4]) -> [f32; 3] {
    let mut n = [du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]];
    let mag = f64::from(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt() as f32;
    if mag > 0.0 {
        for c in &mut n {
            *c /= mag;
        }
    }
    n
}

/// The Bernstein polynomials of `order` at t and their derivatives (GLU
/// `inPreEvaluateWithDeriv`): each order's coefficients from the previous one's, the
/// derivatives taken from the next-to-last order.
fn coefficients(order: usize, t: f32) -> ([f32; MAX_ORDER], [f32; MAX_ORDER]) {
    let (mut c, mut d) = ([0.0f32; MAX_ORDER], [0.0f32; MAX_ORDER]);
    let one_minus = 1.0 - t;
    match order {
        1 => {
            c[0] = 1.0;
            return (c, d);
        }
        2 => {
            (c[0], c[1], d[0], d[1]) = (one_minus, t, -1.0, 1.0);
            return (c, d);
        }
        _ => {}
    }
    (c[0], c[1]) = (one_minus, t);
    for i in 2..order - 1 {
        raise(&mut c, i, t, one_minus);
    }
    d[0] = -c[0];
    for j in 1..order - 1 {
        d[j] = c[j - 1] - c[j];
    }
    d[order - 1] = c[order - 2];
    raise(&mut c, order - 1, t, one_minus);
    (c, d)
}

/// The sums along u of [`PatchMachine::position_row`]: point i of the row from the row sums
/// `p` (the first `U.min(p.len())` of them) and the u coefficients of column i. Each
/// component's sum runs over the rows in GLU's order from zero, the four components side by
/// side (unused ones stay zero) so that they share one vector register; `U` fixed at compile
/// time for the usual orders so that the sum unrolls. The same bits for every `U`.
#[inline]
fn row_along_u<const U: usize>(
    p: &[[f32; 4]],
    k: usize,
    v: f32,
    us: &[f32],
    ucoeffs: &[[f32; MAX_ORDER]],
    out: &mut [[f32; 5]],
) {
    let p = &p[..U.min(p.len())];
    for ((slot, &u), uc) in out.iter_mut().zip(us).zip(ucoeffs) {
        let mut point = [0.0f32; 4];
        for (w, sums) in uc[..p.len()].iter().zip(p) {
            for (c, s) in point.iter_mut().zip(sums) {
                *c += w * s;
            }
        }
        let q = project(&point, k);
        *slot = [q[0], q[1], q[2], u, v];
    }
}

/// [`coefficients`]' first half alone: the same steps, the same bits, no derivatives.
fn values(order: usize, t: f32) -> [f32; MAX_ORDER] {
    let mut c = [0.0f32; MAX_ORDER];
    let one_minus = 1.0 - t;
    if order == 1 {
        c[0] = 1.0;
        return c;
    }
    (c[0], c[1]) = (one_minus, t);
    for i in 2..order {
        raise(&mut c, i, t, one_minus);
    }
    c
}

/// One order up: the `i` coefficients of order i become the i + 1 of order i + 1.
fn raise(c: &mut [f32; MAX_ORDER], i: usize, t: f32, one_minus: f32) {
    let mut old = c[0] * t;
    c[0] *= one_minus;
    for j in 1..i {
        let temp = old;
        old = c[j] * t;
        c[j] = temp + one_minus * c[j];
    }
    c[i] = old;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bernstein_coefficients_sum_to_one_and_derivatives_to_zero() {
        for order in 1..=6 {
            let (c, d) = coefficients(order, 0.3);
            let sum: f32 = c[..order].iter().sum();
            let dsum: f32 = d[..order].iter().sum();
            assert!((sum - 1.0).abs() < 1e-6 && dsum.abs() < 1e-6, "order {order}");
        }
        // Cubic at t: (1−t)³, 3t(1−t)², 3t²(1−t), t³; GLU's derivatives are the quadratic's
        // differences, the true derivatives over 3: −(1−t)², (1−t)² − 2t(1−t), ...
        let (c, d) = coefficients(4, 0.5);
        assert_eq!(&c[..4], &[0.125, 0.375, 0.375, 0.125]);
        assert_eq!(&d[..4], &[-0.25, -0.25, 0.25, 0.25]);
    }

    #[test]
    fn flat_bilinear_patch_has_the_z_normal() {
        let pts = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0];
        let m = PatchMachine::new(&pts, 3, (2, 2), (0.0, 1.0), (0.0, 1.0)).unwrap();
        let at = m.sample(0.25, 0.5).unwrap();
        assert_eq!(m.point_and_normal_of(at, 0.25, 0.5), Some(([0.25, 0.5, 0.0], [0.0, 0.0, 1.0])));
    }

    /// A grid of samples, and samples one by one in any order (whatever the machine kept from
    /// the samples before), give the bits of a fresh machine's first sample, and a machine
    /// without partials the same values: rational and not, orders 1 to 7, parameters on and
    /// off the patch.
    #[test]
    fn grid_and_repeated_samples_match_fresh_ones() {
        let bits = |s: &MachineSample| [s.point, s.du, s.dv].concat().iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        for (k, uo, vo) in [(3, 4, 4), (4, 3, 5), (3, 1, 7), (2, 7, 2), (4, 4, 1)] {
            let pts: Vec<f64> = (0..uo * vo * k)
                .map(|x| ((x * 37 % 23) as f64) * 0.3 - 2.5 + if x % k == 3 { 4.0 } else { 0.0 })
                .collect();
            let machine = || PatchMachine::new(&pts, k, (uo, vo), (0.5, 2.0), (-1.0, 1.0)).unwrap();
            let us = [0.5, 0.75, 1.1, 2.0, 0.3, 1.1];
            let vs = [-1.0, 0.2, 1.0, 0.2, 1.7];
            let grid = machine().sample_grid(&us, &vs).unwrap();
            let lean = machine().without_partials().sample_grid(&us, &vs).unwrap();
            let shared = machine();
            for (n, (j, i)) in (0..vs.len()).flat_map(|j| (0..us.len()).map(move |i| (j, i))).rev().enumerate() {
                let fresh = machine().sample(us[i], vs[j]).unwrap();
                assert_eq!(bits(&grid[j * us.len() + i]), bits(&fresh), "{k} {uo}x{vo} grid ({i}, {j})");
                let point_bits = |p: [f32; 4]| p.map(f32::to_bits);
                assert_eq!(point_bits(lean[j * us.len() + i].point), point_bits(fresh.point), "{k} {uo}x{vo} lean");
                assert_eq!(bits(&shared.sample(us[i], vs[j]).unwrap()), bits(&fresh), "{k} {uo}x{vo} sample {n}");
            }
        }
    }

    /// A grid row through `position_row` (its sums along u unrolled for orders 2 to 6, a loop
    /// for the others) gives the bits of each sample's position: u orders 1 to 8, rational
    /// and not, parameters on and off the patch.
    #[test]
    fn position_rows_match_sampled_positions() {
        for uo in 1..=8 {
            for (k, vo) in [(3, 4), (4, 3), (2, 1)] {
                let pts: Vec<f64> = (0..uo * vo * k)
                    .map(|x| ((x * 37 % 23) as f64) * 0.3 - 2.5 + if x % k == 3 { 4.0 } else { 0.0 })
                    .collect();
                let machine = PatchMachine::new(&pts, k, (uo, vo), (0.5, 2.0), (-1.0, 1.0)).unwrap();
                let us = [0.5, 0.75, 1.1, 2.0, 0.3, 1.1, 0.6180339, 2.25];
                let ucoeffs = machine.u_coefficients(&us);
                for v in [-1.0, 0.2, 1.0, 1.7, -0.333] {
                    let mut row = [[0.0; 5]; 8];
                    machine.position_row(v, &us, &ucoeffs, &mut row).unwrap();
                    for (i, &u) in us.iter().enumerate() {
                        let p = machine.position_of(&machine.sample(u, v).unwrap());
                        let expected = [p[0], p[1], p[2], u, v].map(f32::to_bits);
                        assert_eq!(row[i].map(f32::to_bits), expected, "k {k}, order {uo}x{vo}, ({u}, {v})");
                    }
                }
            }
        }
    }

    /// The shareable positions give the bits of a sample's position, point by point, along
    /// point lists and over grids: rational and not, orders 1 to 7, on and off the patch.
    #[test]
    fn positions_match_sampled_positions() {
        for (k, uo, vo) in [(3, 4, 4), (4, 3, 5), (3, 1, 7), (2, 7, 2), (4, 4, 1), (1, 2, 3)] {
            let pts: Vec<f64> = (0..uo * vo * k)
                .map(|x| ((x * 37 % 23) as f64) * 0.3 - 2.5 + if x % k == 3 { 4.0 } else { 0.0 })
                .collect();
            let machine = PatchMachine::new(&pts, k, (uo, vo), (0.5, 2.0), (-1.0, 1.0)).unwrap();
            let lean = machine.clone().without_partials();
            let positions = machine.positions();
            let us = [0.5, 0.75, 1.1, 2.0, 0.3, 1.1, 0.6180339];
            let vs = [-1.0, 0.2, 1.0, 0.2, 1.7, -0.333];
            let expect = |u: f32, v: f32| {
                let p = machine.position_of(&machine.sample(u, v).unwrap());
                assert_eq!(p.map(f32::to_bits), lean.position_of(&lean.sample(u, v).unwrap()).map(f32::to_bits));
                [p[0], p[1], p[2], u, v].map(f32::to_bits)
            };
            let mut grid = vec![[0.0; 5]; us.len() * vs.len()];
            positions.grid_into(&us, &vs, &mut grid).unwrap();
            let uvs: Vec<[f32; 2]> = vs.iter().flat_map(|&v| us.iter().map(move |&u| [u, v])).collect();
            let mut listed = vec![[0.0; 5]; uvs.len()];
            positions.points_into(&uvs, &mut listed).unwrap();
            let table = positions.line_table(us.to_vec(), vs.to_vec());
            let some_lines = positions.line_table(vec![0.75, 1.1], vec![0.2]);
            let mut looked_up = vec![[0.0; 5]; uvs.len()];
            positions.points_into_with(&uvs, &mut looked_up, &some_lines).unwrap();
            for (n, &[u, v]) in uvs.iter().enumerate() {
                let (i, j) = (n % us.len(), n / us.len());
                assert_eq!(positions.table_at(&table, i, j).map(f32::to_bits), expect(u, v), "{k} {uo}x{vo} table");
                let mut row = [[0.0; 5]; 2];
                positions.table_row_into(&table, [i, i].into_iter(), j, &mut row);
                assert_eq!(row[1].map(f32::to_bits), expect(u, v), "{k} {uo}x{vo} table row");
                assert_eq!(grid[n].map(f32::to_bits), expect(u, v), "{k} {uo}x{vo} grid ({u}, {v})");
                assert_eq!(listed[n].map(f32::to_bits), expect(u, v), "{k} {uo}x{vo} list ({u}, {v})");
                assert_eq!(looked_up[n].map(f32::to_bits), expect(u, v), "{k} {uo}x{vo} looked up ({u}, {v})");
                assert_eq!(positions.at(u, v).unwrap().map(f32::to_bits), expect(u, v), "{k} {uo}x{vo} at");
            }
        }
        let flat = PatchMachine::new(&[0.0; 12], 3, (2, 2), (1.0, 1.0), (0.0, 1.0)).unwrap();
        assert!(flat.positions().at(1.0, 0.5).is_none() && flat.sample(1.0, 0.5).is_none());
    }

    #[test]
    fn values_are_the_coefficients() {
        for order in 1..=MAX_ORDER {
            for t in [0.0f32, 0.3, 0.5, 0.77, 1.0, -0.2, 1.3] {
                assert_eq!(
                    values(order, t).map(f32::to_bits),
                    coefficients(order, t).0.map(f32::to_bits),
                    "{order} {t}"
                );
            }
        }
    }

    #[test]
    fn refused_orders_and_short_nets_give_no_machine() {
        assert!(PatchMachine::new(&[0.0; 3], 3, (2, 2), (0.0, 1.0), (0.0, 1.0)).is_none());
        assert!(PatchMachine::new(&[0.0; 300], 3, (25, 1), (0.0, 1.0), (0.0, 1.0)).is_none());
    }
}
