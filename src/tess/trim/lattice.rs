//! The sampling grid of a trimmed domain: its lines, where the trim loops cross them, and the
//! grid points and cells the loops pass near or through. The triangulations ask these questions
//! for every loop point and crossing, so the line lookups are cheap (see [`count_at_most`]).

use super::geometry::{flush, midpoint, P};

/// Sorted, deduplicated finite values strictly between `lo` and `hi`.
pub(super) fn sorted_lines(values: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let mut v: Vec<f64> = values.iter().copied().map(flush).filter(|x| x.is_finite() && *x > lo && *x < hi).collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

/// The domain bounds with the interior grid lines between them.
pub(super) fn grid_lines(values: &[f64], lo: f64, hi: f64) -> Vec<f64> {
    let mut v = vec![lo];
    v.extend(sorted_lines(values, lo, hi));
    v.push(hi);
    v
}

/// How many of the sorted `lines` are at most x (`lines.partition_point(|l| *l <= x)`).
/// The answer is guessed as if the lines were evenly spaced (as GLU's sampling lines are within
/// a piece), checked against the lines and stepped; a binary search only when the guess is far.
/// Trimming asks this for every loop point and crossing, where a binary search's mispredicted
/// branches cost more than the rest of the work.
pub(super) fn count_at_most(lines: &[f64], x: f64) -> usize {
    count_where(lines, x, |l| l <= x)
}

/// How many of the sorted `lines` are below x (`lines.partition_point(|l| *l < x)`).
pub(super) fn count_below(lines: &[f64], x: f64) -> usize {
    count_where(lines, x, |l| l < x)
}

/// The partition point of `before` (true on a prefix of `lines`), starting from the evenly
/// spaced guess for x.
fn count_where(lines: &[f64], x: f64, before: impl Fn(f64) -> bool) -> usize {
    let n = lines.len();
    if n < 2 {
        return lines.partition_point(|&l| before(l));
    }
    let (first, last) = (lines[0], lines[n - 1]);
    let guess = (x - first) / (last - first) * (n - 1) as f64;
    if !guess.is_finite() {
        return lines.partition_point(|&l| before(l));
    }
    // Truncation is the floor here (clamped at 0 first): no call to libm's floor.
    let mut k = (guess.clamp(0.0, (n - 1) as f64) as usize) + 1;
    for _ in 0..3 {
        if k < n && before(lines[k]) {
            k += 1;
        } else if k > 0 && !before(lines[k - 1]) {
            k -= 1;
        } else {
            return k;
        }
    }
    lines.partition_point(|&l| before(l))
}

/// The lattice's lines in u and v, sorted. For the triangulation the first and last are the domain bounds
/// and only the lines between them carry grid points.
pub(super) struct LatticeLines {
    pub(super) u: Vec<f64>,
    pub(super) v: Vec<f64>,
}

/// A crossing of an edge with grid lines: edge parameter t and the point.
pub(super) type Cut = (f64, P);

/// Grid points within this many cells of a loop count as on it and are always left out (a CDT
/// vertex on a loop edge would split it), whatever the clearance.
pub(super) const ON_LOOP: f64 = 1e-9;

/// Split points closer than this (in grid cells) to a neighbour on the edge are not inserted.
pub(super) const MIN_SPLIT: f64 = 0.01;

impl LatticeLines {
    pub(super) fn point_count(&self) -> usize {
        self.u.len().saturating_mul(self.v.len())
    }

    /// Drops every other interior line in both directions; false when there is nothing to drop.
    pub(super) fn coarsen(&mut self) -> bool {
        let halve = |lines: &mut Vec<f64>| {
            if lines.len() > 2 {
                let last = lines[lines.len() - 1];
                let keep: Vec<f64> = lines[..lines.len() - 1].iter().step_by(2).copied().chain([last]).collect();
                *lines = keep;
            }
        };
        let before = self.u.len() + self.v.len();
        halve(&mut self.u);
        halve(&mut self.v);
        self.u.len() + self.v.len() < before
    }

    /// Lines strictly between a and b.
    fn between(lines: &[f64], a: f64, b: f64) -> &[f64] {
        let (lo, hi) = (a.min(b), a.max(b));
        let i = count_at_most(lines, lo);
        let j = count_below(lines, hi).max(i);
        &lines[i..j]
    }

    pub(super) fn count_crossings(&self, loops: &[Vec<P>]) -> usize {
        loops
            .iter()
            .flat_map(|l| (0..l.len()).map(move |i| (l[i], l[(i + 1) % l.len()])))
            .map(|(a, b)| Self::between(&self.u, a[0], b[0]).len() + Self::between(&self.v, a[1], b[1]).len())
            .fold(0usize, usize::saturating_add)
    }

    /// Where edge a→b crosses the grid lines, by increasing t in (0, 1); a crossing of a u line
    /// and a v line at the same t is one point with both coordinates exact.
    pub(super) fn crossings(&self, a: P, b: P) -> Vec<Cut> {
        let mut trace = EdgeTrace::default();
        self.crossings_into(a, b, &mut trace);
        trace.cuts
    }

    /// [`LatticeLines::crossings`] into `trace.cuts` (its buffers reused: this runs for every loop edge).
    fn crossings_into(&self, a: P, b: P, trace: &mut EdgeTrace) {
        let (du, dv) = (b[0] - a[0], b[1] - a[1]);
        let raw = &mut trace.raw;
        raw.clear();
        raw.extend(Self::between(&self.u, a[0], b[0]).iter().map(|&u| ((u - a[0]) / du, Some(u), None)));
        raw.extend(Self::between(&self.v, a[1], b[1]).iter().map(|&v| ((v - a[1]) / dv, None, Some(v))));
        raw.retain(|c| c.0 > 0.0 && c.0 < 1.0);
        raw.sort_by(|x, y| x.0.total_cmp(&y.0));
        trace.merged.clear();
        for &c in raw.iter() {
            match trace.merged.last_mut() {
                Some(last) if c.0 - last.0 <= 1e-12 => {
                    last.1 = last.1.or(c.1);
                    last.2 = last.2.or(c.2);
                }
                _ => trace.merged.push(c),
            }
        }
        trace.cuts.clear();
        trace.cuts.extend(
            trace.merged.iter().map(|&(t, u, v)| (t, [u.unwrap_or(a[0] + t * du), v.unwrap_or(a[1] + t * dv)])),
        );
    }

    /// Edge a→b's crossings and, in cell coordinates, a, every crossing and b.
    pub(super) fn trace(&self, a: P, b: P, trace: &mut EdgeTrace) {
        self.crossings_into(a, b, trace);
        trace.coords.clear();
        let points = std::iter::once(a).chain(trace.cuts.iter().map(|c| c.1)).chain([b]);
        trace.coords.extend(points.map(|p| self.cell_coords(p)));
    }

    /// Fractional line index of x: i + (x - lines[i]) / (lines[i+1] - lines[i]).
    fn index(lines: &[f64], x: f64) -> f64 {
        if lines.len() < 2 {
            return 0.0;
        }
        let i = count_at_most(lines, x).clamp(1, lines.len() - 1) - 1;
        let (lo, hi) = (lines[i], lines[i + 1]);
        i as f64 + ((x - lo) / (hi - lo)).clamp(0.0, 1.0)
    }

    /// A point in grid-index space, where grid points are the integer lattice.
    pub(super) fn cell_coords(&self, p: P) -> P {
        [Self::index(&self.u, p[0]), Self::index(&self.v, p[1])]
    }

    /// The split points worth inserting: not within [`MIN_SPLIT`] cells of the previous vertex
    /// or of b.
    pub(super) fn thin<'a>(&'a self, a: P, b: P, cuts: &'a [Cut]) -> impl Iterator<Item = P> + 'a {
        let far = |p: P, q: P| {
            let (x, y) = (self.cell_coords(p), self.cell_coords(q));
            (x[0] - y[0]).abs().max((x[1] - y[1]).abs()) >= MIN_SPLIT
        };
        let mut prev = a;
        cuts.iter().filter_map(move |&(_, p)| {
            let keep = far(prev, p) && far(p, b);
            if keep {
                prev = p;
            }
            keep.then_some(p)
        })
    }

    /// Marks the grid points within `clearance` cells of an edge, given as its points in cell
    /// coordinates ([`LatticeLines::trace`]). Between consecutive cuts the edge lies in one grid cell,
    /// where the map to cell coordinates is affine; only that cell's corners can be closer than
    /// one cell.
    pub(super) fn block_near(&self, coords: &[P], clearance: f64, blocked: &mut [bool]) {
        let (nu, nv) = (self.u.len(), self.v.len());
        if nu < 2 || nv < 2 {
            return;
        }
        let limit = clearance.max(ON_LOOP);
        for piece in coords.windows(2) {
            let (prev, next) = (piece[0], piece[1]);
            let mid = midpoint(prev, next);
            // `as usize` truncates and saturates at 0: the floor of these non-negative values.
            let ci = (mid[0].max(0.0) as usize).min(nu - 2);
            let cj = (mid[1].max(0.0) as usize).min(nv - 2);
            for (i, j) in [(ci, cj), (ci + 1, cj), (ci, cj + 1), (ci + 1, cj + 1)] {
                if distance_squared_to_segment([i as f64, j as f64], prev, next) < limit * limit {
                    blocked[j * nu + i] = true;
                }
            }
        }
    }

    /// Per grid point (row-major, `u.len()` per row): inside the retained region (even-odd over
    /// all loops, row by row with sorted crossings, starting inside when `inside_domain`) and
    /// not blocked. The points on the domain's border are kept exactly when `inside_domain`.
    pub(super) fn retained_mask(&self, loops: &[Vec<P>], blocked: &[bool], inside_domain: bool) -> Vec<bool> {
        let (nu, nv) = (self.u.len(), self.v.len());
        let mut hits: Vec<(usize, f64)> = Vec::new();
        for l in loops {
            for i in 0..l.len() {
                let (a, b) = (l[i], l[(i + 1) % l.len()]);
                // Rows with min(a.v, b.v) <= v < max(a.v, b.v): the half-open rule of `inside`.
                let (lo, hi) = (a[1].min(b[1]), a[1].max(b[1]));
                let (j0, j1) = (count_below(&self.v, lo), count_below(&self.v, hi));
                for (j, &v) in self.v.iter().enumerate().take(j1).skip(j0) {
                    hits.push((j, a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0])));
                }
            }
        }
        hits.sort_by(|x, y| x.0.cmp(&y.0).then(x.1.total_cmp(&y.1)));
        let mut out = vec![false; blocked.len()];
        let mut k = 0;
        for (j, (row, blocked)) in out.chunks_exact_mut(nu).zip(blocked.chunks_exact(nu)).enumerate() {
            let row_start = k;
            while k < hits.len() && hits[k].0 == j {
                k += 1;
            }
            // The domain's border, when it is the outer loop, keeps every grid point: the other
            // loops lie strictly inside it (validated), and the border must be whole.
            if j == 0 || j == nv - 1 {
                row.fill(inside_domain);
                continue;
            }
            // Between consecutive crossings (a point on one counts as past it) the parity of
            // the crossings to the right is constant: runs filled at once, not point by point.
            let xs = &hits[row_start..k];
            let mut from = 0;
            for crossed in 0..=xs.len() {
                let to = xs.get(crossed).map_or(nu, |&(_, x)| count_below(&self.u, x));
                let odd = (xs.len() - crossed) % 2 == 1;
                row[from..to.max(from)].fill(odd != inside_domain);
                from = from.max(to);
            }
            for (keep, &b) in row.iter_mut().zip(blocked) {
                *keep &= !b;
            }
            row[0] = inside_domain;
            row[nu - 1] = inside_domain;
        }
        out
    }

    /// Number of grid cells (between consecutive lines, domain bounds included).
    pub(super) fn cell_count(&self) -> usize {
        self.u.len().saturating_sub(1).saturating_mul(self.v.len().saturating_sub(1))
    }

    /// Marks the cells an edge (its points in cell coordinates, [`LatticeLines::trace`]) passes through
    /// or touches: between consecutive cuts the edge
    /// lies in one closed cell, and a piece's ends and middle mark every cell whose closed box
    /// holds them (a point on a grid line marks both sides), so no loop point lies in an
    /// unmarked closed cell.
    pub(super) fn touch(&self, coords: &[P], touched: &mut [bool]) {
        const EPS: f64 = 1e-9;
        let (cu, cv) = (self.u.len().saturating_sub(1), self.v.len().saturating_sub(1));
        if cu == 0 || cv == 0 {
            return;
        }
        let mut mark = |p: P| {
            let span = |x: f64, n: usize| {
                // Truncation of a value clamped at 0 is its floor (without a libm call).
                let lo = ((x - EPS).max(0.0) as usize).min(n - 1);
                let hi = ((x + EPS).max(0.0) as usize).min(n - 1);
                lo..=hi
            };
            for j in span(p[1], cv) {
                for i in span(p[0], cu) {
                    touched[j * cu + i] = true;
                }
            }
        };
        let Some(&first) = coords.first() else { return };
        mark(first);
        for piece in coords.windows(2) {
            mark(midpoint(piece[0], piece[1]));
            mark(piece[1]);
        }
    }
}

/// Scratch buffers of [`LatticeLines::trace`], reused from edge to edge.
#[derive(Default)]
pub(super) struct EdgeTrace {
    /// Line crossings before merging: (t, u line, v line).
    raw: Vec<(f64, Option<f64>, Option<f64>)>,
    merged: Vec<(f64, Option<f64>, Option<f64>)>,
    /// The crossings by increasing t.
    pub(super) cuts: Vec<Cut>,
    /// The edge's start, its crossings and its end, in cell coordinates.
    pub(super) coords: Vec<P>,
}

/// The squared distance from p to segment a–b (no square root: compared with a squared limit).
pub(super) fn distance_squared_to_segment(p: P, a: P, b: P) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    let (x, y) = (p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
    x * x + y * y
}
