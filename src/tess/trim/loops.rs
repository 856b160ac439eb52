//! Trim loops: joining curves head to tail as GLU does, and GLU's rules for a valid set of loops
//! (`arc.cc`, `reader.cc`, `trimvertex`): closed, not self-intersecting, not crossing one
//! another, oriented by nesting depth.

use super::geometry::{bbox, doubles_back, flush, inside, is_finite, midpoint, segments_meet, signed_area, P};
use super::lattice::{sorted_lines, LatticeLines};

/// GLU's tolerance for joining trim curves (`arc.cc` ZERO): |Δu| and |Δv| both at most this.
pub const JOIN_TOLERANCE: f64 = 1e-5;

/// A closed trim loop: a polyline in (u, v), the last point joined back to the first.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TrimLoop {
    /// The vertices. Repeating the first point at the end is allowed but not needed.
    pub points: Vec<[f64; 2]>,
}

impl TrimLoop {
    /// A loop through `points`.
    #[must_use]
    pub fn new(points: Vec<[f64; 2]>) -> Self {
        Self { points }
    }

    /// The signed area (shoelace formula): positive for a counter-clockwise loop.
    #[must_use]
    pub fn signed_area(&self) -> f64 {
        signed_area(&self.points)
    }
}

/// Why a set of trim loops is rejected, with GLU's error numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TrimError {
    /// Consecutive curves of a loop do not meet within 1e-5 (GLU error 31).
    Unconnected,
    /// A loop crosses or touches itself, runs the wrong way for its nesting depth, has fewer than
    /// three distinct points or no area, has a point that is not finite or lies outside the
    /// domain; or the domain itself is empty or not finite (GLU error 28).
    Misoriented,
    /// Two loops cross or touch (GLU error 29).
    Intersecting,
    /// A loop without any point, or no curve at all (GLU error 18).
    Empty,
}

impl TrimError {
    /// The GLU NURBS error number (`GLU_NURBS_ERRORn`): 31, 28, 29 or 18.
    ///
    /// ```
    /// use gleval::tess::trim::{join_curves, TrimError};
    /// let err = join_curves(&[vec![[0.0, 0.0], [1.0, 0.0]], vec![[1.0, 0.5], [0.0, 0.0]]]);
    /// assert_eq!(err, Err(TrimError::Unconnected));
    /// assert_eq!(TrimError::Unconnected.glu_number(), 31);
    /// ```
    #[must_use]
    pub fn glu_number(self) -> u32 {
        match self {
            Self::Unconnected => 31,
            Self::Misoriented => 28,
            Self::Intersecting => 29,
            Self::Empty => 18,
        }
    }
}

impl std::fmt::Display for TrimError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // GLU's own texts (`glue.c` __gluNurbsErrors).
        let text = match self {
            Self::Unconnected => "unconnected trim curves",
            Self::Misoriented => "intersecting or misoriented trim curves",
            Self::Intersecting => "intersecting trim curves",
            Self::Empty => "invalid or missing trim curve",
        };
        f.write_str(text)
    }
}

impl std::error::Error for TrimError {}

/// Whether two points meet within GLU's join tolerance in u and in v.
fn close(a: P, b: P) -> bool {
    (a[0] - b[0]).abs() <= JOIN_TOLERANCE && (a[1] - b[1]).abs() <= JOIN_TOLERANCE
}

/// Joins the curves (polylines) of one trim loop head to tail, as GLU does before tessellating.
///
/// Each curve's last point must meet the next curve's first point, and the last curve's end the
/// first curve's start, within [`JOIN_TOLERANCE`] in u and in v (`arc.cc` `isDisconnected`);
/// meeting points are snapped to their average. Consecutive points within the tolerance are
/// merged (`reader.cc` ELIMINATE_REDUNDANT_POINTS), as is a closing point equal to the first.
///
/// Errors: no curves or no points → [`TrimError::Empty`]; a gap → [`TrimError::Unconnected`];
/// a point that is not finite, or fewer than three distinct points → [`TrimError::Misoriented`].
///
/// ```
/// use gleval::tess::trim::join_curves;
/// let bottom = vec![[0.0, 0.0], [1.0, 0.0]];
/// let rest = vec![[1.0, 4e-6], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]];
/// let l = join_curves(&[bottom, rest]).unwrap();
/// assert_eq!(l.points, vec![[0.0, 0.0], [1.0, 2e-6], [1.0, 1.0], [0.0, 1.0]]);
/// ```
pub fn join_curves(pieces: &[Vec<[f64; 2]>]) -> Result<TrimLoop, TrimError> {
    let mut pieces: Vec<Vec<P>> = pieces.iter().filter(|p| !p.is_empty()).cloned().collect();
    if pieces.is_empty() {
        return Err(TrimError::Empty);
    }
    if pieces.iter().flatten().any(|p| !is_finite(*p)) {
        return Err(TrimError::Misoriented);
    }
    let n = pieces.len();
    for i in 0..n {
        let j = (i + 1) % n;
        let (Some(&end), Some(&start)) = (pieces[i].last(), pieces[j].first()) else { continue };
        if !close(end, start) {
            return Err(TrimError::Unconnected);
        }
        let m = midpoint(end, start);
        if let Some(last) = pieces[i].last_mut() {
            *last = m;
        }
        pieces[j][0] = m;
    }
    let mut points: Vec<P> = Vec::new();
    for p in pieces.iter().flatten() {
        if points.last().is_none_or(|q| !close(*q, *p)) {
            points.push(*p);
        }
    }
    while points.len() > 1 && points.last().is_some_and(|q| close(points[0], *q)) {
        points.pop();
    }
    if points.len() < 3 {
        return Err(TrimError::Misoriented);
    }
    Ok(TrimLoop { points })
}

/// The loop with a vertex added wherever an edge crosses one of the lines u = `us[i]` or
/// v = `vs[j]` (GLU's `splitInS`/`splitInT` at knot lines). The new vertices lie on the edges,
/// with the crossed coordinate exactly equal to the line's.
#[must_use]
pub fn split_at_lines(l: &TrimLoop, us: &[f64], vs: &[f64]) -> TrimLoop {
    let grid = LatticeLines {
        u: sorted_lines(us, f64::NEG_INFINITY, f64::INFINITY),
        v: sorted_lines(vs, f64::NEG_INFINITY, f64::INFINITY),
    };
    let n = l.points.len();
    let mut points = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b) = (l.points[i], l.points[(i + 1) % n]);
        points.push(a);
        if n > 1 && is_finite(a) && is_finite(b) {
            points.extend(grid.crossings(a, b).into_iter().map(|c| c.1));
        }
    }
    TrimLoop { points }
}

/// The loop's points with exact consecutive duplicates (and a closing repeat) removed.
pub(super) fn clean_loop(l: &TrimLoop) -> Result<Vec<P>, TrimError> {
    if l.points.is_empty() {
        return Err(TrimError::Empty);
    }
    let mut points: Vec<P> = Vec::with_capacity(l.points.len());
    for &p in &l.points {
        if !is_finite(p) {
            return Err(TrimError::Misoriented);
        }
        let p = [flush(p[0]), flush(p[1])];
        if points.last() != Some(&p) {
            points.push(p);
        }
    }
    while points.len() > 1 && points.last() == Some(&points[0]) {
        points.pop();
    }
    if points.len() < 3 {
        return Err(TrimError::Misoriented);
    }
    Ok(points)
}

/// Whether the loop runs once counter-clockwise round the domain's border: every point on the
/// border and the loop's area the domain's.
pub(super) fn is_domain_border(l: &[P], [u0, u1, v0, v1]: [f64; 4]) -> bool {
    let on_border = |p: &P| {
        (p[0] == u0 || p[0] == u1) && p[1] >= v0 && p[1] <= v1 || (p[1] == v0 || p[1] == v1) && p[0] >= u0 && p[0] <= u1
    };
    let area = (u1 - u0) * (v1 - v0);
    l.iter().all(on_border) && (signed_area(l) - area).abs() <= 1e-12 * area
}

/// GLU's loop rules; see [`triangulate_with`] for the order of the checks.
pub(super) fn validate(loops: &[Vec<P>], [u0, u1, v0, v1]: [f64; 4]) -> Result<(), TrimError> {
    let slack = 1e-12 * ((u1 - u0) + (v1 - v0));
    let in_domain = |p: &P| p[0] >= u0 - slack && p[0] <= u1 + slack && p[1] >= v0 - slack && p[1] <= v1 + slack;
    for l in loops {
        let n = l.len();
        let spike = (0..n).any(|i| doubles_back(l[i], l[(i + 1) % n], l[(i + 2) % n]));
        if !l.iter().all(in_domain) || signed_area(l) == 0.0 || spike {
            return Err(TrimError::Misoriented);
        }
    }
    if let Some(e) = find_touching_edges(loops) {
        return Err(e);
    }
    let boxes: Vec<[f64; 4]> = loops.iter().map(|l| bbox(l)).collect();
    for (i, l) in loops.iter().enumerate() {
        let p = l[0];
        let depth = (0..loops.len())
            .filter(|&j| {
                let b = boxes[j];
                j != i && p[0] >= b[0] && p[0] <= b[1] && p[1] >= b[2] && p[1] <= b[3] && inside(&loops[j], p)
            })
            .count();
        if (signed_area(l) > 0.0) != (depth % 2 == 0) {
            return Err(TrimError::Misoriented);
        }
    }
    Ok(())
}

/// Looks for touching edges with a uniform bucket grid over all loops: non-adjacent edges of one
/// loop → `Misoriented` (reported first), edges of two loops → `Intersecting`.
fn find_touching_edges(loops: &[Vec<P>]) -> Option<TrimError> {
    let segs: Vec<(usize, usize)> =
        loops.iter().enumerate().flat_map(|(k, l)| (0..l.len()).map(move |i| (k, i))).collect();
    let ends = |(k, i): (usize, usize)| (loops[k][i], loops[k][(i + 1) % loops[k].len()]);
    let all = bbox(&loops.iter().flatten().copied().collect::<Vec<_>>());
    let cells = ((segs.len() as f64).sqrt().ceil() as usize).clamp(1, 2048);
    let cell_of = |x: f64, lo: f64, hi: f64| {
        let w = hi - lo;
        if w > 0.0 {
            (((x - lo) / w * cells as f64).max(0.0) as usize).min(cells - 1)
        } else {
            0
        }
    };
    let ranges = |s: (usize, usize)| {
        let (a, b) = ends(s);
        let b4 = bbox(&[a, b]);
        let (i0, i1) = (cell_of(b4[0], all[0], all[1]), cell_of(b4[1], all[0], all[1]));
        let (j0, j1) = (cell_of(b4[2], all[2], all[3]), cell_of(b4[3], all[2], all[3]));
        (j0..=j1).flat_map(move |j| (i0..=i1).map(move |i| j * cells + i))
    };
    // Compressed buckets: counts, prefix sums, fill.
    let mut start = vec![0usize; cells * cells + 1];
    for &s in &segs {
        ranges(s).for_each(|c| start[c + 1] += 1);
    }
    for c in 0..cells * cells {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut bucket = vec![0u32; start[cells * cells]];
    for (id, &s) in segs.iter().enumerate() {
        for c in ranges(s) {
            bucket[fill[c]] = id as u32;
            fill[c] += 1;
        }
    }
    let mut crossing = false;
    for c in 0..cells * cells {
        let ids = &bucket[start[c]..start[c + 1]];
        for (x, &p) in ids.iter().enumerate() {
            for &q in &ids[x + 1..] {
                let (s, t) = (segs[p as usize], segs[q as usize]);
                let n = loops[s.0].len();
                let adjacent = s.0 == t.0 && (s.1.abs_diff(t.1) == 1 || s.1.abs_diff(t.1) == n - 1);
                if adjacent || (crossing && s.0 != t.0) {
                    continue;
                }
                let ((a, b), (d, e)) = (ends(s), ends(t));
                if segments_meet(a, b, d, e) {
                    if s.0 == t.0 {
                        return Some(TrimError::Misoriented);
                    }
                    crossing = true;
                }
            }
        }
    }
    crossing.then_some(TrimError::Intersecting)
}
