//! Property tests of the typed API and of GLU NURBS: arbitrary (mostly bad) input never panics,
//! errors come back as `Err` or through GLU's error callback with GLU's codes, outputs keep
//! their invariants, and a GLU object that saw garbage draws the next valid surface exactly as
//! a fresh one does. Several contexts alive at once do not disturb each other.
//!
//! `PROPTEST_CASES=N` sets the number of cases (docs/testing.md: the long run).

use gleval::math::{BSplineCurve, BSplineSurface, BezierPatch, KnotVector};
use gleval::prelude::*;
use proptest::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

/// Cases per property: `PROPTEST_CASES`, else `default`.
fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// Any float, weighted towards the troublesome ones.
fn value() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -4.0..4.0f64,
        1 => Just(0.0),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(-1e30),
        1 => Just(1e-30),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(300), ..ProptestConfig::default() })]

    /// `BezierPatch::try_new` + `tessellate`: Ok or Err, never a panic; an Ok mesh has the grid's
    /// vertex count, indices inside it, and unit or zero normals.
    #[test]
    fn typed_patches_never_panic(
        dim in 0usize..6,
        uorder in 0usize..33,
        vorder in 0usize..33,
        extra in -3i32..3,
        values in proptest::collection::vec(value(), 0..64),
        su in 0usize..40,
        sv in 0usize..40,
    ) {
        let want = (dim * uorder * vorder) as i64 + i64::from(extra);
        let points: Vec<f64> = (0..want.max(0)).map(|k| values.get(k as usize % values.len().max(1)).copied().unwrap_or(1.0)).collect();
        // Straight through the public fields too: a malformed patch must be refused, not read.
        let raw = BezierPatch { dim, uorder, vorder, points: points.clone() };
        let _ = raw.tessellate(su, sv);
        if let Ok(patch) = BezierPatch::try_new(dim, uorder, vorder, points) {
            match patch.tessellate(su, sv) {
                Ok(mesh) => {
                    prop_assert_eq!(mesh.positions.len(), (su + 1) * (sv + 1));
                    prop_assert_eq!(mesh.indices.len(), 6 * su * sv);
                    prop_assert!(mesh.indices.iter().all(|&i| (i as usize) < mesh.positions.len()));
                    for n in &mesh.normals {
                        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
                        prop_assert!(len == 0.0 || (len - 1.0).abs() < 1e-4, "normal {:?}", n);
                    }
                }
                Err(e) => prop_assert!(!e.to_string().is_empty()),
            }
        }
    }

    /// B-spline curves and surfaces from arbitrary knots (unsorted, negative, repeated, tiny and
    /// huge spans, NaN): construction refuses with a message or evaluation answers, anywhere.
    #[test]
    fn bsplines_with_arbitrary_knots_never_panic(
        order in 0usize..8,
        knots in proptest::collection::vec(value(), 0..16),
        values in proptest::collection::vec(value(), 0..48),
        dim in 1usize..5,
        at in proptest::collection::vec(value(), 1..6),
    ) {
        let count = knots.len().saturating_sub(order);
        let points: Vec<f64> = (0..count * dim).map(|k| values.get(k % values.len().max(1)).copied().unwrap_or(0.5)).collect();
        match BSplineCurve::try_new(dim, order, KnotVector::new(knots.clone()), points.clone()) {
            Ok(curve) => {
                for &u in &at {
                    let _ = curve.eval(u);
                    let _ = curve.derivative(u);
                    let _ = curve.eval_rational(u);
                    let _ = curve.insert_knot(u, 1);
                }
                let _ = curve.to_bezier();
            }
            Err(e) => prop_assert!(!e.to_string().is_empty()),
        }
        let (uk, vk) = knots.split_at(knots.len() / 2);
        let (nu, nv) = (uk.len().saturating_sub(order), vk.len().saturating_sub(order));
        let net: Vec<f64> = (0..nu * nv * dim).map(|k| values.get(k % values.len().max(1)).copied().unwrap_or(0.5)).collect();
        if let Ok(s) = BSplineSurface::try_new(dim, order, order, KnotVector::new(uk.to_vec()), KnotVector::new(vk.to_vec()), net) {
            for w in at.windows(2) {
                let _ = s.eval_with_partials(w[0], w[1]);
                let _ = s.eval_rational_with_partials(w[0], w[1]);
            }
            let _ = s.to_bezier();
        }
    }
}

/// A GLU call with arbitrary arguments.
#[derive(Clone, Debug)]
enum GluCall {
    BeginSurface,
    EndSurface,
    BeginCurve,
    EndCurve,
    BeginTrim,
    EndTrim,
    Surface { knots: (i32, i32), strides: (i32, i32), orders: (i32, i32), kind: u32, len: usize },
    Curve { knots: i32, stride: i32, order: i32, kind: u32, len: usize },
    Pwl { count: i32, stride: i32, kind: u32, len: usize },
    Property(u32, f32),
    DeleteAndRecreate,
}

fn glu_kind() -> impl Strategy<Value = u32> {
    prop_oneof![
        Just(GL_MAP2_VERTEX_3),
        Just(GL_MAP2_VERTEX_4),
        Just(GL_MAP2_NORMAL),
        Just(GL_MAP2_COLOR_4),
        Just(GL_MAP1_VERTEX_3),
        Just(GL_MAP1_VERTEX_4),
        Just(GLU_MAP1_TRIM_2),
        Just(GLU_MAP1_TRIM_3),
        Just(0x1234u32),
    ]
}

fn glu_call() -> impl Strategy<Value = GluCall> {
    let small = -2i32..14;
    prop_oneof![
        Just(GluCall::BeginSurface),
        Just(GluCall::EndSurface),
        Just(GluCall::BeginCurve),
        Just(GluCall::EndCurve),
        Just(GluCall::BeginTrim),
        Just(GluCall::EndTrim),
        (small.clone(), small.clone(), -1i32..30, -1i32..30, -1i32..9, -1i32..9, glu_kind(), 0usize..400).prop_map(
            |(a, b, s, t, o, p, kind, len)| GluCall::Surface {
                knots: (a, b),
                strides: (s, t),
                orders: (o, p),
                kind,
                len
            }
        ),
        (small.clone(), -1i32..6, -1i32..9, glu_kind(), 0usize..60)
            .prop_map(|(knots, stride, order, kind, len)| GluCall::Curve { knots, stride, order, kind, len }),
        (-1i32..8, -1i32..4, glu_kind(), 0usize..30).prop_map(|(count, stride, kind, len)| GluCall::Pwl {
            count,
            stride,
            kind,
            len
        }),
        (
            prop_oneof![
                Just(GLU_SAMPLING_TOLERANCE),
                Just(GLU_PARAMETRIC_TOLERANCE),
                Just(GLU_SAMPLING_METHOD),
                Just(GLU_U_STEP),
                Just(GLU_V_STEP),
                Just(GLU_DISPLAY_MODE),
                Just(GLU_CULLING),
                Just(GLU_AUTO_LOAD_MATRIX),
                Just(GLU_NURBS_MODE),
                Just(0x9999u32),
            ],
            prop_oneof![
                Just(-1.0f32),
                Just(0.0),
                Just(1.0),
                Just(1e9),
                Just(f32::NAN),
                Just(GLU_FILL as f32),
                Just(GLU_DOMAIN_DISTANCE as f32),
                0.0f32..100.0
            ],
        )
            .prop_map(|(p, v)| GluCall::Property(p, v)),
        Just(GluCall::DeleteAndRecreate),
    ]
}

/// Knots that are sometimes fine, sometimes decreasing, sometimes closer than GLU's 1e-5.
fn knots_for(n: i32) -> Vec<f32> {
    (0..n.max(0))
        .map(|i| match i % 5 {
            4 => (i / 2) as f32 + 4e-6,
            _ => (i / 2) as f32,
        })
        .collect()
}

fn apply_glu(gl: &mut Gl, nurb: &mut GLUnurbs, c: &GluCall, sink: &Rc<RefCell<Vec<u32>>>) {
    let ctl = |len: usize| -> Vec<f32> { (0..len).map(|i| ((i * 13) % 7) as f32 * 0.3 - 0.9).collect() };
    match c {
        GluCall::BeginSurface => gl.glu_begin_surface(*nurb),
        GluCall::EndSurface => gl.glu_end_surface(*nurb),
        GluCall::BeginCurve => gl.glu_begin_curve(*nurb),
        GluCall::EndCurve => gl.glu_end_curve(*nurb),
        GluCall::BeginTrim => gl.glu_begin_trim(*nurb),
        GluCall::EndTrim => gl.glu_end_trim(*nurb),
        GluCall::Surface { knots, strides, orders, kind, len } => gl.glu_nurbs_surface(
            *nurb,
            knots.0,
            &knots_for(knots.0),
            knots.1,
            &knots_for(knots.1),
            strides.0,
            strides.1,
            &ctl(*len),
            orders.0,
            orders.1,
            *kind,
        ),
        GluCall::Curve { knots, stride, order, kind, len } => {
            gl.glu_nurbs_curve(*nurb, *knots, &knots_for(*knots), *stride, &ctl(*len), *order, *kind);
        }
        GluCall::Pwl { count, stride, kind, len } => gl.glu_pwl_curve(*nurb, *count, &ctl(*len), *stride, *kind),
        GluCall::Property(p, v) => gl.glu_nurbs_property(*nurb, *p, *v),
        GluCall::DeleteAndRecreate => {
            gl.glu_delete_nurbs_renderer(*nurb);
            *nurb = new_nurbs(gl, sink);
        }
    }
}

/// A NURBS object whose error callback records the codes.
fn new_nurbs(gl: &mut Gl, sink: &Rc<RefCell<Vec<u32>>>) -> GLUnurbs {
    let nurb = gl.glu_new_nurbs_renderer();
    let sink = Rc::clone(sink);
    gl.glu_nurbs_callback(nurb, GLU_NURBS_ERROR, Some(NurbsCallback::error(move |e| sink.borrow_mut().push(e))));
    nurb
}

/// A valid trimmed bicubic surface drawn with fixed properties; the frame's vertices.
fn valid_surface(gl: &mut Gl, nurb: GLUnurbs) -> Vec<Vertex> {
    const KNOTS: [f32; 8] = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    const TRIM: [f32; 10] = [0.2, 0.2, 0.8, 0.2, 0.8, 0.8, 0.2, 0.8, 0.2, 0.2];
    let ctl: Vec<f32> = (0..16).flat_map(|k| [(k / 4) as f32, (k % 4) as f32, ((k * 7) % 5) as f32 * 0.2]).collect();
    for (p, v) in [
        (GLU_NURBS_MODE, GLU_NURBS_RENDERER as f32),
        (GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32),
        (GLU_U_STEP, 6.0),
        (GLU_V_STEP, 5.0),
        (GLU_DISPLAY_MODE, GLU_FILL as f32),
        (GLU_CULLING, 0.0),
        (GLU_AUTO_LOAD_MATRIX, 1.0),
    ] {
        gl.glu_nurbs_property(nurb, p, v);
    }
    let _ = gl.take_frame();
    gl.glu_begin_surface(nurb);
    gl.glu_nurbs_surface(nurb, 8, &KNOTS, 8, &KNOTS, 12, 3, &ctl, 4, 4, GL_MAP2_VERTEX_3);
    gl.glu_begin_trim(nurb);
    gl.glu_pwl_curve(nurb, 5, &TRIM, 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(nurb);
    gl.glu_end_surface(nurb);
    gl.take_frame().expanded().vertices
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(200), ..ProptestConfig::default() })]

    /// Random GLU call sequences: no panic, only GLU's error codes (NURBS errors 1..=37,
    /// `GLU_INVALID_ENUM`/`_VALUE`, `GLU_OUT_OF_MEMORY`, through the callback), no GL error left behind, and afterwards (inside-begin/end state closed as a
    /// program would) a valid trimmed surface draws what it draws on a fresh object.
    #[test]
    fn random_glu_calls_never_panic_and_leave_a_usable_object(calls in proptest::collection::vec(glu_call(), 0..30)) {
        let mut gl = Gl::new(64, 64);
        let seen = Rc::new(RefCell::new(Vec::new()));
        let mut nurb = new_nurbs(&mut gl, &seen);
        for c in &calls {
            apply_glu(&mut gl, &mut nurb, c, &seen);
        }
        for code in seen.borrow().iter() {
            let glu_code = (GLU_NURBS_ERROR1..=GLU_NURBS_ERROR37).contains(code)
                || [GLU_INVALID_ENUM, GLU_INVALID_VALUE, GLU_OUT_OF_MEMORY].contains(code);
            prop_assert!(glu_code, "code {:#x}", code);
        }
        prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
        // Whatever was left open is closed, as a program does before its next frame.
        gl.glu_end_trim(nurb);
        gl.glu_end_curve(nurb);
        gl.glu_end_surface(nurb);
        let after = valid_surface(&mut gl, nurb);
        let mut fresh_gl = Gl::new(64, 64);
        let fresh_nurb = fresh_gl.glu_new_nurbs_renderer();
        let fresh = valid_surface(&mut fresh_gl, fresh_nurb);
        prop_assert!(!fresh.is_empty());
        prop_assert_eq!(after, fresh);
    }
}

/// Two contexts (each with a NURBS object) used in alternation record exactly what each
/// records alone: no state is shared between `Gl`s.
#[test]
fn several_contexts_alive_at_once_are_independent() {
    let draw = |gl: &mut Gl, nurb: GLUnurbs, step: usize| {
        let patch: Vec<f32> =
            (0..16).flat_map(|k| [(k / 4) as f32, (k % 4) as f32, ((k * step) % 5) as f32 * 0.2]).collect();
        gl.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 12, 4, 0.0, 1.0, 3, 4, &patch);
        gl.enable(GL_MAP2_VERTEX_3);
        gl.enable(GL_AUTO_NORMAL);
        gl.map_grid2f(3 + step as i32, 0.0, 1.0, 4, 0.0, 1.0);
        gl.eval_mesh2(GL_FILL, 0, 3 + step as i32, 0, 4);
        let mut vertices = gl.take_frame().expanded().vertices;
        vertices.extend(valid_surface(gl, nurb));
        vertices
    };
    let alone: Vec<Vec<Vertex>> = (1..=2)
        .map(|step| {
            let mut gl = Gl::new(64, 64);
            let nurb = gl.glu_new_nurbs_renderer();
            let mut v = draw(&mut gl, nurb, step);
            v.extend(draw(&mut gl, nurb, step));
            v
        })
        .collect();
    let mut gls = [Gl::new(64, 64), Gl::new(64, 64)];
    let nurbs: Vec<GLUnurbs> = gls.iter_mut().map(|gl| gl.glu_new_nurbs_renderer()).collect();
    let mut together = vec![Vec::new(), Vec::new()];
    for _ in 0..2 {
        for (k, gl) in gls.iter_mut().enumerate() {
            together[k].extend(draw(gl, nurbs[k], k + 1));
        }
    }
    assert_eq!(together, alone);
}

/// Found by the property above. Real GLU (checked with a C program on OSMesa) reports 15, 18 and
/// 7 for `gluBeginTrim; gluEndTrim; gluEndCurve; gluEndSurface` on a fresh object (the trim
/// begins a surface, which `gluEndSurface` then closes silently), and afterwards draws a
/// trimmed surface exactly as a fresh object does.
#[test]
fn a_surface_begun_by_begin_trim_ends_cleanly() {
    let mut gl = Gl::new(64, 64);
    let seen = Rc::new(RefCell::new(Vec::new()));
    let nurb = new_nurbs(&mut gl, &seen);
    gl.glu_begin_trim(nurb);
    gl.glu_end_trim(nurb);
    gl.glu_end_curve(nurb);
    gl.glu_end_surface(nurb);
    let numbers: Vec<u32> = seen.borrow().iter().map(|e| e - GLU_NURBS_ERROR1 + 1).collect();
    assert_eq!(numbers, [15, 18, 7]);
    let after = valid_surface(&mut gl, nurb);
    let mut fresh_gl = Gl::new(64, 64);
    let fresh_nurb = fresh_gl.glu_new_nurbs_renderer();
    assert_eq!(after, valid_surface(&mut fresh_gl, fresh_nurb));
}
