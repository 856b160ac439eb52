//! EvalMesh / EvalCoord / EvalPoint against closed forms: primitive order (spec 1.7), exact grid
//! ends, map precedence (1.2), auto normals (1.8) including reversed domains and rational maps.

use gleval::gl::{MeshVertices, Tessellator};
use gleval::prelude::*;

/// Bilinear patch p(u, v) = (u, v, u·v) on [0,1]²: corners (0,0,0), (0,1,0), (1,0,0), (1,1,1).
const SADDLE: [f32; 12] = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0];

fn saddle(gl: &mut Gl, u: (f32, f32), v: (f32, f32)) {
    gl.map2f(GL_MAP2_VERTEX_3, u.0, u.1, 6, 2, v.0, v.1, 3, 2, &SADDLE);
    gl.enable(GL_MAP2_VERTEX_3);
}

fn xy(v: &Vertex) -> (f32, f32) {
    (v.position[0], v.position[1])
}

#[test]
fn seed_004_cubic_through_eval_mesh1() {
    // (0,0),(1,1),(2,-1),(3,0): p(1/3) = (1, 2/9), p(2/3) = (2, -2/9) (seed 004, 9.7.1).
    let mut gl = Gl::new(1, 1);
    let pts = [0.0f32, 0.0, 0.0, 1.0, 1.0, 0.0, 2.0, -1.0, 0.0, 3.0, 0.0, 0.0];
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &pts);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(3, 0.0, 1.0);
    gl.eval_mesh1(GL_LINE, 0, 3);
    let f = gl.frame().expanded();
    assert_eq!(f.primitives.len(), 1);
    assert_eq!(f.primitives[0].mode, GL_LINE_STRIP);
    let want = [(0.0, 0.0), (1.0, 2.0 / 9.0), (2.0, -2.0 / 9.0), (3.0, 0.0)];
    for (v, w) in f.vertices.iter().zip(want) {
        let (x, y) = xy(v);
        assert!((x - w.0).abs() < 1e-6 && (y - w.1).abs() < 1e-6, "{:?} vs {w:?}", (x, y));
        assert_eq!(v.position[3], 1.0);
    }
}

/// GL 1.1 §5.1 defines `glEvalMesh1(GL_LINE, i1, i2)` as `glBegin(GL_LINE_STRIP)`, then
/// `glEvalPoint1(i)` for i = i1..=i2, then `glEnd`: the two record the same vertices bit for
/// bit, for a degree-10 vertex map with colour, normal and texture maps, on grids long enough
/// to be split between the cores and short ones, and over a reversed domain (a range with
/// i2 < i1 records nothing either way).
#[test]
fn eval_mesh1_is_the_eval_point1_loop_bit_for_bit() {
    let curve: Vec<f32> =
        (0..11).flat_map(|i| [i as f32 * 0.1 - 0.5, (i % 3) as f32 * 0.2, 0.3, 1.0 + i as f32 * 0.05]).collect();
    let colors: Vec<f32> = (0..3).flat_map(|i| [0.1 * i as f32, 0.9, 0.5, 1.0]).collect();
    let normals: Vec<f32> = (0..2).flat_map(|i| [i as f32, 1.0, 0.5]).collect();
    let tex: Vec<f32> = (0..5).flat_map(|i| [i as f32 * 0.25, 1.0 - i as f32 * 0.2]).collect();
    for (n, i1, i2, domain) in [(30, 0, 30, (0.0, 1.0)), (100_000, 0, 100_000, (-0.5, 2.0)), (40, 35, 3, (1.0, 0.0))] {
        let record = |mesh: bool| {
            let mut gl = Gl::new(8, 8);
            gl.map1f(GL_MAP1_VERTEX_4, domain.0, domain.1, 4, 11, &curve);
            gl.map1f(GL_MAP1_COLOR_4, 0.0, 1.0, 4, 3, &colors);
            gl.map1f(GL_MAP1_NORMAL, 0.0, 1.0, 3, 2, &normals);
            gl.map1f(GL_MAP1_TEXTURE_COORD_2, -1.0, 1.0, 2, 5, &tex);
            for cap in [GL_MAP1_VERTEX_4, GL_MAP1_COLOR_4, GL_MAP1_NORMAL, GL_MAP1_TEXTURE_COORD_2] {
                gl.enable(cap);
            }
            gl.map_grid1f(n, 0.0, 1.0);
            if mesh {
                gl.eval_mesh1(GL_LINE, i1, i2);
            } else {
                gl.begin(GL_LINE_STRIP);
                for i in i1..=i2 {
                    gl.eval_point1(i);
                }
                gl.end();
            }
            gl.frame().expanded().vertices
        };
        let (mesh, points) = (record(true), record(false));
        let bits = |v: &Vertex| {
            [v.position, v.color, v.tex_coord]
                .concat()
                .into_iter()
                .chain(v.normal)
                .map(f32::to_bits)
                .collect::<Vec<_>>()
        };
        assert_eq!(mesh.len(), points.len(), "{n}");
        for (k, (a, b)) in mesh.iter().zip(&points).enumerate() {
            assert_eq!(bits(a), bits(b), "{n} points, vertex {k}");
        }
    }
}

#[test]
fn eval_mesh1_partial_and_reversed_ranges() {
    let mut gl = Gl::new(1, 1);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 2, &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(10, 0.0, 1.0);
    gl.eval_mesh1(GL_POINT, 3, 5);
    gl.eval_mesh1(GL_LINE, 5, 3); // i1 > i2: an empty begin/end, as Mesa
    gl.map_grid1f(4, 1.0, 0.0); // reversed grid
    gl.eval_mesh1(GL_LINE, 0, 4);
    let f = gl.frame().expanded();
    let xs: Vec<f32> = f.vertices_of(&f.primitives[0]).iter().map(|v| v.position[0]).collect();
    assert_eq!(f.primitives[0].mode, GL_POINTS);
    assert!(xs.iter().zip([0.3, 0.4, 0.5]).all(|(a, b)| (a - b).abs() < 1e-6), "{xs:?}");
    assert_eq!(f.primitives[1].count, 0);
    let xs: Vec<f32> = f.vertices_of(&f.primitives[2]).iter().map(|v| v.position[0]).collect();
    assert_eq!(xs, [1.0, 0.75, 0.5, 0.25, 0.0]);
}

#[test]
fn grid_end_is_exact_at_i_equals_n() {
    // 0.1 is not representable; accumulating 0.1/3 three times would miss it.
    let mut gl = Gl::new(1, 1);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 2, &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(3, 0.0, 0.1);
    gl.eval_mesh1(GL_POINT, 0, 3);
    gl.begin(GL_POINTS);
    gl.eval_point1(3);
    gl.end();
    let v = &gl.frame().expanded().vertices;
    assert_eq!(v[3].position[0], 0.1f32);
    assert_eq!(v[4].position[0], 0.1f32);
}

#[test]
fn eval_mesh2_fill_strips_are_mesas_order_and_clockwise() {
    let mut gl = Gl::new(1, 1);
    saddle(&mut gl, (0.0, 1.0), (0.0, 1.0));
    gl.map_grid2f(2, 0.0, 1.0, 2, 0.0, 1.0);
    gl.eval_mesh2(GL_FILL, 0, 2, 0, 2);
    let f = gl.frame().expanded();
    assert_eq!(f.primitives.len(), 2, "one strip per row j in j1..j2");
    for (j, (p, verts)) in f.iter().enumerate() {
        assert_eq!(p.mode, GL_TRIANGLE_STRIP);
        let got: Vec<(f32, f32)> = verts.iter().map(xy).collect();
        let v0 = j as f32 * 0.5;
        let want: Vec<(f32, f32)> = (0..3).flat_map(|i| [(i as f32 * 0.5, v0), (i as f32 * 0.5, v0 + 0.5)]).collect();
        assert_eq!(got, want);
        // First triangle (u_i,v_j), (u_i,v_j+1), (u_i+1,v_j) turns clockwise in (u, v).
        let (a, b, c) = (got[0], got[1], got[2]);
        let cross = (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
        assert!(cross < 0.0);
    }
}

#[test]
fn eval_mesh2_lines_rows_then_columns_and_points() {
    let mut gl = Gl::new(1, 1);
    saddle(&mut gl, (0.0, 1.0), (0.0, 1.0));
    gl.map_grid2f(4, 0.0, 1.0, 2, 0.0, 1.0);
    gl.eval_mesh2(GL_LINE, 1, 3, 0, 2);
    let f = gl.take_frame().expanded();
    let counts: Vec<usize> = f.primitives.iter().map(|p| p.count).collect();
    assert_eq!(counts, [3, 3, 3, 3, 3, 3], "3 row strips of 3, then 3 column strips of 3");
    let row1: Vec<(f32, f32)> = f.vertices_of(&f.primitives[1]).iter().map(xy).collect();
    assert_eq!(row1, [(0.25, 0.5), (0.5, 0.5), (0.75, 0.5)]);
    let col0: Vec<(f32, f32)> = f.vertices_of(&f.primitives[3]).iter().map(xy).collect();
    assert_eq!(col0, [(0.25, 0.0), (0.25, 0.5), (0.25, 1.0)]);
    gl.eval_mesh2(GL_POINT, 0, 1, 1, 2);
    let f = gl.take_frame().expanded();
    let pts: Vec<(f32, f32)> = f.vertices.iter().map(xy).collect();
    assert_eq!(pts, [(0.0, 0.5), (0.25, 0.5), (0.0, 1.0), (0.25, 1.0)], "j outer, i inner");
    gl.eval_mesh2(GL_FILL, 0, 4, 1, 1);
    assert!(gl.frame().expanded().primitives.is_empty(), "j1 == j2 draws nothing");
}

fn unit(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    [v[0] / l, v[1] / l, v[2] / l]
}

fn assert_normal(got: [f32; 3], want: [f64; 3], tol: f64) {
    for c in 0..3 {
        assert!((f64::from(got[c]) - want[c]).abs() < tol, "normal {got:?} vs {want:?}");
    }
}

#[test]
fn auto_normal_closed_form_and_reversed_domain_sign() {
    // n = du x dv = (1,0,v) x (0,1,u) = (-v, -u, 1).
    for (udom, flip) in [((0.0, 1.0), false), ((1.0, 0.0), true)] {
        let mut gl = Gl::new(1, 1);
        saddle(&mut gl, udom, (0.0, 1.0));
        gl.enable(GL_AUTO_NORMAL);
        gl.map_grid2f(4, 0.0, 1.0, 4, 0.0, 1.0);
        gl.eval_mesh2(GL_POINT, 0, 4, 0, 4);
        for v in &gl.frame().expanded().vertices {
            let (x, y) = (f64::from(v.position[0]), f64::from(v.position[1]));
            // x and y are the normalised parameters s, t of the control net.
            let analytic_du_sign = if flip { -1.0 } else { 1.0 };
            // Mesa differentiates with respect to the normalised parameter, so its normal is
            // (-t, -s, 1) whatever the domain direction: the analytic d/du x d/dv flips sign.
            let want = unit([-y, -x, 1.0]);
            assert_normal(v.normal, want, 1e-6);
            let analytic = unit([-y * analytic_du_sign, -x * analytic_du_sign, analytic_du_sign]);
            let dot: f64 = (0..3).map(|c| analytic[c] * f64::from(v.normal[c])).sum();
            assert!((dot - analytic_du_sign).abs() < 1e-5);
        }
    }
}

/// Rational bilinear patch with weights: p = Σ B w P / Σ B w (f64 closed form).
fn rational_saddle(s: f64, t: f64) -> [f64; 3] {
    let w = [1.0, 2.0, 3.0, 0.5];
    let p = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 1.0]];
    let b = [(1.0 - s) * (1.0 - t), (1.0 - s) * t, s * (1.0 - t), s * t];
    let den: f64 = (0..4).map(|k| b[k] * w[k]).sum();
    let mut out = [0.0; 3];
    for c in 0..3 {
        out[c] = (0..4).map(|k| b[k] * w[k] * p[k][c]).sum::<f64>() / den;
    }
    out
}

#[test]
fn rational_auto_normal_matches_finite_differences() {
    let w = [1.0f32, 2.0, 3.0, 0.5];
    let mut hom = Vec::new();
    for k in 0..4 {
        for c in 0..3 {
            hom.push(SADDLE[k * 3 + c] * w[k]);
        }
        hom.push(w[k]);
    }
    let mut gl = Gl::new(1, 1);
    gl.map2f(GL_MAP2_VERTEX_4, 0.0, 1.0, 8, 2, 0.0, 1.0, 4, 2, &hom);
    gl.enable(GL_MAP2_VERTEX_4);
    gl.enable(GL_MAP2_VERTEX_3); // VERTEX_4 wins
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(5, 0.0, 1.0, 5, 0.0, 1.0);
    gl.eval_mesh2(GL_POINT, 0, 5, 0, 5);
    let h = 1e-6;
    for (k, v) in gl.frame().expanded().vertices.iter().enumerate() {
        let (s, t) = ((k % 6) as f64 / 5.0, (k / 6) as f64 / 5.0);
        let p = rational_saddle(s, t);
        let w = f64::from(v.position[3]);
        for c in 0..3 {
            assert!((f64::from(v.position[c]) / w - p[c]).abs() < 1e-6, "w is passed through, not divided");
        }
        let du: Vec<f64> =
            (0..3).map(|c| (rational_saddle(s + h, t)[c] - rational_saddle(s - h, t)[c]) / (2.0 * h)).collect();
        let dv: Vec<f64> =
            (0..3).map(|c| (rational_saddle(s, t + h)[c] - rational_saddle(s, t - h)[c]) / (2.0 * h)).collect();
        let n = unit([du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]]);
        assert_normal(v.normal, n, 1e-5);
    }
}

#[test]
fn collapsed_edge_gives_zero_normal_not_nan() {
    // Row u = 0 collapsed to a point: a cone-like corner.
    let pts = [0.0f32, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, -1.0, 0.0, 1.0, 1.0, 0.0];
    let mut gl = Gl::new(1, 1);
    gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 6, 2, 0.0, 1.0, 3, 2, &pts);
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(2, 0.0, 1.0, 2, 0.0, 1.0);
    gl.eval_mesh2(GL_FILL, 0, 2, 0, 2);
    for v in &gl.frame().expanded().vertices {
        assert!(v.normal.iter().all(|c| c.is_finite()));
        if v.position == [0.0, 0.0, 1.0, 1.0] {
            assert_eq!(v.normal, [0.0, 0.0, 0.0]);
        } else {
            let len: f32 = v.normal.iter().map(|c| c * c).sum();
            assert!((len - 1.0).abs() < 1e-5);
        }
    }
}

#[test]
fn attribute_maps_precedence_and_current_state_untouched() {
    let mut gl = Gl::new(1, 1);
    gl.color4f(0.2, 0.3, 0.4, 0.5);
    gl.normal3f(0.0, 1.0, 0.0);
    gl.tex_coord4f(9.0, 9.0, 9.0, 9.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 2, &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    gl.map1f(GL_MAP1_COLOR_4, 0.0, 1.0, 4, 2, &[1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0]);
    gl.map1f(GL_MAP1_TEXTURE_COORD_1, 0.0, 1.0, 1, 2, &[5.0, 6.0]);
    gl.map1f(GL_MAP1_TEXTURE_COORD_3, 0.0, 1.0, 3, 2, &[0.0, 0.0, 0.0, 1.0, 2.0, 3.0]);
    gl.map1f(GL_MAP1_NORMAL, 0.0, 1.0, 3, 2, &[0.0, 0.0, 2.0, 0.0, 0.0, 4.0]);
    for cap in [GL_MAP1_VERTEX_3, GL_MAP1_COLOR_4, GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_3, GL_MAP1_NORMAL] {
        gl.enable(cap);
    }
    gl.begin(GL_POINTS);
    gl.eval_coord1f(0.5);
    gl.vertex3f(7.0, 7.0, 7.0);
    gl.end();
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    let v = gl.frame().expanded().vertices.clone();
    assert_eq!(v[0].position, [0.5, 0.0, 0.0, 1.0]);
    assert_eq!(v[0].color, [0.5, 0.0, 0.5, 1.0]);
    assert_eq!(v[0].tex_coord, [0.5, 1.0, 1.5, 1.0], "TEXTURE_COORD_3 beats _1; q defaults to 1");
    assert_eq!(v[0].normal, [0.0, 0.0, 3.0], "map normals are not normalised");
    // The plain vertex after it still has the current attributes.
    assert_eq!(v[1].color, [0.2, 0.3, 0.4, 0.5]);
    assert_eq!(v[1].normal, [0.0, 1.0, 0.0]);
    assert_eq!(v[1].tex_coord, [9.0; 4]);
}

#[test]
fn nothing_without_vertex_map_or_outside_begin_end() {
    let mut gl = Gl::new(1, 1);
    gl.map1f(GL_MAP1_COLOR_4, 0.0, 1.0, 4, 1, &[1.0, 0.0, 0.0, 1.0]);
    gl.enable(GL_MAP1_COLOR_4);
    gl.map_grid1f(4, 0.0, 1.0);
    gl.eval_mesh1(GL_LINE, 0, 4);
    gl.begin(GL_POINTS);
    gl.eval_coord1f(0.5);
    gl.end();
    assert_eq!(gl.frame().expanded().vertices.len(), 0);
    assert_eq!(gl.frame().expanded().primitives.len(), 1, "only the user's own begin/end");
    gl.enable(GL_MAP1_VERTEX_3);
    gl.eval_coord1f(0.5);
    gl.eval_point1(1);
    assert_eq!(gl.frame().expanded().vertices.len(), 0, "a vertex outside begin/end draws nothing");
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn vertex4_passes_w_through() {
    let mut gl = Gl::new(1, 1);
    gl.map1f(GL_MAP1_VERTEX_4, 0.0, 1.0, 4, 2, &[0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0, 2.0]);
    gl.enable(GL_MAP1_VERTEX_4);
    gl.map_grid1f(2, 0.0, 1.0);
    gl.eval_mesh1(GL_POINT, 0, 2);
    assert_eq!(gl.frame().expanded().vertices[1].position, [1.0, 1.0, 1.0, 1.5]);
}

/// A grid large enough to be split between threads (bands of rows) still gives the closed form
/// at every point: the saddle p = (s, t, s·t) with normal (−t, −s, 1), on a 401 × 301 grid.
#[test]
fn large_grids_split_between_cores_match_the_closed_form() {
    let mut gl = Gl::new(1, 1);
    saddle(&mut gl, (0.0, 1.0), (0.0, 1.0));
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(400, 0.0, 1.0, 300, 0.0, 1.0);
    gl.eval_mesh2(GL_POINT, 0, 400, 0, 300);
    let f = gl.frame().expanded();
    assert_eq!(f.vertices.len(), 401 * 301);
    for (k, v) in f.vertices.iter().enumerate() {
        let (s, t) = ((k % 401) as f64 / 400.0, (k / 401) as f64 / 300.0);
        let p = [s, t, s * t];
        for c in 0..3 {
            assert!((f64::from(v.position[c]) - p[c]).abs() < 1e-6, "vertex {k}: {:?} vs {p:?}", v.position);
        }
        assert_normal(v.normal, unit([-t, -s, 1.0]), 1e-5);
    }
}

/// A frame given back with `recycle_frame` lends its buffers to the next one, which must be
/// exactly what a fresh context records (whatever the recycled buffers held).
#[test]
fn recycled_frames_record_what_a_fresh_context_records() {
    let draw = |gl: &mut Gl, n: i32, color: [f32; 4]| {
        gl.color4f(color[0], color[1], color[2], color[3]);
        saddle(gl, (0.0, 1.0), (0.0, 1.0));
        gl.map_grid2f(n, 0.0, 1.0, n, 0.0, 1.0);
        gl.eval_mesh2(GL_FILL, 0, n, 0, n);
        gl.eval_mesh2(GL_LINE, 0, n / 2, 0, n);
    };
    let mut fresh = Gl::new(1, 1);
    draw(&mut fresh, 7, [0.2, 0.4, 0.6, 1.0]);
    let want = fresh.take_frame();
    let mut gl = Gl::new(1, 1);
    for (n, color) in [(200, [1.0, 0.0, 0.0, 1.0]), (3, [0.0, 1.0, 0.0, 1.0])] {
        draw(&mut gl, n, color);
        let frame = gl.take_frame();
        gl.recycle_frame(frame);
    }
    draw(&mut gl, 7, [0.2, 0.4, 0.6, 1.0]);
    assert_eq!(gl.take_frame(), want);
}

/// Records `count` small bicubic patches (9 × 9 points), each with its own control points and
/// current colour, into `gl`.
fn many_small_patches(gl: &mut Gl, count: usize) {
    gl.enable(GL_MAP2_VERTEX_3);
    gl.enable(GL_AUTO_NORMAL);
    gl.map_grid2f(8, 0.0, 1.0, 8, 0.0, 1.0);
    for k in 0..count {
        let points: Vec<f32> =
            (0..16).flat_map(|p| [(p / 4) as f32 + k as f32, (p % 4) as f32, ((p * 7 + k) % 5) as f32 * 0.3]).collect();
        gl.color3f(k as f32 / count as f32, 0.5, 1.0);
        gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &points);
        gl.eval_mesh2(GL_FILL, 0, 8, 0, 8);
    }
}

/// Small meshes are evaluated in batches after they are recorded: each must still hold what
/// its own maps and state gave when it was recorded, across batch boundaries and for the
/// meshes still pending when the frame is looked at. Checked against each mesh's job evaluated
/// on its own (the GPU tessellator's deferred jobs, evaluated here on the CPU) and against the
/// closed form at the corners (a Bezier patch passes through its corner control points).
#[test]
fn small_meshes_evaluated_in_batches_keep_their_own_maps_and_state() {
    let count = 1000; // 81,000 points: two full batches and a pending rest.
    let mut gl = Gl::new(1, 1);
    many_small_patches(&mut gl, count);
    let mut deferred = Gl::new(1, 1);
    deferred.set_tessellator(Tessellator::Gpu);
    many_small_patches(&mut deferred, count);
    let frame = gl.frame().clone();
    let jobs = deferred.frame().clone();
    assert_eq!(frame.meshes.len(), count);
    for (k, (mesh, job)) in frame.meshes.iter().zip(&jobs.meshes).enumerate() {
        let (MeshVertices::Evaluated(got), MeshVertices::Deferred(job)) = (&mesh.vertices, &job.vertices) else {
            panic!("mesh {k}: evaluated on the CPU, deferred on the GPU tessellator");
        };
        assert_eq!(got, &job[0].evaluate(), "mesh {k}");
        // Corners: P00 = (k, 0, z), P33 = (k + 3, 3, z').
        let corner = |p: usize| [(p / 4) as f32 + k as f32, (p % 4) as f32, ((p * 7 + k) % 5) as f32 * 0.3, 1.0];
        assert_eq!(got.vertex(0).position, corner(0), "mesh {k}");
        assert_eq!(got.vertex(80).position, corner(15), "mesh {k}");
        assert_eq!(got.vertex(40).color, [k as f32 / count as f32, 0.5, 1.0, 1.0], "mesh {k}");
    }
}
