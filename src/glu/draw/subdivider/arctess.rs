//! NURBS trim curves sampled as GLU samples them (`Subdivider::decompose` and `tessellate`
//! in `internals/monotonizer.cc`, `ArcTessellator::tessellateLinear`, `tessellateNonlinear`,
//! `pwl` and `trim_power_coeffs` in `arctess.cc`, `Mapdesc::calcPartialVelocity` in
//! `mapdescv.cc`): each Bezier arc of a trim curve is cut into steps of the surface's finest
//! rate over the arc's speed, evaluated in power form in `f32`; a line arc is cut like a
//! border side.

use super::split::sample_side;
use super::Side;

type Pt = [f32; 2];

/// GLU's `MAXORDER`.
pub(crate) const MAX_ORDER: usize = 8;

/// One Bezier arc of a trim curve: `order` control points of `dim` floats (3: homogeneous).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct BezierArc {
    pub cpts: Vec<f32>,
    pub dim: usize,
    pub order: usize,
}

impl BezierArc {
    fn point(&self, i: usize) -> Pt {
        let p = &self.cpts[i * self.dim..];
        if self.dim == 3 {
            [p[0] / p[2], p[1] / p[2]]
        } else {
            [p[0], p[1]]
        }
    }

    /// GLU `Mapdesc::calcVelocityNonrational` / `calcVelocityRational`: the first
    /// derivative's bound over the control polygon (projected for a rational arc).
    fn velocity(&self) -> f32 {
        let pts: Vec<Pt> = (0..self.order).map(|i| self.point(i)).collect();
        let max = pts
            .windows(2)
            .map(|w| {
                let (du, dv) = (w[1][0] - w[0][0], w[1][1] - w[0][1]);
                du * du + dv * dv
            })
            .fold(0.0f32, |m, x| if x > m { x } else { m });
        (self.order - 1) as f32 * max.sqrt()
    }

    /// GLU `ArcTessellator::trim_power_coeffs`: coordinate `c` in power form, highest power
    /// first.
    fn power(&self, c: usize) -> Vec<f32> {
        let n = self.order - 1;
        (0..self.order)
            .map(|r| {
                let mut s = 0.0f32;
                for k in 0..self.order {
                    s += bernstein(n, r, k) * self.cpts[k * self.dim + c];
                }
                s
            })
            .collect()
    }
}

/// GLU's `gl_Bernstein[n][r][k]`: the coefficient of point k in the term of power n − r.
fn bernstein(n: usize, r: usize, k: usize) -> f32 {
    if k + r > n {
        return 0.0;
    }
    let sign = if (n - r - k) % 2 == 0 { 1.0 } else { -1.0 };
    sign * (choose(n, k) * choose(n - k, n - r - k)) as f32
}

fn choose(n: usize, k: usize) -> u64 {
    (0..k).fold(1u64, |c, i| c * (n - i) as u64 / (i + 1) as u64)
}

/// GLU `Subdivider::tessellate(Arc, geo_stepsize)`: the arc's polyline.
pub(crate) fn tessellate(arc: &BezierArc, geo: f32) -> Vec<Pt> {
    let max = arc.velocity();
    let arc_step = if max > 1.0 { 1.0 / max } else { 1.0 };
    if arc.order == 2 {
        linear(arc, geo)
    } else {
        nonlinear(arc, geo, arc_step)
    }
}

/// GLU `ArcTessellator::tessellateLinear`.
fn linear(arc: &BezierArc, rate: f32) -> Vec<Pt> {
    let ([s1, t1], [s2, t2]) = (arc.point(0), arc.point(1));
    let along = |side: Side, from: Pt, to: Pt, vertical: bool| -> Vec<Pt> {
        let xs = sample_side(side, from, to, rate);
        xs.into_iter().map(|x| if vertical { [s1, x] } else { [x, t1] }).collect()
    };
    if s1 == s2 {
        along(if t1 < t2 { Side::Right } else { Side::Left }, [s1, t1], [s2, t2], true)
    } else if t1 == t2 {
        along(if s1 < s2 { Side::Bottom } else { Side::Top }, [s1, t1], [s2, t2], false)
    } else {
        pwl([s1, t1], [s2, t2], rate)
    }
}

/// GLU `ArcTessellator::pwl`: a slanted line in equal steps, accumulated.
fn pwl([mut s1, mut t1]: Pt, [s2, t2]: Pt, rate: f32) -> Vec<Pt> {
    let count = |d: f32| 1 + crate::glu::draw::slicer::c_int(d.abs() / rate);
    let n = count(s2 - s1).max(count(t2 - t1)).clamp(1, crate::glu::evaluation::sampling::MAX_SEGMENTS as i64);
    let (ds, dt) = ((s2 - s1) / n as f32, (t2 - t1) / n as f32);
    let mut out = Vec::with_capacity(n as usize + 1);
    for _ in 0..n {
        out.push([s1, t1]);
        s1 += ds;
        t1 += dt;
    }
    out.push([s2, t2]);
    out
}

/// GLU `ArcTessellator::tessellateNonlinear`: ⌊size/(geo·arc)⌋ steps over the control box's
/// larger side (GLU's `arctess.cc` defines `NOELIMINATION`: every step is kept).
fn nonlinear(arc: &BezierArc, geo: f32, arc_step: f32) -> Vec<Pt> {
    let step = geo * arc_step;
    let raw = |i: usize, c: usize| arc.cpts[i * arc.dim + c];
    let (mut umin, mut umax, mut vmin, mut vmax) = (raw(0, 0), raw(0, 0), raw(0, 1), raw(0, 1));
    for i in 1..arc.order {
        let (u, v) = (raw(i, 0), raw(i, 1));
        (umin, umax) = (if u < umin { u } else { umin }, if u > umax { u } else { umax });
        (vmin, vmax) = (if v < vmin { v } else { vmin }, if v > vmax { v } else { vmax });
    }
    let size = if umax - umin < vmax - vmin { vmax - vmin } else { umax - umin };
    let limit = crate::glu::evaluation::sampling::MAX_SEGMENTS as i64;
    let n = crate::glu::draw::slicer::c_int(size / step).clamp(1, limit) as usize;
    let dp = 1.0 / n as f32;
    let pows: Vec<Vec<f32>> = (0..arc.dim).map(|c| arc.power(c)).collect();
    let mut out = Vec::with_capacity(n + 1);
    out.push(arc.point(0));
    for k in 1..n {
        let p = dp * k as f32;
        let eval = |c: usize| pows[c][1..].iter().fold(pows[c][0], |x, &a| x * p + a);
        out.push(if arc.dim == 3 { [eval(0) / eval(2), eval(1) / eval(2)] } else { [eval(0), eval(1)] });
    }
    out.push(arc.point(arc.order - 1));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bernstein_rows_are_glus_table() {
        let row = |n: usize, r: usize| (0..=n).map(|k| bernstein(n, r, k)).collect::<Vec<_>>();
        assert_eq!(row(3, 0), vec![-1.0, 3.0, -3.0, 1.0]);
        assert_eq!(row(3, 1), vec![3.0, -6.0, 3.0, 0.0]);
        assert_eq!(row(7, 1), vec![7.0, -42.0, 105.0, -140.0, 105.0, -42.0, 7.0, 0.0]);
    }

    #[test]
    fn a_cubic_arc_runs_from_its_first_point_to_its_last() {
        let arc = BezierArc { cpts: vec![0.25, 0.5, 0.25, 0.75, 0.75, 0.75, 0.75, 0.5], dim: 2, order: 4 };
        let pts = tessellate(&arc, 0.01);
        assert_eq!(pts[0], [0.25, 0.5]);
        assert_eq!(pts[pts.len() - 1], [0.75, 0.5]);
        assert!(pts.len() > 10);
    }
}
