//! The Rust side of `bench/compare.sh`: the same workloads as `bench/anchor.c` (real Mesa and
//! GLU), timed here as medians of several runs. Prints "<case> <rate per second>".
//!
//! `cargo run --release --example bench`

use gleval::prelude::*;
use gleval::tess::{eval_grid2, Grid2, MapView};
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
        std::hint::black_box(gl.take_frame());
    });
    f64::from((n + 1) * (n + 1)) / t
}

/// The typed API: grid points, partials and unit normals of a bicubic patch.
fn typed_grid(n: usize, runs: usize) -> f64 {
    let points = patch();
    let map = MapView { dim: 3, uorder: 4, vorder: 4, points: &points };
    let params: Vec<f32> = (0..=n).map(|i| i as f32 / n as f32).collect();
    let mut grid = Grid2::default();
    let mut normals: Vec<[f32; 3]> = Vec::new();
    let t = time(runs, || {
        eval_grid2(&map, &params, &params, true, &mut grid);
        normals.clear();
        normals.extend(grid.du.iter().zip(&grid.dv).map(|(a, b)| {
            gleval::math::rational::normalize(gleval::math::rational::cross([a[0], a[1], a[2]], [b[0], b[1], b[2]]))
        }));
        std::hint::black_box(&normals);
    });
    ((n + 1) * (n + 1)) as f64 / t
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
        std::hint::black_box(gl.take_frame());
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
    println!("eval_mesh2_100 {:.0}", facade_mesh2(100, 9));
    println!("eval_mesh2_1000 {:.0}", facade_mesh2(1000, 5));
    println!("grid_100 {:.0}", typed_grid(100, 9));
    println!("grid_1000 {:.0}", typed_grid(1000, 5));
    println!("eval_mesh1_degree10 {:.0}", facade_mesh1(5));
    println!("nurbs_untrimmed {:.0}", nurbs_untrimmed(5));
}
