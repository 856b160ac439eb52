//! GLU's monotone triangulations on chains and small polygons (`nurbtess/monoTriangulation.cc`:
//! `monoTriangulation2`, `monoTriangulationRecGen`, `monoTriangulationRecGenOpt`,
//! `monoTriangulationOpt`, `monoTriangulationFun`; `partitionX.cc`: the interior cusps in u;
//! `sampleMonoPoly.cc`: `triangulateXYMono`, `stripOfFanLeft`; `sampleCompRight.cc`:
//! `stripOfFanRight`).

use super::chain::at;
use super::grid::GridWrap;
use super::partition;
use super::{Poly, Pt, Stream};
use crate::glu::draw::subdivider::mono::{chains, comp_v2_in_y, ReflexChain};
use std::cmp::Ordering;

/// GLU `compV2InX`: by u, then by v.
pub(crate) fn comp_v2_in_x(a: Pt, b: Pt) -> Ordering {
    if a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]) {
        Ordering::Less
    } else if a == b {
        Ordering::Equal
    } else {
        Ordering::Greater
    }
}

/// Points `a..=b` of a chain (none when b < a).
pub(crate) fn span(c: &[Pt], a: i64, b: i64) -> Vec<Pt> {
    (a..=b).map(|i| at(c, i)).collect()
}

/// `monoTriangulationRecGen`: between chains `inc[ic..=ie]` and `dec[dc..=de]` from `top` to
/// `bot`, by v.
#[allow(clippy::too_many_arguments)]
pub(crate) fn rec_gen(top: Pt, bot: Pt, inc: &[Pt], ic: i64, ie: i64, dec: &[Pt], dc: i64, de: i64, s: &mut Stream) {
    if ic > ie && dc > de {
        return;
    }
    chains(top, bot, (&span(inc, ic, ie), 0), (&span(dec, dc, de), 0), comp_v2_in_y, &mut s.pieces);
}

/// `monoTriangulation2`: between one chain `c[small..=large]` (increasing: on the left) and
/// the segment top–bot.
pub(crate) fn mono2(top: Pt, bot: Pt, c: &[Pt], small: i64, large: i64, increasing: bool, s: &mut Stream) {
    if small > large {
        return;
    }
    if small == large {
        let p = at(c, small);
        return s.fan(if increasing { vec![p, bot, top] } else { vec![p, top, bot] });
    }
    if increasing && bot[1] == at(c, large)[1] {
        s.fan(vec![bot, at(c, large - 1), at(c, large)]);
        return mono2(top, bot, c, small, large - 1, increasing, s);
    }
    if !increasing && top[1] == at(c, small)[1] {
        s.fan(vec![top, at(c, small + 1), at(c, small)]);
        return mono2(top, bot, c, small + 1, large, increasing, s);
    }
    let mut chain = ReflexChain::new(increasing);
    chain.process(top, &mut s.pieces);
    for i in small..=large {
        chain.process(at(c, i), &mut s.pieces);
    }
    chain.process(bot, &mut s.pieces);
}

/// `monoTriangulationRecGenOpt`: the region as a polygon of segments, triangulated by u
/// ([`mono_u`]), or where it has several interior cusps in u, cut by GLU's `monoPolyPart` into
/// polygons monotone in u, each triangulated by u.
#[allow(clippy::too_many_arguments)]
pub(crate) fn rec_gen_opt(
    top: Pt,
    bot: Pt,
    inc: &[Pt],
    ic: i64,
    ie: i64,
    dec: &[Pt],
    dc: i64,
    de: i64,
    s: &mut Stream,
) {
    let mut lines: Vec<Vec<Pt>> = Vec::new();
    if ic <= ie {
        lines.push(vec![top, at(inc, ic)]);
        lines.extend((ic..ie).map(|i| vec![at(inc, i), at(inc, i + 1)]));
        lines.push(vec![at(inc, ie), bot]);
    } else {
        lines.push(vec![top, bot]);
    }
    if dc <= de {
        lines.push(vec![bot, at(dec, de)]);
        lines.extend((dc + 1..=de).rev().map(|i| vec![at(dec, i), at(dec, i - 1)]));
        lines.push(vec![at(dec, dc), top]);
    } else {
        lines.push(vec![bot, top]);
    }
    let poly = Poly { lines };
    if !mono_u(&poly, s) {
        match partition::mono_poly_part(&poly) {
            Some(parts) => parts.iter().for_each(|p| mono_fun(p, comp_v2_in_x, s)),
            None => s.bad = true,
        }
    }
}

/// The polygon triangulated by u where it has no interior cusp in u, or one that a diagonal
/// cuts off (GLU's u-monotone cases in `sampleMonoPoly`, `monoTriangulationOpt` and
/// `monoTriangulationRecGenOpt`); false, with nothing drawn, where it has several.
pub(crate) fn mono_u(poly: &Poly, s: &mut Stream) -> bool {
    let cusps = cusps_x(poly);
    match cusps[..] {
        [] => mono_fun(poly, comp_v2_in_x, s),
        [c] => match partition::split_at_cusp(poly, c) {
            Some(halves) => halves.iter().for_each(|h| mono_fun(h, comp_v2_in_x, s)),
            None => mono_fun(poly, comp_v2_in_x, s),
        },
        _ => return false,
    }
    true
}

/// `monoTriangulationOpt`: a polygon monotone in u by u, one with a single interior cusp cut
/// at it, any other by v.
pub(crate) fn mono_opt(poly: &Poly, s: &mut Stream) {
    if !mono_u(poly, s) {
        mono_fun(poly, comp_v2_in_y, s);
    }
}

/// GLU `findInteriorCuspsX` (`partitionX.cc`): the vertices where the polygon turns back in u
/// into its inside.
fn cusps_x(poly: &Poly) -> Vec<usize> {
    (0..poly.len()).filter(|&v| is_cusp_x(poly, v) && is_reflex_x(poly, v)).collect()
}

fn is_cusp_x(poly: &Poly, v: usize) -> bool {
    let (t, p, n) = (poly.head(v), poly.head(poly.prev(v)), poly.head(poly.next(v)));
    let (tp, tn) = (comp_v2_in_x(t, p), comp_v2_in_x(t, n));
    (tp != Ordering::Less && tn != Ordering::Less) || (tp != Ordering::Greater && tn != Ordering::Greater)
}

/// GLU `isReflexX`, its coordinates scaled by 10 in `f32`.
fn is_reflex_x(poly: &Poly, v: usize) -> bool {
    let (a, b, c) = (poly.head(poly.prev(v)), poly.head(v), poly.tail(v));
    let (bx, by) = (10.0 * (b[0] - a[0]), 10.0 * (b[1] - a[1]));
    let (cx, cy) = (10.0 * (c[0] - a[0]), 10.0 * (c[1] - a[1]));
    f64::from(bx * cy - cx * by) < -1.0e-6
}

/// GLU `monoTriangulationFun`: the polygon's two chains from its top to its bottom under
/// `cmp`, triangulated together.
pub(crate) fn mono_fun(poly: &Poly, cmp: fn(Pt, Pt) -> Ordering, s: &mut Stream) {
    let (top, bot) = poly.extremes(cmp);
    let (inc, dec) = poly.chains(top, bot);
    if !(inc.is_empty() && dec.is_empty()) {
        chains(poly.head(top), poly.head(bot), (&inc, 0), (&dec, 0), cmp, &mut s.pieces);
    }
}

/// GLU `triangulateXYMono`: the strip between an upper and a lower row of points, both
/// increasing in u.
pub(crate) fn xy_mono(upper: &[Pt], lower: &[Pt], s: &mut Stream) {
    if upper.is_empty() || lower.is_empty() {
        return;
    }
    let (mut i, mut j, mut left) = if upper[0][0] <= lower[0][0] { (1, 0, upper[0]) } else { (0, 1, lower[0]) };
    loop {
        if i >= upper.len() {
            if j + 1 < lower.len() {
                let mut fan = vec![left];
                fan.extend_from_slice(&lower[j..]);
                s.fan(fan);
            }
            return;
        }
        if j >= lower.len() {
            if i + 1 < upper.len() {
                let mut fan = vec![left];
                fan.extend(upper[i..].iter().rev());
                s.fan(fan);
            }
            return;
        }
        if upper[i][0] <= lower[j][0] {
            let mut k = i;
            while k < upper.len() && upper[k][0] <= lower[j][0] {
                k += 1;
            }
            let k = k - 1;
            let mut fan = vec![lower[j]];
            fan.extend(upper[i..=k].iter().rev());
            fan.push(left);
            s.fan(fan);
            i = k + 1;
            left = upper[k];
        } else {
            let mut fan = vec![upper[i], left];
            let mut k = j;
            while k < lower.len() && lower[k][0] < upper[i][0] {
                fan.push(lower[k]);
                k += 1;
            }
            s.fan(fan);
            j = k;
            left = lower[j - 1];
        }
    }
}

/// GLU `stripOfFanLeft` (`left`) and `stripOfFanRight`: the strip between chain points
/// `small..=large` and grid points `ul_small..=ul_large` on grid line `vline`, the grid line
/// above the chain when `grid_up`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn strip_of_fan(
    c: &[Pt],
    (large, small): (i64, i64),
    grid: &GridWrap,
    vline: i64,
    (ul_small, ul_large): (i64, i64),
    grid_up: bool,
    left: bool,
    s: &mut Stream,
) {
    let forward = if left { grid_up } else { !grid_up };
    let mut trim = span(c, small, large);
    if !forward {
        trim.reverse();
    }
    let v = grid.v_at(vline);
    let row: Vec<Pt> = (ul_small..=ul_large).map(|i| [grid.u_at(i), v]).collect();
    if grid_up {
        xy_mono(&row, &trim, s);
    } else {
        xy_mono(&trim, &row, s);
    }
}
