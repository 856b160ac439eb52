//! The position map on grids, through the row kernel of [`crate::tess`]: one kernel per Bezier
//! piece (its basis tables computed once), rows of points turned into the vertex-callback data
//! GLU hands out ((x, y, z) divided by w, then u, v).

use crate::math::{BezierPatches, Scalar};
use crate::tess::{MapView, Row, RowKernel};

/// The row kernel of Bezier piece (a, b) of `p` (its control points `net`, in the kernel's
/// precision) over the lines `us` × `vs`, given in the surface's parameters.
pub(crate) fn piece_kernel<'a, S: Scalar>(
    p: &BezierPatches<f64>,
    (a, b): (usize, usize),
    net: &'a [S],
    us: &[f64],
    vs: &[f64],
) -> Option<RowKernel<'a, S>> {
    let normalised = |lines: &[f64], (lo, hi): (f64, f64)| -> Vec<S> {
        lines.iter().map(|&x| S::from_f64((x - lo) / (hi - lo))).collect()
    };
    let (su, sv) = (normalised(us, p.uintervals[a]), normalised(vs, p.vintervals[b]));
    let view = MapView { dim: p.dim, uorder: p.uorder, vorder: p.vorder, points: net };
    RowKernel::new(view, &su, &sv, false)
}

/// A row of points as vertex-callback data, `wrap`ped into `out`: x, y, z (divided by w when
/// `k` is 4: only then, as a division per coordinate costs more than the rest of the point's
/// work), then the point's u (from `us`) and `v`.
pub(crate) fn vertex_row<S: Scalar, T>(
    row: &Row<S>,
    k: usize,
    us: &[f64],
    v: f64,
    out: &mut [T],
    wrap: impl Fn([f32; 5]) -> T,
) {
    let [x, y, z, w] = &row.point;
    let xyz = x.iter().zip(y).zip(z).map(|((x, y), z)| [*x, *y, *z]);
    let out = out.iter_mut().zip(us);
    let (f, v) = (|c: S| c.to_f64() as f32, v as f32);
    if k == 4 {
        for ((o, &u), ([x, y, z], &w)) in out.zip(xyz.zip(w)) {
            *o = wrap([f(x / w), f(y / w), f(z / w), u as f32, v]);
        }
    } else {
        for ((o, &u), [x, y, z]) in out.zip(xyz) {
            *o = wrap([f(x), f(y), f(z), u as f32, v]);
        }
    }
}
