//! freeglut 3.4's tea set (`glutSolidTeapot`, `glutWireTeacup`, `glutSolidTeaspoon`, ...), drawn
//! as freeglut draws it (fg_teapot.c, read to learn its rules): each bicubic patch evaluated on
//! the CPU in `f32` on an 8 × 8 grid (solid) or 10 × 10 (wire), with the Bernstein weights and
//! their derivatives; normals from the cross product of the two tangents; the teapot's and
//! teacup's first six patches turned into the four quadrants and the others mirrored, the
//! teaspoon's patches as they are; the first row of normals of the teapot's lid top and of its
//! bottom's middle (where the tangents vanish) set straight up and down. Solids are one
//! `GL_TRIANGLES` (two triangles a grid square) with texture coordinates (u, v) per patch; wires
//! are line strips along both directions of every patch.
//!
//! freeglut computes the normals once, at the first call's size, and keeps them for later
//! sizes; so does this (for the GLUT program: every window's context of it), so that the same
//! calls light the same pixels.

use super::solids_data::*;
use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;

/// One of the tea set's pieces as freeglut keeps it.
struct Piece {
    control_points: &'static [f32],
    patches: &'static [u16],
    /// Rotate the first six patches into four quadrants and mirror the rest.
    rotate_flip: bool,
    /// The height freeglut subtracts to centre the piece.
    z_offset: f32,
    /// What freeglut divides the size by (in `f32`) to scale the control points.
    size_divisor: f32,
    /// The teapot's patches 3 (the lid's top) and 5 (the bottom's middle) meet at a point where
    /// the tangents vanish: their first row of normals is set to +y and -y.
    normal_fix: bool,
}

const TEAPOT: Piece = Piece {
    control_points: &TEAPOT_CP,
    patches: &TEAPOT_PATCHES,
    rotate_flip: true,
    z_offset: 1.575,
    size_divisor: 1.0,
    normal_fix: true,
};
const TEACUP: Piece = Piece {
    control_points: &TEACUP_CP,
    patches: &TEACUP_PATCHES,
    rotate_flip: true,
    z_offset: 1.5121,
    size_divisor: 2.5,
    normal_fix: false,
};
const TEASPOON: Piece = Piece {
    control_points: &TEASPOON_CP,
    patches: &TEASPOON_PATCHES,
    rotate_flip: false,
    z_offset: -0.0315,
    size_divisor: 2.5,
    normal_fix: false,
};

/// The Bernstein weight of degree 3 and its derivative, as freeglut computes them in `f32`.
fn bernstein3(i: usize, x: f32) -> (f32, f32) {
    let inv = 1.0 - x;
    match i {
        0 => {
            let t = inv * inv;
            (inv * t, -3.0 * t)
        }
        1 => {
            let t = inv * inv;
            (3.0 * x * t, 3.0 * t - 6.0 * x * inv)
        }
        2 => {
            let t = x * x;
            (3.0 * t * inv, 6.0 * x * inv - 3.0 * t)
        }
        _ => {
            let t = x * x;
            (x * t, 3.0 * t)
        }
    }
}

/// The weights at the grid's `n` samples.
fn weights(n: usize) -> (Vec<[f32; 4]>, Vec<[f32; 4]>) {
    let (mut b0, mut b1) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for s in 0..n {
        let x = s as f32 / (n as f32 - 1.0);
        let (mut w0, mut w1) = ([0.0; 4], [0.0; 4]);
        for i in 0..4 {
            (w0[i], w1[i]) = bernstein3(i, x);
        }
        b0.push(w0);
        b1.push(w1);
    }
    (b0, b1)
}

type Patch = [[[f32; 3]; 4]; 4];

/// Patch `p`'s control points, turned, scaled and moved as freeglut folds its
/// `glRotate(270, 1, 0, 0)`, `glScale(scale / 2)` and `glTranslate(0, 0, -z_offset)` into them.
fn control_points(piece: &Piece, p: usize, scale: f32) -> Patch {
    let mut cp = [[[0.0; 3]; 4]; 4];
    for i in 0..16 {
        let index = usize::from(piece.patches[p * 16 + i]);
        let c = &piece.control_points[3 * index..3 * index + 3];
        cp[i / 4][i % 4] = [c[0] * scale / 2.0, (c[2] - piece.z_offset) * scale / 2.0, -c[1] * scale / 2.0];
    }
    cp
}

/// A patch's grid points and unit normals, in freeglut's order and arithmetic.
fn evaluate(cp: &Patch, b0: &[[f32; 4]], b1: &[[f32; 4]]) -> (Vec<[f32; 3]>, Vec<[f32; 3]>) {
    let n = b0.len();
    let (mut verts, mut norms) = (Vec::with_capacity(n * n), Vec::with_capacity(n * n));
    for u in 0..n {
        for v in 0..n {
            let (mut vert, mut tan1, mut tan2) = ([0.0f32; 3], [0.0f32; 3], [0.0f32; 3]);
            for i in 0..4 {
                let (mut v0, mut v1) = ([0.0f32; 3], [0.0f32; 3]);
                for j in 0..4 {
                    for c in 0..3 {
                        v0[c] += b0[v][j] * cp[i][j][c];
                        v1[c] += b1[v][j] * cp[i][j][c];
                    }
                }
                for c in 0..3 {
                    vert[c] += b0[u][i] * v0[c];
                    tan1[c] += b0[u][i] * v1[c];
                    tan2[c] += b1[u][i] * v0[c];
                }
            }
            let mut normal = [
                tan1[1] * tan2[2] - tan1[2] * tan2[1],
                tan1[2] * tan2[0] - tan1[0] * tan2[2],
                tan1[0] * tan2[1] - tan1[1] * tan2[0],
            ];
            let squared = normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2];
            let len = f64::from(squared).sqrt() as f32;
            normal = normal.map(|c| c / len);
            verts.push(vert);
            norms.push(normal);
        }
    }
    (verts, norms)
}

/// freeglut's copies of a patch's values: turned into the other three quadrants about y
/// (`flag` 4), or mirrored in z with the rows reversed to keep the winding (`flag` 2).
fn copies(values: &[[f32; 3]], n: usize, flag: usize) -> Vec<[f32; 3]> {
    let mut out = values.to_vec();
    match flag {
        4 => {
            out.extend(values.iter().map(|&[x, y, z]| [z, y, -x]));
            out.extend(values.iter().map(|&[x, y, z]| [-x, y, -z]));
            out.extend(values.iter().map(|&[x, y, z]| [-z, y, x]));
        }
        2 => {
            for u in 0..n {
                let row = &values[(n - u - 1) * n..(n - u) * n];
                out.extend(row.iter().map(|&[x, y, z]| [x, y, -z]));
            }
        }
        _ => {}
    }
    out
}

/// The whole piece's grid points and normals (every patch and copy, in freeglut's order), the
/// normals from `first`, the size the piece was first drawn at.
fn generate(piece: &Piece, wire: bool, scale: f32, first: f32) -> (Vec<[f32; 3]>, Vec<[f32; 3]>, usize) {
    let n = if wire { 10 } else { 8 };
    let (b0, b1) = weights(n);
    let (mut verts, mut norms) = (Vec::new(), Vec::new());
    for p in 0..piece.patches.len() / 16 {
        let flag = if !piece.rotate_flip {
            1
        } else if p < 6 {
            4
        } else {
            2
        };
        let (v, _) = evaluate(&control_points(piece, p, scale), &b0, &b1);
        let (_, mut normals) = evaluate(&control_points(piece, p, first), &b0, &b1);
        if piece.normal_fix && (p == 3 || p == 5) {
            let y = if p == 3 { 1.0 } else { -1.0 };
            normals[..n].fill([0.0, y, 0.0]);
        }
        verts.extend(copies(&v, n, flag));
        norms.extend(copies(&normals, n, flag));
    }
    (verts, norms, n)
}

impl Gl {
    /// The size piece `which` (teapot, teacup, teaspoon), solid or wire, was first drawn at in
    /// this program: `scale` if this is the first time.
    fn tea_set_first_scale(&mut self, which: usize, wire: bool, scale: f32) -> f32 {
        *self.glut.program_mut().tea_set_first_scale[which][usize::from(wire)].get_or_insert(scale)
    }

    fn solid_piece(&mut self, piece: &Piece, which: usize, size: GLdouble) {
        let scale = size as f32 / piece.size_divisor;
        let first = self.tea_set_first_scale(which, false, scale);
        let (verts, norms, n) = generate(piece, false, scale, first);
        let patches = verts.len() / (n * n);
        let tex = |k: usize| {
            let (r, c) = ((k % (n * n)) / n, k % n);
            (r as f32 / (n as f32 - 1.0), c as f32 / (n as f32 - 1.0))
        };
        let [s0, t0, r0, q0] = self.server.current.tex_coord;
        self.drawing_shape(|gl| {
            gl.begin(GL_TRIANGLES);
            for p in 0..patches {
                for r in 0..n - 1 {
                    for c in 0..n - 1 {
                        let row1 = p * n * n + r * n + c;
                        let row2 = row1 + n;
                        for k in [row1, row2, row2 + 1, row1, row2 + 1, row1 + 1] {
                            let (s, t) = tex(k);
                            gl.tex_coord2f(s, t);
                            gl.normal3f(norms[k][0], norms[k][1], norms[k][2]);
                            gl.vertex3f(verts[k][0], verts[k][1], verts[k][2]);
                        }
                    }
                }
            }
            gl.end();
        });
        // Arrays leave the current texture coordinates alone, as they leave the normal.
        self.tex_coord4f(s0, t0, r0, q0);
    }

    fn wire_piece(&mut self, piece: &Piece, which: usize, size: GLdouble) {
        let scale = size as f32 / piece.size_divisor;
        let first = self.tea_set_first_scale(which, true, scale);
        let (verts, norms, n) = generate(piece, true, scale, first);
        let patches = verts.len() / (n * n);
        let point = |k: usize| (norms[k], verts[k]);
        self.drawing_shape(|gl| {
            for p in 0..patches {
                for c in 0..n {
                    gl.shape_primitive(GL_LINE_STRIP, (0..n).map(|r| point(p * n * n + r * n + c)));
                }
            }
            for p in 0..patches {
                for r in 0..n {
                    gl.shape_primitive(GL_LINE_STRIP, (0..n).map(|c| point(p * n * n + r * n + c)));
                }
            }
        });
    }

    /// `glutSolidTeapot(size)`: Newell's teapot, `size` its scale (GLUT's teapot is 3 · size
    /// wide).
    pub fn glut_solid_teapot(&mut self, size: GLdouble) {
        self.solid_piece(&TEAPOT, 0, size);
    }
    /// `glutWireTeapot(size)`.
    pub fn glut_wire_teapot(&mut self, size: GLdouble) {
        self.wire_piece(&TEAPOT, 0, size);
    }
    /// `glutSolidTeacup(size)` (freeglut).
    pub fn glut_solid_teacup(&mut self, size: GLdouble) {
        self.solid_piece(&TEACUP, 1, size);
    }
    /// `glutWireTeacup(size)` (freeglut).
    pub fn glut_wire_teacup(&mut self, size: GLdouble) {
        self.wire_piece(&TEACUP, 1, size);
    }
    /// `glutSolidTeaspoon(size)` (freeglut).
    pub fn glut_solid_teaspoon(&mut self, size: GLdouble) {
        self.solid_piece(&TEASPOON, 2, size);
    }
    /// `glutWireTeaspoon(size)` (freeglut).
    pub fn glut_wire_teaspoon(&mut self, size: GLdouble) {
        self.wire_piece(&TEASPOON, 2, size);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn odd_sizes_draw_without_panicking() {
        for size in [f64::NAN, f64::INFINITY, -1.0, 0.0, 1e30] {
            let mut gl = Gl::new(4, 4);
            gl.glut_solid_teacup(size);
            gl.glut_wire_teaspoon(size);
            gl.glut_solid_teapot(size);
            gl.glut_wire_teapot(size);
            assert_eq!(gl.get_error(), GL_NO_ERROR);
        }
    }
}
