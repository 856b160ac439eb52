//! GLUT's solid and wire sphere, cube, cone and torus, drawn as freeglut 3.4 draws them: the
//! same vertices in the same order, the same normals and the same primitives (triangle strips for
//! the round solids and triangles for the cube; line strips, lines and line loops for the
//! wires), so the same winding and the same pixels. freeglut hands the GL client arrays and
//! `glDrawElements`; these send the same vertices through `glBegin`/`glEnd`, and, as drawing from
//! arrays leaves the current normal alone in Mesa, put the current normal back afterwards.
//!
//! Checked against real freeglut: `tests/reference/pictures/glut_shapes.h` draws what these
//! draw, and was compared with freeglut 3.4 pixel for pixel (its header says how).

use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;

/// A vertex with its normal: (normal, position).
pub(super) type Point = ([f32; 3], [f32; 3]);

/// Sample `i` of freeglut's circle table of `n` steps over a full turn (half a turn if `half`),
/// as (sin, cos): a negative `n` turns clockwise; the step is an `f32`, each sample a double
/// sine or cosine rounded to `f32`, and the last sample (`i == |n|`) closes the circle exactly.
pub(super) fn circle(n: i32, half: bool, i: i32) -> (f32, f32) {
    let size = n.abs();
    if i == 0 || (i == size && !half) {
        return (0.0, 1.0);
    }
    if i == size {
        return (0.0, -1.0);
    }
    let turn = if half { 1.0 } else { 2.0 };
    let step = turn * std::f32::consts::PI / n as f32;
    let angle = f64::from(step * i as f32);
    (angle.sin() as f32, angle.cos() as f32)
}

/// A sphere of `stacks` bands from the +z pole (stack 0) to the −z pole (stack `stacks`),
/// `slices` meridians turning clockwise seen from +z.
struct Sphere {
    radius: f32,
    slices: i32,
    stacks: i32,
}

impl Sphere {
    /// The sphere, or `None` for the sizes freeglut draws nothing for (`slices < 1` or
    /// `stacks < 2`, `fghGenerateSphere` in `fg_geometry.c`): the check both sphere calls open
    /// with.
    fn new(radius: GLdouble, slices: GLint, stacks: GLint) -> Option<Sphere> {
        (slices >= 1 && stacks >= 2).then_some(Sphere { radius: radius as f32, slices, stacks })
    }

    fn point(&self, i: i32, j: i32) -> Point {
        let n = if i == 0 || i == self.stacks {
            [0.0, 0.0, if i == 0 { 1.0 } else { -1.0 }]
        } else {
            let (s1, c1) = circle(-self.slices, false, j);
            let (s2, c2) = circle(self.stacks, true, i);
            [c1 * s2, s1 * s2, c2]
        };
        (n, n.map(|c| c * self.radius))
    }
}

/// A cone with its base's rim at z = 0 (ring 0) and its apex at z = `height` (ring `stacks`),
/// radius and height stepped in `f32` from ring to ring as freeglut accumulates them.
struct Cone {
    base: f32,
    slices: i32,
    /// (z, radius) of each ring.
    rings: Vec<(f32, f32)>,
    /// The side's normal: (cos, sin) of its slope.
    slope: (f32, f32),
}

impl Cone {
    /// The cone, or `None` for the sizes freeglut draws nothing for (`slices < 1` or
    /// `stacks < 1`, `fghGenerateCone` in `fg_geometry.c`).
    fn new(base: GLdouble, height: GLdouble, slices: GLint, stacks: GLint) -> Option<Cone> {
        if slices < 1 || stacks < 1 {
            return None;
        }
        let (base, height) = (base as f32, height as f32);
        let (dz, dr) = (height / stacks as f32, base / stacks as f32);
        let mut rings = Vec::with_capacity(stacks as usize + 1);
        let (mut z, mut r) = (0.0f32, base);
        for _ in 0..=stacks {
            rings.push((z, r));
            z += dz;
            r -= dr;
        }
        let hypot = f64::from(height * height + base * base).sqrt();
        let slope = ((f64::from(height) / hypot) as f32, (f64::from(base) / hypot) as f32);
        Some(Cone { base, slices, rings, slope })
    }

    fn side(&self, i: i32, j: i32) -> Point {
        let (s, c) = circle(-self.slices, false, j);
        let (z, r) = self.rings[i as usize];
        let (cosn, sinn) = self.slope;
        ([c * cosn, s * cosn, sinn], [c * r, s * r, z])
    }

    /// A point of the base's rim, with the base's downward normal.
    fn rim(&self, j: i32) -> Point {
        let (s, c) = circle(-self.slices, false, j);
        ([0.0, 0.0, -1.0], [c * self.base, s * self.base, 0.0])
    }
}

/// A torus around the z axis: `rings` circles around the axis turning anticlockwise seen from
/// +z, `sides` points around the tube turning clockwise.
struct Torus {
    inner: f32,
    outer: f32,
    sides: i32,
    rings: i32,
}

impl Torus {
    /// The torus, or `None` for the sizes freeglut draws nothing for (`sides < 2` or
    /// `rings < 2`, `fghGenerateTorus` in `fg_geometry.c`).
    fn new(inner: GLdouble, outer: GLdouble, sides: GLint, rings: GLint) -> Option<Torus> {
        (sides >= 2 && rings >= 2).then_some(Torus { inner: inner as f32, outer: outer as f32, sides, rings })
    }

    fn point(&self, ring: i32, side: i32) -> Point {
        let (sp, cp) = circle(self.rings, false, ring);
        let (st, ct) = circle(-self.sides, false, side);
        let r = self.outer + ct * self.inner;
        ([cp * ct, sp * ct, st], [cp * r, sp * r, st * self.inner])
    }
}

/// The cube's faces: the outward normal, then four corners anticlockwise seen from outside, as
/// signs of x, y and z (times half the size).
const CUBE_FACES: [[[i8; 3]; 5]; 6] = [
    [[0, 0, 1], [1, 1, 1], [-1, 1, 1], [-1, -1, 1], [1, -1, 1]],
    [[1, 0, 0], [1, 1, 1], [1, -1, 1], [1, -1, -1], [1, 1, -1]],
    [[0, 1, 0], [1, 1, 1], [1, 1, -1], [-1, 1, -1], [-1, 1, 1]],
    [[-1, 0, 0], [-1, 1, 1], [-1, 1, -1], [-1, -1, -1], [-1, -1, 1]],
    [[0, -1, 0], [-1, -1, -1], [1, -1, -1], [1, -1, 1], [-1, -1, 1]],
    [[0, 0, -1], [1, -1, -1], [-1, -1, -1], [-1, 1, -1], [1, 1, -1]],
];

/// A face's corner `k`: the face's normal and the corner scaled as freeglut scales its unit
/// cube (`size · ±0.5` in `f32`).
fn cube_corner(face: &[[i8; 3]; 5], k: usize, size: f32) -> Point {
    (face[0].map(f32::from), face[k + 1].map(|s| size * (0.5 * f32::from(s))))
}

impl Gl {
    /// `glutSolidSphere(radius, slices, stacks)`: one triangle strip a band, lit with the
    /// sphere's normals. Nothing for `slices < 1` or `stacks < 2`.
    pub fn glut_solid_sphere(&mut self, radius: GLdouble, slices: GLint, stacks: GLint) {
        let Some(sphere) = Sphere::new(radius, slices, stacks) else { return };
        self.drawing_shape(|gl| {
            for i in 0..stacks {
                let band = (0..=slices).flat_map(|j| [sphere.point(i + 1, j % slices), sphere.point(i, j % slices)]);
                gl.shape_primitive(GL_TRIANGLE_STRIP, band);
            }
        });
    }

    /// `glutWireSphere(radius, slices, stacks)`: a line strip a meridian from pole to pole,
    /// then a line loop a parallel.
    pub fn glut_wire_sphere(&mut self, radius: GLdouble, slices: GLint, stacks: GLint) {
        let Some(sphere) = Sphere::new(radius, slices, stacks) else { return };
        self.drawing_shape(|gl| {
            for j in 0..slices {
                gl.shape_primitive(GL_LINE_STRIP, (0..=stacks).map(|i| sphere.point(i, j)));
            }
            for i in 1..stacks {
                gl.shape_primitive(GL_LINE_LOOP, (0..slices).map(|j| sphere.point(i, j)));
            }
        });
    }

    /// `glutSolidCone(base, height, slices, stacks)`: the base as a triangle strip facing down,
    /// then one strip a band of the side. Nothing for `slices < 1` or `stacks < 1`.
    pub fn glut_solid_cone(&mut self, base: GLdouble, height: GLdouble, slices: GLint, stacks: GLint) {
        let Some(cone) = Cone::new(base, height, slices, stacks) else { return };
        let centre = ([0.0, 0.0, -1.0], [0.0; 3]);
        self.drawing_shape(|gl| {
            gl.shape_primitive(GL_TRIANGLE_STRIP, (0..=slices).flat_map(|j| [centre, cone.rim(j % slices)]));
            for i in 0..stacks {
                let band = (0..=slices).flat_map(|j| [cone.side(i, j % slices), cone.side(i + 1, j % slices)]);
                gl.shape_primitive(GL_TRIANGLE_STRIP, band);
            }
        });
    }

    /// `glutWireCone(base, height, slices, stacks)`: lines from the rim to the apex, then a
    /// line loop a ring below the apex.
    pub fn glut_wire_cone(&mut self, base: GLdouble, height: GLdouble, slices: GLint, stacks: GLint) {
        let Some(cone) = Cone::new(base, height, slices, stacks) else { return };
        self.drawing_shape(|gl| {
            gl.shape_primitive(GL_LINES, (0..slices).flat_map(|j| [cone.side(0, j), cone.side(stacks, j)]));
            for i in 0..stacks {
                gl.shape_primitive(GL_LINE_LOOP, (0..slices).map(|j| cone.side(i, j)));
            }
        });
    }

    /// `glutSolidTorus(innerRadius, outerRadius, sides, rings)`: one triangle strip a side,
    /// all the way round the axis. Nothing for `sides < 2` or `rings < 2`.
    pub fn glut_solid_torus(&mut self, inner: GLdouble, outer: GLdouble, sides: GLint, rings: GLint) {
        let Some(torus) = Torus::new(inner, outer, sides, rings) else { return };
        self.drawing_shape(|gl| {
            for i in 0..sides {
                let strip =
                    (0..=rings).flat_map(|j| [torus.point(j % rings, i), torus.point(j % rings, (i + 1) % sides)]);
                gl.shape_primitive(GL_TRIANGLE_STRIP, strip);
            }
        });
    }

    /// `glutWireTorus(innerRadius, outerRadius, sides, rings)`: a line loop around the tube at
    /// each ring, then one around the axis at each side.
    pub fn glut_wire_torus(&mut self, inner: GLdouble, outer: GLdouble, sides: GLint, rings: GLint) {
        let Some(torus) = Torus::new(inner, outer, sides, rings) else { return };
        self.drawing_shape(|gl| {
            for j in 0..rings {
                gl.shape_primitive(GL_LINE_LOOP, (0..sides).map(|i| torus.point(j, i)));
            }
            for i in 0..sides {
                gl.shape_primitive(GL_LINE_LOOP, (0..rings).map(|j| torus.point(j, i)));
            }
        });
    }

    /// `glutSolidCube(size)`: two triangles a face (corners 0 1 2 and 0 2 3), in one
    /// `GL_TRIANGLES`.
    pub fn glut_solid_cube(&mut self, size: GLdouble) {
        let size = size as f32;
        let triangles = CUBE_FACES.iter().flat_map(|face| [0, 1, 2, 0, 2, 3].map(|k| cube_corner(face, k, size)));
        self.drawing_shape(|gl| gl.shape_primitive(GL_TRIANGLES, triangles));
    }

    /// `glutWireCube(size)`: a line loop a face.
    pub fn glut_wire_cube(&mut self, size: GLdouble) {
        let size = size as f32;
        self.drawing_shape(|gl| {
            for face in &CUBE_FACES {
                gl.shape_primitive(GL_LINE_LOOP, (0..4).map(|k| cube_corner(face, k, size)));
            }
        });
    }

    /// One primitive of a shape: each point's normal, then its vertex.
    pub(super) fn shape_primitive(&mut self, mode: GLenum, points: impl IntoIterator<Item = Point>) {
        self.begin(mode);
        for (n, v) in points {
            self.normal3f(n[0], n[1], n[2]);
            self.vertex3f(v[0], v[1], v[2]);
        }
        self.end();
    }

    /// Runs `draw` as freeglut's array drawing behaves in Mesa: inside `glBegin`/`glEnd` it is
    /// `GL_INVALID_OPERATION` and draws nothing (as `glDrawElements` there), and afterwards the
    /// current normal is the one before (arrays do not set it). In a display list being compiled
    /// that is the normal current when the list is called, kept by `glPushAttrib(GL_CURRENT_BIT)`,
    /// which saves nothing else the shapes change. (All checked with freeglut 3.4 on Mesa.)
    pub(super) fn drawing_shape(&mut self, draw: impl FnOnce(&mut Gl)) {
        if self.inside_begin_end() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let mut list = [0];
        self.get_integerv(GL_LIST_INDEX, &mut list);
        if list[0] != 0 {
            self.push_attrib(GL_CURRENT_BIT);
            draw(self);
            self.pop_attrib();
        } else {
            let [x, y, z] = self.server.current.normal;
            draw(self);
            self.normal3f(x, y, z);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vertices(gl: &mut Gl) -> Vec<[f32; 3]> {
        gl.frame().vertices.iter().map(|v| [v.position[0], v.position[1], v.position[2]]).collect()
    }

    #[test]
    fn the_circle_closes_exactly_and_turns_the_way_its_sign_says() {
        assert_eq!(circle(8, false, 8), (0.0, 1.0));
        assert_eq!(circle(8, true, 8), (0.0, -1.0));
        let (s, c) = circle(-4, false, 1);
        assert!((s + 1.0).abs() < 1e-7 && c.abs() < 1e-7, "a quarter turn clockwise: ({s}, {c})");
    }

    #[test]
    fn sphere_vertices_lie_on_the_sphere_and_their_normals_point_out() {
        let mut gl = Gl::new(10, 10);
        gl.glut_solid_sphere(2.0, 7, 5);
        // 5 bands of (7 + 1) pairs.
        assert_eq!(gl.frame().vertices.len(), 5 * 8 * 2);
        for v in &gl.frame().vertices {
            let r = v.position[..3].iter().map(|c| c * c).sum::<f32>().sqrt();
            assert!((r - 2.0).abs() < 1e-5, "radius {r}");
            for k in 0..3 {
                assert!((v.normal[k] * 2.0 - v.position[k]).abs() < 1e-5);
            }
        }
    }

    #[test]
    fn cube_faces_are_anticlockwise_seen_from_outside() {
        let mut gl = Gl::new(10, 10);
        gl.glut_solid_cube(3.0);
        let v = vertices(&mut gl);
        assert_eq!(v.len(), 36);
        for (t, tri) in v.chunks(3).enumerate() {
            let e1: Vec<f32> = (0..3).map(|k| tri[1][k] - tri[0][k]).collect();
            let e2: Vec<f32> = (0..3).map(|k| tri[2][k] - tri[0][k]).collect();
            let cross = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
            let n = gl.frame().vertices[3 * t].normal;
            let dot: f32 = (0..3).map(|k| cross[k] * n[k]).sum();
            assert!(dot > 0.0, "triangle {t} faces inward");
            assert!(tri.iter().all(|p| p.iter().all(|c| c.abs() == 1.5)));
        }
    }

    #[test]
    fn the_cone_runs_from_its_base_to_its_apex() {
        let mut gl = Gl::new(10, 10);
        gl.glut_wire_cone(1.0, 2.0, 6, 3);
        let v = vertices(&mut gl);
        // 6 lines (12 vertices) from rim to apex, then 3 rings of 6.
        assert_eq!(v.len(), 12 + 3 * 6);
        assert_eq!(v[0], [1.0, 0.0, 0.0]);
        assert!(v[1][0].abs() < 1e-6 && (v[1][2] - 2.0).abs() < 1e-6, "apex {:?}", v[1]);
        // The side's normal is perpendicular to the side, from the rim (1, 0, 0) to the apex (0, 0, 2).
        let n = gl.frame().vertices[0].normal;
        assert!((n[2] * 2.0 - n[0]).abs() < 1e-6, "normal {n:?}");
    }

    #[test]
    fn torus_points_lie_on_the_tube() {
        let mut gl = Gl::new(10, 10);
        gl.glut_wire_torus(0.5, 2.0, 5, 9);
        let v = vertices(&mut gl);
        assert_eq!(v.len(), 2 * 5 * 9);
        for p in v {
            let from_axis = (p[0] * p[0] + p[1] * p[1]).sqrt() - 2.0;
            assert!((from_axis * from_axis + p[2] * p[2] - 0.25).abs() < 1e-5);
        }
    }

    #[test]
    fn inside_begin_end_a_shape_is_an_error_and_draws_nothing() {
        let mut gl = Gl::new(10, 10);
        gl.begin(GL_LINES);
        gl.glut_wire_cube(1.0);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        let primitives: Vec<_> = gl.frame().primitives.iter().map(|p| (p.mode, p.count)).collect();
        assert_eq!(primitives, [(GL_LINES, 0)], "only the program's own primitive, empty");
    }

    #[test]
    fn a_shape_in_a_list_keeps_the_normal_current_when_the_list_is_called() {
        let mut gl = Gl::new(10, 10);
        let list = gl.gen_lists(1);
        gl.new_list(list, GL_COMPILE);
        gl.glut_solid_cube(1.0);
        gl.end_list();
        gl.normal3f(0.0, 0.0, 0.25);
        gl.call_list(list);
        assert_eq!(gl.server.current.normal, [0.0, 0.0, 0.25]);
        assert_eq!(gl.frame().vertices.len(), 36);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn shapes_keep_the_current_normal_and_bad_counts_draw_nothing() {
        let mut gl = Gl::new(10, 10);
        gl.normal3f(0.0, 0.6, 0.8);
        gl.glut_solid_torus(0.2, 1.0, 8, 8);
        gl.glut_wire_cube(1.0);
        assert_eq!(gl.server.current.normal, [0.0, 0.6, 0.8]);
        let before = gl.frame().vertices.len();
        gl.glut_solid_sphere(1.0, 0, 5);
        gl.glut_wire_sphere(1.0, -3, 5);
        gl.glut_solid_sphere(1.0, 5, 1);
        gl.glut_solid_cone(1.0, 1.0, 3, 0);
        gl.glut_wire_cone(1.0, 1.0, i32::MIN, 3);
        gl.glut_solid_torus(1.0, 2.0, 1, 5);
        gl.glut_wire_torus(1.0, 2.0, 5, -1);
        assert_eq!(gl.frame().vertices.len(), before);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}
