//! `gluScaleImage3D`, GLU's own (static) resampling of a 3D image that `gluBuild3DMipmaps`
//! scales to powers of two first (SGI GLU 9.0 `libutil/mipmap.c`: `fillImage3D`,
//! `scaleInternal3D`, `emptyImage3D`): the image read into 16-bit components with the unpack
//! modes in force when it runs, a box filter in floats over the three axes, and the result
//! written with the pack modes, as the 2D `gluScaleImage` of [`super::scale`] does.
//!
//! GLU has by then set the unpack row length, skips and image height to 0 (it skipped to the
//! first pixel itself), so the user's row length and image height are not read here: the
//! image is read as if tightly packed but for the alignment (as GLU does).

use super::element::Element;
use super::memory::{load, store};
use super::packed_pixel::PackedPixel;
use super::scale::{components, coverage, double_to_ushort, empty_element, extent, fill_element, float_to_ushort};
use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::PixelStore;

/// Sides in pixels.
type Sides = (usize, usize, usize);

/// An image's layout under a pixel store (`fillImage3D`'s and `emptyImage3D`'s own
/// arithmetic): the first byte, and bytes a component, row and image.
struct Layout3D {
    start: usize,
    element: usize,
    row: usize,
    image: usize,
}

impl Layout3D {
    fn new(store: &PixelStore, (width, height): (usize, usize), per_pixel: usize, element: usize) -> Self {
        let groups = if store.row_length > 0 { store.row_length } else { width };
        let group = element * per_pixel;
        let mut row = groups * group;
        if row % store.alignment != 0 {
            row += store.alignment - row % store.alignment;
        }
        let rows = if store.image_height > 0 { store.image_height } else { height };
        let image = rows * row;
        let start = store.skip_rows * row + store.skip_pixels * group + store.skip_images * image;
        Self { start, element, row, image }
    }

    /// Each component's first byte, image by image and row by row (`elements` a row).
    fn offsets(&self, (height, depth): (usize, usize), elements: usize) -> impl Iterator<Item = usize> + '_ {
        (0..depth).flat_map(move |d| {
            (0..height).flat_map(move |h| {
                (0..elements).map(move |e| self.start + d * self.image + h * self.row + e * self.element)
            })
        })
    }
}

/// The type's element size and elements a pixel (a packed type is one element).
fn element_layout(format: GLenum, type_: GLenum) -> (usize, usize) {
    match (PackedPixel::of(type_), Element::of(type_)) {
        (Some(p), _) => (p.size, 1),
        (None, Some(e)) => (e.size(), components(format)),
        _ => (1, components(format)),
    }
}

/// `fillImage3D`: the image at `data` as 16-bit components.
fn fill(store: &PixelStore, (w, h, d): Sides, format: GLenum, type_: GLenum, data: &[u8]) -> Vec<u16> {
    let (element, per_pixel) = element_layout(format, type_);
    let layout = Layout3D::new(store, (w, h), per_pixel, element);
    let swap = store.swap_bytes && element > 1;
    let index = matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX);
    let mut out = Vec::with_capacity(w * h * d * components(format));
    for at in layout.offsets((h, d), w * per_pixel) {
        match PackedPixel::of(type_) {
            Some(p) => {
                // extract332 and extract233rev are passed 0, the others the swap flag (which
                // GLU's macros make a little-endian read).
                let c = p.extract(data, at as isize, swap && p.size > 1);
                out.extend(c[..p.components()].iter().map(|&c| float_to_ushort(c * 65535.0)));
            }
            None => {
                let bytes: Vec<u8> = (0..element).map(|k| load::<1>(data, (at + k) as isize)[0]).collect();
                out.push(fill_element(&bytes, type_, swap, index));
            }
        }
    }
    out
}

/// `scaleInternal3D`: the box filter over depth, height and width, in GLU's float arithmetic
/// (no halving shortcut, unlike the 2D filter).
fn scale(n: usize, (wi, hi, di): Sides, data: &[u16], (wo, ho, d_o): Sides) -> Vec<u16> {
    let conv = |a: usize, b: usize| a as f32 / b as f32;
    let (cx, cy, cz) = (conv(wi, wo), conv(hi, ho), conv(di, d_o));
    let mut out = vec![0u16; wo * ho * d_o * n];
    for d in 0..d_o {
        let (lowz, highz) = extent(d, cz, di, d_o);
        let zs = coverage(lowz, highz, di);
        for i in 0..ho {
            let (lowy, highy) = extent(i, cy, hi, ho);
            let ys = coverage(lowy, highy, hi);
            for j in 0..wo {
                let (lowx, highx) = extent(j, cx, wi, wo);
                let xs = coverage(lowx, highx, wi);
                let (mut totals, mut volume) = ([0.0f32; 4], 0.0f32);
                for &(z, zp) in &zs {
                    for &(y, yp) in &ys {
                        for &(x, xp) in &xs {
                            let percent = xp * yp * zp;
                            volume += percent;
                            let base = (x + y * wi + z * wi * hi) * n;
                            for (total, &c) in totals.iter_mut().zip(&data[base..base + n]) {
                                *total += f32::from(c) * percent;
                            }
                        }
                    }
                }
                let at = (j + i * wo + d * wo * ho) * n;
                for (k, total) in totals[..n].iter().enumerate() {
                    out[at + k] = double_to_ushort((f64::from(*total) + 0.5) / f64::from(volume));
                }
            }
        }
    }
    out
}

/// `emptyImage3D`: 16-bit components written into `out` with the pack modes `store`.
fn empty(modes: &PixelStore, (w, h, d): Sides, format: GLenum, type_: GLenum, image: &[u16], out: &mut [u8]) {
    let (element, per_pixel) = element_layout(format, type_);
    let layout = Layout3D::new(modes, (w, h), per_pixel, element);
    let swap = modes.swap_bytes && element > 1;
    let index = matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX);
    let mut values = image.iter();
    for at in layout.offsets((h, d), w * per_pixel) {
        match PackedPixel::of(type_) {
            Some(p) => {
                let mut c = [0.0f32; 4];
                for c in &mut c[..p.components()] {
                    *c = (f64::from(*values.next().unwrap_or(&0)) / 65535.0) as f32;
                }
                let mut bytes = [0u8; 4];
                p.shove(&c, 0, &mut bytes);
                if swap && p.size > 1 {
                    bytes[..p.size].reverse();
                }
                store(out, at, &bytes[..p.size]);
            }
            None => {
                let mut bytes = [0u8; 4];
                empty_element(*values.next().unwrap_or(&0), &mut bytes[..element], type_, swap, index);
                store(out, at, &bytes[..element]);
            }
        }
    }
}

/// `gluScaleImage3D` as `gluBuild3DMipmapLevelsCore` calls it: `data` (`sides_in` of `format`
/// and `type_`, read with `unpack`) resampled to `sides_out` into `out` (written with `pack`).
pub(super) fn scale_image_3d(
    (unpack, pack): (&PixelStore, &PixelStore),
    format: GLenum,
    type_: GLenum,
    (sides_in, data): (Sides, &[u8]),
    (sides_out, out): (Sides, &mut [u8]),
) {
    let before = fill(unpack, sides_in, format, type_, data);
    let after = scale(components(format), sides_in, &before, sides_out);
    empty(pack, sides_out, format, type_, &after, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn doubling_repeats_and_halving_averages() {
        let store = PixelStore { alignment: 1, ..PixelStore::default() };
        // One byte component, 2×1×1 to 4×1×1: each box is a pixel wide, centred at 0.25, 0.75,
        // 1.25 and 1.75, and wraps (as GLU's does): (257·200·0.25 + 257·10·0.75 + 0.5) = 14778
        // → 57, and 257·(10·0.25 + 200·0.75) + 0.5 = 39193 → 153.
        let mut out = [0u8; 4];
        scale_image_3d(
            (&store, &store),
            GL_LUMINANCE,
            GL_UNSIGNED_BYTE,
            ((2, 1, 1), &[10, 200]),
            ((4, 1, 1), &mut out),
        );
        assert_eq!(out, [57, 57, 153, 153]);
        // 1×1×2 to 1×1×1: (257·10 + 257·30 + 0.5) / 2 = 5140 → 5140 >> 8 = 20.
        let mut out = [0u8; 1];
        scale_image_3d((&store, &store), GL_LUMINANCE, GL_UNSIGNED_BYTE, ((1, 1, 2), &[10, 30]), ((1, 1, 1), &mut out));
        assert_eq!(out, [20]);
    }
}
