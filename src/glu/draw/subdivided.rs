//! Trimmed surfaces as GLU tessellates them, where [`super::subdivider`] can: the trim loops
//! cut along the knot lines and sampled as GLU samples them, the regions left sliced, drawn
//! patch by patch as untrimmed ones are ([`super::sliced`]).

use super::sliced::{rect_steps, sampling_matrix, SlicedPatch};
use super::subdivider::{subdivide, Failure, Setup};
use crate::glu::consts::*;
use crate::glu::evaluation::surface::{PatchGrid, Surface};
use crate::glu::model::maps::TrimPiece;
use crate::glu::model::object::NurbsObject;

/// GLU's pieces for the surface trimmed by `loops`, or why not: `Failure::Unsupported` for
/// NURBS trim curves, `GLU_OUTLINE_PATCH` and regions this port does not slice as GLU yet.
pub(crate) fn slice_trimmed(
    obj: &NurbsObject,
    surface: &Surface,
    loops: &[Vec<TrimPiece>],
) -> Result<Vec<SlicedPatch>, Failure> {
    if obj.props.display_mode == GLU_OUTLINE_PATCH {
        return Err(Failure::Unsupported);
    }
    let pwl = pwl_loops(loops).ok_or(Failure::Unsupported)?;
    let matrix = sampling_matrix(obj);
    let steps = |su: (f32, f32), sv: (f32, f32)| rect_steps(obj, &matrix, surface, su, sv);
    let p = &surface.pos.patches;
    let setup = Setup {
        ubreaks: breaks(&p.uintervals),
        vbreaks: breaks(&p.vintervals),
        steps: &steps,
        linear: (p.uorder == 2, p.vorder == 2),
    };
    let patches = subdivide(&pwl, &setup)?;
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

/// The loops' pwl curves in `f32`, with GLU's `ELIMINATE_REDUNDANT_POINTS` (`reader.cc`): a
/// point within 1e-5 in u and v of the one kept before it is dropped. `None` if a loop has a
/// NURBS trim curve.
fn pwl_loops(loops: &[Vec<TrimPiece>]) -> Option<Vec<Vec<Vec<[f32; 2]>>>> {
    loops
        .iter()
        .map(|lp| {
            lp.iter()
                .map(|piece| match piece {
                    TrimPiece::Pwl(points) => Some(without_repeats(points)),
                    TrimPiece::Curve(_) => None,
                })
                .collect()
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
