//! `glGetPolygonStipple` (GL 1.1 spec §6.1.5; Mesa `_mesa_GetPolygonStipple`): the 32 × 32
//! mask packed into client memory as `glReadPixels` packs a bitmap, with the pack modes
//! (alignment, row length, skipped rows and pixels, bit order), first row at the bottom.

use super::consts::*;
use super::types::*;
use super::Gl;

impl Gl {
    /// Bytes `glGetPolygonStipple` writes under the current pack modes.
    #[must_use]
    pub fn polygon_stipple_len(&self) -> usize {
        let store = self.client.pixel_stores.pack;
        let stride = store.bitmap_row_stride(32);
        store.skip_rows * stride + 31 * stride + (store.skip_pixels + 32).div_ceil(8)
    }

    /// `glGetPolygonStipple(mask)`: writes the mask's bits, leaving the padding and skipped bytes
    /// as they were. A `mask` shorter than [`Gl::polygon_stipple_len`] → `GL_INVALID_VALUE`;
    /// inside `begin`/`end` → `GL_INVALID_OPERATION`. Not compiled into lists.
    pub fn get_polygon_stipple(&mut self, mask: &mut [GLubyte]) {
        if self.reject_inside_begin_end() {
            return;
        }
        if mask.len() < self.polygon_stipple_len() {
            return self.set_error(GL_INVALID_VALUE);
        }
        let store = self.client.pixel_stores.pack;
        let stride = store.bitmap_row_stride(32);
        for (y, row) in self.server.polygon_stipple.iter().enumerate() {
            // Mesa packs each row into a cleared buffer and copies its bytes: the skipped bits
            // of the first byte and the unused bits of the last are written as 0.
            let start = (store.skip_rows + y) * stride;
            mask[start + store.skip_pixels / 8..start + (store.skip_pixels + 32).div_ceil(8)].fill(0);
            for x in 0..32 {
                let b = store.skip_pixels + x;
                let byte = &mut mask[(store.skip_rows + y) * stride + b / 8];
                let bit = if store.lsb_first { 1 << (b % 8) } else { 0x80 >> (b % 8) };
                if row >> x & 1 != 0 {
                    *byte |= bit;
                } else {
                    *byte &= !bit;
                }
            }
        }
    }
}
