//! GLU tessellator mode: the vertices gleval hands to the callbacks lie on the true surface
//! (f64 oracle) and their number is within a factor of 2 of what real GLU emits for the same
//! NURBS, properties and sampling matrices (`tests/reference/glu/tess_counts.c`).

use gleval::gl::Tessellator;
use gleval::math::{BSplineCurve, BSplineSurface, KnotVector};
use gleval::prelude::*;
use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;

fn glu_counts() -> Vec<(String, usize)> {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu/tess_counts.txt"))
            .expect("tess_counts.txt");
    text.lines()
        .map(|l| {
            let f: Vec<&str> = l.split(' ').collect();
            (format!("{} {}", f[0], f[1]), f[2].parse().expect("count"))
        })
        .collect()
}

fn surface_net() -> (Vec<f32>, Vec<f32>) {
    let knots: Vec<f32> = (0..14).map(|i| i as f32).collect();
    let mut ctl = Vec::new();
    for i in 0..10 {
        for j in 0..10 {
            ctl.extend([-1.5 + i as f32 / 3.0, -1.5 + j as f32 / 3.0, ((i * 3 + j * 5) % 7) as f32 / 7.0 - 0.5]);
        }
    }
    (knots, ctl)
}

const CURVE_KNOTS: [f32; 12] = [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0, 5.0];
const CURVE_CTL: [f32; 24] = [
    -1.5, 0.0, 0.0, -1.0, 1.0, 0.0, -0.5, -1.0, 0.0, 0.0, 1.0, 0.0, 0.5, -1.0, 0.0, 1.0, 1.0, 0.0, 1.5, 0.0, 0.0, 1.8,
    0.5, 0.0,
];

fn configure(gl: &mut Gl, method: u32, tolerance: f32, step: f32) -> (GLUnurbs, Rc<RefCell<Vec<Vec<f32>>>>) {
    let n = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    gl.glu_nurbs_property(n, GLU_AUTO_LOAD_MATRIX, 0.0);
    let model: [f32; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    let proj: [f32; 16] = [0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, -0.1, 0.0, 0.0, 0.0, 0.0, 1.0];
    gl.glu_load_sampling_matrices(n, &model, &proj, &[0, 0, 400, 400]);
    gl.glu_nurbs_property(n, GLU_SAMPLING_METHOD, method as f32);
    gl.glu_nurbs_property(n, GLU_SAMPLING_TOLERANCE, tolerance);
    gl.glu_nurbs_property(n, GLU_PARAMETRIC_TOLERANCE, tolerance);
    gl.glu_nurbs_property(n, GLU_U_STEP, step);
    gl.glu_nurbs_property(n, GLU_V_STEP, step);
    let seen = Rc::new(RefCell::new(Vec::new()));
    let sink = Rc::clone(&seen);
    gl.glu_nurbs_callback(
        n,
        GLU_NURBS_VERTEX,
        Some(NurbsCallback::vertex(move |_, v| sink.borrow_mut().push(v.to_vec()))),
    );
    (n, seen)
}

fn method(name: &str) -> (u32, f32, f32) {
    let (kind, value) = name.rsplit_once('_').expect("name_value");
    let value: f32 = value.parse().expect("value");
    match kind {
        "path_length" => (GLU_PATH_LENGTH, value, 100.0),
        "parametric_error" => (GLU_PARAMETRIC_ERROR, value, 100.0),
        _ => (GLU_DOMAIN_DISTANCE, 50.0, value),
    }
}

#[test]
fn tessellator_vertices_lie_on_the_surface_and_counts_are_near_glu() {
    let (knots, ctl) = surface_net();
    let oracle = BSplineSurface::try_new(
        3,
        4,
        4,
        KnotVector::new(knots.iter().map(|&k| f64::from(k)).collect()),
        KnotVector::new(knots.iter().map(|&k| f64::from(k)).collect()),
        ctl.iter().map(|&c| f64::from(c)).collect(),
    )
    .expect("valid surface");
    let curve_oracle = BSplineCurve::try_new(
        3,
        4,
        KnotVector::new(CURVE_KNOTS.iter().map(|&k| f64::from(k)).collect()),
        CURVE_CTL.iter().map(|&c| f64::from(c)).collect(),
    )
    .expect("valid curve");
    let mut report = Vec::new();
    for (case, glu) in glu_counts() {
        let (kind, name) = case.split_once(' ').expect("kind name");
        let (m, tolerance, step) = method(name);
        let mut gl = Gl::new(400, 400);
        let (n, seen) = configure(&mut gl, m, tolerance, step);
        if kind == "surface" {
            gl.glu_begin_surface(n);
            gl.glu_nurbs_surface(n, 14, &knots, 14, &knots, 30, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
            gl.glu_end_surface(n);
        } else {
            gl.glu_begin_curve(n);
            gl.glu_nurbs_curve(n, 12, &CURVE_KNOTS, 3, &CURVE_CTL, 4, GL_MAP1_VERTEX_3);
            gl.glu_end_curve(n);
        }
        let vertices = seen.borrow();
        let mut worst = 0.0f64;
        for v in vertices.iter() {
            if kind == "surface" {
                let p = oracle.eval(f64::from(v[3]), f64::from(v[4])).expect("(u, v) inside the domain");
                worst = worst.max((0..3).map(|c| (p[c] - f64::from(v[c])).abs()).fold(0.0, f64::max));
            } else {
                // Curve vertices carry no parameter: the distance to the curve, found by a
                // coarse scan refined by golden-section search.
                worst = worst.max(distance_to_curve(&curve_oracle, [v[0], v[1], v[2]]));
            }
        }
        let ratio = vertices.len() as f64 / glu as f64;
        report.push(format!("{case}: ours {} glu {glu} ratio {ratio:.2} worst {worst:.1e}", vertices.len()));
        let tolerance = 1e-5;
        assert!(worst <= tolerance, "{case}: a vertex is {worst} off the true geometry");
        assert!(
            (0.5..=2.0).contains(&ratio),
            "{case}: {} vertices vs GLU's {glu}\n{}",
            vertices.len(),
            report.join("\n")
        );
    }
    println!("{}", report.join("\n"));
}

fn distance_to_curve(c: &BSplineCurve<f64>, v: [f32; 3]) -> f64 {
    let d = |t: f64| {
        let p = c.eval(t.clamp(0.0, 5.0)).expect("inside");
        (0..3).map(|k| (p[k] - f64::from(v[k])).powi(2)).sum::<f64>().sqrt()
    };
    let best = (0..=500).map(|i| 5.0 * f64::from(i) / 500.0).min_by(|a, b| d(*a).total_cmp(&d(*b))).unwrap_or(0.0);
    let (mut lo, mut hi) = (best - 0.01, best + 0.01);
    for _ in 0..80 {
        let (a, b) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
        if d(a) < d(b) {
            hi = b;
        } else {
            lo = a;
        }
    }
    d(0.5 * (lo + hi))
}

/// What one tessellation issued: `B prim`, vertex data, `E`, as strings.
type Trace = Rc<RefCell<Vec<String>>>;

/// Tessellates the surface net at `step` with begin/vertex/end callbacks recording into a trace;
/// `data_forms` registers the `_DATA` callbacks (user data: a tag they check), and
/// `unused_color` also registers a colour callback, which the surface (no colour map) never calls
/// but which makes the tessellator issue every vertex through its general per-vertex path.
fn trace_surface(step: f32, data_forms: bool, unused_color: bool) -> Vec<String> {
    let (knots, ctl) = surface_net();
    let mut gl = Gl::new(8, 8);
    let n = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    gl.glu_nurbs_property(n, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    gl.glu_nurbs_property(n, GLU_U_STEP, step);
    gl.glu_nurbs_property(n, GLU_V_STEP, step);
    let trace: Trace = Rc::default();
    let (b, v, e) = (Rc::clone(&trace), Rc::clone(&trace), Rc::clone(&trace));
    let tagged = |d: &mut dyn std::any::Any| assert_eq!(d.downcast_ref::<u32>(), Some(&7), "user data");
    if data_forms {
        gl.glu_nurbs_callback_data(n, Box::new(7u32));
        let cbs = [
            NurbsCallback::BeginData(Box::new(move |_, p, d| {
                tagged(d);
                b.borrow_mut().push(format!("B {p}"));
            })),
            NurbsCallback::VertexData(Box::new(move |_, x, d| {
                tagged(d);
                v.borrow_mut().push(format!("{x:?}"));
            })),
            NurbsCallback::EndData(Box::new(move |_, d| {
                tagged(d);
                e.borrow_mut().push("E".into());
            })),
        ];
        for (which, cb) in [GLU_NURBS_BEGIN_DATA, GLU_NURBS_VERTEX_DATA, GLU_NURBS_END_DATA].into_iter().zip(cbs) {
            gl.glu_nurbs_callback(n, which, Some(cb));
        }
    } else {
        gl.glu_nurbs_callback(
            n,
            GLU_NURBS_BEGIN,
            Some(NurbsCallback::begin(move |_, p| b.borrow_mut().push(format!("B {p}")))),
        );
        gl.glu_nurbs_callback(
            n,
            GLU_NURBS_VERTEX,
            Some(NurbsCallback::vertex(move |_, x| v.borrow_mut().push(format!("{x:?}")))),
        );
        gl.glu_nurbs_callback(n, GLU_NURBS_END, Some(NurbsCallback::end(move |_| e.borrow_mut().push("E".into()))));
    }
    if unused_color {
        gl.glu_nurbs_callback(n, GLU_NURBS_COLOR, Some(NurbsCallback::color(|_, _| panic!("no colour map"))));
    }
    gl.glu_begin_surface(n);
    gl.glu_nurbs_surface(n, 14, &knots, 14, &knots, 30, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
    gl.glu_end_surface(n);
    let out = trace.borrow().clone();
    out
}

/// The tessellator's fast path (only begin, vertex and end callbacks: grids evaluated a batch
/// ahead on other threads, one indirect call per vertex) issues exactly what its general path
/// issues, primitive for primitive and bit for bit, also with the `_DATA` forms, and at a step
/// large enough for several batches.
#[test]
fn fast_tessellator_path_issues_what_the_general_path_issues() {
    for step in [3.0, 90.0] {
        let general = trace_surface(step, false, true);
        let begins = general.iter().filter(|s| s.starts_with("B ")).count();
        assert_eq!(begins, general.iter().filter(|s| *s == "E").count());
        assert!(general.len() > begins * 4, "step {step}: {} entries", general.len());
        assert_eq!(trace_surface(step, false, false), general, "step {step}: fast path");
        assert_eq!(trace_surface(step, true, false), general, "step {step}: _DATA forms");
        assert_eq!(trace_surface(step, true, true), general, "step {step}: _DATA forms, general path");
    }
}

/// The primitives one tessellation issued: type and vertex data.
type Primitives = Rc<RefCell<Vec<(u32, Vec<[f32; 5]>)>>>;

/// A rational bicubic NURBS (the surface net with weights) trimmed by the domain's border and
/// a heptagonal hole, in tessellator mode at `step`; `unused_color` as in [`trace_surface`].
fn trimmed_primitives(step: f32, hole: &[[f32; 2]], unused_color: bool) -> Vec<(u32, Vec<[f32; 5]>)> {
    let (knots, ctl) = surface_net();
    let net: Vec<f32> = ctl
        .chunks_exact(3)
        .enumerate()
        .flat_map(|(k, p)| {
            let w = 1.0 + 0.5 * (k % 3) as f32;
            [p[0] * w, p[1] * w, p[2] * w, w]
        })
        .collect();
    let mut gl = Gl::new(8, 8);
    let n = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    gl.glu_nurbs_property(n, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    gl.glu_nurbs_property(n, GLU_U_STEP, step);
    gl.glu_nurbs_property(n, GLU_V_STEP, step);
    let prims: Primitives = Rc::default();
    let (b, v) = (Rc::clone(&prims), Rc::clone(&prims));
    gl.glu_nurbs_callback(
        n,
        GLU_NURBS_BEGIN,
        Some(NurbsCallback::begin(move |_, p| b.borrow_mut().push((p, Vec::new())))),
    );
    gl.glu_nurbs_callback(
        n,
        GLU_NURBS_VERTEX,
        Some(NurbsCallback::vertex(move |_, x| {
            if let Some(last) = v.borrow_mut().last_mut() {
                last.1.push([x[0], x[1], x[2], x[3], x[4]]);
            }
        })),
    );
    if unused_color {
        gl.glu_nurbs_callback(n, GLU_NURBS_COLOR, Some(NurbsCallback::color(|_, _| panic!("no colour map"))));
    }
    let border = [3.0f32, 3.0, 10.0, 3.0, 10.0, 10.0, 3.0, 10.0, 3.0, 3.0];
    let hole_closed: Vec<f32> = hole.iter().chain(&hole[..1]).flat_map(|p| *p).collect();
    gl.glu_begin_surface(n);
    gl.glu_nurbs_surface(n, 14, &knots, 14, &knots, 40, 4, &net, 4, 4, GL_MAP2_VERTEX_4);
    gl.glu_begin_trim(n);
    gl.glu_pwl_curve(n, 5, &border, 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(n);
    gl.glu_begin_trim(n);
    gl.glu_pwl_curve(n, hole.len() as i32 + 1, &hole_closed, 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(n);
    gl.glu_end_surface(n);
    let out = prims.borrow().clone();
    out
}

/// Trimmed tessellation (GLU's fans and quad strips), checked against independent truths:
/// every vertex on the rational surface (f64 oracle), every triangle counter-clockwise in
/// (u, v) and outside the hole, and
/// the triangles' (u, v) area equal to the domain's minus the hole's (shoelace). The fast and
/// the general callback paths issue the same primitives.
#[test]
fn trimmed_tessellation_covers_the_retained_region_on_the_surface() {
    let (knots, ctl) = surface_net();
    let weighted: Vec<f64> = ctl
        .chunks_exact(3)
        .enumerate()
        .flat_map(|(k, p)| {
            let w = 1.0 + 0.5 * (k % 3) as f64;
            [f64::from(p[0]) * w, f64::from(p[1]) * w, f64::from(p[2]) * w, w]
        })
        .collect();
    let k64: Vec<f64> = knots.iter().map(|&k| f64::from(k)).collect();
    let oracle = BSplineSurface::try_new(4, 4, 4, KnotVector::new(k64.clone()), KnotVector::new(k64), weighted)
        .expect("valid surface");
    // A clockwise heptagon (a hole) around (6.5, 6.2).
    let hole: Vec<[f32; 2]> = (0..7)
        .map(|i| {
            let a = -std::f32::consts::TAU * i as f32 / 7.0;
            [6.5 + 2.1 * a.cos(), 6.2 + 1.7 * a.sin()]
        })
        .collect();
    let hole64: Vec<[f64; 2]> = hole.iter().map(|p| [f64::from(p[0]), f64::from(p[1])]).collect();
    let shoelace: f64 = 0.5
        * (0..7).map(|i| hole64[i][0] * hole64[(i + 1) % 7][1] - hole64[(i + 1) % 7][0] * hole64[i][1]).sum::<f64>();
    let inside_hole = |p: [f64; 2]| {
        let mut odd = false;
        for i in 0..7 {
            let (a, b) = (hole64[i], hole64[(i + 1) % 7]);
            if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
                odd = !odd;
            }
        }
        odd
    };
    for step in [4.0, 20.0] {
        let prims = trimmed_primitives(step, &hole, false);
        assert_eq!(prims, trimmed_primitives(step, &hole, true), "step {step}: fast vs general path");
        let mut triangles: Vec<[[f32; 5]; 3]> = Vec::new();
        for (prim, v) in &prims {
            match *prim {
                GL_TRIANGLES => {
                    assert_eq!(v.len() % 3, 0);
                    triangles.extend(v.chunks_exact(3).map(|t| [t[0], t[1], t[2]]));
                }
                GL_TRIANGLE_FAN => {
                    assert!(v.len() >= 3);
                    triangles.extend(v[1..].windows(2).map(|w| [v[0], w[0], w[1]]));
                }
                GL_QUAD_STRIP => {
                    assert!(v.len() >= 4 && v.len() % 2 == 0);
                    for q in v.windows(4).step_by(2) {
                        triangles.push([q[0], q[1], q[3]]);
                        triangles.push([q[0], q[3], q[2]]);
                    }
                }
                other => panic!("unexpected primitive {other}"),
            }
        }
        let mut worst = 0.0f64;
        let mut area = 0.0;
        for t in &triangles {
            for x in t {
                let (u, v) = (f64::from(x[3]), f64::from(x[4]));
                let p = oracle.eval(u, v).expect("(u, v) inside the domain");
                worst = worst.max((0..3).map(|c| (p[c] / p[3] - f64::from(x[c])).abs()).fold(0.0, f64::max));
            }
            let uv = t.map(|x| [f64::from(x[3]), f64::from(x[4])]);
            let a =
                0.5 * ((uv[1][0] - uv[0][0]) * (uv[2][1] - uv[0][1]) - (uv[2][0] - uv[0][0]) * (uv[1][1] - uv[0][1]));
            assert!(a > -1e-9, "step {step}: clockwise triangle {uv:?}");
            let c = [(uv[0][0] + uv[1][0] + uv[2][0]) / 3.0, (uv[0][1] + uv[1][1] + uv[2][1]) / 3.0];
            assert!(!inside_hole(c), "step {step}: triangle {uv:?} inside the hole");
            area += a;
        }
        let want = 49.0 - shoelace.abs();
        assert!(worst < 1e-5, "step {step}: a vertex is {worst} off the surface");
        assert!((area - want).abs() < 1e-4, "step {step}: area {area} vs {want}");
        let quads = prims.iter().filter(|p| p.0 == GL_QUAD_STRIP).count();
        assert!(quads > 0, "step {step}: the interior comes as quad strips");
    }
}

/// A trimmed NURBS surface drawn through GLU inside a display list (`GL_COMPILE`, then
/// `call_list`) records exactly what drawing it directly records, on both tessellators and in
/// every display mode: GLU's GL calls (evaluators, vertices, attribute pushes) are compiled as
/// real GLU's are.
#[test]
fn glu_surfaces_in_display_lists_draw_as_when_drawn_directly() {
    fn draw(gl: &mut Gl, mode: u32) {
        let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let mut ctl = Vec::new();
        for u in 0..4 {
            for v in 0..4 {
                ctl.extend([u as f32 - 1.5, v as f32 - 1.5, if (1..3).contains(&u) { 1.0 } else { -0.5 }]);
            }
        }
        let hole = [0.3, 0.3, 0.3, 0.7, 0.7, 0.7, 0.7, 0.3, 0.3, 0.3];
        let border = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0];
        let nurb = gl.glu_new_nurbs_renderer();
        gl.glu_nurbs_property(nurb, GLU_DISPLAY_MODE, mode as f32);
        gl.glu_nurbs_property(nurb, GLU_SAMPLING_TOLERANCE, 10.0);
        gl.glu_begin_surface(nurb);
        gl.glu_nurbs_surface(nurb, 8, &knots, 8, &knots, 12, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
        gl.glu_begin_trim(nurb);
        gl.glu_pwl_curve(nurb, 5, &border, 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(nurb);
        gl.glu_begin_trim(nurb);
        gl.glu_pwl_curve(nurb, 5, &hole, 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(nurb);
        gl.glu_end_surface(nurb);
        gl.glu_delete_nurbs_renderer(nurb);
    }
    for tessellator in [Tessellator::Cpu, Tessellator::Gpu] {
        for mode in [GLU_FILL, GLU_OUTLINE_POLYGON, GLU_OUTLINE_PATCH] {
            let mut direct = Gl::new(200, 200);
            direct.set_tessellator(tessellator);
            direct.enable(GL_AUTO_NORMAL);
            draw(&mut direct, mode);
            let mut listed = Gl::new(200, 200);
            listed.set_tessellator(tessellator);
            listed.enable(GL_AUTO_NORMAL);
            listed.new_list(1, GL_COMPILE);
            draw(&mut listed, mode);
            listed.end_list();
            assert!(listed.frame().expanded().vertices.is_empty(), "GL_COMPILE drew");
            listed.call_list(1);
            let (a, b) = (direct.frame().expanded(), listed.frame().expanded());
            assert!(!a.vertices.is_empty());
            assert_eq!(a.vertices.len(), b.vertices.len(), "{tessellator:?} mode {mode}");
            let first_difference = a.vertices.iter().zip(&b.vertices).position(|(x, y)| x != y);
            assert_eq!(first_difference, None, "{tessellator:?} mode {mode}");
            assert_eq!(a.primitives.len(), b.primitives.len(), "{tessellator:?} mode {mode}");
            assert_eq!((direct.get_error(), listed.get_error()), (GL_NO_ERROR, GL_NO_ERROR));
        }
    }
}

/// The usual way to draw GLU's tessellation yourself, as C programs do it: tessellator-mode
/// callbacks that call `glBegin`, `glNormal3fv`, `glVertex3fv` and `glEnd` on the context
/// they are given. What they draw is exactly what the callbacks were handed, on the fast path
/// (begin, vertex, end only) and on the per-vertex path (with normals), trimmed or not.
#[test]
fn tessellator_callbacks_draw_through_the_context() {
    fn surface(gl: &mut Gl, nurb: GLUnurbs, trimmed: bool) {
        let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let ctl: Vec<f32> =
            (0..16).flat_map(|i| [(i / 4) as f32, (i % 4) as f32, if i == 5 || i == 10 { 1.0 } else { 0.0 }]).collect();
        gl.glu_begin_surface(nurb);
        gl.glu_nurbs_surface(nurb, 8, &knots, 8, &knots, 12, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
        if trimmed {
            gl.glu_begin_trim(nurb);
            gl.glu_pwl_curve(nurb, 5, &[0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0], 2, GLU_MAP1_TRIM_2);
            gl.glu_end_trim(nurb);
            gl.glu_begin_trim(nurb);
            gl.glu_pwl_curve(nurb, 5, &[0.2, 0.2, 0.2, 0.8, 0.8, 0.8, 0.8, 0.2, 0.2, 0.2], 2, GLU_MAP1_TRIM_2);
            gl.glu_end_trim(nurb);
        }
        gl.glu_end_surface(nurb);
    }
    for (trimmed, normals) in [(false, false), (false, true), (true, false), (true, true)] {
        let mut gl = Gl::new(100, 100);
        let nurb = gl.glu_new_nurbs_renderer();
        gl.glu_nurbs_property(nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
        gl.glu_nurbs_property(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
        gl.glu_nurbs_property(nurb, GLU_U_STEP, 6.0);
        gl.glu_nurbs_property(nurb, GLU_V_STEP, 6.0);
        let handed = Rc::new(RefCell::new(Vec::new()));
        let sink = handed.clone();
        gl.glu_nurbs_callback(nurb, GLU_NURBS_BEGIN, Some(NurbsCallback::begin(|gl, mode| gl.begin(mode))));
        gl.glu_nurbs_callback(
            nurb,
            GLU_NURBS_VERTEX,
            Some(NurbsCallback::vertex(move |gl, v| {
                sink.borrow_mut().push([v[0], v[1], v[2]]);
                gl.vertex3fv(v);
            })),
        );
        if normals {
            gl.glu_nurbs_callback(nurb, GLU_NURBS_NORMAL, Some(NurbsCallback::normal(|gl, n| gl.normal3fv(n))));
        }
        gl.glu_nurbs_callback(nurb, GLU_NURBS_END, Some(NurbsCallback::end(|gl| gl.end())));
        surface(&mut gl, nurb, trimmed);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let frame = gl.frame().expanded();
        let drawn: Vec<[f32; 3]> =
            frame.vertices.iter().map(|v| [v.position[0], v.position[1], v.position[2]]).collect();
        assert!(drawn.len() > 50, "trimmed {trimmed}, normals {normals}: {} vertices", drawn.len());
        assert_eq!(drawn, *handed.borrow(), "trimmed {trimmed}, normals {normals}");
        if normals {
            // Each vertex carries the normal GLU handed over before it: unit length, not the
            // initial (0, 0, 1) everywhere.
            assert!(frame.vertices.iter().all(|v| (v.normal.iter().map(|c| c * c).sum::<f32>() - 1.0).abs() < 1e-4));
            assert!(frame.vertices.iter().any(|v| v.normal != [0.0, 0.0, 1.0]));
        }
    }
}

/// GLU's subdivision and slicing of trimmed domains on random holes (stars of 3 to 12 points
/// around a random centre, some snapped to eighths, under every sampling method): never a
/// panic, and the triangles handed out cover the border's square less the hole (shoelace), in
/// signed area. Not every triangle is counter-clockwise: real GLU hands out an occasional
/// clockwise one overlapping its neighbours (checked with GLU 9.0.2 on such a hole, PATH_LENGTH
/// 16.9: one clockwise triangle of 127 primitives, the same as gleval's), so the sum is signed.
mod random_holes {
    use super::*;
    use proptest::prelude::*;

    fn cases(default: u32) -> u32 {
        std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(default)
    }

    fn triangles(prims: &[(u32, Vec<[f32; 5]>)]) -> Vec<[[f64; 2]; 3]> {
        let uv = |x: &[f32; 5]| [f64::from(x[3]), f64::from(x[4])];
        let mut out = Vec::new();
        for (prim, v) in prims {
            match *prim {
                GL_TRIANGLE_FAN => out.extend(v[1..].windows(2).map(|w| [uv(&v[0]), uv(&w[0]), uv(&w[1])])),
                GL_QUAD_STRIP => {
                    for q in v.windows(4).step_by(2) {
                        out.push([uv(&q[0]), uv(&q[1]), uv(&q[3])]);
                        out.push([uv(&q[0]), uv(&q[3]), uv(&q[2])]);
                    }
                }
                GL_TRIANGLES => out.extend(v.chunks_exact(3).map(|t| [uv(&t[0]), uv(&t[1]), uv(&t[2])])),
                other => panic!("unexpected primitive {other}"),
            }
        }
        out
    }

    fn run(method: u32, value: f32, hole: &[[f32; 2]]) -> Vec<(u32, Vec<[f32; 5]>)> {
        let mut gl = Gl::new(64, 64);
        gl.matrix_mode(GL_PROJECTION);
        gl.glu_perspective(45.0, 1.0, 1.0, 10.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.translatef(0.0, 0.0, -4.0);
        let n = gl.glu_new_nurbs_renderer();
        gl.glu_nurbs_property(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
        gl.glu_nurbs_property(n, GLU_SAMPLING_METHOD, method as f32);
        gl.glu_nurbs_property(n, GLU_SAMPLING_TOLERANCE, value);
        gl.glu_nurbs_property(n, GLU_PARAMETRIC_TOLERANCE, value / 50.0);
        gl.glu_nurbs_property(n, GLU_U_STEP, value / 4.0);
        gl.glu_nurbs_property(n, GLU_V_STEP, value / 3.0);
        let prims: Primitives = Rc::default();
        let (b, v) = (Rc::clone(&prims), Rc::clone(&prims));
        gl.glu_nurbs_callback(
            n,
            GLU_NURBS_BEGIN,
            Some(NurbsCallback::begin(move |_, p| b.borrow_mut().push((p, vec![])))),
        );
        let vertex = NurbsCallback::vertex(move |_, x| {
            if let Some(last) = v.borrow_mut().last_mut() {
                last.1.push([x[0], x[1], x[2], x[3], x[4]]);
            }
        });
        gl.glu_nurbs_callback(n, GLU_NURBS_VERTEX, Some(vertex));
        let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let ctl: Vec<f32> =
            (0..16).flat_map(|k| [(k / 4) as f32 - 1.5, (k % 4) as f32 - 1.5, (k % 3) as f32 * 0.4]).collect();
        gl.glu_begin_surface(n);
        gl.glu_nurbs_surface(n, 8, &knots, 8, &knots, 12, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
        let border = [0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0, 0.0, 0.0];
        gl.glu_begin_trim(n);
        gl.glu_pwl_curve(n, 5, &border, 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(n);
        let mut closed: Vec<f32> = hole.iter().flatten().copied().collect();
        closed.extend_from_slice(&hole[0]);
        gl.glu_begin_trim(n);
        gl.glu_pwl_curve(n, hole.len() as i32 + 1, &closed, 2, GLU_MAP1_TRIM_2);
        gl.glu_end_trim(n);
        gl.glu_end_surface(n);
        let out = prims.borrow().clone();
        out
    }

    /// No two edges meet but neighbours at their shared point, which no other edge touches.
    fn simple(h: &[[f64; 2]]) -> bool {
        let n = h.len();
        let cross =
            |a: [f64; 2], b: [f64; 2], c: [f64; 2]| (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        let meet = |a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]| {
            let (d1, d2, d3, d4) = (cross(a, b, c), cross(a, b, d), cross(c, d, a), cross(c, d, b));
            let within = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
                r[0] >= p[0].min(q[0]) && r[0] <= p[0].max(q[0]) && r[1] >= p[1].min(q[1]) && r[1] <= p[1].max(q[1])
            };
            (d1 * d2 < 0.0 && d3 * d4 < 0.0)
                || (d1 == 0.0 && within(a, b, c))
                || (d2 == 0.0 && within(a, b, d))
                || (d3 == 0.0 && within(c, d, a))
                || (d4 == 0.0 && within(c, d, b))
        };
        (0..n).all(|i| {
            let (a, b) = (h[i], h[(i + 1) % n]);
            a != b
                && cross(h[(i + n - 1) % n], a, b) != 0.0
                && (0..n)
                    .filter(|&j| j != i && j != (i + 1) % n && (j + 1) % n != i)
                    .all(|j| !meet(a, b, h[j], h[(j + 1) % n]))
        })
    }

    fn star() -> impl Strategy<Value = Vec<[f32; 2]>> {
        (3usize..12, 0.3f32..0.7, 0.3f32..0.7, 0.05f32..0.25, any::<bool>(), proptest::collection::vec(0.3f32..1.0, 12))
            .prop_map(|(n, cx, cy, r, snap, radii)| {
                (0..n)
                    .map(|i| {
                        // Clockwise: a hole.
                        let a = -std::f32::consts::TAU * i as f32 / n as f32;
                        let p = [cx + r * radii[i] * a.cos(), cy + r * radii[i] * a.sin()];
                        if snap {
                            p.map(|x| (x * 8.0).round() / 8.0)
                        } else {
                            p
                        }
                    })
                    .collect()
            })
    }

    proptest! {
        // A fixed seed: the closed form below is not what GLU draws for every hole. Under
        // some samplings GLU's mesher covers part of a hole (the star of trimcases.c's
        // `overcover` cases, which this test found on random seeds: GLU's triangles cover
        // 0.97665 of the square, not 0.97420), and gleval draws GLU's triangles, as
        // glu_trimcases checks line for line. These cases all keep the closed form.
        #![proptest_config(ProptestConfig {
            cases: cases(64),
            max_global_rejects: 100_000,
            rng_seed: proptest::test_runner::RngSeed::Fixed(34),
            ..ProptestConfig::default()
        })]
        #[test]
        fn random_holes_cover_the_trimmed_region(
            hole in star(),
            method in prop_oneof![Just(GLU_PATH_LENGTH), Just(GLU_PARAMETRIC_ERROR), Just(GLU_DOMAIN_DISTANCE)],
            value in 5.0f32..60.0,
        ) {
            let h: Vec<[f64; 2]> = hole.iter().map(|p| [f64::from(p[0]), f64::from(p[1])]).collect();
            let n = h.len();
            let shoelace = 0.5 * (0..n).map(|i| h[i][0] * h[(i + 1) % n][1] - h[(i + 1) % n][0] * h[i][1]).sum::<f64>();
            // A star with its points snapped may cross itself or collapse: GLU reports an
            // error then, and these checks apply only to a proper clockwise hole.
            prop_assume!(shoelace < -1e-3 && simple(&h));
            let prims = run(method, value, &hole);
            let mut area = 0.0;
            for t in triangles(&prims) {
                area += 0.5 * ((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]));
            }
            prop_assert!((area - (1.0 + shoelace)).abs() < 1e-4, "area {} vs {}", area, 1.0 + shoelace);
        }
    }
}
