//! GLU's tessellation of trimmed surfaces along its rarer ways (`sampleMonoPoly`'s thin and
//! convex regions, interior cusps that need a diagonal, `monoPolyPart`): the cases of
//! `tests/reference/glu/trimcases.c`, which prints each case's inputs ("@" lines: the surface,
//! its sampling and callbacks, every trim curve) and then what real GLU hands to the
//! `GLU_NURBS_TESSELLATOR` callbacks. Each case's inputs are read back here, drawn through
//! gleval and printed the same way; the text must be identical. No case may take gleval's own
//! triangulation (the fallback for regions GLU itself mishandles).

use gleval::prelude::*;
use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;

/// One case of the reference: its name, its "@" lines and GLU's output.
struct Case {
    name: String,
    inputs: Vec<String>,
    glu: String,
}

/// The committed cases, or those of the file `GLEVAL_TRIMCASES` names (`trimcases random SEED
/// COUNT` prints random ones, to search wider).
fn cases() -> Vec<Case> {
    let committed = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu/trimcases.txt");
    let path = std::env::var_os("GLEVAL_TRIMCASES").map_or(committed, Into::into);
    let text = std::fs::read_to_string(path).expect("trimcases.txt");
    let mut cases: Vec<Case> = Vec::new();
    for line in text.lines() {
        if let Some(name) = line.strip_prefix("# ") {
            cases.push(Case { name: name.to_string(), inputs: Vec::new(), glu: String::new() });
        } else if let Some(case) = cases.last_mut() {
            if let Some(input) = line.strip_prefix("@ ") {
                case.inputs.push(input.to_string());
            } else {
                case.glu.push_str(line);
                case.glu.push('\n');
            }
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

fn floats(words: &[&str]) -> Vec<f32> {
    words.iter().map(|w| w.parse().expect("a float")).collect()
}

/// The surfaces of trimcases.c.
fn surface(gl: &mut Gl, n: GLUnurbs, shape: &str) {
    const BEZIER_KNOTS: [f32; 8] = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    match shape {
        "hill" => {
            let mut hill = Vec::new();
            for u in 0..4 {
                for v in 0..4 {
                    let inside = (u == 1 || u == 2) && (v == 1 || v == 2);
                    hill.extend([2.0 * (u as f32 - 1.5), 2.0 * (v as f32 - 1.5), if inside { 3.0 } else { -3.0 }]);
                }
            }
            gl.glu_nurbs_surface(n, 8, &BEZIER_KNOTS, 8, &BEZIER_KNOTS, 12, 3, &hill, 4, 4, GL_MAP2_VERTEX_3);
        }
        "cylinder" => {
            // The C program's literal 0.7071f, not 1/√2.
            #[allow(clippy::approx_constant)]
            let w = 0.7071;
            let cyl = [
                [1.0, 0.0, -1.0, 1.0, 1.0, 0.0, 1.0, 1.0],
                [w, w, -w, w, w, w, w, w],
                [0.0, 1.0, -1.0, 1.0, 0.0, 1.0, 1.0, 1.0],
            ]
            .concat();
            let (uk, vk) = ([0.0, 0.0, 0.0, 1.0, 1.0, 1.0], [0.0, 0.0, 1.0, 1.0]);
            gl.glu_nurbs_surface(n, 6, &uk, 4, &vk, 8, 4, &cyl, 3, 2, GL_MAP2_VERTEX_4);
        }
        "sheet" => {
            let knots: Vec<f32> = (0..9).map(|i| i as f32).collect();
            let mut sheet = Vec::new();
            for i in 0..5 {
                for j in 0..5 {
                    let z = ((i * 3 + j * 5) % 7) as f32 / 3.5 - 1.0;
                    sheet.extend([-3.0 + i as f32 * 1.5, -3.0 + j as f32 * 1.5, z]);
                }
            }
            gl.glu_nurbs_surface(n, 9, &knots, 9, &knots, 15, 3, &sheet, 4, 4, GL_MAP2_VERTEX_3);
        }
        other => panic!("unknown surface {other}"),
    }
}

/// A bilinear colour map over [0, 1]².
const COLOURS: [f32; 16] = [1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.5];

/// How a run prints: as trimcases.c, or every vertex value's bits (with `slow`, a texture
/// coordinate callback is registered too, which no case has a map for: it adds nothing, but
/// takes the vertices off the fast path that evaluates them ahead on the thread pool).
#[derive(Clone, Copy, PartialEq)]
enum Print {
    AsGlu,
    Bits { slow: bool },
}

fn callbacks(gl: &mut Gl, n: GLUnurbs, normals: bool, colour: bool, print: Print) -> Rc<RefCell<String>> {
    let out = Rc::new(RefCell::new(String::new()));
    let o = Rc::clone(&out);
    let begin = NurbsCallback::begin(move |_, t| o.borrow_mut().push_str(&format!("glBegin({})\n", prim(t))));
    gl.glu_nurbs_callback(n, GLU_NURBS_BEGIN, Some(begin));
    let o = Rc::clone(&out);
    let vertex = if print == Print::AsGlu {
        NurbsCallback::vertex(move |_, v| {
            o.borrow_mut().push_str(&format!("glVertex3f ({:.3}, {:.3}, {:.3})\n", v[0], v[1], v[2]))
        })
    } else {
        NurbsCallback::vertex(move |_, v| o.borrow_mut().push_str(&format!("{:08x?}\n", v.iter().map(|x| x.to_bits()))))
    };
    gl.glu_nurbs_callback(n, GLU_NURBS_VERTEX, Some(vertex));
    if print == (Print::Bits { slow: true }) {
        gl.glu_nurbs_callback(n, GLU_NURBS_TEXTURE_COORD, Some(NurbsCallback::tex_coord(|_, _| {})));
    }
    if normals {
        let o = Rc::clone(&out);
        let normal = NurbsCallback::normal(move |_, v| {
            o.borrow_mut().push_str(&format!("glNormal3f ({:.3}, {:.3}, {:.3})\n", v[0], v[1], v[2]))
        });
        gl.glu_nurbs_callback(n, GLU_NURBS_NORMAL, Some(normal));
    }
    if colour {
        let o = Rc::clone(&out);
        let color = NurbsCallback::color(move |_, v| {
            o.borrow_mut().push_str(&format!("glColor4f ({:.3}, {:.3}, {:.3}, {:.3})\n", v[0], v[1], v[2], v[3]))
        });
        gl.glu_nurbs_callback(n, GLU_NURBS_COLOR, Some(color));
    }
    let o = Rc::clone(&out);
    gl.glu_nurbs_callback(n, GLU_NURBS_END, Some(NurbsCallback::end(move |_| o.borrow_mut().push_str("glEnd()\n"))));
    let o = Rc::clone(&out);
    let error = NurbsCallback::error(move |e| o.borrow_mut().push_str(&format!("error {e}\n")));
    gl.glu_nurbs_callback(n, GLU_NURBS_ERROR, Some(error));
    out
}

/// Draws a case's inputs through gleval and prints the callbacks as trimcases.c does.
fn run(inputs: &[String]) -> String {
    run_printing(inputs, Print::AsGlu)
}

fn run_printing(inputs: &[String], print: Print) -> String {
    let head: Vec<&str> = inputs[0].split_whitespace().collect();
    // surface SHAPE METHOD TOLERANCE STEP viewport SIZE normals N colour N outline N
    assert_eq!(head[0], "surface");
    let (shape, method) = (head[1], head[2]);
    let (tolerance, step) = (head[3].parse().expect("tolerance"), head[4].parse().expect("step"));
    let size: i32 = head[6].parse().expect("viewport");
    let flag = |i: usize| head[i] == "1";
    let (normals, colour, outline) = (flag(8), flag(10), flag(12));
    let mut gl = Gl::new(500, 500);
    gl.viewport(0, 0, size, size);
    let n = gl.glu_new_nurbs_renderer();
    gl.glu_nurbs_property(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    let m = if method == "path_length" { GLU_PATH_LENGTH } else { GLU_DOMAIN_DISTANCE };
    gl.glu_nurbs_property(n, GLU_SAMPLING_METHOD, m as f32);
    gl.glu_nurbs_property(n, GLU_SAMPLING_TOLERANCE, tolerance);
    gl.glu_nurbs_property(n, GLU_U_STEP, step);
    gl.glu_nurbs_property(n, GLU_V_STEP, step);
    let mode = if outline { GLU_OUTLINE_POLYGON } else { GLU_FILL };
    gl.glu_nurbs_property(n, GLU_DISPLAY_MODE, mode as f32);
    let out = callbacks(&mut gl, n, normals, colour, print);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.glu_perspective(45.0, 1.0, 3.0, 8.0);
    gl.matrix_mode(GL_MODELVIEW);
    gl.load_identity();
    gl.translatef(0.0, 0.0, -5.0);
    gl.rotatef(330.0, 1.0, 0.0, 0.0);
    gl.scalef(0.5, 0.5, 0.5);
    gl.glu_begin_surface(n);
    surface(&mut gl, n, shape);
    if colour {
        let k = [0.0, 0.0, 1.0, 1.0];
        gl.glu_nurbs_surface(n, 4, &k, 4, &k, 8, 4, &COLOURS, 2, 2, GL_MAP2_COLOR_4);
    }
    let mut open = false;
    for input in &inputs[1..] {
        let words: Vec<&str> = input.split_whitespace().collect();
        match words[0] {
            "loop" => {
                if open {
                    gl.glu_end_trim(n);
                }
                gl.glu_begin_trim(n);
                open = true;
            }
            "pwl" => {
                let pts = floats(&words[1..]);
                gl.glu_pwl_curve(n, (pts.len() / 2) as i32, &pts, 2, GLU_MAP1_TRIM_2);
            }
            "nurbs" => {
                let (order, dim): (i32, i32) = (words[1].parse().expect("order"), words[2].parse().expect("dim"));
                let colon = words.iter().position(|w| *w == ":").expect("knots : points");
                let (knots, pts) = (floats(&words[3..colon]), floats(&words[colon + 1..]));
                let kind = if dim == 3 { GLU_MAP1_TRIM_3 } else { GLU_MAP1_TRIM_2 };
                gl.glu_nurbs_curve(n, knots.len() as i32, &knots, dim, &pts, order, kind);
            }
            other => panic!("unknown input {other}"),
        }
    }
    if open {
        gl.glu_end_trim(n);
    }
    gl.glu_end_surface(n);
    gl.glu_delete_nurbs_renderer(n);
    let text = out.borrow().clone();
    text
}

#[test]
fn trimmed_tessellation_is_glus_line_for_line_without_fallback() {
    let mut diffs = Vec::new();
    for case in cases() {
        let before = gleval::testing::trim_fallbacks();
        let ours = run(&case.inputs);
        let fell_back = gleval::testing::trim_fallbacks() - before;
        if fell_back > 0 {
            diffs.push(format!("{}: took gleval's own triangulation", case.name));
        }
        if ours != case.glu {
            let lines = ours.lines().zip(case.glu.lines()).filter(|(a, b)| a != b).count();
            let (mut a, mut b) = (ours.lines().map(Some).chain([None]), case.glu.lines().map(Some).chain([None]));
            let first = (0..).zip(a.by_ref().zip(b.by_ref())).find(|(_, (a, b))| a != b);
            diffs.push(format!(
                "{}: glu {} lines / ours {}; {lines} differ, first {first:?}",
                case.name,
                case.glu.lines().count(),
                ours.lines().count()
            ));
        }
    }
    assert!(diffs.is_empty(), "{} cases:\n{}", diffs.len(), diffs.join("\n"));
}

/// With only begin, vertex and end callbacks gleval evaluates the vertices on the thread pool
/// ahead of the callbacks: every case's vertices are those of the vertex-by-vertex path, to
/// the bit (x, y, z, u, v).
#[test]
fn vertices_evaluated_ahead_are_the_exact_paths_to_the_bit() {
    let mut diffs = Vec::new();
    for case in cases() {
        let fast = run_printing(&case.inputs, Print::Bits { slow: false });
        let slow = run_printing(&case.inputs, Print::Bits { slow: true });
        if fast != slow {
            diffs.push(case.name.clone());
        }
    }
    assert!(diffs.is_empty(), "{} cases differ: {}", diffs.len(), diffs.join(", "));
}
