//! The CPU rasteriser's buffers, and GL's per-fragment operations after the fragment's colour
//! is known: the stencil test (GL 1.1 spec §4.1.4), the depth test (§4.1.5), blending
//! (§4.1.6), the logic op (§4.1.7) and the write masks (§4.2.2), on RGBA8 front and back
//! colour buffers, a 32-bit float depth buffer (as the wgpu target has them) and an 8-bit
//! stencil buffer. Clears honour the scissor box and the masks (§4.2.3); the accumulation
//! buffer is `accum.rs`'s.

use super::ops::{blend, logic_op, stencil_op, to_unorm8};
use crate::gl::consts::*;
use crate::gl::fragments::{FragmentTests, Stencil, BACK_BUFFER, FRONT_BUFFER};
use crate::gl::types::GLenum;
use crate::render::Image;

/// The buffers, one value a pixel, rows top to bottom.
#[derive(Clone)]
pub(super) struct Framebuffer {
    pub width: u32,
    pub height: u32,
    /// The front colour buffer: a single-buffered context's only one.
    front: Vec<[u8; 4]>,
    /// The back colour buffer, made when a double-buffered context first reaches it.
    back: Option<Vec<[u8; 4]>>,
    /// Whether the front buffer holds the picture: something was drawn into it or swapped to
    /// it since the back buffer came into use.
    front_shown: bool,
    depth: Vec<f32>,
    stencil: Vec<u8>,
    /// The accumulation buffer (Mesa's `RGBA_SNORM16`), made at its first use.
    pub accum: Option<Vec<[i16; 4]>>,
    /// The frame's occlusion query slots: samples that passed the depth and stencil tests
    /// while each was counting (GL 1.5 §4.1.6; [`crate::gl::Command::Query`]).
    pub samples: Vec<u64>,
    /// The slot counting now.
    pub counting: Option<usize>,
}

/// One colour write: the fragment's colour and how it meets the buffer's.
#[derive(Clone, Copy)]
pub(super) struct ColorWrite {
    pub color: [f32; 4],
    pub blend: Option<crate::gl::Blend>,
    pub tests: FragmentTests,
}

impl Framebuffer {
    /// A new buffer as a new OSMesa context has it: transparent black, depth 1, stencil 0.
    pub fn new(width: u32, height: u32) -> Self {
        let n = width as usize * height as usize;
        Self {
            width,
            height,
            front: vec![[0; 4]; n],
            back: None,
            front_shown: true,
            depth: vec![1.0; n],
            stencil: vec![0; n],
            accum: None,
            samples: Vec::new(),
            counting: None,
        }
    }

    /// A fragment passed the depth and stencil tests: the counting query's slot counts it.
    pub fn count_sample(&mut self) {
        if let Some(slot) = self.counting {
            if self.samples.len() <= slot {
                self.samples.resize(slot + 1, 0);
            }
            self.samples[slot] += 1;
        }
    }

    /// The colour buffer `bit` names (the back one made on first use, transparent black).
    pub fn color_mut(&mut self, bit: u8) -> &mut Vec<[u8; 4]> {
        if bit == BACK_BUFFER {
            if self.back.is_none() {
                self.front_shown = false;
            }
            let n = self.front.len();
            return self.back.get_or_insert_with(|| vec![[0; 4]; n]);
        }
        self.front_shown = true;
        &mut self.front
    }

    /// The colour buffer `bit` names, to read (the front one if the back does not exist).
    pub fn color(&self, bit: u8) -> &[[u8; 4]] {
        match (&self.back, bit) {
            (Some(back), BACK_BUFFER) => back,
            _ => &self.front,
        }
    }

    /// The buffer bits of `draw_buffers`, one at a time.
    pub fn buffers(draw_buffers: u8) -> impl Iterator<Item = u8> {
        [FRONT_BUFFER, BACK_BUFFER].into_iter().filter(move |b| draw_buffers & b != 0)
    }

    /// The pixels of `rect` (`[x0, top, x1, bottom]`, rows top to bottom, ends exclusive).
    pub fn indices(&self, [x0, top, x1, bottom]: [u32; 4]) -> impl Iterator<Item = usize> {
        let w = self.width as usize;
        (top as usize..bottom as usize).flat_map(move |y| (x0 as usize..x1 as usize).map(move |x| y * w + x))
    }

    /// `glClear` within `rect` (the scissor box): colour through the colour mask into the draw
    /// buffers, depth if depth writes are on, stencil through the stencil mask.
    pub fn clear(
        &mut self,
        rect: [u32; 4],
        (color, depth, stencil): (Option<[f32; 4]>, Option<f32>, Option<i32>),
        tests: &FragmentTests,
    ) {
        let pixels: Vec<usize> = self.indices(rect).collect();
        if let Some(c) = color {
            let value = c.map(to_unorm8);
            for bit in Self::buffers(tests.draw_buffers) {
                let buffer = self.color_mut(bit);
                for &i in &pixels {
                    buffer[i] = masked(value, buffer[i], tests.color_write);
                }
            }
        }
        if let Some(d) = depth.filter(|_| tests.depth_write) {
            pixels.iter().for_each(|&i| self.depth[i] = d.clamp(0.0, 1.0));
        }
        if let Some(s) = stencil {
            let mask = tests.stencil_write_mask as u8;
            pixels.iter().for_each(|&i| self.stencil[i] = (self.stencil[i] & !mask) | (s as u8 & mask));
        }
    }

    /// `glutSwapBuffers`: the back buffer becomes the front one (its contents stay, as Mesa's
    /// software swap copies them).
    pub fn swap(&mut self) {
        if let Some(back) = &self.back {
            self.front.clone_from(back);
        }
        self.front_shown = true;
    }

    /// GL's depth test for pixel `index` at depth `z`: whether the fragment survives. `None`
    /// is `GL_DEPTH_TEST` disabled: no test and no write.
    pub fn depth_passes(&self, index: usize, z: f32, test: Option<GLenum>) -> bool {
        test.is_none_or(|func| compare(func, z, self.depth[index]))
    }

    /// `glCopyPixels(GL_STENCIL)`: the stencil values of `copy`'s source rectangle (all read
    /// before any is written) written where the zoomed rectangle lands inside `rect` (the scissor
    /// box), through the stencil write mask. As Mesa 22.3 on llvmpipe does (measured with an
    /// OSMesa program): the stencil and depth tests do not apply, nor do the index shift, offset
    /// and `GL_MAP_STENCIL`, which GL 1.1 §4.3.3 would apply; sources outside the window are not
    /// copied.
    pub fn copy_stencil(&mut self, copy: &crate::gl::PixelCopy, rect: [u32; 4], write_mask: u32) {
        let [sx, sy, w, h] = copy.source;
        let (Ok(w), Ok(h)) = (usize::try_from(w), usize::try_from(h)) else { return };
        let (width, height) = (i64::from(self.width), i64::from(self.height));
        let index = |x: i64, y: i64| ((height - 1 - y) * width + x) as usize;
        let inside = |x: i64, y: i64| (0..width).contains(&x) && (0..height).contains(&y);
        let mut writes = Vec::new();
        let size = (self.width, self.height);
        for ((i, j), (x, y)) in crate::gl::pixel_zoom::zoomed_pixels(copy.origin, copy.zoom, (w, h), size) {
            let (px, py) = (i64::from(sx) + i as i64, i64::from(sy) + j as i64);
            let top = self.height - 1 - y;
            let in_rect = (rect[0]..rect[2]).contains(&x) && (rect[1]..rect[3]).contains(&top);
            let value = match &copy.stencil_values {
                // glDrawPixels' values: the whole image, wherever it came from.
                Some(values) => values.get(j * w + i).copied(),
                None => inside(px, py).then(|| self.stencil[index(px, py)]),
            };
            if let (true, Some(value)) = (in_rect, value) {
                writes.push((index(i64::from(x), i64::from(y)), value));
            }
        }
        let mask = write_mask as u8;
        for (at, value) in writes {
            self.stencil[at] = (self.stencil[at] & !mask) | (value & mask);
        }
    }

    /// GL's stencil test at pixel `index`: the reference (clamped to the 8-bit range) against
    /// the stored value, both ANDed with the value mask.
    pub fn stencil_passes(&self, index: usize, s: &Stencil) -> bool {
        let mask = s.value_mask & 0xFF;
        let reference = s.reference.clamp(0, 255) as u32 & mask;
        let stored = u32::from(self.stencil[index]) & mask;
        compare(s.func, reference as f32, stored as f32)
    }

    /// Applies stencil operation `op` at pixel `index` through the write mask.
    pub fn stencil_update(&mut self, index: usize, s: &Stencil, op: GLenum) {
        let old = self.stencil[index];
        let new = stencil_op(op, old, s.reference.clamp(0, 255) as u8);
        let mask = s.write_mask as u8;
        self.stencil[index] = (old & !mask) | (new & mask);
    }

    /// Writes a fragment that passed every test: its depth (`write_depth`: testing with depth
    /// writes on) and its colour into each draw buffer, blended or through the logic op, and
    /// through the colour mask.
    pub fn write(&mut self, index: usize, z: f32, write_depth: bool, w: &ColorWrite) {
        if write_depth {
            self.depth[index] = z;
        }
        let source = w.color.map(|c| c.clamp(0.0, 1.0));
        for bit in Self::buffers(w.tests.draw_buffers) {
            let buffer = self.color_mut(bit);
            let dest = buffer[index];
            let out = match (w.tests.logic_op, &w.blend) {
                (Some(op), _) => {
                    let s = source.map(to_unorm8);
                    std::array::from_fn(|k| logic_op(op, s[k], dest[k]))
                }
                (None, None) => source.map(to_unorm8),
                (None, Some(b)) => blend(b, source, dest.map(|c| f32::from(c) / 255.0)).map(to_unorm8),
            };
            buffer[index] = masked(out, dest, w.tests.color_write);
        }
    }

    /// The picture: the front buffer, or a double-buffered context's back buffer while nothing
    /// was drawn into the front or swapped to it (a headless frame that never swapped).
    fn shown(&self) -> &[[u8; 4]] {
        match (&self.back, self.front_shown) {
            (Some(back), false) => back,
            _ => &self.front,
        }
    }

    /// The picture as an [`Image`].
    pub fn into_image(self) -> Image {
        self.image()
    }

    /// A copy of the picture (the buffer [`Framebuffer::image`] shows) and the depth buffer:
    /// what `glReadPixels` and `glCopyPixels` read.
    pub fn window_image(&self) -> crate::gl::WindowImage {
        let color = self.shown().iter().flatten().copied().collect();
        let samples = self.samples.clone();
        crate::gl::WindowImage { width: self.width, height: self.height, color, depth: self.depth.clone(), samples }
    }

    /// A copy of the colour buffer `bit` names (the front one if the back does not exist) and
    /// the depth buffer.
    pub fn buffer_image(&self, bit: u8) -> crate::gl::WindowImage {
        let color = self.color(bit).iter().flatten().copied().collect();
        let samples = self.samples.clone();
        crate::gl::WindowImage { width: self.width, height: self.height, color, depth: self.depth.clone(), samples }
    }

    /// A copy of the picture as an [`Image`].
    pub fn image(&self) -> Image {
        Image { width: self.width, height: self.height, pixels: self.shown().iter().flatten().copied().collect() }
    }

    /// The stencil buffer, rows top to bottom.
    pub fn stencil(&self) -> &[u8] {
        &self.stencil
    }
}

/// `value` where the colour mask lets a channel through, `old` elsewhere.
fn masked(value: [u8; 4], old: [u8; 4], mask: [bool; 4]) -> [u8; 4] {
    std::array::from_fn(|k| if mask[k] { value[k] } else { old[k] })
}

/// GL's comparison functions (the depth test's, §4.1.5, the stencil test's, §4.1.4, and the
/// alpha test's, §4.1.3): whether `value` passes against `reference` under `func`.
pub(super) fn compare(func: GLenum, value: f32, reference: f32) -> bool {
    match func {
        GL_NEVER => false,
        GL_LESS => value < reference,
        GL_EQUAL => value == reference,
        GL_LEQUAL => value <= reference,
        GL_GREATER => value > reference,
        GL_NOTEQUAL => value != reference,
        GL_GEQUAL => value >= reference,
        _ => true,
    }
}
