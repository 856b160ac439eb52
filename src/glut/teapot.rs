//! `glutSolidTeapot` and `glutWireTeapot`, drawn as GLUT 3.7's `teapot.c` draws them: through
//! the GL evaluators, one `glMap2f` per bicubic patch with a bilinear texture-coordinate map, so
//! the teapot is lit with `GL_AUTO_NORMAL` normals and textured with (s, t) = (u, v) per patch.
//! The control points are Newell's 32 patches ([`crate::data::teapot`]) rather than GLUT's 10
//! and their mirror images: the same surface, other patch boundaries.

use crate::data::teapot::{TEAPOT_PATCHES, TEAPOT_VERTICES};
use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;

impl Gl {
    /// `glutSolidTeapot(size)`: the teapot filled, on a 14 × 14 grid per patch.
    pub fn glut_solid_teapot(&mut self, size: GLdouble) {
        self.teapot(14, size, GL_FILL);
    }

    /// `glutWireTeapot(size)`: the teapot as lines, on a 10 × 10 grid per patch.
    pub fn glut_wire_teapot(&mut self, size: GLdouble) {
        self.teapot(10, size, GL_LINE);
    }

    /// GLUT's `teapot(grid, scale, type)`: the evaluator state and enables it changes are
    /// saved and restored around it, as GLUT does.
    fn teapot(&mut self, grid: GLint, size: GLdouble, mode: GLenum) {
        self.push_attrib(GL_ENABLE_BIT | GL_EVAL_BIT);
        self.enable(GL_AUTO_NORMAL);
        self.enable(GL_NORMALIZE);
        self.enable(GL_MAP2_VERTEX_3);
        self.enable(GL_MAP2_TEXTURE_COORD_2);
        self.push_matrix();
        self.rotatef(270.0, 1.0, 0.0, 0.0);
        let scale = (0.5 * size) as f32;
        self.scalef(scale, scale, scale);
        self.translatef(0.0, 0.0, -1.5);
        let tex: [f32; 8] = [0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        for patch in &TEAPOT_PATCHES {
            // Row j, column k of the patch at (j · 4 + k) · 3, as GLUT fills its `p`.
            let p: Vec<f32> =
                patch.iter().flat_map(|&index| TEAPOT_VERTICES[usize::from(index)].map(|c| c as f32)).collect();
            self.map2f(GL_MAP2_TEXTURE_COORD_2, 0.0, 1.0, 2, 2, 0.0, 1.0, 4, 2, &tex);
            self.map2f(GL_MAP2_VERTEX_3, 0.0, 1.0, 3, 4, 0.0, 1.0, 12, 4, &p);
            self.map_grid2f(grid, 0.0, 1.0, grid, 0.0, 1.0);
            self.eval_mesh2(mode, 0, grid, 0, grid);
        }
        self.pop_matrix();
        self.pop_attrib();
    }
}
