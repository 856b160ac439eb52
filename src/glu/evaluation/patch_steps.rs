//! GLU's step sizes for one Bezier patch, in `f32` as GLU computes them (`REAL` is `float`):
//! the interior step in each direction and the four "sidesteps" its border is sampled with.
//!
//! Follows `Patch::getstepsize` (`internals/patch.cc`) with the velocity bounds of
//! `Mapdesc::calcPartialVelocity` (`internals/mapdescv.cc`): the control net is transformed by
//! the sampling matrix and divided by w, finite differences of the net bound the partial
//! derivatives (over the whole net for the interior step, over the first and last row or
//! column for the border), and the sampling method turns bound and tolerance into a step.
//! With path-length sampling the interior step is half the border's (t/(2m) against t/m):
//! the border is sampled coarser and joined to the interior grid by fans.

use crate::glu::consts::*;
use crate::glu::model::props::NurbsProperties;
use glam::Mat4;

/// The steps of one patch direction (GLU `Pspec`): `step` inside, `side[0]` along the border
/// where the other parameter is at its minimum, `side[1]` where it is at its maximum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DirectionSteps {
    pub step: f32,
    pub side: [f32; 2],
    /// The step is below range / rate: GLU would bisect the patch (`samplingSplit`).
    pub needs_split: bool,
}

impl DirectionSteps {
    /// One step over the whole range (GLU `Patchspec::singleStep`).
    fn single(range: f32) -> Self {
        Self { step: range.abs(), side: [range.abs(); 2], needs_split: false }
    }

    /// A fixed number of samples over the range (GLU `Patchspec::getstepsize(max)`).
    fn fixed(range: f32, samples: f32) -> Self {
        let step = if samples >= 1.0 { range / samples } else { range }.abs();
        Self { step, side: [step; 2], needs_split: false }
    }
}

/// A control net: `k` floats a point, `orders.1` points a row, `orders.0` rows.
pub(crate) struct Net<'a> {
    pub points: &'a [f64],
    pub k: usize,
    pub orders: (usize, usize),
}

/// The steps of a patch of parameter lengths `ranges` in (u, v).
pub(crate) fn patch_steps(
    props: &NurbsProperties,
    matrix: &Mat4,
    net: &Net,
    ranges: (f32, f32),
) -> [DirectionSteps; 2] {
    let (rs, rt) = ranges;
    match props.sampling_method {
        GLU_DOMAIN_DISTANCE => {
            return [DirectionSteps::fixed(rs, props.u_step * rs), DirectionSteps::fixed(rt, props.v_step * rt)]
        }
        GLU_PATH_LENGTH | GLU_OBJECT_PATH_LENGTH | GLU_PARAMETRIC_ERROR | GLU_OBJECT_PARAMETRIC_ERROR => {}
        _ => return [DirectionSteps::single(rs), DirectionSteps::single(rt)],
    }
    let Some(q) = project(matrix, net) else {
        // The net crosses infinity: partials are undefined, a fixed rate (GLU's fallback).
        return [DirectionSteps::fixed(rs, props.u_step), DirectionSteps::fixed(rt, props.v_step)];
    };
    let grid = Projected { q, orders: net.orders, ranges };
    let mut steps = if matches!(props.sampling_method, GLU_PATH_LENGTH | GLU_OBJECT_PATH_LENGTH) {
        path_length(&grid, props.sampling_tolerance)
    } else {
        parametric_error(&grid, props.parametric_tolerance)
    };
    let minimum = [min_step(rs, props.u_step), min_step(rt, props.v_step)];
    for (d, m) in steps.iter_mut().zip(minimum) {
        d.needs_split = d.step < m;
    }
    steps
}

fn min_step(range: f32, rate: f32) -> f32 {
    if rate > 0.0 {
        range / rate
    } else {
        0.0
    }
}

/// The projected net (x/w, y/w, z/w), row-major as [`Net`].
struct Projected {
    q: Vec<[f32; 3]>,
    orders: (usize, usize),
    ranges: (f32, f32),
}

/// The net in sampling space, or `None` when w changes sign (GLU `Mapdesc::project`).
/// Points are row vectors times the matrix as GLU's `xformNonrational`/`xformRational`.
fn project(matrix: &Mat4, net: &Net) -> Option<Vec<[f32; 3]>> {
    let m = matrix.to_cols_array_2d();
    let mut out = Vec::with_capacity(net.points.len() / net.k.max(1));
    let mut sign = 0.0f32;
    for p in net.points.chunks_exact(net.k) {
        let s = [p[0] as f32, p.get(1).map_or(0.0, |&c| c as f32), p.get(2).map_or(0.0, |&c| c as f32)];
        let w_in = if net.k == 4 { p[3] as f32 } else { 1.0 };
        let d: [f32; 4] = std::array::from_fn(|i| s[0] * m[0][i] + s[1] * m[1][i] + s[2] * m[2][i] + w_in * m[3][i]);
        let sg = if d[3] > 0.0 {
            1.0
        } else if d[3] < 0.0 {
            -1.0
        } else {
            0.0
        };
        if sign != 0.0 && sg != sign || sg == 0.0 || !d.iter().all(|c| c.is_finite()) {
            return None;
        }
        sign = sg;
        out.push([d[0] / d[3], d[1] / d[3], d[2] / d[3]]);
    }
    Some(out)
}

/// GLU `calcPartialVelocity` for a surface: the largest magnitude of the (sp, tp) partial's
/// control points over the whole net, and over the two border lines (`side` 0: the first and
/// last column, i.e. v at its minimum and maximum; 1: the first and last row).
fn velocity(g: &Projected, sp: usize, tp: usize, side: usize) -> (f32, [f32; 2]) {
    let (rows, cols) = g.orders;
    if sp >= rows || tp >= cols {
        return (0.0, [0.0; 2]);
    }
    let mut t: Vec<[f32; 3]> = g.q.clone();
    let at = |i: usize, j: usize| i * cols + j;
    for level in 0..sp {
        for i in 0..rows - 1 - level {
            for j in 0..cols {
                let (a, b) = (t[at(i + 1, j)], t[at(i, j)]);
                t[at(i, j)] = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
            }
        }
    }
    for level in 0..tp {
        for j in 0..cols - 1 - level {
            for i in 0..rows - sp {
                let (a, b) = (t[at(i, j + 1)], t[at(i, j)]);
                t[at(i, j)] = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
            }
        }
    }
    let mag = |i: usize, j: usize| {
        let c = t[at(i, j)];
        c[0] * c[0] + c[1] * c[1] + c[2] * c[2]
    };
    let (ni, nj) = (rows - sp, cols - tp);
    let mut max = 0.0f32;
    for i in 0..ni {
        for j in 0..nj {
            max = max.max(mag(i, j));
        }
    }
    let mut fac = 1.0f32;
    let (invs, invt) = (1.0 / g.ranges.0, 1.0 / g.ranges.1);
    for s in (rows - sp..rows).rev() {
        fac *= s as f32 * invs;
    }
    for s in (cols - tp..cols).rev() {
        fac *= s as f32 * invt;
    }
    let mut dist = [0.0f32; 2];
    if side == 0 {
        for i in 0..ni {
            dist[0] = dist[0].max(mag(i, 0));
            dist[1] = dist[1].max(mag(i, nj - 1));
        }
    } else {
        for j in 0..nj {
            dist[0] = dist[0].max(mag(0, j));
            dist[1] = dist[1].max(mag(ni - 1, j));
        }
    }
    (fac * max.sqrt(), [fac * dist[0].sqrt(), fac * dist[1].sqrt()])
}

/// Path-length sampling (`N_PIXEL_TOLERANCE` t): the interior step t/(2m), each border t/m_side.
fn path_length(g: &Projected, t: f32) -> [DirectionSteps; 2] {
    let (rs, rt) = g.ranges;
    let (ms, msv) = velocity(g, 1, 0, 0);
    let (mt, mtv) = velocity(g, 0, 1, 1);
    let side = |v: f32, r: f32| if v * r > t { t / v } else { r };
    let both = |m: f32, mv: [f32; 2], r: f32| {
        let d = t / (2.0 * m);
        DirectionSteps { step: if d < r { d } else { r }, side: [side(mv[0], r), side(mv[1], r)], needs_split: false }
    };
    let alone = |m: f32, mv: [f32; 2], r: f32| DirectionSteps {
        step: if t < m * r { t / m } else { r },
        side: [side(mv[0], r), side(mv[1], r)],
        needs_split: false,
    };
    match (ms != 0.0, mt != 0.0) {
        (true, true) => [both(ms, msv, rs), both(mt, mtv, rt)],
        (true, false) => [alone(ms, msv, rs), DirectionSteps::single(rt)],
        (false, true) => [DirectionSteps::single(rs), alone(mt, mtv, rt)],
        (false, false) => [DirectionSteps::single(rs), DirectionSteps::single(rt)],
    }
}

/// Parametric-error sampling (`N_ERROR_TOLERANCE` t2): steps from the second-derivative bounds.
fn parametric_error(g: &Projected, t2: f32) -> [DirectionSteps; 2] {
    let (rs, rt) = g.ranges;
    let (ss, ssv) = velocity(g, 2, 0, 0);
    let (st, _) = velocity(g, 1, 1, 2);
    let (tt, ttv) = velocity(g, 0, 2, 1);
    let (ss, st, tt) = (ss.abs(), st.abs(), tt.abs());
    let clamp = |d: f32, r: f32| if d < r { d } else { r };
    let sides = |v: [f32; 2], r: f32| {
        let cutoff = 2.0 * t2 / (r * r);
        let one = |x: f32| if x > cutoff { (2.0 * t2 / x).sqrt() } else { r };
        [one(v[0]), one(v[1])]
    };
    let dir = |d: f32, v: [f32; 2], r: f32| DirectionSteps { step: clamp(d, r), side: sides(v, r), needs_split: false };
    if ss != 0.0 && tt != 0.0 {
        let (ttq, ssq) = (ss.sqrt(), tt.sqrt());
        let ds = (4.0 * t2 * ttq / (ss * ttq + st * ssq)).sqrt();
        let dt = (4.0 * t2 * ssq / (tt * ssq + st * ttq)).sqrt();
        [dir(ds, ssv, rs), dir(dt, ttv, rt)]
    } else if ss != 0.0 {
        let x = rt * st;
        let ds = ((x * x + 8.0 * t2 * ss).sqrt() - x) / ss;
        [dir(ds, ssv, rs), DirectionSteps::single(rt)]
    } else if tt != 0.0 {
        let x = rs * st;
        let dt = ((x * x + 8.0 * t2 * tt).sqrt() - x) / tt;
        [DirectionSteps::single(rs), dir(dt, ttv, rt)]
    } else if 4.0 * t2 > st * rs * rt {
        [DirectionSteps::single(rs), DirectionSteps::single(rt)]
    } else {
        let area = 4.0 * t2 / st;
        let ds = (area * rs / rt).sqrt();
        let dt = (area * rt / rs).sqrt();
        let flat = |d: f32, r: f32| DirectionSteps { step: clamp(d, r), side: [r; 2], needs_split: false };
        [flat(ds, rs), flat(dt, rt)]
    }
}
