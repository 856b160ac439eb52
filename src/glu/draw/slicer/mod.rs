//! GLU's own tessellation of a rectangular region of the domain, primitive for primitive: how
//! SGI's `libnurbs` (as shipped in GLU 9.0) covers an untrimmed patch. The region's border is
//! sampled as a trim loop at the coarser "sidestep" rates ([`border`]), the inside on a uniform
//! grid at the interior steps, and the two are joined by triangle fans ([`strip`]); a region too
//! thin for an inner grid is covered by fans and one quad strip ([`thin`]).
//!
//! The pieces are (u, v) parameters only, in `f32` as GLU computes them; [`output`] evaluates
//! them through the callbacks (`GLU_NURBS_TESSELLATOR`) or hands them to the GL evaluators
//! (`GLU_NURBS_RENDERER`). Follows `Slicer::slice_new` and the rectangle functions of
//! `internals/slicer.cc`.

pub(crate) mod border;
pub(crate) mod output;
pub(crate) mod split;
mod strip;
mod thin;
pub(crate) mod vertex;

use crate::glu::evaluation::sampling::MAX_SEGMENTS;
use border::RectLoop;

/// One primitive of the tessellation, in parameter space.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Piece {
    /// `GL_TRIANGLE_FAN` through these (u, v).
    Fan(Vec<[f32; 2]>),
    /// `GL_QUAD_STRIP` through these (u, v).
    QuadStrip(Vec<[f32; 2]>),
    /// A block of the uniform grid (GLU `surfgrid` + `surfmesh`).
    Grid(Grid),
    /// Part of a grid: lines `u.0..=u.1` by `v.0..=v.1` of it (GLU `surfgrid` then
    /// `surfmesh(u.0, v.0, u.1 - u.0, v.1 - v.0)`, as `Slicer::evalRBArray` draws its blocks).
    Block { grid: Grid, u: (i64, i64), v: (i64, i64) },
    /// `GL_LINE_STRIP` through these (u, v): an outline (`GLU_OUTLINE_PATCH`).
    Line(Vec<[f32; 2]>),
}

/// `glMapGrid2(nu, u0, u1, nv, v0, v1)` and `glEvalMesh2(0, nu, 0, nv)`: GLU passes v from
/// the top line to the bottom one, so that the mesh's strips turn counter-clockwise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Grid {
    pub u: (f32, f32),
    pub nu: usize,
    pub v: (f32, f32),
    pub nv: usize,
}

impl Grid {
    /// Line `i` of the grid in u, as GLU's `mapmesh2f` computes it in callback mode.
    pub fn u_at(&self, i: usize) -> f32 {
        line(self.u, self.nu, i)
    }

    /// Line `j` of the grid in v.
    pub fn v_at(&self, j: usize) -> f32 {
        line(self.v, self.nv, j)
    }
}

pub(super) fn line((a, b): (f32, f32), n: usize, i: usize) -> f32 {
    if i == n {
        b
    } else {
        a + i as f32 * ((b - a) / n as f32)
    }
}

/// The interior sampling of a region: steps in u and v and whether each direction is linear
/// (order 2), which changes how a thin region is covered.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Interior {
    pub du: f32,
    pub dv: f32,
    pub ulinear: bool,
    pub vlinear: bool,
}

/// The pieces covering the rectangle `rect` (GLU `Slicer::slice_new` for a rectangular loop):
/// a grid of 3 + ⌊width/du⌋ lines across u (2 when one step covers it) and 2 + ⌊height/dv⌋
/// across v (2 when one step covers it) counting the border, the border joined to the inner
/// lines by fans; with no inner line in some direction, [`thin::triangulate`].
pub(crate) fn slice_rect(rect: &RectLoop, interior: Interior) -> Vec<Piece> {
    let ([u0, v0], [u1, v1]) = (rect.min(), rect.max());
    if u1 == u0 {
        return Vec::new(); // GLU returns here to avoid a division by zero.
    }
    let (du, dv) = (interior.du.abs(), interior.dv.abs());
    let ulines = if du > u1 - u0 { 2 } else { 3 + c_int((u1 - u0) / du) };
    let vlines = if dv >= v1 - v0 { 2 } else { 2 + c_int((v1 - v0) / dv) };
    if ulines <= 2 || vlines <= 2 {
        let across = match (interior.vlinear, interior.ulinear) {
            (true, _) => thin::Across::TopBottom,
            (false, true) => thin::Across::LeftRight,
            _ => thin::Across::Denser,
        };
        return thin::triangulate(rect, across);
    }
    let cap = |n: i64| (n as usize).min(MAX_SEGMENTS);
    strip::triangulate_with_grid(rect, cap(ulines - 2), cap(vlines - 2))
}

/// `GLU_OUTLINE_PATCH`: the sampled border, each side as a line strip run backwards, from
/// the left side round to the bottom (GLU `Subdivider::outline` walks its bin's loop through
/// `prev` from the left side, the bin's first arc; `Slicer::outline` lists each arc's points
/// from the last).
pub(crate) fn outline_rect(rect: &RectLoop) -> Vec<Piece> {
    [&rect.left, &rect.top, &rect.right, &rect.bottom]
        .into_iter()
        .filter(|side| side.len() >= 2)
        .map(|side| Piece::Line(side.iter().rev().copied().collect()))
        .collect()
}

/// C's `(int)x` as GLU's x86 build computes it: the integer part, or `INT_MIN` (the "integer
/// indefinite" of `cvttss2si`) when x is not finite or out of range. A zero step thus gives
/// GLU a negative line count, and the thin covering, rather than endless lines.
pub(crate) fn c_int(x: f32) -> i64 {
    if x.is_finite() && x > -2_147_483_649.0 && x < 2_147_483_648.0 {
        x.trunc() as i64
    } else {
        i64::from(i32::MIN)
    }
}
