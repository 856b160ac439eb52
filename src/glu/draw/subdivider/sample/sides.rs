//! The left and right strips of a component, between its trim chains and the grid points
//! next to them (`sampleCompLeft`, `sampleLeftSingleTrimEdgeRegionGen` in
//! `nurbtess/sampleComp.cc`; `sampleLeftStripRecF`, `sampleLeftOneGridStep`,
//! `sampleLeftSingleTrimEdgeRegion` in `sampleMonoPoly.cc`; their mirrors in
//! `sampleCompRight.cc`). GLU writes the two sides separately with small differences
//! (how the middle grid lines are found, `>` against `>=`), kept here.

use super::chain::{at, check_middle, index_above, index_below};
use super::corners::{Corner, Sides};
use super::grid::BoundaryChain;
use super::tri::{mono2, mono_opt, rec_gen};
use super::{Poly, Pt, Stream};

/// One component: its top and bottom, chains, grid chain, grid lines and corners.
pub(crate) struct Comp<'a, 'g> {
    pub top: Pt,
    pub bot: Pt,
    pub sides: Sides<'a>,
    pub grid: &'a BoundaryChain<'g>,
    pub g1: i64,
    pub g2: i64,
    pub up: Corner,
    pub down: Corner,
}

/// GLU `sampleCompLeft`.
pub(crate) fn comp_left(c: &Comp, s: &mut Stream) {
    let (l, gc) = (c.sides.l, c.grid);
    let (ls, le) = (c.sides.ls, c.sides.le);
    let mid1 = index_below(l, gc.v(c.g1), ls, le);
    let mut mid2 = -1;
    let (mut gmid1, mut gmid2) = (0, 0);
    if mid1 <= le && c.g1 < c.g2 && at(l, mid1)[1] >= gc.v(c.g2) {
        mid2 = index_above(l, gc.v(c.g2), mid1, le);
        gmid1 = gc.lookfor(at(l, mid1)[1], c.g1, c.g2);
        gmid2 = 1 + gc.lookfor(at(l, mid2)[1], gmid1, c.g2);
    }
    let (ctop, cls, crue) = match c.up {
        (0, i) => (at(l, i), i + 1, -1),
        (1, _) => (c.top, ls, -1),
        (_, i) => (c.top, ls, i),
    };
    let (cbot, cle, crds) = match c.down {
        (0, i) => (at(l, i), i - 1, c.sides.re + 1),
        (1, _) => (c.bot, le, c.sides.re + 1),
        (_, i) => (c.bot, le, i),
    };
    if mid2 >= 0 {
        edge_region_left(ctop, at(l, mid1), (cls, mid1 - 1), (c.g1, gmid1), (c.sides.rs, crue), (0, -1), c, s);
        edge_region_left(at(l, mid2), cbot, (mid2 + 1, cle), (gmid2, c.g2), (0, -1), (crds, c.sides.re), c, s);
        strip_left(l, (mid1, mid2), gc, (gmid1, gmid2), s);
    } else {
        edge_region_left(ctop, cbot, (cls, cle), (c.g1, c.g2), (c.sides.rs, crue), (crds, c.sides.re), c, s);
    }
}

/// GLU `sampleLeftSingleTrimEdgeRegionGen`: the left chain against the grid chain's end
/// points (with the right chain's pieces above and below), the stairs of the grid as fans.
#[allow(clippy::too_many_arguments)]
fn edge_region_left(
    top: Pt,
    bot: Pt,
    (ls, le): (i64, i64),
    (gb, ge): (i64, i64),
    (rub, rue): (i64, i64),
    (rdb, rde): (i64, i64),
    c: &Comp,
    s: &mut Stream,
) {
    let (r, gc) = (c.sides.r, c.grid);
    let mut v: Vec<Pt> = (rub..=rue).map(|i| at(r, i)).collect();
    v.push(gc.vertex(gb));
    for i in gb + 1..=ge {
        v.push(gc.vertex(i));
        gc.left_end_fan(i, s);
    }
    v.extend((rdb..=rde).map(|i| at(r, i)));
    rec_gen(top, bot, c.sides.l, ls, le, &v, 0, v.len() as i64 - 1, s);
}

/// GLU `sampleLeftStripRecF`: the left chain between grid lines `g0..g1`, one grid step at
/// a time.
fn strip_left(l: &[Pt], (mut top, bot): (i64, i64), gc: &BoundaryChain, (mut g0, g1): (i64, i64), s: &mut Stream) {
    while top <= bot && g0 < g1 {
        let second = gc.v(g0 + 1);
        let mut i1 = top;
        while at(l, i1)[1] > second {
            i1 += 1;
            if i1 > bot {
                break;
            }
        }
        if i1 > bot || at(l, i1)[1] < second {
            i1 -= 1;
        }
        one_step_left(l, (top, i1), gc, g0, s);
        if at(l, i1)[1] == second {
            (top, g0) = (i1, g0 + 1);
        } else if i1 < bot {
            let (upper, lower) = (at(l, i1), at(l, i1 + 1));
            let mut i2 = g0 + 1;
            while gc.v(i2) >= lower[1] {
                i2 += 1;
                if i2 > g1 {
                    break;
                }
            }
            i2 -= 1;
            single_edge_left(upper, lower, gc, (g0 + 1, i2), s);
            (top, g0) = (i1 + 1, i2);
        } else {
            return;
        }
    }
}

/// GLU `sampleLeftSingleTrimEdgeRegion`.
fn single_edge_left(upper: Pt, lower: Pt, gc: &BoundaryChain, (b, e): (i64, i64), s: &mut Stream) {
    let mut v = vec![gc.vertex(b)];
    for i in b + 1..=e {
        v.push(gc.vertex(i));
        gc.left_end_fan(i, s);
    }
    mono2(upper, lower, &v, 0, e - b, false, s);
}

/// GLU `sampleLeftOneGridStep`: the chain between two grid lines; with no point strictly
/// between them a fan and a chain, else the polygon of the step (`monoTriangulationOpt`).
fn one_step_left(l: &[Pt], (b, e): (i64, i64), gc: &BoundaryChain, g: i64, s: &mut Stream) {
    if check_middle(l, b, e, gc.v(g), gc.v(g + 1)).is_none() {
        gc.left_end_fan(g + 1, s);
        return mono2(gc.vertex(g), gc.vertex(g + 1), l, b, e, true, s);
    }
    let grid = gc.grid;
    let (inner, upper, lower) = (gc.inner(g + 1), gc.uline(g), gc.uline(g + 1));
    let (uv, lv) = (gc.v(g), gc.v(g + 1));
    let mut lines: Vec<Vec<Pt>> = Vec::new();
    lines.extend((upper + 1..=inner).rev().map(|i| vec![[grid.u_at(i), uv], [grid.u_at(i - 1), uv]]));
    lines.push(vec![[grid.u_at(upper), uv], at(l, b)]);
    lines.extend((b..e).map(|i| vec![at(l, i), at(l, i + 1)]));
    lines.push(vec![at(l, e), [grid.u_at(lower), lv]]);
    lines.extend((lower..inner).map(|i| vec![[grid.u_at(i), lv], [grid.u_at(i + 1), lv]]));
    lines.push(vec![[grid.u_at(inner), lv], [grid.u_at(inner), uv]]);
    mono_opt(&Poly { lines }, s);
}

/// GLU `sampleCompRight`.
pub(crate) fn comp_right(c: &Comp, s: &mut Stream) {
    let (r, gc) = (c.sides.r, c.grid);
    let (rs, re) = (c.sides.rs, c.sides.re);
    let mid1 = index_below(r, gc.v(c.g1), rs, re);
    let mut mid2 = -1;
    let (mut gmid1, mut gmid2) = (0, 0);
    if mid1 <= re && c.g1 < c.g2 && at(r, mid1)[1] >= gc.v(c.g2) {
        mid2 = index_above(r, gc.v(c.g2), mid1, re);
        let t = at(r, mid1)[1];
        gmid1 = c.g1;
        if gc.v(c.g1) != t {
            while gc.v(gmid1) > t {
                gmid1 += 1;
            }
            gmid1 -= 1;
        }
        let t = at(r, mid2)[1];
        gmid2 = gmid1 + 1;
        while gmid2 <= c.g2 && gc.v(gmid2) > t {
            gmid2 += 1;
        }
    }
    let (ctop, crs, clue) = match c.up {
        (2, i) => (at(r, i), i + 1, -1),
        (1, _) => (c.top, rs, -1),
        (_, i) => (c.top, rs, i),
    };
    let (cbot, cre, clds) = match c.down {
        (2, i) => (at(r, i), i - 1, c.sides.le + 1),
        (1, _) => (c.bot, re, c.sides.le + 1),
        (_, i) => (c.bot, re, i),
    };
    if mid2 >= 0 {
        edge_region_right(ctop, at(r, mid1), (crs, mid1 - 1), (c.g1, gmid1), (c.sides.ls, clue), (0, -1), c, s);
        edge_region_right(at(r, mid2), cbot, (mid2 + 1, cre), (gmid2, c.g2), (0, -1), (clds, c.sides.le), c, s);
        strip_right(r, (mid1, mid2), gc, (gmid1, gmid2), s);
    } else {
        edge_region_right(ctop, cbot, (crs, cre), (c.g1, c.g2), (c.sides.ls, clue), (clds, c.sides.le), c, s);
    }
}

/// GLU `sampleRightSingleTrimEdgeRegionGen`.
#[allow(clippy::too_many_arguments)]
fn edge_region_right(
    top: Pt,
    bot: Pt,
    (rs, re): (i64, i64),
    (gb, ge): (i64, i64),
    (lub, lue): (i64, i64),
    (ldb, lde): (i64, i64),
    c: &Comp,
    s: &mut Stream,
) {
    let (l, gc) = (c.sides.l, c.grid);
    let mut v: Vec<Pt> = (lub..=lue).map(|i| at(l, i)).collect();
    v.push(gc.vertex(gb));
    for i in gb + 1..=ge {
        v.push(gc.vertex(i));
        gc.right_end_fan(i, s);
    }
    v.extend((ldb..=lde).map(|i| at(l, i)));
    rec_gen(top, bot, &v, 0, v.len() as i64 - 1, c.sides.r, rs, re, s);
}

/// GLU `sampleRightStripRecF`.
fn strip_right(r: &[Pt], (mut top, bot): (i64, i64), gc: &BoundaryChain, (mut g0, g1): (i64, i64), s: &mut Stream) {
    while top <= bot && g0 < g1 {
        let second = gc.v(g0 + 1);
        let mut i1 = top;
        while at(r, i1)[1] >= second {
            i1 += 1;
            if i1 > bot {
                break;
            }
        }
        i1 -= 1;
        one_step_right(r, (top, i1), gc, g0, s);
        if at(r, i1)[1] == second {
            (top, g0) = (i1, g0 + 1);
        } else if i1 < bot {
            let (upper, lower) = (at(r, i1), at(r, i1 + 1));
            let mut i2 = g0 + 1;
            while gc.v(i2) > lower[1] {
                i2 += 1;
                if i2 > g1 {
                    break;
                }
            }
            i2 -= 1;
            single_edge_right(upper, lower, gc, (g0 + 1, i2), s);
            (top, g0) = (i1 + 1, i2);
        } else {
            return;
        }
    }
}

/// GLU `sampleRightSingleTrimEdgeRegion`.
fn single_edge_right(upper: Pt, lower: Pt, gc: &BoundaryChain, (b, e): (i64, i64), s: &mut Stream) {
    let mut v = vec![gc.vertex(b)];
    for i in b + 1..=e {
        v.push(gc.vertex(i));
        gc.right_end_fan(i, s);
    }
    mono2(upper, lower, &v, 0, e - b, true, s);
}

/// GLU `sampleRightOneGridStep`.
fn one_step_right(r: &[Pt], (b, e): (i64, i64), gc: &BoundaryChain, g: i64, s: &mut Stream) {
    if check_middle(r, b, e, gc.v(g), gc.v(g + 1)).is_none() {
        gc.right_end_fan(g + 1, s);
        return mono2(gc.vertex(g), gc.vertex(g + 1), r, b, e, false, s);
    }
    let grid = gc.grid;
    let (inner, upper, lower) = (gc.inner(g + 1), gc.uline(g), gc.uline(g + 1));
    let (uv, lv) = (gc.v(g), gc.v(g + 1));
    let mut lines: Vec<Vec<Pt>> = Vec::new();
    lines.extend((inner + 1..=upper).rev().map(|i| vec![[grid.u_at(i), uv], [grid.u_at(i - 1), uv]]));
    lines.push(vec![[grid.u_at(inner), uv], [grid.u_at(inner), lv]]);
    lines.extend((inner..lower).map(|i| vec![[grid.u_at(i), lv], [grid.u_at(i + 1), lv]]));
    lines.push(vec![[grid.u_at(lower), lv], at(r, e)]);
    lines.extend((b + 1..=e).rev().map(|i| vec![at(r, i), at(r, i - 1)]));
    lines.push(vec![at(r, b), [grid.u_at(upper), uv]]);
    mono_opt(&Poly { lines }, s);
}
