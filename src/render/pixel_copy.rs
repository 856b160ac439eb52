//! `glCopyPixels` on a rasteriser: at its place in the frame ([`super::Op::CopyPixels`]) the
//! rasteriser reads its own buffers into a [`WindowImage`], and the copy's fragments (GL's rules:
//! `gl::PixelCopy::fragments`) become one-pixel points at their pixel centres, drawn as a batch
//! with the copy's depth test, blending and alpha test like any other. Both rasterisers do
//! exactly this, so their copies agree wherever their reads do.

use super::assemble::{Batch, RasterVertex, Topology};
use crate::gl::{PixelCopy, WindowImage};

/// The points `copy` draws into `window` (read from it), in the clip space of a viewport
/// covering the whole window, depth already in [0, 1].
#[must_use]
pub fn copy_vertices(copy: &PixelCopy, window: &WindowImage) -> Vec<RasterVertex> {
    let (w, h) = (window.width.max(1) as f32, window.height.max(1) as f32);
    copy.fragments(window)
        .iter()
        .map(|f| {
            let [x, y] = f.pixel.map(|c| c as f32 + 0.5);
            RasterVertex {
                clip: [2.0 * x / w - 1.0, 2.0 * y / h - 1.0, f.depth, 1.0],
                color: f.color,
                ..Default::default()
            }
        })
        .collect()
}

/// The batch that draws `count` copy points from vertex `first` on, with `template`'s depth
/// test, blending and fragment operations, over the whole `window`.
#[must_use]
pub fn copy_batch(template: &Batch, window: &WindowImage, first: u32, count: u32) -> Batch {
    let viewport = [0, 0, window.width as i32, window.height as i32];
    Batch { viewport, topology: Topology::Points, first, count, ..*template }
}
