//! `gluBuild1DMipmaps`, `gluBuild1DMipmapLevels` and `gluBuild2DMipmapLevels` (GLU 1.3 §3.1; SGI GLU 9.0
//! `libutil/mipmap.c`), checked against real GLU 9.0.2 over OSMesa
//! (`tests/reference/glu/mipmaps.c`: return codes, GL errors, every level's size and texels).
//!
//! GLU's argument checks come first (`checkMipmapArgs`: an unknown format or type, or
//! `GL_STENCIL_INDEX`, is `GLU_INVALID_ENUM`; a packed type of the wrong format
//! `GLU_INVALID_OPERATION`; then sizes below 1, and for the `Levels` forms `isLegalLevels`,
//! `GLU_INVALID_VALUE`). A 1D image goes through GLU's 16-bit path (`gluBuild1DMipmapLevelsCore`:
//! `fill_image`, then `scale_internal` for every level), a 2D one of bytes through the
//! byte path of [`Gl::glu_build_2d_mipmaps`].
//! The 3D forms are in [`super::mipmap_3d`].

use super::scale::{fill_image, legal_format, legal_type, packed, packed_format_ok, scale, Layout};
use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;
use crate::glu::consts::*;

/// `checkMipmapArgs`.
pub(super) fn check_mipmap_args(format: GLenum, type_: GLenum) -> Result<(), GLint> {
    if !legal_format(format) || !(legal_type(type_) || packed(type_)) || format == GL_STENCIL_INDEX {
        return Err(GLU_INVALID_ENUM as GLint);
    }
    if !packed_format_ok(format, type_) {
        return Err(GLU_INVALID_OPERATION as GLint);
    }
    Ok(())
}

/// `checkMipmapArgs`, then a side below 1 (`GLU_INVALID_VALUE`): the opening that
/// `gluBuild1DMipmaps`, `gluBuild3DMipmaps` and every `gluBuild*MipmapLevels` share in GLU's
/// `mipmap.c`.
pub(super) fn check_args_and_sides(format: GLenum, type_: GLenum, sides: &[GLsizei]) -> Result<(), GLint> {
    check_mipmap_args(format, type_)?;
    if sides.iter().any(|&side| side < 1) {
        return Err(GLU_INVALID_VALUE as GLint);
    }
    Ok(())
}

/// The last level a `gluBuild*MipmapLevels` makes, `user` plus the largest of the sides'
/// `computeLog`s (as `mipmap.c` takes the larger of the logs), or `GLU_INVALID_VALUE` where
/// `isLegalLevels` refuses the range `(user, base, max)`.
pub(super) fn level_range(sides: &[GLsizei], (user, base, max): (GLint, GLint, GLint)) -> Result<GLint, GLint> {
    let levels = sides.iter().map(|&side| compute_log(side)).fold(-1, GLint::max).saturating_add(user);
    if !legal_levels(user, base, max, levels) {
        return Err(GLU_INVALID_VALUE as GLint);
    }
    Ok(levels)
}

/// `computeLog`: log2 of a power of two, -1 for anything else.
fn compute_log(value: i32) -> i32 {
    if value > 0 && value.count_ones() == 1 {
        value.trailing_zeros() as i32
    } else {
        -1
    }
}

/// `isLegalLevels`.
fn legal_levels(user: GLint, base: GLint, max: GLint, total: GLint) -> bool {
    !(base < 0 || base < user || max < base || total < max)
}

/// `nearestPower` (as `gluBuild2DMipmaps`'s), clamped to GL's largest texture.
fn fitted_power(n: i32) -> i32 {
    let (mut n, mut power) = (n, 1);
    loop {
        match n {
            0 | 1 => break,
            3 => {
                power *= 4;
                break;
            }
            _ => {
                n >>= 1;
                power *= 2;
            }
        }
    }
    power.min(crate::gl::MAX_TEXTURE_SIZE)
}

impl Gl {
    /// `gluBuild1DMipmaps`: `data` (`width` pixels of `format` and `type_`, read with the
    /// unpack modes) scaled to the nearest power of two and every level below it loaded into
    /// the bound 1D texture. Returns 0 or GLU's error (see the module); a slice shorter than
    /// the image is `GLU_INVALID_VALUE`.
    pub fn glu_build_1d_mipmaps<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        width: GLsizei,
        format: GLenum,
        type_: GLenum,
        data: &[P],
    ) -> GLint {
        if let Err(code) = check_args_and_sides(format, type_, &[width]) {
            return code;
        }
        let power = fitted_power(width);
        let levels = compute_log(power);
        self.build_1d_core(
            target,
            internal_format,
            (width, power),
            (format, type_),
            (0, 0, levels),
            bytemuck::cast_slice(data),
        )
    }

    /// `gluBuild1DMipmapLevels`: `data` is level `user_level`; the levels below it down to
    /// width 1 are made, and those from `base_level` to `max_level` loaded. A width that is
    /// not a power of two is halved as it is (GLU does not scale it).
    #[allow(clippy::too_many_arguments)]
    pub fn glu_build_1d_mipmap_levels<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        width: GLsizei,
        format: GLenum,
        type_: GLenum,
        user_level: GLint,
        base_level: GLint,
        max_level: GLint,
        data: &[P],
    ) -> GLint {
        let range = (user_level, base_level, max_level);
        if let Err(code) = check_args_and_sides(format, type_, &[width]).and_then(|()| level_range(&[width], range)) {
            return code;
        }
        self.build_1d_core(target, internal_format, (width, width), (format, type_), range, bytemuck::cast_slice(data))
    }

    /// `gluBuild1DMipmapLevelsCore`: the image as GLU's 16-bit components, scaled to
    /// `first_width` and then halved level by level; each level in `base..=max` loaded. GLU
    /// hands GL 16-bit components (`GL_UNSIGNED_SHORT`); gleval's GL takes them as the floats
    /// GL converts them to (c / 65535, GL 1.1 table 2.6).
    fn build_1d_core(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        (width, first_width): (GLsizei, GLsizei),
        (format, type_): (GLenum, GLenum),
        (user, base, max): (GLint, GLint, GLint),
        data: &[u8],
    ) -> GLint {
        let store = self.glu_store(false);
        let n = super::scale::components(format);
        let index = matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX);
        let Some(layout) = Layout::new(&store, width as usize, 1, n, type_).filter(|l| l.end <= data.len()) else {
            return GLU_INVALID_VALUE as GLint;
        };
        let mut image = fill_image(&store, &layout, type_, index, data);
        let (mut image_width, mut new_width) = (width as usize, first_width as usize);
        let saved = self.unpack_store();
        for (pname, value) in [(GL_UNPACK_ALIGNMENT, 2), (GL_UNPACK_SKIP_ROWS, 0), (GL_UNPACK_SKIP_PIXELS, 0)] {
            self.pixel_storei(pname, value);
        }
        self.pixel_storei(GL_UNPACK_ROW_LENGTH, 0);
        self.pixel_storei(GL_UNPACK_SWAP_BYTES, 0);
        let levels = compute_log(first_width).saturating_add(user);
        for level in user..=levels {
            if image_width != new_width {
                image = scale(n, (image_width, 1), &image, (new_width, 1));
                image_width = new_width;
            }
            if base <= level && level <= max {
                let floats: Vec<f32> = image.iter().map(|&c| f32::from(c) / 65535.0).collect();
                self.tex_image_1d(target, level, internal_format, image_width as GLsizei, 0, format, GL_FLOAT, &floats);
            }
            new_width = (new_width / 2).max(1);
        }
        self.pixel_storei(GL_UNPACK_ALIGNMENT, saved.alignment as GLint);
        self.pixel_storei(GL_UNPACK_SKIP_ROWS, saved.skip_rows as GLint);
        self.pixel_storei(GL_UNPACK_SKIP_PIXELS, saved.skip_pixels as GLint);
        self.pixel_storei(GL_UNPACK_ROW_LENGTH, saved.row_length as GLint);
        self.pixel_storei(GL_UNPACK_SWAP_BYTES, GLint::from(saved.swap_bytes));
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// mipmaps.c's input: bytes, and floats in [-0.1, 1.1).
    fn input(seed: u32) -> (Vec<u8>, Vec<f32>) {
        let mut state = seed;
        let bytes: Vec<u8> = (0..4096)
            .map(|_| {
                state = state.wrapping_mul(1_103_515_245).wrapping_add(12345);
                (state >> 16) as u8
            })
            .collect();
        let floats = bytes[..1024].iter().map(|&b| f32::from(b) / 255.0 * 1.2 - 0.1).collect();
        (bytes, floats)
    }

    /// The levels loaded, as mipmaps.c prints them.
    fn levels(gl: &mut Gl, dims: u8) -> Vec<String> {
        let mut out = Vec::new();
        for (k, level) in gl.bound_levels(dims).into_iter().enumerate() {
            let Some(level) = level.filter(|l| l.width > 0) else { continue };
            let hex: String = level.texels.iter().flatten().map(|b| format!("{b:02x}")).collect();
            out.push(format!("L {k} {} {} {hex}", level.width, level.height));
        }
        out
    }

    fn run(gl: &mut Gl, v: &[i64]) -> (i64, i64, Vec<String>) {
        let n = |k: usize| v[k] as i32;
        match v[0] {
            1 => {
                let (bytes, floats) = input(v[8] as u32);
                gl.bind_texture(GL_TEXTURE_1D, 1);
                gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
                let (format, type_) = (v[1] as u32, v[2] as u32);
                let rc = match (n(7) == 1, type_ == GL_FLOAT) {
                    (true, true) => {
                        gl.glu_build_1d_mipmaps(GL_TEXTURE_1D, GL_RGBA as i32, n(3), format, type_, &floats)
                    }
                    (true, false) => {
                        gl.glu_build_1d_mipmaps(GL_TEXTURE_1D, GL_RGBA as i32, n(3), format, type_, &bytes)
                    }
                    (false, _) => gl.glu_build_1d_mipmap_levels(
                        GL_TEXTURE_1D,
                        GL_RGBA as i32,
                        n(3),
                        format,
                        type_,
                        n(4),
                        n(5),
                        n(6),
                        &bytes,
                    ),
                };
                (i64::from(rc), i64::from(gl.get_error()), levels(gl, 1))
            }
            2 => {
                let (bytes, _) = input(v[7] as u32);
                gl.bind_texture(GL_TEXTURE_2D, 1);
                gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
                let format = v[1] as u32;
                let rc = gl.glu_build_2d_mipmap_levels(
                    GL_TEXTURE_2D,
                    GL_RGBA as i32,
                    n(2),
                    n(3),
                    format,
                    GL_UNSIGNED_BYTE,
                    n(4),
                    n(5),
                    n(6),
                    &bytes,
                );
                (i64::from(rc), i64::from(gl.get_error()), levels(gl, 2))
            }
            _ => unreachable!("the 3D cases are mipmap_3d.rs's"),
        }
    }

    #[test]
    fn mipmaps_match_real_glu() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu/mipmaps.txt");
        let text = std::fs::read_to_string(path).expect("mipmaps.txt");
        let mut cases: Vec<(Vec<i64>, Vec<String>)> = Vec::new();
        for line in text.lines() {
            if let Some(rest) = line.strip_prefix("M ") {
                let mut words = rest.split(' ');
                let dims = match words.next() {
                    Some("1d") => 1,
                    Some("2d") => 2,
                    _ => {
                        cases.push((vec![3], Vec::new()));
                        continue;
                    }
                };
                let mut v = vec![dims];
                v.extend(words.map(|w| w.parse::<i64>().unwrap()));
                cases.push((v, Vec::new()));
            } else {
                cases.last_mut().unwrap().1.push(line.to_string());
            }
        }
        assert!(cases.len() > 90);
        let mut failures = Vec::new();
        cases.retain(|(v, _)| v[0] != 3);
        for (v, want) in &cases {
            let mut gl = Gl::new(4, 4);
            let (rc, error, got) = run(&mut gl, v);
            let (want_rc, want_error) = (v[v.len() - 2], v[v.len() - 1]);
            if (rc, error) != (want_rc, want_error) || got != *want {
                failures.push(format!(
                    "{v:?}: rc {rc} error {error}, GLU {want_rc} {want_error}; levels {got:?} vs {want:?}"
                ));
            }
        }
        assert!(failures.is_empty(), "{} of {} differ:\n{}", failures.len(), cases.len(), failures.join("\n"));
    }
}
