//! The top and bottom of a component, between its first (last) grid line and the trim
//! chains above (below) it (`sampleCompTop`, `sampleTopRightWithGridLine`,
//! `sampleCompTopSimple` in `nurbtess/sampleCompTop.cc`; `sampleCompBot`,
//! `sampleBotRightWithGridLine`, `sampleBotLeftWithGridLine`, `sampleCompBotSimple` in
//! `sampleCompBot.cc`).

use super::chain::at;
use super::corners::Corner;
use super::grid::{BoundaryChain, GridWrap};
use super::tri::{mono2, rec_gen_opt, strip_of_fan};
use super::{Pt, Stream};

/// The grid line a component starts or ends on, and its chains.
pub(crate) struct End<'a, 'g> {
    pub lg: &'a BoundaryChain<'g>,
    pub rg: &'a BoundaryChain<'g>,
    pub index: i64,
    pub l: &'a [Pt],
    pub r: &'a [Pt],
}

impl End<'_, '_> {
    fn grid(&self) -> &GridWrap {
        self.lg.grid
    }

    /// (grid line, left u index, right u index).
    fn line(&self) -> (i64, i64, i64) {
        (self.lg.vline(self.index), self.lg.uline(self.index), self.rg.uline(self.index))
    }

    /// The line's grid points from the right end to the left.
    fn points(&self) -> Vec<Pt> {
        let (gv, lu, ru) = self.line();
        let g = self.grid();
        (lu..=ru).rev().map(|i| [g.u_at(i), g.v_at(gv)]).collect()
    }
}

/// GLU `sampleCompTop`: from the chains' starts `ls`, `rs` down to the first grid line.
pub(crate) fn comp_top(top: Pt, e: &End, (ls, rs): (i64, i64), (lc, rc): (Corner, Corner), s: &mut Stream) {
    let (gv, lu, ru) = e.line();
    if lc.0 == 1 && rc.0 == 1 {
        e.grid().fan_with_point(gv, lu, ru, top, s);
    } else if lc.0 != 0 {
        let (t, start) = if lc.0 == 1 { (top, rs) } else { (at(e.r, lc.1), lc.1 + 1) };
        top_right(t, e, (start, rc.1), s);
    } else {
        top_simple(top, e, (ls, rs), (lc, rc), s);
    }
}

/// GLU `sampleTopRightWithGridLine` (with `findTopRightSegment` and its `Post`).
fn top_right(top: Pt, e: &End, (start, end): (i64, i64), s: &mut Stream) {
    let (gv, lu, ru) = e.line();
    let (g, r) = (e.grid(), e.r);
    if end < start {
        return g.fan_with_point(gv, lu, ru, top, s);
    }
    let u = g.u_at(ru);
    let mut large = end;
    while large >= start && at(r, large)[0] > u {
        large -= 1;
    }
    let mut small = 0;
    if large >= start {
        small = large;
        while small > start && at(r, small - 1)[0] < at(r, small)[0] {
            small -= 1;
        }
    }
    if large < end {
        let t = if large >= start { at(r, large) } else { top };
        rec_gen_opt(t, [g.u_at(ru), g.v_at(gv)], &[], 1, 0, r, large + 1, end, s);
    }
    if large >= start {
        strip_of_fan(r, (large, small), g, gv, (lu, ru), false, false, s);
        mono2(top, [g.u_at(lu), g.v_at(gv)], r, start, small, false, s);
    } else {
        g.fan_with_point(gv, lu, ru, top, s);
    }
}

/// GLU `sampleCompTopSimple` (with `sampleCompTopSimpleOpt`).
fn top_simple(top: Pt, e: &End, (ls, rs): (i64, i64), (lc, rc): (Corner, Corner), s: &mut Stream) {
    let (gv, _, _) = e.line();
    let points = e.points();
    let rstart = if lc.0 != 2 { rs } else { lc.1 + 1 };
    let rend = if rc.0 != 2 { rs - 1 } else { rc.1 };
    let mut right: Vec<Pt> = (rstart..=rend).map(|i| at(e.r, i)).collect();
    right.extend_from_slice(&points);
    let lend = if lc.0 != 0 { ls - 1 } else { lc.1 };
    let lstart = if rc.0 != 0 { ls } else { rc.1 + 1 };
    let actual_top = match (lc.0, rc.0) {
        (0, 0) => at(e.l, rc.1),
        (0, _) | (1, _) => top,
        _ => at(e.r, lc.1),
    };
    let bot = points[points.len() - 1];
    let n = right.len() as i64;
    let simple = TopSimple { grid: e.grid(), inc: e.l, dec: &right };
    if at(e.l, lend)[1] == bot[1] {
        simple.run(gv, actual_top, at(e.l, lend), (lstart, lend - 1), (0, n - 1), s);
    } else {
        simple.run(gv, actual_top, bot, (lstart, lend), (0, n - 2), s);
    }
}

struct TopSimple<'a> {
    grid: &'a GridWrap,
    inc: &'a [Pt],
    dec: &'a [Pt],
}

impl TopSimple<'_> {
    /// GLU `sampleCompTopSimpleOpt`: cut the region at the grid line above where both chains
    /// have passed it, down the grid lines.
    fn run(
        &self,
        mut gv: i64,
        top: Pt,
        mut bot: Pt,
        (ic, mut ie): (i64, i64),
        (dc, mut de): (i64, i64),
        s: &mut Stream,
    ) {
        let (inc, dec) = (self.inc, self.dec);
        loop {
            if gv <= 0 || de < dc || ie < ic || self.grid.v_at(gv + 1) >= top[1] {
                return rec_gen_opt(top, bot, inc, ic, ie, dec, dc, de, s);
            }
            let v = self.grid.v_at(gv + 1);
            if !(at(inc, ie)[1] <= v && at(dec, de)[1] < v) {
                gv += 1;
                continue;
            }
            let mut i = ie;
            while i >= ic && at(inc, i)[1] <= v {
                i -= 1;
            }
            i += 1;
            let mut j = de;
            while j >= dc && at(dec, j)[1] < v {
                j -= 1;
            }
            j += 1;
            if at(inc, i)[1] <= at(dec, j)[1] {
                let mut k = j;
                while k <= de && at(dec, k)[1] >= at(inc, i)[1] {
                    k += 1;
                }
                let mut best = j;
                let mut dmin = (at(inc, i)[0] - at(dec, j)[0]).abs();
                for l in j + 1..k {
                    let d = (at(inc, i)[0] - at(dec, l)[0]).abs();
                    if d <= dmin {
                        (dmin, best) = (d, l);
                    }
                }
                rec_gen_opt(at(dec, best), bot, inc, i, ie, dec, best + 1, de, s);
                (gv, bot, ie, de) = (gv + 1, at(inc, i), i - 1, best);
            } else {
                let mut k = i;
                while k <= ie && at(inc, k)[1] > at(dec, j)[1] {
                    k += 1;
                }
                let mut best = i;
                let mut dmin = (at(inc, i)[0] - at(dec, j)[0]).abs();
                for l in i + 1..k {
                    let d = (at(inc, l)[0] - at(dec, j)[0]).abs();
                    if d <= dmin {
                        (dmin, best) = (d, l);
                    }
                }
                rec_gen_opt(at(inc, best), bot, inc, best + 1, ie, dec, j, de, s);
                (gv, bot, ie, de) = (gv + 1, at(dec, j), best, j - 1);
            }
        }
    }
}

/// GLU `sampleCompBot`: from the last grid line down to the chains' ends `le`, `re`.
pub(crate) fn comp_bot(bot: Pt, e: &End, (le, re): (i64, i64), (lc, rc): (Corner, Corner), s: &mut Stream) {
    let (gv, lu, ru) = e.line();
    if lc.0 == 1 && rc.0 == 1 {
        e.grid().fan_with_point(gv, lu, ru, bot, s);
    } else if lc.0 != 0 {
        let (b, end) = if lc.0 == 1 { (bot, re) } else { (at(e.r, lc.1), lc.1 - 1) };
        bot_right(b, e, (end, rc.1), s);
    } else if rc.0 != 2 {
        let (b, end) = if rc.0 == 1 { (bot, le) } else { (at(e.l, rc.1), rc.1 - 1) };
        bot_left(b, e, (end, lc.1), s);
    } else {
        bot_simple(bot, e, (le, re), (lc, rc), s);
    }
}

/// GLU `sampleBotRightWithGridLine` (with `findBotRightSegment` and its `Post`).
fn bot_right(bot: Pt, e: &End, (end, corner): (i64, i64), s: &mut Stream) {
    let (gv, lu, ru) = e.line();
    let (g, r) = (e.grid(), e.r);
    if end < corner {
        return g.fan_with_point(gv, lu, ru, bot, s);
    }
    let u = g.u_at(ru);
    let mut pass = corner;
    while pass <= end && at(r, pass)[0] > u {
        pass += 1;
    }
    let mut mono = 0;
    if pass <= end {
        mono = pass;
        while mono < end && at(r, mono + 1)[0] < at(r, mono)[0] {
            mono += 1;
        }
    }
    if pass > corner {
        let b = if pass <= end { at(r, pass) } else { bot };
        mono2([g.u_at(ru), g.v_at(gv)], b, r, corner, pass - 1, false, s);
    }
    if pass > end {
        return g.fan_with_point(gv, lu, ru, bot, s);
    }
    let optimize = bot[0] > g.u_at(lu) && (mono..=end).all(|i| at(r, i)[0] > bot[0]);
    let from = if optimize {
        let mut mid = lu;
        while g.u_at(mid) <= bot[0] {
            mid += 1;
            if mid > ru {
                break;
            }
        }
        mid -= 1;
        g.fan_with_point(gv, lu, mid, bot, s);
        mid
    } else {
        lu
    };
    strip_of_fan(r, (mono, pass), g, gv, (from, ru), true, false, s);
    mono2([g.u_at(from), g.v_at(gv)], bot, r, mono, end, false, s);
}

/// GLU `sampleBotLeftWithGridLine` (with `findBotLeftSegment` and its `Post`).
fn bot_left(bot: Pt, e: &End, (end, corner): (i64, i64), s: &mut Stream) {
    let (gv, lu, ru) = e.line();
    let (g, l) = (e.grid(), e.l);
    if end < corner {
        return g.fan_with_point(gv, lu, ru, bot, s);
    }
    let u = g.u_at(lu);
    let mut pass = corner;
    while pass <= end && at(l, pass)[0] < u {
        pass += 1;
    }
    let mut mono = 0;
    if pass <= end {
        mono = pass;
        while mono < end && at(l, mono + 1)[0] > at(l, mono)[0] {
            mono += 1;
        }
    }
    if pass > corner {
        let b = if pass <= end { at(l, pass) } else { bot };
        mono2([g.u_at(lu), g.v_at(gv)], b, l, corner, pass - 1, true, s);
    }
    if pass <= end {
        strip_of_fan(l, (mono, pass), g, gv, (lu, ru), true, true, s);
        mono2([g.u_at(ru), g.v_at(gv)], bot, l, mono, end, true, s);
    } else {
        g.fan_with_point(gv, lu, ru, bot, s);
    }
}

/// GLU `sampleCompBotSimple`.
fn bot_simple(bot: Pt, e: &End, (le, re): (i64, i64), (lc, rc): (Corner, Corner), s: &mut Stream) {
    let points = e.points();
    let lend = if rc.0 != 0 { le } else { rc.1 - 1 };
    let lstart = if lc.0 != 0 { le + 1 } else { lc.1 };
    let mut left = points.clone();
    left.extend((lstart..=lend).map(|i| at(e.l, i)));
    let rstart = if rc.0 != 2 { re + 1 } else { rc.1 };
    let rend = if lc.0 != 2 { re } else { lc.1 - 1 };
    let actual_bot = match (rc.0, lc.0) {
        (2, 2) => at(e.r, lc.1),
        (2, _) | (1, _) => bot,
        _ => at(e.l, rc.1),
    };
    let top = points[0];
    let n = left.len() as i64;
    if at(e.r, rstart)[1] == top[1] {
        rec_gen_opt(at(e.r, rstart), actual_bot, &left, 0, n - 1, e.r, rstart + 1, rend, s);
    } else {
        rec_gen_opt(top, actual_bot, &left, 1, n - 1, e.r, rstart, rend, s);
    }
}
