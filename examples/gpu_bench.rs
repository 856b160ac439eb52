//! GPU vs CPU tessellation throughput, side by side in one run (medians of several runs):
//! a bicubic patch with GL_AUTO_NORMAL over 100², 1000² and 4000² grid points, and 10,000
//! small patches (4×4 control points, 9×9 grid each) in one frame, and a GLU NURBS surface
//! (bicubic, 10 × 10 control points: 49 Bezier patches) drawn with `GLU_PATH_LENGTH` at a fixed
//! `GLU_SAMPLING_TOLERANCE` of 2 pixels, the whole surface in a 1000 × 1000 viewport, which GLU samples into one
//! `glEvalMesh2` per patch.
//!
//! - `cpu`: the façade's CPU tessellator, `glEvalMesh2(GL_FILL)` recorded into a frame (grid
//!   points with normals, evaluated once each).
//! - `gpu`: the same calls on the GPU tessellator, then the compute dispatch that writes the
//!   vertex and index buffers the render pass would draw, waited for (no read-back: the render
//!   pass reads the buffers on the GPU). Grids larger than one storage binding are split into
//!   row bands, one dispatch each.
//!
//! `cargo run --release --example gpu_bench [CASE...]` (needs a wgpu adapter: lavapipe on machines
//! without a GPU). Prints `<case> cpu=<M points/s> gpu=<M points/s> ratio=<gpu/cpu>`, and
//! where the adapter has timestamp queries `gpu_pass=<M points/s>`: the same points over the
//! compute passes' own GPU time (median of the runs), without the recording, packing,
//! submission and wait that the wall-time `gpu` column includes. A second line per case gives
//! the same three rates as patches and triangles per second (`patches/s`, `M triangles/s`).

use gleval::gl::{Gl, MeshVertices, Tessellator};
use gleval::prelude::*;
use gleval::render::Renderer;
use gleval::testing::{Evaluator, PackedJobs, PassTimer};
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

fn patch(seed: usize) -> Vec<f32> {
    (0..16)
        .flat_map(|k| {
            let bump = ((k / 4 + k % 4 + seed) % 3) as f32 * 0.2;
            [(k / 4) as f32 / 3.0 - 0.5, (k % 4) as f32 / 3.0 - 0.5, bump]
        })
        .collect()
}

/// Records `patches` bicubic patches, each over an `n` × `n`-segment grid split into bands of
/// at most `band` rows (one glEvalMesh2 per band, as a program drawing a huge grid would).
fn record(gl: &mut Gl, patches: usize, n: i32, band: i32) {
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(n, 0.0, 1.0, n, 0.0, 1.0);
    for p in 0..patches {
        gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &patch(p));
        let mut j = 0;
        while j < n {
            let j2 = (j + band).min(n);
            gl.eval_mesh2(GL_FILL, 0, n, j, j2);
            j = j2;
        }
    }
}

/// What one case records into a frame.
#[derive(Clone, Copy)]
enum Case {
    /// `patches` bicubic patches over an `n` × `n` grid in bands of `band` rows.
    Grid { patches: usize, n: i32, band: i32 },
    /// The GLU NURBS surface at the fixed tolerance.
    Nurbs,
}

/// The GLU case's surface: bicubic, 10 × 10 control points on uniform knots 0..13 (as
/// `bench/anchor.c`'s), seen whole in a 1000 × 1000 viewport.
fn record_nurbs(gl: &mut Gl) {
    let knots: Vec<f32> = (0..14).map(|k| k as f32).collect();
    let ctl: Vec<f32> = (0..10)
        .flat_map(|i| (0..10).flat_map(move |j| [i as f32, j as f32, ((i * 3 + j * 5) % 7) as f32 * 0.3]))
        .collect();
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(-0.5, 9.5, -0.5, 9.5, -10.0, 10.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.enable(GL_AUTO_NORMAL);
    let nb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nb, GLU_SAMPLING_METHOD, GLU_PATH_LENGTH as f32);
    gl.glu_nurbs_property(nb, GLU_SAMPLING_TOLERANCE, 2.0);
    gl.glu_begin_surface(nb);
    gl.glu_nurbs_surface(nb, 14, &knots, 14, &knots, 30, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
    gl.glu_end_surface(nb);
    gl.glu_delete_nurbs_renderer(nb);
}

impl Case {
    fn record(self, gl: &mut Gl) {
        match self {
            Self::Grid { patches, n, band } => record(gl, patches, n, band),
            Self::Nurbs => record_nurbs(gl),
        }
    }
}

/// Patches, grid points and triangles of a recorded frame's meshes.
fn count(frame: &gleval::gl::Frame) -> [f64; 3] {
    frame.meshes.iter().fold([0.0; 3], |[p, v, t], m| {
        let (nu, nv) = (m.nu as f64, m.nv as f64);
        [p + 1.0, v + nu * nv, t + 2.0 * (nu - 1.0) * (nv - 1.0)]
    })
}

fn cpu_rate(case: Case, runs: usize) -> f64 {
    let mut gl = Gl::new(1000, 1000);
    gl.set_tessellator(Tessellator::Cpu);
    let t = time(runs, || {
        case.record(&mut gl);
        std::hint::black_box(gl.take_frame());
    });
    1.0 / t
}

/// Evaluates the deferred jobs of a frame, one dispatch per batch that fits the device, and
/// returns the dispatches' GPU time in seconds when `timer` can measure it.
fn gpu_evaluate(
    r: &Renderer,
    evaluator: &Evaluator,
    frame: &gleval::gl::Frame,
    timer: Option<&PassTimer>,
) -> Option<f64> {
    let mut encoder = r.device.create_command_encoder(&Default::default());
    let mut packed = PackedJobs::default();
    let mut keep = Vec::new();
    let mut passes = 0;
    let mut dispatch = |encoder: &mut wgpu::CommandEncoder, packed: &PackedJobs| {
        let writes = timer.map(|t| t.writes(passes));
        passes += 1;
        keep.push(evaluator.evaluate_timed(&r.device, &r.queue, encoder, packed, writes));
    };
    for mesh in &frame.meshes {
        let MeshVertices::Deferred(_) = &mesh.vertices else { continue };
        let extra = (mesh.nu * mesh.nv) as u64;
        if !packed.jobs.is_empty() && !Evaluator::fits(&r.device, u64::from(packed.vertices) + extra, 0) {
            dispatch(&mut encoder, &packed);
            packed = PackedJobs::default();
        }
        packed.push_mesh(mesh).expect("valid mesh");
    }
    dispatch(&mut encoder, &packed);
    let gpu_time = match timer {
        Some(timer) => Some(timer.read(&r.device, &r.queue, encoder, passes).expect("timestamps read back")),
        None => {
            let submission = r.queue.submit([encoder.finish()]);
            r.device
                .poll(wgpu::PollType::Wait { submission_index: Some(submission), timeout: None })
                .expect("GPU finishes");
            None
        }
    };
    if let Err(e) = r.take_error() {
        panic!("{e}");
    }
    drop(keep);
    gpu_time
}

/// Frames per second by wall time, and by the compute passes' GPU time where measured.
fn gpu_rate(r: &Renderer, evaluator: &Evaluator, case: Case, runs: usize) -> (f64, Option<f64>) {
    let mut gl = Gl::new(1000, 1000);
    gl.set_tessellator(Tessellator::Gpu);
    let timer = PassTimer::new(&r.device, &r.queue, 64);
    // One untimed run compiles the pipeline.
    record(&mut gl, 1, 2, 2);
    gpu_evaluate(r, evaluator, &gl.take_frame(), timer.as_ref());
    let mut gpu_times = Vec::new();
    let t = time(runs, || {
        case.record(&mut gl);
        gpu_times.extend(gpu_evaluate(r, evaluator, &gl.take_frame(), timer.as_ref()));
    });
    (1.0 / t, (!gpu_times.is_empty()).then(|| 1.0 / median(gpu_times)))
}

/// What one frame of `case` holds: [patches, grid points, triangles] (a grid case's bands
/// are meshes of one patch).
fn frame_size(case: Case) -> [f64; 3] {
    let mut gl = Gl::new(1000, 1000);
    gl.set_tessellator(Tessellator::Gpu);
    case.record(&mut gl);
    let [meshes, points, triangles] = count(&gl.take_frame());
    match case {
        Case::Grid { patches, .. } => [patches as f64, points, triangles],
        Case::Nurbs => [meshes, points, triangles],
    }
}

fn main() {
    let renderer = match Renderer::new() {
        Ok(r) => r,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let evaluator = Evaluator::new(&renderer.device);
    let limit = renderer.device.limits().max_storage_buffer_binding_size;
    println!("# adapter {}; storage binding limit {} MiB", renderer.adapter_name(), limit >> 20);
    // Rows per band so that one band's vertices (64 bytes each) fit one binding.
    let band_for = |n: i32| ((limit / 64) / (n as u64 + 1) - 1).clamp(1, n as u64) as i32;
    if std::env::args().any(|a| a == "--overhead") {
        let (frames, _) = gpu_rate(&renderer, &evaluator, Case::Grid { patches: 1, n: 1, band: 1 }, 30);
        println!("4-point frame: {:.3} ms", 1e3 / frames);
        return;
    }
    let grid = |patches, n| Case::Grid { patches, n, band: band_for(n) };
    let cases = [
        ("grid_100x100", grid(1, 99), 30),
        ("grid_1000x1000", grid(1, 999), 7),
        ("grid_4000x4000", grid(1, 3999), 3),
        ("patches_10000_9x9", grid(10_000, 8), 5),
        ("glu_nurbs_path_length_2px", Case::Nurbs, 7),
    ];
    // `gpu_bench [NAME...]`: only the cases whose names start with one of NAME.
    let only: Vec<String> = std::env::args().skip(1).filter(|a| !a.starts_with("--")).collect();
    for (name, case, runs) in cases {
        if !only.is_empty() && !only.iter().any(|o| name.starts_with(o.as_str())) {
            continue;
        }
        let [patches, points, triangles] = frame_size(case);
        eprintln!("# {name}: {patches} patches, {points} grid points, {triangles} triangles a frame");
        let cpu = cpu_rate(case, runs);
        let (gpu, pass) = gpu_rate(&renderer, &evaluator, case, runs);
        let rate = |per_frame: f64, f: f64, scale: f64| format!("{:.2}", per_frame * f / scale);
        let pass_points = pass.map_or_else(|| "- (no timestamp queries)".to_owned(), |p| rate(points, p, 1e6));
        println!(
            "{name} cpu={} gpu={} ratio={:.2} gpu_pass={pass_points}",
            rate(points, cpu, 1e6),
            rate(points, gpu, 1e6),
            gpu / cpu
        );
        let pass_tri = pass.map_or_else(|| "-".to_owned(), |p| rate(triangles, p, 1e6));
        let pass_patch = pass.map_or_else(|| "-".to_owned(), |p| rate(patches, p, 1.0));
        println!(
            "  {patches} patches, {triangles} triangles a frame: patches/s cpu={} gpu={} gpu_pass={pass_patch}; M triangles/s cpu={} gpu={} gpu_pass={pass_tri}",
            rate(patches, cpu, 1.0),
            rate(patches, gpu, 1.0),
            rate(triangles, cpu, 1e6),
            rate(triangles, gpu, 1e6)
        );
    }
}
