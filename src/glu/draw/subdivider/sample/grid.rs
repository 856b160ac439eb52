//! The grid a region is sampled on and the grid points just inside its left and right
//! chains (`nurbtess/gridWrap.cc`: `gridWrap`, `gridBoundaryChain`; `findLeftGridIndices`
//! and `findRightGridIndices` of `sampleMonoPoly.cc`).

use super::{c_int, Poly, Pt, Stream, ZERO};

/// GLU `gridWrap`: `n_u` lines across u and `n_v` across v, accumulated in `f32` from the
/// minimum, the last line the maximum exactly.
pub(crate) struct GridWrap {
    pub u_min: f32,
    pub u_max: f32,
    pub v_min: f32,
    pub v_max: f32,
    pub u: Vec<f32>,
    pub v: Vec<f32>,
}

fn lines(min: f32, max: f32, n: usize) -> Vec<f32> {
    let d = (max - min) / (n as f32 - 1.0);
    let mut out = Vec::with_capacity(n);
    let mut x = min;
    out.push(x);
    for _ in 1..n {
        x += d;
        out.push(x);
    }
    out[n - 1] = max;
    out
}

impl GridWrap {
    pub fn new(n_u: usize, n_v: usize, u: (f32, f32), v: (f32, f32)) -> Self {
        Self { u_min: u.0, u_max: u.1, v_min: v.0, v_max: v.1, u: lines(u.0, u.1, n_u), v: lines(v.0, v.1, n_v) }
    }

    /// Line `i` across u, NaN outside the grid (marked by the caller's checks).
    pub fn u_at(&self, i: i64) -> f32 {
        usize::try_from(i).ok().and_then(|i| self.u.get(i)).copied().unwrap_or(f32::NAN)
    }

    pub fn v_at(&self, j: i64) -> f32 {
        usize::try_from(j).ok().and_then(|j| self.v.get(j)).copied().unwrap_or(f32::NAN)
    }

    /// GLU `gridWrap::outputFanWithPoint`: a fan from `vert` over grid line `v` between
    /// `uleft` and `uright`, turned counter-clockwise.
    pub fn fan_with_point(&self, v: i64, uleft: i64, uright: i64, vert: Pt, s: &mut Stream) {
        if uleft >= uright {
            return;
        }
        let mut fan = vec![vert];
        if vert[1] > self.v_at(v) {
            fan.extend((uleft..=uright).map(|i| [self.u_at(i), self.v_at(v)]));
        } else {
            fan.extend((uleft..=uright).rev().map(|i| [self.u_at(i), self.v_at(v)]));
        }
        s.fan(fan);
    }
}

/// GLU `gridBoundaryChain`: on consecutive v lines from `first` downwards, the grid point at
/// the region's left (or right) end and the inner index that bounds the block of quads.
pub(crate) struct BoundaryChain<'g> {
    pub grid: &'g GridWrap,
    pub first: i64,
    pub uline: Vec<i64>,
    pub inner: Vec<i64>,
    pub vertices: Vec<Pt>,
}

impl<'g> BoundaryChain<'g> {
    pub fn new(grid: &'g GridWrap, first: i64, uline: Vec<i64>, inner: Vec<i64>) -> Self {
        let vertices = uline.iter().enumerate().map(|(i, &u)| [grid.u_at(u), grid.v_at(first - i as i64)]).collect();
        Self { grid, first, uline, inner, vertices }
    }

    pub fn n(&self) -> i64 {
        self.uline.len() as i64
    }

    fn get<T: Copy>(v: &[T], i: i64, bad: T) -> T {
        usize::try_from(i).ok().and_then(|i| v.get(i)).copied().unwrap_or(bad)
    }

    pub fn vertex(&self, i: i64) -> Pt {
        Self::get(&self.vertices, i, [f32::NAN; 2])
    }

    pub fn v(&self, i: i64) -> f32 {
        self.vertex(i)[1]
    }

    pub fn u(&self, i: i64) -> f32 {
        self.vertex(i)[0]
    }

    pub fn uline(&self, i: i64) -> i64 {
        Self::get(&self.uline, i, 0)
    }

    pub fn inner(&self, i: i64) -> i64 {
        Self::get(&self.inner, i, 0)
    }

    pub fn vline(&self, i: i64) -> i64 {
        self.first - i
    }

    /// GLU `gridBoundaryChain::lookfor`: bisection for the line just above v.
    pub fn lookfor(&self, v: f32, mut i1: i64, mut i2: i64) -> i64 {
        while i1 < i2 - 1 {
            let mid = (i1 + i2) / 2;
            if v > self.v(mid) {
                i2 = mid;
            } else {
                i1 = mid;
            }
        }
        i1
    }

    /// GLU `gridBoundaryChain::leftEndFan`: the stair between lines i-1 and i at the left.
    pub fn left_end_fan(&self, i: i64, s: &mut Stream) {
        let (a, b) = (self.uline(i - 1), self.uline(i));
        if b < a {
            let mut fan = vec![self.vertex(i - 1)];
            fan.extend((b..=a).map(|j| [self.grid.u_at(j), self.v(i)]));
            s.fan(fan);
        } else if b > a {
            let mut fan = vec![self.vertex(i)];
            fan.extend((a..=b).rev().map(|j| [self.grid.u_at(j), self.v(i - 1)]));
            s.fan(fan);
        }
    }

    /// GLU `gridBoundaryChain::rightEndFan`.
    pub fn right_end_fan(&self, i: i64, s: &mut Stream) {
        let (a, b) = (self.uline(i - 1), self.uline(i));
        if b > a {
            let mut fan = vec![self.vertex(i - 1)];
            fan.extend((a..=b).map(|j| [self.grid.u_at(j), self.v(i)]));
            s.fan(fan);
        } else if b < a {
            let mut fan = vec![self.vertex(i)];
            fan.extend((b..=a).rev().map(|j| [self.grid.u_at(j), self.v(i - 1)]));
            s.fan(fan);
        }
    }
}

/// GLU `findLeftGridIndices`: for grid lines `first` down to `last`, the first grid point
/// right of the polygon's left chain (walked from the top line `top`) and the inner index.
pub(crate) fn left_indices(poly: &Poly, top: usize, first: i64, last: i64, grid: &GridWrap) -> (Vec<i64>, Vec<i64>) {
    let n_u = grid.u.len() as i64;
    let (u_min, u_max) = (grid.u_min, grid.u_max);
    let (mut indices, mut inner) = (Vec::new(), Vec::new());
    let mut line = top;
    let mut vtail = grid.v_at(first) + 1.0;
    let mut temp_max = u_min;
    let (mut horizontal, mut slope) = (false, 0.0f32);
    let mut guard = 0usize;
    let mut i = first;
    while i >= last {
        let gv = grid.v_at(i);
        if vtail > gv {
            loop {
                vtail = poly.tail(line)[1];
                let above = vtail > gv;
                if !above || guard > 4 * poly.len() + 8 {
                    break;
                }
                guard += 1;
                temp_max = max(temp_max, poly.tail(line)[0]);
                line = poly.next(line);
            }
            let head = poly.head(line);
            horizontal = f64::from((head[1] - vtail).abs()) < ZERO;
            if !horizontal {
                slope = (head[0] - poly.tail(line)[0]) / (head[1] - vtail);
            }
        }
        let (head, tail) = (poly.head(line), poly.tail(line));
        let mut uinterc = if horizontal { max(head[0], tail[0]) } else { slope * (gv - vtail) + tail[0] };
        temp_max = max(temp_max, uinterc);
        if uinterc < u_min && f64::from(uinterc) >= f64::from(u_min) - ZERO {
            uinterc = u_min;
        }
        if uinterc > u_max && f64::from(uinterc) <= f64::from(u_max) + ZERO {
            uinterc = u_max;
        }
        let mut index =
            if uinterc == u_max { n_u - 1 } else { c_int((uinterc - u_min) / (u_max - u_min) * (n_u - 1) as f32) + 1 };
        if index >= n_u {
            index = n_u - 1;
        }
        indices.push(index);
        inner.push(c_int((temp_max - u_min) / (u_max - u_min) * (n_u - 1) as f32) + 1);
        temp_max = uinterc;
        i -= 1;
    }
    (indices, inner)
}

/// GLU `findRightGridIndices`: the same at the right chain, walked backwards from the top.
pub(crate) fn right_indices(poly: &Poly, top: usize, first: i64, last: i64, grid: &GridWrap) -> (Vec<i64>, Vec<i64>) {
    let n_u = grid.u.len() as i64;
    let (u_min, u_max) = (grid.u_min, grid.u_max);
    let (mut indices, mut inner) = (Vec::new(), Vec::new());
    let mut line = poly.prev(top);
    let mut vhead = poly.tail(line)[1];
    let mut temp_min = u_max;
    let mut slope = 0.0f32;
    let mut guard = 0usize;
    let mut i = first;
    while i >= last {
        let gv = grid.v_at(i);
        if vhead >= gv {
            loop {
                vhead = poly.head(line)[1];
                let above = vhead > gv;
                if !above || guard > 4 * poly.len() + 8 {
                    break;
                }
                guard += 1;
                temp_min = min(temp_min, poly.head(line)[0]);
                line = poly.prev(line);
            }
            while poly.head(line)[1] == gv && guard <= 4 * poly.len() + 8 {
                guard += 1;
                line = poly.prev(line);
            }
            let (t, h) = (poly.tail(line), poly.head(line));
            slope = (t[0] - h[0]) / (t[1] - h[1]);
        }
        let h = poly.head(line);
        let mut uinterc = slope * (gv - h[1]) + h[0];
        if uinterc < u_min {
            uinterc = u_min;
        } else if uinterc > u_max {
            uinterc = u_max;
        }
        temp_min = min(temp_min, uinterc);
        let scale = |x: f32| (((x - u_min) / (u_max - u_min)) * (n_u - 1) as f32).ceil();
        indices.push(if uinterc == u_min { 0 } else { c_int(scale(uinterc)) - 1 });
        inner.push(c_int(scale(temp_min)) - 1);
        temp_min = uinterc;
        i -= 1;
    }
    (indices, inner)
}

/// C's `max(a, b)` macro: `(a > b) ? a : b`.
pub(crate) fn max(a: f32, b: f32) -> f32 {
    if a > b {
        a
    } else {
        b
    }
}

/// C's `min(a, b)` macro: `(a > b) ? b : a`.
pub(crate) fn min(a: f32, b: f32) -> f32 {
    if a > b {
        b
    } else {
        a
    }
}
