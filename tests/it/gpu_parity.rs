//! GPU vs CPU parity: the WGSL grid evaluator against the f64 CPU evaluation of the same packed
//! patches, for every order GL allows, rational maps, reversed parameter runs and a collapsed
//! edge. Tolerances: positions 2e-5 relative to the patch's size, normals 2e-3 (absolute, unit
//! vectors) where the CPU normal is non-zero, exactly zero where it is zero.

use gleval::render::Renderer;
use gleval::tess::gpu::{GpuTessellator, PatchGrid};
use gleval::tess::{eval_grid2, Grid2, MapView};

/// The renderer's device, or `None` (skip) when no adapter exists and CI did not require one.
pub fn device() -> Option<Renderer> {
    match Renderer::new() {
        Ok(r) => Some(r),
        Err(e) if std::env::var("GLEVAL_REQUIRE_ADAPTER").is_ok_and(|v| v == "1") => panic!("{e}"),
        Err(e) => {
            eprintln!("skipping GPU test: {e}");
            None
        }
    }
}

fn net(uo: usize, vo: usize, dim: usize, seed: usize) -> Vec<f32> {
    (0..uo * vo * dim)
        .map(|k| {
            let c = k % dim;
            if dim == 4 && c == 3 {
                0.5 + ((k * 31 + seed) % 7) as f32 * 0.25 // positive weights
            } else {
                ((k * 37 + seed * 11) % 17) as f32 * 0.125 - 1.0
            }
        })
        .collect()
}

fn oracle(points: &[f32], dim: usize, uo: usize, vo: usize, us: &[f32], vs: &[f32]) -> Grid2<f64> {
    let p64: Vec<f64> = points.iter().map(|&v| f64::from(v)).collect();
    let map = MapView { dim, uorder: uo, vorder: vo, points: &p64 };
    let (u64s, v64s): (Vec<f64>, Vec<f64>) =
        (us.iter().map(|&u| f64::from(u)).collect(), vs.iter().map(|&v| f64::from(v)).collect());
    let mut g = Grid2::default();
    eval_grid2(&map, &u64s, &v64s, true, &mut g);
    g
}

/// The unit normal and |du × dv| (after the rational correction), for conditioning.
fn normal64(dim: usize, p: [f64; 4], du: [f64; 4], dv: [f64; 4]) -> ([f64; 3], f64) {
    let (a, b) = if dim == 4 {
        (
            [du[0] * p[3] - du[3] * p[0], du[1] * p[3] - du[3] * p[1], du[2] * p[3] - du[3] * p[2]],
            [dv[0] * p[3] - dv[3] * p[0], dv[1] * p[3] - dv[3] * p[1], dv[2] * p[3] - dv[3] * p[2]],
        )
    } else {
        ([du[0], du[1], du[2]], [dv[0], dv[1], dv[2]])
    };
    let n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if l == 0.0 {
        ([0.0; 3], 0.0)
    } else {
        ([n[0] / l, n[1] / l, n[2] / l], l)
    }
}

/// name, uorder, vorder, k, control points, u parameters, v parameters.
type Case = (String, usize, usize, usize, Vec<f32>, Vec<f32>, Vec<f32>);

#[test]
fn gpu_grid_matches_cpu_for_all_orders_rational_reversed_and_degenerate() {
    let Some(r) = device() else { return };
    let gpu = GpuTessellator::new(&r.device);
    let us: Vec<f32> = (0..=12).map(|i| i as f32 / 12.0).collect();
    let reversed: Vec<f32> = us.iter().rev().copied().collect();
    let mut cases: Vec<Case> = Vec::new();
    for order in 1..=30 {
        cases.push((
            format!("order {order}x{order} k=3"),
            order,
            order,
            3,
            net(order, order, 3, order),
            us.clone(),
            us.clone(),
        ));
    }
    for (uo, vo) in [(2, 7), (7, 2), (1, 5), (30, 1)] {
        cases.push((format!("rational {uo}x{vo}"), uo, vo, 4, net(uo, vo, 4, uo + vo), us.clone(), reversed.clone()));
    }
    cases.push(("reversed u".into(), 4, 4, 3, net(4, 4, 3, 3), reversed.clone(), us.clone()));
    let mut collapsed = net(4, 4, 3, 5);
    for j in 1..4 {
        for c in 0..3 {
            collapsed[j * 3 + c] = collapsed[c];
        }
    }
    cases.push(("collapsed edge".into(), 4, 4, 3, collapsed, us.clone(), us.clone()));
    let grids: Vec<PatchGrid> = cases
        .iter()
        .map(|(_, uo, vo, k, pts, u, v)| PatchGrid {
            map: MapView { dim: *k, uorder: *uo, vorder: *vo, points: pts },
            us: u,
            vs: v,
        })
        .collect();
    let out = gpu.evaluate(&r.device, &r.queue, &grids, true).expect("GPU evaluation");
    let (mut offset, mut worst_p, mut worst_n) = (0, 0.0f64, 0.0f64);
    for (name, uo, vo, k, pts, u, v) in &cases {
        let want = oracle(pts, *k, *uo, *vo, u, v);
        let scale = pts.iter().fold(1.0f64, |m, &x| m.max(f64::from(x).abs()));
        for idx in 0..u.len() * v.len() {
            let (gp, gn) = (out.points[offset + idx], out.normals[offset + idx]);
            for c in 0..*k {
                let e = (f64::from(gp[c]) - want.points[idx][c]).abs() / scale;
                worst_p = worst_p.max(e);
                assert!(e < 2e-5, "{name}: point {idx} component {c}: gpu {} cpu {}", gp[c], want.points[idx][c]);
            }
            let (n, area) = normal64(*k, want.points[idx], want.du[idx], want.dv[idx]);
            if n == [0.0; 3] {
                assert!(gn.iter().all(|c| c.is_finite()), "{name}: NaN normal at {idx}");
                continue;
            }
            let e = (0..3).map(|c| (f64::from(gn[c]) - n[c]).abs()).fold(0.0, f64::max);
            // The normal is ill-conditioned where du x dv is tiny (du and dv nearly parallel);
            // the f32 GPU result may point anywhere there, so only well-conditioned points count.
            let weight = if *k == 4 { want.points[idx][3] * want.points[idx][3] } else { 1.0 };
            if area > 1e-2 * scale * scale * weight {
                worst_n = worst_n.max(e);
                assert!(e < 2e-3, "{name}: normal {idx}: gpu {gn:?} cpu {n:?}");
            }
        }
        offset += u.len() * v.len();
    }
    println!("GPU vs CPU worst position error {worst_p:.2e} (relative), worst normal error {worst_n:.2e}");
}
