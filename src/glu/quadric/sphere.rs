//! `gluSphere` (`quad.c`): a sphere about the origin, cut into `slices` around the z axis and
//! `stacks` from +z (stack boundary 0) to −z.

use super::{fraction, sin_cos, Cache, Quadric, QuadricSink, CACHE_SIZE, PI};
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::glu::consts::*;

/// What every part of one sphere shares. `a` caches run around (slice boundaries), `b` caches
/// down (stack boundaries); 1 are positions, 2 the vertices' normals, 3 the faces' normals
/// (half a step back).
struct Sphere {
    q: Quadric,
    radius: f64,
    slices: i32,
    stacks: i32,
    a1: Cache,
    a3: Cache,
    /// `radius · (sin, cos)` down the sphere, the sines at the poles forced to 0.
    b1: Cache,
    b2: Cache,
    b3: Cache,
}

impl Quadric {
    /// `gluSphere`: `Err(GLU_INVALID_VALUE)` (nothing drawn) for fewer than 2 slices or 1
    /// stack (after clamping both to 239) or a negative radius.
    pub fn sphere(&self, sink: &mut impl QuadricSink, radius: f64, slices: i32, stacks: i32) -> Result<(), GLenum> {
        let (slices, stacks) = (slices.min(CACHE_SIZE - 1), stacks.min(CACHE_SIZE - 1));
        if slices < 2 || stacks < 1 || radius < 0.0 {
            return Err(GLU_INVALID_VALUE);
        }
        let around = |i: i32| (2.0 * PI * f64::from(i) / f64::from(slices)) as f32;
        let around_face = |i: i32| (2.0 * PI * (f64::from(i) - 0.5) / f64::from(slices)) as f32;
        let down = |j: i32| (PI * f64::from(j) / f64::from(stacks)) as f32;
        let down_face = |j: i32| (PI * (f64::from(j) - 0.5) / f64::from(stacks)) as f32;
        let mut b1 = Cache::scaled(stacks + 1, radius, down);
        b1.sin[0] = 0.0;
        b1.sin[stacks as usize] = 0.0;
        let sphere = Sphere {
            q: *self,
            radius,
            slices,
            stacks,
            a1: Cache::scaled(slices, 1.0, around).closed(),
            a3: Cache::scaled(slices, 1.0, around_face).closed(),
            b1,
            b2: Cache::scaled(stacks + 1, self.facing(1.0), down),
            b3: Cache::scaled(stacks + 1, self.facing(1.0), down_face),
        };
        match self.draw_style {
            GLU_FILL => sphere.fill(sink),
            GLU_POINT => sphere.points(sink),
            GLU_LINE | GLU_SILHOUETTE => sphere.lines(sink),
            _ => {}
        }
        Ok(())
    }
}

impl Sphere {
    /// The smooth normals around: the positions' cache (`quad.c` copies it). Past `slices`
    /// (read only by the south pole when `stacks > slices`, where GLU reads an unfilled
    /// entry) the angle goes on around.
    fn a2(&self, i: i32) -> (f32, f32) {
        if i <= self.slices {
            self.a1.at(i)
        } else {
            sin_cos((2.0 * PI * f64::from(i) / f64::from(self.slices)) as f32)
        }
    }

    fn tex(&self, sink: &mut impl QuadricSink, i: i32, j: i32) {
        if self.q.texture {
            sink.tex_coord([1.0 - fraction(i, self.slices), 1.0 - fraction(j, self.stacks)]);
        }
    }

    /// The vertex at slice `i` on the ring of stack boundary `j`.
    fn vertex(&self, sink: &mut impl QuadricSink, i: i32, j: i32) {
        let ((s, c), (r, z)) = (self.a1.at(i), self.b1.at(j));
        sink.vertex([r * s, r * c, z]);
    }

    /// A normal around slice `i` (from `around`) tilted by `(sin, cos)` down.
    fn normal(sink: &mut impl QuadricSink, around: (f32, f32), (sin, cos): (f32, f32)) {
        sink.normal([around.0 * sin, around.1 * sin, cos]);
    }

    /// `GLU_FILL`: triangle fans at the poles (unless texturing, which needs a texture
    /// coordinate per apex) and a quad strip per stack between them.
    fn fill(&self, sink: &mut impl QuadricSink) {
        let rows = if self.q.texture {
            0..self.stacks
        } else {
            self.fan(sink, true);
            self.fan(sink, false);
            1..self.stacks - 1
        };
        for j in rows {
            self.strip(sink, j);
        }
    }

    /// The fan around the north (`north`) or south pole.
    fn fan(&self, sink: &mut impl QuadricSink, north: bool) {
        let (ring, apex) = if north { (1, self.radius) } else { (self.stacks - 1, -self.radius) };
        let tilt = match self.q.normals {
            GLU_FLAT => self.b3.at(if north { 1 } else { self.stacks }),
            GLU_SMOOTH => {
                let pole = if north { 0 } else { self.stacks };
                Self::normal(sink, self.a2(pole), (self.b2.sin[pole as usize], self.b2.cos[pole as usize]));
                self.b2.at(ring)
            }
            _ => (0.0, 0.0),
        };
        sink.begin(GL_TRIANGLE_FAN);
        sink.vertex([0.0, 0.0, apex as f32]);
        // Facing out, the north fan runs backwards around (so does the south one facing in);
        // a backward fan's flat normal is the next face's, and its first vertex has none.
        let backward = north == self.q.outside();
        let order: Vec<i32> = if backward { (0..=self.slices).rev().collect() } else { (0..=self.slices).collect() };
        for i in order {
            match self.q.normals {
                GLU_SMOOTH => Self::normal(sink, self.a2(i), tilt),
                GLU_FLAT if !backward => Self::normal(sink, self.a3.at(i), tilt),
                GLU_FLAT if i != self.slices => Self::normal(sink, self.a3.at(i + 1), tilt),
                _ => {}
            }
            self.vertex(sink, i, ring);
        }
        sink.end();
    }

    /// The quad strip between stack boundaries `j` and `j + 1`.
    fn strip(&self, sink: &mut impl QuadricSink, j: i32) {
        let (first, second) = if self.q.outside() { (j + 1, j) } else { (j, j + 1) };
        let tilt_second = match self.q.normals {
            GLU_FLAT => self.b3.at(j + 1),
            _ => self.b2.at(second),
        };
        sink.begin(GL_QUAD_STRIP);
        for i in 0..=self.slices {
            if self.q.normals == GLU_SMOOTH {
                Self::normal(sink, self.a2(i), self.b2.at(first));
            }
            self.tex(sink, i, first);
            self.vertex(sink, i, first);
            match self.q.normals {
                GLU_SMOOTH => Self::normal(sink, self.a2(i), tilt_second),
                GLU_FLAT => Self::normal(sink, self.a3.at(i), tilt_second),
                _ => {}
            }
            self.tex(sink, i, second);
            self.vertex(sink, i, second);
        }
        sink.end();
    }

    /// `GLU_POINT`: every vertex, ring by ring from the north pole (a pole repeats its point
    /// once per slice), each with its smooth normal.
    fn points(&self, sink: &mut impl QuadricSink) {
        sink.begin(GL_POINTS);
        for j in 0..=self.stacks {
            for i in 0..self.slices {
                if self.q.normals != GLU_NONE {
                    Self::normal(sink, self.a2(i), self.b2.at(j));
                }
                self.tex(sink, i, j);
                self.vertex(sink, i, j);
            }
        }
        sink.end();
    }

    /// `GLU_LINE` and `GLU_SILHOUETTE` (the same in `quad.c`): the rings between the poles,
    /// then a line from pole to pole along each slice.
    fn lines(&self, sink: &mut impl QuadricSink) {
        for j in 1..self.stacks {
            sink.begin(GL_LINE_STRIP);
            for i in 0..=self.slices {
                match self.q.normals {
                    GLU_FLAT => Self::normal(sink, self.a3.at(i), self.b2.at(j)),
                    GLU_SMOOTH => Self::normal(sink, self.a2(i), self.b2.at(j)),
                    _ => {}
                }
                self.tex(sink, i, j);
                self.vertex(sink, i, j);
            }
            sink.end();
        }
        for i in 0..self.slices {
            sink.begin(GL_LINE_STRIP);
            for j in 0..=self.stacks {
                match self.q.normals {
                    GLU_FLAT => Self::normal(sink, self.a2(i), self.b3.at(j)),
                    GLU_SMOOTH => Self::normal(sink, self.a2(i), self.b2.at(j)),
                    _ => {}
                }
                self.tex(sink, i, j);
                self.vertex(sink, i, j);
            }
            sink.end();
        }
    }
}
