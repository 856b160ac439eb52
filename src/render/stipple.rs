//! Line stipple (GL 1.1 spec §3.4.2) as Mesa's llvmpipe draws it: each line is cut into the
//! pieces whose fragments the pattern keeps, and the pieces are drawn as ordinary lines.
//!
//! The counter s advances once per window-space step along the line's major axis: a line of
//! length L = max(|Δx|, |Δy|) pixels takes ⌈L⌉ steps, step i reading bit ⌊(s + i) / factor⌋
//! mod 16 of the pattern; a run of kept steps i0..i1 becomes the piece from i0/L to i1/L of
//! the line (the last run ending at the line's end). s carries on along a strip or loop and
//! restarts with each `glBegin` and with each segment of `GL_LINES` (§3.4.2). Measured on
//! Mesa 22.3 llvmpipe: the counter moves by whole steps (⌈L⌉ per line), not by L. Lines are
//! cut to the view volume first, so a line leaving the viewport counts only its visible part
//! (Mesa clips before stippling too; where its guard band lets a line through unclipped the
//! count may differ).

use super::corner::Corner;

/// The most steps one line takes (GL's largest viewport, Mesa's 16384, along a diagonal, with
/// room to spare).
const MAX_STEPS: f32 = 65536.0;

/// The stipple counter of one primitive.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Stipple {
    counter: u32,
}

impl Stipple {
    /// Restarts the pattern (a new primitive, or a new `GL_LINES` segment).
    pub fn reset(&mut self) {
        self.counter = 0;
    }

    /// The drawn pieces of the line from `a` to `b` (clip coordinates inside the view volume),
    /// in the viewport `[x, y, w, h]`, as corners with w = 1 (cut in window space).
    /// With `euclidean` (smooth lines, drawn as rectangles) L is the Euclidean length.
    pub fn pieces(
        &mut self,
        a: Corner,
        b: Corner,
        viewport: [i32; 4],
        (factor, pattern): (i32, u16),
        euclidean: bool,
    ) -> Vec<(Corner, Corner)> {
        let (a, b) = (projected(a), projected(b));
        let (sx, sy) = (viewport[2] as f32 * 0.5, viewport[3] as f32 * 0.5);
        let (dx, dy) = ((b.clip.x - a.clip.x) * sx, (b.clip.y - a.clip.y) * sy);
        let length = if euclidean { dx.hypot(dy) } else { dx.abs().max(dy.abs()) };
        // The line is inside the view volume, so this bounds only absurd viewports.
        let steps = if length.is_finite() { length.ceil().min(MAX_STEPS) as u32 } else { 0 };
        let factor = factor.max(1) as u32;
        let kept = |i: u32| pattern >> ((self.counter.wrapping_add(i) / factor) % 16) & 1 == 1;
        let mut pieces = Vec::new();
        let mut start = None;
        for i in 0..steps {
            match (kept(i), start) {
                (true, None) => start = Some(i),
                (false, Some(s)) => {
                    pieces.push((a.lerp(b, s as f32 / length), a.lerp(b, i as f32 / length)));
                    start = None;
                }
                _ => {}
            }
        }
        if let Some(s) = start {
            pieces.push((a.lerp(b, s as f32 / length), b));
        }
        self.counter = self.counter.wrapping_add(steps);
        pieces
    }
}

/// The corner with its clip position divided by w (so that interpolation is in window space).
fn projected(c: Corner) -> Corner {
    let w = c.clip.w;
    Corner { clip: c.clip / w, ..c }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec4;

    fn at(x: f32) -> Corner {
        let p = Vec4::new(x, 0.0, 0.0, 1.0);
        Corner {
            clip: p,
            eye: p,
            color: Vec4::ONE,
            secondary: Vec4::ZERO,
            tex: Vec4::ZERO,
            units: [Vec4::ZERO; 7],
            fog: 0.0,
            depth_offset: 0.0,
            aa: Vec4::ZERO,
        }
    }

    /// NDC x of window x in a 64-pixel viewport.
    fn ndc(x: f32) -> f32 {
        x / 32.0 - 1.0
    }

    fn window(c: &Corner) -> f32 {
        (c.clip.x + 1.0) * 32.0
    }

    #[test]
    fn the_counter_moves_by_whole_steps_along_a_strip() {
        // 0x0F0F, factor 1: four on, four off. A strip 0.5 → 10.3 → 30.7 (see the module doc).
        let mut s = Stipple::default();
        let first = s.pieces(at(ndc(0.5)), at(ndc(10.3)), [0, 0, 64, 1], (1, 0x0F0F), false);
        let ends: Vec<(f32, f32)> = first.iter().map(|(p, q)| (window(p), window(q))).collect();
        assert_eq!(ends.len(), 2);
        assert!((ends[0].0 - 0.5).abs() < 1e-4 && (ends[0].1 - 4.5).abs() < 1e-4);
        assert!((ends[1].0 - 8.5).abs() < 1e-4 && (ends[1].1 - 10.3).abs() < 1e-4);
        // Ten steps taken: the next line starts at counter 10, two steps on (10, 11).
        let second = s.pieces(at(ndc(10.3)), at(ndc(30.7)), [0, 0, 64, 1], (1, 0x0F0F), false);
        assert!((window(&second[0].1) - 12.3).abs() < 1e-3, "{}", window(&second[0].1));
        s.reset();
        let again = s.pieces(at(ndc(10.3)), at(ndc(30.7)), [0, 0, 64, 1], (1, 0x0F0F), false);
        assert!((window(&again[0].1) - 14.3).abs() < 1e-3);
    }
}
