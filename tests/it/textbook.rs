//! The calculation exercises of seed 004 (9.7.1, questions 5 to 8) and its worked example of a
//! uniform quadratic B-spline (figure 9-7), through the typed API and the GL façade. The
//! expected values are worked out by hand in the comments, from the basis functions.

use gleval::math::{BSplineCurve, BezierCurve, HermiteCurve, KnotVector};
use gleval::prelude::*;

fn close(got: &[f64], want: &[f64]) {
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-9, "{got:?} vs {want:?}");
    }
}

/// Question 5: p(0) = (0, 0), p(1) = (5, 6), p'(0) = (3, 8), p'(1) = (5, 1). At u = 0.5 the
/// Hermite weights are H₀ = H₁ = 1/2, H₂ = 1/8, H₃ = −1/8: p(0.5) = (2.5, 3) + (0.375, 1) −
/// (0.625, 0.125) = (2.25, 3.875).
#[test]
fn question_5_hermite_at_one_half() {
    let c = HermiteCurve { p0: [0.0, 0.0], p1: [5.0, 6.0], t0: [3.0, 8.0], t1: [5.0, 1.0] };
    close(&c.eval(0.5), &[2.25, 3.875]);
    // The same cubic drawn by the evaluators from its Bezier form.
    let bez: Vec<f32> = c.to_bezier().iter().flat_map(|p| [p[0] as f32, p[1] as f32, 0.0]).collect();
    let mut gl = Gl::new(1, 1);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &bez);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(2, 0.0, 1.0);
    gl.eval_mesh1(GL_POINT, 0, 2);
    let mid = gl.frame().expanded().vertices[1].position;
    close(&[f64::from(mid[0]), f64::from(mid[1])], &[2.25, 3.875]);
}

/// Question 6: A(0,0,0), B(1,1,1), C(2,−1,−1), D(3,0,0). Bernstein weights at 1/3 are
/// (8, 12, 6, 1)/27, so p(1/3) = (27, 6, 6)/27 = (1, 2/9, 2/9); at 2/3 (1, 6, 12, 8)/27, so
/// p(2/3) = (54, −6, −6)/27 = (2, −2/9, −2/9); p(0) = A, p(1) = D.
#[test]
fn question_6_cubic_bezier_values() {
    let c = BezierCurve::try_new(3, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, -1.0, -1.0, 3.0, 0.0, 0.0]).unwrap();
    let want = [[0.0, 0.0, 0.0], [1.0, 2.0 / 9.0, 2.0 / 9.0], [2.0, -2.0 / 9.0, -2.0 / 9.0], [3.0, 0.0, 0.0]];
    for (k, w) in want.iter().enumerate() {
        close(&c.eval(k as f64 / 3.0)[..3], w);
    }
}

/// The uniform B-spline of `order` through `pts` (3D), evaluated at the local parameter u of
/// its only segment (knots 0, 1, 2, ...: the segment is [order − 1, order]).
fn uniform_segment(order: usize, pts: &[f64], u: f64) -> Vec<f64> {
    let n = pts.len() / 3;
    let c = BSplineCurve::try_new(3, order, KnotVector::uniform(n, order).unwrap(), pts.to_vec()).unwrap();
    c.eval((order - 1) as f64 + u).unwrap()[..3].to_vec()
}

/// Question 7: A(0,0,0), B(50,60,0), C(100,10,0), uniform quadratic: p(u) = ½[(1−u)² A +
/// (−2u² + 2u + 1) B + u² C]. p(0) = (A + B)/2 = (25, 30, 0), p(1) = (B + C)/2 = (75, 35, 0),
/// p(½) = (A + 6B + C)/8 = (50, 46.25, 0).
#[test]
fn question_7_uniform_quadratic_bspline() {
    let pts = [0.0, 0.0, 0.0, 50.0, 60.0, 0.0, 100.0, 10.0, 0.0];
    close(&uniform_segment(3, &pts, 0.0), &[25.0, 30.0, 0.0]);
    close(&uniform_segment(3, &pts, 0.5), &[50.0, 46.25, 0.0]);
    close(&uniform_segment(3, &pts, 1.0), &[75.0, 35.0, 0.0]);
}

/// Figure 9-7's example: P0(0,0), P1(0.5,1), P2(1,0): p(0) = (0.25, 0.5), p(½) = (0.5, 0.75),
/// p(1) = (0.75, 0.5).
#[test]
fn figure_9_7_uniform_quadratic_bspline() {
    let pts = [0.0, 0.0, 0.0, 0.5, 1.0, 0.0, 1.0, 0.0, 0.0];
    close(&uniform_segment(3, &pts, 0.0), &[0.25, 0.5, 0.0]);
    close(&uniform_segment(3, &pts, 0.5), &[0.5, 0.75, 0.0]);
    close(&uniform_segment(3, &pts, 1.0), &[0.75, 0.5, 0.0]);
}

/// Question 8: A(0,0,0), B(1,0,1), C(2,0,0), D(3,0,0), uniform cubic: weights
/// ((1−u)³, 3u³ − 6u² + 4, −3u³ + 3u² + 3u + 1, u³)/6. At 0: (A + 4B + C)/6 = (1, 0, 2/3);
/// at 1/3: (8, 93, 60, 1)/162, so (216/162, 0, 93/162) = (4/3, 0, 31/54); at 2/3:
/// (1, 60, 93, 8)/162, so (270/162, 0, 60/162) = (5/3, 0, 10/27); at 1: (B + 4C + D)/6 =
/// (2, 0, 1/6).
#[test]
fn question_8_uniform_cubic_bspline() {
    let pts = [0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 2.0, 0.0, 0.0, 3.0, 0.0, 0.0];
    let want =
        [[1.0, 0.0, 2.0 / 3.0], [4.0 / 3.0, 0.0, 31.0 / 54.0], [5.0 / 3.0, 0.0, 10.0 / 27.0], [2.0, 0.0, 1.0 / 6.0]];
    for (k, w) in want.iter().enumerate() {
        close(&uniform_segment(4, &pts, k as f64 / 3.0), w);
    }
    // Through the textbook's gllUniBCurve in GLU's tessellator mode, every vertex lies on it:
    // x = 1 + u, and z is the cubic above.
    let mut gl = Gl::new(100, 100);
    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    let seen = std::rc::Rc::new(std::cell::RefCell::new(Vec::new()));
    let sink = std::rc::Rc::clone(&seen);
    gl.glu_nurbs_callback(
        nurb,
        GLU_NURBS_VERTEX,
        Some(NurbsCallback::vertex(move |_, v| sink.borrow_mut().push(v.to_vec()))),
    );
    let knots: Vec<f32> = (0..8).map(|k| k as f32).collect();
    let pts32: Vec<f32> = pts.iter().map(|&v| v as f32).collect();
    gl.glu_begin_curve(nurb);
    gl.glu_nurbs_curve(nurb, 8, &knots, 3, &pts32, 4, GL_MAP1_VERTEX_3);
    gl.glu_end_curve(nurb);
    let vertices = seen.borrow();
    assert!(vertices.len() > 2);
    for v in vertices.iter() {
        let u = f64::from(v[0]) - 1.0;
        let z = (1.0 / 6.0) * (3.0 * u * u * u - 6.0 * u * u + 4.0);
        assert!((f64::from(v[2]) - z).abs() < 1e-5, "{v:?}");
    }
}
