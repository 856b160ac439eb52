//! Texture images from the window and the other GL 1.1 texture calls of the pixel path (GL 1.1
//! spec §3.8.2, §3.8.8; Mesa `main/teximage.c`, `texobj.c`): `glCopyTexImage1D/2D`,
//! `glCopyTexSubImage1D/2D/3D`, `glAreTexturesResident`,
//! `glPrioritizeTextures`.
//!
//! A copy reads the window as drawn so far, in program order: the context draws what it has
//! recorded through its reader ([`Gl::set_window_reader`]) when the call runs, and the texels
//! it reads become an ordinary level (so later frames, `glGetTexImage` and display lists see
//! them). Colours go through the pixel transfer, as Mesa's copies do. Source pixels outside the
//! window leave their texels 0 (GL leaves them undefined; Mesa clips the copy).

use super::consts::*;
use super::lists::ListCommand;
use super::texture::{base_format, copied_depth_texel, fits_level, image_target_of, max_level, strip_border, TexLevel};

/// The base format of a `glCopyTexImage` internal format: the named colour formats of
/// `glTexImage` (Mesa 22 refuses the component counts 1 to 4 here: `GL_INVALID_ENUM`,
/// measured), and GL 1.4's depth formats, whose levels take the window's depths
/// (`texture/depth.rs`).
fn copy_base_format(internal: GLenum) -> Option<GLenum> {
    match internal {
        1..=4 => None,
        _ => base_format(internal as GLint),
    }
}
use super::types::*;
use super::window_read::WindowImage;
use super::Gl;

/// A `glCopyTexImage` call: dimensions (1 or 2), target, level, internal format, the window
/// rectangle (x, y, width, height) and the border.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CopyTexImage {
    pub dims: u8,
    pub target: GLenum,
    pub level: GLint,
    pub internalformat: GLenum,
    pub rect: [GLint; 4],
    pub border: GLint,
}

/// A `glCopyTexSubImage` call: dimensions, target, level, the offset in the level (x, y, and
/// the image z of a 3D texture) and the window rectangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CopyTexSubImage {
    pub dims: u8,
    pub target: GLenum,
    pub level: GLint,
    pub offset: [GLint; 3],
    pub rect: [GLint; 4],
}

/// A call of this file as a display list holds it (GL 1.1 §5.4 compiles every one).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum CopyTextureCall {
    /// `glCopyTexImage1D/2D`.
    CopyTexImage(CopyTexImage),
    /// `glCopyTexSubImage1D/2D/3D`.
    CopyTexSubImage(CopyTexSubImage),
    /// `glPrioritizeTextures`, as (name, priority) pairs.
    PrioritizeTextures(Vec<(GLuint, GLclampf)>),
}

impl Gl {
    /// Replays a listed call of this file.
    pub(crate) fn replay_copy_texture_call(&mut self, call: &CopyTextureCall) {
        match call {
            CopyTextureCall::CopyTexImage(call) => self.copy_tex_image(*call),
            CopyTextureCall::CopyTexSubImage(call) => self.copy_tex_sub_image(*call),
            CopyTextureCall::PrioritizeTextures(pairs) => {
                for &(name, priority) in pairs {
                    self.prioritize_textures(1, &[name], &[priority]);
                }
            }
        }
    }
}

impl Gl {
    /// `glCopyTexImage2D`: defines level `level` of the bound 2D texture from the window
    /// rectangle at (`x`, `y`) (see the module docs). Errors, in Mesa's order: inside
    /// `begin`/`end` → `GL_INVALID_OPERATION`; target → `GL_INVALID_ENUM`; level, border →
    /// `GL_INVALID_VALUE`; internal format → `GL_INVALID_ENUM`; sizes (negative or over
    /// [`super::MAX_TEXTURE_SIZE`]) → `GL_INVALID_VALUE`. Compiled into display lists.
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
        border: GLint,
    ) {
        self.copy_tex_image(CopyTexImage {
            dims: 2,
            target,
            level,
            internalformat,
            rect: [x, y, width, height],
            border,
        });
    }

    /// `glCopyTexImage1D`: as [`Gl::copy_tex_image_2d`] for the bound 1D texture (one row).
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        internalformat: GLenum,
        x: GLint,
        y: GLint,
        width: GLsizei,
        border: GLint,
    ) {
        self.copy_tex_image(CopyTexImage { dims: 1, target, level, internalformat, rect: [x, y, width, 1], border });
    }

    pub(crate) fn copy_tex_image(&mut self, call: CopyTexImage) {
        if self.compiled_state_call(|| ListCommand::CopyTexture(CopyTextureCall::CopyTexImage(call))) {
            return;
        }
        let Some(t) = image_target_of(call.dims, call.target) else { return self.set_error(GL_INVALID_ENUM) };
        if !(0..=max_level(call.dims)).contains(&call.level) || !(0..=1).contains(&call.border) {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(base) = copy_base_format(call.internalformat) else { return self.set_error(GL_INVALID_ENUM) };
        let [x, y, width, height] = call.rect;
        // A cube map's faces are square (Mesa's `_mesa_legal_texture_dimensions`).
        let square = t.slot != super::texture::CUBE || width == height;
        if !fits_level(call.dims, call.level, [width, height, 1], call.border) || !square {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (w, h) = (width as usize, height as usize);
        let depth = (base == GL_DEPTH_COMPONENT).then_some(call.internalformat as GLint);
        let texels = self.window_texels([x, y], (w, h), depth);
        // The border's texels are read and dropped, as Mesa keeps a texture's inside only.
        let (texels, [w, h, _]) = strip_border(call.dims, texels, [w, h, 1], call.border as usize);
        let image = TexLevel::flat(w as u32, h as u32, texels);
        let internal = call.internalformat as GLint;
        self.bound_object_mut(t.slot).define_level(t.face, call.level as usize, Some(image), (base, internal), 0);
        self.image_changed(t.slot);
        self.generate_if_base(t, call.level as usize);
    }

    /// `glCopyTexSubImage2D`: replaces the rectangle at (`xoffset`, `yoffset`) of level `level`
    /// of the bound 2D texture with the window rectangle at (`x`, `y`). Errors, in Mesa's
    /// order: inside `begin`/`end` → `GL_INVALID_OPERATION`; target → `GL_INVALID_ENUM`; a level
    /// not defined → `GL_INVALID_OPERATION`; negative sizes or a rectangle outside the level →
    /// `GL_INVALID_VALUE`. Compiled into display lists.
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_sub_image_2d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
    ) {
        let call =
            CopyTexSubImage { dims: 2, target, level, offset: [xoffset, yoffset, 0], rect: [x, y, width, height] };
        self.copy_tex_sub_image(call);
    }

    /// `glCopyTexSubImage1D`: as [`Gl::copy_tex_sub_image_2d`] for the bound 1D texture.
    pub fn copy_tex_sub_image_1d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        x: GLint,
        y: GLint,
        width: GLsizei,
    ) {
        let call = CopyTexSubImage { dims: 1, target, level, offset: [xoffset, 0, 0], rect: [x, y, width, 1] };
        self.copy_tex_sub_image(call);
    }

    /// `glCopyTexSubImage3D` (GL 1.2 §3.8.2): as [`Gl::copy_tex_sub_image_2d`] into image
    /// `zoffset` of level `level` of the bound 3D texture.
    #[allow(clippy::too_many_arguments)]
    pub fn copy_tex_sub_image_3d(
        &mut self,
        target: GLenum,
        level: GLint,
        xoffset: GLint,
        yoffset: GLint,
        zoffset: GLint,
        x: GLint,
        y: GLint,
        width: GLsizei,
        height: GLsizei,
    ) {
        let offset = [xoffset, yoffset, zoffset];
        self.copy_tex_sub_image(CopyTexSubImage { dims: 3, target, level, offset, rect: [x, y, width, height] });
    }

    pub(crate) fn copy_tex_sub_image(&mut self, call: CopyTexSubImage) {
        if self.compiled_state_call(|| ListCommand::CopyTexture(CopyTextureCall::CopyTexSubImage(call))) {
            return;
        }
        let Some(t) = image_target_of(call.dims, call.target) else { return self.set_error(GL_INVALID_ENUM) };
        let [x, y, width, height] = call.rect;
        let Some(region) = self.sub_image_box(t, call.level, call.offset, [width, height, 1]) else { return };
        // A depth level takes the window's depths (GL 1.4 §3.8.2).
        let images = self.bound_object(t.slot).face(t.face);
        let level = call.level as usize;
        let depth = (images.formats[level] == GL_DEPTH_COMPONENT).then(|| images.level_format(level).0);
        let texels = self.window_texels([x, y], (region.size[0], region.size[1]), depth);
        self.replace_texels(t, call.level as usize, region, &texels);
    }

    /// The window's `w` × `h` rectangle at (`x`, `y`) as texels, rows from the bottom, through
    /// the colour transfer (`depth`: its depths through the depth transfer, as a depth level
    /// of that internal format keeps them); 0
    /// outside the window (and where the window cannot be read).
    fn window_texels(&mut self, [x, y]: [GLint; 2], (w, h): (usize, usize), depth: Option<GLint>) -> Vec<[u8; 4]> {
        if w == 0 || h == 0 {
            return Vec::new();
        }
        let window = self.read_window().unwrap_or_default();
        let (transfer, depths) = (self.color_transfer(), self.depth_transfer());
        let texel = |window: &WindowImage, i: usize, j: usize| {
            let (wx, wy) = (i64::from(x) + i as i64, i64::from(y) + j as i64);
            let c = if let Some(internal) = depth {
                let d = window.depth_at(wx, wy).map_or(0.0, |d| depths.apply(d));
                return copied_depth_texel(d, internal);
            } else {
                let Some(c) = window.color_at(wx, wy) else { return [0; 4] };
                transfer.as_ref().map_or(c, |t| t.apply(c))
            };
            c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8)
        };
        (0..h).flat_map(|j| (0..w).map(move |i| (i, j))).map(|(i, j)| texel(&window, i, j)).collect()
    }

    /// `glAreTexturesResident`: `GL_TRUE` when every name is a texture object (gleval's
    /// textures are always resident; `residences` is left as it was, as Mesa leaves it). Errors,
    /// as Mesa: `n` < 0, a name 0 or one that names no object (generated names count) →
    /// `GL_INVALID_VALUE` and `GL_FALSE`; `textures` shorter than `n` → `GL_INVALID_VALUE`;
    /// inside `begin`/`end` → `GL_INVALID_OPERATION`. Executed at once, not compiled.
    pub fn are_textures_resident(
        &mut self,
        n: GLsizei,
        textures: &[GLuint],
        residences: &mut [GLboolean],
    ) -> GLboolean {
        if self.reject_inside_begin_end() {
            return GL_FALSE;
        }
        let Ok(count) = usize::try_from(n) else {
            self.set_error(GL_INVALID_VALUE);
            return GL_FALSE;
        };
        let _ = residences;
        let names = textures.get(..count);
        let known = |name: &GLuint| *name != 0 && self.server.textures.objects.contains_key(name);
        if names.is_some_and(|names| names.iter().all(known)) {
            GL_TRUE
        } else {
            self.set_error(GL_INVALID_VALUE);
            GL_FALSE
        }
    }

    /// `glPrioritizeTextures`: each named object's `GL_TEXTURE_PRIORITY`, clamped to [0, 1]
    /// (names 0 and unknown names are skipped, as in Mesa). `n` < 0, or slices shorter than `n` →
    /// `GL_INVALID_VALUE`. Compiled into display lists, one pair at a time as Mesa compiles it.
    pub fn prioritize_textures(&mut self, n: GLsizei, textures: &[GLuint], priorities: &[GLclampf]) {
        let pairs = || {
            let count = usize::try_from(n).unwrap_or(0);
            textures.iter().zip(priorities).take(count).map(|(&t, &p)| (t, p)).collect()
        };
        if self.compiled(|| ListCommand::CopyTexture(CopyTextureCall::PrioritizeTextures(pairs())))
            || self.reject_inside_begin_end()
        {
            return;
        }
        let Ok(count) = usize::try_from(n) else { return self.set_error(GL_INVALID_VALUE) };
        let (Some(names), Some(values)) = (textures.get(..count), priorities.get(..count)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        for (name, &priority) in names.iter().zip(values) {
            if let Some(object) = self.server.textures.objects.get_mut(name) {
                object.set_priority(priority);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A context whose window reads as a 2 × 2 picture: red, green on the bottom row; blue,
    /// white above.
    fn gl_with_window() -> Gl {
        let mut gl = Gl::new(2, 2);
        gl.set_window_reader(|_, w, h| {
            let color = [[0, 0, 255, 255], [255, 255, 255, 255], [255, 0, 0, 255], [0, 255, 0, 255]].concat();
            Some(WindowImage { width: w, height: h, color, depth: Vec::new(), samples: Vec::new() })
        });
        gl
    }

    fn level0(gl: &mut Gl, dims: u8) -> TexLevel {
        gl.bound_object(usize::from(dims - 1)).face(0).levels[0].clone().expect("defined")
    }

    #[test]
    fn copies_read_the_window_bottom_up_and_clip() {
        let mut gl = gl_with_window();
        gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 2, 2, 0);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let level = level0(&mut gl, 2);
        assert_eq!(level.texels, [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 255, 255]]);
        gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, 0, 1, 0, 1, 1, 1, 1);
        let level = level0(&mut gl, 2);
        assert_eq!(level.texels[1], [255, 255, 255, 255]);
        gl.copy_tex_image_1d(GL_TEXTURE_1D, 0, GL_RGBA, 1, 0, 3, 0);
        assert_eq!(level0(&mut gl, 1).texels, [[0, 255, 0, 255], [0; 4], [0; 4]], "outside the window: 0");
        gl.pixel_transferf(GL_RED_SCALE, 0.5);
        gl.copy_tex_sub_image_1d(GL_TEXTURE_1D, 0, 0, 0, 0, 1);
        assert_eq!(level0(&mut gl, 1).texels[0], [128, 0, 0, 255], "through the transfer");
        gl.tex_sub_image_1d(GL_TEXTURE_1D, 0, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[1u8, 2, 3, 4]);
        // Red 1 · 0.5 is halfway, stored even as Mesa does (measured: 0; 3 · 0.5 stores 2).
        assert_eq!(level0(&mut gl, 1).texels[2], [0, 2, 3, 4]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn copy_errors_in_mesas_order() {
        let mut gl = gl_with_window();
        gl.copy_tex_image_2d(GL_TEXTURE_1D, -1, 0x1234, 0, 0, -1, 1, 2);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.copy_tex_image_2d(GL_TEXTURE_2D, -1, 0x1234, 0, 0, -1, 1, 0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, 0x1234, 0, 0, -1, 1, 0);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, -1, 1, 0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 1, 1);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION, "no level yet");
        gl.copy_tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 2, 2, 0);
        gl.copy_tex_sub_image_2d(GL_TEXTURE_2D, 0, 1, 1, 0, 0, 2, 1);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE, "outside the level");
        gl.tex_sub_image_1d(GL_TEXTURE_2D, 0, 0, 1, GL_RGB, GL_UNSIGNED_BYTE, &[0u8; 3]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn residency_and_priorities_as_mesa() {
        let mut gl = Gl::new(2, 2);
        let mut names = [0; 2];
        gl.gen_textures(2, &mut names);
        let mut residences = [7; 2];
        assert_eq!(gl.are_textures_resident(2, &names, &mut residences), GL_TRUE);
        assert_eq!(residences, [7, 7], "left as they were");
        assert_eq!(gl.are_textures_resident(2, &[names[0], 99], &mut residences), GL_FALSE);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        assert_eq!(gl.are_textures_resident(1, &[0], &mut residences), GL_FALSE);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.bind_texture(GL_TEXTURE_2D, names[1]);
        let priority = |gl: &mut Gl| {
            let mut p = [f32::NAN];
            gl.get_tex_parameterfv(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, &mut p);
            p[0]
        };
        gl.prioritize_textures(1, &[names[1]], &[0.25]);
        assert_eq!(priority(&mut gl), 0.25);
        gl.prioritize_textures(3, &[0, 99, names[1]], &[0.5, 0.5, 2.0]);
        assert_eq!(priority(&mut gl), 1.0);
        gl.prioritize_textures(1, &[names[1]], &[-1.0]);
        assert_eq!(priority(&mut gl), 0.0);
        gl.prioritize_textures(-1, &[], &[]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }
}
