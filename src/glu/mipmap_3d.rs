//! `gluBuild3DMipmaps` and `gluBuild3DMipmapLevels` (GLU 1.3 §3.1; SGI GLU 9.0
//! `libutil/mipmap.c`: `closestFit3D`, `gluBuild3DMipmapLevelsCore`), checked bit for bit
//! against real GLU 9.0.2 over OSMesa (`tests/reference/glu/mipmaps.c`: every type, packed
//! ones included, every format, sizes that are not powers of two, one image deep, rows and
//! columns of images, level windows, the unpack modes, the errors).
//!
//! As GLU: the checks (`checkMipmapArgs`, sides, `GL_BITMAP`, `isLegalLevels`); for the plain
//! form the largest powers of two no larger than GLU's nearest ones that `GL_PROXY_TEXTURE_3D`
//! takes at level 1; then level `user` is the client's image itself (loaded by GL with the
//! client's alignment and byte swapping, GLU having skipped to its first pixel and set the
//! other unpack modes to 0) or its scaling ([`super::scale_3d`]); each next level is GLU's
//! halving of the one before ([`super::halve_3d`], or [`super::halve_2d`] one image deep), in
//! buffers of GLU's own, tightly packed but loaded with the client's alignment still set.
//! Those are GLU's quirks, kept: an odd side halved as it is slips a pixel per row pair, a
//! row's bytes halve with its width (not as its new width times the pixel), byte swapping of
//! the client's image is a no-op in GLU's own halving on a little-endian machine.

use super::element::Element;
use super::halve_2d::{halve_2d, Sides, Steps};
use super::halve_3d::{halve_3d, halve_packed_3d};
use super::memory::furthest_read;
use super::mipmap_levels::{check_args_and_sides, level_range};
use super::packed_pixel::PackedPixel;
use super::scale::components;
use super::scale_3d::scale_image_3d;
use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::{Gl, PixelStore};
use crate::glu::consts::*;

/// The unpack modes GLU sets to 0 around its work, and restores.
const ZEROED: [GLenum; 5] =
    [GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_IMAGE_HEIGHT];

/// A type GLU halves: components of a GL 1.1 type, or packed pixels.
#[derive(Clone, Copy)]
enum Kind {
    Elements(Element),
    Packed(PackedPixel),
}

impl Kind {
    fn of(type_: GLenum) -> Option<Self> {
        Element::of(type_).map(Self::Elements).or_else(|| PackedPixel::of(type_).map(Self::Packed))
    }

    /// `bytes_per_element`.
    fn size(self) -> usize {
        match self {
            Self::Elements(e) => e.size(),
            Self::Packed(p) => p.size,
        }
    }
}

/// `computeLog`: log2 of a power of two, -1 for anything else.
fn compute_log(value: GLsizei) -> GLint {
    if value > 0 && value.count_ones() == 1 {
        value.trailing_zeros() as GLint
    } else {
        -1
    }
}

/// `nearestPower`: halving until 1 or 3 (which counts as 4).
fn nearest_power(value: GLsizei) -> GLsizei {
    let (mut v, mut power) = (i64::from(value.max(1)), 1i64);
    while v != 1 && v != 3 {
        v >>= 1;
        power *= 2;
    }
    let power = if v == 3 { power * 4 } else { power };
    GLsizei::try_from(power).unwrap_or(1 << 30)
}

/// The checks both builders open with, in GLU's order: format and type, a side under 1
/// (`GLU_INVALID_VALUE`), then `GL_BITMAP`, which has no 3D form (`GLU_INVALID_ENUM`).
fn check_3d_args(format: GLenum, type_: GLenum, sides: [GLsizei; 3]) -> Result<(), GLint> {
    check_args_and_sides(format, type_, &sides)?;
    if type_ == GL_BITMAP {
        return Err(GLU_INVALID_ENUM as GLint);
    }
    Ok(())
}

/// The bytes of a `width`×`height`×`depth` image of `format` and `type_` in GLU's buffers
/// (`imageSize3D`), `None` where that overflows (GLU's `malloc` fails).
fn image_size_3d((w, h, d): (usize, usize, usize), format: GLenum, kind: Kind) -> Option<usize> {
    let per_pixel = if matches!(kind, Kind::Packed(_)) { 1 } else { components(format) };
    kind.size().checked_mul(w)?.checked_mul(h)?.checked_mul(d)?.checked_mul(per_pixel)
}

/// Where the client's image lies under the unpack modes, as GLU computes it: the first
/// pixel's byte, and the byte steps.
struct ClientImage {
    start: usize,
    steps: Steps,
    /// The last byte GLU reads, plus one.
    end: usize,
}

impl ClientImage {
    fn new(store: &PixelStore, (w, h, d): (usize, usize, usize), format: GLenum, kind: Kind) -> Option<Self> {
        let per_pixel = if matches!(kind, Kind::Packed(_)) { 1 } else { components(format) };
        let element = kind.size();
        let group = element * per_pixel;
        let groups = if store.row_length > 0 { store.row_length } else { w };
        let mut row = groups.checked_mul(group)?;
        if row % store.alignment != 0 {
            row += store.alignment - row % store.alignment;
        }
        let rows = if store.image_height > 0 { store.image_height } else { h };
        let image = rows.checked_mul(row)?;
        let start = store
            .skip_rows
            .checked_mul(row)?
            .checked_add(store.skip_pixels.checked_mul(group)?)?
            .checked_add(store.skip_images.checked_mul(image)?)?;
        let extent = (d - 1).checked_mul(image)?.checked_add((h - 1).checked_mul(row)?)?.checked_add(w * group)?;
        let steps = Steps {
            element: element as isize,
            group: group as isize,
            row: isize::try_from(row).ok()?,
            image: isize::try_from(image).ok()?,
        };
        Some(Self { start, steps, end: start.checked_add(extent)? })
    }
}

impl Gl {
    /// Bytes `gluBuild3DMipmaps` (`levels_form` false) or `gluBuild3DMipmapLevels` (true)
    /// read from the client for a `width`×`height`×`depth` image of `format` and `type_` under
    /// the unpack modes (image height and skipped images included), and past it where GLU's
    /// first halving slips beyond the image (with a row length or padding, its step to the next
    /// pair of images overshoots; real GLU reads that memory too); `None` for sizes, formats or
    /// types GLU refuses before reading. The C ABI sizes its slice with this.
    #[must_use]
    pub fn glu_image_len_3d(
        &self,
        (width, height, depth): (GLsizei, GLsizei, GLsizei),
        format: GLenum,
        type_: GLenum,
        levels_form: bool,
    ) -> Option<usize> {
        check_3d_args(format, type_, [width, height, depth]).ok()?;
        let kind = Kind::of(type_)?;
        let sides = (width as usize, height as usize, depth as usize);
        let store = self.unpack_store();
        let client = ClientImage::new(&store, sides, format, kind)?;
        // GLU halves the client's image itself when it needs no scaling (the plain form:
        // powers of two, which GL is assumed to take), else reads it only to scale it.
        let halved = levels_form || [width, height, depth].iter().all(|&s| compute_log(s) >= 0);
        if !halved || sides == (1, 1, 1) {
            return Some(client.end);
        }
        let cmpts = if matches!(kind, Kind::Packed(_)) { 1 } else { components(format) };
        let next = ((sides.0 / 2).max(1), (sides.1 / 2).max(1), (sides.2 / 2).max(1));
        let mut scratch = vec![0u8; image_size_3d(next, format, kind)?];
        let swap = store.swap_bytes && kind.size() > 1;
        let far = furthest_read(|| halve_level(kind, cmpts, to_isize(sides), &[], &mut scratch, client.steps, swap));
        let far = far.and_then(|end| usize::try_from(end).ok()).unwrap_or(0);
        Some(client.end.max(client.start.checked_add(far)?))
    }

    /// `gluBuild3DMipmaps`: `data` (`width`×`height`×`depth` pixels of `format` and `type_`,
    /// read with the unpack modes) scaled to powers of two GL takes, if it is not one, and
    /// every level below it loaded into the bound 3D texture by `glTexImage3D` (see the
    /// module). Returns 0, GLU's error for its checks, or `GLU_INVALID_VALUE` for a slice
    /// shorter than the image (C would read past it); GL's errors are GL's.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_build_3d_mipmaps<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        format: GLenum,
        type_: GLenum,
        data: &[P],
    ) -> GLint {
        if let Err(code) = check_3d_args(format, type_, [width, height, depth]) {
            return code;
        }
        let fitted = self.closest_fit_3d(internal_format, (width, height, depth), (format, type_));
        let levels = compute_log(fitted.0).max(compute_log(fitted.1)).max(compute_log(fitted.2));
        let sides = ((width, height, depth), fitted);
        self.build_3d_core(target, internal_format, sides, (format, type_), (0, 0, levels), bytemuck::cast_slice(data))
    }

    /// `gluBuild3DMipmapLevels`: `data` is level `user_level`; the levels below it are GLU's
    /// halvings of it (a side that is not a power of two halved as it is), and those from
    /// `base_level` to `max_level` loaded. Returns as [`Gl::glu_build_3d_mipmaps`], and
    /// `GLU_INVALID_VALUE` where `isLegalLevels` refuses the range over the largest side's
    /// levels.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_build_3d_mipmap_levels<P: bytemuck::Pod>(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        width: GLsizei,
        height: GLsizei,
        depth: GLsizei,
        format: GLenum,
        type_: GLenum,
        user_level: GLint,
        base_level: GLint,
        max_level: GLint,
        data: &[P],
    ) -> GLint {
        let sides = [width, height, depth];
        let range = (user_level, base_level, max_level);
        if let Err(code) = check_3d_args(format, type_, sides).and_then(|()| level_range(&sides, range).map(drop)) {
            return code;
        }
        let sides = ((width, height, depth), (width, height, depth));
        self.build_3d_core(target, internal_format, sides, (format, type_), range, bytemuck::cast_slice(data))
    }

    /// `closestFit3D`: GLU's nearest powers of two, halved together until level 1 of them
    /// fits `GL_PROXY_TEXTURE_3D` (or all are 1).
    fn closest_fit_3d(
        &mut self,
        internal_format: GLint,
        (width, height, depth): (GLsizei, GLsizei, GLsizei),
        (format, type_): (GLenum, GLenum),
    ) -> (GLsizei, GLsizei, GLsizei) {
        let mut fit = (nearest_power(width), nearest_power(height), nearest_power(depth));
        loop {
            let one = |p: GLsizei| if p > 1 { p >> 1 } else { p };
            let next = (one(fit.0), one(fit.1), one(fit.2));
            let proxy = GL_PROXY_TEXTURE_3D;
            self.tex_image_3d::<u8>(proxy, 1, internal_format, next.0, next.1, next.2, 0, format, type_, &[]);
            let mut proxy_width = [0];
            self.get_tex_level_parameteriv(proxy, 1, GL_TEXTURE_WIDTH, &mut proxy_width);
            if proxy_width[0] != 0 {
                return fit;
            }
            if fit == (1, 1, 1) {
                return fit;
            }
            fit = next;
        }
    }

    /// `gluBuild3DMipmapLevelsCore`: level `user` from the client's image (`sides.0`, scaled
    /// to `sides.1` if they differ), then each halving down to the last level, those in
    /// `base..=max` loaded; the unpack modes GLU changed restored.
    fn build_3d_core(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        ((width, height, depth), fitted): ((GLsizei, GLsizei, GLsizei), (GLsizei, GLsizei, GLsizei)),
        (format, type_): (GLenum, GLenum),
        (user, base, max): (GLint, GLint, GLint),
        data: &[u8],
    ) -> GLint {
        let Some(kind) = Kind::of(type_) else { return GLU_INVALID_ENUM as GLint };
        let levels = compute_log(fitted.0).max(compute_log(fitted.1)).max(compute_log(fitted.2)).saturating_add(user);
        let saved = self.unpack_store();
        let user_sides = (width as usize, height as usize, depth as usize);
        let Some(client) = ClientImage::new(&saved, user_sides, format, kind).filter(|c| c.end <= data.len()) else {
            return GLU_INVALID_VALUE as GLint;
        };
        let users_image = &data[client.start..];
        let swap = saved.swap_bytes && kind.size() > 1;
        for pname in ZEROED {
            self.pixel_storei(pname, 0);
        }
        let code = self.build_3d_levels(
            target,
            internal_format,
            (user_sides, fitted),
            (format, kind, type_),
            (user, base, max, levels),
            (users_image, client.steps, swap),
        );
        self.restore_unpack(&saved);
        code
    }

    /// The levels of [`Gl::build_3d_core`], once the client's image is found.
    #[allow(clippy::too_many_arguments)]
    fn build_3d_levels(
        &mut self,
        target: GLenum,
        internal_format: GLint,
        (user_sides, fitted): ((usize, usize, usize), (GLsizei, GLsizei, GLsizei)),
        (format, kind, type_): (GLenum, Kind, GLenum),
        (user, base, max, levels): (GLint, GLint, GLint, GLint),
        (users_image, client_steps, swap): (&[u8], Steps, bool),
    ) -> GLint {
        let cmpts = if matches!(kind, Kind::Packed(_)) { 1 } else { components(format) };
        let group = kind.size() * cmpts;
        let mut sides = (fitted.0 as usize, fitted.1 as usize, fitted.2 as usize);
        let halved = |(w, h, d): (usize, usize, usize)| ((w / 2).max(1), (h / 2).max(1), (d / 2).max(1));
        let buffer = |s| image_size_3d(s, format, kind).map(|n| vec![0u8; n]);
        let mut level = user;
        let (mut src, mut dst);
        if user_sides == sides {
            if base <= level && level <= max {
                self.load_level_3d(target, level, internal_format, sides, (format, type_), users_image);
            }
            if levels == 0 {
                return 0;
            }
            let Some(mut next) = buffer(halved(sides)) else { return GLU_OUT_OF_MEMORY as GLint };
            halve_level(kind, cmpts, to_isize(sides), users_image, &mut next, client_steps, swap);
            sides = halved(user_sides);
            src = next;
            let Some(spare) = buffer(sides) else { return GLU_OUT_OF_MEMORY as GLint };
            dst = spare;
            level = user + 1;
        } else {
            let Some(mut scaled) = buffer(sides) else { return GLU_OUT_OF_MEMORY as GLint };
            let stores = (self.unpack_store(), self.pack_store());
            scale_image_3d((&stores.0, &stores.1), format, type_, (user_sides, users_image), (sides, &mut scaled));
            src = scaled;
            dst = if levels != 0 {
                let Some(spare) = buffer(halved(sides)) else { return GLU_OUT_OF_MEMORY as GLint };
                spare
            } else {
                Vec::new()
            };
        }
        // GLU's own buffers: tightly packed, no swapping.
        let mut steps = Steps {
            element: kind.size() as isize,
            group: group as isize,
            row: (sides.0 * group) as isize,
            image: (sides.0 * group * sides.1) as isize,
        };
        self.pixel_storei(GL_UNPACK_SWAP_BYTES, 0);
        if base <= level && level <= max {
            self.load_level_3d(target, level, internal_format, sides, (format, type_), &src);
        }
        level += 1;
        while level <= levels {
            halve_level(kind, cmpts, to_isize(sides), &src, &mut dst, steps, false);
            std::mem::swap(&mut src, &mut dst);
            if sides.0 > 1 {
                sides.0 /= 2;
                steps.row /= 2;
            }
            if sides.1 > 1 {
                sides.1 /= 2;
                steps.image = steps.row * sides.1 as isize;
            }
            if sides.2 > 1 {
                sides.2 /= 2;
            }
            if base <= level && level <= max {
                self.load_level_3d(target, level, internal_format, sides, (format, type_), &src);
            }
            level += 1;
        }
        0
    }

    /// `glTexImage3D` of one level from GLU's bytes, handed over with room for whatever GL
    /// reads past them under the client's alignment (C would read the heap there: zeros here).
    fn load_level_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        internal_format: GLint,
        (w, h, d): (usize, usize, usize),
        (format, type_): (GLenum, GLenum),
        bytes: &[u8],
    ) {
        let room = (h * d).saturating_mul(self.unpack_store().alignment);
        let mut padded = Vec::with_capacity(bytes.len() + room);
        padded.extend_from_slice(bytes);
        padded.resize(bytes.len() + room, 0);
        let (w, h, d) = (w as GLsizei, h as GLsizei, d as GLsizei);
        self.tex_image_3d(target, level, internal_format, w, h, d, 0, format, type_, &padded);
    }

    /// The unpack modes as they were before GLU's work (it restores each one it set).
    fn restore_unpack(&mut self, saved: &PixelStore) {
        self.pixel_storei(GL_UNPACK_ALIGNMENT, saved.alignment as GLint);
        self.pixel_storei(GL_UNPACK_SKIP_ROWS, saved.skip_rows as GLint);
        self.pixel_storei(GL_UNPACK_SKIP_PIXELS, saved.skip_pixels as GLint);
        self.pixel_storei(GL_UNPACK_ROW_LENGTH, saved.row_length as GLint);
        self.pixel_storei(GL_UNPACK_SWAP_BYTES, GLint::from(saved.swap_bytes));
        self.pixel_storei(GL_UNPACK_SKIP_IMAGES, saved.skip_images as GLint);
        self.pixel_storei(GL_UNPACK_IMAGE_HEIGHT, saved.image_height as GLint);
    }
}

fn to_isize((w, h, d): (usize, usize, usize)) -> Sides {
    (w as isize, h as isize, d as isize)
}

/// One halving of the level in `src` into `dst`, by GLU's routine for the type and depth.
fn halve_level(kind: Kind, cmpts: usize, sides: Sides, src: &[u8], dst: &mut [u8], steps: Steps, swap: bool) {
    match kind {
        Kind::Elements(e) if sides.2 > 1 => halve_3d(e, cmpts as isize, sides, src, dst, steps, swap),
        Kind::Elements(e) => halve_2d(e, cmpts as isize, (sides.0, sides.1), src, dst, steps, swap),
        Kind::Packed(p) => halve_packed_3d(&p, sides, src, dst, steps, swap),
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

    /// mipmaps.c's `stores`: alignment, row length, image height, skipped rows, pixels and
    /// images, swap bytes.
    const STORES: [[i32; 7]; 6] = [
        [1, 0, 0, 0, 0, 0, 0],
        [4, 0, 0, 0, 0, 0, 0],
        [1, 0, 0, 0, 0, 0, 1],
        [1, 6, 0, 1, 2, 0, 0],
        [1, 0, 5, 0, 0, 1, 0],
        [2, 5, 6, 1, 1, 1, 1],
    ];
    const NAMES: [GLenum; 7] = [
        GL_UNPACK_ALIGNMENT,
        GL_UNPACK_ROW_LENGTH,
        GL_UNPACK_IMAGE_HEIGHT,
        GL_UNPACK_SKIP_ROWS,
        GL_UNPACK_SKIP_PIXELS,
        GL_UNPACK_SKIP_IMAGES,
        GL_UNPACK_SWAP_BYTES,
    ];

    /// One case of mipmaps.c's `build3d` (`v`: format type w h d user base max plain store
    /// seed), printed as it prints it.
    fn run(v: &[i64]) -> Vec<String> {
        let n = |k: usize| v[k] as i32;
        let mut gl = Gl::new(4, 4);
        gl.bind_texture(GL_TEXTURE_3D, 1);
        let store = STORES[v[9] as usize];
        for (name, value) in NAMES.iter().zip(store) {
            gl.pixel_storei(*name, value);
        }
        let (bytes, floats) = input(v[10] as u32);
        let (format, type_) = (v[0] as u32, v[1] as u32);
        let rgba = GL_RGBA as i32;
        let rc = match (n(8) == 1, type_ == GL_FLOAT) {
            (true, true) => gl.glu_build_3d_mipmaps(GL_TEXTURE_3D, rgba, n(2), n(3), n(4), format, type_, &floats),
            (true, false) => gl.glu_build_3d_mipmaps(GL_TEXTURE_3D, rgba, n(2), n(3), n(4), format, type_, &bytes),
            (false, true) => gl.glu_build_3d_mipmap_levels(
                GL_TEXTURE_3D,
                rgba,
                n(2),
                n(3),
                n(4),
                format,
                type_,
                n(5),
                n(6),
                n(7),
                &floats,
            ),
            (false, false) => gl.glu_build_3d_mipmap_levels(
                GL_TEXTURE_3D,
                rgba,
                n(2),
                n(3),
                n(4),
                format,
                type_,
                n(5),
                n(6),
                n(7),
                &bytes,
            ),
        };
        let words: Vec<String> = v[..11].iter().map(i64::to_string).collect();
        let mut out = vec![format!("M 3d {} {rc} {}", words.join(" "), gl.get_error())];
        for (i, (name, value)) in NAMES.iter().zip(store).enumerate() {
            let mut got = [-1];
            gl.get_integerv(*name, &mut got);
            if got[0] != value {
                out.push(format!("S {i} {}", got[0]));
            }
        }
        for (k, level) in gl.bound_levels(3).into_iter().enumerate() {
            let Some(level) = level.filter(|l| l.width > 0) else { continue };
            let hex: String = level.texels.iter().flatten().map(|b| format!("{b:02x}")).collect();
            out.push(format!("L {k} {} {} {} {hex}", level.width, level.height, level.depth));
        }
        out
    }

    #[test]
    fn mipmaps_3d_match_real_glu() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu/mipmaps.txt");
        let text = std::fs::read_to_string(path).expect("mipmaps.txt");
        let mut cases: Vec<Vec<String>> = Vec::new();
        let mut in_3d = false;
        for line in text.lines() {
            if line.starts_with("M ") {
                in_3d = line.starts_with("M 3d ");
                if in_3d {
                    cases.push(Vec::new());
                }
            }
            if in_3d {
                cases.last_mut().expect("a case").push(line.to_string());
            }
        }
        assert!(cases.len() > 200, "{} 3D cases", cases.len());
        let mut failures = Vec::new();
        for want in &cases {
            let v: Vec<i64> = want[0].split(' ').skip(2).map(|w| w.parse().unwrap()).collect();
            let got = run(&v);
            if got != *want {
                failures.push(format!("{}\n  gleval {:?}\n  GLU    {:?}", want[0], &got[..], &want[..]));
            }
        }
        assert!(failures.is_empty(), "{} of {} differ:\n{}", failures.len(), cases.len(), failures.join("\n"));
    }

    #[test]
    fn nearest_power_is_glus() {
        let got: Vec<GLsizei> = [1, 2, 3, 5, 6, 7, 12, 129].iter().map(|&n| nearest_power(n)).collect();
        assert_eq!(got, [1, 2, 4, 4, 8, 8, 16, 128]);
        assert_eq!(nearest_power(GLsizei::MAX), 1 << 30);
    }
}
