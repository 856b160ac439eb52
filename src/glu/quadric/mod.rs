//! GLU's quadrics (GLU 1.3 §6; SGI GLU 9.0 `libutil/quad.c`): spheres, cylinders (and cones),
//! disks and partial disks, drawn as GL primitives in one of four styles, with flat, smooth or
//! no normals, facing out or in, with or without texture coordinates.
//!
//! The shapes are written out to a [`QuadricSink`] (GL's `glBegin`, `glNormal3f`,
//! `glTexCoord2f`, `glVertex3f`, `glEnd`): [`Gl`](crate::gl::Gl) is one, so
//! `gl.glu_sphere(q, ...)` draws through GL as GLU does; any other sink receives the same calls
//! without GL (a mesh builder, a test's recorder).
//!
//! The output is `quad.c`'s call for call and bit for bit: the same primitives, in the same
//! order, with every value computed in the precision `quad.c` computes it (angles stored as
//! floats, sines and cosines in double, radii interpolated in float), checked against real
//! GLU 9.0.2 by `tests/reference/glu/quadrics.c`. Where `quad.c` reads a normal cache it never
//! filled (`GLU_FLAT` with `GLU_POINT` or `GLU_SILHOUETTE`, and a sphere's south-pole normal
//! when `stacks > slices`), GLU's normals are whatever was on its stack; here they are the
//! smooth normals that cache holds when it is filled.
//!
//! ```
//! use gleval::glu::consts::*;
//! use gleval::glu::quadric::{Quadric, QuadricSink};
//!
//! #[derive(Default)]
//! struct Count(usize, usize);
//! impl QuadricSink for Count {
//!     fn begin(&mut self, _mode: u32) { self.0 += 1 }
//!     fn end(&mut self) {}
//!     fn normal(&mut self, _n: [f32; 3]) {}
//!     fn tex_coord(&mut self, _t: [f32; 2]) {}
//!     fn vertex(&mut self, _v: [f32; 3]) { self.1 += 1 }
//! }
//! let mut count = Count::default();
//! Quadric::DEFAULT.sphere(&mut count, 1.0, 8, 4).unwrap();
//! // Two triangle fans at the poles and two quad strips between them.
//! assert_eq!((count.0, count.1), (4, 2 * 10 + 2 * 18));
//! assert_eq!(Quadric::DEFAULT.sphere(&mut count, 1.0, 1, 4), Err(GLU_INVALID_VALUE));
//! ```

mod calls;
mod cylinder;
mod disk;
mod sphere;

pub(crate) use calls::QuadricObject;
pub use calls::{GLUquadric, QuadricErrorFn};

use crate::gl::types::GLenum;
use crate::glu::consts::*;

/// `quad.c`'s `CACHE_SIZE`: slices (and a sphere's stacks) are clamped below it.
const CACHE_SIZE: i32 = 240;

/// `quad.c`'s `PI`.
const PI: f64 = std::f64::consts::PI;

/// Where a quadric's GL calls go: GL itself, or anything that wants the same calls.
pub trait QuadricSink {
    /// `glBegin(mode)`.
    fn begin(&mut self, mode: GLenum);
    /// `glEnd()`.
    fn end(&mut self);
    /// `glNormal3f`.
    fn normal(&mut self, n: [f32; 3]);
    /// `glTexCoord2f`.
    fn tex_coord(&mut self, t: [f32; 2]);
    /// `glVertex3f`.
    fn vertex(&mut self, v: [f32; 3]);
}

/// The modes of a quadric object (`gluQuadricDrawStyle`, `gluQuadricNormals`,
/// `gluQuadricOrientation`, `gluQuadricTexture`), with GLU's defaults in [`Quadric::DEFAULT`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Quadric {
    /// `GLU_FILL`, `GLU_LINE`, `GLU_SILHOUETTE` or `GLU_POINT`.
    pub draw_style: GLenum,
    /// `GLU_NONE`, `GLU_FLAT` or `GLU_SMOOTH`.
    pub normals: GLenum,
    /// `GLU_OUTSIDE` or `GLU_INSIDE`.
    pub orientation: GLenum,
    /// Whether texture coordinates are generated.
    pub texture: bool,
}

impl Default for Quadric {
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl Quadric {
    /// `gluNewQuadric`'s modes: filled, smooth normals, facing out, no texture coordinates.
    pub const DEFAULT: Self =
        Self { draw_style: GLU_FILL, normals: GLU_SMOOTH, orientation: GLU_OUTSIDE, texture: false };

    /// Sets the draw style; `Err(GLU_INVALID_ENUM)` (and no change) for another value.
    pub fn set_draw_style(&mut self, style: GLenum) -> Result<(), GLenum> {
        match style {
            GLU_POINT | GLU_LINE | GLU_FILL | GLU_SILHOUETTE => {
                self.draw_style = style;
                Ok(())
            }
            _ => Err(GLU_INVALID_ENUM),
        }
    }

    /// Sets the normal mode; `Err(GLU_INVALID_ENUM)` (and no change) for another value.
    pub fn set_normals(&mut self, normals: GLenum) -> Result<(), GLenum> {
        match normals {
            GLU_SMOOTH | GLU_FLAT | GLU_NONE => {
                self.normals = normals;
                Ok(())
            }
            _ => Err(GLU_INVALID_ENUM),
        }
    }

    /// Sets the orientation; `Err(GLU_INVALID_ENUM)` (and no change) for another value.
    pub fn set_orientation(&mut self, orientation: GLenum) -> Result<(), GLenum> {
        match orientation {
            GLU_OUTSIDE | GLU_INSIDE => {
                self.orientation = orientation;
                Ok(())
            }
            _ => Err(GLU_INVALID_ENUM),
        }
    }

    fn outside(&self) -> bool {
        self.orientation == GLU_OUTSIDE
    }

    /// `x` facing out, `-x` facing in: a normal's scale. A negation, as `quad.c`'s
    /// `-xyNormalRatio`, so that even a NaN's sign is GLU's.
    fn facing(&self, x: f64) -> f64 {
        if self.outside() {
            x
        } else {
            -x
        }
    }
}

/// `(float) j / n`, as `quad.c` writes its fractions.
fn fraction(j: i32, n: i32) -> f32 {
    j as f32 / n as f32
}

/// The sine and cosine of an angle `quad.c` stored in a `GLfloat`, computed in double (GLU calls
/// `sin`/`cos`) and stored as floats.
fn sin_cos(angle: f32) -> (f32, f32) {
    let a = f64::from(angle);
    (a.sin() as f32, a.cos() as f32)
}

/// A cache of sines and cosines, `n + 1` long (entry `n` repeats entry 0 where `quad.c` closes
/// the circle).
#[derive(Clone, Default)]
struct Cache {
    sin: Vec<f32>,
    cos: Vec<f32>,
}

impl Cache {
    /// `(sin, cos)` of `angle(i)` scaled by `scale` (in double), for `i` in `0..n`.
    fn scaled(n: i32, scale: f64, angle: impl Fn(i32) -> f32) -> Self {
        let mut cache = Self::default();
        for i in 0..n {
            let a = f64::from(angle(i));
            cache.sin.push((scale * a.sin()) as f32);
            cache.cos.push((scale * a.cos()) as f32);
        }
        cache
    }

    /// Entry `n` repeats entry 0.
    fn closed(mut self) -> Self {
        if let (Some(&s), Some(&c)) = (self.sin.first(), self.cos.first()) {
            self.sin.push(s);
            self.cos.push(c);
        }
        self
    }

    fn at(&self, i: i32) -> (f32, f32) {
        (self.sin[i as usize], self.cos[i as usize])
    }
}
