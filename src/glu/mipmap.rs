//! `gluBuild2DMipmaps` (GLU 1.3 §3.1; SGI GLU `libutil/mipmap.c`): the image scaled to a power
//! of two on each side if it is not one, then halved level by level down to 1×1, every level
//! handed to `glTexImage2D`. GLU calls GL only: so does this, through the public `Gl` methods.
//!
//! Halving averages each 2×2 block of bytes with rounding, `(a + b + c + d + 2) / 4`, and a
//! pair `(a + b) / 2` (truncated) once one side is 1, as real GLU does for `GL_UNSIGNED_BYTE`
//! (measured against GLU 9.0.2 with `glGetTexImage`).
//! The power-of-two scaling of other sizes is an area average (GLU's `gluScaleImage` is one
//! too; its rounding may differ by one step).

use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;
use crate::glu::consts::{GLU_INVALID_ENUM, GLU_INVALID_VALUE};
use crate::glu::mipmap_levels::{check_args_and_sides, level_range};

/// An image of `components` bytes a pixel, rows packed (alignment 1).
struct Image {
    width: usize,
    height: usize,
    components: usize,
    bytes: Vec<u8>,
}

impl Image {
    fn at(&self, x: usize, y: usize, c: usize) -> u32 {
        u32::from(self.bytes[(y * self.width + x) * self.components + c])
    }

    /// The next mipmap level: each side halved (a side of 1 stays 1).
    fn halved(&self) -> Image {
        let (w, h) = ((self.width / 2).max(1), (self.height / 2).max(1));
        let mut bytes = Vec::with_capacity(w * h * self.components);
        for y in 0..h {
            for x in 0..w {
                for c in 0..self.components {
                    let value = match (self.width > 1, self.height > 1) {
                        (true, true) => {
                            let sum = self.at(2 * x, 2 * y, c)
                                + self.at(2 * x + 1, 2 * y, c)
                                + self.at(2 * x, 2 * y + 1, c)
                                + self.at(2 * x + 1, 2 * y + 1, c);
                            (sum + 2) / 4
                        }
                        (true, false) => (self.at(2 * x, y, c) + self.at(2 * x + 1, y, c)) / 2,
                        (false, true) => (self.at(x, 2 * y, c) + self.at(x, 2 * y + 1, c)) / 2,
                        (false, false) => self.at(x, y, c),
                    };
                    bytes.push(value as u8);
                }
            }
        }
        Image { width: w, height: h, components: self.components, bytes }
    }

    /// The image resampled to `w`×`h` by averaging the source area each new pixel covers.
    fn scaled(&self, w: usize, h: usize) -> Image {
        let (sx, sy) = (self.width as f64 / w as f64, self.height as f64 / h as f64);
        let mut bytes = Vec::with_capacity(w * h * self.components);
        for y in 0..h {
            for x in 0..w {
                let (x0, x1) = (x as f64 * sx, (x + 1) as f64 * sx);
                let (y0, y1) = (y as f64 * sy, (y + 1) as f64 * sy);
                for c in 0..self.components {
                    let (mut sum, mut area) = (0.0, 0.0);
                    for py in y0.floor() as usize..(y1.ceil() as usize).min(self.height) {
                        let cover_y = (y1.min(py as f64 + 1.0) - y0.max(py as f64)).max(0.0);
                        for px in x0.floor() as usize..(x1.ceil() as usize).min(self.width) {
                            let cover = cover_y * (x1.min(px as f64 + 1.0) - x0.max(px as f64)).max(0.0);
                            sum += cover * f64::from(self.at(px, py, c));
                            area += cover;
                        }
                    }
                    bytes.push((sum / area).round() as u8);
                }
            }
        }
        Image { width: w, height: h, components: self.components, bytes }
    }
}

/// The power of two GLU scales a side to: halving until 1 or 3 (which counts as 4), so a side
/// rounds to the nearer power in the binary sense (6 → 8, 5 → 4).
fn nearest_power(mut n: usize) -> usize {
    let mut power = 1;
    loop {
        match n {
            0 | 1 => return power,
            3 => return power * 4,
            _ => {
                n >>= 1;
                power *= 2;
            }
        }
    }
}

impl Gl {
    /// `gluBuild2DMipmaps`: loads `data` (`width`×`height` pixels of `format`, bytes laid out
    /// by the pixel store) and every mipmap level below it into the bound 2D texture. Returns 0,
    /// or `GLU_INVALID_VALUE` for a side below 1, `GLU_INVALID_ENUM` for a `format` or `type_`
    /// GLU does not take here (`GL_UNSIGNED_BYTE` of `GL_ALPHA`, `GL_LUMINANCE`,
    /// `GL_LUMINANCE_ALPHA`, `GL_RGB`, `GL_RGBA`), or `GLU_INVALID_VALUE` for data shorter than
    /// the image; GL's own errors are GL's.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_build_2d_mipmaps<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        data: &[P],
    ) -> GLint {
        if width < 1 || height < 1 {
            return GLU_INVALID_VALUE as GLint;
        }
        let mut image = match self.byte_image(width, height, format, type_, bytemuck::cast_slice(data)) {
            Ok(image) => image,
            Err(code) => return code,
        };
        let max = crate::gl::MAX_TEXTURE_SIZE as usize;
        let (w, h) = (nearest_power(image.width).min(max), nearest_power(image.height).min(max));
        if (w, h) != (image.width, image.height) {
            image = image.scaled(w, h);
        }
        // GLU unpacks the client's image itself and hands GL tightly packed levels.
        let saved = self.unpack_alignment();
        self.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        let mut level = 0;
        loop {
            let (lw, lh) = (image.width as GLsizei, image.height as GLsizei);
            self.tex_image_2d(target, level, internal_format, lw, lh, 0, format, type_, &image.bytes);
            if image.width == 1 && image.height == 1 {
                break;
            }
            image = image.halved();
            level += 1;
        }
        self.pixel_storei(GL_UNPACK_ALIGNMENT, saved);
        0
    }

    /// `gluBuild2DMipmapLevels`: `data` (bytes, `GL_UNSIGNED_BYTE`) is level `user_level`;
    /// the levels below it are made by GLU's halving (sides that are not powers of two are
    /// halved as they are, as GLU does) and those from `base_level` to `max_level` loaded.
    /// GLU's checks first: `checkMipmapArgs`, sizes below 1, then `isLegalLevels` over the
    /// larger side's levels (`GLU_INVALID_VALUE`). Types other than `GL_UNSIGNED_BYTE`, which
    /// GLU takes, are `GLU_INVALID_ENUM` here.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_build_2d_mipmap_levels<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        user_level: GLint,
        base_level: GLint,
        max_level: GLint,
        data: &[P],
    ) -> GLint {
        let sides = [width, height];
        let range = (user_level, base_level, max_level);
        let levels = match check_args_and_sides(format, type_, &sides).and_then(|()| level_range(&sides, range)) {
            Ok(levels) => levels,
            Err(code) => return code,
        };
        let mut image = match self.byte_image(width, height, format, type_, bytemuck::cast_slice(data)) {
            Ok(image) => image,
            Err(code) => return code,
        };
        let saved = self.unpack_alignment();
        self.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        for level in user_level..=levels.min(max_level) {
            if level >= base_level {
                let (lw, lh) = (image.width as GLsizei, image.height as GLsizei);
                self.tex_image_2d(target, level, internal_format, lw, lh, 0, format, type_, &image.bytes);
            }
            if image.width == 1 && image.height == 1 {
                break;
            }
            image = image.halved();
        }
        self.pixel_storei(GL_UNPACK_ALIGNMENT, saved);
        0
    }

    /// The client's image for the byte path both 2D builders share: `GLU_INVALID_ENUM` for a
    /// `format` or `type_` it does not take, `GLU_INVALID_VALUE` for data shorter than the
    /// image, else the image packed.
    fn byte_image(
        &self,
        width: GLsizei,
        height: GLsizei,
        format: GLenum,
        type_: GLenum,
        data: &[u8],
    ) -> Result<Image, GLint> {
        let components = match format {
            GL_ALPHA | GL_LUMINANCE => 1,
            GL_LUMINANCE_ALPHA => 2,
            GL_RGB => 3,
            GL_RGBA => 4,
            _ => return Err(GLU_INVALID_ENUM as GLint),
        };
        if type_ != GL_UNSIGNED_BYTE {
            return Err(GLU_INVALID_ENUM as GLint);
        }
        self.packed_image(width as usize, height as usize, components, data).ok_or(GLU_INVALID_VALUE as GLint)
    }

    /// The client's image as tightly packed rows, read with the unpack pixel store.
    fn packed_image(&self, width: usize, height: usize, components: usize, bytes: &[u8]) -> Option<Image> {
        // GLU reads the unpack modes (glGetIntegerv) and unpacks the image itself.
        let store = self.unpack_store();
        let stride = store.row_stride(width, components, 1);
        let first = store.first_byte(stride, components);
        let needed =
            first.checked_add((height - 1).checked_mul(stride)?)?.checked_add(width.checked_mul(components)?)?;
        if bytes.len() < needed {
            return None;
        }
        let mut packed = Vec::with_capacity(width * height * components);
        for row in 0..height {
            packed.extend_from_slice(&bytes[first + row * stride..][..width * components]);
        }
        Some(Image { width, height, components, bytes: packed })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_power_is_glus() {
        // Level 0's width after gluBuild2DMipmaps on real GLU 9.0.2 for these widths.
        let got: Vec<usize> = [1, 2, 3, 4, 5, 6, 7, 8, 12, 100, 129].iter().map(|&n| nearest_power(n)).collect();
        assert_eq!(got, [1, 2, 4, 4, 4, 8, 8, 8, 16, 128, 128]);
    }

    #[test]
    fn halving_rounds_to_nearest() {
        let image = Image { width: 2, height: 2, components: 1, bytes: vec![0, 1, 1, 1] };
        assert_eq!(image.halved().bytes, [1]); // (3 + 2) / 4
                                               // Measured on real GLU: a pair truncates.
        let row = Image { width: 2, height: 1, components: 1, bytes: vec![0, 1] };
        assert_eq!(row.halved().bytes, [0]);
    }

    #[test]
    fn builds_the_whole_chain() {
        let mut gl = Gl::new(4, 4);
        gl.bind_texture(GL_TEXTURE_2D, 1);
        let image = vec![200u8; 4 * 2 * 3];
        assert_eq!(gl.glu_build_2d_mipmaps(GL_TEXTURE_2D, 3, 4, 2, GL_RGB, GL_UNSIGNED_BYTE, &image), 0);
        gl.enable(GL_TEXTURE_2D);
        let bound = gl.bound_texture().expect("complete with the initial mipmap filter");
        let sizes: Vec<(u32, u32)> = bound.levels.iter().map(|l| (l.width, l.height)).collect();
        assert_eq!(sizes, [(4, 2), (2, 1), (1, 1)]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(gl.glu_build_2d_mipmaps(GL_TEXTURE_2D, 3, 0, 2, GL_RGB, GL_UNSIGNED_BYTE, &image), 100901);
        assert_eq!(gl.glu_build_2d_mipmaps(GL_TEXTURE_2D, 3, 4, 2, 0x1234, GL_UNSIGNED_BYTE, &image), 100900);
    }
}
