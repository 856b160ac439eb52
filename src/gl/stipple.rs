//! `glPolygonStipple` (GL 1.1 spec §3.5.6): a 32 × 32 bit mask tiled
//! over window coordinates that keeps or drops each fragment of a filled polygon; the raster
//! shader tests it. (`glLineStipple` is the line group's, `line.rs`.)

use super::consts::*;
use super::lists::ListCommand;
use super::pixel_unpack::unpack_bitmap;
use super::types::*;
use super::Gl;

impl Gl {
    /// `glPolygonStipple(mask)`: a 32 × 32 bitmap unpacked as `glBitmap` unpacks (the pixel
    /// store's alignment, skips, row length and bit order; first row at the bottom). A `mask`
    /// shorter than that → `GL_INVALID_VALUE`; inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub fn polygon_stipple(&mut self, mask: &[GLubyte]) {
        let rows = unpack_bitmap(self.unpack_store(), 32, 32, mask).map(|bits| stipple_rows(&bits));
        if self.compiled_state_call(|| ListCommand::PolygonStipple(rows)) {
            return;
        }
        self.set_polygon_stipple(rows);
    }

    /// Sets the unpacked mask (`None`: the client's data was too short).
    pub(crate) fn set_polygon_stipple(&mut self, rows: Option<[u32; 32]>) {
        let Some(rows) = rows else { return self.set_error(GL_INVALID_VALUE) };
        self.server.polygon_stipple = rows;
        self.touch_state();
    }

    /// The mask while `GL_POLYGON_STIPPLE` is on: row y (from the window's bottom, modulo 32)
    /// has bit x set where fragments are kept.
    pub(crate) fn enabled_polygon_stipple(&self) -> Option<[u32; 32]> {
        self.capability(GL_POLYGON_STIPPLE).then_some(self.server.polygon_stipple)
    }
}

/// 32 × 32 unpacked bits as 32 rows of 32 bits, bit x of row y for pixel (x, y).
fn stipple_rows(bits: &[bool]) -> [u32; 32] {
    std::array::from_fn(|y| (0..32).filter(|&x| bits[y * 32 + x]).fold(0u32, |row, x| row | 1 << x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_polygon_mask_is_read_as_a_bitmap() {
        let mut gl = Gl::new(4, 4);
        // Row 0 (the bottom): its first byte 0x80 is pixel 0 (most significant bit first).
        let mut mask = [0u8; 128];
        mask[0] = 0x80;
        mask[4 * 31 + 3] = 0x01;
        gl.polygon_stipple(&mask);
        assert_eq!(gl.server.polygon_stipple[0], 1);
        assert_eq!(gl.server.polygon_stipple[31], 1 << 31);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.polygon_stipple(&mask[..127]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }
}
