//! `gluScaleImage` (GLU 1.3 §3.1; SGI GLU 9.0 `libutil/mipmap.c`: `fill_image`,
//! `scale_internal`, `empty_image`), bit for bit as real GLU 9.0.2 computes it
//! (`tests/reference/glu/scale_image.c` compares every format with every pair of the GL 1.1
//! types, under several pixel-store modes).
//!
//! GLU reads the image with the unpack modes into 16-bit components (`fill_image`: a byte
//! times 257, a signed byte times 516, an int shifted right 15, a float times 65535, ...),
//! resamples it with a box filter in floats (`scale_internal`, or an exact 2×2 average when
//! both sides halve), and writes it with the pack modes (`empty_image`: the top bits of each
//! component, or a float divided by 65535). Index formats (`GL_COLOR_INDEX`,
//! `GL_STENCIL_INDEX`) keep their values instead of scaling them.

use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;
use crate::glu::consts::*;

/// The formats GLU takes (`legalFormat`).
pub(super) fn legal_format(format: GLenum) -> bool {
    matches!(
        format,
        GL_COLOR_INDEX
            | GL_STENCIL_INDEX
            | GL_DEPTH_COMPONENT
            | GL_RED
            | GL_GREEN
            | GL_BLUE
            | GL_ALPHA
            | GL_RGB
            | GL_RGBA
            | GL_LUMINANCE
            | GL_LUMINANCE_ALPHA
            | GL_BGR
            | GL_BGRA
    )
}

/// GL 1.2's packed types, which GLU takes (`legalType`) but gleval's `gluScaleImage` does not
/// convert yet: they answer `GLU_INVALID_ENUM` (after GLU's own format check).
pub(super) fn packed(type_: GLenum) -> bool {
    (GL_UNSIGNED_BYTE_3_3_2..=GL_UNSIGNED_INT_10_10_10_2).contains(&type_)
        || (GL_UNSIGNED_BYTE_2_3_3_REV..=GL_UNSIGNED_INT_2_10_10_10_REV).contains(&type_)
}

/// `isLegalFormatForPackedPixelType`: 3_3_2 and 5_6_5 (and their reverses) are RGB only, the
/// other packed types RGBA or BGRA only.
pub(super) fn packed_format_ok(format: GLenum, type_: GLenum) -> bool {
    match type_ {
        GL_UNSIGNED_BYTE_3_3_2 | GL_UNSIGNED_BYTE_2_3_3_REV | GL_UNSIGNED_SHORT_5_6_5 | GL_UNSIGNED_SHORT_5_6_5_REV => {
            format == GL_RGB
        }
        t if packed(t) => matches!(format, GL_RGBA | GL_BGRA),
        _ => true,
    }
}

/// The GL 1.1 types GLU converts here (`legalType`, packed types aside).
pub(super) fn legal_type(type_: GLenum) -> bool {
    matches!(
        type_,
        GL_BITMAP | GL_BYTE | GL_UNSIGNED_BYTE | GL_SHORT | GL_UNSIGNED_SHORT | GL_INT | GL_UNSIGNED_INT | GL_FLOAT
    )
}

/// `elements_per_group`: components a pixel of `format` has.
pub(crate) fn components(format: GLenum) -> usize {
    match format {
        GL_RGB | GL_BGR => 3,
        GL_LUMINANCE_ALPHA => 2,
        GL_RGBA | GL_BGRA => 4,
        _ => 1,
    }
}

/// Bytes per component of a type (`bytes_per_element`), 0 for `GL_BITMAP`.
fn element_size(type_: GLenum) -> usize {
    match type_ {
        GL_UNSIGNED_BYTE | GL_BYTE => 1,
        GL_UNSIGNED_SHORT | GL_SHORT => 2,
        GL_BITMAP => 0,
        _ => 4,
    }
}

/// The pixel-store modes GLU reads with `glGetIntegerv` (`retrieveStoreModes`), one direction.
pub(super) struct PixelStore {
    swap_bytes: bool,
    lsb_first: bool,
    row_length: usize,
    skip_rows: usize,
    skip_pixels: usize,
    alignment: usize,
}

impl Gl {
    /// The pack (`true`) or unpack modes.
    pub(super) fn glu_store(&self, pack: bool) -> PixelStore {
        let s = if pack { self.pack_store() } else { self.unpack_store() };
        PixelStore {
            swap_bytes: s.swap_bytes,
            lsb_first: s.lsb_first,
            row_length: s.row_length,
            skip_rows: s.skip_rows,
            skip_pixels: s.skip_pixels,
            alignment: s.alignment,
        }
    }
}

/// Where the components of an image lie in client memory under a pixel store (GLU's own
/// arithmetic, which is GL's): each row's first byte, and the bit or byte step.
pub(super) struct Layout {
    /// The first row's first byte.
    start: usize,
    /// Bytes from one row to the next.
    row_size: usize,
    height: usize,
    /// The bit of the first component of each row (bitmaps).
    first_bit: usize,
    element: usize,
    elements_per_row: usize,
    /// The last byte touched, plus one.
    pub end: usize,
}

impl Layout {
    /// `None` when the image's extent overflows memory.
    pub(super) fn new(
        store: &PixelStore,
        width: usize,
        height: usize,
        components: usize,
        type_: GLenum,
    ) -> Option<Self> {
        let groups = if store.row_length > 0 { store.row_length } else { width };
        let element = element_size(type_);
        let unpadded = if type_ == GL_BITMAP {
            groups.checked_mul(components)?.checked_add(7)? / 8
        } else {
            groups.checked_mul(components)?.checked_mul(element)?
        };
        let padding = unpadded % store.alignment;
        let row_size = if padding > 0 { unpadded + store.alignment - padding } else { unpadded };
        let skipped = if type_ == GL_BITMAP {
            store.skip_pixels.checked_mul(components)? / 8
        } else {
            store.skip_pixels.checked_mul(components * element)?
        };
        let start = store.skip_rows.checked_mul(row_size)?.checked_add(skipped)?;
        let first_bit = store.skip_pixels.wrapping_mul(components) % 8;
        let elements_per_row = width.checked_mul(components)?;
        let row_bytes = if type_ == GL_BITMAP {
            first_bit.checked_add(elements_per_row)?.div_ceil(8)
        } else {
            elements_per_row.checked_mul(element)?
        };
        let end = match height {
            0 => 0,
            h => start.checked_add((h - 1).checked_mul(row_size)?)?.checked_add(row_bytes)?,
        };
        Some(Layout { start, row_size, height, first_bit, element, elements_per_row, end })
    }

    /// Each row's first byte.
    fn rows(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.height).map(|i| self.start + i * self.row_size)
    }
}

/// C's conversion of a float to `GLushort` on x86: truncation to a 32-bit integer (the
/// "integer indefinite" 0x80000000 for NaN and out of range), then its low 16 bits.
pub(super) fn float_to_ushort(f: f32) -> u16 {
    if f.is_nan() || !(-2_147_483_648.0..2_147_483_648.0).contains(&f) {
        0
    } else {
        f as i32 as u16
    }
}

/// The same for a double (`scale_internal`'s `(totals[k] + 0.5) / area`).
pub(super) fn double_to_ushort(f: f64) -> u16 {
    if f.is_nan() || !(-2_147_483_648.0..2_147_483_648.0).contains(&f) {
        0
    } else {
        f as i32 as u16
    }
}

/// One component read from client memory as GLU's 16-bit value (`fill_image`).
pub(super) fn fill_element(bytes: &[u8], type_: GLenum, swap: bool, index: bool) -> u16 {
    let mut b = [0u8; 4];
    b[..bytes.len()].copy_from_slice(bytes);
    if swap {
        b[..bytes.len()].reverse();
    }
    let word = u32::from_ne_bytes(b);
    match (type_, index) {
        (GL_UNSIGNED_BYTE, true) => u16::from(b[0]),
        (GL_UNSIGNED_BYTE, false) => u16::from(b[0]) * 257,
        (GL_BYTE, true) => i16::from(b[0] as i8) as u16,
        (GL_BYTE, false) => (i32::from(b[0] as i8) * 516) as u16,
        (GL_UNSIGNED_SHORT, _) => u16::from_ne_bytes([b[0], b[1]]),
        (GL_SHORT, true) => u16::from_ne_bytes([b[0], b[1]]),
        (GL_SHORT, false) => (i32::from(i16::from_ne_bytes([b[0], b[1]])) * 2) as u16,
        (GL_UNSIGNED_INT, true) => word as u16,
        (GL_UNSIGNED_INT, false) => (word >> 16) as u16,
        (GL_INT, true) => word as u16,
        (GL_INT, false) => ((word as i32) >> 15) as u16,
        (_, true) => float_to_ushort(f32::from_bits(word)),
        (_, false) => float_to_ushort(65535.0 * f32::from_bits(word)),
    }
}

/// One 16-bit value written to client memory as `type_` (`empty_image`).
pub(super) fn empty_element(value: u16, out: &mut [u8], type_: GLenum, swap: bool, index: bool) {
    let v = u32::from(value);
    let bytes: Vec<u8> = match (type_, index) {
        (GL_UNSIGNED_BYTE, true) | (GL_BYTE, true) => vec![value as u8],
        (GL_UNSIGNED_BYTE, false) => vec![(value >> 8) as u8],
        (GL_BYTE, false) => vec![(value >> 9) as u8],
        (GL_UNSIGNED_SHORT, _) | (GL_SHORT, true) => value.to_ne_bytes().to_vec(),
        (GL_SHORT, false) => (value >> 1).to_ne_bytes().to_vec(),
        (GL_UNSIGNED_INT, true) | (GL_INT, true) => v.to_ne_bytes().to_vec(),
        (GL_UNSIGNED_INT, false) => v.wrapping_mul(65537).to_ne_bytes().to_vec(),
        (GL_INT, false) => (v.wrapping_mul(65537) / 2).to_ne_bytes().to_vec(),
        (_, true) => f32::from(value).to_ne_bytes().to_vec(),
        (_, false) => (f32::from(value) / 65535.0).to_ne_bytes().to_vec(),
    };
    out.copy_from_slice(&bytes);
    if swap {
        out.reverse();
    }
}

/// `fill_image`: the client's image as GLU's 16-bit components, row after row.
pub(super) fn fill_image(store: &PixelStore, layout: &Layout, type_: GLenum, index: bool, data: &[u8]) -> Vec<u16> {
    let mut out = Vec::with_capacity(layout.height * layout.elements_per_row);
    for row in layout.rows() {
        for j in 0..layout.elements_per_row {
            if type_ == GL_BITMAP {
                let bit = layout.first_bit + j;
                let byte = data[row + bit / 8];
                let mask = if store.lsb_first { 1 << (bit % 8) } else { 0x80 >> (bit % 8) };
                out.push(match (byte & mask != 0, index) {
                    (false, _) => 0,
                    (true, true) => 1,
                    (true, false) => 65535,
                });
            } else {
                let at = row + j * layout.element;
                let swap = store.swap_bytes && layout.element > 1;
                out.push(fill_element(&data[at..at + layout.element], type_, swap, index));
            }
        }
    }
    out
}

/// `empty_image`: GLU's 16-bit components written into the client's memory.
fn empty_image(store: &PixelStore, layout: &Layout, type_: GLenum, index: bool, image: &[u16], out: &mut [u8]) {
    let mut values = image.iter();
    for row in layout.rows() {
        for j in 0..layout.elements_per_row {
            let Some(&value) = values.next() else { return };
            if type_ == GL_BITMAP {
                let bit = layout.first_bit + j;
                let mask = if store.lsb_first { 1 << (bit % 8) } else { 0x80 >> (bit % 8) };
                let set = if index { value & 1 == 1 } else { value > 32767 };
                let byte = &mut out[row + bit / 8];
                *byte = if set { *byte | mask } else { *byte & !mask };
            } else {
                let at = row + j * layout.element;
                let swap = store.swap_bytes && layout.element > 1;
                empty_element(value, &mut out[at..at + layout.element], type_, swap, index);
            }
        }
    }
}

/// `halveImage`: each 2×2 block averaged with rounding.
fn halve(components: usize, width: usize, height: usize, data: &[u16]) -> Vec<u16> {
    let (w, h) = (width / 2, height / 2);
    let at = |x: usize, y: usize, k: usize| u32::from(data[(y * width + x) * components + k]);
    let mut out = Vec::with_capacity(w * h * components);
    for i in 0..h {
        for j in 0..w {
            for k in 0..components {
                let sum = at(2 * j, 2 * i, k)
                    + at(2 * j + 1, 2 * i, k)
                    + at(2 * j, 2 * i + 1, k)
                    + at(2 * j + 1, 2 * i + 1, k);
                out.push(((sum + 2) / 4) as u16);
            }
        }
    }
    out
}

/// The box filter's extent along one axis for output pixel `i`: `(low, high)` in input pixels,
/// as floats (`scale_internal`).
pub(super) fn extent(i: usize, conv: f32, size_in: usize, size_out: usize) -> (f32, f32) {
    let centre = (f64::from(conv) * (i as f64 + 0.5)) as f32;
    if size_in > size_out {
        let half = conv / 2.0;
        (centre - half, centre + half)
    } else {
        ((f64::from(centre) - 0.5) as f32, (f64::from(centre) + 0.5) as f32)
    }
}

/// The input pixels a box covers along one axis, each with its (wrapped) index and the
/// fraction covered, in `scale_internal`'s order and float arithmetic.
pub(super) fn coverage(low: f32, high: f32, size: usize) -> Vec<(usize, f32)> {
    let mut cells = Vec::new();
    let mut at = low;
    let mut int = f64::from(at).floor() as i64;
    while at < high {
        let index = (int + size as i64).rem_euclid(size as i64) as usize;
        let next = (int + 1) as f32;
        cells.push((index, if high < next { high - at } else { next - at }));
        int += 1;
        at = int as f32;
    }
    cells
}

/// `scale_internal`: the box filter, in GLU's float arithmetic.
pub(super) fn scale(
    components: usize,
    (win, hin): (usize, usize),
    data: &[u16],
    (wout, hout): (usize, usize),
) -> Vec<u16> {
    if win == wout * 2 && hin == hout * 2 {
        return halve(components, win, hin, data);
    }
    let (convx, convy) = (win as f32 / wout as f32, hin as f32 / hout as f32);
    let mut out = Vec::with_capacity(wout * hout * components);
    for i in 0..hout {
        let (lowy, highy) = extent(i, convy, hin, hout);
        let rows = coverage(lowy, highy, hin);
        for j in 0..wout {
            let (lowx, highx) = extent(j, convx, win, wout);
            let columns = coverage(lowx, highx, win);
            let (mut totals, mut area) = ([0.0f32; 4], 0.0f32);
            for &(y, ypercent) in &rows {
                for &(x, xpercent) in &columns {
                    let percent = xpercent * ypercent;
                    area += percent;
                    let base = (x + y * win) * components;
                    for (total, &c) in totals.iter_mut().zip(&data[base..base + components]) {
                        *total += f32::from(c) * percent;
                    }
                }
            }
            for total in &totals[..components] {
                out.push(double_to_ushort((f64::from(*total) + 0.5) / f64::from(area)));
            }
        }
    }
    out
}

impl Gl {
    /// Bytes GLU reads (`pack` false: with the unpack modes) or writes (`pack` true: with the
    /// pack modes) for a `width` × `height` image of `format` and `type_` in its mipmap and
    /// scaling calls; `None` for sizes, formats or types GLU rejects before touching memory.
    /// The C ABI sizes its slices with this.
    #[must_use]
    pub fn glu_image_len(
        &self,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        pack: bool,
    ) -> Option<usize> {
        if width <= 0 || height <= 0 || !legal_format(format) || !legal_type(type_) {
            return None;
        }
        let store = self.glu_store(pack);
        Layout::new(&store, width as usize, height as usize, components(format), type_).map(|l| l.end)
    }

    /// `gluScaleImage`: `datain` (`widthin`×`heightin` pixels of `format` and `typein`, read
    /// with the unpack modes) resampled to `widthout`×`heightout` into `dataout` (as
    /// `typeout`, written with the pack modes). Returns 0 (also when a size is 0, doing
    /// nothing), `GLU_INVALID_VALUE` for a negative size, `GLU_INVALID_ENUM` for a format or
    /// type GLU does not take, or `GLU_INVALID_VALUE` when a slice is shorter than the image
    /// its modes describe (C would read or write past it). GL 1.2's packed types are not
    /// converted: `GLU_INVALID_ENUM`.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_scale_image<P: bytemuck::Pod, Q: bytemuck::Pod>(
        &mut self,
        format: GLenum,
        widthin: GLsizei,
        heightin: GLsizei,
        typein: GLenum,
        datain: &[P],
        widthout: GLsizei,
        heightout: GLsizei,
        typeout: GLenum,
        dataout: &mut [Q],
    ) -> GLint {
        if widthin == 0 || heightin == 0 || widthout == 0 || heightout == 0 {
            return 0;
        }
        if widthin < 0 || heightin < 0 || widthout < 0 || heightout < 0 {
            return GLU_INVALID_VALUE as GLint;
        }
        let legal = |t| legal_type(t) || packed(t);
        if !legal_format(format) || !legal(typein) || !legal(typeout) {
            return GLU_INVALID_ENUM as GLint;
        }
        if !packed_format_ok(format, typein) || !packed_format_ok(format, typeout) {
            return GLU_INVALID_OPERATION as GLint;
        }
        if packed(typein) || packed(typeout) {
            return GLU_INVALID_ENUM as GLint;
        }
        let (unpack, pack) = (self.glu_store(false), self.glu_store(true));
        let n = components(format);
        let index = matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX);
        let (win, hin, wout, hout) = (widthin as usize, heightin as usize, widthout as usize, heightout as usize);
        let (Some(read), Some(write)) =
            (Layout::new(&unpack, win, hin, n, typein), Layout::new(&pack, wout, hout, n, typeout))
        else {
            return GLU_INVALID_VALUE as GLint;
        };
        let (input, output): (&[u8], &mut [u8]) = (bytemuck::cast_slice(datain), bytemuck::cast_slice_mut(dataout));
        if input.len() < read.end || output.len() < write.end {
            return GLU_INVALID_VALUE as GLint;
        }
        let before = fill_image(&unpack, &read, typein, index, input);
        let after = scale(n, (win, hin), &before, (wout, hout));
        empty_image(&pack, &write, typeout, index, &after, output);
        0
    }
}
