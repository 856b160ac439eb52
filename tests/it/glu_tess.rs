//! GLU's tessellator against real GLU: `tests/reference/glu/tess_cases.in` run through
//! gleval here and through the installed GLU by `tess_calls.c` (its output committed as
//! `tess_calls.txt`); every callback, with every number bit for bit, must be the same.

use gleval::glu::TessData;
use gleval::prelude::*;
use std::any::Any;
use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;

fn reference(name: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu").join(name))
        .expect("reference file")
}

/// A vertex's data, as the C program's `Vert`.
struct Vert {
    id: i32,
}

type Out = Rc<RefCell<String>>;

fn vid(d: Option<&dyn Any>) -> i32 {
    d.and_then(|d| d.downcast_ref::<Vert>()).map_or(-1, |v| v.id)
}

fn pid(p: &dyn Any) -> String {
    format!(" poly {}", p.downcast_ref::<i32>().map_or(-1, |p| *p))
}

fn say(out: &Out, line: String) {
    let mut o = out.borrow_mut();
    o.push_str(&line);
    o.push('\n');
}

/// The combine callback's line, and the new vertex's data.
fn combine_line(out: &Out, next: &Rc<RefCell<i32>>, c: &[f64; 3], d: [Option<&dyn Any>; 4], w: &[f32; 4]) -> TessData {
    let id = 1000 + *next.borrow();
    *next.borrow_mut() += 1;
    let ids = d.map(vid);
    say(
        out,
        format!(
            "combine {id} {:016x} {:016x} {:016x} | {} {} {} {} | {:08x} {:08x} {:08x} {:08x}",
            c[0].to_bits(),
            c[1].to_bits(),
            c[2].to_bits(),
            ids[0],
            ids[1],
            ids[2],
            ids[3],
            w[0].to_bits(),
            w[1].to_bits(),
            w[2].to_bits(),
            w[3].to_bits()
        ),
    );
    Rc::new(Vert { id })
}

/// The callback `name` of the C program, printing to `out`.
fn callback(name: &str, out: &Out, next: &Rc<RefCell<i32>>) -> Option<(GLenum, TessCallback)> {
    let o = Rc::clone(out);
    let n = Rc::clone(next);
    Some(match name {
        "begin" => (GLU_TESS_BEGIN, TessCallback::begin(move |_, t| say(&o, format!("begin {t}")))),
        "vertex" => (GLU_TESS_VERTEX, TessCallback::vertex(move |_, d| say(&o, format!("vertex {}", vid(Some(d)))))),
        "end" => (GLU_TESS_END, TessCallback::end(move |_| say(&o, "end".into()))),
        "error" => (GLU_TESS_ERROR, TessCallback::error(move |_, e| say(&o, format!("error {e}")))),
        "edge" => (GLU_TESS_EDGE_FLAG, TessCallback::edge_flag(move |_, f| say(&o, format!("edge {f}")))),
        "combine" => (GLU_TESS_COMBINE, TessCallback::combine(move |_, c, d, w| Some(combine_line(&o, &n, c, d, w)))),
        "begin_data" => (
            GLU_TESS_BEGIN_DATA,
            TessCallback::BeginData(Box::new(move |_, t, p| say(&o, format!("begin {t}{}", pid(p))))),
        ),
        "vertex_data" => (
            GLU_TESS_VERTEX_DATA,
            TessCallback::VertexData(Box::new(move |_, d, p| say(&o, format!("vertex {}{}", vid(Some(d)), pid(p))))),
        ),
        "end_data" => {
            (GLU_TESS_END_DATA, TessCallback::EndData(Box::new(move |_, p| say(&o, format!("end{}", pid(p))))))
        }
        "error_data" => (
            GLU_TESS_ERROR_DATA,
            TessCallback::ErrorData(Box::new(move |_, e, p| say(&o, format!("error {e}{}", pid(p))))),
        ),
        "edge_data" => (
            GLU_TESS_EDGE_FLAG_DATA,
            TessCallback::EdgeFlagData(Box::new(move |_, f, p| say(&o, format!("edge {f}{}", pid(p))))),
        ),
        "combine_data" => (
            GLU_TESS_COMBINE_DATA,
            TessCallback::CombineData(Box::new(move |_, c, d, w, p| {
                let data = combine_line(&o, &n, c, d, w);
                // The C program appends the polygon data to the same line.
                o.borrow_mut().pop();
                say(&o, pid(p));
                Some(data)
            })),
        ),
        _ => return None,
    })
}

fn rule(name: &str) -> GLenum {
    match name {
        "NONZERO" => GLU_TESS_WINDING_NONZERO,
        "POSITIVE" => GLU_TESS_WINDING_POSITIVE,
        "NEGATIVE" => GLU_TESS_WINDING_NEGATIVE,
        "ABS_GEQ_TWO" => GLU_TESS_WINDING_ABS_GEQ_TWO,
        _ => GLU_TESS_WINDING_ODD,
    }
}

/// The C program's LCG.
struct Lcg(u32);

impl Lcg {
    fn next(&mut self) -> u32 {
        self.0 = self.0.wrapping_mul(1_103_515_245).wrapping_add(12345) & 0x7fff_ffff;
        self.0
    }
}

/// Runs the case file's commands through gleval, printing what `tess_calls.c` prints.
fn run_cases(text: &str) -> String {
    let out: Out = Rc::new(RefCell::new(String::new()));
    let next = Rc::new(RefCell::new(0));
    let mut gl = Gl::new(8, 8);
    let mut tess: Option<GLUtesselator> = None;
    let mut id = 0;
    let vertex = |gl: &mut Gl, t: GLUtesselator, id: &mut i32, p: [f64; 3]| {
        gl.glu_tess_vertex(t, &p, Vert { id: *id });
        *id += 1;
    };
    for line in text.lines() {
        let mut words = line.split_whitespace();
        let Some(cmd) = words.next().filter(|c| !c.starts_with('#')) else { continue };
        let rest: Vec<&str> = words.collect();
        let nums: Vec<f64> = rest.iter().filter_map(|w| w.parse().ok()).collect();
        if cmd == "case" {
            if let Some(t) = tess.take() {
                gl.glu_delete_tess(t);
            }
            say(&out, format!("case {}", rest[0]));
            tess = Some(gl.glu_new_tess());
            id = 0;
            *next.borrow_mut() = 0;
            continue;
        }
        let t = tess.expect("a case first");
        match cmd {
            "cb" => {
                for w in &rest {
                    if let Some((which, cb)) = callback(w, &out, &next) {
                        gl.glu_tess_callback(t, which, Some(cb));
                    }
                }
            }
            "cbraw" => gl.glu_tess_callback(t, rest[0].parse().unwrap(), None),
            "rule" => gl.glu_tess_property(t, GLU_TESS_WINDING_RULE, f64::from(rule(rest[0]))),
            "prop" => gl.glu_tess_property(t, rest[0].parse().unwrap(), nums[1]),
            "get" => {
                let which: GLenum = rest[0].parse().unwrap();
                let mut v = [-1.0];
                gl.glu_get_tess_property(t, which, &mut v);
                say(&out, format!("value {which} {:016x}", v[0].to_bits()));
            }
            "normal" => gl.glu_tess_normal(t, nums[0], nums[1], nums[2]),
            "bp" => gl.glu_tess_begin_polygon(t, Some(Box::new(77i32))),
            "bc" => gl.glu_tess_begin_contour(t),
            "ec" => gl.glu_tess_end_contour(t),
            "ep" => gl.glu_tess_end_polygon(t),
            "v" => vertex(&mut gl, t, &mut id, [nums[0], nums[1], nums[2]]),
            "c" => {
                gl.glu_tess_begin_contour(t);
                for p in nums.chunks_exact(3) {
                    vertex(&mut gl, t, &mut id, [p[0], p[1], p[2]]);
                }
                gl.glu_tess_end_contour(t);
            }
            "circle" => {
                let (count, cx, cy, r) = (nums[0] as usize, nums[1], nums[2], nums[3]);
                gl.glu_tess_begin_contour(t);
                for i in 0..count {
                    let a = std::f64::consts::TAU * i as f64 / count as f64;
                    let (c, s) = ((a.cos() * 1024.0).trunc() / 1024.0, (a.sin() * 1024.0).trunc() / 1024.0);
                    vertex(&mut gl, t, &mut id, [cx + r * c, cy + r * s, 0.0]);
                }
                gl.glu_tess_end_contour(t);
            }
            "random" => {
                let (count, size) = (nums[0] as usize, nums[2] as u32);
                let mut lcg = Lcg(nums[1] as u32);
                gl.glu_tess_begin_contour(t);
                for _ in 0..count {
                    let x = f64::from(lcg.next() % (size * 8)) / 8.0;
                    let y = f64::from(lcg.next() % (size * 8)) / 8.0;
                    vertex(&mut gl, t, &mut id, [x, y, 0.0]);
                }
                gl.glu_tess_end_contour(t);
            }
            "poly" => gl.glu_begin_polygon(t),
            "next" => gl.glu_next_contour(t, GLU_UNKNOWN),
            "endpoly" => gl.glu_end_polygon(t),
            other => panic!("unknown command {other}"),
        }
    }
    if let Some(t) = tess.take() {
        gl.glu_delete_tess(t);
    }
    let text = out.borrow().clone();
    text
}

/// Splits an output into its cases.
fn cases(text: &str) -> Vec<(String, String)> {
    let mut v: Vec<(String, String)> = Vec::new();
    for line in text.lines() {
        if let Some(name) = line.strip_prefix("case ") {
            v.push((name.to_string(), String::new()));
        } else if let Some(last) = v.last_mut() {
            last.1.push_str(line);
            last.1.push('\n');
        }
    }
    v
}

#[test]
fn every_case_calls_back_as_real_glu_does() {
    let expected = cases(&reference("tess_calls.txt"));
    let actual = cases(&run_cases(&reference("tess_cases.in")));
    assert_eq!(expected.len(), actual.len(), "number of cases");
    let mut differ = Vec::new();
    for ((name, want), (_, got)) in expected.iter().zip(&actual) {
        if want != got {
            let line = want
                .lines()
                .zip(got.lines())
                .position(|(a, b)| a != b)
                .unwrap_or(want.lines().count().min(got.lines().count()));
            differ.push(format!("{name} (first difference at line {line})"));
            if std::env::var_os("GLEVAL_TESS_DUMP").is_some() {
                eprintln!("--- {name}: GLU\n{want}--- gleval\n{got}");
            }
        }
    }
    assert!(differ.is_empty(), "{} of {} cases differ from GLU: {differ:?}", differ.len(), expected.len());
}
