//! The position map on grids, through the row kernel of [`crate::tess`]: one kernel per Bezier
//! piece (its basis tables computed once), rows of points turned into the vertex-callback data
//! GLU hands out ((x, y, z) divided by w, then u, v).

use super::pieces::{locate, SurfacePatches};
use crate::math::{BezierPatches, Scalar};
use crate::tess::{MapView, Row, RowKernel};

/// The vertex-callback data (x, y, z divided by w, then u, v) of every point of the grid
/// `us` × `vs` (v outer), all inside one Bezier piece of `pos`, evaluated on the grid path.
pub(crate) fn grid_vertices(pos: &SurfacePatches, k: usize, us: &[f64], vs: &[f64]) -> Option<Vec<[f32; 5]>> {
    let mut out = vec![[0.0; 5]; us.len() * vs.len()];
    grid_vertices_into(pos, k, us, vs, &mut out)?;
    Some(out)
}

/// [`grid_vertices`] into `out` (`us.len() * vs.len()` entries, v outer).
///
/// Evaluated in f32, as GLU's own evaluator does (libnurbs `REAL` is `float`) and as the
/// callbacks receive it: four points per SSE register instead of two. The vertices stay within
/// an f32 ulp of the f64 evaluation (`tessellator_vertices_lie_on_the_surface...` in the tests:
/// worst 4.4e-7 on a net ten units across), and the untrimmed case runs about 10% faster, its
/// evaluation sharing two cores with the callbacks.
pub(crate) fn grid_vertices_into(
    pos: &SurfacePatches,
    k: usize,
    us: &[f64],
    vs: &[f64],
    out: &mut [[f32; 5]],
) -> Option<()> {
    let p = &pos.patches;
    let mid = |r: &[f64]| 0.5 * (r[0] + r[r.len() - 1]);
    let a = locate(&p.uintervals, mid(us))?;
    let b = locate(&p.vintervals, mid(vs))?;
    let net: Vec<f32> = p.patch(a, b)?.iter().map(|&c| c as f32).collect();
    let kernel = piece_kernel(p, (a, b), &net, us, vs)?;
    let mut row = Row::default();
    let n = us.len();
    if out.len() != n * vs.len() {
        return None;
    }
    for ((j, &v), line) in vs.iter().enumerate().zip(out.chunks_exact_mut(n)) {
        kernel.eval_row(j, &mut row);
        vertex_row(&row, k, us, v, line, |data| data);
    }
    Some(())
}

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
