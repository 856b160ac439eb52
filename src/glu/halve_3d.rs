//! GLU's halving of a 3D image, two or more images deep (SGI GLU 9.0 `libutil/mipmap.c`:
//! `halveImage3D` and `halveImageSlice` for the GL 1.1 types, `halveImagePackedPixel3D` and
//! `halveImagePackedPixelSlice` for the packed ones), with its pointer steps and their slips:
//! an odd width or height leaves the next pair of rows or images a pixel or row short; a
//! column of images steps a row, not two images, between its pairs; a packed row or column of
//! images steps two images between its pairs of pixels (see [`super::memory`]).

use super::element::Element;
use super::halve_2d::{halve_packed_2d, mean, Sides, Steps};
use super::packed_pixel::PackedPixel;

/// `halveImage3D`: each 2×2×2 block of components averaged in doubles (a single row, column or
/// column of images through [`halve_slice`]).
pub(super) fn halve_3d(e: Element, components: isize, sides: Sides, src: &[u8], out: &mut [u8], s: Steps, swap: bool) {
    let (width, height, depth) = sides;
    if width == 1 || height == 1 {
        return halve_slice(e, components, sides, src, out, s, swap);
    }
    let row_pad = s.row - width * s.group;
    let image_pad = s.image - width * height * s.group;
    let (mut t, mut k) = (0isize, 0usize);
    for _ in 0..depth / 2 {
        for _ in 0..height / 2 {
            for _ in 0..width / 2 {
                for _ in 0..components {
                    let offsets = [0, s.group, s.row, s.row + s.group];
                    let near = offsets.map(|o| e.extract(src, t + o, swap));
                    let far = offsets.map(|o| e.extract(src, t + o + s.image, swap));
                    let total = near.iter().chain(&far).fold(0.0, |sum, v| sum + v);
                    e.shove(total / 8.0, k, out);
                    k += 1;
                    t += s.element;
                }
                t += s.group;
            }
            t += row_pad + s.row;
        }
        t += image_pad + s.image;
    }
}

/// `halveImageSlice`: a column of images (pairs of images averaged), or a row or column
/// one pixel thick through the images (2×2 blocks of it).
fn halve_slice(e: Element, components: isize, sides: Sides, src: &[u8], out: &mut [u8], s: Steps, swap: bool) {
    let (width, height, depth) = sides;
    let row_pad = s.row - width * s.group;
    let image_pad = s.image - width * height * s.group;
    let (mut t, mut k) = (0isize, 0usize);
    let mut average = |t: isize, offsets: &[isize], k: &mut usize| {
        let total = offsets.iter().fold(0.0, |sum, &o| sum + e.extract(src, t + o, swap));
        e.shove(total / offsets.len() as f64, *k, out);
        *k += 1;
    };
    if width == height {
        for _ in 0..depth / 2 {
            for _ in 0..components {
                average(t, &[0, s.image], &mut k);
                t += s.element;
            }
            t += s.row;
        }
    } else if height == 1 {
        for _ in 0..depth / 2 {
            for _ in 0..width / 2 {
                for _ in 0..components {
                    average(t, &[0, s.group, s.image, s.image + s.group], &mut k);
                    t += s.element;
                }
                t += s.group;
            }
            t += row_pad + s.row;
        }
    } else if width == 1 {
        for _ in 0..depth / 2 {
            for _ in 0..height / 2 {
                for _ in 0..components {
                    average(t, &[0, s.row, s.image, s.image + s.row], &mut k);
                    t += s.element;
                }
                t += row_pad + s.row;
            }
            t += image_pad + s.image;
        }
    }
}

/// `halveImagePackedPixel3D`: packed pixels, each 2×2×2 block averaged in floats (one image
/// deep through [`halve_packed_2d`], a row or column through the images through
/// `halveImagePackedPixelSlice`).
pub(super) fn halve_packed_3d(p: &PackedPixel, sides: Sides, src: &[u8], out: &mut [u8], s: Steps, swap: bool) {
    let (width, height, depth) = sides;
    let (pixel, n) = (s.group, p.components());
    let at = |a: isize| p.extract(src, a, swap);
    if depth == 1 {
        return halve_packed_2d(p, (width, height), src, out, (pixel, s.row), swap);
    }
    let mut index = 0;
    let mut t = 0isize;
    if width == 1 || height == 1 {
        let step = match (width, height) {
            (1, 1) => None,
            (_, 1) => Some(pixel),
            _ => Some(s.row),
        };
        let count = match (width, height) {
            (1, 1) => depth / 2,
            (_, 1) => depth / 2 * (width / 2),
            _ => depth / 2 * (height / 2),
        };
        for _ in 0..count {
            let pixels = match step {
                None => vec![at(t), at(t + s.image)],
                Some(step) => vec![at(t), at(t + step), at(t + s.image), at(t + s.image + step)],
            };
            p.shove(&mean(&pixels, n), index, out);
            index += 1;
            t += 2 * s.image;
        }
        return;
    }
    let pad = s.row - width * pixel;
    for _ in 0..depth / 2 {
        for _ in 0..height / 2 {
            for _ in 0..width / 2 {
                let offsets = [0, pixel, s.row, s.row + pixel];
                let mut pixels: Vec<[f32; 4]> = offsets.iter().map(|&o| at(t + o)).collect();
                pixels.extend(offsets.iter().map(|&o| at(t + o + s.image)));
                p.shove(&mean(&pixels, n), index, out);
                index += 1;
                t += 2 * pixel;
            }
            t += pad + s.row;
        }
        t += s.image;
    }
}
