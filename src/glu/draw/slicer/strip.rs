//! A rectangle with inner grid lines in both directions (GLU `triangulateRectGen`,
//! `triangulateRectTopGen` and `triangulateRectCenter` in `internals/slicer.cc`): the four
//! sides are joined to the outermost inner lines by fans (`evalUStrip`/`evalVStrip` in
//! `interface/glsurfeval.cc`), top, bottom, left, right in that order, then the inner lines
//! form one grid block.

use super::border::RectLoop;
use super::{Grid, Piece};

/// The pieces of `rect` with `nu` inner lines across u and `nv` across v (both at least 1).
pub(super) fn triangulate_with_grid(rect: &RectLoop, nu: usize, nv: usize) -> Vec<Piece> {
    let ([u0, v0], [u1, v1]) = (rect.min(), rect.max());
    let us = inner_lines(u0, u1, nu);
    let vs = inner_lines(v0, v1, nv);
    let (u_first, u_last) = (us[0], us[nu - 1]);
    let (v_first, v_last) = (vs[0], vs[nv - 1]);
    let along_u = |line: &[[f32; 2]]| line.iter().map(|p| p[0]).collect::<Vec<f32>>();
    let along_v = |line: &[[f32; 2]]| line.iter().map(|p| p[1]).collect::<Vec<f32>>();
    let at_v = |v: f32| move |a: f32| [a, v];
    let at_u = |u: f32| move |a: f32| [u, a];
    let mut out = Vec::new();
    let top: Vec<f32> = along_u(&rect.top).into_iter().rev().collect();
    fans_between((&top, at_v(rect.top[0][1])), (&us, at_v(v_last)), &mut out);
    fans_between((&us, at_v(v_first)), (&along_u(&rect.bottom), at_v(rect.bottom[0][1])), &mut out);
    let left: Vec<f32> = along_v(&rect.left).into_iter().rev().collect();
    fans_between((&left, at_u(rect.left[0][0])), (&vs, at_u(u_first)), &mut out);
    fans_between((&vs, at_u(u_last)), (&along_v(&rect.right), at_u(rect.right[0][0])), &mut out);
    if nu > 1 && nv > 1 {
        out.push(Piece::Grid(Grid { u: (u_first, u_last), nu: nu - 1, v: (v_last, v_first), nv: nv - 1 }));
    }
    out
}

/// `n` lines strictly inside [a, b], n + 1 equal steps accumulated from `a` in `f32`.
fn inner_lines(a: f32, b: f32, n: usize) -> Vec<f32> {
    let step = (b - a) / (n as f32 + 1.0);
    let mut x = a + step;
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        out.push(x);
        x += step;
    }
    out
}

/// Fans joining two parallel sampled lines, both increasing along the line, swept from the
/// low end (GLU `evalUStrip`; `evalVStrip` is the same with u and v exchanged). `first` is the
/// upper line of a u strip or the left line of a v strip; each line comes with the map from a
/// value along it to (u, v). Each fan has one vertex on one line and the run of the other
/// line's points it sees, listed backwards where GLU lists them so "for two-side lighting".
fn fans_between<F: Fn(f32) -> [f32; 2], G: Fn(f32) -> [f32; 2]>(
    (a, pa): (&[f32], F),
    (b, pb): (&[f32], G),
    out: &mut Vec<Piece>,
) {
    let (n, m) = (a.len(), b.len());
    if n == 0 || m == 0 {
        return;
    }
    let (mut i, mut j, mut lowest) = if a[0] <= b[0] { (1, 0, pa(a[0])) } else { (0, 1, pb(b[0])) };
    loop {
        if i >= n {
            if j + 1 < m {
                let mut fan = vec![lowest];
                fan.extend(b[j..].iter().map(|&x| pb(x)));
                out.push(Piece::Fan(fan));
            }
            return;
        }
        if j >= m {
            if i + 1 < n {
                let mut fan = vec![lowest];
                fan.extend(a[i..].iter().rev().map(|&x| pa(x)));
                out.push(Piece::Fan(fan));
            }
            return;
        }
        if a[i] <= b[j] {
            // The run of `a` up to b[j], fanned around b[j].
            let k = i + a[i..].iter().take_while(|&&x| x <= b[j]).count() - 1;
            let mut fan = vec![pb(b[j])];
            fan.extend(a[i..=k].iter().rev().map(|&x| pa(x)));
            fan.push(lowest);
            out.push(Piece::Fan(fan));
            i = k + 1;
            lowest = pa(a[k]);
        } else {
            // The run of `b` below a[i], fanned around a[i].
            let mut fan = vec![pa(a[i]), lowest];
            let k = j + b[j..].iter().take_while(|&&x| x < a[i]).count();
            fan.extend(b[j..k].iter().map(|&x| pb(x)));
            out.push(Piece::Fan(fan));
            j = k;
            lowest = pb(b[j - 1]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fans(a: &[f32], b: &[f32]) -> Vec<Piece> {
        let mut out = Vec::new();
        fans_between((a, |x| [x, 1.0]), (b, |x| [x, 0.0]), &mut out);
        out
    }

    #[test]
    fn a_coarse_line_over_a_fine_one_makes_fans_around_the_coarse_points() {
        // GLU's first fan of a 12-point top side over 53 inner lines starts at the top's
        // second point, then the corner, then the inner points below it.
        let out = fans(&[0.0, 0.5, 1.0], &[0.2, 0.4, 0.6, 0.8]);
        assert_eq!(out[0], Piece::Fan(vec![[0.5, 1.0], [0.0, 1.0], [0.2, 0.0], [0.4, 0.0]]));
        // 0.5 lies below 0.6: a fan round the lower point, back over the upper run.
        assert_eq!(out[1], Piece::Fan(vec![[0.6, 0.0], [0.5, 1.0], [0.4, 0.0]]));
        assert_eq!(out[2], Piece::Fan(vec![[1.0, 1.0], [0.5, 1.0], [0.6, 0.0], [0.8, 0.0]]));
        assert_eq!(out.len(), 3);
    }

    #[test]
    fn triangles_cover_the_band_once() {
        // Every fan of n vertices is n − 2 triangles; the band between lines of 3 and 4 points
        // has (3 − 1) + (4 − 1) triangles.
        let tri: usize = fans(&[0.0, 0.5, 1.0], &[0.2, 0.4, 0.6, 0.8])
            .iter()
            .map(|p| match p {
                Piece::Fan(v) => v.len() - 2,
                _ => 0,
            })
            .sum();
        assert_eq!(tri, 5);
    }
}
