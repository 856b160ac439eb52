//! Trimmed parameter domains (GLU trimming, spec 2.7): trim loops in (u, v) are checked the way
//! GLU requires them (joined head to tail within 1e-5, outer loops counter-clockwise, holes
//! clockwise, nested loops alternating, no crossings), then the retained region is triangulated
//! by a constrained Delaunay triangulation (`spade`) of the loops and of the sampling grid's
//! interior points. The result is a mesh in (u, v) that the surface is evaluated on.

use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

/// GLU's tolerance for joining trim curves (`arc.cc` ZERO).
pub const JOIN_TOLERANCE: f64 = 1e-5;

/// Upper bound on interior grid points inserted, so that absurd sampling cannot exhaust memory.
pub const MAX_GRID_POINTS: usize = 4_000_000;

/// A closed trim loop: a polyline in (u, v), the last point joined back to the first.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TrimLoop {
    /// The vertices, without repeating the first at the end.
    pub points: Vec<[f64; 2]>,
}

/// Why a set of trim loops is rejected, with GLU's error numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrimError {
    /// Consecutive curves do not meet within 1e-5 (GLU error 31).
    Unconnected,
    /// A loop crosses itself, runs the wrong way for its nesting depth, is degenerate, or
    /// leaves the domain (GLU error 28).
    Misoriented,
    /// Two loops cross (GLU error 29).
    Intersecting,
    /// A loop without any point (GLU error 18).
    Empty,
}

impl TrimError {
    /// The GLU NURBS error number.
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

/// A triangulated region of the parameter domain.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TrimMesh {
    /// Vertices in (u, v).
    pub points: Vec<[f64; 2]>,
    /// Counter-clockwise triangles (u to the right, v up).
    pub triangles: Vec<[u32; 3]>,
}

fn close(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).abs() <= JOIN_TOLERANCE && (a[1] - b[1]).abs() <= JOIN_TOLERANCE
}

fn midpoint(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
}

/// Joins the curves of one loop head to tail: each end must meet the next curve's start (and
/// the last the first) within 1e-5 in u and v; meeting points are snapped to their average, and
/// consecutive points within 1e-5 are merged (GLU's `ELIMINATE_REDUNDANT_POINTS`).
pub fn join_curves(pieces: &[Vec<[f64; 2]>]) -> Result<TrimLoop, TrimError> {
    let mut pieces: Vec<Vec<[f64; 2]>> = pieces.iter().filter(|p| !p.is_empty()).cloned().collect();
    if pieces.is_empty() {
        return Err(TrimError::Empty);
    }
    if pieces.iter().flatten().any(|p| !p[0].is_finite() || !p[1].is_finite()) {
        return Err(TrimError::Misoriented);
    }
    let n = pieces.len();
    for i in 0..n {
        let j = (i + 1) % n;
        let (end, start) = (*pieces[i].last().expect("non-empty"), pieces[j][0]);
        if !close(end, start) {
            return Err(TrimError::Unconnected);
        }
        let m = midpoint(end, start);
        *pieces[i].last_mut().expect("non-empty") = m;
        pieces[j][0] = m;
    }
    let mut points: Vec<[f64; 2]> = Vec::new();
    for p in pieces.iter().flatten() {
        if points.last().is_none_or(|q| !close(*q, *p)) {
            points.push(*p);
        }
    }
    while points.len() > 1 && close(points[0], *points.last().expect("non-empty")) {
        points.pop();
    }
    if points.len() < 3 {
        return Err(TrimError::Misoriented);
    }
    Ok(TrimLoop { points })
}

/// Twice the signed area (positive for counter-clockwise).
fn signed_area(points: &[[f64; 2]]) -> f64 {
    (0..points.len())
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % points.len()]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum()
}

fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether the closed segments ab and cd share a point (touching counts).
fn segments_meet(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let (d1, d2, d3, d4) = (orient(c, d, a), orient(c, d, b), orient(a, b, c), orient(a, b, d));
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
        return true;
    }
    let on = |p: [f64; 2], q: [f64; 2], r: [f64; 2], o: f64| {
        o == 0.0 && r[0] >= p[0].min(q[0]) && r[0] <= p[0].max(q[0]) && r[1] >= p[1].min(q[1]) && r[1] <= p[1].max(q[1])
    };
    on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4)
}

fn edges(l: &TrimLoop) -> impl Iterator<Item = ([f64; 2], [f64; 2])> + '_ {
    let n = l.points.len();
    (0..n).map(move |i| (l.points[i], l.points[(i + 1) % n]))
}

fn self_intersects(l: &TrimLoop) -> bool {
    let e: Vec<_> = edges(l).collect();
    let n = e.len();
    (0..n).any(|i| {
        (i + 2..n).any(|j| {
            // Adjacent edges share an endpoint by construction.
            !(i == 0 && j == n - 1) && segments_meet(e[i].0, e[i].1, e[j].0, e[j].1)
        })
    })
}

fn loops_cross(a: &TrimLoop, b: &TrimLoop) -> bool {
    edges(a).any(|(p, q)| edges(b).any(|(r, s)| segments_meet(p, q, r, s)))
}

/// Even-odd point-in-polygon test.
fn inside(points: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut result = false;
    let n = points.len();
    for i in 0..n {
        let (a, b) = (points[i], points[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
            result = !result;
        }
    }
    result
}

/// Inside the retained region: inside an odd number of loops (with valid nesting and
/// orientation this is GLU's "to the left of every curve").
fn retained(loops: &[TrimLoop], p: [f64; 2]) -> bool {
    loops.iter().filter(|l| inside(&l.points, p)).count() % 2 == 1
}

/// Checks GLU's rules on the loops (inside the domain, simple, not crossing, orientation by
/// nesting depth).
fn validate(loops: &[TrimLoop], [u0, u1, v0, v1]: [f64; 4]) -> Result<(), TrimError> {
    let slack = 1e-9 * (1.0 + (u1 - u0).abs() + (v1 - v0).abs());
    let in_domain = |p: &[f64; 2]| p[0] >= u0 - slack && p[0] <= u1 + slack && p[1] >= v0 - slack && p[1] <= v1 + slack;
    for l in loops {
        if l.points.len() < 3 || !l.points.iter().all(in_domain) || signed_area(&l.points) == 0.0 || self_intersects(l)
        {
            return Err(TrimError::Misoriented);
        }
    }
    for (i, a) in loops.iter().enumerate() {
        if loops[i + 1..].iter().any(|b| loops_cross(a, b)) {
            return Err(TrimError::Intersecting);
        }
    }
    for (i, l) in loops.iter().enumerate() {
        let depth = loops.iter().enumerate().filter(|(j, o)| *j != i && inside(&o.points, l.points[0])).count();
        let ccw = signed_area(&l.points) > 0.0;
        if ccw != (depth % 2 == 0) {
            return Err(TrimError::Misoriented);
        }
    }
    Ok(())
}

/// The domain rectangle as a counter-clockwise loop through every grid line it crosses
/// (GLU's `makeBorderTrim`), so that the border is sampled like the interior.
fn border_loop([u0, u1, v0, v1]: [f64; 4], us: &[f64], vs: &[f64]) -> TrimLoop {
    let between = |lines: &[f64], a: f64, b: f64| -> Vec<f64> {
        let (lo, hi) = (a.min(b), a.max(b));
        let mut v: Vec<f64> = lines.iter().copied().filter(|x| *x > lo && *x < hi).collect();
        v.sort_by(f64::total_cmp);
        v
    };
    let mut points = vec![[u0, v0]];
    points.extend(between(us, u0, u1).into_iter().map(|u| [u, v0]));
    points.push([u1, v0]);
    points.extend(between(vs, v0, v1).into_iter().map(|v| [u1, v]));
    points.push([u1, v1]);
    points.extend(between(us, u0, u1).into_iter().rev().map(|u| [u, v1]));
    points.push([u0, v1]);
    points.extend(between(vs, v0, v1).into_iter().rev().map(|v| [u0, v]));
    TrimLoop { points }
}

fn distance_to_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 { (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0) } else { 0.0 };
    ((p[0] - a[0] - t * dx).powi(2) + (p[1] - a[1] - t * dy).powi(2)).sqrt()
}

/// Triangulates the region the loops retain within `domain` = [u0, u1, v0, v1], with the grid
/// points `us` × `vs` that lie inside it (and not within a quarter of the grid spacing of a
/// loop, to avoid slivers). No loops means the whole domain.
///
/// ```
/// use gleval::tess::trim::{triangulate, TrimLoop};
/// // A square hole (clockwise) in the unit square.
/// let hole = TrimLoop { points: vec![[0.25, 0.25], [0.25, 0.75], [0.75, 0.75], [0.75, 0.25]] };
/// let outer = TrimLoop { points: vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]] };
/// let grid = [0.0, 0.5, 1.0];
/// let mesh = triangulate(&[outer, hole], [0.0, 1.0, 0.0, 1.0], &grid, &grid).unwrap();
/// let area: f64 = mesh.triangles.iter().map(|t| {
///     let [a, b, c] = t.map(|i| mesh.points[i as usize]);
///     0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
/// }).sum();
/// assert!((area - 0.75).abs() < 1e-12);
/// ```
pub fn triangulate(loops: &[TrimLoop], domain: [f64; 4], us: &[f64], vs: &[f64]) -> Result<TrimMesh, TrimError> {
    if !domain.iter().all(|c| c.is_finite()) || domain[0] >= domain[1] || domain[2] >= domain[3] {
        return Err(TrimError::Misoriented);
    }
    let loops: Vec<TrimLoop> = if loops.is_empty() { vec![border_loop(domain, us, vs)] } else { loops.to_vec() };
    validate(&loops, domain)?;
    let mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>> = ConstrainedDelaunayTriangulation::new();
    for l in &loops {
        let handles: Vec<FixedVertexHandle> = l
            .points
            .iter()
            .map(|p| cdt.insert(Point2::new(p[0], p[1])).map_err(|_| TrimError::Misoriented))
            .collect::<Result<_, _>>()?;
        for i in 0..handles.len() {
            let (a, b) = (handles[i], handles[(i + 1) % handles.len()]);
            if a != b {
                if !cdt.can_add_constraint(a, b) {
                    return Err(TrimError::Intersecting);
                }
                cdt.add_constraint(a, b);
            }
        }
    }
    insert_grid_points(&mut cdt, &loops, domain, us, vs)?;
    let points: Vec<[f64; 2]> = cdt.vertices().map(|v| [v.position().x, v.position().y]).collect();
    let triangles = cdt
        .inner_faces()
        .filter_map(|f| {
            let [a, b, c] = f.positions();
            let centroid = [(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0];
            retained(&loops, centroid).then(|| f.vertices().map(|v| v.fix().index() as u32))
        })
        .collect();
    Ok(TrimMesh { points, triangles })
}

/// Inserts the interior grid points of the retained region.
fn insert_grid_points(
    cdt: &mut ConstrainedDelaunayTriangulation<Point2<f64>>,
    loops: &[TrimLoop],
    [u0, u1, v0, v1]: [f64; 4],
    us: &[f64],
    vs: &[f64],
) -> Result<(), TrimError> {
    if us.len().saturating_mul(vs.len()) > MAX_GRID_POINTS {
        return Err(TrimError::Misoriented);
    }
    let spacing = |lines: &[f64]| {
        lines.windows(2).map(|w| (w[1] - w[0]).abs()).filter(|d| *d > 0.0).fold(f64::INFINITY, f64::min)
    };
    let keep_off = 0.25 * spacing(us).min(spacing(vs)).min((u1 - u0).max(v1 - v0));
    let segments: Vec<([f64; 2], [f64; 2])> = loops.iter().flat_map(edges).collect();
    for &v in vs.iter().filter(|v| **v > v0 && **v < v1) {
        for &u in us.iter().filter(|u| **u > u0 && **u < u1) {
            let p = [u, v];
            if !retained(loops, p) || segments.iter().any(|(a, b)| distance_to_segment(p, *a, *b) < keep_off) {
                continue;
            }
            cdt.insert(Point2::new(u, v)).map_err(|_| TrimError::Misoriented)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(mesh: &TrimMesh) -> f64 {
        mesh.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| mesh.points[i as usize]);
                0.5 * orient(a, b, c)
            })
            .sum()
    }

    fn circle(cx: f64, cy: f64, r: f64, n: usize, ccw: bool) -> TrimLoop {
        let mut points: Vec<[f64; 2]> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                [cx + r * a.cos(), cy + r * a.sin()]
            })
            .collect();
        if !ccw {
            points.reverse();
        }
        TrimLoop { points }
    }

    fn square(lo: f64, hi: f64, ccw: bool) -> TrimLoop {
        let mut points = vec![[lo, lo], [hi, lo], [hi, hi], [lo, hi]];
        if !ccw {
            points.reverse();
        }
        TrimLoop { points }
    }

    fn grid(n: usize) -> Vec<f64> {
        (0..=n).map(|i| i as f64 / n as f64).collect()
    }

    const UNIT: [f64; 4] = [0.0, 1.0, 0.0, 1.0];

    #[test]
    fn no_loops_is_the_whole_domain() {
        let mesh = triangulate(&[], [0.0, 2.0, -1.0, 1.0], &[0.0, 0.5, 1.0, 1.5, 2.0], &[-1.0, 0.0, 1.0]).unwrap();
        assert!((area(&mesh) - 4.0).abs() < 1e-12);
        assert_eq!(mesh.points.len(), 15, "every grid point, border included");
    }

    #[test]
    fn hole_area_is_outer_minus_polygon_area() {
        let hole = circle(0.5, 0.5, 0.3, 64, false);
        let want = 1.0 - 0.5 * signed_area(&hole.points).abs();
        let mesh = triangulate(&[square(0.0, 1.0, true), hole], UNIT, &grid(20), &grid(20)).unwrap();
        assert!((area(&mesh) - want).abs() < 1e-12, "{} vs {want}", area(&mesh));
        assert!(mesh.triangles.iter().all(|t| {
            let [a, b, c] = t.map(|i| mesh.points[i as usize]);
            orient(a, b, c) > 0.0
        }));
    }

    #[test]
    fn constraint_edges_are_respected() {
        let hole = circle(0.5, 0.5, 0.3, 16, false);
        let mesh = triangulate(&[square(0.0, 1.0, true), hole.clone()], UNIT, &grid(10), &grid(10)).unwrap();
        for (a, b) in edges(&hole) {
            let found = mesh.triangles.iter().any(|t| {
                let p = t.map(|i| mesh.points[i as usize]);
                (0..3).any(|k| (p[k] == a && p[(k + 1) % 3] == b) || (p[k] == b && p[(k + 1) % 3] == a))
            });
            assert!(found, "edge {a:?}-{b:?} missing");
        }
    }

    #[test]
    fn nested_island_is_kept() {
        let loops = [square(0.0, 1.0, true), square(0.2, 0.8, false), square(0.4, 0.6, true)];
        let mesh = triangulate(&loops, UNIT, &grid(10), &grid(10)).unwrap();
        assert!((area(&mesh) - (1.0 - 0.36 + 0.04)).abs() < 1e-12);
    }

    #[test]
    fn glu_errors() {
        assert_eq!(triangulate(&[square(0.0, 1.0, false)], UNIT, &grid(4), &grid(4)), Err(TrimError::Misoriented));
        let eight = TrimLoop { points: vec![[0.1, 0.1], [0.9, 0.9], [0.9, 0.1], [0.1, 0.9]] };
        assert_eq!(triangulate(&[eight], UNIT, &grid(4), &grid(4)), Err(TrimError::Misoriented));
        let overlapping = [square(0.0, 1.0, true), square(0.1, 0.6, false), square(0.4, 0.9, false)];
        assert_eq!(triangulate(&overlapping, UNIT, &grid(4), &grid(4)), Err(TrimError::Intersecting));
        let outside = [square(-0.5, 1.0, true)];
        assert_eq!(triangulate(&outside, UNIT, &grid(4), &grid(4)), Err(TrimError::Misoriented));
        assert_eq!(TrimError::Unconnected.glu_number(), 31);
        assert_eq!(TrimError::Intersecting.glu_number(), 29);
    }

    #[test]
    fn joining_snaps_within_glu_tolerance_only() {
        let a = vec![[0.0, 0.0], [1.0, 0.0]];
        let b = vec![[1.0, 5e-6], [1.0, 1.0], [0.0, 1.0]];
        let c = vec![[0.0, 1.0], [0.0, 0.0]];
        let l = join_curves(&[a.clone(), b, c.clone()]).unwrap();
        assert_eq!(l.points, vec![[0.0, 0.0], [1.0, 2.5e-6], [1.0, 1.0], [0.0, 1.0]]);
        let gap = vec![[1.0, 1e-3], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(join_curves(&[a, gap, c]), Err(TrimError::Unconnected));
        assert_eq!(join_curves(&[]), Err(TrimError::Empty));
        assert_eq!(join_curves(&[vec![[0.0, 0.0], [1.0, 0.0], [0.5, 0.5]]]), Err(TrimError::Unconnected));
    }

    #[test]
    fn bad_numbers_are_errors_not_panics() {
        let nan = TrimLoop { points: vec![[f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]] };
        assert!(triangulate(&[nan], UNIT, &grid(2), &grid(2)).is_err());
        assert!(triangulate(&[], [0.0, 0.0, 0.0, 1.0], &grid(2), &grid(2)).is_err());
        let duplicate = TrimLoop { points: vec![[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]] };
        let _ = triangulate(&[duplicate], UNIT, &grid(2), &grid(2));
    }

    proptest::proptest! {
        #[test]
        fn star_holes_never_panic_and_areas_match(radii in proptest::collection::vec(0.05f64..0.35, 3..40)) {
            let n = radii.len();
            let hole: Vec<[f64; 2]> = (0..n).rev().map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                [0.5 + radii[i] * a.cos(), 0.5 + radii[i] * a.sin()]
            }).collect();
            let want = 1.0 - 0.5 * signed_area(&hole).abs();
            let mesh = triangulate(&[square(0.0, 1.0, true), TrimLoop { points: hole }], UNIT, &grid(16), &grid(16)).unwrap();
            proptest::prop_assert!((area(&mesh) - want).abs() < 1e-9);
        }
    }
}
