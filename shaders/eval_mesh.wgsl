// Evaluates every glEvalMesh grid of a frame in one dispatch, one invocation per grid point,
// straight into the vertex and index buffers the render pass draws (no CPU round trip).
//
// A job is one glEvalMesh call: up to four enabled maps (attribute maps in Mesa's order, the
// vertex map last), each with its own normalised parameters, plus the current attributes for
// what no map sets. Each point writes its vertex (position, normal, colour, texture coordinate,
// widened as GL widens them) and, for its grid cell, the indices of GL's primitives: for
// GL_FILL the two triangles of Mesa's strip with the provoking vertex first (so flat shading
// picks GL's colour and the winding stays GL's), for GL_LINE the row and column segments.
// The maths matches src/tess/grid.rs: Bernstein bases tabulated once per grid row and column,
// partials on control-point differences (a collapsed edge gives exactly zero, hence a zero
// normal, never NaN).

const MAX_MAPS: u32 = 4u;

// Slot numbers (gl::Slot): the offset of the target from GL_MAP*_COLOR_4.
const SLOT_COLOR: u32 = 0u;
const SLOT_NORMAL: u32 = 2u;
const SLOT_TEX1: u32 = 3u;
const SLOT_TEX4: u32 = 6u;
const SLOT_VERTEX3: u32 = 7u;
const SLOT_VERTEX4: u32 = 8u;

// Mesh modes (gl::MeshMode): points, curve lines, surface lines, fill; and scattered points
// (GLU's trimmed surfaces: point k at row k of both tables, triangles supplied by the CPU).
const MODE_POINTS: u32 = 0u;
const MODE_FILL: u32 = 3u;
const MODE_SCATTERED: u32 = 4u;

struct MapDesc {
    slot: u32,
    dim: u32,
    uorder: u32,
    vorder: u32,
    point_offset: u32,   // first float of the control points
    u_offset: u32,       // Bernstein table of the nu columns (2·uorder − 1 values each)
    v_offset: u32,       // Bernstein table of the nv rows (2·vorder − 1 values each)
    _pad: u32,
};

struct Job {
    maps: array<MapDesc, 4>,
    map_count: u32,
    nu: u32,
    nv: u32,
    mode: u32,
    out_offset: u32,     // first output vertex (prefix sum of nu·nv)
    index_offset: u32,   // first output index (prefix sum of the index counts)
    auto_normal: u32,
    _pad: u32,
    normal: vec4<f32>,   // current attributes
    color: vec4<f32>,
    tex: vec4<f32>,
};

struct Meta {
    job_count: u32,
    total_points: u32,
    provoking_last: u32,   // 1 where flat shading takes the last vertex (wgpu's GL backend)
    _pad: u32,
};

struct Vertex {
    position: vec4<f32>,
    normal: vec4<f32>,
    color: vec4<f32>,
    tex: vec4<f32>,
};

// Control points and normalised parameters share one array (downlevel devices allow four
// storage buffers per stage).
@group(0) @binding(0) var<storage, read> jobs: array<Job>;
@group(0) @binding(1) var<storage, read> data: array<f32>;
@group(0) @binding(2) var<storage, read_write> vertices: array<Vertex>;
@group(0) @binding(3) var<storage, read_write> indices: array<u32>;
@group(0) @binding(4) var<uniform> info: Meta;

// Control point (i, j) of a map: its `dim` components, the rest zero (selected, not
// multiplied, so whatever lies beyond in the buffer cannot turn into a NaN).
fn control(m: MapDesc, i: u32, j: u32) -> vec4<f32> {
    let base = m.point_offset + (i * m.vorder + j) * m.dim;
    let raw = vec4<f32>(data[base], data[base + 1u], data[base + 2u], data[base + 3u]);
    return select(vec4<f32>(0.0), raw, vec4<u32>(0u, 1u, 2u, 3u) < vec4<u32>(m.dim));
}

struct Sample {
    point: vec4<f32>,
    du: vec4<f32>,
    dv: vec4<f32>,
};

// The map at grid point (i, j). The Bernstein values come from tables the CPU computed once
// per grid column and row (in f64): at column i, `uorder` values of degree uorder−1 followed
// by uorder−1 values of degree uorder−2 (for the derivative); rows likewise. Partials are
// (n−1)·Σ B_{n−2}·ΔP over control-point differences, as the CPU kernel computes them, so a
// collapsed edge gives exactly zero. No private arrays: llvmpipe and real GPUs keep it all in
// registers.
fn evaluate(m: MapDesc, i: u32, j: u32, partials: bool) -> Sample {
    let ustride = 2u * m.uorder - 1u;
    let vstride = 2u * m.vorder - 1u;
    let bu = m.u_offset + i * ustride;
    let bv = m.v_offset + j * vstride;
    var s: Sample;
    var prev_row = vec4<f32>(0.0);
    for (var a = 0u; a < m.uorder; a++) {
        var prev = control(m, a, 0u);
        var row = data[bv] * prev;
        var row_dv = vec4<f32>(0.0);
        for (var b = 1u; b < m.vorder; b++) {
            let c = control(m, a, b);
            row += data[bv + b] * c;
            if (partials) {
                row_dv += data[bv + m.vorder + b - 1u] * (c - prev);
            }
            prev = c;
        }
        let w = data[bu + a];
        s.point += w * row;
        if (partials) {
            s.dv += w * row_dv;
            if (a > 0u) {
                s.du += data[bu + m.uorder + a - 1u] * (row - prev_row);
            }
        }
        prev_row = row;
    }
    s.du *= f32(m.uorder - 1u);
    s.dv *= f32(m.vorder - 1u);
    return s;
}

// The first `dim` components of p over the default (0, 0, 0, 1).
fn widen(p: vec4<f32>, dim: u32) -> vec4<f32> {
    var out = vec4<f32>(0.0, 0.0, 0.0, 1.0);
    for (var c = 0u; c < dim; c++) {
        out[c] = p[c];
    }
    return out;
}

// GL's AUTO_NORMAL: du × dv, for a rational map of the projected surface (w·p' − w'·p
// has the direction of the projected derivative); a zero cross product stays zero.
fn auto_normal(s: Sample, dim: u32) -> vec3<f32> {
    var a = s.du.xyz;
    var b = s.dv.xyz;
    if (dim == 4u) {
        a = s.du.xyz * s.point.w - s.du.w * s.point.xyz;
        b = s.dv.xyz * s.point.w - s.dv.w * s.point.xyz;
    }
    let n = cross(a, b);
    let len2 = dot(n, n);
    if (len2 > 0.0) {
        return n * inverseSqrt(len2);
    }
    return vec3<f32>(0.0);
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

// GL_FILL: row j of Mesa's strip alternates (i, j), (i, j+1). Cell i holds its triangles 2i and
// 2i+1: (i,j) (i,j+1) (i+1,j) and, odd so swapped, (i+1,j) (i,j+1) (i+1,j+1); GL's provoking
// vertex is the last. Where the backend's flat shading takes the first vertex (Vulkan, WGSL's
// `flat`), each triangle is rotated to start there; rotation keeps the winding.
fn write_cell(job: Job, i: u32, j: u32) {
    if (i + 1u >= job.nu || j + 1u >= job.nv) {
        return;
    }
    let a = job.out_offset + j * job.nu + i;   // (i, j)
    let b = a + job.nu;                         // (i, j+1)
    let c = a + 1u;                             // (i+1, j)
    let d = b + 1u;                             // (i+1, j+1)
    let k = job.index_offset + 6u * (j * (job.nu - 1u) + i);
    if (info.provoking_last != 0u) {
        indices[k] = a;
        indices[k + 1u] = b;
        indices[k + 2u] = c;
        indices[k + 3u] = c;
        indices[k + 4u] = b;
        indices[k + 5u] = d;
        return;
    }
    indices[k] = c;
    indices[k + 1u] = a;
    indices[k + 2u] = b;
    indices[k + 3u] = d;
    indices[k + 4u] = c;
    indices[k + 5u] = b;
}

// GL_LINE: the segment of row j from i to i+1, then (after all rows) the segment of column i
// from j to j+1; the provoking (second) vertex placed where the backend's flat shading looks.
fn write_segment(k: u32, start: u32, end: u32) {
    if (info.provoking_last != 0u) {
        indices[k] = start;
        indices[k + 1u] = end;
    } else {
        indices[k] = end;
        indices[k + 1u] = start;
    }
}

fn write_segments(job: Job, i: u32, j: u32) {
    let a = job.out_offset + j * job.nu + i;
    let rows = job.nv * (job.nu - 1u);
    if (i + 1u < job.nu) {
        write_segment(job.index_offset + 2u * (j * (job.nu - 1u) + i), a, a + 1u);
    }
    if (j + 1u < job.nv) {
        write_segment(job.index_offset + 2u * (rows + i * (job.nv - 1u) + j), a, a + job.nu);
    }
}

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let p = id.x + id.y * groups.x * 64u;
    if (p >= info.total_points) {
        return;
    }
    let index = find_job(p);
    let job = jobs[index];
    let local = p - job.out_offset;
    var i = local % job.nu;
    var j = local / job.nu;
    if (job.mode == MODE_SCATTERED) {
        i = local;
        j = local;
    }
    var out: Vertex;
    out.position = vec4<f32>(0.0, 0.0, 0.0, 1.0);
    out.normal = job.normal;
    out.color = job.color;
    out.tex = job.tex;
    for (var k = 0u; k < job.map_count; k++) {
        let m = jobs[index].maps[k];
        let is_vertex = m.slot == SLOT_VERTEX3 || m.slot == SLOT_VERTEX4;
        let normals = is_vertex && job.auto_normal != 0u;
        let s = evaluate(m, i, j, normals);
        if (m.slot == SLOT_COLOR) {
            out.color = s.point;
        } else if (m.slot == SLOT_NORMAL) {
            out.normal = vec4<f32>(s.point.xyz, 0.0);
        } else if (m.slot >= SLOT_TEX1 && m.slot <= SLOT_TEX4) {
            out.tex = widen(s.point, m.dim);
        } else if (m.slot == SLOT_VERTEX3) {
            out.position = widen(s.point, 3u);
        } else if (m.slot == SLOT_VERTEX4) {
            out.position = s.point;
        }
        if (normals) {
            out.normal = vec4<f32>(auto_normal(s, m.dim), 0.0);
        }
    }
    vertices[p] = out;
    if (job.mode == MODE_FILL) {
        write_cell(job, i, j);
    } else if (job.mode != MODE_POINTS && job.mode != MODE_SCATTERED) {
        write_segments(job, i, j);
    }
}
