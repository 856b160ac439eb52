//! The trimmed domain in (u, v): the surface's grid lines merged over its patches, and the trim
//! loops as closed polylines sampled about as finely as that grid (spec 2.7).

use crate::glu::evaluation::surface::PatchGrid;
use crate::glu::evaluation::trim_curves::trim_polylines;
use crate::glu::model::maps::TrimPiece;
use crate::glu::model::object::NurbsObject;
use crate::tess::trim::{join_curves, TrimLoop, TrimOptions};

/// The triangulation of trimmed surfaces in both modes: the band cell by cell, as GLU's slicer
/// cuts its grid.
pub(super) const BY_CELLS: TrimOptions = TrimOptions::DEFAULT.with_clearance(0.0).with_by_cells(true);

/// Grid lines of every patch at its sampling density, merged over the whole domain.
pub(super) fn grid_lines(steps: &[PatchGrid]) -> (Vec<f64>, Vec<f64>) {
    let mut us: Vec<f64> = Vec::new();
    let mut vs: Vec<f64> = Vec::new();
    for &PatchGrid { u: (u0, u1), v: (v0, v1), nu, nv } in steps {
        us.extend((0..=nu).map(|i| u0 + (u1 - u0) * i as f64 / nu as f64));
        vs.extend((0..=nv).map(|j| v0 + (v1 - v0) * j as f64 / nv as f64));
    }
    for lines in [&mut us, &mut vs] {
        lines.sort_by(f64::total_cmp);
        lines.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    }
    (us, vs)
}

/// The trim loops as closed polylines; `None` after reporting GLU's error for a loop that does
/// not close (or is otherwise malformed).
pub(super) fn trim_loops(
    obj: &mut NurbsObject,
    loops: &[Vec<TrimPiece>],
    steps: &[PatchGrid],
) -> Option<Vec<TrimLoop>> {
    let spacing = grid_spacing(steps);
    let segments = |points: &[f64], dim: usize, _order: usize| trim_segments(points, dim, spacing);
    let mut trim_loops = Vec::with_capacity(loops.len());
    for pieces in loops {
        match join_curves(&trim_polylines(pieces, segments)) {
            Ok(l) => trim_loops.push(l),
            Err(e) => {
                obj.nurbs_error(e.glu_number());
                return None;
            }
        }
    }
    Some(trim_loops)
}

/// The finest grid step of any patch, in either direction.
fn grid_spacing(steps: &[PatchGrid]) -> f64 {
    steps
        .iter()
        .map(|&PatchGrid { u: (u0, u1), v: (v0, v1), nu, nv }| ((u1 - u0) / nu as f64).min((v1 - v0) / nv as f64))
        .fold(f64::INFINITY, f64::min)
}

/// Segments for one Bezier piece of a trim curve: its control polygon's length in (u, v) over
/// the grid `spacing`, so that trim curves are sampled about as finely as the surface grid.
fn trim_segments(points: &[f64], dim: usize, spacing: f64) -> usize {
    let length: f64 = points
        .chunks_exact(dim)
        .map(|p| if dim == 3 { [p[0] / p[2], p[1] / p[2]] } else { [p[0], p[1]] })
        .collect::<Vec<_>>()
        .windows(2)
        .map(|w| ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt())
        .sum();
    ((length / spacing).ceil() as usize).clamp(4, 4096)
}
