//! The teapot data against what is known of the shape independently of the numbers: its mirror
//! symmetries, its published extent, which of its patch edges are open, and outward normals.

use super::*;

const RIM: std::ops::Range<usize> = 0..4;
const BODY: std::ops::Range<usize> = 4..12;
const HANDLE: std::ops::Range<usize> = 12..16;
const SPOUT: std::ops::Range<usize> = 16..20;
const LID: std::ops::Range<usize> = 20..28;
const BOTTOM: std::ops::Range<usize> = 28..32;

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|c| (a[c] - b[c]).abs() <= tol)
}

fn point(p: &BezierPatch<f64>, u: f64, v: f64) -> [f64; 3] {
    let q = p.eval(u, v);
    [q[0], q[1], q[2]]
}

/// The eight maps of the unit square onto itself (flips and the swap).
fn square_maps() -> impl Iterator<Item = impl Fn(f64, f64) -> (f64, f64)> {
    (0..8).map(|k: u8| {
        move |u: f64, v: f64| {
            let (u, v) = if k & 4 != 0 { (v, u) } else { (u, v) };
            let u = if k & 1 != 0 { 1.0 - u } else { u };
            let v = if k & 2 != 0 { 1.0 - v } else { v };
            (u, v)
        }
    })
}

/// Whether the mirror image of patch `a` (coordinates multiplied by `sign`) is, as a point set,
/// one of the patches: some patch and reparameterisation agree with it on a 5 × 5 grid.
fn mirror_is_a_patch(patches: &[BezierPatch<f64>], a: usize, sign: [f64; 3]) -> bool {
    let ts = [0.0, 0.25, 0.5, 0.75, 1.0];
    patches.iter().any(|b| {
        square_maps().any(|map| {
            ts.iter().all(|&u| {
                ts.iter().all(|&v| {
                    let p = point(&patches[a], u, v);
                    let (mu, mv) = map(u, v);
                    close([p[0] * sign[0], p[1] * sign[1], p[2] * sign[2]], point(b, mu, mv), 1e-12)
                })
            })
        })
    })
}

#[test]
fn raw_arrays_have_the_classic_sizes_and_valid_indices() {
    assert_eq!(TEAPOT_VERTICES.len(), 306);
    assert_eq!(TEAPOT_PATCHES.len(), TEAPOT_PATCH_COUNT);
    assert!(TEAPOT_PATCHES.iter().flatten().all(|&i| (i as usize) < 306));
    for p in teapot_patches() {
        assert_eq!((p.dim, p.uorder, p.vorder, p.points.len()), (3, 4, 4, 48));
    }
}

#[test]
fn whole_teapot_is_symmetric_under_y_to_minus_y() {
    let patches = teapot_patches();
    for a in 0..patches.len() {
        assert!(mirror_is_a_patch(&patches, a, [1.0, -1.0, 1.0]), "patch {a}");
    }
}

#[test]
fn pot_without_handle_and_spout_is_symmetric_under_x_to_minus_x() {
    let patches = teapot_patches();
    for a in RIM.chain(BODY).chain(LID).chain(BOTTOM) {
        assert!(mirror_is_a_patch(&patches, a, [-1.0, 1.0, 1.0]), "patch {a}");
    }
    // The handle (at -x) and the spout (at +x) are not.
    assert!(!mirror_is_a_patch(&patches, HANDLE.start, [-1.0, 1.0, 1.0]));
    assert!(!mirror_is_a_patch(&patches, SPOUT.start, [-1.0, 1.0, 1.0]));
}

#[test]
fn bounding_box_is_the_published_extent() {
    // Extent of Newell's teapot: x in [-3, 3.434] (handle back to spout tip), y in [-2, 2],
    // z in [0, 3.15] (bottom to the knob).
    let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
    let n = 200;
    for p in teapot_patches() {
        for i in 0..=n {
            for j in 0..=n {
                let q = point(&p, i as f64 / n as f64, j as f64 / n as f64);
                for c in 0..3 {
                    lo[c] = lo[c].min(q[c]);
                    hi[c] = hi[c].max(q[c]);
                }
            }
        }
    }
    assert!(close(lo, [-3.0, -2.0, 0.0], 1e-9), "{lo:?}");
    assert!(close(hi, [3.434, 2.0, 3.15], 5e-4), "{hi:?}");
}

/// The four boundary curves of a patch, sampled: u = 0, u = 1, v = 0, v = 1.
fn edges(p: &BezierPatch<f64>) -> [Vec<[f64; 3]>; 4] {
    let ts: Vec<f64> = (0..=10).map(|k| k as f64 / 10.0).collect();
    [
        ts.iter().map(|&t| point(p, 0.0, t)).collect(),
        ts.iter().map(|&t| point(p, 1.0, t)).collect(),
        ts.iter().map(|&t| point(p, t, 0.0)).collect(),
        ts.iter().map(|&t| point(p, t, 1.0)).collect(),
    ]
}

fn same_curve(a: &[[f64; 3]], b: &[[f64; 3]]) -> bool {
    a.iter().zip(b).all(|(p, q)| close(*p, *q, 1e-12))
        || a.iter().zip(b.iter().rev()).all(|(p, q)| close(*p, *q, 1e-12))
}

#[test]
fn patches_meet_along_whole_edges_except_at_the_known_openings() {
    // Evaluated boundary curves, not shared indices: every edge that is not collapsed to a point
    // is traced by another patch, except the pot's openings: the rim's inner edge and the lid's
    // outer edge (the lid sits in the rim without touching it) and both ends of the handle and of
    // the spout (they pass into the body).
    let patches = teapot_patches();
    let all: Vec<[Vec<[f64; 3]>; 4]> = patches.iter().map(edges).collect();
    let mut open = Vec::new();
    for (a, ea) in all.iter().enumerate() {
        for (k, curve) in ea.iter().enumerate() {
            if curve.iter().all(|q| close(*q, curve[0], 1e-12)) {
                continue;
            }
            let matched = all
                .iter()
                .enumerate()
                .any(|(b, eb)| eb.iter().enumerate().any(|(l, other)| (a, k) != (b, l) && same_curve(curve, other)));
            if !matched {
                open.push((a, k));
            }
        }
    }
    let (v0, v1) = (2, 3);
    let mut expected: Vec<(usize, usize)> = RIM.map(|a| (a, v0)).collect();
    expected.extend(LID.skip(4).map(|a| (a, v1)));
    for part in [HANDLE, SPOUT] {
        expected.extend([(part.start, v0), (part.start + 1, v0), (part.start + 2, v1), (part.start + 3, v1)]);
    }
    expected.sort_unstable();
    assert_eq!(open, expected);
}

#[test]
fn normals_point_out_of_the_pot() {
    // u along a data row, v across: ∂p/∂u × ∂p/∂v leaves the body sideways, the bottom away from a point inside,
    // and the lid and the top of its knob upwards (away from where the lid turns down into the
    // rim, v near 1, and from the knob's underside, v past 0.3).
    let patches = teapot_patches();
    for a in BODY.chain(LID).chain(BOTTOM) {
        let mesh = patches[a].tessellate(10, 10).unwrap();
        for ((p, n), st) in mesh.positions.iter().zip(&mesh.normals).zip(&mesh.tex_coords) {
            let outward = if BODY.contains(&a) {
                n[0] * p[0] + n[1] * p[1]
            } else if BOTTOM.contains(&a) {
                n[0] * p[0] + n[1] * p[1] + n[2] * (p[2] - 0.5)
            } else if (a < 24 && st[1] <= 0.3) || (a >= 24 && st[1] < 0.9) {
                n[2]
            } else {
                continue;
            };
            // Collapsed points have no normal; elsewhere a clear outward component.
            assert!(*n == [0.0; 3] || outward > 0.0, "patch {a} at {p:?}: {n:?}");
        }
    }
}
