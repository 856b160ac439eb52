//! The interactive demo: drag the control points with the left mouse button and look at the
//! curve as a Bezier curve, a uniform cubic B-spline or a NURBS curve.
//!
//! Keys: `b` Bezier, `s` B-spline, `n` NURBS; `p` control polygon, `c` de Casteljau's
//! construction (Bezier), `h` hodograph (inset, Bezier); `[` `]` fewer/more segments; `,` `.`
//! move the construction's parameter t; `+` `-` the weight of the last point dragged (NURBS).
//! The current state is in the window title. Headless (`--png`), the demo draws its starting
//! state: the Bezier curve with de Casteljau's construction at t = 0.4 and the hodograph.
//!
//! `cargo run --release --example demo`

use gleval::math::BezierCurve;
use gleval::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

/// The scene's world window: x ∈ [0, 10], y ∈ [0, 6].
const WORLD: (f32, f32) = (10.0, 6.0);

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Bezier,
    BSpline,
    Nurbs,
}

struct State {
    points: Vec<[f32; 2]>,
    weights: Vec<f32>,
    kind: Kind,
    polygon: bool,
    casteljau: bool,
    hodograph: bool,
    segments: i32,
    t: f32,
    /// The point being dragged (and the one whose weight `+`/`-` change).
    selected: Option<usize>,
    last: usize,
}

impl State {
    fn new() -> Self {
        let points = vec![[1.0, 1.0], [2.0, 4.5], [4.0, 5.0], [5.0, 2.0], [6.5, 1.0], [8.0, 3.5], [9.0, 5.0]];
        let weights = vec![1.0; points.len()];
        Self {
            points,
            weights,
            kind: Kind::Bezier,
            polygon: true,
            casteljau: true,
            hodograph: true,
            segments: 40,
            t: 0.4,
            selected: None,
            last: 3,
        }
    }

    fn title(&self) -> String {
        let kind = match self.kind {
            Kind::Bezier => "Bezier",
            Kind::BSpline => "uniform cubic B-spline",
            Kind::Nurbs => "NURBS (open uniform, cubic)",
        };
        format!(
            "{kind} | segments {} | t {:.2} | weight of P{} = {:.2} | b s n, p c h, [ ], , ., + -",
            self.segments, self.t, self.last, self.weights[self.last]
        )
    }

    fn flat(&self) -> Vec<f32> {
        self.points.iter().flat_map(|p| [p[0], p[1], 0.0]).collect()
    }
}

fn ortho(gl: &mut Gl, x0: f64, x1: f64, y0: f64, y1: f64) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_ortho_2d(x0, x1, y0, y1);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
}

fn polyline(gl: &mut Gl, pts: &[f32], dim: usize, mode: GLenum) {
    gl.begin(mode);
    for p in pts.chunks(dim) {
        gl.vertex2f(p[0], p[1]);
    }
    gl.end();
}

/// The curve of the current kind through the evaluators (Bezier) or GLU NURBS (the others).
fn draw_curve(gl: &mut Gl, s: &State) {
    let n = s.points.len() as i32;
    gl.color3f(0.0, 0.0, 0.8);
    gl.line_width(2.0);
    match s.kind {
        Kind::Bezier => {
            gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, n, &s.flat());
            gl.enable(GL_MAP1_VERTEX_3);
            gl.map_grid1f(s.segments, 0.0, 1.0);
            gl.eval_mesh1(GL_LINE, 0, s.segments);
        }
        Kind::BSpline => gll::uni_b_curve(gl, n, &s.flat(), 4, 100.0 / s.segments as f32),
        Kind::Nurbs => {
            let hom: Vec<f32> =
                s.points.iter().zip(&s.weights).flat_map(|(p, &w)| [w * p[0], w * p[1], 0.0, w]).collect();
            let mut knots = vec![0.0; (n + 4) as usize];
            gll::open_uniknots(&mut knots, n, 4);
            let nurb = gl.glu_new_nurbs_renderer();
            gl.glu_nurbs_property(nurb, GLU_SAMPLING_TOLERANCE, 100.0 / s.segments as f32);
            gl.glu_begin_curve(nurb);
            gl.glu_nurbs_curve(nurb, n + 4, &knots, 4, &hom, 4, GL_MAP1_VERTEX_4);
            gl.glu_end_curve(nurb);
            gl.glu_delete_nurbs_renderer(nurb);
        }
    }
}

/// De Casteljau's construction at t: every intermediate polygon, lighter as it shrinks, and
/// the point on the curve.
fn draw_casteljau(gl: &mut Gl, bezier: &BezierCurve<f32>, t: f32) {
    let levels = bezier.de_casteljau_levels(t);
    let count = levels.len() as f32;
    gl.line_width(1.0);
    gl.point_size(5.0);
    for (k, level) in levels.iter().enumerate().skip(1) {
        let f = k as f32 / count;
        gl.color3f(0.2 + 0.6 * f, 0.6 * (1.0 - f), 0.2);
        polyline(gl, level, 2, GL_LINE_STRIP);
        polyline(gl, level, 2, GL_POINTS);
    }
    gl.color3f(0.9, 0.0, 0.0);
    gl.point_size(9.0);
    polyline(gl, levels.last().map(Vec::as_slice).unwrap_or_default(), 2, GL_POINTS);
}

/// The hodograph p'(u) in an inset at the bottom right, with the vector p'(t).
fn draw_hodograph(gl: &mut Gl, bezier: &BezierCurve<f32>, t: f32, w: i32, h: i32) {
    let Some(hodo) = bezier.hodograph() else { return };
    let (iw, ih) = (w / 4, h / 3);
    gl.viewport(w - iw - 8, 8, iw, ih);
    let reach = hodo.points.iter().fold(1.0f32, |m, v| m.max(v.abs())) * 1.1;
    ortho(gl, -f64::from(reach), f64::from(reach), -f64::from(reach), f64::from(reach));
    gl.color3f(0.85, 0.85, 0.85);
    polyline(gl, &[-reach, -reach, reach, -reach, reach, reach, -reach, reach], 2, GL_POLYGON);
    gl.color3f(0.5, 0.5, 0.5);
    gl.line_width(1.0);
    polyline(gl, &[-reach, 0.0, reach, 0.0], 2, GL_LINES);
    polyline(gl, &[0.0, -reach, 0.0, reach], 2, GL_LINES);
    let pts: Vec<f32> = hodo.points.chunks(2).flat_map(|p| [p[0], p[1], 0.0]).collect();
    gl.color3f(0.0, 0.5, 0.0);
    gl.line_width(2.0);
    gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, hodo.order() as i32, &pts);
    gl.enable(GL_MAP1_VERTEX_3);
    gl.map_grid1f(40, 0.0, 1.0);
    gl.eval_mesh1(GL_LINE, 0, 40);
    let d = bezier.derivative(t);
    gl.color3f(0.9, 0.0, 0.0);
    polyline(gl, &[0.0, 0.0, d[0], d[1]], 2, GL_LINES);
}

fn paint(gl: &mut Gl, s: &State) {
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH), gl.glut_get(GLUT_WINDOW_HEIGHT));
    gl.clear_color(1.0, 1.0, 1.0, 1.0);
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.viewport(0, 0, w, h);
    ortho(gl, 0.0, f64::from(WORLD.0), 0.0, f64::from(WORLD.1));
    let flat2: Vec<f32> = s.points.iter().flatten().copied().collect();
    if s.polygon {
        gl.color3f(0.6, 0.6, 0.6);
        gl.line_width(1.0);
        polyline(gl, &flat2, 2, GL_LINE_STRIP);
    }
    draw_curve(gl, s);
    let bezier = BezierCurve::try_new(2, flat2.clone()).expect("whole 2D points");
    if s.casteljau && s.kind == Kind::Bezier {
        draw_casteljau(gl, &bezier, s.t);
    }
    gl.color3f(0.0, 0.0, 0.0);
    gl.point_size(8.0);
    polyline(gl, &flat2, 2, GL_POINTS);
    if s.hodograph && s.kind == Kind::Bezier {
        draw_hodograph(gl, &bezier, s.t, w, h);
    }
    gl.flush();
    gl.glut_set_window_title(&s.title());
}

fn key(s: &mut State, key: char) {
    match key {
        'b' => s.kind = Kind::Bezier,
        's' => s.kind = Kind::BSpline,
        'n' => s.kind = Kind::Nurbs,
        'p' => s.polygon = !s.polygon,
        'c' => s.casteljau = !s.casteljau,
        'h' => s.hodograph = !s.hodograph,
        '[' => s.segments = (s.segments / 2).max(2),
        ']' => s.segments = (s.segments * 2).min(1280),
        ',' => s.t = (s.t - 0.05).max(0.0),
        '.' => s.t = (s.t + 0.05).min(1.0),
        '+' | '=' => s.weights[s.last] = (s.weights[s.last] * 1.25).min(50.0),
        '-' => s.weights[s.last] = (s.weights[s.last] / 1.25).max(0.02),
        _ => {}
    }
}

/// Window pixels (origin top left) to world coordinates.
fn to_world(gl: &Gl, x: i32, y: i32) -> [f32; 2] {
    let (w, h) = (gl.glut_get(GLUT_WINDOW_WIDTH).max(1), gl.glut_get(GLUT_WINDOW_HEIGHT).max(1));
    [x as f32 / w as f32 * WORLD.0, (h - y) as f32 / h as f32 * WORLD.1]
}

fn mouse(gl: &mut Gl, s: &mut State, button: i32, state: i32, x: i32, y: i32) {
    if button != GLUT_LEFT_BUTTON {
        return;
    }
    if state == GLUT_UP {
        s.selected = None;
        return;
    }
    let at = to_world(gl, x, y);
    let distance = |p: &[f32; 2]| (p[0] - at[0]).hypot(p[1] - at[1]);
    s.selected = s
        .points
        .iter()
        .enumerate()
        .map(|(k, p)| (k, distance(p)))
        .filter(|&(_, d)| d < 0.3)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(k, _)| k);
    if let Some(k) = s.selected {
        s.last = k;
    }
}

/// The program; the state is shared by the callbacks.
pub fn app() -> App {
    let state = Rc::new(RefCell::new(State::new()));
    let (s1, s2, s3, s4) = (Rc::clone(&state), Rc::clone(&state), Rc::clone(&state), state);
    App::new("gleval demo", 800, 480)
        .display(move |gl| paint(gl, &s1.borrow()))
        .keyboard(move |_, k, _, _| key(&mut s2.borrow_mut(), k))
        .mouse(move |gl, b, st, x, y| mouse(gl, &mut s3.borrow_mut(), b, st, x, y))
        .motion(move |gl, x, y| {
            let mut s = s4.borrow_mut();
            if let Some(k) = s.selected {
                s.points[k] = to_world(gl, x, y);
            }
        })
}

#[allow(dead_code)]
fn main() {
    app().run();
}
