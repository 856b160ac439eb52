//! Tests of trimmed-domain triangulation against independently computed truths: shoelace areas,
//! winding numbers, distances to the loops.

use super::geometry::midpoint;
use super::lattice::{count_at_most, count_below};
use super::*;
use proptest::prelude::*;

const UNIT: [f64; 4] = [0.0, 1.0, 0.0, 1.0];

/// Shoelace area, written independently of the module's.
fn shoelace(points: &[[f64; 2]]) -> f64 {
    let n = points.len();
    0.5 * (0..n).map(|i| points[i][0] * points[(i + 1) % n][1] - points[(i + 1) % n][0] * points[i][1]).sum::<f64>()
}

fn tri(mesh: &TrimMesh, t: &[u32; 3]) -> [[f64; 2]; 3] {
    t.map(|i| mesh.points[i as usize])
}

fn tri_area(p: [[f64; 2]; 3]) -> f64 {
    0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]))
}

fn mesh_area(mesh: &TrimMesh) -> f64 {
    mesh.triangles().map(|t| tri_area(tri(mesh, &t))).sum()
}

/// Winding number of a closed polyline around p (sum of signed angles).
fn winding(points: &[[f64; 2]], p: [f64; 2]) -> i32 {
    let n = points.len();
    let total: f64 = (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            let (ax, ay, bx, by) = (a[0] - p[0], a[1] - p[1], b[0] - p[0], b[1] - p[1]);
            (ax * by - ay * bx).atan2(ax * bx + ay * by)
        })
        .sum();
    (total / std::f64::consts::TAU).round() as i32
}

/// GLU's rule for well-formed loops: retained where the loops wind once around the point.
fn retained_by_winding(loops: &[TrimLoop], p: [f64; 2]) -> bool {
    loops.iter().map(|l| winding(&l.points, p)).sum::<i32>() == 1
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
    rect(lo, hi, lo, hi, ccw)
}

fn rect(u0: f64, u1: f64, v0: f64, v1: f64, ccw: bool) -> TrimLoop {
    let mut points = vec![[u0, v0], [u1, v0], [u1, v1], [u0, v1]];
    if !ccw {
        points.reverse();
    }
    TrimLoop { points }
}

fn grid(n: usize) -> Vec<f64> {
    (0..=n).map(|i| i as f64 / n as f64).collect()
}

fn loop_edges(l: &TrimLoop) -> Vec<([f64; 2], [f64; 2])> {
    let n = l.points.len();
    (0..n).map(|i| (l.points[i], l.points[(i + 1) % n])).collect()
}

fn has_edge(mesh: &TrimMesh, a: [f64; 2], b: [f64; 2]) -> bool {
    mesh.triangles().any(|t| {
        let p = tri(mesh, &t);
        (0..3).any(|k| (p[k] == a && p[(k + 1) % 3] == b) || (p[k] == b && p[(k + 1) % 3] == a))
    })
}

fn seg_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let t = (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    ((p[0] - a[0] - t * dx).powi(2) + (p[1] - a[1] - t * dy).powi(2)).sqrt()
}

/// Whether segment ab meets the closed box [lo, hi] (Liang–Barsky clipping).
fn segment_meets_box(a: [f64; 2], b: [f64; 2], lo: [f64; 2], hi: [f64; 2]) -> bool {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for c in 0..2 {
        let d = b[c] - a[c];
        if d == 0.0 {
            if a[c] < lo[c] || a[c] > hi[c] {
                return false;
            }
            continue;
        }
        let (mut s0, mut s1) = ((lo[c] - a[c]) / d, (hi[c] - a[c]) / d);
        if s0 > s1 {
            std::mem::swap(&mut s0, &mut s1);
        }
        t0 = t0.max(s0);
        t1 = t1.min(s1);
    }
    t0 <= t1
}

/// The grid strips: axis-aligned cells whose triangles follow the band's, that no loop edge
/// meets (touching counts); and every point is used.
fn assert_strips_sound(mesh: &TrimMesh, loops: &[TrimLoop]) {
    let cells: usize = mesh.strips.iter().map(|s| s.cells as usize).sum();
    let all: Vec<[u32; 3]> = mesh.triangles().collect();
    assert_eq!(all.len(), mesh.triangle_count());
    assert_eq!(all.len(), mesh.band.len() + 2 * cells);
    assert_eq!(&all[..mesh.band.len()], &mesh.band[..]);
    let edges: Vec<_> = loops.iter().flat_map(loop_edges).collect();
    for s in &mesh.strips {
        for i in 0..s.cells {
            let (b0, b1) = (mesh.points[(s.bottom + i) as usize], mesh.points[(s.bottom + i + 1) as usize]);
            let (t0, t1) = (mesh.points[(s.top + i) as usize], mesh.points[(s.top + i + 1) as usize]);
            assert!(b0[1] == b1[1] && t0[1] == t1[1] && b0[0] == t0[0] && b1[0] == t1[0], "not a grid cell");
            assert!(b0[0] < b1[0] && b0[1] < t0[1], "not counter-clockwise");
            for (a, b) in &edges {
                // Only an edge along one of the cell's sides (the domain's border) may touch it.
                let along = |c: usize, x: f64| a[c] == x && b[c] == x;
                let on_side = along(0, b0[0]) || along(0, b1[0]) || along(1, b0[1]) || along(1, t0[1]);
                assert!(
                    on_side || !segment_meets_box(*a, *b, b0, t1),
                    "loop edge {a:?}-{b:?} meets cell {b0:?}-{t1:?}"
                );
            }
        }
    }
    let mut used = vec![false; mesh.points.len()];
    mesh.triangles().flatten().for_each(|i| used[i as usize] = true);
    assert!(used.iter().all(|&u| u), "unused point");
    assert_lattice_sound(mesh);
}

/// The lattice's lines increase, and every grid point is at the lattice point its index names,
/// row by row.
fn assert_lattice_sound(mesh: &TrimMesh) {
    let l = &mesh.lattice;
    assert!(l.u.windows(2).all(|w| w[0] < w[1]) && l.v.windows(2).all(|w| w[0] < w[1]), "lines not increasing");
    assert!(l.index.windows(2).all(|w| w[0] < w[1]), "grid points not row by row");
    assert!(l.index.len() <= mesh.points.len());
    for (&k, p) in l.index.iter().zip(&mesh.points) {
        let (i, j) = (k as usize % l.u.len(), k as usize / l.u.len());
        assert_eq!(*p, [l.u[i], l.v[j]], "grid point at lattice index {k}");
    }
}

/// Area, orientation and containment checks shared by the tests.
fn assert_sound(mesh: &TrimMesh, loops: &[TrimLoop], want_area: f64) {
    assert_strips_sound(mesh, loops);
    assert!((mesh_area(mesh) - want_area).abs() < 1e-10, "area {} vs {want_area}", mesh_area(mesh));
    for t in mesh.triangles() {
        let p = tri(mesh, &t);
        assert!(tri_area(p) > 0.0, "clockwise or flat triangle {p:?}");
        let c = [(p[0][0] + p[1][0] + p[2][0]) / 3.0, (p[0][1] + p[1][1] + p[2][1]) / 3.0];
        assert!(retained_by_winding(loops, c), "centroid {c:?} outside the retained region");
    }
}

#[test]
fn no_loops_is_the_whole_domain_with_a_sampled_border() {
    let mesh = triangulate(&[], [0.0, 2.0, -1.0, 1.0], &[0.0, 0.5, 1.0, 1.5, 2.0], &[-1.0, 0.0, 1.0]).unwrap();
    assert_sound(&mesh, &[rect(0.0, 2.0, -1.0, 1.0, true)], 4.0);
    assert_eq!(mesh.points.len(), 15, "every grid point, border included");
}

#[test]
fn cells_away_from_the_loops_come_from_the_grid() {
    let loops = [square(0.0, 1.0, true), circle(0.5, 0.5, 0.3, 64, false)];
    let want = 1.0 - shoelace(&loops[1].points).abs();
    let mesh = triangulate(&loops, UNIT, &grid(100), &grid(100)).unwrap();
    assert_sound(&mesh, &loops, want);
    // Only the cells along the loops (the border ring and about 2πr·100 cells around the hole,
    // with their neighbours) are left to the constrained triangulation.
    let cells: usize = mesh.strips.iter().map(|s| s.cells as usize).sum();
    let grid_area = cells as f64 * 1e-4;
    assert!(grid_area > want - 0.08, "grid cells cover {grid_area} of {want}");
    assert!(mesh.band.len() < 1500, "{} band triangles", mesh.band.len());
}

/// A loop running round the domain's border (any start, extra points on the sides) is the
/// domain itself: the grid's border points are used, the same mesh as with no outer loop at all.
#[test]
fn a_border_loop_is_the_domain() {
    let hole = circle(0.5, 0.5, 0.3, 32, false);
    let g = grid(7);
    let plain = triangulate(&[square(0.0, 1.0, true), hole.clone()], UNIT, &g, &g).unwrap();
    let sides = TrimLoop::new(vec![[1.0, 0.3], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0], [0.61, 0.0], [1.0, 0.0]]);
    assert_eq!(triangulate(&[sides.clone(), hole.clone()], UNIT, &g, &g).unwrap(), plain);
    assert_sound(&plain, &[sides, hole.clone()], 1.0 - shoelace(&hole.points).abs());
    for (i, &u) in g.iter().enumerate() {
        for p in [[u, 0.0], [u, 1.0], [0.0, g[i]], [1.0, g[i]]] {
            assert!(plain.points.contains(&p), "border grid point {p:?} missing");
        }
    }
    assert!(!plain.strips.is_empty());
    // The border run clockwise is a misoriented loop, not the domain.
    assert_eq!(triangulate(&[square(0.0, 1.0, false)], UNIT, &g, &g), Err(TrimError::Misoriented));
}

#[test]
fn hole_area_is_square_minus_polygon() {
    let loops = [square(0.0, 1.0, true), circle(0.5, 0.5, 0.3, 64, false)];
    let want = 1.0 - shoelace(&loops[1].points).abs();
    let mesh = triangulate(&loops, UNIT, &grid(20), &grid(20)).unwrap();
    assert_sound(&mesh, &loops, want);
}

#[test]
fn grid_points_are_kept_inside_and_away_from_the_loops() {
    let loops = [square(0.0, 1.0, true), circle(0.5, 0.5, 0.3, 64, false)];
    let g = grid(20);
    let mesh = triangulate(&loops, UNIT, &g, &g).unwrap();
    let edges: Vec<_> = loops.iter().flat_map(loop_edges).collect();
    for &v in &g[1..20] {
        for &u in &g[1..20] {
            let d = edges.iter().map(|(a, b)| seg_distance([u, v], *a, *b)).fold(f64::INFINITY, f64::min);
            let present = mesh.points.contains(&[u, v]);
            if loops.iter().any(|l| l.points.contains(&[u, v])) {
                continue; // a loop vertex, present as such
            }
            if retained_by_winding(&loops, [u, v]) && d > 0.25 / 20.0 + 1e-12 {
                assert!(present, "grid point {u},{v} missing");
            } else if d < 0.25 / 20.0 - 1e-12 || !retained_by_winding(&loops, [u, v]) {
                assert!(!present, "grid point {u},{v} should be left out (distance {d})");
            }
        }
    }
}

#[test]
fn constraint_edges_are_triangle_edges() {
    let loops = [square(0.0, 1.0, true), circle(0.5, 0.5, 0.3, 16, false), circle(0.5, 0.5, 0.1, 7, true)];
    let mesh = triangulate(&loops, UNIT, &grid(10), &grid(10)).unwrap();
    // The domain's border is sampled at the grid lines (checked in `split_edges_keep_the_boundary`).
    for l in &loops[1..] {
        for (a, b) in loop_edges(l) {
            assert!(has_edge(&mesh, a, b), "edge {a:?}-{b:?} missing");
        }
    }
}

#[test]
fn split_edges_keep_the_boundary() {
    let loops = [square(0.0, 1.0, true), circle(0.5, 0.5, 0.3, 16, false)];
    let options = TrimOptions::DEFAULT.with_split_at_grid_lines(true);
    let mesh = triangulate_with(&loops, UNIT, &grid(10), &grid(10), &options).unwrap();
    let want = 1.0 - shoelace(&loops[1].points).abs();
    assert_sound(&mesh, &loops, want);
    // Boundary edges of the mesh (used by one triangle) lie on the loops and add up to their length.
    let mut count = std::collections::HashMap::new();
    for t in mesh.triangles() {
        for k in 0..3 {
            let (a, b) = (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]));
            *count.entry((a, b)).or_insert(0) += 1;
        }
    }
    let edges: Vec<_> = loops.iter().flat_map(loop_edges).collect();
    let mut length = 0.0;
    for (&(a, b), _) in count.iter().filter(|(_, c)| **c == 1) {
        let (p, q) = (mesh.points[a as usize], mesh.points[b as usize]);
        let on = |x: [f64; 2]| edges.iter().any(|(s, e)| seg_distance(x, *s, *e) < 1e-12);
        assert!(on(p) && on(q) && on(midpoint(p, q)), "boundary edge {p:?}-{q:?} off the loops");
        length += (q[0] - p[0]).hypot(q[1] - p[1]);
    }
    let perimeter: f64 = edges.iter().map(|(a, b)| (b[0] - a[0]).hypot(b[1] - a[1])).sum();
    assert!((length - perimeter).abs() < 1e-9);
    // The outer square now has a vertex on every grid line.
    for &u in &grid(10) {
        assert!(mesh.points.contains(&[u, 0.0]) && mesh.points.contains(&[u, 1.0]));
    }
}

#[test]
fn split_at_lines_puts_exact_coordinates_on_the_lines() {
    let l = split_at_lines(&TrimLoop::new(vec![[0.0, 0.0], [1.0, 0.5], [0.0, 1.0]]), &[0.5], &[0.25, 0.5]);
    // Edge 1 crosses u = 0.5 and v = 0.25 at one point, edge 2 crosses u = 0.5, edge 3 both v lines.
    let want = [[0.0, 0.0], [0.5, 0.25], [1.0, 0.5], [0.5, 0.75], [0.0, 1.0], [0.0, 0.5], [0.0, 0.25]];
    assert_eq!(l.points, want);
    assert!((shoelace(&l.points) - 0.5).abs() < 1e-15);
}

#[test]
fn nested_island_is_kept() {
    let loops = [square(0.0, 1.0, true), square(0.2, 0.8, false), square(0.4, 0.6, true)];
    let mesh = triangulate(&loops, UNIT, &grid(10), &grid(10)).unwrap();
    assert_sound(&mesh, &loops, 1.0 - 0.36 + 0.04);
}

#[test]
fn two_outer_loops_and_a_closing_repeat() {
    let mut a = rect(0.1, 0.4, 0.1, 0.9, true);
    a.points.push(a.points[0]);
    let loops = [a, rect(0.6, 0.9, 0.1, 0.9, true)];
    let mesh = triangulate(&loops, UNIT, &grid(8), &grid(8)).unwrap();
    assert_sound(&mesh, &loops, 2.0 * 0.3 * 0.8);
}

#[test]
fn orientation_must_match_nesting_depth() {
    let g = grid(4);
    assert_eq!(triangulate(&[square(0.0, 1.0, false)], UNIT, &g, &g), Err(TrimError::Misoriented));
    let ccw_hole = [square(0.0, 1.0, true), square(0.3, 0.6, true)];
    assert_eq!(triangulate(&ccw_hole, UNIT, &g, &g), Err(TrimError::Misoriented));
    let cw_island = [square(0.0, 1.0, true), square(0.2, 0.8, false), square(0.4, 0.6, false)];
    assert_eq!(triangulate(&cw_island, UNIT, &g, &g), Err(TrimError::Misoriented));
}

#[test]
fn self_intersection_and_crossings() {
    let g = grid(4);
    let eight = TrimLoop::new(vec![[0.1, 0.1], [0.9, 0.9], [0.9, 0.1], [0.1, 0.9]]);
    assert_eq!(triangulate(&[eight], UNIT, &g, &g), Err(TrimError::Misoriented));
    let pinched = TrimLoop::new(vec![[0.1, 0.1], [0.5, 0.5], [0.9, 0.1], [0.9, 0.9], [0.5, 0.5], [0.1, 0.9]]);
    assert_eq!(triangulate(&[pinched], UNIT, &g, &g), Err(TrimError::Misoriented));
    let spike = TrimLoop::new(vec![[0.1, 0.1], [0.9, 0.1], [0.5, 0.1], [0.5, 0.9]]);
    assert_eq!(triangulate(&[spike], UNIT, &g, &g), Err(TrimError::Misoriented));
    let overlapping = [square(0.0, 1.0, true), square(0.1, 0.6, false), square(0.4, 0.9, false)];
    assert_eq!(triangulate(&overlapping, UNIT, &g, &g), Err(TrimError::Intersecting));
    let two_outer = [square(0.1, 0.6, true), square(0.4, 0.9, true)];
    assert_eq!(triangulate(&two_outer, UNIT, &g, &g), Err(TrimError::Intersecting));
    let touching = [square(0.0, 1.0, true), rect(0.2, 0.5, 0.2, 0.8, false), rect(0.5, 0.8, 0.2, 0.8, false)];
    assert_eq!(triangulate(&touching, UNIT, &g, &g), Err(TrimError::Intersecting));
}

#[test]
fn degenerate_loops() {
    let g = grid(4);
    assert_eq!(triangulate(&[TrimLoop::default()], UNIT, &g, &g), Err(TrimError::Empty));
    let two = TrimLoop::new(vec![[0.1, 0.1], [0.9, 0.9], [0.1, 0.1]]);
    assert_eq!(triangulate(&[two], UNIT, &g, &g), Err(TrimError::Misoriented));
    let flat = TrimLoop::new(vec![[0.1, 0.1], [0.5, 0.5], [0.9, 0.9]]);
    assert_eq!(triangulate(&[flat], UNIT, &g, &g), Err(TrimError::Misoriented));
    assert_eq!(triangulate(&[square(-0.5, 1.0, true)], UNIT, &g, &g), Err(TrimError::Misoriented));
    let duplicate = TrimLoop::new(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    let mesh = triangulate(std::slice::from_ref(&duplicate), UNIT, &g, &g).unwrap();
    assert_sound(&mesh, &[duplicate], 0.5);
}

#[test]
fn bad_numbers_are_errors_not_panics() {
    let g = grid(2);
    let nan = TrimLoop::new(vec![[f64::NAN, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    assert_eq!(triangulate(&[nan], UNIT, &g, &g), Err(TrimError::Misoriented));
    let inf = TrimLoop::new(vec![[f64::INFINITY, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    assert_eq!(triangulate(&[inf], UNIT, &g, &g), Err(TrimError::Misoriented));
    for domain in [[0.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0], [0.0, f64::NAN, 0.0, 1.0], [0.0, 1e300, 0.0, 1.0]] {
        assert_eq!(triangulate(&[], domain, &g, &g), Err(TrimError::Misoriented));
    }
    let odd = [f64::NAN, f64::INFINITY, -3.0, 0.5, 0.5, 7.0, 1e-300, 0.25];
    let mesh = triangulate(&[], UNIT, &odd, &odd).unwrap();
    assert_sound(&mesh, &[square(0.0, 1.0, true)], 1.0);
    let tiny = TrimLoop::new(vec![[1e-300, 1e-300], [1.0, 0.0], [0.0, 1.0]]);
    assert!(triangulate(&[tiny], UNIT, &g, &g).is_ok());
    for clearance in [0.0, f64::NAN, -1.0, 10.0] {
        let options = TrimOptions::DEFAULT.with_clearance(clearance);
        let loops = [square(0.0, 1.0, true), square(0.25, 0.75, false)];
        let mesh = triangulate_with(&loops, UNIT, &grid(4), &grid(4), &options).unwrap();
        assert_sound(&mesh, &loops, 0.75);
    }
}

#[test]
fn the_point_budget_coarsens_the_grid() {
    let loops = [square(0.0, 1.0, true), circle(0.5, 0.5, 0.3, 40, false)];
    let options = TrimOptions::DEFAULT.with_max_points(1000);
    let mesh = triangulate_with(&loops, UNIT, &grid(200), &grid(200), &options).unwrap();
    assert!(mesh.points.len() <= 1000 + 44, "{} points", mesh.points.len());
    assert!(mesh.points.len() > 200);
    assert_sound(&mesh, &loops, 1.0 - shoelace(&loops[1].points).abs());
    let none = triangulate_with(&loops, UNIT, &grid(20), &grid(20), &TrimOptions::DEFAULT.with_max_points(0)).unwrap();
    assert_eq!(none.points.len(), 44);
    // The coarsened lattice is not the one the sampling lines give; its indices still hold.
    assert!(!mesh.lattice.same_lines(&Lattice::lines(UNIT, &grid(200), &grid(200))));
    assert_lattice_sound(&mesh);
}

#[test]
fn the_lattice_is_the_sampling_lines_between_the_bounds() {
    let loops = [square(0.0, 1.0, true), circle(0.5, 0.5, 0.3, 40, false)];
    // Unsorted lines with a duplicate, one outside the domain and a NaN: sorted and cleaned.
    let us = [0.5, 0.25, 0.75, 0.25, 1.5, f64::NAN];
    let mesh = triangulate(&loops, UNIT, &us, &grid(8)).unwrap();
    let want = Lattice::lines(UNIT, &us, &grid(8));
    assert_eq!(want.u, [0.0, 0.25, 0.5, 0.75, 1.0]);
    assert_eq!(want.point_count(), 5 * 9);
    assert!(mesh.lattice.same_lines(&want));
    assert!(!mesh.lattice.index.is_empty());
    assert_lattice_sound(&mesh);
}

#[test]
fn joining_snaps_within_glu_tolerance_only() {
    let a = vec![[0.0, 0.0], [1.0, 0.0]];
    let b = vec![[1.0, 5e-6], [1.0, 1.0], [0.0, 1.0]];
    let c = vec![[0.0, 1.0], [0.0, 0.0]];
    let l = join_curves(&[a.clone(), b, c.clone()]).unwrap();
    assert_eq!(l.points, vec![[0.0, 0.0], [1.0, 2.5e-6], [1.0, 1.0], [0.0, 1.0]]);
    let gap = vec![[1.0, 1e-3], [1.0, 1.0], [0.0, 1.0]];
    assert_eq!(join_curves(&[a.clone(), gap, c.clone()]), Err(TrimError::Unconnected));
    // The last curve must come back to the first.
    let open = vec![[0.0, 1.0], [0.0, 0.5]];
    assert_eq!(join_curves(&[a.clone(), vec![[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], open]), Err(TrimError::Unconnected));
    assert_eq!(join_curves(&[]), Err(TrimError::Empty));
    assert_eq!(join_curves(&[vec![], vec![]]), Err(TrimError::Empty));
    assert_eq!(join_curves(&[vec![[0.0, 0.0], [1.0, 0.0], [0.5, 0.5]]]), Err(TrimError::Unconnected));
    assert_eq!(join_curves(&[vec![[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]]]), Err(TrimError::Misoriented));
    assert_eq!(join_curves(&[vec![[f64::NAN, 0.0]]]), Err(TrimError::Misoriented));
}

#[test]
fn joining_drops_near_duplicates() {
    let piece = vec![[0.0, 0.0], [0.5, 0.0], [0.5 + 4e-6, 3e-6], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [3e-6, 0.0]];
    let l = join_curves(&[piece]).unwrap();
    assert_eq!(l.points.len(), 5);
    assert_eq!(l.points[0], [1.5e-6, 0.0]);
}

#[test]
fn glu_numbers_and_messages() {
    let all = [TrimError::Unconnected, TrimError::Misoriented, TrimError::Intersecting, TrimError::Empty];
    assert_eq!(all.map(TrimError::glu_number), [31, 28, 29, 18]);
    assert_eq!(TrimError::Misoriented.to_string(), "intersecting or misoriented trim curves");
}

fn star(radii: &[f64], c: [f64; 2]) -> TrimLoop {
    let n = radii.len();
    TrimLoop::new(
        (0..n)
            .rev()
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                [c[0] + radii[i] * a.cos(), c[1] + radii[i] * a.sin()]
            })
            .collect(),
    )
}

proptest! {
    #[test]
    fn star_holes_never_panic_and_areas_match(
        radii in proptest::collection::vec(0.01f64..0.35, 3..60),
        c in (0.36f64..0.64, 0.36f64..0.64),
        n in 1usize..40,
        split in any::<bool>(),
    ) {
        let loops = [square(0.0, 1.0, true), star(&radii, [c.0, c.1])];
        let want = 1.0 - shoelace(&loops[1].points).abs();
        let options = TrimOptions::DEFAULT.with_split_at_grid_lines(split);
        let mesh = triangulate_with(&loops, UNIT, &grid(n), &grid(n), &options).unwrap();
        assert_sound(&mesh, &loops, want);
    }

    #[test]
    fn random_loops_never_panic(
        points in proptest::collection::vec((-0.2f64..1.2, -0.2f64..1.2), 0..12),
        n in 0usize..12,
    ) {
        let l = TrimLoop::new(points.iter().map(|p| [p.0, p.1]).collect());
        if let Ok(mesh) = triangulate(&[square(0.0, 1.0, true), l.clone()], UNIT, &grid(n), &grid(n)) {
            let want = 1.0 - shoelace(&l.points).abs();
            assert_sound(&mesh, &[square(0.0, 1.0, true), l.clone()], want);
        }
        let _ = triangulate(&[l], UNIT, &grid(n), &grid(n));
    }
}

// ---------------------------------------------------------------------------------------------
// The band cell by cell (`TrimOptions::by_cells`).

/// The cell-by-cell options.
const CELLS: TrimOptions = TrimOptions { clearance: 0.0, by_cells: true, ..TrimOptions::DEFAULT };

/// Triangulates cell by cell, checks the result as every triangulation is checked, and
/// returns whether it came from the cells (no hand-over to the Delaunay triangulation).
fn cells_sound(loops: &[TrimLoop], domain: [f64; 4], us: &[f64], vs: &[f64], want_area: f64) -> bool {
    let plan = TrimPlan::new(loops, domain, us, vs, &CELLS).unwrap();
    let by_cells = plan.triangulate_band_by_cells();
    let handed_over = by_cells.is_none();
    let band = by_cells.map_or_else(|| plan.triangulate_band(), Ok).unwrap();
    let mesh = plan.into_mesh(band);
    let truth: Vec<TrimLoop> =
        if loops.is_empty() { vec![rect(domain[0], domain[1], domain[2], domain[3], true)] } else { loops.to_vec() };
    assert_sound(&mesh, &truth, want_area);
    !handed_over
}

#[test]
fn cells_cover_holes_islands_and_outer_loops() {
    let hole = circle(0.5, 0.5, 0.3, 64, false);
    let loops = [square(0.0, 1.0, true), hole.clone()];
    assert!(cells_sound(&loops, UNIT, &grid(20), &grid(20), 1.0 - shoelace(&hole.points).abs()));
    let nested = [square(0.0, 1.0, true), circle(0.5, 0.5, 0.35, 40, false), circle(0.5, 0.5, 0.2, 30, true)];
    let want = 1.0 - shoelace(&nested[1].points).abs() + shoelace(&nested[2].points);
    assert!(cells_sound(&nested, UNIT, &grid(13), &grid(17), want));
    // Outer loops inside the domain, no border loop.
    let two = [circle(0.3, 0.3, 0.2, 24, true), rect(0.6, 0.9, 0.1, 0.95, true)];
    let want = shoelace(&two[0].points) + 0.3 * 0.85;
    assert!(cells_sound(&two, UNIT, &grid(10), &grid(10), want));
    assert!(cells_sound(&[], [0.0, 2.0, -1.0, 1.0], &[0.5, 1.0, 1.5], &[0.0], 4.0));
}

/// Loops through grid points, along grid lines and through cell corners on diagonals: the
/// cases the half-open rule decides.
#[test]
fn cells_decide_points_on_grid_lines() {
    let g = grid(4);
    // A hole whose edges lie on grid lines.
    let hole = square(0.25, 0.75, false);
    assert!(cells_sound(&[square(0.0, 1.0, true), hole], UNIT, &g, &g, 0.75));
    // A diamond through grid points, its edges diagonals through cell corners.
    let diamond = TrimLoop::new(vec![[0.5, 0.0 + 0.25], [0.25, 0.5], [0.5, 0.75], [0.75, 0.5]]);
    assert!(diamond.signed_area() < 0.0);
    assert!(cells_sound(&[square(0.0, 1.0, true), diamond.clone()], UNIT, &grid(8), &grid(8), 1.0 - 0.125));
    // The same diamond counter-clockwise, as an outer loop.
    let mut ccw = diamond.points.clone();
    ccw.reverse();
    assert!(cells_sound(&[TrimLoop::new(ccw)], UNIT, &grid(8), &grid(8), 0.125));
    // The red book's hills hole: a Bezier arc and a polyline from (0.75, 0.5) through (0.5, 0.25).
    let mut arc: Vec<[f64; 2]> = (0..=40)
        .map(|i| {
            let t = f64::from(i) / 40.0;
            let b = [(1.0 - t).powi(3), 3.0 * t * (1.0 - t).powi(2), 3.0 * t * t * (1.0 - t), t.powi(3)];
            let (xs, ys) = ([0.25, 0.25, 0.75, 0.75], [0.5, 0.75, 0.75, 0.5]);
            [(0..4).map(|k| b[k] * xs[k]).sum(), (0..4).map(|k| b[k] * ys[k]).sum()]
        })
        .collect();
    arc.push([0.5, 0.25]);
    let hole = TrimLoop::new(arc);
    let tri = TrimLoop::new(vec![[0.1, 0.1], [0.2, 0.3], [0.3, 0.1]]);
    let want = 1.0 - shoelace(&hole.points).abs() - shoelace(&tri.points).abs();
    for n in [4, 8, 20, 300] {
        let loops = [square(0.0, 1.0, true), hole.clone(), tri.clone()];
        assert!(cells_sound(&loops, UNIT, &grid(n), &grid(n), want), "grid {n}");
    }
}

/// Whether the loop's bounding box spans one of the interior lines of `grid(n)` (so that the
/// loop crosses it).
fn spans_a_line(l: &TrimLoop, n: usize) -> bool {
    let lines = &grid(n)[1..n];
    (0..2).any(|c| {
        let lo = l.points.iter().map(|p| p[c]).fold(f64::INFINITY, f64::min);
        let hi = l.points.iter().map(|p| p[c]).fold(f64::NEG_INFINITY, f64::max);
        lines.iter().any(|&x| lo < x && x <= hi)
    })
}

/// Whether the loop (repeated points aside) turns back on itself within rounding somewhere.
fn has_near_spike(l: &TrimLoop) -> bool {
    let mut p = l.points.clone();
    p.dedup();
    let n = p.len();
    (0..n).any(|i| {
        let (a, b, c) = (p[i], p[(i + 1) % n], p[(i + 2) % n]);
        let cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        let dot = (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]);
        cross.abs() <= 1e-12 && dot < 0.0
    })
}

/// A loop inside one grid cell is left to the Delaunay triangulation, which still gives the
/// right region.
#[test]
fn a_loop_inside_one_cell_hands_over() {
    let hole = circle(0.55, 0.55, 0.01, 9, false);
    let loops = [square(0.0, 1.0, true), hole.clone()];
    assert!(!cells_sound(&loops, UNIT, &grid(10), &grid(10), 1.0 - shoelace(&hole.points).abs()));
}

proptest! {
    #[test]
    fn cells_cut_star_holes_exactly(
        radii in proptest::collection::vec(0.01f64..0.35, 3..60),
        c in (0.36f64..0.64, 0.36f64..0.64),
        n in 1usize..40,
    ) {
        let loops = [square(0.0, 1.0, true), star(&radii, [c.0, c.1])];
        let want = 1.0 - shoelace(&loops[1].points).abs();
        let by_cells = cells_sound(&loops, UNIT, &grid(n), &grid(n), want);
        prop_assert_eq!(by_cells, spans_a_line(&loops[1], n), "handed over to the Delaunay triangulation");
    }

}

fn star_on_grid(spokes: &[u32], n: u32) -> TrimLoop {
    let step = 1.0 / f64::from(n);
    let k = spokes.len();
    let points: Vec<[f64; 2]> = spokes
        .iter()
        .enumerate()
        .map(|(i, &r)| {
            let a = -std::f64::consts::TAU * i as f64 / k as f64;
            let snap = |x: f64| (x / step).round() * step;
            [snap(0.5 + f64::from(r) * step * a.cos()), snap(0.5 + f64::from(r) * step * a.sin())]
        })
        .collect();
    TrimLoop::new(points)
}

proptest! {
    // Many generated stars fold back within rounding and are skipped.
    #![proptest_config(ProptestConfig { max_global_rejects: 1_000_000, ..ProptestConfig::default() })]

    /// Stars whose points sit on the grid (coordinates in steps of 1/n): every crossing is a
    /// tie the half-open rule breaks.
    #[test]
    fn cells_cut_stars_on_grid_points(spokes in proptest::collection::vec(1u32..6, 4..24), n in 8u32..24) {
        let hole = star_on_grid(&spokes, n);
        // Snapping can fold an edge back onto the previous one up to rounding: a spike of no
        // width, which the cells leave to the Delaunay triangulation.
        prop_assume!(!has_near_spike(&hole));
        let loops = [square(0.0, 1.0, true), hole.clone()];
        let g = grid(n as usize);
        if triangulate(&loops, UNIT, &g, &g).is_ok() {
            let want = 1.0 - shoelace(&hole.points).abs();
            prop_assert!(cells_sound(&loops, UNIT, &g, &g, want), "handed over");
        }
    }
}

/// Sorted lines of many shapes: evenly spaced (the guess is exact), jittered, geometric (the
/// guess is far off), with repeats, single.
fn line_shapes() -> impl Strategy<Value = Vec<f64>> {
    (1usize..40, 0u8..4, -5.0f64..5.0, 0.01f64..10.0, proptest::collection::vec(0.0f64..1.0, 40)).prop_map(
        |(n, shape, start, width, jitter)| {
            let mut lines: Vec<f64> = (0..n)
                .map(|i| {
                    let t = i as f64 / n.max(2) as f64;
                    match shape {
                        0 => start + width * t,
                        1 => start + width * (t + 0.4 * jitter[i] / n as f64),
                        2 => start + width * (1.0 - 0.5f64.powi(i as i32)),
                        _ => start + width * (t * 4.0).floor(),
                    }
                })
                .collect();
            lines.sort_by(f64::total_cmp);
            lines
        },
    )
}

proptest! {
    /// The guessed partition points are the binary search's, for any sorted lines and any x:
    /// on a line, between, outside, infinite or NaN.
    #[test]
    fn counts_match_the_binary_search(lines in line_shapes(), pick in 0usize..40, offset in -1.0f64..1.0, kind in 0u8..5) {
        let x = match kind {
            0 => lines[pick % lines.len()],
            1 => lines[pick % lines.len()] + offset * 1e-3,
            2 => offset * 20.0,
            3 => f64::INFINITY * offset.signum(),
            _ => f64::NAN,
        };
        prop_assert_eq!(count_at_most(&lines, x), lines.partition_point(|l| *l <= x));
        prop_assert_eq!(count_below(&lines, x), lines.partition_point(|l| *l < x));
    }
}
