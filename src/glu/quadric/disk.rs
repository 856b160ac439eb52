//! `gluDisk` and `gluPartialDisk` (`quad.c`): a ring in the z = 0 plane between two radii,
//! cut into `slices` around and `loops` across, over a sweep of angles measured clockwise
//! from +y.

use super::{fraction, sin_cos, Quadric, QuadricSink, CACHE_SIZE, PI};
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::glu::consts::*;

/// What every part of one disk shares.
struct Disk {
    q: Quadric,
    inner: f64,
    outer: f64,
    slices: i32,
    loops: i32,
    /// Slices that have their own radial line: one more than `slices` unless the sweep closes.
    spokes: i32,
    /// `outer - inner`, a float in `quad.c`.
    delta_radius: f32,
    /// The sweep is below 360 (false for a NaN sweep, as GLU's test): the silhouette draws the
    /// straight edges.
    partial: bool,
    sin: Vec<f32>,
    cos: Vec<f32>,
}

impl Quadric {
    /// `gluDisk`: `gluPartialDisk` over the whole circle.
    pub fn disk(
        &self,
        sink: &mut impl QuadricSink,
        inner: f64,
        outer: f64,
        slices: i32,
        loops: i32,
    ) -> Result<(), GLenum> {
        self.partial_disk(sink, inner, outer, slices, loops, 0.0, 360.0)
    }

    /// `gluPartialDisk`: `Err(GLU_INVALID_VALUE)` (nothing drawn) for fewer than 2 slices
    /// (after clamping to 239), fewer than 1 loop, an outer radius not above 0, a negative inner
    /// radius or one beyond the outer. A sweep beyond ±360 is 360 (GLU's clamp, even below
    /// −360); a negative sweep runs from `start + sweep` instead.
    #[allow(clippy::too_many_arguments)]
    pub fn partial_disk(
        &self,
        sink: &mut impl QuadricSink,
        inner: f64,
        outer: f64,
        slices: i32,
        loops: i32,
        start: f64,
        sweep: f64,
    ) -> Result<(), GLenum> {
        let slices = slices.min(CACHE_SIZE - 1);
        if slices < 2 || loops < 1 || outer <= 0.0 || inner < 0.0 || inner > outer {
            return Err(GLU_INVALID_VALUE);
        }
        let (start, sweep) = normalised_sweep(start, sweep);
        let full_circle = sweep == 360.0;
        let offset = (start / 180.0 * PI) as f32;
        let step = PI * sweep / 180.0;
        let mut angles: Vec<(f32, f32)> = (0..=slices)
            .map(|i| sin_cos((f64::from(offset) + step * f64::from(i) / f64::from(slices)) as f32))
            .collect();
        if full_circle {
            angles[slices as usize] = angles[0];
        }
        let disk = Disk {
            q: *self,
            inner,
            outer,
            slices,
            loops,
            spokes: if full_circle { slices } else { slices + 1 },
            delta_radius: (outer - inner) as f32,
            partial: sweep < 360.0,
            sin: angles.iter().map(|a| a.0).collect(),
            cos: angles.iter().map(|a| a.1).collect(),
        };
        disk.draw(sink);
        Ok(())
    }
}

/// GLU's sweep rules: beyond ±360 is 360; a negative sweep starts that much earlier. A NaN
/// sweep stays NaN (GLU's two comparisons are false for it; `RangeInclusive::contains` would
/// make it 360).
#[allow(clippy::manual_range_contains)]
fn normalised_sweep(mut start: f64, mut sweep: f64) -> (f64, f64) {
    if sweep < -360.0 || sweep > 360.0 {
        sweep = 360.0;
    }
    if sweep < 0.0 {
        start += sweep;
        sweep = -sweep;
    }
    (start, sweep)
}

impl Disk {
    fn draw(&self, sink: &mut impl QuadricSink) {
        if self.q.normals != GLU_NONE {
            sink.normal([0.0, 0.0, if self.q.outside() { 1.0 } else { -1.0 }]);
        }
        match self.q.draw_style {
            GLU_FILL => self.fill(sink),
            GLU_POINT => self.points(sink),
            GLU_LINE if self.inner == self.outer => self.circle(sink),
            GLU_LINE => {
                self.rings(sink, 0..=self.loops);
                self.spokes(sink, 0..self.spokes);
            }
            GLU_SILHOUETTE => self.silhouette(sink),
            _ => {}
        }
    }

    /// The radius of loop boundary `j` (0 is the outer edge).
    fn radius(&self, j: i32) -> f32 {
        (self.outer - f64::from(self.delta_radius * fraction(j, self.loops))) as f32
    }

    /// The vertex of slice `i` at radius `r`, after its texture coordinate when texturing is
    /// on: the disk maps onto the unit square's inscribed circle. `quad.c` writes this pair out
    /// at each of its vertices.
    fn point(&self, sink: &mut impl QuadricSink, i: i32, r: f32) {
        let (s, c) = (self.sin[i as usize], self.cos[i as usize]);
        if self.q.texture {
            let t = (f64::from(r) / self.outer / 2.0) as f32;
            sink.tex_coord([(f64::from(t * s) + 0.5) as f32, (f64::from(t * c) + 0.5) as f32]);
        }
        sink.vertex([r * s, r * c, 0.0]);
    }

    /// The vertices of spoke `i`, one a loop boundary, outside in: what `GLU_POINT` and
    /// `GLU_LINE`'s radial lines in `quad.c` both walk.
    fn along_spoke(&self, sink: &mut impl QuadricSink, i: i32) {
        for j in 0..=self.loops {
            self.point(sink, i, self.radius(j));
        }
    }

    /// `GLU_FILL`: a fan at the centre when the inner radius is 0, and a quad strip per loop.
    fn fill(&self, sink: &mut impl QuadricSink) {
        let mut finish = self.loops;
        if self.inner == 0.0 {
            finish = self.loops - 1;
            sink.begin(GL_TRIANGLE_FAN);
            if self.q.texture {
                sink.tex_coord([0.5, 0.5]);
            }
            sink.vertex([0.0, 0.0, 0.0]);
            let r = self.radius(self.loops - 1);
            let around: Vec<i32> =
                if self.q.outside() { (0..=self.slices).rev().collect() } else { (0..=self.slices).collect() };
            for i in around {
                self.point(sink, i, r);
            }
            sink.end();
        }
        for j in 0..finish {
            let (low, high) = (self.radius(j), self.radius(j + 1));
            let order = if self.q.outside() { [low, high] } else { [high, low] };
            sink.begin(GL_QUAD_STRIP);
            for i in 0..=self.slices {
                for r in order {
                    self.point(sink, i, r);
                }
            }
            sink.end();
        }
    }

    /// `GLU_POINT`: every vertex, spoke by spoke.
    fn points(&self, sink: &mut impl QuadricSink) {
        sink.begin(GL_POINTS);
        for i in 0..self.spokes {
            self.along_spoke(sink, i);
        }
        sink.end();
    }

    /// `GLU_LINE` of a disk of no width: the one circle, at the inner radius (a double).
    fn circle(&self, sink: &mut impl QuadricSink) {
        sink.begin(GL_LINE_STRIP);
        for i in 0..=self.slices {
            let (s, c) = (self.sin[i as usize], self.cos[i as usize]);
            if self.q.texture {
                sink.tex_coord([(f64::from(s / 2.0) + 0.5) as f32, (f64::from(c / 2.0) + 0.5) as f32]);
            }
            sink.vertex([(self.inner * f64::from(s)) as f32, (self.inner * f64::from(c)) as f32, 0.0]);
        }
        sink.end();
    }

    /// The circles at loop boundaries `rows`, as line strips.
    fn rings(&self, sink: &mut impl QuadricSink, rows: impl Iterator<Item = i32>) {
        for j in rows {
            let r = self.radius(j);
            sink.begin(GL_LINE_STRIP);
            for i in 0..=self.slices {
                self.point(sink, i, r);
            }
            sink.end();
            if self.q.draw_style == GLU_SILHOUETTE && self.inner == self.outer {
                break;
            }
        }
    }

    /// The radial lines of spokes `around`, outside in.
    fn spokes(&self, sink: &mut impl QuadricSink, around: impl Iterator<Item = i32>) {
        for i in around {
            sink.begin(GL_LINE_STRIP);
            self.along_spoke(sink, i);
            sink.end();
        }
    }

    /// `GLU_SILHOUETTE`: the two straight edges of a partial disk, then the outer and inner
    /// circles (one when they coincide).
    fn silhouette(&self, sink: &mut impl QuadricSink) {
        if self.partial {
            self.spokes(sink, [0, self.slices].into_iter());
        }
        self.rings(sink, [0, self.loops].into_iter());
    }
}
