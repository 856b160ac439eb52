//! GLU's tessellation, primitive for primitive: the cases of
//! `tests/reference/glu/surfpoints.c`, which prints what real GLU hands to the
//! `GLU_NURBS_TESSELLATOR` callbacks (`glBegin(...)`, `glNormal3f`, `glVertex3f`, `glEnd()`, 3
//! decimals, as the Red Book's surfpoints.c), run through gleval and printed the same way:
//! untrimmed and trimmed surfaces, outlines (of many patches, and trimmed) and curves. The
//! text must be identical, case by case, the sign of zero included, and no case may take
//! gleval's own triangulation of trimmed regions.

use gleval::prelude::*;
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::path::Path;
use std::rc::Rc;

fn reference() -> BTreeMap<String, String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu/surfpoints.txt");
    let text = std::fs::read_to_string(path).expect("surfpoints.txt");
    let mut cases = BTreeMap::new();
    let mut name = String::new();
    for line in text.lines() {
        if let Some(n) = line.strip_prefix("# ") {
            name = n.to_string();
            cases.insert(name.clone(), String::new());
        } else if let Some(body) = cases.get_mut(&name) {
            body.push_str(line);
            body.push('\n');
        }
    }
    cases
}

fn prim(t: u32) -> &'static str {
    match t {
        GL_TRIANGLE_FAN => "GL_TRIANGLE_FAN",
        GL_QUAD_STRIP => "GL_QUAD_STRIP",
        GL_TRIANGLE_STRIP => "GL_TRIANGLE_STRIP",
        GL_TRIANGLES => "GL_TRIANGLES",
        GL_LINE_STRIP => "GL_LINE_STRIP",
        GL_LINE_LOOP => "GL_LINE_LOOP",
        _ => "?",
    }
}

fn nurbs(gl: &mut Gl, method: u32, tolerance: f32, step: f32, normals: bool) -> (GLUnurbs, Rc<RefCell<String>>) {
    let n = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    gl.glu_nurbs_property(n, GLU_SAMPLING_METHOD, method as f32);
    gl.glu_nurbs_property(n, GLU_SAMPLING_TOLERANCE, tolerance);
    gl.glu_nurbs_property(n, GLU_PARAMETRIC_TOLERANCE, tolerance);
    gl.glu_nurbs_property(n, GLU_U_STEP, step);
    gl.glu_nurbs_property(n, GLU_V_STEP, step);
    let out = Rc::new(RefCell::new(String::new()));
    let o = Rc::clone(&out);
    let begin = NurbsCallback::begin(move |_, t| o.borrow_mut().push_str(&format!("glBegin({})\n", prim(t))));
    gl.glu_nurbs_callback(n, GLU_NURBS_BEGIN, Some(begin));
    let o = Rc::clone(&out);
    let vertex = NurbsCallback::vertex(move |_, v| {
        o.borrow_mut().push_str(&format!("glVertex3f ({:.3}, {:.3}, {:.3})\n", v[0], v[1], v[2]))
    });
    gl.glu_nurbs_callback(n, GLU_NURBS_VERTEX, Some(vertex));
    if normals {
        let o = Rc::clone(&out);
        let normal = NurbsCallback::normal(move |_, v| {
            o.borrow_mut().push_str(&format!("glNormal3f ({:.3}, {:.3}, {:.3})\n", v[0], v[1], v[2]))
        });
        gl.glu_nurbs_callback(n, GLU_NURBS_NORMAL, Some(normal));
    }
    let o = Rc::clone(&out);
    gl.glu_nurbs_callback(n, GLU_NURBS_END, Some(NurbsCallback::end(move |_| o.borrow_mut().push_str("glEnd()\n"))));
    (n, out)
}

/// surface.c's view: gluPerspective(45, 1, 3, 8), 5 units away, 330° about x, halved.
fn view(gl: &mut Gl) {
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(45.0, 1.0, 3.0, 8.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -5.0);
    gl.rotatef(330.0, 1.0, 0.0, 0.0);
    gl.scalef(0.5, 0.5, 0.5);
}

const BEZIER_KNOTS: [f32; 8] = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];

fn hill() -> Vec<f32> {
    let mut out = Vec::new();
    for u in 0..4 {
        for v in 0..4 {
            let inside = (u == 1 || u == 2) && (v == 1 || v == 2);
            out.extend([2.0 * (u as f32 - 1.5), 2.0 * (v as f32 - 1.5), if inside { 3.0 } else { -3.0 }]);
        }
    }
    out
}

fn sheet() -> (Vec<f32>, Vec<f32>) {
    let knots = (0..14).map(|i| i as f32).collect();
    let mut out = Vec::new();
    for i in 0..10 {
        for j in 0..10 {
            let z = ((i * 3 + j * 5) % 7) as f32 / 3.5 - 1.0;
            out.extend([-3.0 + i as f32 * (2.0 / 3.0), -3.0 + j as f32 * (2.0 / 3.0), z]);
        }
    }
    (knots, out)
}

// The C program's literals (0.7071f, 1.4142f), not 1/√2 and √2: the same floats as GLU got.
#[allow(clippy::approx_constant)]
const CYL: [f32; 24] = [
    1.0, 0.0, -1.0, 1.0, 1.0, 0.0, 1.0, 1.0, 0.7071, 0.7071, -0.7071, 0.7071, 0.7071, 0.7071, 0.7071, 0.7071, 0.0, 1.0,
    -1.0, 1.0, 0.0, 1.0, 1.0, 1.0,
];
const TWIST: [f32; 12] = [-2.0, -2.0, 0.0, -2.0, 2.0, 1.0, 2.0, -2.0, 1.0, 2.0, 2.0, -1.0];
const CURVE_KNOTS: [f32; 12] = [0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0, 5.0];
const CURVE: [f32; 24] = [
    -3.0, 0.0, 0.0, -2.0, 2.0, 0.0, -1.0, -2.0, 0.0, 0.0, 2.0, 0.0, 1.0, -2.0, 0.0, 2.0, 2.0, 0.0, 3.0, 0.0, 0.0, 3.6,
    1.0, 0.0,
];
#[allow(clippy::approx_constant)]
const ARC: [f32; 12] = [2.0, 0.0, 0.0, 1.0, 1.4142, 1.4142, 0.0, 0.7071, 0.0, 2.0, 0.0, 1.0];

/// (shape, method, tolerance, step, normals) of a surface case from its name.
fn surface_case(name: &str) -> (&str, u32, f32, f32, bool) {
    let (shape, rest) = name.split_once('_').expect("shape_method");
    let (method, value) = rest.rsplit_once('_').expect("method_value");
    let value: f32 = value.parse().expect("value");
    let m = method_enum(method);
    let (tolerance, step) = if m == GLU_DOMAIN_DISTANCE { (50.0, value) } else { (value, 100.0) };
    // Without a normal callback (GLU's plain vertex path; for domain distance, gleval's
    // parallel grid path).
    let without = [
        "hill_parametric_error_4",
        "hill_object_parametric_error_0.1",
        "hill_path_length_12",
        "hill_domain_distance_9",
        "sheet_domain_distance_3",
        "hillhole_path_length_120",
        "hillhole_domain_distance_3",
        "hillredbook_domain_distance_6",
        "sheethole_domain_distance_3",
    ];
    let normals = !without.contains(&name) && name != "sheet_path_length_12";
    (shape, m, tolerance, step, normals)
}

fn method_enum(method: &str) -> u32 {
    match method {
        "path_length" => GLU_PATH_LENGTH,
        "parametric_error" => GLU_PARAMETRIC_ERROR,
        "object_path_length" => GLU_OBJECT_PATH_LENGTH,
        "object_parametric_error" => GLU_OBJECT_PARAMETRIC_ERROR,
        "domain_distance" => GLU_DOMAIN_DISTANCE,
        other => panic!("unknown method {other}"),
    }
}

fn run_surface(name: &str, display_mode: u32) -> String {
    let (shape, method, tolerance, step, normals) = surface_case(name);
    let normals = normals && display_mode == GLU_FILL;
    let mut gl = Gl::new(500, 500);
    gl.viewport(0, 0, 500, 500);
    let (n, out) = nurbs(&mut gl, method, tolerance, step, normals);
    gl.glu_nurbs_property(n, GLU_DISPLAY_MODE, display_mode as f32);
    view(&mut gl);
    gl.glu_begin_surface(n);
    let (shape, trim) = split_trim(shape);
    match shape {
        "hill" => gl.glu_nurbs_surface(n, 8, &BEZIER_KNOTS, 8, &BEZIER_KNOTS, 12, 3, &hill(), 4, 4, GL_MAP2_VERTEX_3),
        "sheet" => {
            let (knots, points) = sheet();
            gl.glu_nurbs_surface(n, 14, &knots, 14, &knots, 30, 3, &points, 4, 4, GL_MAP2_VERTEX_3)
        }
        "cylinder" => {
            let (uk, vk) = ([0.0, 0.0, 0.0, 1.0, 1.0, 1.0], [0.0, 0.0, 1.0, 1.0]);
            gl.glu_nurbs_surface(n, 6, &uk, 4, &vk, 8, 4, &CYL, 3, 2, GL_MAP2_VERTEX_4)
        }
        "twist" => {
            let k = [0.0, 0.0, 1.0, 1.0];
            gl.glu_nurbs_surface(n, 4, &k, 4, &k, 6, 3, &TWIST, 2, 2, GL_MAP2_VERTEX_3)
        }
        other => panic!("unknown shape {other}"),
    }
    trims(&mut gl, n, shape, trim);
    gl.glu_end_surface(n);
    gl.glu_delete_nurbs_renderer(n);
    let text = out.borrow().clone();
    text
}

/// "hillhole" -> ("hill", "hole"): the surface and its trim loops.
fn split_trim(shape: &str) -> (&str, &str) {
    ["hill", "sheet", "cylinder", "twist"]
        .into_iter()
        .find_map(|s| shape.strip_prefix(s).map(|trim| (s, trim)))
        .expect("known shape")
}

fn pwl_loop(gl: &mut Gl, n: GLUnurbs, pts: &[[f32; 2]]) {
    gl.glu_begin_trim(n);
    gl.glu_pwl_curve(n, pts.len() as i32, pts.as_flattened(), 2, GLU_MAP1_TRIM_2);
    gl.glu_end_trim(n);
}

/// The domain's border, counter-clockwise, from (a, a) to (b, b).
fn border(gl: &mut Gl, n: GLUnurbs, a: f32, b: f32) {
    pwl_loop(gl, n, &[[a, a], [b, a], [b, b], [a, b], [a, a]]);
}

/// A clockwise square hole [a, b] × [c, d].
fn hole(gl: &mut Gl, n: GLUnurbs, (a, b): (f32, f32), (c, d): (f32, f32)) {
    pwl_loop(gl, n, &[[a, c], [a, d], [b, d], [b, c], [a, c]]);
}

/// The trim loops of surfpoints.c's `trims` (and the sheet's hole).
fn trims(gl: &mut Gl, n: GLUnurbs, shape: &str, trim: &str) {
    match (shape, trim) {
        (_, "") => {}
        ("sheet", "hole") => {
            border(gl, n, 3.0, 10.0);
            hole(gl, n, (4.5, 8.2), (5.3, 7.5));
        }
        (_, "hole") => {
            border(gl, n, 0.0, 1.0);
            hole(gl, n, (0.25, 0.75), (0.25, 0.75));
        }
        (_, "island") => {
            border(gl, n, 0.0, 1.0);
            hole(gl, n, (0.2, 0.8), (0.2, 0.8));
            border(gl, n, 0.4, 0.6);
        }
        (_, "notch") => {
            let notch = [
                [0.0, 0.0],
                [0.3, 0.0],
                [0.3, 0.4],
                [0.7, 0.4],
                [0.7, 0.0],
                [1.0, 0.0],
                [1.0, 1.0],
                [0.0, 1.0],
                [0.0, 0.0],
            ];
            pwl_loop(gl, n, &notch);
        }
        (_, "diamond") => {
            border(gl, n, 0.0, 1.0);
            pwl_loop(gl, n, &[[0.5, 0.2], [0.2, 0.5], [0.5, 0.8], [0.8, 0.5], [0.5, 0.2]]);
        }
        (_, "redbook") => {
            // The Red Book's trim.c: a hole of a cubic NURBS arc and a pwl arc.
            border(gl, n, 0.0, 1.0);
            let curve = [0.25, 0.5, 0.25, 0.75, 0.75, 0.75, 0.75, 0.5];
            gl.glu_begin_trim(n);
            gl.glu_nurbs_curve(n, 8, &BEZIER_KNOTS, 2, &curve, 4, GLU_MAP1_TRIM_2);
            gl.glu_pwl_curve(n, 3, &[0.75, 0.5, 0.5, 0.25, 0.25, 0.5], 2, GLU_MAP1_TRIM_2);
            gl.glu_end_trim(n);
        }
        other => panic!("unknown trim {other:?}"),
    }
}

fn run_curve(name: &str) -> String {
    let (shape, rest) = name.split_once('_').expect("shape_method");
    let (method, value) = rest.rsplit_once('_').expect("method_value");
    let value: f32 = value.parse().expect("value");
    let m = method_enum(method);
    let (tolerance, step) = if m == GLU_DOMAIN_DISTANCE { (50.0, value) } else { (value, 100.0) };
    let mut gl = Gl::new(500, 500);
    gl.viewport(0, 0, 500, 500);
    let (n, out) = nurbs(&mut gl, m, tolerance, step, false);
    view(&mut gl);
    gl.glu_begin_curve(n);
    if shape == "arc" {
        gl.glu_nurbs_curve(n, 6, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 4, &ARC, 3, GL_MAP1_VERTEX_4);
    } else {
        gl.glu_nurbs_curve(n, 12, &CURVE_KNOTS, 3, &CURVE, 4, GL_MAP1_VERTEX_3);
    }
    gl.glu_end_curve(n);
    gl.glu_delete_nurbs_renderer(n);
    let text = out.borrow().clone();
    text
}

/// Primitive counts by kind and the vertex count of a printout.
fn summary(text: &str) -> String {
    let mut kinds: BTreeMap<&str, usize> = BTreeMap::new();
    for l in text.lines().filter(|l| l.starts_with("glBegin(")) {
        *kinds.entry(&l[8..l.len() - 1]).or_default() += 1;
    }
    let vertices = text.lines().filter(|l| l.starts_with("glVertex3f")).count();
    format!("{kinds:?} {vertices} vertices")
}

/// The cases whose output differs, each with its summaries and first differing line.
fn differences() -> Vec<String> {
    let mut out = Vec::new();
    for (case, glu) in reference() {
        let (kind, name) = case.split_once(' ').expect("kind name");
        let before = gleval::testing::trim_fallbacks();
        let (ours, glu) = if kind == "surface" {
            (run_surface(name, GLU_FILL), glu)
        } else if kind == "outline" {
            (run_surface(name, GLU_OUTLINE_PATCH), glu)
        } else {
            (run_curve(name), glu)
        };
        if gleval::testing::trim_fallbacks() != before {
            out.push(format!("{case}: took gleval's own triangulation"));
        }
        if ours == glu {
            continue;
        }
        let lines = ours.lines().zip(glu.lines()).filter(|(a, b)| a != b).count();
        let first = ours.lines().zip(glu.lines()).enumerate().find(|(_, (a, b))| a != b);
        out.push(format!(
            "{case}: glu {} / ours {}; {lines} lines differ, first {first:?}",
            summary(&glu),
            summary(&ours)
        ));
    }
    out
}

#[test]
fn tessellator_output_is_glus_line_for_line() {
    let diffs = differences();
    assert!(diffs.is_empty(), "{}", diffs.join("\n"));
}
