//! Trimmed surfaces as GLU tessellates them, where [`super::subdivider`] can: the trim loops
//! cut along the knot lines and sampled as GLU samples them, the regions left sliced, drawn
//! patch by patch as untrimmed ones are ([`super::sliced`]).

use super::sliced::{rect_steps, sampling_matrix, SlicedPatch};
use super::subdivider::arctess::{BezierArc, MAX_ORDER};
use super::subdivider::{subdivide, Failure, Setup, TrimArc};
use crate::glu::consts::*;
use crate::glu::evaluation::patch_steps::DirectionSteps;
use crate::glu::evaluation::pieces::CurvePieces;
use crate::glu::evaluation::surface::{PatchGrid, Surface};
use crate::glu::model::maps::CurveMap;
use crate::glu::model::maps::TrimPiece;
use crate::glu::model::object::NurbsObject;

/// GLU's pieces for the surface trimmed by `loops` (none: the whole domain, GLU's border
/// trim), sliced, or outlined under `GLU_OUTLINE_PATCH`; or why not: `Failure::Unsupported`
/// for regions this port does not slice as GLU yet.
pub(crate) fn slice_trimmed(
    obj: &NurbsObject,
    surface: &Surface,
    loops: &[Vec<TrimPiece>],
) -> Result<Vec<SlicedPatch>, Failure> {
    let arcs = trim_arcs(loops).ok_or(Failure::Unsupported)?;
    let matrix = sampling_matrix(obj);
    let steps = |su: (f32, f32), sv: (f32, f32)| rect_steps(obj, &matrix, surface, su, sv);
    let p = &surface.pos.patches;
    let (ubreaks, vbreaks) = (breaks(&p.uintervals), breaks(&p.vintervals));
    let geo_step = find_rate(&ubreaks, &vbreaks, &steps);
    let outline = obj.props.display_mode == GLU_OUTLINE_PATCH;
    let setup = Setup { geo_step, ubreaks, vbreaks, steps: &steps, linear: (p.uorder == 2, p.vorder == 2), outline };
    let patches = subdivide(&arcs, &setup)?;
    let wide = |r: (f32, f32)| (f64::from(r.0), f64::from(r.1));
    Ok(patches
        .into_iter()
        .map(|pp| SlicedPatch { grid: PatchGrid { u: wide(pp.u), v: wide(pp.v), nu: 0, nv: 0 }, pieces: pp.pieces })
        .collect())
}

/// The knots bounding the intervals, in `f32` as GLU keeps them.
fn breaks(intervals: &[(f64, f64)]) -> Vec<f32> {
    let mut out: Vec<f32> = intervals.iter().map(|i| i.0 as f32).collect();
    out.extend(intervals.last().map(|i| i.1 as f32));
    out
}

/// GLU `Quilt::findRates` (with `findSampleRates`): in each direction the smallest of 0.4 ×
/// the domain's length and every patch's interior step over its length (at most 1); the
/// smaller of the two is the rate NURBS trim curves are sampled at.
fn find_rate(ub: &[f32], vb: &[f32], steps: &dyn Fn((f32, f32), (f32, f32)) -> [DirectionSteps; 2]) -> f32 {
    let whole = |b: &[f32]| 0.4 * (b[b.len() - 1] - b[0]);
    let (mut r0, mut r1) = (whole(ub), whole(vb));
    for u in ub.windows(2) {
        for v in vb.windows(2) {
            let [s, t] = steps((u[0], u[1]), (v[0], v[1]));
            let edge = |a: f32, b: f32| f64::from(b - a).abs().min(1.0) as f32;
            let (es, et) = (edge(u[0], u[1]), edge(v[0], v[1]));
            if s.step / es < r0 {
                r0 = s.step / es;
            }
            if t.step / et < r1 {
                r1 = t.step / et;
            }
        }
    }
    if r0 < r1 {
        r0
    } else {
        r1
    }
}

/// The loops' curves in `f32`: pwl curves with GLU's `ELIMINATE_REDUNDANT_POINTS`
/// (`reader.cc`: a point within 1e-5 in u and v of the one kept before it is dropped), NURBS
/// trim curves as their Bezier arcs. `None` for an arc of more than GLU's 8 points.
fn trim_arcs(loops: &[Vec<TrimPiece>]) -> Option<Vec<Vec<TrimArc>>> {
    let mut out = Vec::with_capacity(loops.len());
    for lp in loops {
        let mut arcs = Vec::new();
        for piece in lp {
            match piece {
                TrimPiece::Pwl(points) => arcs.push(TrimArc::Pwl(without_repeats(points))),
                TrimPiece::Curve(map) => arcs.extend(bezier_arcs(map)?),
            }
        }
        out.push(arcs);
    }
    Some(out)
}

/// A NURBS trim curve's Bezier arcs (GLU `Quilt::toBezier`, in `f32` as GLU: [`CurvePieces::new`]).
fn bezier_arcs(map: &CurveMap) -> Option<Vec<TrimArc>> {
    let c = CurvePieces::new(map)?;
    let (dim, order) = (c.pieces.dim, c.pieces.order);
    if order > MAX_ORDER || !(2..=3).contains(&dim) {
        return None;
    }
    (0..c.pieces.intervals.len())
        .map(|i| {
            let cpts = c.pieces.piece(i)?.iter().map(|&x| x as f32).collect();
            Some(TrimArc::Bezier(BezierArc { cpts, dim, order }))
        })
        .collect()
}

fn without_repeats(points: &[[f64; 2]]) -> Vec<[f32; 2]> {
    let mut out: Vec<[f32; 2]> = Vec::with_capacity(points.len());
    for p in points {
        let p = [p[0] as f32, p[1] as f32];
        let near = |q: &[f32; 2]| (0..2).all(|c| f64::from((q[c] - p[c]).abs()) <= 0.00001);
        if !out.last().is_some_and(near) {
            out.push(p);
        }
    }
    out
}
