//! The Rust side of `bench/compare.sh`: the same workloads as `bench/anchor.c` (real Mesa and
//! GLU), timed here as medians of several runs. Prints "<case> <rate per second>".
//!
//! `cargo run --release --example bench`

use gleval::math::BezierPatch;
use gleval::prelude::*;
use gleval::tess::Mesh;
use std::time::Instant;

fn median(mut t: Vec<f64>) -> f64 {
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

fn time(runs: usize, mut f: impl FnMut()) -> f64 {
    median(
        (0..runs)
            .map(|_| {
                let s = Instant::now();
                f();
                s.elapsed().as_secs_f64()
            })
            .collect(),
    )
}

fn patch() -> Vec<f32> {
    (0..16)
        .flat_map(|k| [(k / 4) as f32 / 3.0 - 0.5, (k % 4) as f32 / 3.0 - 0.5, ((k / 4 + k % 4) % 3) as f32 * 0.2])
        .collect()
}

/// The façade: glEvalMesh2(GL_FILL) with GL_AUTO_NORMAL, recorded into a frame.
fn facade_mesh2(n: i32, runs: usize) -> f64 {
    let mut gl = Gl::new(64, 64);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &patch());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(n, 0.0, 1.0, n, 0.0, 1.0);
    let t = time(runs, || {
        gl.eval_mesh2(GL_FILL, 0, n, 0, n);
        let frame = std::hint::black_box(gl.take_frame());
        gl.recycle_frame(frame);
    });
    f64::from((n + 1) * (n + 1)) / t
}

/// The typed API: a bicubic patch tessellated into a mesh (positions, unit normals, texture
/// coordinates, triangle indices) over an n × n grid, re-tessellated into the same mesh as a
/// program updating a surface does (`fresh`: a new mesh each time, as `tessellate` gives).
fn typed_grid(n: usize, runs: usize, fresh: bool) -> f64 {
    let patch = BezierPatch::try_new(3, 4, 4, patch()).expect("a bicubic patch");
    let params: Vec<f32> = (0..=n).map(|i| i as f32 / n as f32).collect();
    let mut mesh = Mesh::default();
    let t = time(runs, || {
        if fresh {
            mesh = patch.tessellate(n, n).expect("mesh");
        } else {
            patch.tessellate_grid_into(&params, &params, &mut mesh).expect("mesh");
        }
        std::hint::black_box(&mesh);
    });
    ((n + 1) * (n + 1)) as f64 / t
}

/// 10,000 small bicubic patches in one frame (one `map2f` and one 8 × 8 `eval_mesh2` each).
fn facade_patches(runs: usize) -> f64 {
    let (count, n) = (10_000, 8);
    let mut gl = Gl::new(64, 64);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(n, 0.0, 1.0, n, 0.0, 1.0);
    let mut points = patch();
    let t = time(runs, || {
        for k in 0..count {
            points[2] = (k % 7) as f32 * 0.1;
            gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &points);
            gl.eval_mesh2(GL_FILL, 0, n, 0, n);
        }
        let frame = std::hint::black_box(gl.take_frame());
        gl.recycle_frame(frame);
    });
    f64::from(count * (n + 1) * (n + 1)) / t
}

/// Peak resident memory of the process so far (Linux `VmHWM`), in MiB.
fn peak_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

fn facade_mesh1(runs: usize) -> f64 {
    let curve: Vec<f32> = (0..11).flat_map(|i| [i as f32 * 0.1 - 0.5, (i % 3) as f32 * 0.2, 0.0]).collect();
    let n = 1_000_000;
    let mut gl = Gl::new(64, 64);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 11, &curve);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(n, 0.0, 1.0);
    let t = time(runs, || {
        gl.eval_mesh1(GL_LINE, 0, n);
        let frame = std::hint::black_box(gl.take_frame());
        gl.recycle_frame(frame);
    });
    f64::from(n + 1) / t
}

fn nurbs_untrimmed(runs: usize) -> f64 {
    let knots: Vec<f32> = (0..14).map(|i| i as f32).collect();
    let ctl: Vec<f32> = (0..100)
        .flat_map(|k| [(k / 10) as f32, (k % 10) as f32, ((k / 10 * 3 + k % 10 * 5) % 7) as f32 * 0.3])
        .collect();
    let mut gl = Gl::new(64, 64);
    let nb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    gl.glu_nurbs_property(nb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    gl.glu_nurbs_property(nb, GLU_U_STEP, 100.0);
    gl.glu_nurbs_property(nb, GLU_V_STEP, 100.0);
    let count = std::rc::Rc::new(std::cell::Cell::new(0u64));
    let c = std::rc::Rc::clone(&count);
    gl.glu_nurbs_callback(nb, GLU_NURBS_VERTEX, Some(NurbsCallback::vertex(move |_| c.set(c.get() + 1))));
    let t = time(runs, || {
        count.set(0);
        gl.glu_begin_surface(nb);
        gl.glu_nurbs_surface(nb, 14, &knots, 14, &knots, 30, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
        gl.glu_end_surface(nb);
    });
    count.get() as f64 / t
}

fn main() {
    // `bench [case ...]` runs the cases whose names start with one of the arguments (all without).
    let filters: Vec<String> = std::env::args().skip(1).collect();
    let wanted = |name: &str| filters.is_empty() || filters.iter().any(|f| name.starts_with(f.as_str()));
    // The largest case first, so that the process's peak memory is its own.
    if wanted("grid_4000") {
        let before = peak_mib();
        let rate = typed_grid(4000, 3, false);
        if let (Some(a), Some(b)) = (before, peak_mib()) {
            let output = 4001.0 * 4001.0 * (12.0 + 12.0 + 8.0) + 4000.0 * 4000.0 * 24.0;
            eprintln!(
                "grid_4000: peak memory {:.0} MiB above the {a:.0} MiB baseline; the mesh is {:.0} MiB",
                b - a,
                output / 1048576.0
            );
        }
        println!("grid_4000 {rate:.0}");
    }
    let cases: [(&str, &dyn Fn() -> f64); 9] = [
        ("eval_mesh2_100", &|| facade_mesh2(100, 9)),
        ("eval_mesh2_1000", &|| facade_mesh2(1000, 5)),
        ("eval_mesh2_4000", &|| facade_mesh2(4000, 3)),
        ("grid_100", &|| typed_grid(100, 9, false)),
        ("grid_1000", &|| typed_grid(1000, 5, false)),
        ("grid_fresh_1000", &|| typed_grid(1000, 5, true)),
        ("patches_10000", &|| facade_patches(5)),
        ("eval_mesh1_degree10", &|| facade_mesh1(5)),
        ("nurbs_untrimmed", &|| nurbs_untrimmed(5)),
    ];
    for (name, case) in cases {
        if wanted(name) {
            println!("{name} {:.0}", case());
        }
    }
}
