//! GPU vs CPU parity: the GPU evaluator (`shaders/eval_mesh.wgsl`) against the f64 CPU
//! evaluation of the same packed patches, for every order GL allows, rational maps, reversed
//! parameter runs and a collapsed edge; then the façade's `glEvalMesh` jobs, GLU's trimmed
//! surfaces and the typed API through the same evaluator. Tolerances: positions 2e-5 relative
//! to the patch's size, normals 2e-3 (absolute, unit vectors) where the CPU normal is non-zero
//! and well conditioned; where it is zero, finite, and exactly zero on a collapsed edge.

use gleval::render::Renderer;
use gleval::testing::{eval_grid2, evaluate_job_indices, evaluate_jobs, Grid2, MapView};

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

/// A bare patch as the evaluator's job: its one vertex map over the grid `us` × `vs`, with
/// `GL_AUTO_NORMAL` (GL_MAP2_VERTEX_3, or _4 for a rational patch).
fn patch_job(k: usize, uorder: usize, vorder: usize, points: &[f32], us: &[f32], vs: &[f32]) -> (MeshJob, MeshMode) {
    let slot = if k == 4 { Slot::Vertex4 } else { Slot::Vertex3 };
    let map = MapSample { slot, uorder, vorder, points: points.to_vec(), us: us.to_vec(), vs: vs.to_vec() };
    let job = MeshJob {
        maps: vec![map],
        auto_normal: true,
        template: gleval::gl::Vertex::default(),
        nu: us.len(),
        nv: vs.len(),
        scattered: false,
    };
    (job, MeshMode::Fill)
}

#[test]
fn gpu_grid_matches_cpu_for_all_orders_rational_reversed_and_degenerate() {
    let Some(r) = device() else { return };
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
    let jobs: Vec<(MeshJob, MeshMode)> =
        cases.iter().map(|(_, uo, vo, k, pts, u, v)| patch_job(*k, *uo, *vo, pts, u, v)).collect();
    let out = evaluate_jobs(r.gpu(), &jobs).expect("GPU evaluation");
    let (mut offset, mut worst_p, mut worst_n) = (0, 0.0f64, 0.0f64);
    for (name, uo, vo, k, pts, u, v) in &cases {
        let want = oracle(pts, *k, *uo, *vo, u, v);
        let scale = pts.iter().fold(1.0f64, |m, &x| m.max(f64::from(x).abs()));
        for idx in 0..u.len() * v.len() {
            let (gp, gn) = (out[offset + idx][0], &out[offset + idx][1][..3]);
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

// ---------------------------------------------------------------------------------------------
// The façade on the GPU tessellator: glEvalMesh jobs recorded by a `Gl` on the GPU
// tessellator, evaluated in one dispatch, against an f64 evaluation of the same job.

use gleval::gl::{Gl, MapSample, MeshJob, MeshMode, MeshVertices, Slot, Tessellator};
use gleval::prelude::*;

/// The value GL gives attribute `slot` from the map's components `p` (spec table 5.1: missing
/// texture components are 0, 0, 1; a 3-component vertex has w = 1).
fn widen(slot: Slot, p: [f64; 4]) -> [f64; 4] {
    let k = slot.components();
    let mut out = [0.0, 0.0, 0.0, 1.0];
    out[..k].copy_from_slice(&p[..k]);
    out
}

/// f64 oracle of one job: per vertex position, normal, colour, texture coordinate; and per
/// vertex the conditioning |du × dv| of the auto normal (0 when none or degenerate).
fn oracle_job(job: &MeshJob) -> (Vec<[[f64; 4]; 4]>, Vec<f64>) {
    let t = job.template;
    let n = job.nu * job.nv;
    let f = |a: [f32; 4]| a.map(f64::from);
    let template = [[0.0, 0.0, 0.0, 1.0], f([t.normal[0], t.normal[1], t.normal[2], 0.0]), f(t.color), f(t.tex_coord)];
    let mut out = vec![template; n];
    let mut area = vec![0.0; n];
    for map in &job.maps {
        let g = oracle(&map.points, map.slot.components(), map.uorder, map.vorder, &map.us, &map.vs);
        for idx in 0..n {
            let p = g.points[idx];
            match map.slot {
                Slot::Vertex3 | Slot::Vertex4 => out[idx][0] = widen(map.slot, p),
                Slot::Normal => out[idx][1] = [p[0], p[1], p[2], 0.0],
                Slot::Color4 => out[idx][2] = p,
                Slot::Index => {}
                _ => out[idx][3] = widen(map.slot, p),
            }
            if job.auto_normal && matches!(map.slot, Slot::Vertex3 | Slot::Vertex4) {
                let (nrm, a) = normal64(map.slot.components(), p, g.du[idx], g.dv[idx]);
                out[idx][1] = [nrm[0], nrm[1], nrm[2], 0.0];
                area[idx] = if map.slot == Slot::Vertex4 { a / (p[3] * p[3]) } else { a };
            }
        }
    }
    (out, area)
}

/// A context on the GPU tessellator with `setup` run, its deferred jobs collected.
fn jobs_of(setup: impl FnOnce(&mut Gl)) -> Vec<(MeshJob, MeshMode)> {
    let mut gl = Gl::new(64, 64);
    gl.set_tessellator(Tessellator::Gpu);
    setup(&mut gl);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let frame = gl.take_frame();
    frame
        .meshes
        .into_iter()
        .map(|m| match m.vertices {
            MeshVertices::Deferred(mut jobs) => (jobs.remove(0), m.mode),
            MeshVertices::Evaluated(_) => panic!("mesh evaluated on the CPU under the GPU tessellator"),
        })
        .collect()
}

fn surface(gl: &mut Gl, target: GLenum, k: usize, (uo, vo): (usize, usize), dom: [f32; 4], seed: usize) {
    let pts = net(uo, vo, k, seed);
    gl.map2f(target, dom[0], dom[1], (vo * k) as i32, uo as i32, dom[2], dom[3], k as i32, vo as i32, &pts);
    gl.enable(target);
}

#[test]
fn facade_gpu_meshes_match_the_f64_oracle() {
    let Some(r) = device() else { return };
    let mut jobs = Vec::new();
    // Every order GL allows, vertex map with AUTO_NORMAL, FILL over a partial grid range.
    for order in 1..=30 {
        jobs.extend(jobs_of(|gl| {
            surface(gl, GL_MAP2_VERTEX_3, 3, (order, order), [0.0, 1.0, 0.0, 1.0], order);
            gl.enable(GL_AUTO_NORMAL);
            gl.map_grid2f(10, 0.0, 1.0, 8, 0.0, 1.0);
            gl.eval_mesh2(GL_FILL, 1, 10, 0, 7);
        }));
    }
    // Rational maps, reversed map domains and a reversed grid, every attribute map.
    jobs.extend(jobs_of(|gl| {
        surface(gl, GL_MAP2_VERTEX_4, 4, (4, 3), [2.0, -1.0, 0.5, 3.0], 7);
        surface(gl, GL_MAP2_COLOR_4, 4, (2, 3), [2.0, -1.0, 0.5, 3.0], 8);
        surface(gl, GL_MAP2_TEXTURE_COORD_2, 2, (3, 2), [-1.0, 2.0, 0.5, 3.0], 9);
        gl.enable(GL_AUTO_NORMAL);
        gl.map_grid2f(9, 2.0, -1.0, 6, 3.0, 0.5);
        gl.eval_mesh2(GL_FILL, 0, 9, 0, 6);
        gl.eval_mesh2(GL_LINE, 2, 7, 1, 5);
        gl.eval_mesh2(GL_POINT, 0, 3, 0, 6);
    }));
    // A normal map without AUTO_NORMAL, and the current attributes where no map is enabled.
    jobs.extend(jobs_of(|gl| {
        surface(gl, GL_MAP2_VERTEX_3, 3, (5, 4), [0.0, 1.0, 0.0, 1.0], 3);
        surface(gl, GL_MAP2_NORMAL, 3, (3, 3), [0.0, 1.0, 0.0, 1.0], 4);
        gl.color4f(0.25, 0.5, 0.75, 1.0);
        gl.tex_coord2f(0.125, 0.375);
        gl.map_grid2f(7, 0.0, 1.0, 5, 0.0, 1.0);
        gl.eval_mesh2(GL_FILL, 0, 7, 0, 5);
    }));
    // A collapsed edge (all of u = 0 at one point): GL's normal there is zero, never NaN.
    let collapsed_job = jobs.len();
    jobs.extend(jobs_of(|gl| {
        let mut pts = net(4, 4, 3, 5);
        for j in 1..4 {
            for c in 0..3 {
                pts[j * 3 + c] = pts[c];
            }
        }
        gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &pts);
        gl.enable(GL_MAP2_VERTEX_3);
        gl.enable(GL_AUTO_NORMAL);
        gl.map_grid2f(6, 0.0, 1.0, 6, 0.0, 1.0);
        gl.eval_mesh2(GL_FILL, 0, 6, 0, 6);
    }));
    // Curves: glEvalMesh1 with a colour map, lines and points, a reversed domain.
    jobs.extend(jobs_of(|gl| {
        let pts = net(7, 1, 3, 2);
        gl.map1f(GL_MAP1_VERTEX_3, 1.0, -2.0, 3, 7, &pts);
        gl.enable(GL_MAP1_VERTEX_3);
        let col = net(3, 1, 4, 6);
        gl.map1f(GL_MAP1_COLOR_4, 1.0, -2.0, 4, 3, &col);
        gl.enable(GL_MAP1_COLOR_4);
        gl.map_grid1f(20, 1.0, -2.0);
        gl.eval_mesh1(GL_LINE, 0, 20);
        gl.eval_mesh1(GL_POINT, 3, 17);
    }));
    let got = evaluate_jobs(r.gpu(), &jobs).expect("GPU evaluation");
    let (mut offset, mut worst_p, mut worst_n, mut worst_a, mut zero_normals) = (0, 0.0f64, 0.0f64, 0.0f64, 0);
    for (case, (job, _)) in jobs.iter().enumerate() {
        let (want, area) = oracle_job(job);
        let scale = job.maps.iter().flat_map(|m| &m.points).fold(1.0f64, |m, &x| m.max(f64::from(x).abs()));
        for (idx, w) in want.iter().enumerate() {
            let g = got[offset + idx];
            for c in 0..4 {
                let e = (f64::from(g[0][c]) - w[0][c]).abs() / scale;
                worst_p = worst_p.max(e);
                assert!(e < 2e-5, "job {case} vertex {idx}.{c}: gpu {:?} oracle {:?}", g[0], w[0]);
                for attr in [2, 3] {
                    let e = (f64::from(g[attr][c]) - w[attr][c]).abs() / scale;
                    worst_a = worst_a.max(e);
                    assert!(e < 2e-5, "job {case} attribute {attr} at {idx}: gpu {:?} oracle {:?}", g[attr], w[attr]);
                }
            }
            assert!(g[1].iter().all(|c| c.is_finite()), "job {case}: NaN normal at {idx}");
            if job.auto_normal && w[1] == [0.0; 4] {
                // Exactly degenerate in f64: on the collapsed edge the control-point differences
                // are exactly zero in f32 too, so the GPU must give GL's zero; elsewhere (a net
                // that happens to be flat in f64) f32 rounding may leave a tiny cross product.
                if case == collapsed_job {
                    assert_eq!(g[1], [0.0; 4], "job {case}: GL's zero normal at {idx}");
                    zero_normals += 1;
                }
                continue;
            }
            // Auto normals count where well conditioned (see the patch test above); evaluated
            // normal maps and current normals always.
            if !job.auto_normal || area[idx] > 1e-2 * scale * scale {
                let e = (0..3).map(|c| (f64::from(g[1][c]) - w[1][c]).abs()).fold(0.0, f64::max);
                let tol = if job.auto_normal { 2e-3 } else { 2e-5 * scale };
                worst_n = worst_n.max(e);
                assert!(e < tol, "job {case}: normal at {idx}: gpu {:?} oracle {:?}", g[1], w[1]);
            }
        }
        offset += job.nu * job.nv;
    }
    assert!(zero_normals >= 7, "the collapsed edge was exercised ({zero_normals} zero normals)");
    println!(
        "façade GPU vs f64: {} jobs, worst position {worst_p:.2e}, attributes {worst_a:.2e}, normal {worst_n:.2e} \
         (relative to the net's size; normals absolute); {zero_normals} zero normals",
        jobs.len()
    );
}

/// The GPU's index buffer draws GL's primitives: for GL_FILL exactly the triangles of Mesa's
/// strips with their orientation and provoking vertex (rotated to come first), for GL_LINE the
/// segments of the row and column strips.
#[test]
fn facade_gpu_indices_are_gls_primitives() {
    let Some(r) = device() else { return };
    let jobs = jobs_of(|gl| {
        surface(gl, GL_MAP2_VERTEX_3, 3, (3, 3), [0.0, 1.0, 0.0, 1.0], 1);
        gl.map_grid2f(5, 0.0, 1.0, 4, 0.0, 1.0);
        gl.eval_mesh2(GL_FILL, 0, 5, 1, 4);
        gl.eval_mesh2(GL_LINE, 1, 5, 0, 3);
        let pts = net(3, 1, 3, 2);
        gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 3, &pts);
        gl.enable(GL_MAP1_VERTEX_3);
        gl.map_grid1f(6, 0.0, 1.0);
        gl.eval_mesh1(GL_LINE, 0, 6);
    });
    let got = evaluate_job_indices(r.gpu(), &jobs).expect("GPU indices");
    let last = r.provoking_vertex_is_last();
    let (mut vertex_base, mut cursor) = (0u32, 0usize);
    for (job, mode) in &jobs {
        let mesh = gleval::gl::GridMesh {
            mode: *mode,
            nu: job.nu,
            nv: job.nv,
            state: 0,
            vertices: MeshVertices::Evaluated(Default::default()),
            triangles: Vec::new(),
            unit_tex_coords: [[0.0, 0.0, 0.0, 1.0]; 7],
        };
        // Expected primitives from the CPU path's GL order (checked against Mesa elsewhere).
        let mut want: Vec<Vec<u32>> = Vec::new();
        for (prim, idx) in mesh.primitives() {
            let at = |k: usize| vertex_base + idx[k] as u32;
            match prim {
                GL_TRIANGLE_STRIP => {
                    for t in 0..idx.len().saturating_sub(2) {
                        // GL: (t, t+1, t+2), odd triangles (t+1, t, t+2); the provoking t+2
                        // first unless the backend's flat shading takes the last vertex.
                        let gl_order = if t % 2 == 0 { [t, t + 1, t + 2] } else { [t + 1, t, t + 2] };
                        let [p, q, r] = gl_order.map(at);
                        want.push(if last { vec![p, q, r] } else { vec![r, p, q] });
                    }
                }
                GL_LINE_STRIP => {
                    for s in 1..idx.len() {
                        want.push(if last { vec![at(s - 1), at(s)] } else { vec![at(s), at(s - 1)] });
                    }
                }
                other => panic!("unexpected primitive {other:#x}"),
            }
        }
        let per = if *mode == MeshMode::Fill { 3 } else { 2 };
        let count = want.len() * per;
        let mut have: Vec<Vec<u32>> = got[cursor..cursor + count].chunks(per).map(<[u32]>::to_vec).collect();
        have.sort();
        want.sort();
        assert_eq!(have, want, "{mode:?}");
        cursor += count;
        vertex_base += (job.nu * job.nv) as u32;
    }
    assert_eq!(cursor, got.len());
}

/// Hundreds of small NURBS patches in one frame are one dispatch: the job list the renderer
/// packs holds them all, and the pictures agree with the CPU tessellator's (conformance).
#[test]
fn many_patches_make_one_batch() {
    let jobs = jobs_of(|gl| {
        gl.enable(GL_AUTO_NORMAL);
        for p in 0..300 {
            surface(gl, GL_MAP2_VERTEX_3, 3, (4, 4), [0.0, 1.0, 0.0, 1.0], p);
            gl.map_grid2f(4, 0.0, 1.0, 4, 0.0, 1.0);
            gl.eval_mesh2(GL_FILL, 0, 4, 0, 4);
        }
    });
    let mut packed = gleval::testing::PackedJobs::default();
    for (job, mode) in &jobs {
        packed.push(job, *mode).expect("packs");
    }
    assert_eq!(packed.jobs.len(), 300);
    assert_eq!(packed.vertices, 300 * 25);
    assert_eq!(packed.indices, 300 * 16 * 6);
    // Prefix sums: each job starts where the previous one ends.
    for w in packed.jobs.windows(2) {
        assert_eq!(w[1].out_offset, w[0].out_offset + 25);
        assert_eq!(w[1].index_offset, w[0].index_offset + 96);
    }
}

/// A rational bicubic NURBS of 6 × 6 points (3 × 3 Bezier pieces) with a square hole, drawn
/// through GLU on the given tessellator.
fn trimmed_nurbs(tessellator: Tessellator) -> Gl {
    let mut gl = Gl::new(64, 64);
    gl.set_tessellator(tessellator);
    gl.enable(GL_AUTO_NORMAL);
    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    gl.glu_nurbs_property(nurb, GLU_U_STEP, 5.0);
    gl.glu_nurbs_property(nurb, GLU_V_STEP, 4.0);
    let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0, 3.0];
    let mut ctl = Vec::new();
    for u in 0..6 {
        for v in 0..6 {
            let w = 1.0 + 0.25 * ((u * 7 + v * 3) % 4) as f32;
            let z = ((u * 5 + v * 11) % 7) as f32 * 0.2 - 0.6;
            ctl.extend_from_slice(&[u as f32 * 0.4 * w, v as f32 * 0.4 * w, z * w, w]);
        }
    }
    let outer: [f32; 10] = [0.0, 0.0, 3.0, 0.0, 3.0, 3.0, 0.0, 3.0, 0.0, 0.0];
    let hole: [f32; 10] = [1.2, 1.1, 1.2, 1.9, 1.8, 1.9, 1.8, 1.1, 1.2, 1.1];
    gl.glu_begin_surface(nurb);
    gl.glu_nurbs_surface(nurb, 10, &knots, 10, &knots, 24, 4, &ctl, 4, 4, GL_MAP2_VERTEX_4);
    gl.glu_begin_trim(nurb);
    gl.glu_pwl_curve(nurb, 5, &outer, 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(nurb);
    gl.glu_begin_trim(nurb);
    gl.glu_pwl_curve(nurb, 5, &hole, 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(nurb);
    gl.glu_end_surface(nurb);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    gl
}

/// GLU's trimmed surfaces on the GPU tessellator: GLU draws the blocks of its grid inside the
/// trimmed regions with `glEvalMesh2` (and the fans along the trims with `glEvalCoord2f`), so
/// the blocks become GPU jobs; every vertex the GPU evaluates is one of the CPU tessellator's
/// mesh-strip vertices and every one of those is evaluated (positions within 2e-5 of the net's
/// size, normals within 2e-3).
#[test]
fn trimmed_surface_grid_blocks_on_the_gpu_match_the_cpu() {
    let Some(r) = device() else { return };
    let cpu = trimmed_nurbs(Tessellator::Cpu).frame().expanded();
    let cpu_mesh: Vec<gleval::gl::Vertex> =
        cpu.iter().filter(|(p, _)| p.mode == GL_TRIANGLE_STRIP).flat_map(|(_, v)| v.iter().copied()).collect();
    assert!(!cpu_mesh.is_empty(), "GLU's grid blocks inside the trimmed regions");
    let mut gpu_gl = trimmed_nurbs(Tessellator::Gpu);
    let pairs: Vec<(MeshJob, MeshMode)> = gpu_gl
        .frame()
        .meshes
        .iter()
        .filter_map(|m| match &m.vertices {
            MeshVertices::Deferred(jobs) => Some(jobs.iter().map(|j| (j.clone(), m.mode)).collect::<Vec<_>>()),
            _ => None,
        })
        .flatten()
        .collect();
    assert!(!pairs.is_empty(), "the grid blocks go to the GPU");
    let got = evaluate_jobs(r.gpu(), &pairs).expect("GPU evaluation");
    let scale = pairs.iter().flat_map(|(j, _)| &j.maps).flat_map(|m| &m.points).fold(1.0f32, |m, &x| m.max(x.abs()));
    let distance = |g: &[f32; 4], c: &[f32; 4]| (0..4).map(|k| (g[k] - c[k]).abs()).fold(0.0, f32::max) / scale;
    let mut worst_n = 0.0f32;
    for g in &got {
        let c = cpu_mesh.iter().min_by(|a, b| distance(&g[0], &a.position).total_cmp(&distance(&g[0], &b.position)));
        let c = c.expect("CPU vertices");
        assert!(distance(&g[0], &c.position) < 2e-5, "gpu {:?} has no CPU twin", g[0]);
        let e = (0..3).map(|k| (g[1][k] - c.normal[k]).abs()).fold(0.0, f32::max);
        worst_n = worst_n.max(e);
        assert!(e < 2e-3, "normal: gpu {:?} cpu {:?}", g[1], c.normal);
    }
    for c in &cpu_mesh {
        assert!(got.iter().any(|g| distance(&g[0], &c.position) < 2e-5), "cpu {:?} not on the GPU", c.position);
    }
    println!("trimmed on the GPU: {} jobs, {} vertices, worst normal {worst_n:.2e}", pairs.len(), got.len());
}

/// The typed API's two back ends agree: `BezierPatch::tessellate` (CPU, f64) and
/// `render::tessellate_patches` (one dispatch for all patches): same vertices, normals and
/// texture coordinates, same triangles up to where each starts.
#[test]
fn typed_mesh_gpu_matches_cpu() {
    use gleval::math::BezierPatch;
    let Some(r) = device() else { return };
    let patches: Vec<BezierPatch<f64>> = [(4, 4, 3), (3, 5, 4), (6, 2, 3)]
        .iter()
        .enumerate()
        .map(|(s, &(uo, vo, k))| {
            BezierPatch::try_new(k, uo, vo, net(uo, vo, k, s + 2).iter().map(|&x| f64::from(x)).collect()).unwrap()
        })
        .collect();
    let gpu = gleval::render::tessellate_patches(&r, &patches, 7, 5).expect("GPU mesh");
    let mut cpu = gleval::tess::Mesh::default();
    for p in &patches {
        cpu.append(&p.tessellate(7, 5).unwrap());
    }
    assert_eq!(gpu.positions.len(), cpu.positions.len());
    assert_eq!(gpu.tex_coords, cpu.tex_coords);
    for (g, c) in gpu.positions.iter().zip(&cpu.positions) {
        assert!((0..3).all(|k| (g[k] - c[k]).abs() < 2e-5 * c[k].abs().max(1.0)), "{g:?} vs {c:?}");
    }
    for (g, c) in gpu.normals.iter().zip(&cpu.normals) {
        assert!((0..3).all(|k| (g[k] - c[k]).abs() < 2e-3), "{g:?} vs {c:?}");
    }
    // GL's strips split each cell along the other diagonal than the CPU mesh; what must agree
    // is each cell's orientation: the summed vector area of its two triangles.
    let cell_areas = |m: &gleval::tess::Mesh| {
        let mut cells = std::collections::HashMap::new();
        for t in m.indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| m.positions[i as usize].map(f64::from));
            let (e1, e2) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
            let g = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
            let key = t
                .iter()
                .map(|&i| (i / 48, (i % 48) % 8, (i % 48) / 8))
                .fold((u32::MAX, u32::MAX, u32::MAX), |k, v| (v.0, k.1.min(v.1), k.2.min(v.2)));
            let e: &mut [f64; 3] = cells.entry(key).or_insert([0.0; 3]);
            (0..3).for_each(|k| e[k] += g[k]);
        }
        cells
    };
    let (gc, cc) = (cell_areas(&gpu), cell_areas(&cpu));
    assert_eq!(gc.len(), 3 * 7 * 5);
    assert_eq!(gpu.indices.len(), cpu.indices.len());
    for (key, c) in &cc {
        let g = gc[key];
        let dot = g[0] * c[0] + g[1] * c[1] + g[2] * c[2];
        let (gl, cl) = (g.iter().map(|x| x * x).sum::<f64>().sqrt(), c.iter().map(|x| x * x).sum::<f64>().sqrt());
        if cl > 1e-6 {
            assert!(dot > 0.5 * gl * cl, "cell {key:?} faces the other way: gpu {g:?} cpu {c:?}");
        }
    }
}
