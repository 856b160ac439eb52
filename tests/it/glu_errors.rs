//! GLU NURBS errors: the same scenarios as `tests/reference/glu/nurbs_errors.c`, run on real
//! GLU (its output committed in `nurbs_errors.txt`) and on gleval; the error numbers must be
//! the same, and every message must be GLU's (`error_strings.txt`, from the real
//! `gluErrorString`).

use gleval::prelude::*;
use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;

fn reference(name: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu").join(name))
        .expect("reference file")
}

const KNOTS8: [f32; 8] = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
const TRIM_SQUARE: [f32; 10] = [0.2, 0.2, 0.8, 0.2, 0.8, 0.8, 0.2, 0.8, 0.2, 0.2];

fn ctl() -> Vec<f32> {
    (0..64 * 4).map(|i| ((i * 7) % 5) as f32 * 0.1).collect()
}

/// A context and a NURBS object whose error callback records what it receives as the C
/// program prints it: n for GLU_NURBS_ERRORn, else the code in hex.
fn fresh() -> (Gl, GLUnurbs, Rc<RefCell<Vec<String>>>) {
    let mut gl = Gl::new(64, 64);
    let n = gl.glu_new_nurbs_renderer();
    let seen = Rc::new(RefCell::new(Vec::new()));
    let sink = Rc::clone(&seen);
    gl.glu_nurbs_callback(
        n,
        GLU_NURBS_ERROR,
        Some(NurbsCallback::error(move |e| {
            let text = if (GLU_NURBS_ERROR1..=GLU_NURBS_ERROR37).contains(&e) {
                (e - GLU_NURBS_ERROR1 + 1).to_string()
            } else {
                format!("0x{e:x}")
            };
            sink.borrow_mut().push(text);
        })),
    );
    (gl, n, seen)
}

fn surface(gl: &mut Gl, n: GLUnurbs) {
    gl.glu_nurbs_surface(n, 8, &KNOTS8, 8, &KNOTS8, 12, 3, &ctl(), 4, 4, GL_MAP2_VERTEX_3);
}

fn pwl(gl: &mut Gl, n: GLUnurbs, count: i32, stride: i32, kind: u32) {
    gl.glu_pwl_curve(n, count, &TRIM_SQUARE, stride, kind);
}

/// A named scenario.
type Scenario = (&'static str, fn(&mut Gl, GLUnurbs));

/// The scenarios, in the C program's order.
fn scenarios() -> Vec<Scenario> {
    vec![
        ("order_0", |gl, n| gl.glu_nurbs_curve(n, 2, &[0.0, 1.0], 3, &ctl(), 0, GL_MAP1_VERTEX_3)),
        ("order_25", |gl, n| gl.glu_nurbs_curve(n, 8, &KNOTS8, 3, &ctl(), 25, GL_MAP1_VERTEX_3)),
        ("too_few_knots", |gl, n| gl.glu_nurbs_curve(n, 7, &KNOTS8, 3, &ctl(), 4, GL_MAP1_VERTEX_3)),
        ("empty_range", |gl, n| gl.glu_nurbs_curve(n, 8, &[0.0; 8], 3, &ctl(), 4, GL_MAP1_VERTEX_3)),
        ("decreasing", |gl, n| {
            gl.glu_nurbs_curve(n, 8, &[0.0, 0.0, 0.0, 1.0, 0.5, 1.0, 1.0, 1.0], 3, &ctl(), 4, GL_MAP1_VERTEX_3)
        }),
        ("multiplicity", |gl, n| {
            gl.glu_nurbs_curve(n, 9, &[0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], 3, &ctl(), 4, GL_MAP1_VERTEX_3)
        }),
        ("unknown_type", |gl, n| gl.glu_nurbs_curve(n, 8, &KNOTS8, 3, &ctl(), 4, GL_FILL)),
        ("null_control", |gl, n| gl.glu_nurbs_curve(n, 8, &KNOTS8, 3, &[], 4, GL_MAP1_VERTEX_3)),
        ("negative_stride", |gl, n| gl.glu_nurbs_curve(n, 8, &KNOTS8, -3, &ctl(), 4, GL_MAP1_VERTEX_3)),
        ("begin_curve_twice", |gl, n| {
            gl.glu_begin_curve(n);
            gl.glu_begin_curve(n);
            gl.glu_end_curve(n);
        }),
        ("end_curve_alone", |gl, n| gl.glu_end_curve(n)),
        ("begin_surface_twice", |gl, n| {
            gl.glu_begin_surface(n);
            gl.glu_begin_surface(n);
            gl.glu_end_surface(n);
        }),
        ("end_surface_alone", |gl, n| gl.glu_end_surface(n)),
        ("end_surface_in_trim", |gl, n| {
            gl.glu_begin_surface(n);
            surface(gl, n);
            gl.glu_begin_trim(n);
            pwl(gl, n, 5, 2, GLU_MAP1_TRIM_2);
            gl.glu_end_surface(n);
        }),
        ("trim_outside_surface", |gl, n| {
            gl.glu_begin_trim(n);
            pwl(gl, n, 5, 2, GLU_MAP1_TRIM_2);
            gl.glu_end_trim(n);
            surface(gl, n);
            gl.glu_end_surface(n);
        }),
        ("trim_in_trim", |gl, n| {
            gl.glu_begin_surface(n);
            surface(gl, n);
            gl.glu_begin_trim(n);
            gl.glu_begin_trim(n);
            pwl(gl, n, 5, 2, GLU_MAP1_TRIM_2);
            gl.glu_end_trim(n);
            gl.glu_end_surface(n);
        }),
        ("end_trim_alone", |gl, n| {
            gl.glu_begin_surface(n);
            surface(gl, n);
            gl.glu_end_trim(n);
            gl.glu_end_surface(n);
        }),
        ("empty_trim", |gl, n| {
            gl.glu_begin_surface(n);
            surface(gl, n);
            gl.glu_begin_trim(n);
            gl.glu_end_trim(n);
            gl.glu_end_surface(n);
        }),
        ("pwl_outside_trim", |gl, n| {
            gl.glu_begin_surface(n);
            surface(gl, n);
            pwl(gl, n, 5, 2, GLU_MAP1_TRIM_2);
            gl.glu_end_surface(n);
        }),
        ("pwl_wrong_type", |gl, n| trimmed_pwl(gl, n, 5, 2, GL_MAP1_VERTEX_3)),
        ("pwl_negative_count", |gl, n| trimmed_pwl(gl, n, -1, 2, GLU_MAP1_TRIM_2)),
        ("pwl_negative_stride", |gl, n| trimmed_pwl(gl, n, 5, -2, GLU_MAP1_TRIM_2)),
        ("pwl_unknown_type", |gl, n| trimmed_pwl(gl, n, 5, 2, GL_FILL)),
        ("bad_property", |gl, n| gl.glu_nurbs_property(n, 12345, 1.0)),
        ("bad_display_mode", |gl, n| gl.glu_nurbs_property(n, GLU_DISPLAY_MODE, 7.0)),
        ("bad_sampling_method", |gl, n| gl.glu_nurbs_property(n, GLU_SAMPLING_METHOD, 7.0)),
        ("bad_nurbs_mode", |gl, n| gl.glu_nurbs_property(n, GLU_NURBS_MODE, 7.0)),
        ("bad_get_property", |gl, n| gl.glu_get_nurbs_property(n, 12345, &mut [0.0])),
        ("bad_callback", |gl, n| gl.glu_nurbs_callback(n, 12345, Some(NurbsCallback::end(|_| {})))),
        ("valid_surface", |gl, n| {
            gl.glu_begin_surface(n);
            surface(gl, n);
            gl.glu_end_surface(n);
        }),
        ("near_equal_knots", |gl, n| {
            gl.glu_nurbs_curve(
                n,
                9,
                &[0.0, 2e-6, 4e-6, 6e-6, 8e-6, 1.0, 1.0, 1.0, 1.0],
                3,
                &ctl(),
                4,
                GL_MAP1_VERTEX_3,
            );
        }),
        ("knots_just_apart", |gl, n| curve(gl, n, &[0.0, 0.0, 0.0, 0.0, 2e-5, 1.0, 1.0, 1.0, 1.0])),
        ("negative_knots", |gl, n| curve(gl, n, &[-3.0, -3.0, -3.0, -3.0, -1.0, -1.0, -1.0, -1.0])),
        ("tiny_domain", |gl, n| curve(gl, n, &[0.0, 0.0, 0.0, 0.0, 1e-4, 1e-4, 1e-4, 1e-4])),
        ("huge_domain", |gl, n| curve(gl, n, &[0.0, 0.0, 0.0, 0.0, 1e8, 1e8, 1e8, 1e8])),
        ("trim_begins_surface_then_ends", |gl, n| {
            gl.glu_begin_trim(n);
            gl.glu_end_trim(n);
            gl.glu_end_curve(n);
            gl.glu_end_surface(n);
        }),
    ]
}

/// A cubic curve over `knots` between begin and end.
fn curve(gl: &mut Gl, n: GLUnurbs, knots: &[f32]) {
    gl.glu_begin_curve(n);
    gl.glu_nurbs_curve(n, knots.len() as i32, knots, 3, &ctl(), 4, GL_MAP1_VERTEX_3);
    gl.glu_end_curve(n);
}

fn trimmed_pwl(gl: &mut Gl, n: GLUnurbs, count: i32, stride: i32, kind: u32) {
    gl.glu_begin_surface(n);
    surface(gl, n);
    gl.glu_begin_trim(n);
    pwl(gl, n, count, stride, kind);
    gl.glu_end_trim(n);
    gl.glu_end_surface(n);
}

#[test]
fn nurbs_errors_match_real_glu() {
    let expected = reference("nurbs_errors.txt");
    let expected: Vec<&str> = expected.lines().collect();
    let scenarios = scenarios();
    assert_eq!(scenarios.len(), expected.len(), "scenario lists out of step with the C program");
    let mut mismatches = Vec::new();
    for ((name, run), want) in scenarios.into_iter().zip(expected) {
        let (mut gl, n, seen) = fresh();
        run(&mut gl, n);
        gl.glu_delete_nurbs_renderer(n);
        let ours = format!("{name}:{}", seen.borrow().iter().map(|e| format!(" {e}")).collect::<String>());
        if ours != want {
            mismatches.push(format!("ours {ours:?}\n  glu {want:?}"));
        }
    }
    assert!(mismatches.is_empty(), "{}", mismatches.join("\n"));
}

#[test]
fn error_strings_match_real_glu() {
    // Each scanned range: GLU's messages, and NULL for every code it does not list.
    let mut listed = std::collections::BTreeMap::new();
    let mut ranges = Vec::new();
    let text = reference("error_strings.txt");
    for line in text.lines() {
        let (code, text) = line.split_once(' ').expect("code text");
        if code == "range" {
            let (from, to) = text.split_once(' ').expect("range from to");
            ranges.push(from.parse::<u32>().unwrap()..=to.parse::<u32>().unwrap());
        } else {
            listed.insert(code.parse::<u32>().expect("code"), text);
        }
    }
    assert_eq!(ranges.len(), 2);
    for code in ranges.into_iter().flatten() {
        assert_eq!(glu_error_string(code), listed.get(&code).copied(), "gluErrorString({code})");
    }
}

#[test]
fn get_string_and_check_extension_match_real_glu() {
    let gl = Gl::new(1, 1);
    let text = reference("strings.txt");
    let mut checked = 0;
    for line in text.lines() {
        let fields: Vec<&str> = line.splitn(4, '\t').collect();
        match fields[..] {
            ["get", _, name, want] => {
                let want = (want != "(null)").then_some(want);
                assert_eq!(gl.glu_get_string(name.parse().unwrap()), want, "{line}");
            }
            ["check", want, name, string] => {
                assert_eq!(gl.glu_check_extension(name, string), want.parse::<u8>().unwrap(), "{line:?}");
            }
            _ => panic!("bad line {line:?}"),
        }
        checked += 1;
    }
    assert!(checked > 50);
}

#[test]
fn non_trim_curve_inside_a_trim_is_error_14() {
    // GLU defines error 14 but never raises it (spec 2.7: validate yourself).
    let (mut gl, n, seen) = fresh();
    gl.glu_begin_surface(n);
    surface(&mut gl, n);
    gl.glu_begin_trim(n);
    gl.glu_nurbs_curve(n, 8, &KNOTS8, 3, &ctl(), 4, GL_MAP1_VERTEX_3);
    gl.glu_end_trim(n);
    gl.glu_end_surface(n);
    assert_eq!(seen.borrow().first().map(String::as_str), Some("14"));
    assert_eq!(glu_error_string(GLU_NURBS_ERROR14), Some("curve of improper type passed as trim curve"));
}

#[test]
fn short_slices_are_reported_not_read() {
    // C would read past the arrays; gleval reports GLU's "missing or extra ... data".
    let (mut gl, n, seen) = fresh();
    gl.glu_nurbs_curve(n, 8, &KNOTS8[..7], 3, &ctl(), 4, GL_MAP1_VERTEX_3);
    gl.glu_nurbs_curve(n, 8, &KNOTS8, 3, &[0.0; 11], 4, GL_MAP1_VERTEX_3);
    assert_eq!(*seen.borrow(), ["10", "8"]);
}

/// A bilinear patch sampled to a path-length tolerance of 1e-6 pixel: after GLU's six
/// bisections every leaf still asks for millions of lines a side (capped at 2^14), beyond the
/// façade's 2^27 vertices per mesh. GLU's convention: `GLU_OUT_OF_MEMORY` (0x18a26) through
/// the error callback, no GL error, nothing drawn for the patch, in both modes.
#[test]
fn oversampled_patches_report_glu_out_of_memory() {
    let knots = [0.0f32, 0.0, 1.0, 1.0];
    let ctl = [0.0f32, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0];
    for mode in [GLU_NURBS_RENDERER, GLU_NURBS_TESSELLATOR] {
        let (mut gl, n, seen) = fresh();
        gl.glu_nurbs_property(n, GLU_NURBS_MODE, mode as f32);
        gl.glu_nurbs_property(n, GLU_SAMPLING_TOLERANCE, 1e-6);
        let vertices = Rc::new(RefCell::new(0usize));
        let count = Rc::clone(&vertices);
        gl.glu_nurbs_callback(n, GLU_NURBS_VERTEX, Some(NurbsCallback::vertex(move |_, _| *count.borrow_mut() += 1)));
        gl.glu_begin_surface(n);
        gl.glu_nurbs_surface(n, 4, &knots, 4, &knots, 8, 4, &ctl, 2, 2, GL_MAP2_VERTEX_4);
        gl.glu_end_surface(n);
        assert_eq!(*seen.borrow(), ["0x18a26"], "mode {mode:#x}");
        assert_eq!(gl.get_error(), GL_NO_ERROR, "mode {mode:#x}");
        assert_eq!(*vertices.borrow(), 0, "mode {mode:#x}");
        assert_eq!(glu_error_string(GLU_OUT_OF_MEMORY), Some("out of memory"));
    }
}
