//! Which way two arcs meeting on a cut line turn (`internals/ccw.cc`): GLU's
//! `Subdivider::ccwTurn_sr`, `ccwTurn_sl`, `ccwTurn_tr` and `ccwTurn_tl`, which decide on which
//! side of the line a piece of a loop lies and in which order the pieces along a line are
//! joined. The four are one walk here, along axis `p` (0: a line of constant s, 1: of constant
//! t) away from the line in the increasing (`_sr`, `_tr`) or decreasing (`_sl`, `_tl`) sense.

use super::arcs::{ArcId, Arcs};
use super::Jump;

type Pt = [f32; 2];

/// GLU's `ccwTurn_*(j1, j2)`: whether the end of `j1` followed by the start of `j2` turns
/// counter-clockwise, both leaving the line `p` = const in the `increasing` sense (or GLU's
/// error 28 for arcs leaving it the other way).
pub(crate) fn ccw_turn(arcs: &Arcs, j1: ArcId, j2: ArcId, p: usize, increasing: bool) -> Result<bool, Jump> {
    let (a, b) = (&arcs[j1].pts, &arcs[j2].pts);
    if a.len() < 2 || b.len() < 2 {
        return Ok(false);
    }
    let q = 1 - p;
    let before = |x: f32, y: f32| if increasing { x < y } else { x > y };
    // The answer when the first arc ends below (in q) where the second starts.
    let low = (p == 1) == increasing;
    let (mut i1, mut i2) = (a.len() - 1, 0usize);
    let (mut n1, mut n2) = (i1 - 1, 1usize);
    if a[i1][p] == a[n1][p] && b[i2][p] == b[n2][p] {
        return Ok(false); // both arcs lie on the line
    }
    if before(b[n2][p], b[i2][p]) || before(a[n1][p], a[i1][p]) {
        return Err(Jump(28));
    }
    if a[i1][q] != b[i2][q] {
        return Ok(if a[i1][q] < b[i2][q] { low } else { !low });
    }
    loop {
        let (v1, v1n, v2, v2n) = (a[i1], a[n1], b[i2], b[n2]);
        let step1 = if before(v1n[p], v2n[p]) {
            let bb = if increasing { bbox(v2, v2n, v1n, q) } else { bbox(v2n, v2, v1n, q) };
            match bb {
                -1 => return Ok(low),
                1 => return Ok(!low),
                _ => match ccw(v1n, v2, v2n) {
                    Some(turn) => return Ok(turn),
                    None => true,
                },
            }
        } else if before(v2n[p], v1n[p]) {
            let bb = if increasing { bbox(v1, v1n, v2n, q) } else { bbox(v1n, v1, v2n, q) };
            match bb {
                -1 => return Ok(!low),
                1 => return Ok(low),
                _ => match ccw(v1n, v1, v2n) {
                    Some(turn) => return Ok(turn),
                    None => false,
                },
            }
        } else if v1n[q] != v2n[q] {
            return Ok(if v1n[q] < v2n[q] { low } else { !low });
        } else {
            false
        };
        if step1 {
            // `v1 = v1next--`: ill-conditioned at the arc's start, GLU guesses.
            i1 = n1;
            if i1 == 0 {
                return Ok(false);
            }
            n1 -= 1;
        } else {
            i2 = n2;
            if i2 == b.len() - 1 {
                return Ok(false);
            }
            n2 += 1;
        }
    }
}

/// GLU `Subdivider::bbox` on coordinate `p`: where `c` lies against `a` and `b`.
fn bbox(a: Pt, b: Pt, c: Pt, p: usize) -> i32 {
    let (sa, sb, sc) = (a[p], b[p], c[p]);
    if sa < sb {
        if sc <= sa {
            -1
        } else if sb <= sc {
            1
        } else {
            0
        }
    } else if sa > sb {
        if sc >= sa {
            1
        } else if sb >= sc {
            -1
        } else {
            0
        }
    } else if sc > sa {
        1
    } else if sb > sc {
        -1
    } else {
        0
    }
}

/// GLU `Subdivider::ccw` (with `det3`): counter-clockwise or not, `None` when the determinant
/// is under 1e-4 (ill-conditioned).
fn ccw(a: Pt, b: Pt, c: Pt) -> Option<bool> {
    let d = a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]);
    if d.abs() < 0.0001 {
        None
    } else {
        Some(d.is_nan() || d >= 0.0) // C's `(d < 0.0) ? 0 : 1`
    }
}
