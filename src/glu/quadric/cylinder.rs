//! `gluCylinder` (`quad.c`): a cylinder or cone along +z from `z = 0` (radius `base`) to
//! `z = height` (radius `top`), cut into `slices` around and `stacks` along.

use super::{fraction, Cache, Quadric, QuadricSink, CACHE_SIZE, PI};
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::glu::consts::*;

/// What every part of one cylinder shares.
struct Cylinder {
    q: Quadric,
    base: f64,
    height: f64,
    slices: i32,
    stacks: i32,
    /// `base - top`, a float in `quad.c`.
    delta_radius: f32,
    /// The z of every normal (the cone's slope).
    z_normal: f32,
    /// Vertex positions around.
    around: Cache,
    /// Normals at the vertices (smooth).
    smooth: Cache,
    /// Normals of the faces, half a slice back (flat).
    flat: Cache,
}

impl Quadric {
    /// `gluCylinder`: `Err(GLU_INVALID_VALUE)` (nothing drawn) for fewer than 2 slices (after
    /// clamping to 239), fewer than 1 stack, a negative radius or height, or a cylinder of no
    /// length (both radii and the height 0).
    pub fn cylinder(
        &self,
        sink: &mut impl QuadricSink,
        base: f64,
        top: f64,
        height: f64,
        slices: i32,
        stacks: i32,
    ) -> Result<(), GLenum> {
        let slices = slices.min(CACHE_SIZE - 1);
        if slices < 2 || stacks < 1 || base < 0.0 || top < 0.0 || height < 0.0 {
            return Err(GLU_INVALID_VALUE);
        }
        let delta_radius = (base - top) as f32;
        let length = (f64::from(delta_radius * delta_radius) + height * height).sqrt() as f32;
        if length == 0.0 {
            return Err(GLU_INVALID_VALUE);
        }
        let xy_ratio = (height / f64::from(length)) as f32;
        let normal_scale = self.facing(f64::from(xy_ratio));
        let angle = |i: i32| (2.0 * PI * f64::from(i) / f64::from(slices)) as f32;
        let face_angle = |i: i32| (2.0 * PI * (f64::from(i) - 0.5) / f64::from(slices)) as f32;
        let c = Cylinder {
            q: *self,
            base,
            height,
            slices,
            stacks,
            delta_radius,
            z_normal: delta_radius / length,
            around: Cache::scaled(slices, 1.0, angle).closed(),
            smooth: Cache::scaled(slices, normal_scale, angle).closed(),
            flat: Cache::scaled(slices, normal_scale, face_angle).closed(),
        };
        match self.draw_style {
            GLU_FILL => c.fill(sink),
            GLU_POINT => c.points(sink),
            GLU_LINE => {
                c.rings(sink, 1..stacks);
                c.silhouette(sink);
            }
            GLU_SILHOUETTE => c.silhouette(sink),
            _ => {}
        }
        Ok(())
    }
}

impl Cylinder {
    /// The z of stack boundary `j`.
    fn z(&self, j: i32) -> f32 {
        (f64::from(j) * self.height / f64::from(self.stacks)) as f32
    }

    /// The radius at stack boundary `j`.
    fn radius(&self, j: i32) -> f32 {
        (self.base - f64::from(self.delta_radius * fraction(j, self.stacks))) as f32
    }

    /// The normal at slice `i` of a ring or strip: the face's (flat) or the vertex's (smooth).
    fn ring_normal(&self, sink: &mut impl QuadricSink, i: i32) {
        let cache = match self.q.normals {
            GLU_FLAT => &self.flat,
            GLU_SMOOTH => &self.smooth,
            _ => return,
        };
        let (s, c) = cache.at(i);
        sink.normal([s, c, self.z_normal]);
    }

    fn tex(&self, sink: &mut impl QuadricSink, i: i32, j: i32) {
        if self.q.texture {
            sink.tex_coord([1.0 - fraction(i, self.slices), fraction(j, self.stacks)]);
        }
    }

    fn vertex(&self, sink: &mut impl QuadricSink, i: i32, j: i32) {
        let (s, c) = self.around.at(i);
        let r = self.radius(j);
        sink.vertex([r * s, r * c, self.z(j)]);
    }

    /// `GLU_FILL`: one quad strip per stack.
    fn fill(&self, sink: &mut impl QuadricSink) {
        for j in 0..self.stacks {
            sink.begin(GL_QUAD_STRIP);
            for i in 0..=self.slices {
                self.ring_normal(sink, i);
                let order = if self.q.outside() { [j, j + 1] } else { [j + 1, j] };
                for row in order {
                    self.tex(sink, i, row);
                    self.vertex(sink, i, row);
                }
            }
            sink.end();
        }
    }

    /// `GLU_POINT`: the vertices, slice by slice, each slice's smooth normal first.
    fn points(&self, sink: &mut impl QuadricSink) {
        sink.begin(GL_POINTS);
        for i in 0..self.slices {
            self.line_normal(sink, i, self.z_normal);
            for j in 0..=self.stacks {
                self.tex(sink, i, j);
                self.vertex(sink, i, j);
            }
        }
        sink.end();
    }

    /// The rings at stack boundaries `rows`, as line strips.
    fn rings(&self, sink: &mut impl QuadricSink, rows: impl Iterator<Item = i32>) {
        for j in rows {
            sink.begin(GL_LINE_STRIP);
            for i in 0..=self.slices {
                self.ring_normal(sink, i);
                self.tex(sink, i, j);
                self.vertex(sink, i, j);
            }
            sink.end();
        }
    }

    /// `GLU_SILHOUETTE` (and the end of `GLU_LINE`): the two end rings, then a line along each
    /// slice with its smooth normal flattened into the xy plane.
    fn silhouette(&self, sink: &mut impl QuadricSink) {
        self.rings(sink, [0, self.stacks].into_iter());
        for i in 0..self.slices {
            self.line_normal(sink, i, 0.0);
            sink.begin(GL_LINE_STRIP);
            for j in 0..=self.stacks {
                self.tex(sink, i, j);
                self.vertex(sink, i, j);
            }
            sink.end();
        }
    }

    /// The smooth normal of slice `i` with the given z, for any normal mode but `GLU_NONE`.
    fn line_normal(&self, sink: &mut impl QuadricSink, i: i32, z: f32) {
        if self.q.normals != GLU_NONE {
            let (s, c) = self.smooth.at(i);
            sink.normal([s, c, z]);
        }
    }
}
