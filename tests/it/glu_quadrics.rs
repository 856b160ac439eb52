//! GLU's quadrics, call for call and bit for bit: `tests/reference/glu/quadrics.c` prints every
//! GL call real GLU 9.0.2's `quad.c` makes (`glBegin`, `glEnd`, `glNormal3f`, `glTexCoord2f`,
//! `glVertex3f`, floats as their bits) and every error its `GLU_ERROR` callback receives, for
//! spheres, cylinders, disks and partial disks in every draw style, normal mode, orientation
//! and texture flag, and for edge cases (clamped slices, NaN, negative counts, sweeps beyond
//! ±360) and bad modes. Each case is run here twice: through [`Quadric`]'s sink, which must
//! print the same lines, and through `Gl` (`gl.glu_sphere(q, ...)` with the error callback),
//! whose recorded primitives must hold the vertices those calls make.
//!
//! Normals `quad.c` reads from a cache it never filled (the reference prints them as `N ?`)
//! are not compared.

use gleval::gl::Gl;
use gleval::glu::quadric::{Quadric, QuadricSink};
use gleval::prelude::*;
use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;

/// One case of the reference: its header and the lines GLU printed for it.
struct Case {
    header: Vec<String>,
    lines: Vec<String>,
}

fn reference() -> Vec<Case> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu/quadrics.txt");
    let text = std::fs::read_to_string(path).expect("quadrics.txt");
    let mut cases: Vec<Case> = Vec::new();
    for line in text.lines() {
        if line.starts_with("Q ") || line.starts_with("C ") {
            cases.push(Case { header: line.split(' ').map(String::from).collect(), lines: Vec::new() });
        } else {
            cases.last_mut().expect("a case first").lines.push(line.to_string());
        }
    }
    cases
}

/// Prints the calls as quadrics.c does.
struct Printer {
    lines: Vec<String>,
    hide_normals: bool,
}

fn hex(v: &[f32]) -> String {
    v.iter().map(|x| format!("{:08x}", x.to_bits())).collect::<Vec<_>>().join(" ")
}

impl QuadricSink for Printer {
    fn begin(&mut self, mode: u32) {
        self.lines.push(format!("B {mode}"));
    }
    fn end(&mut self) {
        self.lines.push("E".into());
    }
    fn normal(&mut self, n: [f32; 3]) {
        self.lines.push(if self.hide_normals { "N ?".into() } else { format!("N {}", hex(&n)) });
    }
    fn tex_coord(&mut self, t: [f32; 2]) {
        self.lines.push(format!("T {}", hex(&t)));
    }
    fn vertex(&mut self, v: [f32; 3]) {
        self.lines.push(format!("V {}", hex(&v)));
    }
}

/// A shape and its arguments, from a `Q` header.
struct Shape {
    kind: String,
    args: [f64; 5],
    counts: [i32; 2],
}

impl Shape {
    fn parse(h: &[String]) -> Self {
        let arg = |k: usize| f64::from_bits(u64::from_str_radix(&h[6 + k], 16).unwrap());
        Shape {
            kind: h[1].clone(),
            args: [arg(0), arg(1), arg(2), arg(3), arg(4)],
            counts: [h[11].parse().unwrap(), h[12].parse().unwrap()],
        }
    }

    fn draw(&self, q: &Quadric, sink: &mut impl QuadricSink) -> Result<(), u32> {
        let ([a, b, c, d, e], [n1, n2]) = (self.args, self.counts);
        match self.kind.as_str() {
            "sphere" => q.sphere(sink, a, n1, n2),
            "cylinder" => q.cylinder(sink, a, b, c, n1, n2),
            "disk" => q.disk(sink, a, b, n1, n2),
            _ => q.partial_disk(sink, a, b, n1, n2, d, e),
        }
    }

    fn draw_gl(&self, gl: &mut Gl, q: GLUquadric) {
        let ([a, b, c, d, e], [n1, n2]) = (self.args, self.counts);
        match self.kind.as_str() {
            "sphere" => gl.glu_sphere(q, a, n1, n2),
            "cylinder" => gl.glu_cylinder(q, a, b, c, n1, n2),
            "disk" => gl.glu_disk(q, a, b, n1, n2),
            _ => gl.glu_partial_disk(q, a, b, n1, n2, d, e),
        }
    }
}

fn modes(h: &[String]) -> Quadric {
    let n = |k: usize| h[k].parse::<u32>().unwrap();
    Quadric { draw_style: n(2), normals: n(3), orientation: n(4), texture: n(5) != 0 }
}

/// A quadric in `gl` with `modes` and an error callback that prints `ERR code` into `out`.
fn gl_quadric(gl: &mut Gl, out: &Rc<RefCell<Vec<String>>>) -> GLUquadric {
    let q = gl.glu_new_quadric();
    let o = Rc::clone(out);
    gl.glu_quadric_callback(q, GLU_ERROR, Some(Box::new(move |code| o.borrow_mut().push(format!("ERR {code}")))));
    q
}

/// A vertex as GL records it: position, normal (`None` where GLU's is undefined), texture
/// coordinate, all as bits (NaN compares equal to itself).
type Traced = ([u32; 3], Option<[u32; 3]>, [u32; 2]);

/// The vertices a call trace makes: each `V` with the current normal and texture coordinate
/// (GL's initial ones before the first call), grouped by primitive.
fn traced_vertices(lines: &[String]) -> Vec<(u32, Vec<Traced>)> {
    let (mut normal, mut tex) = (Some([0.0f32.to_bits(), 0, 1.0f32.to_bits()]), [0u32, 0]);
    let mut prims: Vec<(u32, Vec<Traced>)> = Vec::new();
    let bits = |l: &str| -> Vec<u32> { l.split(' ').skip(1).map(|x| u32::from_str_radix(x, 16).unwrap()).collect() };
    for l in lines {
        match l.as_bytes()[0] {
            b'B' => prims.push((l[2..].parse().unwrap(), Vec::new())),
            b'N' if l == "N ?" => normal = None,
            b'N' => normal = Some(bits(l).try_into().unwrap()),
            b'T' => tex = bits(l).try_into().unwrap(),
            b'V' => {
                let v: [u32; 3] = bits(l).try_into().unwrap();
                prims.last_mut().unwrap().1.push((v, normal, tex));
            }
            _ => {}
        }
    }
    prims
}

/// What `gl` recorded, as [`traced_vertices`] (normals kept only where `expected` has them).
fn recorded_vertices(gl: &mut Gl, expected: &[(u32, Vec<Traced>)]) -> Vec<(u32, Vec<Traced>)> {
    let frame = gl.frame().expanded();
    let b = |v: &[f32]| -> Vec<u32> { v.iter().map(|x| x.to_bits()).collect() };
    frame
        .primitives
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let vertices = frame.vertices[p.first..p.first + p.count]
                .iter()
                .enumerate()
                .map(|(n, v)| {
                    let known = expected.get(k).and_then(|e| e.1.get(n)).is_none_or(|t| t.1.is_some());
                    let normal = known.then(|| b(&v.normal).try_into().unwrap());
                    (b(&v.position[..3]).try_into().unwrap(), normal, b(&v.tex_coord[..2]).try_into().unwrap())
                })
                .collect();
            (p.mode, vertices)
        })
        .collect()
}

/// Runs a `Q` case through the sink and through `Gl`; `Err` says what differs.
fn check_shape(case: &Case) -> Result<(), String> {
    let h = &case.header;
    let (shape, q) = (Shape::parse(h), modes(h));
    let mut printer = Printer { lines: Vec::new(), hide_normals: h[13] == "1" };
    if let Err(code) = shape.draw(&q, &mut printer) {
        printer.lines.push(format!("ERR {code}"));
    }
    if printer.lines != case.lines {
        let at = printer.lines.iter().zip(&case.lines).position(|(a, b)| a != b).unwrap_or(0);
        return Err(format!(
            "calls differ at line {at} (gleval {:?}, GLU {:?}; {} vs {} lines)",
            printer.lines.get(at),
            case.lines.get(at),
            printer.lines.len(),
            case.lines.len()
        ));
    }
    let mut gl = Gl::new(8, 8);
    let errors = Rc::new(RefCell::new(Vec::new()));
    let handle = gl_quadric(&mut gl, &errors);
    gl.glu_quadric_draw_style(handle, q.draw_style);
    gl.glu_quadric_normals(handle, q.normals);
    gl.glu_quadric_orientation(handle, q.orientation);
    gl.glu_quadric_texture(handle, u8::from(q.texture));
    shape.draw_gl(&mut gl, handle);
    let expected = traced_vertices(&case.lines);
    let glu_errors: Vec<String> = case.lines.iter().filter(|l| l.starts_with("ERR")).cloned().collect();
    if *errors.borrow() != glu_errors || recorded_vertices(&mut gl, &expected) != expected {
        return Err(format!(
            "through Gl: errors {:?} vs {:?}, or the recorded vertices differ",
            errors.borrow(),
            glu_errors
        ));
    }
    Ok(())
}

/// Runs a `C` case: a setter on a fresh quadric, then `gluSphere(q, 1, 3, 2)`.
fn check_setter(case: &Case) -> Result<(), String> {
    let (name, value): (&str, u32) = (&case.header[1], case.header[2].parse().unwrap());
    let mut gl = Gl::new(8, 8);
    let out = Rc::new(RefCell::new(Vec::new()));
    let q = gl_quadric(&mut gl, &out);
    match name {
        "drawstyle" => gl.glu_quadric_draw_style(q, value),
        "normals" => gl.glu_quadric_normals(q, value),
        "orientation" => gl.glu_quadric_orientation(q, value),
        "texture" => gl.glu_quadric_texture(q, value as u8),
        _ => {
            let o = Rc::clone(&out);
            gl.glu_quadric_callback(q, value, Some(Box::new(move |code| o.borrow_mut().push(format!("ERR {code}")))))
        }
    }
    gl.glu_sphere(q, 1.0, 3, 2);
    let glu_errors: Vec<String> = case.lines.iter().filter(|l| l.starts_with("ERR")).cloned().collect();
    let expected = traced_vertices(&case.lines);
    if *out.borrow() != glu_errors || recorded_vertices(&mut gl, &expected) != expected {
        return Err(format!("errors {:?} vs GLU's {:?}, or the sphere differs", out.borrow(), glu_errors));
    }
    Ok(())
}

#[test]
fn quadrics_match_real_glu() {
    let cases = reference();
    assert!(cases.len() > 600, "the reference holds every mode of ten shapes and the edge cases");
    let mut failures = Vec::new();
    for case in &cases {
        let result = if case.header[0] == "Q" { check_shape(case) } else { check_setter(case) };
        if let Err(why) = result {
            failures.push(format!("{}: {why}", case.header.join(" ")));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases differ from GLU:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

/// Checks the sink sees: begin/end balanced and never nested, and the largest |coordinate|.
#[derive(Default)]
struct Outline {
    open: bool,
    balanced: bool,
    largest: f32,
    vertices: usize,
}

impl QuadricSink for Outline {
    fn begin(&mut self, _mode: u32) {
        self.balanced &= !self.open;
        self.open = true;
    }
    fn end(&mut self) {
        self.balanced &= self.open;
        self.open = false;
    }
    fn normal(&mut self, _n: [f32; 3]) {}
    fn tex_coord(&mut self, _t: [f32; 2]) {}
    fn vertex(&mut self, v: [f32; 3]) {
        self.balanced &= self.open;
        self.vertices += 1;
        self.largest = v.iter().fold(self.largest, |m, x| m.max(x.abs()));
    }
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    /// Any double, the awkward ones often.
    fn size() -> impl Strategy<Value = f64> {
        prop_oneof![
            4 => -3.0f64..3.0,
            1 => prop::sample::select(vec![0.0, -0.0, f64::NAN, f64::INFINITY, -f64::INFINITY, 1e30, -1e-30, f64::MAX]),
        ]
    }

    /// Any count: GLU clamps slices (and a sphere's stacks) to 239 itself.
    fn count() -> impl Strategy<Value = i32> {
        prop_oneof![3 => -3i32..12, 1 => any::<i32>()]
    }

    /// A count GLU loops over unclamped (a cylinder's stacks, a disk's loops): kept small, as
    /// GLU would take as long.
    fn loops() -> impl Strategy<Value = i32> {
        prop_oneof![3 => -3i32..12, 1 => Just(i32::MIN)]
    }

    fn modes() -> impl Strategy<Value = Quadric> {
        (
            prop::sample::select(vec![GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT]),
            prop::sample::select(vec![GLU_NONE, GLU_FLAT, GLU_SMOOTH]),
            prop::sample::select(vec![GLU_OUTSIDE, GLU_INSIDE]),
            any::<bool>(),
        )
            .prop_map(|(draw_style, normals, orientation, texture)| Quadric {
                draw_style,
                normals,
                orientation,
                texture,
            })
    }

    /// Ok and a bounded, balanced shape, or GLU's `GLU_INVALID_VALUE` exactly when `invalid`.
    fn verdict(result: Result<(), u32>, shape: &Outline, invalid: bool, bound: f64) -> Result<(), TestCaseError> {
        if invalid {
            prop_assert_eq!(result, Err(GLU_INVALID_VALUE));
            prop_assert_eq!(shape.vertices, 0);
        } else {
            prop_assert_eq!(result, Ok(()));
            prop_assert!(shape.balanced && !shape.open);
            prop_assert!(shape.vertices > 0);
            if bound.abs() < 1e30 {
                prop_assert!(f64::from(shape.largest) <= bound * 1.0001 + 1e-6, "{} > {}", shape.largest, bound);
            }
        }
        Ok(())
    }

    proptest! {
        #[test]
        fn spheres_are_glus_errors_or_bounded_shapes(q in modes(), r in size(), slices in count(), stacks in count()) {
            let mut shape = Outline { balanced: true, ..Outline::default() };
            let result = q.sphere(&mut shape, r, slices, stacks);
            let invalid = slices.min(239) < 2 || stacks.min(239) < 1 || r < 0.0;
            verdict(result, &shape, invalid, r)?;
        }

        #[test]
        fn cylinders_are_glus_errors_or_bounded_shapes(
            q in modes(), base in size(), top in size(), height in size(), slices in count(), stacks in loops()
        ) {
            let mut shape = Outline { balanced: true, ..Outline::default() };
            let result = q.cylinder(&mut shape, base, top, height, slices, stacks);
            let no_length = f64::from((base - top) as f32).hypot(height) == 0.0;
            let invalid = slices.min(239) < 2 || stacks < 1 || base < 0.0 || top < 0.0 || height < 0.0 || no_length;
            verdict(result, &shape, invalid, base.max(top).max(height))?;
        }

        #[test]
        fn disks_are_glus_errors_or_bounded_shapes(
            q in modes(), inner in size(), outer in size(), slices in count(), loops in loops(), start in size(), sweep in size()
        ) {
            let mut shape = Outline { balanced: true, ..Outline::default() };
            let result = q.partial_disk(&mut shape, inner, outer, slices, loops, start * 200.0, sweep * 200.0);
            let invalid = slices.min(239) < 2 || loops < 1 || outer <= 0.0 || inner < 0.0 || inner > outer;
            verdict(result, &shape, invalid, outer)?;
        }

        /// Any sequence of quadric calls through `Gl`, bad modes and deleted handles included:
        /// no panic, no GL error, only GLU's codes through the callback.
        #[test]
        fn random_quadric_calls_never_panic(calls in proptest::collection::vec((0u8..10, any::<u32>(), size(), count(), loops()), 0..30)) {
            let mut gl = Gl::new(16, 16);
            let seen = Rc::new(RefCell::new(Vec::new()));
            let q = gl_quadric(&mut gl, &seen);
            let modes = [GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT, GLU_NONE, GLU_FLAT, GLU_SMOOTH, GLU_OUTSIDE, GLU_INSIDE];
            for (op, e, x, n, m) in calls {
                let mode = if e % 4 == 0 { e } else { modes[e as usize % modes.len()] };
                match op {
                    0 => gl.glu_quadric_draw_style(q, mode),
                    1 => gl.glu_quadric_normals(q, mode),
                    2 => gl.glu_quadric_orientation(q, mode),
                    3 => gl.glu_quadric_texture(q, e as u8),
                    4 => gl.glu_quadric_callback(q, mode, None),
                    5 => gl.glu_sphere(q, x, n, m),
                    6 => gl.glu_cylinder(q, x, x * 0.5, x.abs(), n, m),
                    7 => gl.glu_disk(q, x, 2.0 * x, n, m),
                    8 => gl.glu_partial_disk(q, x, 1.0, n, m, x * 90.0, f64::from(n) * 30.0),
                    _ => gl.glu_delete_quadric(q),
                }
            }
            prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
            for code in seen.borrow().iter() {
                prop_assert!([
                    "ERR 100900", "ERR 100901"
                ].contains(&code.as_str()), "{}", code);
            }
        }
    }
}
