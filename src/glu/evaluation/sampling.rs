//! From GLU's sampling tolerance to a number of segments per Bezier piece (spec 2.4; GLU
//! `curve.cc`, `patch.cc`, `mapdescv.cc`): control points are projected with the sampling
//! matrix, velocity bounds taken on the projected control polygon, and a step size chosen for
//! the sampling method.

use crate::glu::consts::*;
use crate::glu::model::props::{NurbsProperties, SamplingMatrices};
use glam::{Mat4, Vec4};

/// GLU bisects a span at most this many times (`renderhints.cc` subdivisions = 6).
const MAX_SUBDIVISIONS: u32 = 6;
/// Upper bound on segments per piece and direction, so absurd tolerances cannot exhaust memory.
pub const MAX_SEGMENTS: usize = 1 << 14;

/// How a NURBS object samples: the properties and the matrix points are projected with.
pub(crate) struct Sampler {
    props: NurbsProperties,
    matrix: Mat4,
}

impl Sampler {
    pub fn new(props: NurbsProperties, matrices: &SamplingMatrices) -> Self {
        // The OBJECT_ methods measure in object space: GLU loads an identity sampling matrix.
        let matrix = if props.object_space() { Mat4::IDENTITY } else { matrices.sampling() };
        Self { props, matrix }
    }

    /// Projects homogeneous (k = 4) or plain (k = 3, 2) control points; `None` when the points
    /// "cross infinity" (projected w not all of one sign), where derivatives are undefined.
    fn project(&self, points: &[f64], k: usize) -> Option<Vec<[f64; 3]>> {
        let mut out = Vec::with_capacity(points.len() / k);
        let mut sign = 0.0;
        for p in points.chunks_exact(k) {
            let v = match k {
                4 => Vec4::new(p[0] as f32, p[1] as f32, p[2] as f32, p[3] as f32),
                3 => Vec4::new(p[0] as f32, p[1] as f32, p[2] as f32, 1.0),
                2 => Vec4::new(p[0] as f32, p[1] as f32, 0.0, 1.0),
                _ => Vec4::new(p[0] as f32, 0.0, 0.0, 1.0),
            };
            let c = self.matrix * v;
            if c.w == 0.0 || (sign != 0.0 && c.w.signum() != sign) || !c.is_finite() {
                return None;
            }
            sign = c.w.signum();
            out.push([f64::from(c.x / c.w), f64::from(c.y / c.w), f64::from(c.z / c.w)]);
        }
        Some(out)
    }

    fn fixed_step(rate: f32, range: f64) -> f64 {
        if rate >= 1.0 {
            range / f64::from(rate)
        } else {
            range
        }
    }

    /// Segments for each sub-span of a curve piece: GLU's `Curve::getstepsize` and
    /// `Subdivider::samplingSplit`. Returns (t0, t1, segments) in the piece's normalised [0, 1].
    pub fn curve_segments(&self, points: &[f64], k: usize, order: usize, range: f64) -> Vec<(f64, f64, usize)> {
        let mut out = Vec::new();
        self.curve_split(points, k, order, range, (0.0, 1.0), MAX_SUBDIVISIONS, &mut out);
        out
    }

    #[allow(clippy::too_many_arguments)]
    fn curve_split(
        &self,
        points: &[f64],
        k: usize,
        order: usize,
        range: f64,
        span: (f64, f64),
        depth: u32,
        out: &mut Vec<(f64, f64, usize)>,
    ) {
        let (step, min_step) = self.curve_step(points, k, order, range);
        if step < min_step && depth > 0 && order > 1 {
            let (left, right) = crate::math::bezier::split(points, k, order, 0.5);
            let mid = 0.5 * (span.0 + span.1);
            self.curve_split(&left, k, order, range / 2.0, (span.0, mid), depth - 1, out);
            self.curve_split(&right, k, order, range / 2.0, (mid, span.1), depth - 1, out);
            return;
        }
        let segments = if step > 0.0 && step.is_finite() { 1.0 + (range / step).floor() } else { 1.0 };
        out.push((span.0, span.1, (segments as usize).clamp(1, MAX_SEGMENTS)));
    }

    /// (stepsize, minstepsize) for one curve span of parameter length `range`.
    fn curve_step(&self, points: &[f64], k: usize, order: usize, range: f64) -> (f64, f64) {
        let p = &self.props;
        let fixed = |rate: f32| {
            let s = Self::fixed_step(rate, range);
            (s, s)
        };
        let t = f64::from(p.sampling_tolerance);
        let min_step = if p.u_step > 0.0 { range / f64::from(p.u_step) } else { 0.0 };
        match p.sampling_method {
            GLU_DOMAIN_DISTANCE => fixed(p.u_step * range as f32),
            GLU_PATH_LENGTH | GLU_PARAMETRIC_ERROR => {
                let Some(q) = self.project(points, k) else { return fixed(p.u_step) };
                if p.sampling_method == GLU_PATH_LENGTH {
                    let d = velocity1(&q, order, range);
                    (if d > 0.0 { t / d } else { range }, min_step)
                } else {
                    let d = velocity2(&q, order, range);
                    (if d > 0.0 { (8.0 * t / d).sqrt() } else { range }, min_step)
                }
            }
            // GLU's curves have no object-space branch: a fixed rate per span.
            _ => fixed(p.u_step),
        }
    }

    /// Segments (nu, nv) for a Bezier patch: GLU's `Patch::getstepsize`, then the grid GLU
    /// samples with. With `GLU_DOMAIN_DISTANCE` that is the untrimmed fast path,
    /// max(1, ⌊U_STEP·R⌋) (`subdivider.cc`); otherwise the slicer's grid of 3 + ⌊R/step⌋ lines
    /// (`slicer.cc`), and at least 2 segments even when one step covers the patch: real GLU
    /// emits 14 vertices in 4 primitives for such a patch (measured, `tess_counts.c`), which a
    /// 2 × 2 grid (12 vertices) matches far better than a single cell (4). `points` are packed
    /// u-major, `k` per point; `ranges` are the patch's parameter lengths.
    pub fn patch_segments(
        &self,
        points: &[f64],
        k: usize,
        orders: (usize, usize),
        ranges: (f64, f64),
    ) -> (usize, usize) {
        let (rs, rt) = ranges;
        let p = &self.props;
        if p.sampling_method == GLU_DOMAIN_DISTANCE {
            let fast = |rate: f32, r: f64| ((f64::from(rate) * r).floor() as usize).clamp(1, MAX_SEGMENTS);
            return (fast(p.u_step, rs), fast(p.v_step, rt));
        }
        let (step_s, step_t) = match self.project(points, k) {
            None => (Self::fixed_step(p.u_step, rs), Self::fixed_step(p.v_step, rt)),
            Some(q) if p.sampling_method == GLU_PATH_LENGTH || p.sampling_method == GLU_OBJECT_PATH_LENGTH => {
                self.path_length_steps(&q, orders, ranges)
            }
            Some(q) => self.parametric_steps(&q, orders, ranges),
        };
        let count = |r: f64, s: f64| {
            if !(s > 0.0 && s.is_finite()) || s >= r {
                2
            } else {
                (2.0 + (r / s).floor()).min(MAX_SEGMENTS as f64) as usize
            }
        };
        (count(rs, step_s), count(rt, step_t))
    }

    fn path_length_steps(&self, q: &[[f64; 3]], (uo, vo): (usize, usize), (rs, rt): (f64, f64)) -> (f64, f64) {
        let t = f64::from(self.props.sampling_tolerance);
        let ms = (uo as f64 - 1.0) / rs * max_difference(q, uo, vo, true);
        let mt = (vo as f64 - 1.0) / rt * max_difference(q, uo, vo, false);
        match (ms > 0.0, mt > 0.0) {
            (true, true) => ((t / (2.0 * ms)).min(rs), (t / (2.0 * mt)).min(rt)),
            (true, false) => (if t < ms * rs { t / ms } else { rs }, rt),
            (false, true) => (rs, if t < mt * rt { t / mt } else { rt }),
            (false, false) => (rs, rt),
        }
    }

    fn parametric_steps(&self, q: &[[f64; 3]], (uo, vo): (usize, usize), (rs, rt): (f64, f64)) -> (f64, f64) {
        let t2 = f64::from(self.props.parametric_tolerance);
        let ss = (uo as f64 - 1.0) * (uo as f64 - 2.0) / (rs * rs) * max_second_difference(q, uo, vo, true);
        let tt = (vo as f64 - 1.0) * (vo as f64 - 2.0) / (rt * rt) * max_second_difference(q, uo, vo, false);
        let st = (uo as f64 - 1.0) * (vo as f64 - 1.0) / (rs * rt) * max_mixed_difference(q, uo, vo);
        let (ds, dt) = if ss > 0.0 && tt > 0.0 {
            let (sq, tq) = (ss.sqrt(), tt.sqrt());
            ((4.0 * t2 * sq / (ss * sq + st * tq)).sqrt(), (4.0 * t2 * tq / (tt * tq + st * sq)).sqrt())
        } else if ss > 0.0 {
            let x = rt * st;
            (((x * x + 8.0 * t2 * ss).sqrt() - x) / ss, rt)
        } else if tt > 0.0 {
            let x = rs * st;
            (rs, ((x * x + 8.0 * t2 * tt).sqrt() - x) / tt)
        } else if st > 0.0 && 4.0 * t2 <= st * rs * rt {
            let area = 4.0 * t2 / st;
            ((area * rs / rt).sqrt(), (area * rt / rs).sqrt())
        } else {
            (rs, rt)
        };
        (ds.min(rs), dt.min(rt))
    }
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// First-derivative bound of a curve span: (n−1)/R · max |P_{j+1} − P_j|.
fn velocity1(q: &[[f64; 3]], order: usize, range: f64) -> f64 {
    let m = q.windows(2).map(|w| dist(w[0], w[1])).fold(0.0, f64::max);
    (order as f64 - 1.0) / range * m
}

/// Second-derivative bound: (n−1)(n−2)/R² · max |P_{j+2} − 2P_{j+1} + P_j|.
fn velocity2(q: &[[f64; 3]], order: usize, range: f64) -> f64 {
    let m = q
        .windows(3)
        .map(|w| {
            dist(
                [w[0][0] + w[2][0], w[0][1] + w[2][1], w[0][2] + w[2][2]],
                [2.0 * w[1][0], 2.0 * w[1][1], 2.0 * w[1][2]],
            )
        })
        .fold(0.0, f64::max);
    (order as f64 - 1.0) * (order as f64 - 2.0) / (range * range) * m
}

fn at(q: &[[f64; 3]], vo: usize, i: usize, j: usize) -> [f64; 3] {
    q[i * vo + j]
}

/// max |ΔP| along u (`along_u`) or v over the whole net.
fn max_difference(q: &[[f64; 3]], uo: usize, vo: usize, along_u: bool) -> f64 {
    let mut m = 0.0f64;
    for i in 0..uo {
        for j in 0..vo {
            let next = if along_u {
                (i + 1 < uo).then(|| at(q, vo, i + 1, j))
            } else {
                (j + 1 < vo).then(|| at(q, vo, i, j + 1))
            };
            if let Some(n) = next {
                m = m.max(dist(n, at(q, vo, i, j)));
            }
        }
    }
    m
}

fn max_second_difference(q: &[[f64; 3]], uo: usize, vo: usize, along_u: bool) -> f64 {
    let mut m = 0.0f64;
    for i in 0..uo {
        for j in 0..vo {
            let (a, b) = if along_u { (i + 2 < uo, (1, 0)) } else { (j + 2 < vo, (0, 1)) };
            if a {
                let p0 = at(q, vo, i, j);
                let p1 = at(q, vo, i + b.0, j + b.1);
                let p2 = at(q, vo, i + 2 * b.0, j + 2 * b.1);
                m = m.max(dist([p0[0] + p2[0], p0[1] + p2[1], p0[2] + p2[2]], [2.0 * p1[0], 2.0 * p1[1], 2.0 * p1[2]]));
            }
        }
    }
    m
}

fn max_mixed_difference(q: &[[f64; 3]], uo: usize, vo: usize) -> f64 {
    let mut m = 0.0f64;
    for i in 0..uo.saturating_sub(1) {
        for j in 0..vo.saturating_sub(1) {
            let (a, b, c, d) = (at(q, vo, i, j), at(q, vo, i + 1, j), at(q, vo, i, j + 1), at(q, vo, i + 1, j + 1));
            m = m
                .max(dist([d[0] - b[0] - c[0] + a[0], d[1] - b[1] - c[1] + a[1], d[2] - b[2] - c[2] + a[2]], [0.0; 3]));
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pixel_sampler(tolerance: f32) -> Sampler {
        let props = NurbsProperties { sampling_tolerance: tolerance, ..NurbsProperties::DEFAULT };
        // Identity modelview/projection over a 200x200 viewport: 1 unit = 100 px.
        let m = SamplingMatrices { viewport: [0, 0, 200, 200], ..SamplingMatrices::IDENTITY };
        Sampler::new(props, &m)
    }

    #[test]
    fn path_length_curve_segments_follow_glu_formula() {
        // A straight cubic from x = -1 to 1: control edges 2/3 unit = 66.67 px; d1 = 3 * 66.67
        // = 200 px per unit parameter; with t = 50: step = 0.25, nu = 1 + floor(1/0.25) = 5.
        let pts = [-1.0, 0.0, 0.0, -1.0 / 3.0, 0.0, 0.0, 1.0 / 3.0, 0.0, 0.0, 1.0, 0.0, 0.0];
        let segs = pixel_sampler(50.0).curve_segments(&pts, 3, 4, 1.0);
        assert_eq!(segs, vec![(0.0, 1.0, 5)]);
    }

    #[test]
    fn domain_distance_uses_u_step() {
        let props = NurbsProperties { sampling_method: GLU_DOMAIN_DISTANCE, u_step: 10.0, ..NurbsProperties::DEFAULT };
        let s = Sampler::new(props, &SamplingMatrices::IDENTITY);
        let pts = [0.0; 12];
        assert_eq!(s.curve_segments(&pts, 3, 4, 2.0), vec![(0.0, 1.0, 21)]);
    }

    #[test]
    fn points_at_infinity_fall_back_to_fixed_rate() {
        let pts = [0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, -1.0];
        let segs = pixel_sampler(50.0).curve_segments(&pts, 4, 2, 1.0);
        assert_eq!(segs, vec![(0.0, 1.0, 101)]);
    }

    #[test]
    fn patch_covered_by_one_step_still_gets_two_segments() {
        let pts = [0.0; 12];
        assert_eq!(pixel_sampler(50.0).patch_segments(&pts, 3, (2, 2), (1.0, 1.0)), (2, 2));
    }

    #[test]
    fn patch_path_length_halves_the_tolerance() {
        // Bilinear square of 2 units = 200 px each way: ms = 200 px; step = 50 / 400 = 0.125,
        // so the slicer's grid has 3 + 8 lines: 10 segments.
        let pts = [-1.0, -1.0, 0.0, -1.0, 1.0, 0.0, 1.0, -1.0, 0.0, 1.0, 1.0, 0.0];
        assert_eq!(pixel_sampler(50.0).patch_segments(&pts, 3, (2, 2), (1.0, 1.0)), (10, 10));
    }
}
