//! GPU vs CPU tessellation throughput, side by side in one run (medians of several runs):
//! a bicubic patch with GL_AUTO_NORMAL over 100², 1000² and 4000² grid points, and 10,000
//! small patches (4×4 control points, 9×9 grid each) in one frame.
//!
//! - `cpu`: the façade's CPU tessellator, `glEvalMesh2(GL_FILL)` recorded into a frame (grid
//!   points with normals, evaluated once each).
//! - `gpu`: the same calls on the GPU tessellator, then the compute dispatch that writes the
//!   vertex and index buffers the render pass would draw, waited for (no read-back: the render
//!   pass reads the buffers on the GPU). Grids larger than one storage binding are split into
//!   row bands, one dispatch each.
//!
//! `cargo run --release --example gpu_bench` (needs a wgpu adapter: lavapipe on machines
//! without a GPU). Prints `<case> cpu=<M points/s> gpu=<M points/s> ratio=<gpu/cpu>`, and
//! where the adapter has timestamp queries `gpu_pass=<M points/s>`: the same points over the
//! compute passes' own GPU time (median of the runs), without the recording, packing,
//! submission and wait that the wall-time `gpu` column includes.

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

fn cpu_rate(patches: usize, n: i32, band: i32, runs: usize) -> f64 {
    let mut gl = Gl::new(64, 64);
    gl.set_tessellator(Tessellator::Cpu);
    let t = time(runs, || {
        record(&mut gl, patches, n, band);
        std::hint::black_box(gl.take_frame());
    });
    (patches as f64) * f64::from((n + 1) * (n + 1)) / t
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

/// Points per second by wall time, and by the compute passes' GPU time where measured.
fn gpu_rate(r: &Renderer, evaluator: &Evaluator, patches: usize, n: i32, band: i32, runs: usize) -> (f64, Option<f64>) {
    let mut gl = Gl::new(64, 64);
    gl.set_tessellator(Tessellator::Gpu);
    let timer = PassTimer::new(&r.device, &r.queue, 64);
    // One untimed run compiles the pipeline.
    record(&mut gl, 1, 2, 2);
    gpu_evaluate(r, evaluator, &gl.take_frame(), timer.as_ref());
    let mut gpu_times = Vec::new();
    let t = time(runs, || {
        record(&mut gl, patches, n, band);
        gpu_times.extend(gpu_evaluate(r, evaluator, &gl.take_frame(), timer.as_ref()));
    });
    let points = (patches as f64) * f64::from((n + 1) * (n + 1));
    (points / t, (!gpu_times.is_empty()).then(|| points / median(gpu_times)))
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
        let (gpu, _) = gpu_rate(&renderer, &evaluator, 1, 1, 1, 30);
        println!("4-point frame: {:.3} ms", 4.0 / gpu * 1e3);
        return;
    }
    let cases: [(&str, usize, i32, usize); 4] = [
        ("grid_100x100", 1, 99, 30),
        ("grid_1000x1000", 1, 999, 7),
        ("grid_4000x4000", 1, 3999, 3),
        ("patches_10000_9x9", 10_000, 8, 5),
    ];
    for (name, patches, n, runs) in cases {
        let band = band_for(n);
        let cpu = cpu_rate(patches, n, band, runs);
        let (gpu, pass) = gpu_rate(&renderer, &evaluator, patches, n, band, runs);
        let pass =
            pass.map_or_else(|| "gpu_pass=- (no timestamp queries)".to_owned(), |p| format!("gpu_pass={:.2}", p / 1e6));
        println!("{name} cpu={:.2} gpu={:.2} ratio={:.2} {pass}", cpu / 1e6, gpu / 1e6, gpu / cpu);
    }
}
