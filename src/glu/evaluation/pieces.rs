//! The Bezier pieces of every map of a NURBS curve or surface, and the sub-pieces GLU hands to
//! `glMap1`/`glMap2` when a map's breakpoints differ from the position map's.

use super::to_bezier::{curve_to_bezier, surface_to_bezier};
use crate::gl::types::GLenum;
use crate::glu::model::maps::{CurveMap, SurfaceMap};
use crate::math::bezier::{de_casteljau, split, Vec4};
use crate::math::insertion::{decompose_curve, decompose_surface, BezierPatches, BezierPieces};
use crate::math::patch::{patch_with_partials, PatchSample};
use crate::math::{BSplineSurface, KnotVector};

/// A curve map decomposed into Bezier pieces.
pub(crate) struct CurvePieces {
    pub target: GLenum,
    pub pieces: BezierPieces<f64>,
}

impl CurvePieces {
    /// The map's pieces as GLU's `Quilt::toBezier` computes them, in `f32` (see
    /// [`curve_to_bezier`]); the exact decomposition only where GLU's indices would not fit.
    pub fn new(map: &CurveMap) -> Option<Self> {
        let pieces = glu_pieces(map).or_else(|| decompose_curve(&map.knots, &map.points, map.k, map.order).ok())?;
        (!pieces.is_empty()).then_some(Self { target: map.target, pieces })
    }

    /// The piece GLU downloads for the span [r0, r1] (`Quilt::select`: the last piece whose
    /// breakpoints enclose it), its points and its interval.
    pub fn containing(&self, r0: f64, r1: f64) -> Option<(&[f64], (f64, f64))> {
        let p = &self.pieces;
        let k = p.intervals.iter().rposition(|&(a, b)| a <= r0 && r1 <= b)?;
        Some((p.piece(k)?, p.intervals[k]))
    }

    /// The Bezier control points of this map restricted to [r0, r1] (inside one piece).
    pub fn on(&self, r0: f64, r1: f64) -> Option<Vec<f64>> {
        let p = &self.pieces;
        let k = locate(&p.intervals, 0.5 * (r0 + r1))?;
        let (c, d) = p.intervals[k];
        let (s0, s1) = ((r0 - c) / (d - c), (r1 - c) / (d - c));
        Some(sub_range(p.piece(k)?, p.dim, p.order, s0, s1))
    }

    /// The value at `u` through the piece holding it.
    pub fn eval(&self, u: f64) -> Option<Vec4<f64>> {
        let p = &self.pieces;
        let k = locate(&p.intervals, u)?;
        let (c, d) = p.intervals[k];
        Some(de_casteljau(p.piece(k)?, p.dim, p.order, (u - c) / (d - c)))
    }
}

/// A curve map's pieces from GLU's `f32` decomposition, widened exactly to `f64`.
fn glu_pieces(map: &CurveMap) -> Option<BezierPieces<f64>> {
    let knots: Vec<f32> = map.knots.iter().map(|&k| k as f32).collect();
    let points: Vec<f32> = map.points.iter().map(|&c| c as f32).collect();
    let glu = curve_to_bezier(&knots, &points, map.k, map.order)?;
    Some(BezierPieces {
        dim: map.k,
        order: map.order,
        intervals: glu.breakpoints.windows(2).map(|w| (f64::from(w[0]), f64::from(w[1]))).collect(),
        points: glu.points.iter().map(|&c| f64::from(c)).collect(),
    })
}

/// A surface map decomposed into Bezier patches.
pub(crate) struct SurfacePatches {
    pub target: GLenum,
    pub patches: BezierPatches<f64>,
}

impl SurfacePatches {
    /// The map's patches as GLU's `Quilt::toBezier` computes them, in `f32` (see
    /// [`surface_to_bezier`]); the exact decomposition only where GLU's indices would not fit.
    pub fn new(map: &SurfaceMap) -> Option<Self> {
        let patches = glu_patches(map).or_else(|| exact_patches(map))?;
        (!patches.is_empty()).then_some(Self { target: map.target, patches })
    }
}

/// A surface map's patches from the exact (`f64`) decomposition.
fn exact_patches(map: &SurfaceMap) -> Option<BezierPatches<f64>> {
    let (uk, vk) = (KnotVector::new(map.uknots.clone()), KnotVector::new(map.vknots.clone()));
    let s = BSplineSurface::try_new(map.k, map.orders.0, map.orders.1, uk, vk, map.points.clone()).ok()?;
    decompose_surface(&s).ok()
}

/// A surface map's patches from GLU's `f32` decomposition, widened exactly to `f64`.
fn glu_patches(map: &SurfaceMap) -> Option<BezierPatches<f64>> {
    let narrow = |v: &[f64]| -> Vec<f32> { v.iter().map(|&x| x as f32).collect() };
    let (uk, vk, points) = (narrow(&map.uknots), narrow(&map.vknots), narrow(&map.points));
    let glu = surface_to_bezier((&uk, &vk), &points, map.k, map.orders)?;
    let intervals = |b: &[f32]| b.windows(2).map(|w| (f64::from(w[0]), f64::from(w[1]))).collect();
    Some(BezierPatches {
        dim: map.k,
        uorder: map.orders.0,
        vorder: map.orders.1,
        uintervals: intervals(&glu.breakpoints.0),
        vintervals: intervals(&glu.breakpoints.1),
        points: glu.points.iter().map(|&c| f64::from(c)).collect(),
    })
}

impl SurfacePatches {
    /// The patch's control points restricted to [u0, u1] × [v0, v1] (inside one patch).
    pub fn on(&self, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> Option<Vec<f64>> {
        let p = &self.patches;
        let a = locate(&p.uintervals, 0.5 * (u0 + u1))?;
        let b = locate(&p.vintervals, 0.5 * (v0 + v1))?;
        let ((ua, ub), (va, vb)) = (p.uintervals[a], p.vintervals[b]);
        let (uo, vo, k) = (p.uorder, p.vorder, p.dim);
        // Along u the "points" are whole rows of vo·k values; along v, each row separately.
        let by_u = sub_range(p.patch(a, b)?, vo * k, uo, (u0 - ua) / (ub - ua), (u1 - ua) / (ub - ua));
        let (t0, t1) = ((v0 - va) / (vb - va), (v1 - va) / (vb - va));
        Some(by_u.chunks_exact(vo * k).flat_map(|row| sub_range(row, k, vo, t0, t1)).collect())
    }

    /// Point and partials with respect to the true u and v at (u, v).
    pub fn eval(&self, u: f64, v: f64) -> Option<PatchSample<f64>> {
        let p = &self.patches;
        let a = locate(&p.uintervals, u)?;
        let b = locate(&p.vintervals, v)?;
        let ((ua, ub), (va, vb)) = (p.uintervals[a], p.vintervals[b]);
        let mut s =
            patch_with_partials(p.patch(a, b)?, p.dim, p.uorder, p.vorder, (u - ua) / (ub - ua), (v - va) / (vb - va));
        s.du = s.du.map(|c| c / (ub - ua));
        s.dv = s.dv.map(|c| c / (vb - va));
        Some(s)
    }
}

/// The interval holding `u` (clamped to the ends, with a little tolerance).
pub(crate) fn locate(intervals: &[(f64, f64)], u: f64) -> Option<usize> {
    if !u.is_finite() || intervals.is_empty() {
        return None;
    }
    let k = intervals.iter().position(|&(_, b)| u <= b).unwrap_or(intervals.len() - 1);
    Some(k)
}

/// The Bezier points of the sub-range [s0, s1] of a piece given on [0, 1].
fn sub_range(points: &[f64], dim: usize, order: usize, s0: f64, s1: f64) -> Vec<f64> {
    if s0 <= 0.0 && s1 >= 1.0 {
        return points.to_vec();
    }
    let (left, _) = split(points, dim, order, s1);
    if s0 <= 0.0 || s1 == 0.0 {
        return left;
    }
    split(&left, dim, order, s0 / s1).1
}
