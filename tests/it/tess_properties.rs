//! The tessellator on random input: the triangles it draws cover exactly the points the
//! winding rule puts inside (checked at sample points against winding numbers computed from
//! the contours), every triangle is counter-clockwise about the normal, and bad input (NaN,
//! huge coordinates, thousands of vertices, calls out of order) never panics.

use gleval::prelude::*;
use proptest::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

type P = [f64; 3];

/// Runs the tessellator on `contours` with `rule` and normal +z; the triangles drawn.
fn triangles(contours: &[Vec<P>], rule: GLenum, edge_flags: bool) -> Vec<[P; 3]> {
    let mut gl = Gl::new(8, 8);
    let t = gl.glu_new_tess();
    let tris = Rc::new(RefCell::new(Vec::new()));
    let prim: Rc<RefCell<(GLenum, Vec<P>)>> = Rc::new(RefCell::new((0, Vec::new())));
    let (p1, p2, p3) = (prim.clone(), prim.clone(), prim);
    let out = tris.clone();
    gl.glu_tess_callback(t, GLU_TESS_BEGIN, Some(TessCallback::begin(move |_, m| *p1.borrow_mut() = (m, Vec::new()))));
    gl.glu_tess_callback(t, GLU_TESS_VERTEX, Some(TessCallback::vertex_of(move |_, v: &P| p2.borrow_mut().1.push(*v))));
    gl.glu_tess_callback(
        t,
        GLU_TESS_END,
        Some(TessCallback::end(move |_| {
            let (mode, v) = &*p3.borrow();
            out.borrow_mut().extend(expand(*mode, v));
        })),
    );
    gl.glu_tess_callback(t, GLU_TESS_COMBINE, Some(TessCallback::combine_of(|c: &P, _: [Option<&P>; 4], _| *c)));
    if edge_flags {
        gl.glu_tess_callback(t, GLU_TESS_EDGE_FLAG, Some(TessCallback::edge_flag(|_, _| {})));
    }
    gl.glu_tess_property(t, GLU_TESS_WINDING_RULE, f64::from(rule));
    gl.glu_tess_normal(t, 0.0, 0.0, 1.0);
    gl.glu_tess_begin_polygon(t, None);
    for c in contours {
        gl.glu_tess_begin_contour(t);
        for p in c {
            gl.glu_tess_vertex(t, p, *p);
        }
        gl.glu_tess_end_contour(t);
    }
    gl.glu_tess_end_polygon(t);
    gl.glu_delete_tess(t);
    let v = tris.borrow().clone();
    v
}

/// A primitive's triangles, as GL assembles them.
fn expand(mode: GLenum, v: &[P]) -> Vec<[P; 3]> {
    match mode {
        GL_TRIANGLES => v.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
        GL_TRIANGLE_FAN => (1..v.len().saturating_sub(1)).map(|i| [v[0], v[i], v[i + 1]]).collect(),
        GL_TRIANGLE_STRIP => (0..v.len().saturating_sub(2))
            .map(|i| if i % 2 == 0 { [v[i], v[i + 1], v[i + 2]] } else { [v[i + 1], v[i], v[i + 2]] })
            .collect(),
        _ => Vec::new(),
    }
}

fn cross(a: P, b: P, p: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

/// The winding number of the contours around `p`.
fn winding(contours: &[Vec<P>], p: [f64; 2]) -> i32 {
    let mut w = 0;
    for c in contours {
        for i in 0..c.len() {
            let (a, b) = (c[i], c[(i + 1) % c.len()]);
            if a[1] <= p[1] && b[1] > p[1] && cross(a, b, p) > 0.0 {
                w += 1;
            } else if a[1] > p[1] && b[1] <= p[1] && cross(a, b, p) < 0.0 {
                w -= 1;
            }
        }
    }
    w
}

fn inside(rule: GLenum, n: i32) -> bool {
    match rule {
        GLU_TESS_WINDING_ODD => n % 2 != 0,
        GLU_TESS_WINDING_NONZERO => n != 0,
        GLU_TESS_WINDING_POSITIVE => n > 0,
        GLU_TESS_WINDING_NEGATIVE => n < 0,
        _ => n.abs() >= 2,
    }
}

/// Distance from `p` to segment `ab`.
fn distance(a: P, b: P, p: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 == 0.0 { 0.0 } else { (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0) };
    ((a[0] + t * dx - p[0]).powi(2) + (a[1] + t * dy - p[1]).powi(2)).sqrt()
}

const RULES: [GLenum; 5] = [
    GLU_TESS_WINDING_ODD,
    GLU_TESS_WINDING_NONZERO,
    GLU_TESS_WINDING_POSITIVE,
    GLU_TESS_WINDING_NEGATIVE,
    GLU_TESS_WINDING_ABS_GEQ_TWO,
];

/// Checks coverage at a grid of sample points away from every edge (input or triangle).
fn check_coverage(contours: &[Vec<P>], rule: GLenum, edge_flags: bool) -> Result<(), TestCaseError> {
    let tris = triangles(contours, rule, edge_flags);
    for t in &tris {
        // Intersections' coordinates are GLU's weighted sums with `f32` weights, a few 1e-7
        // off the exact crossing: a degenerate triangle may come out barely clockwise.
        let area = cross(t[0], t[1], [t[2][0], t[2][1]]);
        prop_assert!(area >= -1e-4, "a clockwise triangle {t:?}");
    }
    let near_edge = |p: [f64; 2]| {
        let input = contours.iter().any(|c| (0..c.len()).any(|i| distance(c[i], c[(i + 1) % c.len()], p) < 1e-3));
        input || tris.iter().any(|t| (0..3).any(|i| distance(t[i], t[(i + 1) % 3], p) < 1e-3))
    };
    for i in 0..40 {
        for j in 0..40 {
            let p = [f64::from(i) * 0.4137 + 0.0291, f64::from(j) * 0.3971 + 0.0173];
            if near_edge(p) {
                continue;
            }
            let covered = tris
                .iter()
                .filter(|t| cross(t[0], t[1], p) > 0.0 && cross(t[1], t[2], p) > 0.0 && cross(t[2], t[0], p) > 0.0)
                .count();
            let want = usize::from(inside(rule, winding(contours, p)));
            prop_assert_eq!(covered, want, "point {:?}, winding {}, rule {}", p, winding(contours, p), rule);
        }
    }
    Ok(())
}

/// Random contours on a perturbed grid. On an exact grid a vertex may lie exactly on another
/// edge near an intersection, and there GLU itself (and so gleval, case
/// `vertex-on-edge-intersections` of `tess_cases.in`) emits a clockwise triangle: intersection
/// coordinates are weighted sums with `float` weights, not the exact crossing.
fn contour(max_len: usize) -> impl Strategy<Value = Vec<P>> {
    prop::collection::vec((0u8..=16, 0u8..=16, 0u8..50, 0u8..50), 3..max_len).prop_map(|v| {
        v.into_iter()
            .map(|(x, y, dx, dy)| [f64::from(x) + f64::from(dx) * 0.0137, f64::from(y) + f64::from(dy) * 0.0113, 0.0])
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn triangles_cover_what_the_winding_rule_puts_inside(
        contours in prop::collection::vec(contour(12), 1..4), rule in 0usize..5, flags in any::<bool>()
    ) {
        check_coverage(&contours, RULES[rule], flags)?;
    }

    #[test]
    fn short_convex_and_star_contours_take_the_quick_path_correctly(c in contour(7), rule in 0usize..5) {
        check_coverage(&[c], RULES[rule], false)?;
    }

    #[test]
    fn any_coordinates_never_panic(
        pts in prop::collection::vec(prop_oneof![
            Just(f64::NAN), Just(f64::INFINITY), Just(-1e300), Just(1e150), Just(0.0), -1e6f64..1e6
        ], 3..60),
        rule in 0usize..5, boundary in any::<bool>(), normal in 0usize..3
    ) {
        let mut gl = Gl::new(8, 8);
        let t = gl.glu_new_tess();
        gl.glu_tess_callback(t, GLU_TESS_VERTEX, Some(TessCallback::vertex(|_, _| {})));
        gl.glu_tess_callback(t, GLU_TESS_COMBINE, Some(TessCallback::combine_of(|c: &P, _: [Option<&P>; 4], _| *c)));
        gl.glu_tess_property(t, GLU_TESS_WINDING_RULE, f64::from(RULES[rule]));
        gl.glu_tess_property(t, GLU_TESS_BOUNDARY_ONLY, f64::from(u8::from(boundary)));
        let n = [[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [f64::NAN, 1.0, 0.0]][normal];
        gl.glu_tess_normal(t, n[0], n[1], n[2]);
        gl.glu_tess_begin_polygon(t, None);
        for chunk in pts.chunks(9) {
            gl.glu_tess_begin_contour(t);
            for p in chunk.chunks(3) {
                gl.glu_tess_vertex(t, p, ());
            }
            gl.glu_tess_end_contour(t);
        }
        gl.glu_tess_end_polygon(t);
        gl.glu_delete_tess(t);
    }

    #[test]
    fn calls_in_any_order_never_panic(ops in prop::collection::vec(0u8..10, 0..40)) {
        let mut gl = Gl::new(8, 8);
        let t = gl.glu_new_tess();
        gl.glu_tess_callback(t, GLU_TESS_ERROR, Some(TessCallback::error(|_, _| {})));
        for (k, op) in ops.iter().enumerate() {
            let x = k as f64;
            match op {
                0 => gl.glu_tess_begin_polygon(t, None),
                1 => gl.glu_tess_begin_contour(t),
                2..=4 => gl.glu_tess_vertex(t, &[x, (x * 7.0) % 5.0, 0.0], k),
                5 => gl.glu_tess_end_contour(t),
                6 => gl.glu_tess_end_polygon(t),
                7 => gl.glu_next_contour(t, GLU_CW),
                8 => gl.glu_tess_vertex(t, &[x], k),
                _ => gl.glu_delete_tess(t),
            }
        }
        gl.glu_delete_tess(t);
        gl.glu_tess_end_polygon(t);
    }
}

#[test]
fn thousands_of_vertices_tessellate() {
    // A 4000-point star-shaped contour (self-intersecting where the radius jumps) and a ring.
    let star: Vec<P> = (0..4000)
        .map(|i| {
            let a = f64::from(i) * std::f64::consts::TAU / 4000.0;
            let r = if i % 7 == 0 { 50.0 } else { 100.0 + f64::from(i % 13) };
            [r * a.cos(), r * a.sin(), 0.0]
        })
        .collect();
    let tris = triangles(&[star], GLU_TESS_WINDING_NONZERO, false);
    assert!(tris.len() > 3000, "{} triangles", tris.len());
}

#[test]
fn no_callbacks_draw_nothing_and_record_no_gl_calls() {
    // GLU's default callbacks do nothing (libtess's noBegin, noVertex, ...).
    let mut gl = Gl::new(8, 8);
    let t = gl.glu_new_tess();
    gl.glu_tess_begin_polygon(t, None);
    gl.glu_tess_begin_contour(t);
    for p in [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]] {
        gl.glu_tess_vertex(t, &p, p);
    }
    gl.glu_tess_end_contour(t);
    gl.glu_tess_end_polygon(t);
    assert!(gl.frame().meshes.is_empty() && gl.frame().calls.is_empty());
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn a_contour_winding_twice_around_its_first_vertex_is_swept_not_fanned() {
    // Real GLU draws this one as a single fan of 3 overlapping triangles (tess_calls.c on it:
    // `begin 6`, vertices 0..4): the twice-wound middle is covered twice, though the odd rule
    // leaves it out. gleval sends it through the sweep instead.
    let c = vec![[4.0, 11.0, 0.0], [5.0, 7.0, 0.0], [0.0, 9.0, 0.0], [4.0, 12.0, 0.0], [5.0, 0.0, 0.0]];
    assert_eq!(winding(std::slice::from_ref(&c), [4.1661, 9.5477]), -2);
    for rule in RULES {
        check_coverage(std::slice::from_ref(&c), rule, false).unwrap();
    }
}

#[test]
fn a_nan_coordinate_in_a_swept_polygon_is_reported_and_nothing_is_drawn() {
    // Real GLU's sweep crashes on it (a segmentation fault); gleval reports and skips it.
    let mut gl = Gl::new(8, 8);
    let t = gl.glu_new_tess();
    let seen = Rc::new(RefCell::new(Vec::new()));
    let (errors, drawn) = (seen.clone(), seen.clone());
    gl.glu_tess_callback(t, GLU_TESS_ERROR, Some(TessCallback::error(move |_, e| errors.borrow_mut().push(e))));
    gl.glu_tess_callback(t, GLU_TESS_BEGIN, Some(TessCallback::begin(move |_, m| drawn.borrow_mut().push(m))));
    gl.glu_tess_begin_polygon(t, None);
    for c in [
        [[0.0, 0.0, 0.0], [f64::NAN, 0.0, 0.0], [4.0, 4.0, 0.0], [0.0, 4.0, 0.0]],
        [[0.0, 0.0, 0.0], [2.0, 1.0, 0.0], [3.0, 3.0, 0.0], [1.0, 3.0, 0.0]],
    ] {
        gl.glu_tess_begin_contour(t);
        for p in c {
            gl.glu_tess_vertex(t, &p, p);
        }
        gl.glu_tess_end_contour(t);
    }
    gl.glu_tess_end_polygon(t);
    assert_eq!(*seen.borrow(), vec![GLU_TESS_COORD_TOO_LARGE]);
}
