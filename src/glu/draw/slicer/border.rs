//! The border of an untrimmed patch as GLU samples it: a counter-clockwise loop of four sides
//! (`Subdivider::makeBorderTrim`), each cut into 1 + ⌊length/rate⌋ equal steps at its own
//! rate (`ArcTessellator::pwl_bottom`, `pwl_right`, `pwl_top`, `pwl_left` in
//! `internals/arctess.cc`). The points are accumulated step by step in `f32` from the side's
//! start, and the last is the side's end exactly, as GLU does.

use super::c_int;
use crate::glu::evaluation::sampling::MAX_SEGMENTS;

/// A rectangle of the domain as a loop of four sampled sides, each from its first corner to
/// the next: bottom (u increasing at v0), right (v increasing at u1), top (u decreasing at v1)
/// and left (v decreasing at u0).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct RectLoop {
    pub bottom: Vec<[f32; 2]>,
    pub right: Vec<[f32; 2]>,
    pub top: Vec<[f32; 2]>,
    pub left: Vec<[f32; 2]>,
}

impl RectLoop {
    /// The lower-left corner.
    pub fn min(&self) -> [f32; 2] {
        [self.left[0][0], self.bottom[0][1]]
    }

    /// The upper-right corner.
    pub fn max(&self) -> [f32; 2] {
        [self.right[0][0], self.top[0][1]]
    }
}

/// GLU's `steps_function`: max(1, 1 + (int)((large − small)/rate)), with C's conversion
/// ([`c_int`]: a zero rate gives one step), kept within what can be drawn.
fn steps(large: f32, small: f32, rate: f32) -> usize {
    (1 + c_int((large - small) / rate)).clamp(1, MAX_SEGMENTS as i64) as usize
}

/// An increasing side from `a` to `b` (`pwl_bottom`, `pwl_right`): a + i·step accumulated,
/// then `b` itself.
pub(crate) fn side_up(a: f32, b: f32, rate: f32) -> Vec<f32> {
    let n = steps(b, a, rate);
    let step = (b - a) / n as f32;
    let mut out = Vec::with_capacity(n + 1);
    let mut x = a;
    for _ in 0..n {
        out.push(x);
        x += step;
    }
    out.push(b);
    out
}

/// A decreasing side from `a` down to `b` (`pwl_top`, `pwl_left`): GLU fills it from the end,
/// accumulating from `b` upwards, and puts `a` itself first.
pub(crate) fn side_down(a: f32, b: f32, rate: f32) -> Vec<f32> {
    let n = steps(a, b, rate);
    let step = (a - b) / n as f32;
    let mut out = vec![0.0; n + 1];
    let mut x = b;
    for slot in out[1..].iter_mut().rev() {
        *slot = x;
        x += step;
    }
    out[0] = a;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sides_run_end_to_end_with_exact_ends() {
        let up = side_up(0.0, 1.0, 0.3);
        assert_eq!(up.len(), 5); // 1 + ⌊1/0.3⌋ = 4 steps
        assert_eq!((up[0], up[4]), (0.0, 1.0));
        // 1 + ⌊2/1⌋ = 3 steps (GLU's count takes one more than the length needs), filled
        // upwards from the end.
        let down = side_down(2.0, 0.0, 1.0);
        assert_eq!(down, vec![2.0, 1.3333334, 0.6666667, 0.0]);
    }

    #[test]
    fn a_zero_or_absurd_rate_does_not_panic() {
        assert_eq!(side_up(0.0, 1.0, 0.0).len(), 2);
        assert_eq!(side_up(0.0, 1.0, 1e-9).len(), MAX_SEGMENTS + 1);
        assert_eq!(side_up(0.0, 1.0, f32::NAN).len(), 2);
        assert_eq!(side_down(1.0, 0.0, -1.0).len(), 2);
        assert_eq!(side_down(1.0, 0.0, f32::INFINITY).len(), 2);
    }
}
