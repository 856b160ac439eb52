//! The curve operations of the course notes, shown side by side (one viewport each, four to a
//! row): subdivision at u = 1/2 (the two halves' control polygons), repeated degree elevation
//! (the polygons after 0, 2, 8 and 32 elevations close in on the curve), interpolation through
//! the same points with uniform, chord-length and centripetal parameters; the Frenet frames
//! and curvature comb of a cubic, the exact NURBS circle with its control polygon, a vase as a
//! surface of revolution; degree reduction (a quartic and the cubic closest to it), knot
//! refinement of a B-spline (the polygon after 0, 1 and 3 rounds of midpoint insertion), a
//! Hermite segment with its end tangents, and a tube extruded from the NURBS circle. Each
//! panel has a caption strip below it in GLUT bitmap text, its words in the colours of the
//! curves they name.
//!
//! `cargo run --release --example operations -- --png operations.png`

use gleval::math::{extrude, nurbs_circle, revolve};
use gleval::math::{interpolate, Parameterization};
use gleval::math::{BSplineCurve, BSplineSurface, BezierCurve, HermiteCurve, KnotVector};
use gleval::prelude::*;

/// The height in pixels of the caption strip under each panel's drawing.
const CAPTION: i32 = 18;

/// Panel `k`'s drawing area (four panels to a row, three rows, the first at the top left),
/// above its caption strip: x, y, width, height.
fn panel(gl: &Gl, k: i32) -> (i32, i32, i32, i32) {
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH) / 4, gl.glut_get(GLUT_WINDOW_HEIGHT) / 3);
    ((k % 4) * w, (2 - k / 4) * h + CAPTION, w, h - CAPTION)
}

fn view(gl: &mut Gl, k: i32, (x0, x1, y0, y1): (f64, f64, f64, f64)) {
    let (x, y, w, h) = panel(gl, k);
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(x0, x1, y0, y1);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn strip(gl: &mut Gl, pts: &[f64], dim: usize, mode: GLenum) {
    gl.begin(mode);
    for p in pts.chunks(dim) {
        gl.vertex2f(p[0] as f32, p[1] as f32);
    }
    gl.end();
}

/// A curve drawn as a polyline of `n` samples of `f`.
fn sampled(gl: &mut Gl, n: usize, f: impl Fn(f64) -> [f64; 2]) {
    let pts: Vec<f64> = (0..=n).flat_map(|i| f(i as f64 / n as f64)).collect();
    strip(gl, &pts, 2, GL_LINE_STRIP);
}

fn cubic() -> BezierCurve<f64> {
    BezierCurve::try_new(2, vec![0.5, 0.5, 1.5, 3.5, 3.5, 3.5, 4.5, 0.5]).expect("a planar cubic")
}

fn subdivision(gl: &mut Gl) {
    view(gl, 0, (0.0, 5.0, 0.0, 4.0));
    let c = cubic();
    let (left, right) = c.split(0.5);
    gl.color3f(0.7, 0.7, 0.7);
    strip(gl, &c.points, 2, GL_LINE_STRIP);
    for (half, color) in [(&left, [0.9, 0.3, 0.0]), (&right, [0.0, 0.6, 0.2])] {
        gl.color3f(color[0], color[1], color[2]);
        strip(gl, &half.points, 2, GL_LINE_STRIP);
        strip(gl, &half.points, 2, GL_POINTS);
    }
    gl.color3f(0.0, 0.0, 0.8);
    sampled(gl, 60, |t| [c.eval(t)[0], c.eval(t)[1]]);
}

fn elevation(gl: &mut Gl) {
    view(gl, 1, (0.0, 5.0, 0.0, 4.0));
    let c = cubic();
    let mut e = c.clone();
    let mut done = 0;
    for (times, grey) in [(0, 0.2), (2, 0.4), (8, 0.6), (32, 0.8)] {
        while done < times {
            e = e.elevate();
            done += 1;
        }
        gl.color3f(grey, grey, grey);
        strip(gl, &e.points, 2, GL_LINE_STRIP);
    }
    gl.color3f(0.0, 0.0, 0.8);
    sampled(gl, 60, |t| [c.eval(t)[0], c.eval(t)[1]]);
}

fn interpolation(gl: &mut Gl) {
    view(gl, 2, (-0.5, 9.0, -3.0, 4.5));
    let pts = [0.0, 0.0, 0.5, 3.0, 1.0, 3.2, 5.0, 1.0, 6.0, -2.0, 8.0, 0.0, 8.5, 2.0];
    let colors = [[0.9, 0.2, 0.0], [0.0, 0.6, 0.2], [0.1, 0.2, 0.9]];
    let methods = [Parameterization::Uniform, Parameterization::ChordLength, Parameterization::Centripetal];
    for (method, color) in methods.into_iter().zip(colors) {
        let (curve, _) = interpolate(&pts, 2, 3, method).expect("interpolable points");
        gl.color3f(color[0], color[1], color[2]);
        sampled(gl, 200, |t| {
            let p = curve.eval(t).unwrap_or_default();
            [p[0], p[1]]
        });
    }
    gl.color3f(0.0, 0.0, 0.0);
    strip(gl, &pts, 2, GL_POINTS);
}

fn frenet(gl: &mut Gl) {
    view(gl, 3, (0.0, 5.0, 0.0, 4.0));
    let c = cubic();
    gl.color3f(0.0, 0.0, 0.8);
    sampled(gl, 60, |t| [c.eval(t)[0], c.eval(t)[1]]);
    gl.begin(GL_LINES);
    for i in 0..=24 {
        let t = f64::from(i) / 24.0;
        let (Some(f), p) = (c.frenet(t), c.eval(t)) else { continue };
        // The curvature comb: κ·N, scaled, inwards; the tangent in grey.
        gl.color3f(0.9, 0.3, 0.0);
        gl.vertex2f(p[0] as f32, p[1] as f32);
        let k = 0.8 * f.curvature;
        gl.vertex2f((p[0] + k * f.normal[0]) as f32, (p[1] + k * f.normal[1]) as f32);
        gl.color3f(0.5, 0.5, 0.5);
        gl.vertex2f(p[0] as f32, p[1] as f32);
        gl.vertex2f((p[0] + 0.3 * f.tangent[0]) as f32, (p[1] + 0.3 * f.tangent[1]) as f32);
    }
    gl.end();
}

fn circle(gl: &mut Gl) {
    view(gl, 4, (-1.8, 1.8, -1.2, 1.2)); // the viewport's 3:2
    let c = nurbs_circle([0.0, 0.0, 0.0], 1.0).expect("a circle");
    let projected: Vec<f64> = c.points.chunks(4).flat_map(|p| [p[0] / p[3], p[1] / p[3]]).collect();
    gl.color3f(0.6, 0.6, 0.6);
    strip(gl, &projected, 2, GL_LINE_STRIP);
    gl.color3f(0.9, 0.2, 0.0);
    strip(gl, &projected, 2, GL_POINTS);
    gl.color3f(0.0, 0.0, 0.8);
    sampled(gl, 120, |t| {
        let p = c.eval_rational(t).unwrap_or_default();
        [p[0], p[1]]
    });
}

/// A perspective view in viewport `k` for a lit NURBS surface.
fn lit_view(gl: &mut Gl, k: i32, tilt: f32) {
    let (x, y, w, h) = panel(gl, k);
    gl.viewport(x, y, w, h);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(30.0, f64::from(w) / f64::from(h), 1.0, 50.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -11.0);
    gl.rotatef(tilt, 1.0, 0.0, 0.0);
    gl.translatef(0.0, 0.0, -1.5);
    gl.enable(GL_LIGHTING);
    gl.enable(GL_LIGHT0);
    gl.enable(GL_DEPTH_TEST);
    gl.enable(GL_AUTO_NORMAL);
    gl.enable(GL_NORMALIZE);
    gl.light_model_i(GL_LIGHT_MODEL_TWO_SIDE, 1);
}

/// A homogeneous B-spline surface through GLU, then lighting off again.
fn draw_nurbs_surface(gl: &mut Gl, s: &BSplineSurface<f64>, color: [f32; 4]) {
    let (nu, nv) = s.control_counts();
    let f32s = |v: &[f64]| v.iter().map(|&x| x as f32).collect::<Vec<f32>>();
    gl.material_fv(GL_FRONT_AND_BACK, GL_DIFFUSE, &color);
    let nurb = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(nurb, GLU_SAMPLING_TOLERANCE, 10.0);
    gl.glu_begin_surface(nurb);
    gl.glu_nurbs_surface(
        nurb,
        (nu + s.uorder) as i32,
        &f32s(&s.uknots.knots),
        (nv + s.vorder) as i32,
        &f32s(&s.vknots.knots),
        (nv * 4) as i32,
        4,
        &f32s(&s.points),
        s.uorder as i32,
        s.vorder as i32,
        GL_MAP2_VERTEX_4,
    );
    gl.glu_end_surface(nurb);
    gl.glu_delete_nurbs_renderer(nurb);
    gl.disable(GL_LIGHTING);
    gl.disable(GL_DEPTH_TEST);
}

fn vase(gl: &mut Gl) {
    lit_view(gl, 5, -70.0);
    // The profile in the xz plane: radius against height.
    let profile = [0.9, 0.0, 0.0, 1.4, 0.0, 0.6, 0.5, 0.0, 1.6, 0.6, 0.0, 2.4, 1.1, 0.0, 3.0];
    let knots = KnotVector::new(vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0]);
    let curve = BSplineCurve::try_new(3, 4, knots, profile.to_vec()).expect("a profile");
    draw_nurbs_surface(gl, &revolve(&curve).expect("a surface of revolution"), [0.3, 0.5, 0.9, 1.0]);
}

fn reduction(gl: &mut Gl) {
    view(gl, 6, (0.0, 5.0, 0.0, 4.0));
    let quartic = BezierCurve::try_new(2, vec![0.5, 0.5, 1.0, 3.8, 2.5, 0.5, 4.0, 3.8, 4.5, 0.5]).expect("a quartic");
    let cubic = quartic.reduce().expect("order 5");
    for (c, color) in [(&quartic, [0.0, 0.0, 0.8]), (&cubic, [0.9, 0.3, 0.0])] {
        gl.color3f(0.7, 0.7, 0.7);
        strip(gl, &c.points, 2, GL_LINE_STRIP);
        gl.color3f(color[0], color[1], color[2]);
        strip(gl, &c.points, 2, GL_POINTS);
        sampled(gl, 80, |t| [c.eval(t)[0], c.eval(t)[1]]);
    }
}

fn refinement(gl: &mut Gl) {
    view(gl, 7, (-0.3, 5.3, -2.4, 2.4));
    let pts = vec![0.0, 0.0, 1.0, -2.0, 2.0, 0.0, 3.0, 2.0, 4.0, 0.0, 5.0, -2.0];
    let mut curve = BSplineCurve::try_new(2, 4, KnotVector::open_uniform(6, 4).expect("knots"), pts).expect("a cubic");
    for (round, grey) in [(0, 0.2f32), (1, 0.5), (3, 0.75)] {
        while curve.control_count() < 6 * (1 << round) - 3 * ((1 << round) - 1) {
            // Midpoints of every non-empty knot span, inserted once each.
            let k = curve.knots.knots.clone();
            let mids: Vec<f64> = k.windows(2).filter(|w| w[1] > w[0]).map(|w| 0.5 * (w[0] + w[1])).collect();
            for m in mids {
                curve = curve.insert_knot(m, 1).expect("inside the range");
            }
        }
        gl.color3f(grey, grey, grey);
        strip(gl, &curve.points, 2, GL_LINE_STRIP);
    }
    let (a, b) = curve.valid_range().expect("a range");
    gl.color3f(0.0, 0.0, 0.8);
    sampled(gl, 120, |t| {
        let p = curve.eval(a + (b - a) * t).unwrap_or_default();
        [p[0], p[1]]
    });
}

fn hermite(gl: &mut Gl) {
    view(gl, 8, (-0.5, 6.0, -1.0, 7.0));
    let c = HermiteCurve { p0: [0.0, 0.0], p1: [5.0, 6.0], t0: [3.0, 8.0], t1: [5.0, 1.0] };
    gl.color3f(0.0, 0.0, 0.8);
    sampled(gl, 80, |u| c.eval(u));
    gl.color3f(0.9, 0.3, 0.0);
    let (s0, s1) = (0.25, 0.25);
    strip(gl, &[0.0, 0.0, s0 * 3.0, s0 * 8.0, 5.0, 6.0, 5.0 + s1 * 5.0, 6.0 + s1 * 1.0], 2, GL_LINES);
    gl.color3f(0.0, 0.0, 0.0);
    strip(gl, &[0.0, 0.0, 5.0, 6.0], 2, GL_POINTS);
    // The exercise's value p(0.5) = (2.25, 3.875).
    gl.color3f(0.0, 0.6, 0.2);
    let m = c.eval(0.5);
    strip(gl, &m, 2, GL_POINTS);
}

fn tube(gl: &mut Gl) {
    lit_view(gl, 9, -60.0);
    let ring = nurbs_circle([0.0, 0.0, 0.0], 1.0).expect("a circle");
    draw_nurbs_surface(gl, &extrude(&ring, [0.0, 0.0, 2.5]).expect("a tube"), [0.9, 0.6, 0.2, 1.0]);
}

const BLACK: [f32; 3] = [0.0, 0.0, 0.0];
const BLUE: [f32; 3] = [0.0, 0.0, 0.8];
const ORANGE: [f32; 3] = [0.9, 0.3, 0.0];
const GREEN: [f32; 3] = [0.0, 0.6, 0.2];
const GREY: [f32; 3] = [0.45, 0.45, 0.45];

/// Each panel and its caption: pieces of text, each in the colour of what it names.
type Panel = (fn(&mut Gl), &'static [(&'static str, [f32; 3])]);

const PANELS: [Panel; 10] = [
    (
        subdivision,
        &[
            ("subdivision at u = 1/2: ", BLACK),
            ("left", ORANGE),
            (" and ", BLACK),
            ("right", GREEN),
            (" halves", BLACK),
        ],
    ),
    (elevation, &[("degree elevation: ", BLACK), ("0, 2, 8, 32 times", GREY)]),
    (
        interpolation,
        &[
            ("interpolation: ", BLACK),
            ("uniform", [0.9, 0.2, 0.0]),
            (", ", BLACK),
            ("chord", GREEN),
            (", ", BLACK),
            ("centripetal", [0.1, 0.2, 0.9]),
        ],
    ),
    (frenet, &[("Frenet frames: ", BLACK), ("tangents", GREY), (", ", BLACK), ("curvature comb", ORANGE)]),
    (circle, &[("the exact NURBS circle and its control polygon", BLACK)]),
    (vase, &[("a vase: a surface of revolution", BLACK)]),
    (reduction, &[("degree reduction: ", BLACK), ("quartic", BLUE), (" to ", BLACK), ("cubic", ORANGE)]),
    (refinement, &[("knot refinement: ", BLACK), ("0, 1, 3 rounds", GREY)]),
    (hermite, &[("Hermite segment, ", BLACK), ("end tangents", ORANGE), (", ", BLACK), ("p(1/2)", GREEN)]),
    (tube, &[("a tube extruded from the NURBS circle", BLACK)]),
];

/// Panel `k`'s caption, centred in the strip under its drawing, in GLUT's Helvetica 12.
fn caption(gl: &mut Gl, k: i32, pieces: &[(&str, [f32; 3])]) {
    let (x, y, w, _) = panel(gl, k);
    gl.viewport(x, y - CAPTION, w, CAPTION);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(0.0, f64::from(w), 0.0, f64::from(CAPTION));
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    let font = GLUT_BITMAP_HELVETICA_12;
    let width: i32 = pieces.iter().map(|(text, _)| gl.glut_bitmap_length(font, text)).sum();
    let mut left = (w - width) / 2;
    for &(text, [r, g, b]) in pieces {
        // The raster position takes the colour current when it is set.
        gl.color3f(r, g, b);
        gl.raster_pos2i(left, 5);
        gl.glut_bitmap_string(font, text);
        left += gl.glut_bitmap_length(font, text);
    }
}

fn paint(gl: &mut Gl) {
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.line_width(1.5);
    gl.point_size(5.0);
    for (k, (draw, text)) in (0..).zip(PANELS) {
        draw(gl);
        caption(gl, k, text);
    }
    gl.flush();
}

/// The program, for tests that render it headless.
pub fn app() -> App {
    App::new("曲线与曲面运算", 1200, 3 * (200 + CAPTION)).display(paint)
}

#[allow(dead_code)]
fn main() {
    app().run();
}
