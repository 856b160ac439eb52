// Evaluates batches of Bezier patches (GL's glMap2 maps, or NURBS pieces after knot insertion)
// over parameter grids: one invocation per grid point, all patches in one dispatch. Each point
// writes its position (the map's k components, rest 0 0 0 1 as GL widens them) and the unit
// normal du x dv (with the rational correction for k = 4; zero stays zero), exactly as the CPU
// path in src/tess/grid.rs does: derivatives on control-point differences, so a collapsed edge
// gives an exactly zero derivative.

const MAX_ORDER: u32 = 30u;

struct Job {
    dim: u32,
    uorder: u32,
    vorder: u32,
    point_offset: u32,
    nu: u32,
    nv: u32,
    param_offset: u32,   // nu values of u, then nv values of v (normalised parameters)
    out_offset: u32,     // first grid point of this job in the output (prefix sum)
};

struct Meta {
    job_count: u32,
    total_points: u32,
    want_normals: u32,
    _pad: u32,
};

@group(0) @binding(0) var<storage, read> jobs: array<Job>;
@group(0) @binding(1) var<storage, read> points: array<f32>;
@group(0) @binding(2) var<storage, read> params: array<f32>;
@group(0) @binding(3) var<storage, read_write> out: array<vec4<f32>>;
@group(0) @binding(4) var<uniform> info: Meta;

// The Bernstein basis of `order` at t, by the de Casteljau triangle (stable for all t).
fn bernstein(order: u32, t: f32) -> array<f32, 30> {
    var b: array<f32, 30>;
    if (order == 0u) {
        return b;
    }
    let s = 1.0 - t;
    b[0] = 1.0;
    for (var level = 1u; level < order; level++) {
        var saved = 0.0;
        for (var i = 0u; i < level; i++) {
            let v = b[i];
            b[i] = saved + s * v;
            saved = t * v;
        }
        b[level] = saved;
    }
    return b;
}

fn control(job: Job, i: u32, j: u32) -> vec4<f32> {
    let base = job.point_offset + (i * job.vorder + j) * job.dim;
    var p = vec4<f32>(0.0, 0.0, 0.0, 0.0);
    for (var c = 0u; c < job.dim; c++) {
        p[c] = points[base + c];
    }
    return p;
}

// The job holding grid point `p`: binary search on the prefix sums.
fn find_job(p: u32) -> u32 {
    var lo = 0u;
    var hi = info.job_count;
    while (hi - lo > 1u) {
        let mid = (lo + hi) / 2u;
        if (jobs[mid].out_offset <= p) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

fn widen(p: vec4<f32>, dim: u32) -> vec4<f32> {
    var out = vec4<f32>(0.0, 0.0, 0.0, 1.0);
    for (var c = 0u; c < dim; c++) {
        out[c] = p[c];
    }
    return out;
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let p = id.x + id.y * groups.x * 64u;
    if (p >= info.total_points) {
        return;
    }
    let job = jobs[find_job(p)];
    let local = p - job.out_offset;
    let i = local % job.nu;
    let j = local / job.nu;
    let u = params[job.param_offset + i];
    let v = params[job.param_offset + job.nu + j];
    let bu = bernstein(job.uorder, u);
    let bv = bernstein(job.vorder, v);
    let bu1 = bernstein(job.uorder - 1u, u);
    let bv1 = bernstein(job.vorder - 1u, v);
    var rows: array<vec4<f32>, 30>;
    var point = vec4<f32>(0.0);
    var dv = vec4<f32>(0.0);
    for (var a = 0u; a < job.uorder; a++) {
        var row = vec4<f32>(0.0);
        var row_dv = vec4<f32>(0.0);
        for (var b = 0u; b < job.vorder; b++) {
            let c = control(job, a, b);
            row += bv[b] * c;
            if (b + 1u < job.vorder) {
                row_dv += bv1[b] * (control(job, a, b + 1u) - c);
            }
        }
        rows[a] = row;
        point += bu[a] * row;
        dv += bu[a] * f32(job.vorder - 1u) * row_dv;
    }
    var du = vec4<f32>(0.0);
    for (var a = 0u; a + 1u < job.uorder; a++) {
        du += bu1[a] * f32(job.uorder - 1u) * (rows[a + 1u] - rows[a]);
    }
    var normal = vec3<f32>(0.0);
    if (info.want_normals != 0u) {
        var a = du.xyz;
        var b = dv.xyz;
        if (job.dim == 4u) {
            a = du.xyz * point.w - du.w * point.xyz;
            b = dv.xyz * point.w - dv.w * point.xyz;
        }
        let n = cross(a, b);
        let len2 = dot(n, n);
        if (len2 > 0.0) {
            normal = n * inverseSqrt(len2);
        }
    }
    out[2u * p] = widen(point, job.dim);
    out[2u * p + 1u] = vec4<f32>(normal, 0.0);
}
