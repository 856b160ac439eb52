//! The benchmark workloads, shared by `examples/bench.rs` (the Rust side of `bench/compare.sh`,
//! against the same workloads in `bench/anchor.c` on real Mesa and GLU) and the criterion
//! benchmarks in `benches/`. Each workload is set up once and then run repeatedly, as a render
//! loop would: frames are given back with `recycle_frame`, meshes re-tessellated in place.

use gleval::math::BezierPatch;
use gleval::prelude::*;
use gleval::tess::Mesh;
use std::cell::Cell;
use std::rc::Rc;

/// One prepared workload: `run` does one repetition producing `items` grid points or vertices.
pub struct Workload {
    /// Grid points (or callback vertices) per repetition.
    pub items: f64,
    /// One repetition.
    pub run: Box<dyn FnMut()>,
}

/// A case's set-up.
pub type Setup = fn() -> Workload;

/// Every case: its name (as `bench/anchor.c` prints it) and its set-up.
pub fn cases() -> Vec<(&'static str, Setup)> {
    vec![
        ("eval_mesh2_100", || facade_mesh2(100)),
        ("eval_mesh2_1000", || facade_mesh2(1000)),
        ("eval_mesh2_4000", || facade_mesh2(4000)),
        ("grid_100", || typed_grid(100, false)),
        ("grid_1000", || typed_grid(1000, false)),
        ("grid_4000", || typed_grid(4000, false)),
        ("grid_fresh_1000", || typed_grid(1000, true)),
        ("grid_normals_1000", || typed_points_and_normals(1000)),
        ("patches_10000", facade_patches),
        ("eval_mesh1_degree10", facade_mesh1),
        ("eval_coord_curves", eval_coord_curves),
        ("first_eval_mesh2_1000", first_mesh2),
        ("nurbs_untrimmed", nurbs_untrimmed),
        ("nurbs_trimmed", nurbs_trimmed),
        ("callback_floor", callback_floor),
    ]
}

/// The bicubic test patch of `bench/anchor.c`.
fn patch() -> Vec<f32> {
    (0..16)
        .flat_map(|k| [(k / 4) as f32 / 3.0 - 0.5, (k % 4) as f32 / 3.0 - 0.5, ((k / 4 + k % 4) % 3) as f32 * 0.2])
        .collect()
}

/// Takes the frame `gl` recorded and gives it back for reuse.
fn finish_frame(gl: &mut Gl) {
    let frame = std::hint::black_box(gl.take_frame());
    gl.recycle_frame(frame);
}

/// The façade: `glEvalMesh2(GL_FILL)` with `GL_AUTO_NORMAL` over an n × n grid, recorded.
fn facade_mesh2(n: i32) -> Workload {
    let mut gl = Gl::new(64, 64);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &patch());
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(n, 0.0, 1.0, n, 0.0, 1.0);
    let run = move || {
        gl.eval_mesh2(GL_FILL, 0, n, 0, n);
        finish_frame(&mut gl);
    };
    Workload { items: f64::from((n + 1) * (n + 1)), run: Box::new(run) }
}

/// The typed API: the bicubic patch tessellated into a mesh (positions, unit normals, texture
/// coordinates, triangle indices) over an n × n grid, in place (`fresh`: a new mesh each time,
/// as `tessellate` returns).
fn typed_grid(n: usize, fresh: bool) -> Workload {
    let patch = BezierPatch::try_new(3, 4, 4, patch()).expect("a bicubic patch");
    let params: Vec<f32> = (0..=n).map(|i| i as f32 / n as f32).collect();
    let mut mesh = Mesh::default();
    let run = move || {
        if fresh {
            mesh = patch.tessellate(n, n).expect("mesh");
        } else {
            patch.tessellate_grid_into(&params, &params, &mut mesh).expect("mesh");
        }
        std::hint::black_box(&mesh);
    };
    Workload { items: ((n + 1) * (n + 1)) as f64, run: Box::new(run) }
}

/// The typed API's grid evaluation alone: points and unit normals of the bicubic patch over an
/// n × n grid (no texture coordinates, no indices), in place.
fn typed_points_and_normals(n: usize) -> Workload {
    let patch = BezierPatch::try_new(3, 4, 4, patch()).expect("a bicubic patch");
    let params: Vec<f32> = (0..=n).map(|i| i as f32 / n as f32).collect();
    let (mut positions, mut normals) = (Vec::new(), Vec::new());
    let run = move || {
        patch.grid_with_normals_into(&params, &params, &mut positions, &mut normals).expect("grid");
        std::hint::black_box((&positions, &normals));
    };
    Workload { items: ((n + 1) * (n + 1)) as f64, run: Box::new(run) }
}

/// 10,000 small bicubic patches in one frame (one `map2f` and one 8 × 8 `eval_mesh2` each).
fn facade_patches() -> Workload {
    let (count, n) = (10_000, 8);
    let mut gl = Gl::new(64, 64);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(n, 0.0, 1.0, n, 0.0, 1.0);
    let mut points = patch();
    let run = move || {
        for k in 0..count {
            points[2] = (k % 7) as f32 * 0.1;
            gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &points);
            gl.eval_mesh2(GL_FILL, 0, n, 0, n);
        }
        finish_frame(&mut gl);
    };
    Workload { items: f64::from(count * (n + 1) * (n + 1)), run: Box::new(run) }
}

/// 10,000 curves as the textbook's B-spline programs draw their Bezier pieces: a `map1f` of 4
/// points, then `begin(GL_LINE_STRIP)`, 31 `eval_coord1f`, `end`.
fn eval_coord_curves() -> Workload {
    let (count, n) = (10_000, 30);
    let mut ctl = [-0.5, 0.0, 0.0, -0.2, 0.4, 0.0, 0.2, -0.4, 0.0, 0.5, 0.0, 0.0];
    let mut gl = Gl::new(64, 64);
    gl.enable(GL_MAP1_VERTEX_3);
    let run = move || {
        for k in 0..count {
            ctl[1] = (k % 5) as f32 * 0.1;
            gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &ctl);
            gl.begin(GL_LINE_STRIP);
            for i in 0..=n {
                gl.eval_coord1f(i as f32 / n as f32);
            }
            gl.end();
        }
        finish_frame(&mut gl);
    };
    Workload { items: f64::from(count * (n + 1)), run: Box::new(run) }
}

/// The first `eval_mesh2` of a fresh context: 1000², `GL_AUTO_NORMAL`, nothing warm (the
/// context, its map and its frame are new each time; all of it is timed).
fn first_mesh2() -> Workload {
    let n = 1000;
    let points = patch();
    let run = move || {
        let mut gl = Gl::new(64, 64);
        gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &points);
        gl.enable(GL_MAP2_VERTEX_3);
        gl.enable(GL_AUTO_NORMAL);
        gl.map_grid2f(n, 0.0, 1.0, n, 0.0, 1.0);
        gl.eval_mesh2(GL_FILL, 0, n, 0, n);
        std::hint::black_box(gl.frame());
    };
    Workload { items: f64::from((n + 1) * (n + 1)), run: Box::new(run) }
}

/// `glEvalMesh1(GL_LINE)` of a degree-10 curve at 10⁶ + 1 points.
fn facade_mesh1() -> Workload {
    let curve: Vec<f32> = (0..11).flat_map(|i| [i as f32 * 0.1 - 0.5, (i % 3) as f32 * 0.2, 0.0]).collect();
    let n = 1_000_000;
    let mut gl = Gl::new(64, 64);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 11, &curve);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(n, 0.0, 1.0);
    let run = move || {
        gl.eval_mesh1(GL_LINE, 0, n);
        finish_frame(&mut gl);
    };
    Workload { items: f64::from(n + 1), run: Box::new(run) }
}

/// GLU's tessellator mode on an untrimmed bicubic NURBS (10 × 10 control points) at domain
/// steps of 100 per unit; `items` is the vertex count of the first repetition.
fn nurbs_untrimmed() -> Workload {
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
    let count = Rc::new(Cell::new(0u64));
    let c = Rc::clone(&count);
    gl.glu_nurbs_callback(nb, GLU_NURBS_VERTEX, Some(NurbsCallback::vertex(move |_, _| c.set(c.get() + 1))));
    let mut run = move || {
        gl.glu_begin_surface(nb);
        gl.glu_nurbs_surface(nb, 14, &knots, 14, &knots, 30, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
        gl.glu_end_surface(nb);
    };
    run();
    Workload { items: count.get() as f64, run: Box::new(run) }
}

/// GLU's tessellator mode on the trimmed "hills" surface of `bench/anchor.c` (the red book's
/// trim.c) at domain steps of 300; `items` is the vertex count of the first repetition.
fn nurbs_trimmed() -> Workload {
    let hills: Vec<f32> = (0..16)
        .flat_map(|k| {
            let (u, v) = (k / 4, k % 4);
            let z = if (u == 1 || u == 2) && (v == 1 || v == 2) { 3.0 } else { -3.0 };
            [2.0 * (u as f32 - 1.5), 2.0 * (v as f32 - 1.5), z]
        })
        .collect();
    let knots = [0.0f32, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let edge = [0.0f32, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0];
    let curve = [0.25f32, 0.5, 0.25, 0.75, 0.75, 0.75, 0.75, 0.5];
    let pwl = [0.75f32, 0.5, 0.5, 0.25, 0.25, 0.5];
    let tri = [0.1f32, 0.1, 0.2, 0.3, 0.3, 0.1, 0.1, 0.1];
    let mut gl = Gl::new(64, 64);
    let nb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    gl.glu_nurbs_property(nb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    gl.glu_nurbs_property(nb, GLU_U_STEP, 300.0);
    gl.glu_nurbs_property(nb, GLU_V_STEP, 300.0);
    let count = Rc::new(Cell::new(0u64));
    let c = Rc::clone(&count);
    gl.glu_nurbs_callback(nb, GLU_NURBS_VERTEX, Some(NurbsCallback::vertex(move |_, _| c.set(c.get() + 1))));
    let mut run = move || {
        gl.glu_begin_surface(nb);
        gl.glu_nurbs_surface(nb, 8, &knots, 8, &knots, 12, 3, &hills, 4, 4, GL_MAP2_VERTEX_3);
        gl.glu_begin_trim(nb);
        gl.glu_pwl_curve(nb, 5, &edge, 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(nb);
        gl.glu_begin_trim(nb);
        gl.glu_nurbs_curve(nb, 8, &knots, 2, &curve, 4, GLU_MAP1_TRIM_2);
        gl.glu_pwl_curve(nb, 3, &pwl, 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(nb);
        gl.glu_begin_trim(nb);
        gl.glu_pwl_curve(nb, 4, &tri, 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(nb);
        gl.glu_end_surface(nb);
    };
    run();
    Workload { items: count.get() as f64, run: Box::new(run) }
}

/// A vertex callback as GLU's tessellator mode takes it.
type VertexFn = Box<dyn FnMut(&[f32])>;

/// The floor under `nurbs_untrimmed`: the same number of vertex callbacks (a boxed closure
/// called with 5 floats, in the quad strips' order over 49 grids of 101 × 101 points) with no
/// evaluation, tessellation or GLU at all: what the caller's thread cannot avoid.
fn callback_floor() -> Workload {
    let (pieces, n) = (49, 100);
    let grid: Vec<[f32; 5]> = (0..(n + 1) * (n + 1)).map(|k| [k as f32; 5]).collect();
    let count = Rc::new(Cell::new(0u64));
    let c = Rc::clone(&count);
    let mut vertex: VertexFn = Box::new(move |_| c.set(c.get() + 1));
    let run = move || {
        let vertex = std::hint::black_box(&mut vertex);
        for _ in 0..pieces {
            for i in 0..n {
                for j in (0..=n).rev() {
                    vertex(&grid[j * (n + 1) + i]);
                    vertex(&grid[j * (n + 1) + i + 1]);
                }
            }
        }
    };
    Workload { items: (pieces * n * (n + 1) * 2) as f64, run: Box::new(run) }
}
