//! Trim curves as (u, v) polylines: `gluPwlCurve` pieces as given, NURBS trim curves sampled on
//! their Bezier pieces (spec 2.7).

use super::pieces::CurvePieces;
use crate::glu::model::maps::TrimPiece;

/// A trim loop's pieces as (u, v) polylines; a NURBS trim curve is sampled on each of its
/// Bezier pieces with `segments(points, dim, order)` segments (at least one; TRIM_3 divided
/// by w), the pieces' shared ends once.
pub(crate) fn trim_polylines(
    pieces: &[TrimPiece],
    segments: impl Fn(&[f64], usize, usize) -> usize,
) -> Vec<Vec<[f64; 2]>> {
    pieces
        .iter()
        .map(|piece| match piece {
            TrimPiece::Pwl(points) => points.clone(),
            TrimPiece::Curve(map) => {
                let Some(c) = CurvePieces::new(map) else { return Vec::new() };
                let mut out: Vec<[f64; 2]> = Vec::new();
                for (index, &(a, b)) in c.pieces.intervals.iter().enumerate() {
                    let Some(points) = c.pieces.piece(index) else { continue };
                    let n = segments(points, c.pieces.dim, c.pieces.order).max(1);
                    let start = usize::from(!out.is_empty());
                    for i in start..=n {
                        let u = if i == n { b } else { a + (b - a) * i as f64 / n as f64 };
                        if let Some(p) = c.eval(u) {
                            out.push(if map.k == 3 { [p[0] / p[2], p[1] / p[2]] } else { [p[0], p[1]] });
                        }
                    }
                }
                out
            }
        })
        .collect()
}
