//! A rectangle with no inner grid line in some direction (GLU `triangulateRect` and
//! `triangulateRectAux` in `internals/slicer.cc`): two opposite sides are joined by fans at
//! the corners and one quad strip between their middles; the other two sides are fanned from
//! the nearest points of the first two.

use super::border::RectLoop;
use super::Piece;

/// Which pair of opposite sides the quad strip runs between.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Across {
    /// Between top and bottom (GLU when v is linear).
    TopBottom,
    /// Between left and right (GLU when u is linear but v is not).
    LeftRight,
    /// Between the pair with more points (top and bottom on a tie).
    Denser,
}

/// The pieces of `rect`.
pub(super) fn triangulate(rect: &RectLoop, across: Across) -> Vec<Piece> {
    let tb = [&rect.top[..], &rect.bottom[..], &rect.left[..], &rect.right[..]];
    let lr = [&rect.left[..], &rect.right[..], &rect.bottom[..], &rect.top[..]];
    let sides = match across {
        Across::TopBottom => tb,
        Across::LeftRight => lr,
        Across::Denser if rect.top.len() + rect.bottom.len() < rect.left.len() + rect.right.len() => lr,
        Across::Denser => tb,
    };
    let mut out = Vec::new();
    triangulate_sides(sides, &mut out);
    out
}

/// GLU's `triangulateRectAux(top, bot, left, right)`, the sides in loop order.
fn triangulate_sides([top, bot, left, right]: [&[[f32; 2]]; 4], out: &mut Vec<Piece>) {
    let fan = |root: [f32; 2], rest: &mut dyn Iterator<Item = [f32; 2]>| {
        let mut v = vec![root];
        v.extend(rest);
        Piece::Fan(v)
    };
    let (nt, nb) = (top.len(), bot.len());
    if nt < 2 || nb < 2 || left.is_empty() || right.is_empty() {
        return;
    }
    if nt == 2 {
        out.push(fan(top[0], &mut left.iter().chain(&bot[1..nb - 1]).copied()));
        out.push(fan(bot[nb - 2], &mut right.iter().copied()));
        return;
    }
    if nb == 2 {
        out.push(fan(bot[0], &mut right.iter().chain(&top[1..nt - 1]).copied()));
        out.push(fan(top[nt - 2], &mut left.iter().copied()));
        return;
    }
    corner_fans(top, bot, left, right, out);
    middle(top, bot, out);
}

/// The fans at the four corners: the left side split at its middle between the top's and
/// the bottom's points next to it, and the right side likewise.
fn corner_fans(top: &[[f32; 2]], bot: &[[f32; 2]], left: &[[f32; 2]], right: &[[f32; 2]], out: &mut Vec<Piece>) {
    let (nt, nb) = (top.len(), bot.len());
    let d = left.len() / 2;
    out.push(Piece::Fan([&[top[nt - 2]], &left[..=d]].concat()));
    out.push(Piece::Fan([&[bot[1], top[nt - 2]], &left[d..]].concat()));
    let d = right.len() / 2;
    if d + 1 < right.len() {
        out.push(Piece::Fan([&[top[1]], &right[d..]].concat()));
    }
    out.push(Piece::Fan([&[bot[nb - 2]], &right[..=d], &[top[1]]].concat()));
}

/// Between top and bottom: fans for the longer side's extra points, split evenly between its
/// two ends, then one quad strip pairing the rest.
fn middle(top: &[[f32; 2]], bot: &[[f32; 2]], out: &mut Vec<Piece>) {
    let (nt, nb) = (top.len(), bot.len());
    let (mut top_left, mut top_right) = (nt - 2, 1);
    let mut bot_left = 1;
    if nt < nb {
        let delta = nb - nt;
        let half = delta / 2;
        bot_left = 1 + half;
        let bot_right = nb - 2 - (delta - half);
        if bot_left > 1 {
            out.push(Piece::Fan([&[top[nt - 2]], &bot[1..=bot_left]].concat()));
        }
        if bot_right < nb - 2 {
            out.push(Piece::Fan([&[top[1]], &bot[bot_right..=nb - 2]].concat()));
        }
    } else if nt > nb {
        let delta = nt - nb;
        let half = delta / 2;
        top_left = nt - 2 - half;
        top_right = 1 + delta - half;
        if top_left < nt - 2 {
            out.push(Piece::Fan([&[bot[1]], &top[top_left..=nt - 2]].concat()));
        }
        if top_right > 1 {
            out.push(Piece::Fan([&[bot[nb - 2]], &top[1..=top_right]].concat()));
        }
    }
    if top_left <= top_right {
        return;
    }
    let strip = (top_right..=top_left).rev().zip(bot_left..).flat_map(|(i, j)| [top[i], bot[j]]).collect();
    out.push(Piece::QuadStrip(strip));
}
