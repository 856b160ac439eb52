//! GLU's halving of one image, the next level of a 3D mipmap one image deep (SGI GLU 9.0
//! `libutil/mipmap.c`: `halveImage_ubyte` ... `halveImage_float` and their `halve1Dimage_*`
//! for a single row or column, `halveImagePackedPixel` and `halve1DimagePackedPixel`), with
//! its pointer steps: after each pair of pixels it skips a pixel, after each pair of rows the
//! row padding and a row, so an odd width ends each pair of rows one pixel short of the next
//! (as in GLU; see [`super::memory`]).

use super::element::Element;
use super::memory::store;
use super::packed_pixel::PackedPixel;

/// GLU's byte steps through an image: a component, a pixel (group), a row and an image.
#[derive(Clone, Copy, Debug)]
pub(super) struct Steps {
    pub element: isize,
    pub group: isize,
    pub row: isize,
    pub image: isize,
}

/// An image's sides in pixels.
pub(super) type Sides = (isize, isize, isize);

/// `halveImage_<type>`: `src`'s `width`×`height` image of `components` components halved into
/// `out`, each 2×2 block averaged (a row or column through [`halve_1d`]).
pub(super) fn halve_2d(
    e: Element,
    components: isize,
    (width, height): (isize, isize),
    src: &[u8],
    out: &mut [u8],
    steps: Steps,
    swap: bool,
) {
    if width == 1 || height == 1 {
        return halve_1d(e, components, (width, height), src, out, steps, swap);
    }
    let pad = steps.row - width * steps.group;
    let (mut t, mut k) = (0isize, 0usize);
    for _ in 0..height / 2 {
        for _ in 0..width / 2 {
            for _ in 0..components {
                let at = [t, t + steps.group, t + steps.row, t + steps.row + steps.group];
                put(out, k, e.size(), &e.average4(src, at, swap));
                k += 1;
                t += steps.element;
            }
            t += steps.group;
        }
        t += pad + steps.row;
    }
}

/// `halve1Dimage_<type>`: a single row (or column) averaged two pixels at a time.
fn halve_1d(
    e: Element,
    components: isize,
    (width, height): (isize, isize),
    src: &[u8],
    out: &mut [u8],
    steps: Steps,
    swap: bool,
) {
    let (mut t, mut k) = (0isize, 0usize);
    if height == 1 {
        for _ in 0..width / 2 {
            for _ in 0..components {
                put(out, k, e.size(), &e.average2(src, [t, t + steps.group], swap));
                k += 1;
                t += steps.element;
            }
            t += steps.group;
        }
    } else if width == 1 {
        let pad = steps.row - steps.group;
        for _ in 0..height / 2 {
            for _ in 0..components {
                put(out, k, e.size(), &e.average2(src, [t, t + steps.row], swap));
                k += 1;
                t += steps.element;
            }
            t += pad + steps.row;
        }
    }
}

/// Component `k` of the output, `size` bytes of `bytes`.
fn put(out: &mut [u8], k: usize, size: usize, bytes: &[u8; 4]) {
    store(out, k * size, &bytes[..size]);
}

/// The mean of `pixels`' components, summed in floats from 0 in their order.
pub(super) fn mean(pixels: &[[f32; 4]], components: usize) -> [f32; 4] {
    let mut totals = [0.0f32; 4];
    for (c, total) in totals.iter_mut().enumerate().take(components) {
        for p in pixels {
            *total += p[c];
        }
        *total /= pixels.len() as f32;
    }
    totals
}

/// `halveImagePackedPixel`: packed pixels, each 2×2 block averaged in floats (a row or column
/// through `halve1DimagePackedPixel`).
pub(super) fn halve_packed_2d(
    p: &PackedPixel,
    (width, height): (isize, isize),
    src: &[u8],
    out: &mut [u8],
    (pixel, row): (isize, isize),
    swap: bool,
) {
    let n = p.components();
    let at = |a: isize| p.extract(src, a, swap);
    let mut index = 0;
    if width == 1 || height == 1 {
        let (count, step) = if height == 1 { (width / 2, pixel) } else { (height / 2, row) };
        let mut s = 0;
        for _ in 0..count {
            p.shove(&mean(&[at(s), at(s + step)], n), index, out);
            index += 1;
            s += 2 * step;
        }
        return;
    }
    let pad = row - width * pixel;
    let mut s = 0;
    for _ in 0..height / 2 {
        for _ in 0..width / 2 {
            p.shove(&mean(&[at(s), at(s + pixel), at(s + row), at(s + row + pixel)], n), index, out);
            index += 1;
            s += 2 * pixel;
        }
        s += pad + row;
    }
}
