//! freeglut 3.4's cylinder (`glutSolidCylinder`, `glutWireCylinder`), drawn as freeglut draws
//! it (fg_geometry.c's fghGenerateCylinder and fghCylinder, read to learn their rules): a
//! circle of `slices` points turning clockwise seen from +z, repeated for the cap at z = 0
//! (normal −z), for each of the `stacks + 1` rings of the side (outward normals, z stepped in
//! `f32`), and for the cap at the last ring's height (normal +z), between a centre at z = 0 and
//! one at z = `height`. The solid is `stacks + 2` triangle strips (the caps' strips included,
//! with freeglut's indices); the wire is lines along the side and a loop a ring.

use super::shapes::{circle, Point};
use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;

/// freeglut indexes its vertices with `GLushort`s: beyond this many it warns that "indices
/// will wrap" and draws a mangled shape; gleval warns the same and draws nothing (and never
/// runs out of memory for absurd counts).
const MAX_VERTICES: i64 = 65535;

/// The cylinder's vertices in freeglut's order; empty for `slices < 1` or `stacks < 1`.
fn vertices(radius: f32, height: f32, slices: i32, stacks: i32) -> Vec<Point> {
    if slices < 1 || stacks < 1 {
        return Vec::new();
    }
    if i64::from(slices) * (i64::from(stacks) + 3) + 2 > MAX_VERTICES {
        eprintln!("freeglut: fghGenerateCylinder: too many slices or stacks requested, indices will wrap");
        return Vec::new();
    }
    let step = height / stacks as f32;
    let ring = |z: f32, normal: Option<f32>| {
        (0..slices).map(move |j| {
            let (s, c) = circle(-slices, false, j);
            let n = normal.map_or([c, s, 0.0], |nz| [0.0, 0.0, nz]);
            (n, [c * radius, s * radius, z])
        })
    };
    let mut out = vec![([0.0, 0.0, -1.0], [0.0, 0.0, 0.0])];
    out.extend(ring(0.0, Some(-1.0)));
    let mut z = 0.0f32;
    for _ in 0..=stacks {
        out.extend(ring(z, None));
        z += step;
    }
    z -= step;
    out.extend(ring(z, Some(1.0)));
    out.push(([0.0, 0.0, 1.0], [0.0, 0.0, height]));
    out
}

/// The solid's strips as freeglut indexes them.
fn strips(slices: i32, stacks: i32, count: usize) -> Vec<Vec<usize>> {
    let n = slices as usize;
    let mut strips = Vec::new();
    let mut top: Vec<usize> = (0..n).flat_map(|j| [0, j + 1]).collect();
    top.extend([0, 1]);
    strips.push(top);
    for i in 0..stacks as usize {
        let offset = 1 + (i + 1) * n;
        let mut strip: Vec<usize> = (0..n).flat_map(|j| [offset + j, offset + j + n]).collect();
        strip.extend([offset, offset + n]);
        strips.push(strip);
    }
    // The last strip: the +z cap's ring about the centre at z = height.
    let offset = 1 + (stacks as usize + 2) * n;
    let mut bottom: Vec<usize> = (0..n).flat_map(|j| [offset + j, count - 1]).collect();
    bottom.extend([offset, count - 1]);
    strips.push(bottom);
    strips
}

impl Gl {
    /// `glutSolidCylinder(radius, height, slices, stacks)` (freeglut).
    pub fn glut_solid_cylinder(&mut self, radius: GLdouble, height: GLdouble, slices: GLint, stacks: GLint) {
        let points = vertices(radius as f32, height as f32, slices, stacks);
        if points.is_empty() {
            return;
        }
        let strips = strips(slices, stacks, points.len());
        self.drawing_shape(|gl| {
            for strip in strips {
                gl.shape_primitive(GL_TRIANGLE_STRIP, strip.iter().map(|&i| points[i]));
            }
        });
    }

    /// `glutWireCylinder(radius, height, slices, stacks)` (freeglut): a line along the side at
    /// each slice, then a loop at each ring.
    pub fn glut_wire_cylinder(&mut self, radius: GLdouble, height: GLdouble, slices: GLint, stacks: GLint) {
        let points = vertices(radius as f32, height as f32, slices, stacks);
        if points.is_empty() {
            return;
        }
        let n = slices as usize;
        let stacks = stacks as usize;
        self.drawing_shape(|gl| {
            gl.shape_primitive(GL_LINES, (0..n).flat_map(|i| [points[1 + i + n], points[1 + i + (stacks + 1) * n]]));
            for i in 0..=stacks {
                let offset = 1 + (i + 1) * n;
                gl.shape_primitive(GL_LINE_LOOP, (0..n).map(|j| points[offset + j]));
            }
        });
    }
}
